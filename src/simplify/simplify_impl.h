/* Internals of the surface simplification (--surface-tolerance, docs/simplify.md):
 *   dist.c      is a point of a source triangle within distance d of a target triangle:
 *               a double filter with a proven error term, exact rationals when it
 *               cannot tell
 *   cover.c     is a whole triangle within d of a set of triangles: adaptive subdivision,
 *               each piece decided by the convexity of the distance to one triangle
 *   grid.c      the triangles whose boxes come within d of a box
 *   bound.c     the two-sided bound between two whole surfaces (the stats and
 *               `tetrec check --surface-tolerance`)
 *   collapse.c  edge collapses inside the envelope, worst triangle first
 *   stage.c     the pipeline stage: options, frozen vertices, self-intersection rounds,
 *               the PLC handed on */
#ifndef TR_SIMPLIFY_IMPL_H
#define TR_SIMPLIFY_IMPL_H

#include <stdint.h>

#include "core/status.h"

/* A point of source triangle (A, B, C): A + (i (B - A) + j (C - A)) / 2^k, with
 * 0 <= i, j and i + j <= 2^k: the vertices of the pieces of its subdivision, exact
 * dyadic rationals even where their doubles would round. */
typedef struct tr_simp_pt {
  uint32_t i, j;
  int k;
} tr_simp_pt;

/* A target triangle with what the filter reuses for every point: its box, normal and
 * the in-plane normals of its edges (any accuracy: see dist.c), their norms, and an upper
 * bound of the cosine between the normal and each in-plane normal (cos0[0] unused). */
typedef struct tr_simp_tprep {
  const double *a, *b, *c;
  double lo[3], hi[3], m;
  double w[4][3], wn1[4], wlen[4], lo_t[4], hi_t[4], cos0[4];
} tr_simp_tprep;
void tr_simp_prepare(const double *a, const double *b, const double *c, tr_simp_tprep *t);

/* 1 iff the exact point p of (A, B, C) lies within d (>= 0) of the closed triangle t
 * (not degenerate), exactly. px: tr_simp_point of p, m: the largest |coordinate| of A, B
 * and C (what every test of the same point shares). *ub (may be NULL) receives an upper
 * bound of that distance (+inf when the filter did not compute one). */
int tr_simp_within(const double *A, const double *B, const double *C, tr_simp_pt p,
                   const double px[3], double m, const tr_simp_tprep *t, double d, double *ub);

/* The double nearest to p's exact position, within 2^-46 max|coord| of it. */
void tr_simp_point(const double *A, const double *B, const double *C, tr_simp_pt p,
                   double out[3]);

/* A set of target triangles: n triangles, vertex ids into xyz. */
typedef struct tr_simp_targets {
  const double *xyz;
  const uint32_t *tri; /* 3 per triangle */
  const uint32_t *ids; /* the n triangles of the set (indices into tri) */
  uint32_t n;
} tr_simp_targets;

/* Outcome of tr_simp_cover. */
enum { TR_COVER_NO = 0, TR_COVER_YES = 1, TR_COVER_UNDECIDED = 2 };

/* Whether every point of triangle (A, B, C) lies within d of the union of the targets:
 * YES proven (each piece of an adaptive subdivision has its three vertices within d of
 * one target, so all of it is, the distance to a convex set being convex); NO when a
 * vertex of a piece, an exact point of the triangle, is farther than d from every
 * target; UNDECIDED when the piece budget ran out. skip_lo/skip_hi (may be NULL): pieces
 * whose box misses that box are taken as covered (the caller knows they are). *ub
 * (may be NULL) receives an upper bound of the distance over the decided pieces (of
 * YES: of every point). budget: pieces at most. */
int tr_simp_cover(const double *A, const double *B, const double *C,
                  const tr_simp_targets *t, double d, const double *skip_lo,
                  const double *skip_hi, uint32_t budget, double *ub);

/* A uniform grid over the boxes of a triangle set, for the queries of both sides. */
typedef struct tr_simp_grid {
  double lo[3], cell[3];
  uint32_t dim[3];
  uint32_t *start, *item; /* CSR: cell c holds item[start[c] .. start[c + 1]) */
  uint32_t *stamp, tick;  /* one per triangle, to list each once per query */
  double *box;            /* 6 per triangle: its box, lo then hi */
  uint32_t ntris;
} tr_simp_grid;

tr_status tr_simp_grid_build(tr_simp_grid *g, const double *xyz, const uint32_t *tri,
                             uint32_t ntris);
void tr_simp_grid_free(tr_simp_grid *g);
/* The triangles whose boxes meet [lo - d, hi + d] (the test widened by a relative
 * 2^-40, never narrowed), appended to *out (grown as needed). */
tr_status tr_simp_grid_query(tr_simp_grid *g, const double *xyz, const uint32_t *tri,
                             const double *lo, const double *hi, double d, uint32_t **out,
                             uint32_t *n, uint32_t *cap);

/* The box of a triangle. */
void tr_simp_tri_box(const double *a, const double *b, const double *c, double lo[3],
                     double hi[3]);

#endif
