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
 */
#ifndef TETREC_H
#define TETREC_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

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
  TR_ERR_UNSUPPORTED = 11    /* a feature not implemented yet */
} tr_status;

/* A stable short name ("TR_ERR_PARSE") for a status. */
const char *tr_status_name(tr_status s);
/* The detailed message of the last failure in the calling thread ("" if none). */
const char *tr_last_error(void);

/* ---- input: a piecewise linear complex (points + triangles + segments) ---- */
typedef struct tr_plc tr_plc;

tr_status tr_plc_create(tr_plc **out);
void tr_plc_destroy(tr_plc *plc);
/* Copies the arrays. xyz: 3*npoints doubles; tris: 3*ntris indices; markers may be NULL. */
tr_status tr_plc_set(tr_plc *plc, const double *xyz, uint32_t npoints, const uint32_t *tris,
                     uint32_t ntris, const int32_t *markers);
/* Reads a surface; the format is chosen from the extension (.off .stl .obj .ply .mesh
 * .node .poly .smesh). Polygons are triangulated exactly in their plane. */
tr_status tr_plc_read(const char *path, tr_plc **out);
uint32_t tr_plc_num_points(const tr_plc *plc);
uint32_t tr_plc_num_triangles(const tr_plc *plc);
const double *tr_plc_points(const tr_plc *plc);
const uint32_t *tr_plc_triangles(const tr_plc *plc);

/* ---- output: a tetrahedral mesh ---- */
typedef struct tr_mesh tr_mesh;

void tr_mesh_destroy(tr_mesh *mesh);
uint32_t tr_mesh_num_vertices(const tr_mesh *mesh);
uint32_t tr_mesh_num_tets(const tr_mesh *mesh);

/* ---- the whole pipeline ---- */
typedef struct tr_options {
  int smooth;      /* surface diagonal swaps before recovery (default 1) */
  int allow_open;  /* mesh the convex hull, keep facets as constraints (default 0) */
  int verbose;     /* 0 quiet, 1 normal, 2 chatty; messages go to stderr */
  uint64_t round_budget; /* star checks the rounding repair may spend (0: 2,000,000) */
  /* quality refinement (src/refine/refine.h), off unless quality_ratio or max_volume > 0 */
  double quality_ratio;        /* radius-edge bound R (e.g. 1.414), 0: off */
  double quality_min_dihedral; /* minimum dihedral target in degrees: not supported yet,
                                  must be 0 (a nonzero value is refused, never ignored) */
  double max_volume;           /* bound on every tet's volume, 0: none */
  uint64_t refine_budget;      /* points refinement may add (0: 100 per input point +
                                  100,000, + 20 per max_volume in the domain's volume) */
} tr_options;
void tr_options_default(tr_options *opt);

/* The rows of the seed paper's Table 14, plus memory. */
typedef struct tr_stats {
  uint64_t surface_nodes, surface_facets;
  uint64_t volume_nodes, volume_elements;
  uint64_t missing_edges, edges_recovered_by_swap, points_added_for_edges;
  uint64_t missing_facets, facets_recovered_by_swap, points_added_for_facets;
  uint64_t surface_swaps, rounding_repairs;
  uint64_t rounding_flips; /* flips that took away tets flat in doubles (output/flatflip.h) */
  double total_seconds, recovery_seconds;
  uint64_t peak_memory_bytes;
  /* shape of the output tets on the written doubles (src/refine/quality.h) and the points
   * quality refinement added */
  uint64_t points_added_for_quality;
  double min_dihedral, max_dihedral, max_radius_edge; /* degrees, ratio */
  uint64_t tets_dihedral_below_5, tets_dihedral_below_10;
  uint64_t dihedral_histogram[18];   /* all six angles of every tet, 10-degree bins */
  uint64_t radius_edge_histogram[7]; /* <1, <1.414, <2, <4, <10, <100, >=100 */
} tr_stats;

/* Delaunay tetrahedralization of a point set (duplicates merged and reported). */
tr_status tr_delaunay(const double *xyz, uint32_t npoints, tr_mesh **out);

/* ---- I/O, input validation and CLI support (owner: io/input engineer) ---- */
/* Checks and repairs the input in place: exact duplicate vertices are merged and
 * duplicate triangles removed, inconsistent orientation is repaired (each closed shell
 * oriented outward). Edges of three or more triangles (internal facets between regions)
 * and free edges inside the domain (cracks, internal fins) are valid. Zero-area
 * triangles (TR_ERR_INPUT), free edges outside the domain, i.e. an open surface
 * (TR_ERR_OPEN unless opt->allow_open), and improperly intersecting triangles
 * (TR_ERR_SELF_INTERSECT) are errors naming the elements. opt may be NULL (defaults). */
tr_status tr_plc_validate(tr_plc *plc, const tr_options *opt);
/* What the last tr_plc_validate repaired, one line per item ("" if nothing). */
const char *tr_plc_report(const tr_plc *plc);
/* Writes the surface (points + triangles + markers) as .mesh, .vtu, .off or TetGen
 * .node/.face (any other name is a TetGen base name). */
tr_status tr_plc_write(const tr_plc *plc, const char *path);
/* Writes a mesh: .mesh (Medit), .vtu (VTK XML), .node/.ele/.face or a TetGen base name
 * (writes base.node, base.ele, base.face). exact != 0: Steiner points as exact
 * rationals num/den in the .node file. */
tr_status tr_mesh_write(const tr_mesh *mesh, const char *path, int exact);
/* Writes the statistics as one JSON object. */
tr_status tr_stats_write_json(const tr_stats *stats, const char *path);
/* The whole pipeline (read -> Delaunay -> recovery -> outer removal). Declared for the
 * CLI; implemented by the pipeline owner. */
tr_status tr_mesh_plc(const tr_plc *plc, const tr_options *opt, tr_mesh **out, tr_stats *stats);

#ifdef __cplusplus
}
#endif
#endif
