/* tetrec: exact conformal boundary recovery for 3D Delaunay tetrahedralization.
 *
 * Public C API. Everything the `tetrec` command does is reachable from here, so a
 * program that embeds tetrec needs no CLI.
 *
 * Conventions, stated once for the whole library:
 *  - A tetrahedron (v0,v1,v2,v3) is positively oriented iff v3 lies on the side of the
 *    plane v0v1v2 into which the right-hand normal (v1-v0)x(v2-v0) points, i.e.
 *    det[v1-v0; v2-v0; v3-v0] > 0. This is the seed paper's hypothesis 2 and CGAL's
 *    orientation(); it is the opposite sign of Shewchuk's orient3d.
 *  - Every tetrahedron tetrec writes is positively oriented.
 *  - Input surface triangles are oriented with right-hand normals pointing out of the
 *    domain (tetrec repairs inconsistent orientation and reports it).
 *  - Indices are 0-based in the API; file formats use their own base.
 *
 * Every fallible function returns a tr_status; on failure tr_last_error() holds a
 * message that says what is wrong and where (file, line, element).
 *
 * Threads: the library has no global mutable state. Every function may be called from
 * several threads at once on distinct objects (tests/api/test_threads.c meshes four
 * inputs on four threads and runs under ThreadSanitizer). Functions taking a const
 * object may also run concurrently on the same object; a function taking a non-const
 * object (tr_plc_set, tr_plc_validate, the destroy functions) needs it to itself.
 * tr_last_error() is per thread. The notes "thread-safe" below repeat this per function.
 *
 * ABI growth: tr_options and tr_stats begin with `size_t size` and only grow at their
 * end. tr_options_default() sets opt->size = sizeof(tr_options); the library reads only
 * the first opt->size bytes and uses defaults for fields beyond them (size 0 means this
 * header's size). A caller sets stats->size to sizeof(tr_stats) (or 0, meaning this
 * header's size, so a zeroed struct is fine) before a call that fills it; the library
 * writes no more than that many bytes and sets size to the number of bytes it filled.
 */
#ifndef TETREC_H
#define TETREC_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version of this header; tr_version() gives the library's (they differ only when a
 * program runs against another build of the shared library than it was compiled with).
 * Both follow meson.build's project version. */
#define TETREC_VERSION_MAJOR 0
#define TETREC_VERSION_MINOR 1
#define TETREC_VERSION_PATCH 0
#define TETREC_VERSION_STRING "0.1.0"

typedef enum tr_status {
  TR_OK = 0,
  TR_ERR_USAGE = 1,          /* bad arguments or options */
  TR_ERR_IO = 2,             /* a file could not be opened, read or written */
  TR_ERR_PARSE = 3,          /* malformed, truncated or unsupported file content */
  TR_ERR_INPUT = 4,          /* well-formed file, invalid geometry (NaN, bad index, ...) */
  TR_ERR_DEGENERATE = 5,     /* the point set spans less than 3D */
  TR_ERR_OPEN = 6,           /* open or non-manifold surface */
  TR_ERR_SELF_INTERSECT = 7, /* two input elements intersect improperly */
  TR_ERR_NOMEM = 8,          /* allocation failed or a size limit was exceeded */
  TR_ERR_INVALID_MESH = 9,   /* the validator found a violated property */
  TR_ERR_INTERNAL = 10,      /* a bug in tetrec: please report it with the input */
  TR_ERR_UNSUPPORTED = 11,   /* a feature not implemented yet */
  TR_ERR_CANCELLED = 12      /* the progress callback asked to stop (tr_options.progress) */
} tr_status;

/* A stable short name ("TR_ERR_PARSE") for a status. Thread-safe. */
const char *tr_status_name(tr_status s);
/* The detailed message of the last failure in the calling thread ("" if none). The
 * buffer is thread-local: thread-safe. */
const char *tr_last_error(void);
/* The library's version (meson.build's project version). Any argument may be NULL.
 * Thread-safe. */
void tr_version(int *major, int *minor, int *patch);
/* Frees memory the library returned to the caller (tr_mesh_point_exact). Thread-safe. */
void tr_free(void *p);
/* Frees the calling thread's cached exact-arithmetic temporaries (kept per thread so
 * that the predicates do not allocate in their loops). A thread that used tetrec calls
 * it before it exits, or its few kilobytes are lost (leak checkers report them). It may
 * use tetrec again afterwards. Thread-safe. */
void tr_thread_cleanup(void);

/* ---- input: a piecewise linear complex (points + triangles + segments) ---- */
typedef struct tr_plc tr_plc;

/* All tr_plc functions: thread-safe on distinct PLCs; the const ones also on one PLC. */
tr_status tr_plc_create(tr_plc **out);
void tr_plc_destroy(tr_plc *plc);
/* Copies the arrays. xyz: 3*npoints doubles; tris: 3*ntris indices; markers may be NULL. */
tr_status tr_plc_set(tr_plc *plc, const double *xyz, uint32_t npoints, const uint32_t *tris,
                     uint32_t ntris, const int32_t *markers);
/* Reads a surface; the format is chosen from the extension (.off .stl .obj .ply .mesh .msh
 * .node .poly .smesh). Polygons are triangulated exactly in their plane. */
tr_status tr_plc_read(const char *path, tr_plc **out);
uint32_t tr_plc_num_points(const tr_plc *plc);
uint32_t tr_plc_num_triangles(const tr_plc *plc);
const double *tr_plc_points(const tr_plc *plc);
const uint32_t *tr_plc_triangles(const tr_plc *plc);
/* Input segments: edges (pairs of point indices, 2*nsegs) that must appear in the mesh
 * (appended to those already given; tr_plc_set drops them with the points). */
tr_status tr_plc_add_segments(tr_plc *plc, const uint32_t *segs, uint32_t nsegs);
/* A hole point: the cell of the domain that contains it (the space enclosed by the
 * facets around it) is not meshed. It must lie strictly inside the domain, on no facet
 * (else tr_mesh_plc fails naming it). A closed shell nested in another with a hole point
 * inside it is a cavity even when it faces outward (see tr_plc_validate). */
tr_status tr_plc_add_hole(tr_plc *plc, double x, double y, double z);
/* A region point: every tet of the cell that contains it gets region id `attribute` in
 * the output (cells without a region point keep tetrec's numbering 1..k by smallest
 * tet). max_volume > 0 bounds the volume of every tet of that cell: quality refinement
 * (src/refine) runs to meet it, with tr_options.max_volume the smaller bound where both
 * are set. A region point outside the domain or on a facet is an
 * error. Hole and region points are kept by tr_plc_set. */
tr_status tr_plc_add_region(tr_plc *plc, double x, double y, double z, int32_t attribute,
                            double max_volume);
uint32_t tr_plc_num_holes(const tr_plc *plc);
uint32_t tr_plc_num_regions(const tr_plc *plc);

/* ---- output: a tetrahedral mesh ---- */
typedef struct tr_mesh tr_mesh;

/* All tr_mesh functions: thread-safe on distinct meshes; the const accessors also on one
 * mesh (they never allocate or cache). Arrays returned stay valid until tr_mesh_destroy. */
void tr_mesh_destroy(tr_mesh *mesh);
uint32_t tr_mesh_num_vertices(const tr_mesh *mesh);
uint32_t tr_mesh_num_tets(const tr_mesh *mesh);
/* 3 doubles per vertex: exactly the doubles the writers print (for a Steiner point its
 * rounded, possibly repaired double; tr_mesh_point_exact gives its exact position). */
const double *tr_mesh_points(const tr_mesh *mesh);
/* 4 vertex indices per tet, every tet positively oriented (see the conventions above). */
const uint32_t *tr_mesh_tets(const tr_mesh *mesh);
/* One region id per tet (the Medit tet reference); NULL for a tr_delaunay mesh. */
const int32_t *tr_mesh_tet_regions(const tr_mesh *mesh);
/* The mesh faces that lie on an input triangle (boundary facets and internal facets
 * alike): 3 vertex indices per face, ordered so that its right-hand normal points the way
 * its input triangle's does (outward on the boundary), and per face the marker of that
 * triangle (tr_plc_set's markers, a file's boundary markers; 0 when it has none). Sorted
 * by input triangle. A tr_delaunay mesh has none (0, NULL). */
uint32_t tr_mesh_num_boundary_faces(const tr_mesh *mesh);
const uint32_t *tr_mesh_boundary_faces(const tr_mesh *mesh);
const int32_t *tr_mesh_boundary_markers(const tr_mesh *mesh);
/* The input triangle of each boundary face (index in the PLC as meshed, see below). Under
 * refinement, exactly coplanar neighbouring triangles form one planar facet
 * (tr_options.keep_edges) and a face may straddle the edges inside it: its triangle is
 * then the facet's triangle that holds the face's exact centroid (the smallest index on
 * a tie); the face lies in the facet, its marker is the facet's. */
const uint32_t *tr_mesh_boundary_triangles(const tr_mesh *mesh);
/* The exact position of vertex v as text "x y z", each coordinate a rational num/den in
 * lowest terms, base 10, den > 0 (an integer when den is 1): for an input vertex the
 * exact value of its double, for a Steiner point its exact position, which lies exactly
 * on its input edge or triangle. *xyz_text is malloc'ed: free it with tr_free. */
tr_status tr_mesh_point_exact(const tr_mesh *mesh, uint32_t v, char **xyz_text);
/* Where vertex v comes from. Indices refer to the PLC as meshed: the input after
 * tr_plc_validate (which merges duplicate vertices and removes duplicate triangles; a
 * valid input keeps its numbering) and smoothing (which swaps diagonals in place and
 * keeps the triangle count). */
enum tr_vertex_origin {
  TR_VERTEX_INPUT = 0,       /* index = the input vertex */
  TR_VERTEX_ON_EDGE = 1,     /* Steiner point on input edge `index` (tr_mesh_input_edge) */
  TR_VERTEX_ON_TRIANGLE = 2, /* Steiner point inside input triangle `index` (in a merged
                                planar facet: the facet's smallest such triangle) */
  TR_VERTEX_INTERIOR = 3     /* Steiner point on no input edge or triangle; index = v */
};
tr_status tr_mesh_vertex_origin(const tr_mesh *mesh, uint32_t v, int *kind, uint32_t *index);
/* The input edges (unique, a < b, sorted) that TR_VERTEX_ON_EDGE indices refer to. */
uint32_t tr_mesh_num_input_edges(const tr_mesh *mesh);
tr_status tr_mesh_input_edge(const tr_mesh *mesh, uint32_t k, uint32_t *a, uint32_t *b);

/* ---- the whole pipeline ---- */
/* Stages, in pipeline order: the indices of tr_stats.stage_seconds and the names that
 * tr_options.progress receives, `-v` prints and --stats writes (tr_stage_name). The
 * validation row excludes its two sub-steps, self-intersection and nesting (the
 * orientation of closed shells, cavities and cells), which have their own rows. Reading
 * and writing are filled by the caller that reads and writes (the CLI does). */
enum tr_stage {
  TR_STAGE_READ, TR_STAGE_VALIDATE, TR_STAGE_SELFINT, TR_STAGE_NESTING, TR_STAGE_SMOOTH,
  TR_STAGE_DELAUNAY, TR_STAGE_EDGES, TR_STAGE_FACETS, TR_STAGE_COLOR, TR_STAGE_SUPPRESS,
  TR_STAGE_REFINE, TR_STAGE_ROUND, TR_STAGE_STATS, TR_STAGE_WRITE, TR_STAGE_COUNT
};
/* Room in tr_stats.stage_seconds, so that a stage added later leaves the fields after the
 * array where they are (entries from TR_STAGE_COUNT on are 0). Before version 1.0 a new
 * stage may still take its place in pipeline order and move the indices of the stages
 * after it (as "refinement" did): use the enum names, not numbers. */
#define TR_STAGE_SLOTS 24
/* "reading", "validation", "self_intersection", "nesting", "smoothing", "delaunay",
 * "edge_recovery", "facet_recovery", "coloring", "suppression", "refinement", "rounding",
 * "statistics" (the quality figures of tr_stats, measured on the mesh made), "writing";
 * NULL out of range.
 * Thread-safe. */
const char *tr_stage_name(int stage);

typedef struct tr_options {
  size_t size;     /* sizeof(tr_options), set by tr_options_default (ABI growth) */
  int smooth;      /* surface diagonal swaps before recovery (default 1) */
  int allow_open;  /* mesh the convex hull, keep facets as constraints (default 0) */
  int verbose;     /* 0 quiet, 1 normal, 2 chatty; messages go to stderr */
  uint64_t round_budget; /* star checks the rounding repair may spend (0: 2,000,000) */
  /* Called by tr_mesh_plc, from the calling thread, at the start (fraction 0) and end
   * (fraction 1) of each stage it runs, in this order: "validation" (its self-
   * intersection and nesting sub-steps included), "smoothing" (unless smooth is 0),
   * "delaunay", "edge_recovery", "facet_recovery", "coloring", "refinement" (only with a
   * quality or volume bound), "rounding". A non-zero
   * return cancels the run: tr_mesh_plc frees everything it allocated, sets *out to NULL
   * and returns TR_ERR_CANCELLED. NULL: none (default). progress_user is passed back as
   * `user`. */
  int (*progress)(void *user, const char *stage, double fraction);
  void *progress_user;
  int recovery;    /* 0 default; 1 the paper's algorithm only: Swap23/Swap44 then pipels for
                      edges, Swap32 then clusterels for facets (no general flips, midpoint
                      splits, Lawson flips, hub splits or cavity retriangulation); 2 the
                      default without the general flips for facets, so missing facets go
                      from Swap32 straight to cavity retriangulation (for comparisons) */
  int keep_surface;      /* no Steiner point on the surface: the output's boundary faces
                            are exactly the input triangles, or the call fails naming the
                            point (TetGen's -Y; implies no smoothing; default 0). Quality
                            refinement and sliver removal then add interior points only;
                            quality_subface_ratio with it is TR_ERR_USAGE */
  int strict_doubles; /* a written double farther than 2^-40 of the bounding box diagonal
                         from the constraint its exact point lies on makes tr_mesh_plc fail
                         with TR_ERR_INVALID_MESH (default 0: a warning on stderr) */
  /* quality refinement (src/refine/refine.h), off unless quality_ratio or max_volume > 0 */
  double quality_ratio;        /* radius-edge bound R (e.g. 1.414), 0: off */
  double quality_min_dihedral; /* minimum dihedral target in degrees (0: none; at most 70):
                                  sliver removal works on tets under it, which needs
                                  optimize >= 1; a warning counts the tets left under it */
  double max_volume;           /* bound on every tet's volume, 0: none */
  uint64_t refine_budget;      /* points refinement may add (0: 100 per input point +
                                  100,000, + 20 per max_volume in the domain's volume,
                                  at most 2^24 or 8 per input point); volume bounds that
                                  ask for over 8 tets per budget point are refused
                                  (TR_ERR_NOMEM) before refinement starts */
  int keep_steiner; /* 1: the recovery's Steiner points stay where they are (on the input
                       edges and facets, exact rationals); 0 (default): the suppression
                       stage removes them or moves them inside where it can */
  int optimize; /* sliver removal after quality refinement (src/sliver/sliver.h), run only
                   when refinement runs: 0 off, 1 flips that raise the smallest dihedral
                   angle, 2 those flips and smoothing of interior points, 3 (default)
                   also new points at slivers: interior ones
                   (src/sliver/insert.c) and, under the worst tets, exact ones on their
                   input edges and facets (src/sliver/caps.c, src/sliver/sliver.c) */
  int threads; /* threads for the Delaunay stage and refinement's rounds of parallel
                  insertion (docs/refinement.md): 0 (default) every online core, N > 0 at
                  most N (64 at most are used); the output is the same byte for byte for
                  any value. Negative: TR_ERR_USAGE */
  double quality_subface_ratio; /* with refinement: sub-faces whose radius-edge ratio
                                   (circumradius / shortest edge) is above it are split for
                                   their shape (src/refine/subshape.c), unless a small
                                   input angle forces it; 0 (default): off, else >= 1 */
  int keep_edges; /* refinement (quality_ratio / max_volume): 0 (default) merges input
                     triangles that are exactly coplanar (exact orient3d), share a
                     manifold edge, have the same marker and lie on opposite sides of it
                     into one planar facet, whose inner edges are no constraints: sub-faces
                     may cross them (they need not be chains of mesh edges; the facet is
                     covered exactly). 1: every input edge stays a chain of mesh edges */
  int refine_spacing_radii; /* refinement: 1 (default) refuses a circumcentre only within a
                               vertex's current spacing (its insertion radius, shrunk by the
                               points put next to it since); 0 within its insertion radius,
                               which leaves more tets over the ratio bound and more slivers
                               on long thin parts, for fewer points and less CPU
                               (src/refine/refine.c) */
  int refine_partial; /* what reaching refine_budget does. 0 (default): tr_mesh_plc fails
                         with TR_ERR_NOMEM and no mesh. 1: refinement stops there and the
                         rest of the pipeline (sliver removal, rounding) runs on the mesh
                         made so far, which is returned with TR_OK: valid and conforming,
                         the bounds not met everywhere (tr_stats.refine_budget_reached = 1,
                         tets_over_bounds counts the tets left over them). The CLI sets it,
                         writes that mesh and exits 8 */
  /* A size field for refinement (src/refine/sizing.c): sizing[i] > 0 is the target edge
   * length at input point i (the plc's points as passed to tr_mesh_plc: after
   * tr_plc_validate's merges when the caller validated it, as given otherwise; exact
   * duplicates merged later keep the smaller value), 0 no bound there. nsizing must be
   * tr_plc_num_points. The size at any other point is interpolated linearly over the
   * Delaunay tetrahedralization of the input points; a tet whose longest edge is over
   * the mean of its vertices' sizes is refined, and so are the boundary pieces (edges,
   * triangles) whose longest edge is over the mean of theirs (except under
   * keep_surface). It turns refinement on by itself and composes with the other bounds.
   * NULL / 0 (default): none. The array is read during the call only */
  const double *sizing;
  uint32_t nsizing;
  /* Self-intersecting or defective input (issue 49, docs/resolve.md): 1 meshes the solid
   * of the input's winding number (the cells where it is >= 1: the union of the
   * positively oriented parts) bounded by the exact arrangement of the input triangles;
   * pieces between two solid cells are dropped, or kept as internal facets with 2. An
   * input that validation accepts (with its repairs: duplicates merged, triangles turned
   * to agree with their neighbours and outward) is meshed as validated: the same mesh as
   * with 0. Of the others, one whose winding number is not defined (open, or triangles
   * oriented against their neighbours) is TR_ERR_OPEN naming the edge and triangles. Boundary vertices that are rational points and no doubles are mesh
   * vertices with exact points (written exactly by the exact writers, rounded like Steiner
   * points otherwise); on such a surface surface_tolerance and hole points are not
   * implemented yet (TR_ERR_UNSUPPORTED naming the mode; region points work). 0
   * (default): off */
  int resolve;
  /* > 0: the surface may be re-triangulated before recovery (src/simplify,
   * docs/simplify.md) so that every point of the meshed boundary lies within
   * surface_tolerance times the input's bounding box diagonal of the input surface and
   * every point of the input within that distance of the boundary, proven and measured
   * (tr_stats.surface_tolerance_bound). Sharp edges, marker boundaries, open edges and
   * segments stay chains of edges; vertices keep their input coordinates. 0 (default):
   * the input surface exactly. Negative or not finite: TR_ERR_USAGE */
  double surface_tolerance;
  /* > 0: quality refinement inserts circumcentres in rounds of parallel insertion on
   * `threads` threads while at least this many bad tets are queued (docs/refinement.md,
   * "Parallel refinement"); the mesh is the same for any thread count, but another mesh
   * than without rounds. 0 (default): off, one thread */
  uint32_t refine_rounds;
  /* 1: the caller takes the exact mesh (tr_mesh_point_exact; tr_mesh_write with exact to
   * a TetGen .node), as the CLI's --exact does. The Steiner points and resolve's rational
   * corners stay at their nearest doubles in tr_mesh_points, unrepaired: a tet may be
   * flat or inverted there (a warning counts them; tr_mesh_write then refuses every
   * output but the exact one), while on the exact points every tet is positive. So a mesh
   * is returned where no doubles exist for it (two exact corners with one nearest double),
   * and no time goes to a repair nobody uses. 0 (default): the doubles are repaired until
   * every tet is positive on them, or the call fails with TR_ERR_INVALID_MESH */
  int keep_exact;
} tr_options;
/* Sets every field to its default, size included. Thread-safe. */
void tr_options_default(tr_options *opt);

/* tr_plc_read as `opt` will mesh the surface (NULL: tr_plc_read). Its threads read a
 * TetGen point list in parallel. With resolve, a polygon of one loop that cannot be
 * triangulated in its plane (self-overlapping, or all corners collinear) is read as the
 * fan of its loop from its first corner, instead of TR_ERR_INPUT: the winding number
 * that resolve meshes counts any surface the loop bounds, and a planar loop covers each
 * point of its plane as often as its fan does. tr_plc_num_fans counts them and
 * tr_plc_fan_notes gives the first ten reasons, one per line ("" when none). */
tr_status tr_plc_read_options(const char *path, const tr_options *opt, tr_plc **out);
uint32_t tr_plc_num_fans(const tr_plc *plc);
const char *tr_plc_fan_notes(const tr_plc *plc);

/* The rows of the seed paper's Table 14, plus memory and per-stage times. */
typedef struct tr_stats {
  size_t size; /* see "ABI growth" at the top: in, the caller's size; out, bytes filled */
  uint64_t surface_nodes, surface_facets;
  uint64_t volume_nodes, volume_elements;
  uint64_t missing_edges, edges_recovered_by_swap, points_added_for_edges;
  uint64_t missing_facets, facets_recovered_by_swap, points_added_for_facets;
  uint64_t surface_swaps, rounding_repairs;
  uint64_t rounding_flips; /* flips that took away tets flat in doubles (output/flatflip.h) */
  /* input semantics: hole and region points given, nested shells made cavities (holding a
   * hole point, or given facing into themselves with no region point in them) and
   * inclusions (regions of their own) */
  uint64_t hole_points, region_points, cavities, inclusions;
  double total_seconds, recovery_seconds;
  uint64_t peak_memory_bytes;
  double stage_seconds[TR_STAGE_SLOTS]; /* wall-clock time of each stage (enum tr_stage) */
  uint64_t facets_recovered_by_cavity; /* missing facets recovered by cavity
                                          retriangulation, without Steiner points */
  /* Steiner points in the output by where they lie, and the boundary ones taken off the
   * surface after recovery (src/suppress): removed, or relocated into the interior */
  uint64_t steiner_on_edges, steiner_on_facets, steiner_interior;
  uint64_t steiner_removed, steiner_relocated;
  double double_deviation; /* tr_mesh_double_deviation of the written doubles */
  /* shape of the output tets on the written doubles (src/refine/quality.h) and the points
   * quality refinement added */
  uint64_t points_added_for_quality;
  double min_dihedral, max_dihedral, max_radius_edge; /* degrees, ratio */
  uint64_t tets_dihedral_below_5, tets_dihedral_below_10;
  uint64_t dihedral_histogram[18];   /* all six angles of every tet, 10-degree bins */
  uint64_t radius_edge_histogram[7]; /* <1, <1.414, <2, <4, <10, <100, >=100 */
  /* sliver removal (src/sliver/sliver.h): points it added, net of the interior points
   * its last-resort cavities took out (the output has that many vertices more than
   * without the stage), flips it made, interior points it moved */
  uint64_t points_added_for_sliver, sliver_flips, sliver_points_smoothed;
  /* input edges inside merged planar facets under refinement (tr_options.keep_edges):
   * no constraints, so not kept as chains of mesh edges */
  uint64_t input_edges_merged;
  /* refinement reached its point budget (1) and, under tr_options.refine_partial, returned
   * the mesh made so far; tets_over_bounds: tets of the output whose radius-edge ratio is
   * over quality_ratio or whose volume is over its bound (max_volume, its region's), in
   * doubles, those a small input angle exempts included; both 0 without refinement */
  uint64_t refine_budget_reached, tets_over_bounds;
  /* of tets_dihedral_below_10, those standing on a thin input triangle (one of their edges
   * on a boundary face inside an input triangle with a corner under 10 degrees, not merged
   * into a planar facet): every boundary face in such a triangle is thin too, and
   * refinement leaves the tets on them (src/refine/thin.c); and the number of those
   * triangles */
  uint64_t tets_dihedral_below_10_on_thin_input, thin_input_triangles;
  /* peak_memory_bytes / volume_elements (0 without tets): the memory a tet costs at the
   * peak, the figure that says how large a mesh fits in a given memory. The command
   * measures the peak again after writing, so there it covers the whole run */
  double bytes_per_tet;
  /* tr_options.surface_tolerance: the two-sided distance between the input surface and
   * the simplified one, measured (an upper bound, divided by the diagonal; 0 without
   * the option or when nothing changed), the edge collapses made and the time taken
   * (part of the validation row of stage_seconds) */
  double surface_tolerance_bound;
  uint64_t surface_collapses;
  double surface_tolerance_seconds;
  uint64_t surface_flips; /* edge flips made by the same stage */
} tr_stats;

/* Delaunay tetrahedralization of a point set (duplicates merged and reported).
 * Thread-safe. */
tr_status tr_delaunay(const double *xyz, uint32_t npoints, tr_mesh **out);

/* ---- I/O, input validation and CLI support ----
 * Thread-safe on distinct objects; the writers also on one mesh or PLC. */
/* Checks and repairs the input in place: exact duplicate vertices are merged and
 * duplicate triangles removed, inconsistent orientation is repaired (each closed shell
 * oriented outward, cavities into themselves). A closed shell nested in the domain is a
 * cavity if, as given, most of its triangles face into it (a tie: a cavity too) or a
 * hole point lies in it; otherwise it is an inclusion, meshed as a region of its own.
 * Each nested shell's kind is in tr_plc_report. Edges of three or more triangles (internal facets between regions)
 * and free edges inside the domain (cracks, internal fins) are valid. Zero-area
 * triangles (TR_ERR_INPUT), free edges outside the domain, i.e. an open surface
 * (TR_ERR_OPEN unless opt->allow_open), and improperly intersecting triangles
 * (TR_ERR_SELF_INTERSECT) are errors naming the elements. opt may be NULL (defaults). */
tr_status tr_plc_validate(tr_plc *plc, const tr_options *opt);
/* What the last tr_plc_validate repaired, one line per item ("" if nothing). */
const char *tr_plc_report(const tr_plc *plc);
/* Writes the surface (points + triangles + markers) as .mesh, .meshb, .vtu, .vtk, .msh,
 * .off, .stl (binary, float coordinates: the format has no others) or TetGen .node/.face;
 * a name whose extension has no letter ("out", "cube.1") is a TetGen base name; any other
 * extension is TR_ERR_USAGE. */
tr_status tr_plc_write(const tr_plc *plc, const char *path);
/* Writes a mesh: .mesh (Medit), .meshb (binary Medit), .vtu (VTK XML), .vtk (legacy VTK),
 * .msh (Gmsh 4.1), .node/.ele/.face or a TetGen base name as above (writes base.node, base.ele,
 * base.face); any other extension is TR_ERR_USAGE. exact != 0: Steiner points as exact
 * rationals num/den in the .node file. Tets carry their region (Medit reference, .ele
 * attribute, VTU/VTK "region" cell data, Gmsh physical tag). The faces written are those
 * of tr_mesh_boundary_faces with their markers (Medit triangle references, .face
 * markers, VTU and VTK triangle cells after the tets with "marker" cell data, Gmsh physical
 * tags), plus, for an open input meshed within its convex hull, the hull faces with
 * marker 0; a tr_delaunay mesh writes its hull faces with marker 1. */
tr_status tr_mesh_write(const tr_mesh *mesh, const char *path, int exact);
/* The same with the Gmsh format version of a .msh output: 41 (4.1) or 22 (2.2), to which
 * TR_WRITE_BINARY may be added (msh_version = 41 | TR_WRITE_BINARY): the binary form of
 * .msh (Gmsh binary, little-endian), .vtu (raw appended data, UInt64 headers) and .vtk
 * (legacy binary, big-endian); other formats refuse it (TR_ERR_USAGE), except .meshb and
 * .stl, which are binary anyway. */
#define TR_WRITE_BINARY 0x100
tr_status tr_mesh_write_ex(const tr_mesh *mesh, const char *path, int exact, int msh_version);
tr_status tr_plc_write_ex(const tr_plc *plc, const char *path, int msh_version);
/* The largest distance of a written (double) Steiner point of mesh from the input edge or
 * facet of plc (the validated input it was meshed from) that its exact point lies on,
 * divided by the diagonal of plc's bounding box; *vertex = that point (UINT32_MAX if every
 * Steiner point is written exactly). Above 2^-40 the CLI warns, or fails with
 * --strict-doubles (tr_options.strict_doubles). */
tr_status tr_mesh_double_deviation(const tr_mesh *mesh, const tr_plc *plc, double *dev,
                                   uint32_t *vertex);
/* Writes the statistics as one JSON object ("status": "TR_OK", then one key per field,
 * stage_seconds as {"reading": ..., one key per tr_stage_name}). */
tr_status tr_stats_write_json(const tr_stats *stats, const char *path);
/* The same for a run that ended with `status` (its tr_status_name) and `message`. */
tr_status tr_stats_write_json_status(const tr_stats *stats, tr_status status,
                                     const char *message, const char *path);
/* The whole pipeline (validation -> smoothing -> Delaunay -> edge and facet recovery ->
 * outer removal by coloring -> rounding). opt and stats may be NULL. Thread-safe: runs on
 * several threads at once give the same meshes as one after the other. */
tr_status tr_mesh_plc(const tr_plc *plc, const tr_options *opt, tr_mesh **out, tr_stats *stats);

#ifdef __cplusplus
}
#endif
#endif
