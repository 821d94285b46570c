/* The two-sided bound between two whole surfaces (tr_simplify_bound): every triangle of
 * each, against the triangles of the other whose boxes come within d of its box. Used by
 * the stage to measure what it made, and by `tetrec check --surface-tolerance` on the
 * mesh file's triangles, which never saw the simplifier's own local checks. */
#include <math.h>
#include <stdlib.h>

#include "simplify.h"
#include "simplify_impl.h"

/* pieces a triangle may be cut into before its answer is "undecided" */
#define BOUND_BUDGET (1u << 16)
#define BOUND_MAX (1u << 20)

static tr_status one_side(const double *xs, const uint32_t *ts, uint32_t ns,
                          const double *xt, const uint32_t *tt, uint32_t nt, double d,
                          double *worst, int *res, uint32_t *bad)
{
  tr_simp_grid g;
  TR_CHECK(tr_simp_grid_build(&g, xt, tt, nt));
  uint32_t *cand = NULL, ncand = 0, cap = 0;
  tr_status st = TR_OK;
  *res = TR_COVER_YES;
  for (uint32_t s = 0; s < ns && st == TR_OK; s++) {
    const uint32_t *v = ts + 3 * (size_t)s;
    const double *A = xs + 3 * (size_t)v[0], *B = xs + 3 * (size_t)v[1],
                 *C = xs + 3 * (size_t)v[2];
    double lo[3], hi[3];
    tr_simp_tri_box(A, B, C, lo, hi);
    ncand = 0;
    st = tr_simp_grid_query(&g, xt, tt, lo, hi, d, &cand, &ncand, &cap);
    if (st != TR_OK)
      break;
    tr_simp_targets tg = {xt, tt, cand, ncand};
    double ub;
    /* a triangle tiled by many small ones of the other side is proven in pieces of
     * about d (the ball test of cover.c): room for (longest edge / d)^2 of them, at
     * most 2^20 (then undecided: not proven) */
    double l2 = 0;
    for (int k = 0; k < 3; k++)
      l2 = fmax(l2, fmax((A[k] - B[k]) * (A[k] - B[k]),
                         fmax((B[k] - C[k]) * (B[k] - C[k]), (C[k] - A[k]) * (C[k] - A[k]))));
    double want = d > 0 ? 48 * l2 / (d * d) : 0;
    uint32_t budget = want > BOUND_MAX ? BOUND_MAX : want > BOUND_BUDGET ? (uint32_t)want
                                                                         : BOUND_BUDGET;
    int r = tr_simp_cover(A, B, C, &tg, d, NULL, NULL, budget, &ub);
    if (r != TR_COVER_YES) {
      *res = r;
      *bad = s;
      break;
    }
    *worst = fmax(*worst, ub);
  }
  free(cand);
  tr_simp_grid_free(&g);
  return st;
}

tr_status tr_simplify_bound(const double *xyz_x, const uint32_t *tri_x, uint32_t nx,
                            const double *xyz_y, const uint32_t *tri_y, uint32_t ny, double d,
                            tr_simp_bound_result *res)
{
  res->ok = 0, res->side = 0, res->undecided = 0, res->tri = 0;
  res->measured = INFINITY;
  if (!(d >= 0) || !isfinite(d))
    return tr_error(TR_ERR_USAGE, "a surface distance bound is finite and >= 0, not %g", d);
  double worst = 0;
  int r;
  uint32_t bad = 0;
  TR_CHECK(one_side(xyz_x, tri_x, nx, xyz_y, tri_y, ny, d, &worst, &r, &bad));
  if (r == TR_COVER_YES) {
    res->side = 1;
    TR_CHECK(one_side(xyz_y, tri_y, ny, xyz_x, tri_x, nx, d, &worst, &r, &bad));
  }
  if (r != TR_COVER_YES) {
    res->tri = bad;
    res->undecided = r == TR_COVER_UNDECIDED;
    return TR_OK;
  }
  res->ok = 1, res->side = 0;
  res->measured = worst;
  return TR_OK;
}
