#define _POSIX_C_SOURCE 200809L /* clock_gettime, isatty */
/* The tetrec command. Exit status = the tr_status of the first failure (0 on success),
 * so scripts can tell a bad file from a bad surface from a bug. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "delaunay/delaunay.h"
#include "io/io.h"
#include "pipeline/pipeline.h"
#include "refine/refine_stage.h"
#include "resolve/resolve.h"
#include "tetrec.h"

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

static void print_report(const tr_cli_args *a, const tr_plc *plc)
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
static int finish(const tr_cli_args *a, tr_stats *st, double t0, tr_status s)
{
  st->total_seconds = now() - t0;
  /* the peak of the whole process, writing included (tr_mesh_plc measured it before) */
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru) == 0 &&
      (uint64_t)ru.ru_maxrss * 1024u > st->peak_memory_bytes)
    st->peak_memory_bytes = (uint64_t)ru.ru_maxrss * 1024u; /* Linux: kilobytes */
  st->bytes_per_tet =
      st->volume_elements ? (double)st->peak_memory_bytes / (double)st->volume_elements : 0;
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
static tr_status check_names(const tr_cli_args *a, const char *path)
{
  TR_CHECK(tr_io_check_out_name(path, 0));
  if (a->msh_version & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  if (a->exact && tr_io_out_format(path) != TR_OUT_TETGEN)
    return tr_error(TR_ERR_USAGE, "--exact writes exact rationals only to a TetGen .node file, "
                    "not to %s", path);
  return TR_OK;
}

/* Every output file can be created: checked once the input is read (a missing input is the
 * better message), before the work that takes time. */
static tr_status check_writable(const tr_cli_args *a, const char *path)
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
static void warn_nonplanar(const tr_cli_args *a, const tr_plc *plc)
{
  tr_nonplanar *np = NULL;
  uint32_t n = 0;
  if (a->quiet || tr_plc_nonplanar(plc, &np, &n) != TR_OK)
    return;
  /* a polygon read as a fan was named when it was read (tr_cli_read_input) */
  uint32_t kept = 0;
  for (uint32_t i = 0, f = 0; i < n; i++) {
    while (f < plc->nfans && plc->fan_facet[f] < np[i].facet)
      f++;
    if (f == plc->nfans || plc->fan_facet[f] != np[i].facet)
      np[kept++] = np[i];
  }
  n = kept;
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

static int cmd_mesh(const tr_cli_args *a)
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
  if (a->spacing_radii)
    opt.refine_spacing_radii = a->spacing_radii - 1;
  opt.quality_ratio = a->quality;
  opt.quality_min_dihedral = a->quality_dih;
  opt.quality_subface_ratio = a->subface_quality;
  opt.max_volume = a->max_volume;
  opt.refine_budget = a->refine_budget;
  opt.refine_rounds = (uint32_t)a->refine_rounds;
  opt.keep_exact = a->exact; /* check_names: its output is a .node */
  opt.refine_partial = 1; /* the mesh at the budget is written, then exit 8 */
  if (a->optimize)
    opt.optimize = a->optimize - 1;
  opt.threads = a->threads;
  opt.surface_tolerance = a->surface_tolerance;
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
    s = tr_cli_read_input(a, tr_io_thread_count(a->threads), &plc);
  }
  stats.stage_seconds[TR_STAGE_READ] = now() - t0;
  if (s == TR_OK && a->verbose)
    fprintf(stderr, "tetrec: %-22s %.3f s\n", tr_stage_name(TR_STAGE_READ),
            stats.stage_seconds[TR_STAGE_READ]);
  if (s == TR_OK)
    s = a->check_only ? (a->stats ? tr_io_check_file_writable(a->stats) : TR_OK)
                      : check_writable(a, path);
  /* the sizes index the points as read: validation's merges carry them (plc.h) */
  if (s == TR_OK && a->sizing)
    s = tr_read_mtr_file(a->sizing, plc->npoints, &plc->vsize);
  if (s == TR_OK)
    warn_nonplanar(a, plc); /* the polygons as read, before --resolve replaces them */
  if (s == TR_OK && a->resolve) {
    progress("resolving", a->in);
    tr_options ropt = opt; /* the pipeline below meshes plc as it now is */
    ropt.resolve = a->resolve;
    s = tr_resolve_replace(&plc, &ropt, a->verbose);
  }
  if (s == TR_OK) {
    progress("validating", a->in);
    /* --resolve validated it already when it is valid as given (report included) */
    if (!plc->validated)
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
  int bounded = a->quality > 0 || a->max_volume > 0 || a->sizing;
  for (uint32_t i = 0; i < plc->nregions; i++)
    bounded |= plc->region_maxvol[i] > 0;
  if (a->optimize > 1 && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: -O/--optimize has no effect without quality refinement "
            "(--quality, --max-volume or a region's maximum volume)\n");
  if (a->subface_quality > 0 && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --subface-quality has no effect without quality "
            "refinement (--quality, --max-volume or a region's maximum volume)\n");
  if (a->spacing_radii && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --%s-radii has no effect without quality "
            "refinement (--quality, --max-volume or a region's maximum volume)\n",
            a->spacing_radii == 2 ? "spacing" : "insertion");
  if (a->keep_edges && !bounded && !a->quiet)
    fprintf(stderr, "tetrec: warning: --keep-edges has no effect without quality refinement: "
            "every input edge is kept anyway\n");
  /* The pipeline (src/pipeline): Delaunay, edge and facet recovery, outer removal. With
   * --exact (tr_options.keep_exact, checked above to go to a .node), a rounding that
   * cannot be repaired is a warning, not a failure: the exact points are written. */
  tr_mesh *mesh = NULL;
  progress("meshing", a->in);
  progress_line line = {now(), a->progress ? 0.0 : 1.0, 0};
  if (a->progress || progress_on) {
    opt.progress = stage_progress;
    opt.progress_user = &line;
  }
  opt.sizing = plc->vsize;
  opt.nsizing = plc->vsize ? plc->npoints : 0;
  unsigned flags = a->keep_steiner ? TR_PIPE_KEEP_STEINER : 0;
  if (!a->stats) /* quality figures only go to --stats (and -v's notes) */
    flags |= TR_PIPE_NO_QUALITY;
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
    s = tr_mesh_write_threads(mesh, path, a->exact, a->msh_version,
                              tr_io_thread_count(a->threads));
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

/* A stage's time into the statistics, and on stderr with -v. */
static void stage_done(const tr_cli_args *a, tr_stats *st, int stage, double t)
{
  st->stage_seconds[stage] = now() - t;
  if (a->verbose && !a->quiet)
    fprintf(stderr, "tetrec: %-22s %.3f s\n", tr_stage_name(stage), st->stage_seconds[stage]);
}

static int cmd_delaunay(const tr_cli_args *a)
{
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  double t0 = now(), t;
  char *out = a->out ? NULL : default_out(a->in);
  const char *path = a->out ? a->out : out;
  if (!path)
    return finish(a, &stats, t0, tr_error(TR_ERR_NOMEM, "out of memory"));
  tr_status s = check_names(a, path);
  tr_plc *plc = NULL;
  if (s == TR_OK) {
    progress("reading", a->in);
    t = now();
    s = tr_plc_read_threads(a->in, &plc, tr_io_thread_count(a->threads));
    stage_done(a, &stats, TR_STAGE_READ, t);
  }
  if (s == TR_OK)
    s = check_writable(a, path);
  tr_mesh *mesh = NULL;
  if (s == TR_OK) {
    progress("tetrahedralizing", a->in);
    t = now();
    s = tr_delaunay_build_threads(tr_plc_points(plc), tr_plc_num_points(plc), a->threads,
                                  &mesh);
    stage_done(a, &stats, TR_STAGE_DELAUNAY, t);
    stats.surface_nodes = tr_plc_num_points(plc);
    stats.surface_facets = tr_plc_num_triangles(plc);
  }
  tr_plc_destroy(plc);
  if (s == TR_OK) {
    /* the writers read the store as it is (canonical order: real tets first), so the
     * dense copy of the tets that tr_delaunay attaches for tr_mesh_tets is not made */
    progress("writing", path);
    t = now();
    s = tr_mesh_write_threads(mesh, path, a->exact, a->msh_version,
                              tr_io_thread_count(a->threads));
    stage_done(a, &stats, TR_STAGE_WRITE, t);
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

static int cmd_check(const tr_cli_args *a)
{
  tr_plc *surf = NULL, *vol = NULL;
  tr_qpoint **exact = NULL;
  int exact_file = 0;
  tr_options opt;
  tr_options_default(&opt);
  opt.allow_open = a->allow_open;
  tr_status s = tr_cli_read_input(a, 1, &surf);
  if (s == TR_OK)
    warn_nonplanar(a, surf);
  opt.resolve = a->resolve;
  if (s == TR_OK && a->resolve) /* the surface the mesh was made for */
    s = tr_resolve_replace(&surf, &opt, a->verbose);
  if (s == TR_OK && !surf->validated)
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
  opt.quality_ratio = a->quality;
  opt.quality_min_dihedral = a->quality_dih;
  opt.max_volume = a->max_volume;
  opt.surface_tolerance = a->surface_tolerance;
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

static int cmd_convert(const tr_cli_args *a)
{
  tr_plc *plc = NULL;
  tr_status s = tr_io_check_out_name(a->in2, 1);
  if (s == TR_OK && (a->msh_version & TR_WRITE_BINARY))
    s = tr_io_check_binary_name(a->in2);
  if (s == TR_OK)
    s = tr_plc_read_threads(a->in, &plc, tr_io_thread_count(a->threads));
  if (s == TR_OK)
    s = tr_io_check_writable(a->in2);
  if (s == TR_OK) {
    warn_nonplanar(a, plc);
    s = tr_plc_write_threads(plc, a->in2, a->msh_version, tr_io_thread_count(a->threads));
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
  tr_cli_args a;
  tr_status s = tr_cli_parse_args(argc, argv, &a);
  if (s != TR_OK) {
    fail(s);
    return (int)s;
  }
  progress_on = !a.quiet && isatty(2);
  switch (a.cmd_bit) {
  case C_MESH: return cmd_mesh(&a);
  case C_DELAUNAY: return cmd_delaunay(&a);
  case C_CHECK: return cmd_check(&a);
  case C_RESOLVE:
    s = tr_cli_resolve(&a);
    return s == TR_OK ? 0 : fail(s);
  case C_CHECK_SURFACE: {
    /* check-surface writes its .vtk as text (check_surface.c): --binary is for its .msh */
    s = TR_OK;
    if (a.out && (a.msh_version & TR_WRITE_BINARY) && tr_io_out_format(a.out) != TR_OUT_MSH)
      s = tr_error(TR_ERR_USAGE, "%s: check-surface writes .vtk as text only; --binary "
                   "applies to its .msh", a.out);
    if (s == TR_OK)
      s = tr_cli_check_surface(a.in, a.out, a.msh_version, a.quiet);
    return s == TR_OK ? 0 : fail(s);
  }
  default: return cmd_convert(&a);
  }
}
