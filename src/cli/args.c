/* The command line of the tetrec command: the commands and options it knows, with their
 * help (--help prints them from these tables, so the help and the parser cannot
 * disagree), and the parser that fills a tr_cli_args. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "io/io.h"
#include "tetrec.h"

static const char usage[] =
    "usage: tetrec COMMAND [options] FILES   (tetrec COMMAND --help: that command's options)\n"
    "\n"
    "commands:\n"
    "  mesh IN [-o OUT]        tetrahedralize the volume bounded by the surface IN\n"
    "  delaunay IN [-o OUT]    Delaunay tetrahedralization of the points of IN\n"
    "  check IN MESH           validate MESH (.mesh, .meshb, .msh, or .ele/.node) against IN\n"
    "  check-surface IN [-o F] list every defect of the surface IN\n"
    "  convert IN OUT          convert a surface or mesh between formats\n"
    "  resolve IN -o OUT       the solid of a self-intersecting surface, as a clean surface\n"
    "\n"
    "input formats (by extension): .off .stl .obj .ply .mesh .meshb .msh .node .poly .smesh\n"
    "output: .mesh (Medit), .meshb (binary Medit), .vtu (VTK XML), .vtk (legacy VTK),\n"
    "  .msh (Gmsh; --binary: binary .msh, .vtu, .vtk), .off and .stl (binary;\n"
    "  surfaces only: convert), .node/.ele/.face or a TetGen base name (a name whose\n"
    "  extension has no letter, like out or cube.1); any other extension is an error.\n"
    "  Without -o, IN's name with '.1' (cube.off -> cube.1.node/.ele/.face), like TetGen\n"
    "\n"
    "exit status (= tr_status):\n"
    "  0 ok, 1 usage, 2 I/O error, 3 parse error, 4 invalid input (NaN, bad index,\n"
    "  zero-area triangle, ...), 5 degenerate point set, 6 open or non-manifold surface,\n"
    "  7 self-intersecting input, 8 out of memory or a size limit (--refine-budget:\n"
    "  the mesh made so far is written), 9 invalid mesh, 10 internal error,\n"
    "  11 not implemented\n";


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
     "Validate the tetrahedral mesh MESH (.mesh, .meshb, .msh or .node/.ele) against the\n"
     "surface IN: links, exact orientation, and, when every vertex is known exactly\n"
     "(an --exact .node, or no Steiner points), exact conformity and volume; also the\n"
     "largest distance of a rounded Steiner point from the input surface.\n"},
    {"check-surface", C_CHECK_SURFACE, 1, "check-surface IN [-o FILE] [options]",
     "List every self-intersecting pair of triangles, every open or non-manifold edge and\n"
     "every non-planar input polygon (with its deviation) of the surface IN; exit non-zero\n"
     "when there is any (also zero-area and duplicate triangles). -o FILE (.vtk or .msh)\n"
     "writes the offending triangles and edges, with cell data / physical tag 1\n"
     "intersecting triangle, 2 open edge, 3 non-manifold edge, 4 triangle of a non-planar\n"
     "polygon, 5 zero-area, 6 duplicate triangle, 7 triangle of the fan of a polygon that\n"
     "cannot be triangulated in its plane, for ParaView or Gmsh.\n"},
    {"convert", C_CONVERT, 2, "convert IN OUT [options]",
     "Convert a surface or mesh between formats (OUT: .off .stl .mesh .meshb .vtu .vtk .msh\n"
     "or TetGen).\n"},
    {"resolve", C_RESOLVE, 1, "resolve IN -o OUT [options]",
     "Write the boundary of the solid of the surface IN (the cells where its winding\n"
     "number is >= 1, bounded by the exact arrangement of its triangles: overlapping\n"
     "parts united, duplicates and zero-area triangles absorbed) to OUT, any surface\n"
     "format by its extension (.off .stl .mesh .meshb .vtu .vtk .msh or TetGen). Its\n"
     "corners where input triangles cross are rounded to the nearest doubles; the\n"
     "rounded surface is tested for self-intersections exactly and, while it has any,\n"
     "resolved and rounded again (--rounds). If it still has some, nothing is written\n"
     "and the command exits 7 naming the first pair. What was done goes to stderr.\n"},
};

static const struct option {
  const char *name, *arg;
  unsigned cmds;
  const char *help;
} options[] = {
    {"-o", "OUT", C_MESH | C_DELAUNAY | C_CHECK_SURFACE | C_RESOLVE,
     "output file or TetGen base name"},
    {"-q", NULL, C_ALL, "quiet: errors only"},
    {"-v", NULL, C_ALL, "verbose"},
    {"--stats", "FILE", C_MESH | C_DELAUNAY,
     "write statistics as JSON, also when the run fails (with\n"
     "\"status\" and \"message\"); a FILE named like a mesh or\n"
     "surface file, or naming the input or output, is refused"},
    {"--exact", NULL, C_MESH | C_DELAUNAY,
     "write Steiner points as exact rationals num/den in the\n"
     "TetGen .node (exactly on their edges and facets). Without it\n"
     "every output coordinate is a double: a Steiner point is its\n"
     "nearest double, moved by a few ulps where that is needed to\n"
     "keep every tet strictly positive, so it may lie a hair off\n"
     "its facet (see --strict-doubles)"},
    {"--msh-version", "V", C_MESH | C_DELAUNAY | C_CONVERT | C_CHECK_SURFACE | C_RESOLVE,
     ".msh output format: 4.1 (default) or 2.2; 4.1b and 2.2b\n"
     "are the binary forms (the same as adding --binary)"},
    {"--binary", NULL, C_MESH | C_DELAUNAY | C_CONVERT | C_CHECK_SURFACE | C_RESOLVE,
     "write the binary form of the output format: .msh (Gmsh\n"
     "binary), .vtu (raw appended data), .vtk (legacy binary);\n"
     ".meshb and .stl are binary anyway; any other format is a\n"
     "usage error. Text is the default for .msh, .vtu and .vtk"},
    {"--allow-open", NULL, C_MESH | C_CHECK, "accept open or non-manifold surfaces"},
    {"--check-only", NULL, C_MESH, "only read and validate the input"},
    {"--no-smooth", NULL, C_MESH, "no surface diagonal swaps before recovery"},
    {"--keep-surface", NULL, C_MESH,
     "no Steiner point on the surface: the boundary faces of the\n"
     "output are exactly the input triangles (no smoothing either);\n"
     "fails naming the point where this cannot be done; --quality\n"
     "and --max-volume then add interior points only"},
    {"-Y", NULL, C_MESH, "the same as --keep-surface (TetGen's switch)"},
    {"--surface-tolerance", "EPS", C_MESH | C_CHECK,
     "let the surface move within EPS (> 0) times the input's\n"
     "bounding box diagonal, both ways, for better tets on thin\n"
     "triangles (edge collapses; sharp edges, marker boundaries\n"
     "and segments stay; the bound is proven and goes to --stats).\n"
     "check: verify that bound between IN and MESH's boundary\n"
     "instead of exact conformity"},
    {"--keep-edges", NULL, C_MESH,
     "under refinement, keep every input edge a chain of mesh\n"
     "edges (by default edges between exactly coplanar input\n"
     "triangles with the same marker are merged away)"},
    {"--spacing-radii", NULL, C_MESH,
     "under refinement, refuse a circumcentre only within a\n"
     "vertex's current spacing (the default)"},
    {"--insertion-radii", NULL, C_MESH,
     "under refinement, refuse a circumcentre within a vertex's\n"
     "insertion radius, not its current spacing (fewer points\n"
     "and less CPU; more tets over the ratio bound, more slivers\n"
     "where long edges were split early)"},
    {"--keep-steiner", NULL, C_MESH,
     "leave the recovery's Steiner points where they are (by\n"
     "default the ones on the surface are removed or moved inside\n"
     "where that can be done exactly)"},
    {"--resolve", NULL, C_MESH | C_CHECK,
     "mesh the solid of a self-intersecting or defective surface:\n"
     "the cells where its winding number is >= 1, bounded by the\n"
     "exact arrangement of its triangles (docs/resolve.md); an\n"
     "input that validation accepts meshes as without it; a\n"
     "polygon that cannot be triangulated in its plane is read as\n"
     "a fan, with a warning; with check, validate against that\n"
     "surface"},
    {"--resolve-internal", NULL, C_MESH | C_CHECK,
     "--resolve, keeping the pieces between two solid cells as\n"
     "internal facets"},
    {"--internal", NULL, C_RESOLVE,
     "also write the pieces between two solid cells (internal\n"
     "facets), after the boundary's triangles; stderr says which"},
    {"--rounds", "N", C_RESOLVE,
     "resolve and round at most N times (1 to 100, default 8)\n"
     "until the doubles are free of intersections"},
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
     "under a boundary angle over 120 degrees also after the\n"
     "sliver stage's splits (refinement always does so once;\n"
     "default: off)"},
    {"--max-volume", "V", C_MESH | C_CHECK,
     "refinement until every tet's volume is at most V (check:\n"
     "count the tets over V)"},
    {"-a", "V", C_MESH | C_CHECK, "the same as --max-volume (TetGen's switch)"},
    {"--sizing", "FILE", C_MESH,
     "a size field: FILE (TetGen .mtr: first line the point\n"
     "count and 1, then one target edge length per input point,\n"
     "in the input's point order; 0: no bound there). The size\n"
     "elsewhere is interpolated linearly between the input\n"
     "points; refinement (on by itself) splits every tet whose\n"
     "longest edge is over the mean of its vertices' sizes, and\n"
     "every boundary edge and triangle that is (not under\n"
     "--keep-surface); with --quality and -a all bounds hold"},
    {"-m", "FILE", C_MESH,
     "the same as --sizing (TetGen's -m names no file: it reads\n"
     "IN.mtr; here FILE is given, e.g. -m IN.mtr)"},
    {"--refine-budget", "N", C_MESH,
     "points refinement may add; at N it stops, the mesh made so\n"
     "far (valid and conforming, the bounds not met everywhere)\n"
     "is written and tetrec exits 8\n"
     "(default: 100 per input point + 100,000, + 20 per V of the\n"
     "domain's volume with --max-volume, at most 2^24 or 8 per\n"
     "input point); a volume bound asking for over 8 tets per\n"
     "budget point is refused (exit 8) before refinement starts"},
    {"--refine-rounds", "N", C_MESH,
     "refinement inserts circumcentres in rounds of parallel\n"
     "insertion on --threads threads while N or more bad tets are\n"
     "queued (default: off); the mesh is the same for any number\n"
     "of threads, not the one made without rounds"},
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
    {"--threads", "N", C_MESH | C_DELAUNAY | C_CONVERT,
     "threads for the Delaunay tetrahedralization, for reading a\n"
     "large .node, for the rounds of --refine-rounds and for\n"
     "formatting the output file (default 0: every core); the\n"
     "output is the same for any N, byte for byte"},
    {"-j", "N", C_MESH | C_DELAUNAY | C_CONVERT, "the same as --threads"},
    {"--strict-doubles", NULL, C_MESH,
     "fail (exit 9) when a written double lies farther than\n"
     "2^-40 of the bounding box diagonal from the edge or facet\n"
     "its exact point lies on (a warning otherwise)"},
};
#define NOPTIONS (sizeof options / sizeof options[0])
#define NCOMMANDS (sizeof commands / sizeof commands[0])


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

/* One option with its value (NULL for flags); tr_cli_parse_args checks that it applies
 * to the command once the command is known. */
static tr_status set_option(tr_cli_args *a, const char *name, const char *v)
{
  if (!strcmp(name, "-o"))
    a->out = v;
  else if (!strcmp(name, "--stats")) {
    /* The statistics are written also when the run fails: `--stats IN OUT.mesh` (the
     * value forgotten) would read OUT.mesh, fail, and write JSON over the surface IN. A
     * name with a mesh or surface extension is refused before anything is opened. */
    static const char *mesh_ext[] = {".stl", ".off", ".obj", ".ply", ".poly", ".smesh",
                                     ".mesh", ".meshb", ".node", ".ele", ".face", ".msh",
                                     ".vtk", ".vtu"};
    for (size_t i = 0; i < sizeof mesh_ext / sizeof *mesh_ext; i++)
      if (tr_io_has_ext(v, mesh_ext[i]))
        return tr_error(TR_ERR_USAGE, "--stats FILE writes JSON statistics, and '%s' is named "
                        "like a mesh or surface file it would overwrite (--stats OUT.json IN)",
                        v);
    a->stats = v;
  }
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
  else if (!strcmp(name, "--sizing") || !strcmp(name, "-m"))
    a->sizing = v;
  else if (!strcmp(name, "--optimize") || !strcmp(name, "-O")) {
    if (strlen(v) != 1 || v[0] < '0' || v[0] > '3')
      return tr_error(TR_ERR_USAGE, "%s needs a level 0, 1, 2 or 3, not '%s'", name, v);
    a->optimize = v[0] - '0' + 1;
  }
  else if (!strcmp(name, "--keep-surface") || !strcmp(name, "-Y"))
    a->keep_surface = 1;
  else if (!strcmp(name, "--surface-tolerance")) {
    char *end;
    double x = strtod(v, &end);
    if (!*v || *end || !(x > 0) || !isfinite(x))
      return tr_error(TR_ERR_USAGE, "%s needs a finite number > 0 (a fraction of the "
                      "bounding box diagonal, e.g. 1e-3), not '%s'", name, v);
    a->surface_tolerance = x;
  }
  else if (!strcmp(name, "--keep-edges"))
    a->keep_edges = 1;
  else if (!strcmp(name, "--spacing-radii"))
    a->spacing_radii = 2;
  else if (!strcmp(name, "--insertion-radii"))
    a->spacing_radii = 1;
  else if (!strcmp(name, "--keep-steiner"))
    a->keep_steiner = 1;
  else if (!strcmp(name, "--resolve"))
    a->resolve = 1;
  else if (!strcmp(name, "--resolve-internal") || !strcmp(name, "--internal"))
    a->resolve = 2;
  else if (!strcmp(name, "--rounds")) {
    size_t len = strlen(v);
    int ok = len > 0 && len <= 3 && strspn(v, "0123456789") == len;
    long n = ok ? strtol(v, NULL, 10) : 0;
    if (!ok || n < 1 || n > 100)
      return tr_error(TR_ERR_USAGE, "--rounds needs a whole number from 1 to 100, not '%s'", v);
    a->rounds = (int)n;
  }
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
  else if (!strcmp(name, "--binary"))
    a->msh_version |= TR_WRITE_BINARY;
  else if (!strcmp(name, "--msh-version")) {
    /* the version in the low byte, the binary flag kept from --binary given before */
    int bin = a->msh_version & TR_WRITE_BINARY;
    if (!strcmp(v, "4.1") || !strcmp(v, "4"))
      a->msh_version = 41 | bin;
    else if (!strcmp(v, "2.2") || !strcmp(v, "2"))
      a->msh_version = 22 | bin;
    else if (!strcmp(v, "4.1b"))
      a->msh_version = 41 | TR_WRITE_BINARY;
    else if (!strcmp(v, "2.2b"))
      a->msh_version = 22 | TR_WRITE_BINARY;
    else
      return tr_error(TR_ERR_USAGE, "--msh-version is 4.1, 2.2, 4.1b or 2.2b, not '%s'", v);
  } else if (!strcmp(name, "--round-budget") || !strcmp(name, "--refine-budget") ||
             !strcmp(name, "--refine-rounds")) {
    /* digits only, 1 .. 10^15: strtoull alone would take "-1", "+5" and " 7" */
    size_t len = strlen(v);
    int ok = len > 0 && len <= 16 && strspn(v, "0123456789") == len;
    unsigned long long n = ok ? strtoull(v, NULL, 10) : 0;
    int rounds = !strcmp(name, "--refine-rounds");
    unsigned long long most = rounds ? UINT32_MAX : 1000000000000000ull;
    if (!ok || n == 0 || n > most)
      return tr_error(TR_ERR_USAGE, "%s needs a whole number from 1 to %s, not '%s'", name,
                      rounds ? "4294967295" : "10^15", v);
    if (!strcmp(name, "--round-budget"))
      a->round_budget = n;
    else if (rounds)
      a->refine_rounds = n;
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

/* 1 iff both paths name one existing file (however they are spelled). */
static int same_file(const char *x, const char *y)
{
  struct stat sx, sy;
  return x && y && stat(x, &sx) == 0 && stat(y, &sy) == 0 && sx.st_dev == sy.st_dev &&
         sx.st_ino == sy.st_ino;
}

tr_status tr_cli_parse_args(int argc, char **argv, tr_cli_args *a)
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
  if (a->stats && (same_file(a->stats, a->in) || (a->out && same_file(a->stats, a->out))))
    return tr_error(TR_ERR_USAGE, "--stats %s names the %s file", a->stats,
                    same_file(a->stats, a->in) ? "input" : "output");
  return TR_OK;
}
