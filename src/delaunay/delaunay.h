/* Incremental Bowyer-Watson Delaunay tetrahedralization of a point set.
 *
 * The result is the unique Delaunay tetrahedralization of the symbolically perturbed
 * points (tr_insphere_sos with the input indices as perturbation order), so cospherical
 * and coplanar inputs such as integer grids get one well-defined answer, the same on
 * every machine. The convex hull is closed by ghost tets (a, b, c, TR_GHOST): face 3 of
 * a ghost is a hull face, oriented so that tr_orient3d(a, b, c, x) > 0 exactly for points
 * x strictly outside the hull across that face.
 *
 * Conflict rule (who is in the cavity of a new point p):
 *   real tet  t: tr_insphere_sos(t, p) > 0.
 *   ghost tet (a,b,c,G): orient3d(a,b,c,p) > 0 (p strictly beyond the hull face), or
 *     orient3d(a,b,c,p) == 0 and the real tet behind the face conflicts with p.
 *   The coplanar case is forced: a ghost and its real neighbour must agree there, else
 *   the new tet built on their shared face would be flat. It is also what the perturbed
 *   (lifted) point set says: a coplanar p strictly inside the face's circumcircle is
 *   strictly inside the neighbour's sphere, strictly outside it is outside, and on the
 *   circle the perturbation decides, for both tets at once.
 *
 * Vertex ids of the mesh are the input indices. Duplicate points: the first (lowest
 * index) of each group of exactly equal points is kept, the others get no tet;
 * m->dup_map[i] is the kept index and m->ndup their number.
 */
#ifndef TR_DELAUNAY_H
#define TR_DELAUNAY_H

#include "../mesh/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Builds the Delaunay mesh (with its ghost tets) of n points. TR_ERR_INPUT for a
 * non-finite coordinate, TR_ERR_DEGENERATE when the distinct points span less than 3D. */
tr_status tr_delaunay_build(const double *xyz, uint32_t n, struct tr_mesh **out);

/* The same with `threads` threads (0: every online core, see tr_delaunay_thread_count).
 * The store is the same byte for byte for any number of threads: the tetrahedralization
 * is unique and tr_delaunay_canonical orders it. One thread is the serial build. */
tr_status tr_delaunay_build_threads(const double *xyz, uint32_t n, int threads,
                                    struct tr_mesh **out);
/* Points inserted serially before the threads start, per thread: below that the threads
 * would meet in the few tets there are. */
#define TR_DT_SERIAL_PREFIX 4096u
/* For tests: nthreads threads (1..64) after a serial prefix of `prefix` points. */
tr_status tr_delaunay_build_ex(const double *xyz, uint32_t n, int nthreads, uint32_t prefix,
                               struct tr_mesh **out);
/* Threads for an option value: threads itself (at most 64), or 0: the online cores. */
int tr_delaunay_thread_count(int threads);

/* Inserts n exact points (copied) into a Delaunay mesh m as its next vertices, in order,
 * by Bowyer-Watson with exact predicates (qinsert.c), then puts the store in canonical
 * order. Each point must differ from m's points; one outside their hull grows it. */
tr_status tr_delaunay_insert_exact(struct tr_mesh *m, tr_qpoint *const *q, uint32_t n);
/* The Delaunay mesh of nd distinct double points and n distinct exact points after them
 * (copied), every predicate exact (qinsert.c): for when the doubles alone span no tet
 * (fewer than four, or all in a plane: --resolve of a small solid whose corners are mostly
 * rational), where tr_delaunay_build cannot start. The first simplex is the first four
 * points in order that span one; the rest follow in order; canonical store. */
tr_status tr_delaunay_build_exact(const double *xyz, uint32_t nd, tr_qpoint *const *q,
                                  uint32_t n, struct tr_mesh **out);

/* Puts the tet store in canonical order (canon.c): real tets first, sorted by vertex
 * tuple, each rotated (orientation kept) to its smallest vertex first, then the ghosts;
 * free slots dropped, neighbours renumbered, flags cleared, v2t[v] the last slot with v
 * (TR_NONE: none).
 * The store then depends only on the tetrahedralization and the vertex numbering, not on
 * the order the tets were made in. */
tr_status tr_delaunay_canonical(struct tr_mesh *m);
/* The same with up to nthreads threads (at most one per 65536 tets); the same store. */
tr_status tr_delaunay_canonical_threads(struct tr_mesh *m, int nthreads);
/* The same, then every vertex id v replaced by order[v] (order NULL: kept; the sort is
 * on the ids before the map, v2t after it). */
tr_status tr_delaunay_canonical_map(struct tr_mesh *m, int nthreads, const uint32_t *order);

/* Insertion order used by the builder: the distinct points (first of each duplicate
 * group), in BRIO rounds each sorted along a Hilbert curve. order gets *nuniq indices;
 * dup_map (n entries) receives the kept index of every point. Deterministic. */
tr_status tr_spatial_order(const double *xyz, uint32_t n, uint32_t *order, uint32_t *nuniq,
                           uint32_t *dup_map);
/* The same with up to nthreads threads (at most one per 65536 points); the same order. */
tr_status tr_spatial_order_threads(const double *xyz, uint32_t n, uint32_t *order,
                                   uint32_t *nuniq, uint32_t *dup_map, int nthreads);

/* Runs fn on the nth (at most 64) jobs at job, each `size` bytes, job 0 on the calling
 * thread; a job whose thread cannot start runs on the calling thread after the others
 * (so no job may depend on which thread runs it). */
void tr_dt_run_jobs(void *(*fn)(void *), void *job, size_t size, int nth);

/* Hilbert index of an integer point with `bits` bits per coordinate (3*bits <= 64). */
uint64_t tr_hilbert_key(uint32_t x, uint32_t y, uint32_t z, int bits);

/* A key and what it sorts. tr_radix_sort_kv: a[0..n) sorted by key, stable (equal keys
 * keep their order), keys under 2^56; tmp holds n entries. */
typedef struct tr_kv {
  uint64_t key;
  uint32_t idx;
} tr_kv;
void tr_radix_sort_kv(tr_kv *a, tr_kv *tmp, size_t n);

#ifdef __cplusplus
}
#endif

#endif
