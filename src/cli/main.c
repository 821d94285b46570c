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
#include "io/io.h"
#include "pipeline/pipeline.h"
#include "refine/refine_stage.h"
#include "tetrec.h"

static const char usage[] =
    "usage: tetrec COMMAND [options] FILES\n"
    "\n"
    "commands:\n"
    "  mesh IN [-o OUT]      tetrahedralize the volume bounded by the surface IN\n"
    "  delaunay IN [-o OUT]  Delaunay tetrahedralization of the points of IN\n"
    "  check IN MESH         validate MESH (.mesh, or .ele/.node) against the surface IN\n"
    "  convert IN OUT        convert a surface or mesh between formats\n"
    "\n"
    "input formats (by extension): .off .stl .obj .ply .mesh .node .poly .smesh\n"
    "output: .mesh (Medit), .vtu (VTK), .node/.ele/.face or a TetGen base name;\n"
    "  without -o, IN's name with '.1' (cube.off -> cube.1.node/.ele/.face), like TetGen\n"
    "\n"
    "options:\n"
    "  -o OUT            output file or base name\n"
    "  -Q, --quiet       quiet: errors only\n"
    "  -v                verbose\n"
    "  --stats FILE      write statistics as JSON\n"
    "  --exact           write Steiner points as exact rationals num/den in .node\n"
    "                    (exactly on their edges and facets). Without it every output\n"
    "                    coordinate is a double: a Steiner point is its nearest double,\n"
    "                    moved by a few ulps where that is needed to keep every tet\n"
    "                    strictly positive, so it may lie a hair off its facet. `check`\n"
    "                    verifies exact conformity and volume on an --exact .node, and\n"
    "                    only links and orientation on rounded Steiner points\n"
    "  --allow-open      accept open or non-manifold surfaces\n"
    "  --check-only      only read and validate the input (mesh)\n"
    "  --no-smooth       no surface diagonal swaps before recovery\n"
    "  --round-budget N  star checks the rounding repair may spend before it gives up\n"
    "                    (exit 9; default 2000000)\n"
    "  -q, --quality [R[/D]]  refine (constrained Delaunay refinement) until every tet's\n"
    "                    radius-edge ratio is at most R (default 1.414, R >= 1); a minimum\n"
    "                    dihedral target D is not supported yet (refused)\n"
    "  -a, --max-volume V  refine until every tet's volume is at most V\n"
    "  --refine-budget N points refinement may add before it stops with exit 8 (default\n"
    "                    100 per input point + 100000, + 20 per V in the domain's volume)\n"
    "  --help, --version\n"
    "\n"
    "exit status (= tr_status):\n"
    "  0 ok, 1 usage, 2 I/O error, 3 parse error, 4 invalid input (NaN, bad index,\n"
    "  zero-area triangle, ...), 5 degenerate point set, 6 open or non-manifold surface,\n"
    "  7 self-intersecting input, 8 out of memory, 9 invalid mesh, 10 internal error,\n"
    "  11 not implemented\n";

typedef struct {
  const char *cmd, *in, *in2, *out, *stats;
  int quiet, verbose, exact, allow_open, check_only, no_smooth;
  uint64_t round_budget; /* 0: the default */
  double quality, quality_dih, max_volume; /* 0: off */
  uint64_t refine_budget;                  /* 0: the default */
} args;

/* "R" or "R/D", both finite numbers, nothing else: 1 and the values, else 0. */
static int parse_quality(const char *v, double *r, double *d)
{
  char *end;
  if (!v || !*v || !(v[0] == '.' || (v[0] >= '0' && v[0] <= '9')))
    return 0;
  *r = strtod(v, &end);
  *d = 0;
  if (*end == '/') {
    const char *w = end + 1;
    if (!(*w == '.' || (*w >= '0' && *w <= '9')))
      return 0;
    *d = strtod(w, &end);
  }
  return *end == 0 && isfinite(*r) && isfinite(*d);
}

/* digits only, 1 .. 10^15: strtoull alone would take "-1", "+5" and " 7" */
static int parse_count(const char *v, uint64_t *n)
{
  size_t len = strlen(v);
  if (!(len > 0 && len <= 16 && strspn(v, "0123456789") == len))
    return 0;
  unsigned long long x = strtoull(v, NULL, 10);
  *n = x;
  return x > 0 && x <= 1000000000000000ull;
}

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

static int parse_args(int argc, char **argv, args *a)
{
  memset(a, 0, sizeof *a);
  const char *pos[3] = {0};
  int npos = 0;
  for (int i = 1; i < argc; i++) {
    const char *s = argv[i];
    if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
      fputs(usage, stdout);
      exit(0);
    } else if (!strcmp(s, "--version")) {
      printf("tetrec %s\n", TETREC_VERSION_STRING);
      exit(0);
    } else if (!strcmp(s, "-o") || !strcmp(s, "--stats")) {
      if (i + 1 >= argc)
        return tr_error(TR_ERR_USAGE, "%s needs an argument", s);
      if (s[1] == 'o')
        a->out = argv[++i];
      else
        a->stats = argv[++i];
    } else if (!strcmp(s, "-Q") || !strcmp(s, "--quiet"))
      a->quiet = 1;
    else if (!strcmp(s, "-q") || !strcmp(s, "--quality") || !strncmp(s, "--quality=", 10) ||
             (s[1] == 'q' && s[0] == '-' && s[2])) {
      /* the value is optional: attached (-q1.2, --quality=1.2) or the next argument when
       * it reads as R or R/D in full */
      const char *v = s[1] == 'q' ? (s[2] ? s + 2 : NULL) : (s[9] == '=' ? s + 10 : NULL);
      double r = 1.414, d = 0;
      if (v) {
        if (!parse_quality(v, &r, &d))
          return tr_error(TR_ERR_USAGE, "%s: the quality bound must read R or R/D (numbers)", s);
      } else if (i + 1 < argc && parse_quality(argv[i + 1], &r, &d))
        i++;
      else
        r = 1.414, d = 0;
      a->quality = r;
      a->quality_dih = d;
    } else if (!strcmp(s, "-a") || !strcmp(s, "--max-volume") || (s[1] == 'a' && s[0] == '-' && s[2])) {
      const char *v = s[1] == 'a' && s[2] ? s + 2 : i + 1 < argc ? argv[++i] : "";
      char *end;
      double x = strtod(v, &end);
      if (!*v || *end || !(x > 0) || !isfinite(x))
        return tr_error(TR_ERR_USAGE, "%s needs a positive volume, not '%s'", s, v);
      a->max_volume = x;
    } else if (!strcmp(s, "--refine-budget")) {
      const char *v = i + 1 < argc ? argv[++i] : "";
      if (!parse_count(v, &a->refine_budget))
        return tr_error(TR_ERR_USAGE, "--refine-budget needs a whole number from 1 to 10^15, "
                        "not '%s'", v);
    }
    else if (!strcmp(s, "-v"))
      a->verbose = 1;
    else if (!strcmp(s, "--exact"))
      a->exact = 1;
    else if (!strcmp(s, "--allow-open"))
      a->allow_open = 1;
    else if (!strcmp(s, "--check-only"))
      a->check_only = 1;
    else if (!strcmp(s, "--no-smooth"))
      a->no_smooth = 1;
    else if (!strcmp(s, "--round-budget")) {
      /* digits only, 1 .. 10^15: strtoull alone would take "-1", "+5" and " 7" */
      const char *v = i + 1 < argc ? argv[++i] : "";
      size_t len = strlen(v);
      int ok = len > 0 && len <= 16 && strspn(v, "0123456789") == len;
      unsigned long long n = ok ? strtoull(v, NULL, 10) : 0;
      if (!ok || n == 0 || n > 1000000000000000ull)
        return tr_error(TR_ERR_USAGE, "--round-budget needs a whole number from 1 to 10^15, "
                        "not '%s'", v);
      a->round_budget = n;
    }
    else if (s[0] == '-' && s[1])
      return tr_error(TR_ERR_USAGE, "unknown option '%s' (see tetrec --help)", s);
    else if (npos < 3)
      pos[npos++] = s;
    else
      return tr_error(TR_ERR_USAGE, "too many arguments (see tetrec --help)");
  }
  if (npos == 0)
    return tr_error(TR_ERR_USAGE, "no command (see tetrec --help)");
  a->cmd = pos[0];
  a->in = pos[1];
  a->in2 = pos[2];
  int want = (!strcmp(a->cmd, "check") || !strcmp(a->cmd, "convert")) ? 3 : 2;
  if (strcmp(a->cmd, "mesh") && strcmp(a->cmd, "delaunay") && strcmp(a->cmd, "check") &&
      strcmp(a->cmd, "convert"))
    return tr_error(TR_ERR_USAGE, "unknown command '%s' (see tetrec --help)", a->cmd);
  if (strcmp(a->cmd, "mesh") && (a->quality != 0 || a->max_volume != 0 || a->refine_budget))
    return tr_error(TR_ERR_USAGE, "-q/--quality, -a/--max-volume and --refine-budget apply to "
                    "'mesh' only, not '%s'", a->cmd);
  if (npos != want)
    return tr_error(TR_ERR_USAGE, "'%s' takes %d file argument%s (see tetrec --help)", a->cmd,
                    want - 1, want == 3 ? "s" : "");
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

static int write_stats(const args *a, const tr_stats *st)
{
  if (!a->stats)
    return 0;
  tr_status s = tr_stats_write_json(st, a->stats);
  return s == TR_OK ? 0 : fail(s);
}

static int cmd_mesh(const args *a)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.allow_open = a->allow_open;
  opt.smooth = !a->no_smooth;
  opt.verbose = a->quiet ? 0 : a->verbose ? 2 : 1;
  opt.round_budget = a->round_budget;
  opt.quality_ratio = a->quality;
  opt.quality_min_dihedral = a->quality_dih;
  opt.max_volume = a->max_volume;
  opt.refine_budget = a->refine_budget;
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  double t0 = now();
  tr_plc *plc = NULL;
  tr_status s = tr_refine_check_options(&opt); /* before the work, not after recovery */
  if (s != TR_OK)
    return fail(s);
  progress("reading", a->in);
  s = tr_plc_read(a->in, &plc);
  if (s != TR_OK)
    return fail(s);
  progress("validating", a->in);
  s = tr_plc_validate(plc, &opt);
  print_report(a, plc);
  if (s != TR_OK) {
    tr_plc_destroy(plc);
    return fail(s);
  }
  stats.surface_nodes = tr_plc_num_points(plc);
  stats.surface_facets = tr_plc_num_triangles(plc);
  if (!a->quiet)
    fprintf(stderr, "tetrec: %s: %u vertices, %u triangles: valid\n", a->in,
            tr_plc_num_points(plc), tr_plc_num_triangles(plc));
  stats.total_seconds = now() - t0;
  if (a->check_only) {
    tr_plc_destroy(plc);
    return write_stats(a, &stats);
  }
  /* The pipeline (src/pipeline): Delaunay, edge and facet recovery, outer removal. */
  tr_mesh *mesh = NULL;
  progress("meshing", a->in);
  /* With --exact, a .node output carries the exact points: a rounding that cannot be
   * repaired is then a warning, not a failure (the .vtu and .mesh writers print doubles). */
  const char *dest = a->out ? a->out : a->in;
  unsigned flags = a->exact && !(a->out && (tr_io_has_ext(dest, ".vtu") ||
                                            tr_io_has_ext(dest, ".mesh")))
                       ? TR_PIPE_KEEP_EXACT
                       : 0;
  s = tr_mesh_plc_flags(plc, &opt, &mesh, &stats, NULL, flags);
  tr_plc_destroy(plc);
  if (s != TR_OK)
    return fail(s);
  char *out = a->out ? NULL : default_out(a->in);
  const char *path = a->out ? a->out : out;
  progress("writing", path);
  s = path ? tr_mesh_write(mesh, path, a->exact) : TR_ERR_NOMEM;
  stats.total_seconds = now() - t0;
  if (s == TR_OK && !a->quiet)
    fprintf(stderr, "tetrec: %s: %u vertices, %u tetrahedra, %llu Steiner points\n", path,
            tr_mesh_num_vertices(mesh), tr_mesh_num_tets(mesh),
            (unsigned long long)(stats.points_added_for_edges + stats.points_added_for_facets));
  tr_mesh_destroy(mesh);
  free(out);
  if (s != TR_OK)
    return fail(s);
  return write_stats(a, &stats);
}

static int cmd_delaunay(const args *a)
{
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  double t0 = now();
  tr_plc *plc = NULL;
  progress("reading", a->in);
  tr_status s = tr_plc_read(a->in, &plc);
  if (s != TR_OK)
    return fail(s);
  tr_mesh *mesh = NULL;
  progress("tetrahedralizing", a->in);
  s = tr_delaunay(tr_plc_points(plc), tr_plc_num_points(plc), &mesh);
  stats.surface_nodes = tr_plc_num_points(plc);
  stats.surface_facets = tr_plc_num_triangles(plc);
  tr_plc_destroy(plc);
  if (s != TR_OK)
    return fail(s);
  char *out = a->out ? NULL : default_out(a->in);
  const char *path = a->out ? a->out : out;
  progress("writing", path);
  s = path ? tr_mesh_write(mesh, path, a->exact) : TR_ERR_NOMEM;
  stats.volume_nodes = tr_mesh_num_vertices(mesh);
  stats.volume_elements = tr_mesh_num_tets(mesh);
  stats.total_seconds = now() - t0;
  if (s == TR_OK && !a->quiet)
    fprintf(stderr, "tetrec: %s: %u vertices, %u tetrahedra\n", path,
            tr_mesh_num_vertices(mesh), tr_mesh_num_tets(mesh));
  tr_mesh_destroy(mesh);
  free(out);
  if (s != TR_OK)
    return fail(s);
  return write_stats(a, &stats);
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
  if (s == TR_OK)
    s = tr_plc_validate(surf, &opt);
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
  if (s == TR_OK)
    s = tr_cli_check(surf, vol, exact, exact_file, a->allow_open, !a->quiet);
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
  tr_status s = tr_plc_read(a->in, &plc);
  if (s == TR_OK)
    s = tr_plc_write(plc, a->in2);
  if (s == TR_OK && !a->quiet && a->verbose)
    fprintf(stderr, "tetrec: %s -> %s: %u vertices, %u triangles\n", a->in, a->in2,
            tr_plc_num_points(plc), tr_plc_num_triangles(plc));
  tr_plc_destroy(plc);
  return s == TR_OK ? 0 : fail(s);
}

int main(int argc, char **argv)
{
  args a;
  tr_status s = parse_args(argc, argv, &a);
  if (s != TR_OK) {
    fail(s);
    return (int)s;
  }
  progress_on = !a.quiet && isatty(2);
  if (!strcmp(a.cmd, "mesh"))
    return cmd_mesh(&a);
  if (!strcmp(a.cmd, "delaunay"))
    return cmd_delaunay(&a);
  if (!strcmp(a.cmd, "check"))
    return cmd_check(&a);
  return cmd_convert(&a);
}
