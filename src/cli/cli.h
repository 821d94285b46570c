/* Internal pieces of the tetrec command. */
#ifndef TR_CLI_H
#define TR_CLI_H

#include <stdint.h>
#include <stdio.h>

#include "core/plc.h"
#include "core/status.h"
#include "qpoint.h"

/* The commands, as bits of an option's set of commands. */
enum { C_MESH = 1, C_DELAUNAY = 2, C_CHECK = 4, C_CONVERT = 8, C_CHECK_SURFACE = 16,
       C_RESOLVE = 32, C_ALL = 63 };

/* What the command line asked for (args.c). */
typedef struct {
  const char *cmd, *in, *in2, *out, *stats;
  const char *sizing; /* --sizing / -m FILE, or NULL */
  unsigned cmd_bit;
  int quiet, verbose, exact, allow_open, check_only, no_smooth, strict_doubles;
  int keep_surface, keep_steiner, progress, keep_edges;
  int spacing_radii; /* 0: the default, 1: --insertion-radii, 2: --spacing-radii */
  int threads; /* 0: every core */
  int msh_version; /* 41 or 22 */
  int optimize; /* sliver removal level + 1, 0: the default */
  double quality, quality_dih, max_volume, subface_quality; /* 0: off */
  uint64_t refine_budget;                  /* 0: the default */
  uint64_t round_budget; /* 0: the default */
  uint64_t refine_rounds; /* 0: off */
  int recovery;          /* tr_options.recovery */
  int resolve;           /* tr_options.resolve: --resolve 1, --resolve-internal 2 */
  double surface_tolerance; /* --surface-tolerance, 0: off */
  int rounds;               /* resolve --rounds, 0: the default (TR_SNAP_ROUNDS) */
} tr_cli_args;

/* Parses argv into *a: TR_ERR_USAGE with a message for an unknown or misplaced option, a
 * bad value or a wrong number of files; --help and --version print and exit 0. */
tr_status tr_cli_parse_args(int argc, char **argv, tr_cli_args *a);

/* `check`: the validator on the tets of vol, and, when every vertex is known exactly,
 * the exact conformity validator and the exact volume against surface (validated).
 * exact: NULL, or vol->npoints entries, each NULL (the vertex is vol's double) or the
 * exact point read from an --exact .node; the points are moved into the check (entries
 * set to NULL). exact_file: the .node was written with --exact, so its doubles are exact
 * too (without it, vertices beyond the surface's are Steiner points rounded to doubles,
 * whose conformity cannot be verified exactly). allow_open: the surface may be open.
 * bounds (quality_ratio, quality_min_dihedral, max_volume; 0: none) adds a line of the
 * tets over or under each bound given, on the file's doubles. */
tr_status tr_cli_check(const struct tr_plc *surface, const struct tr_plc *vol, tr_qpoint **exact,
                       int exact_file, int allow_open, int verbose, const tr_options *bounds);

/* `check --surface-tolerance EPS` (check_tol.c): the two-sided bound between surface and
 * the boundary of m (built from vol: its faces without a neighbour and vol's triangles),
 * proven; TR_ERR_INVALID_MESH naming a triangle where it does not hold. */
struct tr_mesh;
tr_status tr_cli_check_tolerance(const struct tr_mesh *m, const struct tr_plc *surface,
                                 const struct tr_plc *vol, double eps, int verbose);

/* `check-surface`: prints every defect of the surface in to stdout (check_surface.c),
 * writes them to out (.vtk or .msh; may be NULL), and fails with the status of the worst
 * kind (7 self-intersection, 6 open or non-manifold edge, 4 non-planar polygon,
 * zero-area or duplicate triangle) when there is any. */
tr_status tr_cli_check_surface(const char *in, const char *out, int msh_version, int quiet);

/* `resolve IN -o OUT` (resolve_cmd.c): the boundary of IN's solid by winding number in
 * doubles, free of intersections, written to OUT (any surface format). */
tr_status tr_cli_resolve(const tr_cli_args *a);
/* Reads a->in as --resolve takes it (tr_plc_read_options: a polygon that cannot be
 * triangulated in its plane becomes a fan), with a warning per fanned polygon unless
 * quiet; without --resolve, tr_plc_read_threads. */
tr_status tr_cli_read_input(const tr_cli_args *a, int threads, tr_plc **out);

/* The command's heap policy, first thing in main (heap.c): freed memory is kept for reuse
 * and the heap asks for transparent huge pages, because page faults were a fifth of the
 * command's CPU time. Changes no output. */
void tr_cli_heap_setup(void);

#endif
