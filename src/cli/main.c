#define _POSIX_C_SOURCE 200809L /* clock_gettime, isatty */
/* The tetrec command. Exit status = the tr_status of the first failure (0 on success),
 * so scripts can tell a bad file from a bad surface from a bug. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "delaunay/delaunay.h"
#include "io/io.h"
#include "pipeline/pipeline.h"
#include "refine/refine_stage.h"
#include "tetrec.h"

static const char usage[] =
    "usage: tetrec COMMAND [options] FILES   (tetrec COMMAND --help: that command's options)\n"
    "\n"
    "commands:\n"
    "  mesh IN [-o OUT]        tetrahedralize the volume bounded by the surface IN\n"
    "  delaunay IN [-o OUT]    Delaunay tetrahedralization of the points of IN\n"
    "  check IN MESH           validate MESH (.mesh, .msh, or .ele/.node) against IN\n"
    "  check-surface IN [-o F] list every defect of the surface IN\n"
    "  convert IN OUT          convert a surface or mesh between formats\n"
    "\n"
    "input formats (by extension): .off .stl .obj .ply .mesh .msh .node .poly .smesh\n"
    "output: .mesh (Medit), .vtu (VTK XML), .vtk (legacy VTK), .msh (Gmsh),\n"
    "  .node/.ele/.face or a TetGen base name (a name whose extension has no letter,\n"
    "  like out or cube.1); any other extension is an error. Without -o, IN's name with\n"
    "  '.1' (cube.off -> cube.1.node/.ele/.face), like TetGen\n"
    "\n"
    "exit status (= tr_status):\n"
    "  0 ok, 1 usage, 2 I/O error, 3 parse error, 4 invalid input (NaN, bad index,\n"
    "  zero-area triangle, ...), 5 degenerate point set, 6 open or non-manifold surface,\n"
    "  7 self-intersecting input, 8 out of memory or a size limit (--refine-budget:\n"
    "  the mesh made so far is written), 9 invalid mesh, 10 internal error,\n"
    "  11 not implemented\n";

enum { C_MESH = 1, C_DELAUNAY = 2, C_CHECK = 4, C_CONVERT = 8, C_CHECK_SURFACE = 16, C_ALL = 31 };

static const struct command {
  const char *name;
  unsigned bit;
  int nfiles;
  const char *synopsis, *help;
} commands[] = {
    {"mesh", C_MESH, 1, "mesh IN [-o OUT] [options]",
     "Tetrahedralize the volume bounded by the closed surface IN: a mesh that contains\n"
     "every input vertex, edge and facet, every geometric decision exact. OUT's\n"
     "extension picks the format; every output path is checked writable before meshing.\n"},
    {"delaunay", C_DELAUNAY, 1, "delaunay IN [-o OUT] [options]",
     "Delaunay tetrahedralization of the points of IN (its triangles are ignored).\n"},
    {"check", C_CHECK, 2, "check IN MESH [options]",
     "Validate the tetrahedral mesh MESH (.mesh, .msh or .node/.ele) against the surface\n"
     "IN: links, exact orientation, and, when every vertex is known exactly\n"
     "(an --exact .node, or no Steiner points), exact conformity and volume; also the\n"
     "largest distance of a rounded Steiner point from the input surface.\n"},
    {"check-surface", C_CHECK_SURFACE, 1, "check-surface IN [-o FILE] [options]",
     "List every self-intersecting pair of triangles, every open or non-manifold edge and\n"
     "every non-planar input polygon (with its deviation) of the surface IN; exit non-zero\n"
     "when there is any (also zero-area and duplicate triangles). -o FILE (.vtk or .msh)\n"
     "writes the offending triangles and edges, with cell data / physical tag 1\n"
     "intersecting triangle, 2 open edge, 3 non-manifold edge, 4 triangle of a non-planar\n"
     "polygon, 5 zero-area, 6 duplicate triangle, for ParaView or Gmsh.\n"},
    {"convert", C_CONVERT, 2, "convert IN OUT [options]",
     "Convert a surface or mesh between formats (OUT: .off .mesh .vtu .vtk .msh or TetGen).\n"},
};

static const struct option {
  const char *name, *arg;
  unsigned cmds;
  const char *help;
} options[] = {
    {"-o", "OUT", C_MESH | C_DELAUNAY | C_CHECK_SURFACE, "output file or TetGen base name"},
    {"-q", NULL, C_ALL, "quiet: errors only"},
    {"-v", NULL, C_ALL, "verbose"},
    {"--stats", "FILE", C_MESH | C_DELAUNAY,
     "write statistics as JSON, also when the run fails (with\n"
     "\"status\" and \"message\")"},
    {"--exact", NULL, C_MESH | C_DELAUNAY,
     "write Steiner points as exact rationals num/den in the\n"
     "TetGen .node (exactly on their edges and facets). Without it\n"
     "every output coordinate is a double: a Steiner point is its\n"
     "nearest double, moved by a few ulps where that is needed to\n"
     "keep every tet strictly positive, so it may lie a hair off\n"
     "its facet (see --strict-doubles)"},
    {"--msh-version", "V", C_MESH | C_DELAUNAY | C_CONVERT | C_CHECK_SURFACE,
     ".msh output format: 4.1 (default) or 2.2"},
    {"--allow-open", NULL, C_MESH | C_CHECK, "accept open or non-manifold surfaces"},
    {"--check-only", NULL, C_MESH, "only read and validate the input"},
    {"--no-smooth", NULL, C_MESH, "no surface diagonal swaps before recovery"},
    {"--keep-surface", NULL, C_MESH,
     "no Steiner point on the surface: the boundary faces of the\n"
     "output are exactly the input triangles (no smoothing either);\n"
     "fails naming the point where this cannot be done; --quality\n"
     "and --max-volume then add interior points only"},
    {"-Y", NULL, C_MESH, "the same as --keep-surface (TetGen's switch)"},
    {"--keep-edges", NULL, C_MESH,
     "under refinement, keep every input edge a chain of mesh\n"
     "edges (by default edges between exactly coplanar input\n"
     "triangles with the same marker are merged away)"},
    {"--spacing-radii", NULL, C_MESH,
     "under refinement, refuse a circumcentre only within a new\n"
     "vertex's current spacing, not its insertion radius (more\n"
     "points, fewer slivers where long edges were split early)"},
    {"--keep-steiner", NULL, C_MESH,
     "leave the recovery's Steiner points where they are (by\n"
     "default the ones on the surface are removed or moved inside\n"
     "where that can be done exactly)"},
    {"--recovery", "MODE", C_MESH,
     "default: every recovery step; paper: the published\n"
     "algorithm only (Swap23/Swap44 and pipels for edges, Swap32\n"
     "and clusterels for facets), to reproduce the paper's Table\n"
     "14; no-facet-flips: the default without the general flips\n"
     "for facets (cavity retriangulation right after Swap32)"},
    {"--round-budget", "N", C_MESH,
     "star checks the rounding repair may spend before it gives\n"
     "up (exit 9; default 2000000)"},
    {"--quality", "R[/D]", C_MESH | C_CHECK,
     "constrained Delaunay refinement until every tet's radius-\n"
     "edge ratio is at most R (>= 1; 1.414 is TetGen's default);\n"
     "D (degrees, at most 70): a minimum dihedral angle that sliver\n"
     "removal works towards (tets under it get flips, moves and\n"
     "points); a warning counts the tets left under it. check:\n"
     "count the tets over R (and under D)"},
    {"--subface-quality", "S", C_MESH,
     "with refinement: also split the boundary triangles whose\n"
     "radius-edge ratio is above S (>= 1), except where a small\n"
     "input angle forces it, and split an input-edge piece once\n"
     "under a boundary angle over 120 degrees (default: off)"},
    {"--max-volume", "V", C_MESH | C_CHECK,
     "refinement until every tet's volume is at most V (check:\n"
     "count the tets over V)"},
    {"-a", "V", C_MESH | C_CHECK, "the same as --max-volume (TetGen's switch)"},
    {"--refine-budget", "N", C_MESH,
     "points refinement may add; at N it stops, the mesh made so\n"
     "far (valid and conforming, the bounds not met everywhere)\n"
     "is written and tetrec exits 8\n"
     "(default: 100 per input point + 100,000, + 20 per V of the\n"
     "domain's volume with --max-volume, at most 2^24 or 8 per\n"
     "input point); a volume bound asking for over 8 tets per\n"
     "budget point is refused (exit 8) before refinement starts"},
    {"--optimize", "N", C_MESH,
     "sliver removal after quality refinement (runs only with\n"
     "--quality or --max-volume): 0 off, 1 flips that raise the\n"
     "smallest dihedral angle, 2 those flips and smoothing of\n"
     "interior points, 3 (default) also new points at slivers:\n"
     "interior ones, and exact ones on the input edges and\n"
     "facets under the worst tets; no point is moved off an\n"
     "input edge or facet"},
    {"-O", "N", C_MESH, "the same as --optimize (TetGen's switch)"},
    {"--progress", NULL, C_MESH,
     "a progress line (stage, share of stages done) on stderr from\n"
     "the start; without it the line shows when stderr is a\n"
     "terminal and the run takes over a second"},
    {"--threads", "N", C_MESH | C_DELAUNAY,
     "threads for the Delaunay tetrahedralization (default 0:\n"
     "every core); the output is the same for any N, byte for\n"
     "byte"},
    {"-j", "N", C_MESH | C_DELAUNAY, "the same as --threads"},
    {"--strict-doubles", NULL, C_MESH,
     "fail (exit 9) when a written double lies farther than\n"
     "2^-40 of the bounding box diagonal from the edge or facet\n"
     "its exact point lies on (a warning otherwise)"},
};
#define NOPTIONS (sizeof options / sizeof options[0])
#define NCOMMANDS (sizeof commands / sizeof commands[0])

typedef struct {
  const char *cmd, *in, *in2, *out, *stats;
  unsigned cmd_bit;
  int quiet, verbose, exact, allow_open, check_only, no_smooth, strict_doubles;
  int keep_surface, keep_steiner, progress, keep_edges, spacing_radii;
  int threads; /* 0: every core */
  int msh_version; /* 41 or 22 */
  int optimize; /* sliver removal level + 1, 0: the default */
  double quality, quality_dih, max_volume, subface_quality; /* 0: off */
  uint64_t refine_budget;                  /* 0: the default */
  uint64_t round_budget; /* 0: the default */
  int recovery;          /* tr_options.recovery */
} args;

static int fail(tr_status s)
{
  fprintf(stderr, "tetrec: error: %s [%s]\n", tr_last_error(), tr_status_name(s));
  return (int)s;
}

static int progress_on;
static void progress(const char *what, const char *name)
{
  if (progress_on)
    fprintf(stderr, "tetrec: %s %s...\n", what, name ? name : "");
}

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The progress line of `tetrec mesh` (tr_options.progress): the stage and the share of
 * stages done, rewritten in place on stderr. Shown when stderr is a terminal and the run
 * has taken over a second, or from the start with --progress. */
typedef struct {
  double t0, after; /* start, and the seconds before the line shows */
  int shown;
} progress_line;

static int stage_progress(void *user, const char *stage, double fraction)
{
  /* tr_mesh_plc's stages in their order (include/tetrec.h, tr_options.progress) */
  static const char *const order[] = {"validation",     "smoothing", "delaunay",   "edge_recovery",
                                      "facet_recovery", "coloring",  "suppression", "refinement",
                                      "rounding"};
  const int n = (int)(sizeof order / sizeof *order);
  progress_line *p = user;
  if (now() - p->t0 < p->after)
    return 0;
  int k = 0;
  while (k < n && strcmp(order[k], stage))
    k++;
  double done = k < n ? 100.0 * (k + fraction) / n : 0;
  fprintf(stderr, "\rtetrec: %-16s %3.0f%%", stage, done);
  fflush(stderr);
  p->shown = 1;
  return 0;
}

/* IN without its extension, plus ".1". */
static char *default_out(const char *in)
{
  const char *slash = strrchr(in, '/');
  const char *dot = strrchr(slash ? slash + 1 : in, '.');
  size_t n = dot ? (size_t)(dot - in) : strlen(in);
  char *s = malloc(n + 3);
  if (s) {
    memcpy(s, in, n);
    memcpy(s + n, ".1", 3);
  }
  return s;
}

static void print_help(const struct command *c)
{
  if (!c) {
    fputs(usage, stdout);
    printf("\noptions (each command's --help says which apply):\n");
  } else
    printf("usage: tetrec %s\n\n%s\noptions:\n", c->synopsis, c->help);
  for (size_t i = 0; i < NOPTIONS; i++) {
    if (c && !(options[i].cmds & c->bit))
      continue;
    char head[40];
    snprintf(head, sizeof head, "%s%s%s", options[i].name, options[i].arg ? " " : "",
             options[i].arg ? options[i].arg : "");
    /* a head wider than the column gets a line of its own */
    if (strlen(head) >= 18)
      printf("  %s\n  %-18s", head, "");
    else
      printf("  %-18s", head);
    for (const char *h = options[i].help; *h;) {
      const char *nl = strchr(h, '\n');
      int n = nl ? (int)(nl - h) : (int)strlen(h);
      printf("%.*s\n", n, h);
      h += n + (nl ? 1 : 0);
      if (*h)
        printf("  %-18s", "");
    }
  }
  printf("  --help, --version\n");
}

/* One option with its value (NULL for flags); the table above already checked that it
 * applies to the command. */
static tr_status set_option(args *a, const char *name, const char *v)
{
  if (!strcmp(name, "-o"))
    a->out = v;
  else if (!strcmp(name, "--stats"))
    a->stats = v;
  else if (!strcmp(name, "-q"))
    a->quiet = 1;
  else if (!strcmp(name, "-v"))
    a->verbose = 1;
  else if (!strcmp(name, "--exact"))
    a->exact = 1;
  else if (!strcmp(name, "--allow-open"))
    a->allow_open = 1;
  else if (!strcmp(name, "--check-only"))
    a->check_only = 1;
  else if (!strcmp(name, "--no-smooth"))
    a->no_smooth = 1;
  else if (!strcmp(name, "--strict-doubles"))
    a->strict_doubles = 1;
  else if (!strcmp(name, "--progress"))
    a->progress = 1;
  else if (!strcmp(name, "--quality")) {
    /* "R" or "R/D", finite numbers and nothing else */
    char *end;
    int ok = (v[0] == '.' || (v[0] >= '0' && v[0] <= '9'));
    double r = ok ? strtod(v, &end) : 0, d = 0;
    if (ok && *end == '/') {
      const char *w = end + 1;
      ok = *w == '.' || (*w >= '0' && *w <= '9');
      d = ok ? strtod(w, &end) : 0;
    }
    if (!ok || *end || !isfinite(r) || !isfinite(d))
      return tr_error(TR_ERR_USAGE, "--quality reads R or R/D (numbers), not '%s'", v);
    a->quality = r;
    a->quality_dih = d;
  } else if (!strcmp(name, "--subface-quality")) {
    char *end;
    double x = strtod(v, &end);
    if (!*v || *end || !(x >= 1) || !isfinite(x))
      return tr_error(TR_ERR_USAGE, "%s needs a ratio of at least 1, not '%s'", name, v);
    a->subface_quality = x;
  } else if (!strcmp(name, "--max-volume") || !strcmp(name, "-a")) {
    char *end;
    double x = strtod(v, &end);
    if (!*v || *end || !(x > 0) || !isfinite(x))
      return tr_error(TR_ERR_USAGE, "%s needs a positive volume, not '%s'", name, v);
    a->max_volume = x;
  }
  else if (!strcmp(name, "--optimize") || !strcmp(name, "-O")) {
    if (strlen(v) != 1 || v[0] < '0' || v[0] > '3')
      return tr_error(TR_ERR_USAGE, "%s needs a level 0, 1, 2 or 3, not '%s'", name, v);
    a->optimize = v[0] - '0' + 1;
  }
  else if (!strcmp(name, "--keep-surface") || !strcmp(name, "-Y"))
    a->keep_surface = 1;
  else if (!strcmp(name, "--keep-edges"))
    a->keep_edges = 1;
  else if (!strcmp(name, "--spacing-radii"))
    a->spacing_radii = 1;
  else if (!strcmp(name, "--keep-steiner"))
    a->keep_steiner = 1;
  else if (!strcmp(name, "--recovery")) {
    if (!strcmp(v, "paper"))
      a->recovery = 1;
    else if (!strcmp(v, "default"))
      a->recovery = 0;
    else if (!strcmp(v, "no-facet-flips"))
      a->recovery = 2;
    else
      return tr_error(TR_ERR_USAGE, "--recovery needs 'default', 'paper' or "
                      "'no-facet-flips', not '%s'", v);
  }
  else if (!strcmp(name, "--msh-version")) {
    if (!strcmp(v, "4.1") || !strcmp(v, "4"))
      a->msh_version = 41;
    else if (!strcmp(v, "2.2") || !strcmp(v, "2"))
      a->msh_version = 22;
    else
      return tr_error(TR_ERR_USAGE, "--msh-version is 4.1 or 2.2, not '%s'", v);
  } else if (!strcmp(name, "--round-budget") || !strcmp(name, "--refine-budget")) {
    /* digits only, 1 .. 10^15: strtoull alone would take "-1", "+5" and " 7" */
    size_t len = strlen(v);
    int ok = len > 0 && len <= 16 && strspn(v, "0123456789") == len;
    unsigned long long n = ok ? strtoull(v, NULL, 10) : 0;
    if (!ok || n == 0 || n > 1000000000000000ull)
      return tr_error(TR_ERR_USAGE, "%s needs a whole number from 1 to 10^15, not '%s'", name,
                      v);
    if (!strcmp(name, "--round-budget"))
      a->round_budget = n;
    else
      a->refine_budget = n;
  } else if (!strcmp(name, "--threads") || !strcmp(name, "-j")) {
    size_t len = strlen(v);
    int ok = len > 0 && len <= 4 && strspn(v, "0123456789") == len;
    long n = ok ? strtol(v, NULL, 10) : -1;
    if (!ok || n > 1024)
      return tr_error(TR_ERR_USAGE, "%s needs a whole number from 0 (every core) to 1024, "
                      "not '%s'", name, v);
    a->threads = (int)n;
  } else
    return tr_error(TR_ERR_INTERNAL, "option %s in the table but not handled", name);
  return TR_OK;
}

static int parse_args(int argc, char **argv, args *a)
{
  memset(a, 0, sizeof *a);
  a->msh_version = 41;
  const char *pos[3] = {0};
  int npos = 0, help = 0;
  unsigned char given[NOPTIONS] = {0};
  for (int i = 1; i < argc; i++) {
    const char *s = argv[i];
    if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
      help = 1;
      continue;
    }
    if (!strcmp(s, "--version")) {
      printf("tetrec %s\n", TETREC_VERSION_STRING);
      exit(0);
    }
    if (!(s[0] == '-' && s[1])) {
      if (npos == 3)
        return tr_error(TR_ERR_USAGE, "too many arguments (see tetrec --help)");
      pos[npos++] = s;
      continue;
    }
    size_t k = 0;
    while (k < NOPTIONS && strcmp(s, options[k].name))
      k++;
    if (k == NOPTIONS)
      return tr_error(TR_ERR_USAGE, "unknown option '%s' (see tetrec --help)", s);
    const char *v = NULL;
    if (options[k].arg) {
      if (i + 1 >= argc)
        return tr_error(TR_ERR_USAGE, "%s needs an argument", s);
      v = argv[++i];
    }
    given[k] = 1;
    TR_CHECK(set_option(a, s, v));
  }
  const struct command *c = NULL;
  for (size_t k = 0; npos && k < NCOMMANDS; k++)
    if (!strcmp(pos[0], commands[k].name))
      c = &commands[k];
  for (size_t k = 0; c && k < NOPTIONS; k++)
    if (given[k] && !(options[k].cmds & c->bit))
      return tr_error(TR_ERR_USAGE, "option %s does not apply to '%s' (see tetrec %s --help)",
                      options[k].name, c->name, c->name);
  if (help) {
    print_help(c);
    exit(0);
  }
  if (npos == 0)
    return tr_error(TR_ERR_USAGE, "no command (see tetrec --help)");
  if (!c)
    return tr_error(TR_ERR_USAGE, "unknown command '%s' (see tetrec --help)", pos[0]);
  a->cmd = c->name;
  a->cmd_bit = c->bit;
  a->in = pos[1];
  a->in2 = pos[2];
  if (npos != c->nfiles + 1)
    return tr_error(TR_ERR_USAGE, "'%s' takes %d file argument%s (see tetrec %s --help)",
                    c->name, c->nfiles, c->nfiles > 1 ? "s" : "", c->name);
  return TR_OK;
}

static void print_report(const args *a, const tr_plc *plc)
{
  const char *r = tr_plc_report(plc);
  if (a->quiet || !*r)
    return;
  /* One "tetrec: repaired:" prefix per line keeps the log greppable. */
  while (*r) {
    const char *nl = strchr(r, '\n');
    int n = nl ? (int)(nl - r) : (int)strlen(r);
    fprintf(stderr, "tetrec: repaired: %.*s\n", n, r);
    r += n + (nl ? 1 : 0);
  }
}

/* The end of mesh and delaunay: the error (if any) on stderr, and the statistics, written
 * on failure too with the status and its message. */
static int finish(const args *a, tr_stats *st, double t0, tr_status s)
{
  st->total_seconds = now() - t0;
  char *msg = NULL;
  int rc = 0;
  if (s != TR_OK) {
    const char *e = tr_last_error();
    msg = malloc(strlen(e) + 1);
    if (msg)
      strcpy(msg, e);
    rc = fail(s);
  }
  if (a->stats) {
    tr_status w = tr_stats_write_json_status(st, s, msg ? msg : "", a->stats);
    if (w != TR_OK)
      rc = rc ? (fail(w), rc) : fail(w);
  }
  free(msg);
  return rc;
}

/* What the output names say before any work: the format, and that --exact has a .node to
 * go to. */
static tr_status check_names(const args *a, const char *path)
{
  TR_CHECK(tr_io_check_out_name(path, 0));
  if (a->exact && tr_io_out_format(path) != TR_OUT_TETGEN)
    return tr_error(TR_ERR_USAGE, "--exact writes exact rationals only to a TetGen .node file, "
                    "not to %s", path);
  return TR_OK;
}

/* Every output file can be created: checked once the input is read (a missing input is the
 * better message), before the work that takes time. */
static tr_status check_writable(const args *a, const char *path)
{
  if (a->stats)
    TR_CHECK(tr_io_check_file_writable(a->stats));
  return tr_io_check_writable(path);
}

/* A warning per non-planar input polygon, the first TR_NONPLANAR_LIST of them (all with
 * -v), then one line for the rest: a CAD export can have hundreds, and the pile would bury
 * the other messages. None goes unsaid: the summary gives their number and the largest
 * relative deviation. */
#define TR_NONPLANAR_LIST 10
static void warn_nonplanar(const args *a, const tr_plc *plc)
{
  tr_nonplanar *np = NULL;
  uint32_t n = 0;
  if (a->quiet || tr_plc_nonplanar(plc, &np, &n) != TR_OK)
    return;
  uint32_t list = a->verbose || n <= TR_NONPLANAR_LIST + 1 ? n : TR_NONPLANAR_LIST;
  double worst = 0;
  for (uint32_t i = 0; i < n; i++) {
    worst = np[i].relative > worst ? np[i].relative : worst;
    if (i < list)
      fprintf(stderr, "tetrec: warning: %s: polygon %u (triangles %u..%u) is not planar: a "
              "vertex lies %.3g from the plane of its largest triangle (%.3g of its bounding box "
              "diagonal); triangulated in its projection\n", a->in, np[i].facet,
              np[i].first_tri, np[i].first_tri + np[i].ntris - 1, np[i].deviation,
              np[i].relative);
  }
  if (list < n)
    fprintf(stderr, "tetrec: warning: %s: %u more polygons are not planar (largest deviation "
            "of all %.3g of a bounding box diagonal); -v lists them, `tetrec check-surface` shows "
            "them\n", a->in, n - list, worst);
  free(np);
}

static int cmd_mesh(const args *a)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.allow_open = a->allow_open;
  opt.smooth = !a->no_smooth;
  opt.verbose = a->quiet ? 0 : a->verbose ? 2 : 1;
  opt.round_budget = a->round_budget;
  opt.strict_doubles = a->strict_doubles;
  opt.recovery = a->recovery;
  opt.keep_surface = a->keep_surface;
  opt.keep_edges = a->keep_edges;
  opt.refine_spacing_radii = a->spacing_radii;
  opt.quality_ratio = a->quality;
  opt.quality_min_dihedral = a->quality_dih;
  opt.quality_subface_ratio = a->subface_quality;
  opt.max_volume = a->max_volume;
  opt.refine_budget = a->refine_budget;
  opt.refine_partial = 1; /* the mesh at the budget is written, then exit 8 */
  if (a->optimize)
    opt.optimize = a->optimize - 1;
  opt.threads = a->threads;
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  double t0 = now();
  char *out = a->out ? NULL : default_out(a->in);
  const char *path = a->out ? a->out : out;
  if (!path)
    return finish(a, &stats, t0, tr_error(TR_ERR_NOMEM, "out of memory"));
  /* refinement options are checked before any work, not after the recovery */
  tr_status s = tr_refine_check_options(&opt);
  if (s == TR_OK && !a->check_only)
    s = check_names(a, path);
  tr_plc *plc = NULL;
  if (s == TR_OK) {
    progress("reading", a->in);
    s = tr_plc_read(a->in, &plc);
  }
  stats.stage_seconds[TR_STAGE_READ] = now() - t0;
  if (s == TR_OK && a->verbose)
    fprintf(stderr, "tetrec: %-22s %.3f s\n", tr_stage_name(TR_STAGE_READ),
            stats.stage_seconds[TR_STAGE_READ]);
  if (s == TR_OK)
    s = a->check_only ? (a->stats ? tr_io_check_file_writable(a->stats) : TR_OK)
                      : check_writable(a, path);
  if (s == TR_OK) {
    warn_nonplanar(a, plc);
    progress("validating", a->in);
    s = tr_plc_validate(plc, &opt);
    print_report(a, plc);
    /* the validator stops at the first defect */
    if ((s == TR_ERR_SELF_INTERSECT || s == TR_ERR_OPEN) && !a->quiet)
      fprintf(stderr, "tetrec: note: `tetrec check-surface %s` lists every defect\n", a->in);
  }
  if (s == TR_OK) {
    stats.surface_nodes = tr_plc_num_points(plc);
    stats.surface_facets = tr_plc_num_triangles(plc);
    if (!a->quiet)
      fprintf(stderr, "tetrec: %s: %u vertices, %u triangles: valid\n", a->in,
              tr_plc_num_points(plc), tr_plc_num_triangles(plc));
  }
  if (s == TR_OK && a->check_only) {
    stats.stage_seconds[TR_STAGE_SELFINT] = plc->validate_seconds[1];
    stats.stage_seconds[TR_STAGE_NESTING] = plc->validate_seconds[2];
    stats.stage_seconds[TR_STAGE_VALIDATE] =
        plc->validate_seconds[0] - plc->validate_seconds[1] - plc->validate_seconds[2];
  }
  if (s != TR_OK || a->check_only) {
    tr_plc_destroy(plc);
    free(out);
    return finish(a, &stats, t0, s);
  }
  /* sliver removal follows refinement: without a bound there is nothing it runs after */
  int bounded = a->quality > 0 || a->max_volume > 0;
  for (uint32_t i = 0; i < plc->nregions; i++)
    bounded |= plc->region_maxvol[i] > 0;
  if (a->optimize > 1 && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: -O/--optimize has no effect without quality refinement "
            "(--quality, --max-volume or a region's maximum volume)\n");
  if (a->subface_quality > 0 && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --subface-quality has no effect without quality "
            "refinement (--quality, --max-volume or a region's maximum volume)\n");
  if (a->spacing_radii && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --spacing-radii has no effect without quality "
            "refinement (--quality, --max-volume or a region's maximum volume)\n");
  if (a->keep_edges && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --keep-edges has no effect without quality refinement: "
            "every input edge is kept anyway\n");
  /* The pipeline (src/pipeline): Delaunay, edge and facet recovery, outer removal. With
   * --exact (checked above to go to a .node), a rounding that cannot be repaired is a
   * warning, not a failure: the exact points are written. */
  tr_mesh *mesh = NULL;
  progress("meshing", a->in);
  progress_line line = {now(), a->progress ? 0.0 : 1.0, 0};
  if (a->progress || progress_on) {
    opt.progress = stage_progress;
    opt.progress_user = &line;
  }
  unsigned flags = (a->exact ? TR_PIPE_KEEP_EXACT : 0) |
                   (a->keep_steiner ? TR_PIPE_KEEP_STEINER : 0);
  double t_read = stats.stage_seconds[TR_STAGE_READ];
  s = tr_mesh_plc_flags(plc, &opt, &mesh, &stats, NULL, flags);
  stats.stage_seconds[TR_STAGE_READ] = t_read; /* the pipeline filled the others */
  if (line.shown)
    fputc('\n', stderr);
  /* the deviation of the written doubles (warning or --strict-doubles): tr_mesh_plc */
  tr_plc_destroy(plc);
  if (s == TR_OK) {
    progress("writing", path);
    double t_write = now();
    s = tr_mesh_write_ex(mesh, path, a->exact, a->msh_version);
    stats.stage_seconds[TR_STAGE_WRITE] = now() - t_write;
    if (s == TR_OK && a->verbose)
      fprintf(stderr, "tetrec: %-22s %.3f s\n", tr_stage_name(TR_STAGE_WRITE),
              stats.stage_seconds[TR_STAGE_WRITE]);
  }
  if (s == TR_OK && !a->quiet)
    fprintf(stderr, "tetrec: %s: %u vertices, %u tetrahedra, %llu Steiner points\n", path,
            tr_mesh_num_vertices(mesh), tr_mesh_num_tets(mesh),
            (unsigned long long)(stats.steiner_on_edges + stats.steiner_on_facets +
                                 stats.steiner_interior));
  if (s == TR_OK && !a->quiet && a->verbose)
    fprintf(stderr,
            "tetrec: Steiner points: %llu on input edges, %llu on input facets, %llu inside; "
            "%llu removed and %llu moved inside after recovery\n",
            (unsigned long long)stats.steiner_on_edges,
            (unsigned long long)stats.steiner_on_facets,
            (unsigned long long)stats.steiner_interior,
            (unsigned long long)stats.steiner_removed,
            (unsigned long long)stats.steiner_relocated);
  if (s == TR_OK && stats.refine_budget_reached)
    s = tr_error(TR_ERR_NOMEM, "refinement stopped at its point budget (--refine-budget): %s "
                 "holds the mesh made so far, valid and conforming, with %llu of its %llu tets "
                 "over the bounds", path, (unsigned long long)stats.tets_over_bounds,
                 (unsigned long long)stats.volume_elements);
  tr_mesh_destroy(mesh);
  free(out);
  return finish(a, &stats, t0, s);
}

static int cmd_delaunay(const args *a)
{
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  double t0 = now();
  char *out = a->out ? NULL : default_out(a->in);
  const char *path = a->out ? a->out : out;
  if (!path)
    return finish(a, &stats, t0, tr_error(TR_ERR_NOMEM, "out of memory"));
  tr_status s = check_names(a, path);
  tr_plc *plc = NULL;
  if (s == TR_OK) {
    progress("reading", a->in);
    s = tr_plc_read(a->in, &plc);
  }
  if (s == TR_OK)
    s = check_writable(a, path);
  tr_mesh *mesh = NULL;
  if (s == TR_OK) {
    progress("tetrahedralizing", a->in);
    s = tr_delaunay_build_threads(tr_plc_points(plc), tr_plc_num_points(plc), a->threads,
                                  &mesh);
    if (s == TR_OK)
      s = tr_mesh_attach_dense_tets(mesh); /* what tr_delaunay adds for the writers */
    stats.surface_nodes = tr_plc_num_points(plc);
    stats.surface_facets = tr_plc_num_triangles(plc);
  }
  tr_plc_destroy(plc);
  if (s == TR_OK) {
    progress("writing", path);
    s = tr_mesh_write_ex(mesh, path, a->exact, a->msh_version);
    stats.volume_nodes = tr_mesh_num_vertices(mesh);
    stats.volume_elements = tr_mesh_num_tets(mesh);
  }
  if (s == TR_OK && !a->quiet)
    fprintf(stderr, "tetrec: %s: %u vertices, %u tetrahedra\n", path,
            tr_mesh_num_vertices(mesh), tr_mesh_num_tets(mesh));
  tr_mesh_destroy(mesh);
  free(out);
  return finish(a, &stats, t0, s);
}

/* The .node file of a TetGen mesh name (.node or .ele), read exactly; nothing for other
 * formats. */
static tr_status read_exact_node(const char *mesh, const tr_plc *vol, tr_qpoint ***q,
                                 int *exact_file)
{
  *q = NULL;
  *exact_file = 0;
  if (!tr_io_has_ext(mesh, ".node") && !tr_io_has_ext(mesh, ".ele"))
    return TR_OK;
  size_t n = strlen(mesh);
  char *path = malloc(n + 2);
  if (!path)
    return tr_error(TR_ERR_NOMEM, "out of memory");
  memcpy(path, mesh, n + 1);
  strcpy(strrchr(path, '.'), ".node");
  char *buf = NULL;
  size_t len = 0;
  uint32_t np = 0;
  tr_status s = tr_io_load(path, &buf, &len);
  if (s == TR_OK)
    s = tr_read_node_exact_buf(buf, len, path, q, &np, exact_file);
  if (s == TR_OK && np != vol->npoints)
    s = tr_error(TR_ERR_INTERNAL, "%s: %u points read exactly, %u as doubles", path, np,
                 vol->npoints);
  if (s != TR_OK && *q) {
    for (uint32_t i = 0; i < np; i++)
      if ((*q)[i]) {
        tr_qpoint_clear((*q)[i]);
        free((*q)[i]);
      }
    free(*q);
    *q = NULL;
  }
  free(buf);
  free(path);
  return s;
}

static int cmd_check(const args *a)
{
  tr_plc *surf = NULL, *vol = NULL;
  tr_qpoint **exact = NULL;
  int exact_file = 0;
  tr_options opt;
  tr_options_default(&opt);
  opt.allow_open = a->allow_open;
  tr_status s = tr_plc_read(a->in, &surf);
  if (s == TR_OK) {
    warn_nonplanar(a, surf);
    s = tr_plc_validate(surf, &opt);
  }
  if (s == TR_OK) {
    /* MESH.node alone has no tets: read its .ele. */
    if (tr_io_has_ext(a->in2, ".node")) {
      size_t n = strlen(a->in2);
      char *e = malloc(n + 1);
      if (!e)
        s = tr_error(TR_ERR_NOMEM, "out of memory");
      else {
        memcpy(e, a->in2, n + 1);
        memcpy(e + n - 5, ".ele", 5);
        s = tr_plc_read(e, &vol);
        free(e);
      }
    } else
      s = tr_plc_read(a->in2, &vol);
  }
  if (s == TR_OK)
    s = read_exact_node(a->in2, vol, &exact, &exact_file);
  opt.quality_ratio = a->quality;
  opt.quality_min_dihedral = a->quality_dih;
  opt.max_volume = a->max_volume;
  if (s == TR_OK)
    s = tr_cli_check(surf, vol, exact, exact_file, a->allow_open, !a->quiet, &opt);
  for (uint32_t i = 0; exact && i < vol->npoints; i++)
    if (exact[i]) {
      tr_qpoint_clear(exact[i]);
      free(exact[i]);
    }
  free(exact);
  tr_plc_destroy(surf);
  tr_plc_destroy(vol);
  return s == TR_OK ? 0 : fail(s);
}

static int cmd_convert(const args *a)
{
  tr_plc *plc = NULL;
  tr_status s = tr_io_check_out_name(a->in2, 1);
  if (s == TR_OK)
    s = tr_plc_read(a->in, &plc);
  if (s == TR_OK)
    s = tr_io_check_writable(a->in2);
  if (s == TR_OK) {
    warn_nonplanar(a, plc);
    s = tr_plc_write_ex(plc, a->in2, a->msh_version);
  }
  if (s == TR_OK && !a->quiet && a->verbose)
    fprintf(stderr, "tetrec: %s -> %s: %u vertices, %u triangles\n", a->in, a->in2,
            tr_plc_num_points(plc), tr_plc_num_triangles(plc));
  tr_plc_destroy(plc);
  return s == TR_OK ? 0 : fail(s);
}

int main(int argc, char **argv)
{
  tr_cli_heap_setup();
  args a;
  tr_status s = parse_args(argc, argv, &a);
  if (s != TR_OK) {
    fail(s);
    return (int)s;
  }
  progress_on = !a.quiet && isatty(2);
  switch (a.cmd_bit) {
  case C_MESH: return cmd_mesh(&a);
  case C_DELAUNAY: return cmd_delaunay(&a);
  case C_CHECK: return cmd_check(&a);
  case C_CHECK_SURFACE: {
    s = tr_cli_check_surface(a.in, a.out, a.msh_version, a.quiet);
    return s == TR_OK ? 0 : fail(s);
  }
  default: return cmd_convert(&a);
  }
}
