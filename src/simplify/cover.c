/* Is a whole triangle within d of a set of triangles. The distance to one closed
 * triangle is a convex function of the point, so a piece whose three vertices are within
 * d of one target lies within d of it entirely: each piece is decided by exact tests at
 * its vertices only (dist.c), and pieces no single target covers are cut in four at
 * their edge midpoints (exact dyadic points, tr_simp_pt). A vertex within d of no target
 * is a point of the triangle farther than d from the set: a proof of the contrary. */
#include <math.h>
#include <stdlib.h>

#include "simplify_impl.h"

typedef struct {
  tr_simp_pt v[3];
} piece;

static int boxes_apart(const double *lo, const double *hi, const double *lo2,
                       const double *hi2, double gap)
{
  for (int k = 0; k < 3; k++)
    if (lo2[k] > hi[k] + gap || lo[k] > hi2[k] + gap)
      return 1;
  return 0;
}

/* Target s (a near one) ready for tr_simp_within: prepared when a piece first comes
 * near it (most pieces are decided by the first target tried). */
static void ready_target(const tr_simp_targets *t, tr_simp_tprep *tp, unsigned char *ready,
                         uint32_t s)
{
  if (!ready[s]) {
    const uint32_t *tv = t->tri + 3 * (size_t)t->ids[s];
    tr_simp_prepare(t->xyz + 3 * (size_t)tv[0], t->xyz + 3 * (size_t)tv[1],
                    t->xyz + 3 * (size_t)tv[2], tp + s);
    ready[s] = 1;
  }
}

int tr_simp_cover(const double *A, const double *B, const double *C,
                  const tr_simp_targets *t, double d, const double *skip_lo,
                  const double *skip_hi, uint32_t budget, double *ub)
{
  double m = 0;
  for (int k = 0; k < 3; k++)
    m = fmax(m, fmax(fabs(A[k]), fmax(fabs(B[k]), fabs(C[k]))));
  /* a piece's doubles are within 2^-46 m of its exact points: its box grown by this
   * holds them, so a target farther than d from this box is farther than d from it */
  double grow = 0x1p-40 * m;
  size_t cap = 64, n = 0;
  piece *st = malloc(sizeof *st * cap);
  if (ub)
    *ub = 0;
  if (!st)
    return TR_COVER_UNDECIDED;
  tr_simp_tprep *tp = malloc(sizeof *tp * (t->n ? t->n : 1));
  if (!tp) {
    free(st);
    return TR_COVER_UNDECIDED;
  }
  /* Only the targets near the whole triangle can be near a piece of it: those, in their
   * order, are the ones each piece tries (a choice of which to test, widened, never
   * narrowed), each prepared when first needed. */
  unsigned char *ready = calloc(t->n ? t->n : 1, 1);
  uint32_t *near = malloc(sizeof *near * (t->n ? t->n : 1)), nnear = 0;
  if (!ready || !near) {
    free(st), free(tp), free(ready), free(near);
    return TR_COVER_UNDECIDED;
  }
  {
    double lo[3], hi[3];
    tr_simp_tri_box(A, B, C, lo, hi);
    for (int k = 0; k < 3; k++)
      lo[k] -= grow, hi[k] += grow;
    for (uint32_t s = 0; s < t->n; s++) {
      const uint32_t *tv = t->tri + 3 * (size_t)t->ids[s];
      tr_simp_tri_box(t->xyz + 3 * (size_t)tv[0], t->xyz + 3 * (size_t)tv[1],
                      t->xyz + 3 * (size_t)tv[2], tp[s].lo, tp[s].hi);
      if (!boxes_apart(lo, hi, tp[s].lo, tp[s].hi, d * (1 + 0x1p-40)))
        near[nnear++] = s;
    }
  }
  piece root = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  st[n++] = root;
  uint32_t used = 0;
  int res = TR_COVER_YES;
  double worst = 0;
  while (n && res == TR_COVER_YES) {
    piece q = st[--n];
    if (++used > budget) {
      res = TR_COVER_UNDECIDED;
      break;
    }
    double x[3][3], lo[3], hi[3];
    for (int i = 0; i < 3; i++)
      tr_simp_point(A, B, C, q.v[i], x[i]);
    tr_simp_tri_box(x[0], x[1], x[2], lo, hi);
    for (int k = 0; k < 3; k++)
      lo[k] -= grow, hi[k] += grow;
    if (skip_lo && boxes_apart(lo, hi, skip_lo, skip_hi, 0))
      continue;
    unsigned any = 0;
    double best = INFINITY;
    for (uint32_t r = 0; r < nnear; r++) {
      uint32_t s = near[r];
      if (boxes_apart(lo, hi, tp[s].lo, tp[s].hi, d * (1 + 0x1p-40)))
        continue;
      ready_target(t, tp, ready, s);
      unsigned mask = 0, all = 1;
      double far = 0;
      for (int i = 0; i < 3; i++) {
        double u;
        /* once a vertex is out, s covers no piece: only what any lacks is asked */
        if (!all && (any >> i & 1))
          continue;
        if (tr_simp_within(A, B, C, q.v[i], x[i], m, tp + s, d, &u))
          mask |= 1u << i, far = fmax(far, fmin(u, d));
        else
          all = 0;
      }
      any |= mask;
      if (mask == 7) { /* the first target that covers the piece decides it */
        best = far;
        break;
      }
    }
    /* Or a ball: every point of the piece is within r of its vertex 0, so the piece is
     * within d of a target that vertex is within d - r of. Where the covering target
     * changes (across the edges of a flat fan) this ends the cutting at pieces of about
     * d instead of ever smaller ones. r: an upper bound, with the doubles' error. */
    if (best > d && any == 7) {
      double r = 0;
      for (int i = 1; i < 3; i++) {
        double s2 = 0;
        for (int k = 0; k < 3; k++)
          s2 += (x[i][k] - x[0][k]) * (x[i][k] - x[0][k]);
        r = fmax(r, sqrt(s2));
      }
      double thr = (d - (r * (1 + 0x1p-50) + 4 * grow)) * (1 - 0x1p-50);
      for (uint32_t r = 0; r < nnear && thr > 0 && best > d; r++) {
        uint32_t s = near[r];
        if (boxes_apart(lo, hi, tp[s].lo, tp[s].hi, d * (1 + 0x1p-40)))
          continue;
        ready_target(t, tp, ready, s);
        if (tr_simp_within(A, B, C, q.v[0], x[0], m, tp + s, thr, NULL))
          best = d;
      }
    }
    if (best <= d) {
      worst = fmax(worst, best);
      continue;
    }
    if (any != 7) {
      res = TR_COVER_NO;
      break;
    }
    if (q.v[0].k >= 30) {
      res = TR_COVER_UNDECIDED;
      break;
    }
    tr_simp_pt p[3], mid[3];
    for (int i = 0; i < 3; i++)
      p[i] = (tr_simp_pt){2 * q.v[i].i, 2 * q.v[i].j, q.v[i].k + 1};
    /* mid[i] is the midpoint of edge (i, i+1), at level k + 1 */
    for (int i = 0; i < 3; i++)
      mid[i] = (tr_simp_pt){q.v[i].i + q.v[(i + 1) % 3].i, q.v[i].j + q.v[(i + 1) % 3].j,
                            q.v[i].k + 1};
    if (n + 4 > cap) {
      piece *g = realloc(st, sizeof *st * cap * 2);
      if (!g) {
        res = TR_COVER_UNDECIDED;
        break;
      }
      st = g, cap *= 2;
    }
    st[n++] = (piece){{p[0], mid[0], mid[2]}};
    st[n++] = (piece){{mid[0], p[1], mid[1]}};
    st[n++] = (piece){{mid[2], mid[1], p[2]}};
    st[n++] = (piece){{mid[0], mid[1], mid[2]}};
  }
  free(st), free(tp), free(ready), free(near);
  if (ub)
    *ub = res == TR_COVER_YES ? worst : INFINITY;
  return res;
}
