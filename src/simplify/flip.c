/* Edge flips inside the envelope (tr_simp_try_flip).
 *
 * A collapse removes a short edge; a cap (one corner near 180 degrees, so two near 0)
 * has none to remove, and its long edge is what makes it bad. Flipping edge ab of
 * (a, b, p) and (b, a, q) turns the two into (a, q, p) and (b, p, q). It is made only when
 *  - ab lies on exactly two live triangles and is no feature edge: the two are within
 *    TR_SIMP_SHARP_DEG of each other and carry one marker, and no chain is cut;
 *  - none of a, b, p, q is frozen by the stage (a crossing was made near it);
 *  - pq is no edge yet, so the surface keeps its topology;
 *  - no normal turns over: each new triangle's normal has a positive dot product with
 *    both old ones (exact), so the flip cannot fold the quad over a reflex corner;
 *  - the smallest angle of the two triangles grows (a choice, in doubles);
 *  - the envelope holds both ways (tr_simp_envelope).
 * A flip neither makes, moves nor removes a vertex, and never touches a feature edge.
 * Each flip made raises the sorted vector of the surface's angles, so flips alone end;
 * the caller caps them anyway. */
#define _DEFAULT_SOURCE
#include <math.h>

#include "edit.h"

static uint32_t apex(const uint32_t *t, uint32_t a, uint32_t b)
{
  for (int k = 0; k < 3; k++)
    if (t[k] != a && t[k] != b)
      return t[k];
  return UINT32_MAX;
}

/* 1 iff triangle t lists a then b in its cyclic order */
static int runs(const uint32_t *t, uint32_t a, uint32_t b)
{
  for (int k = 0; k < 3; k++)
    if (t[k] == a)
      return t[(k + 1) % 3] == b;
  return 0;
}

/* A flip turns a fold along ab into one along pq of the other kind: on a cylinder cut
 * into strips the convex diagonal becomes a concave one, a crease in the solid that the
 * refinement then resolves with small tets (CGAL's part.off: 150 such flips, smallest
 * dihedral angle 10.6 -> 8.2 degrees). So the new fold must be nearly flat, its normals
 * within TR_SIMP_FLIP_FOLD_DEG (a choice, in doubles). */
static int flat_enough(const tr_simp_edit *c, const uint32_t *x, const uint32_t *y)
{
  double n[2][3];
  const uint32_t *t[2] = {x, y};
  for (int i = 0; i < 2; i++) {
    const double *a = tr_simp_at(c, t[i][0]), *b = tr_simp_at(c, t[i][1]),
                 *p = tr_simp_at(c, t[i][2]);
    double u[3], v[3];
    for (int k = 0; k < 3; k++)
      u[k] = b[k] - a[k], v[k] = p[k] - a[k];
    n[i][0] = u[1] * v[2] - u[2] * v[1], n[i][1] = u[2] * v[0] - u[0] * v[2];
    n[i][2] = u[0] * v[1] - u[1] * v[0];
  }
  double dt = n[0][0] * n[1][0] + n[0][1] * n[1][1] + n[0][2] * n[1][2];
  double l = sqrt(n[0][0] * n[0][0] + n[0][1] * n[0][1] + n[0][2] * n[0][2]) *
             sqrt(n[1][0] * n[1][0] + n[1][1] * n[1][1] + n[1][2] * n[1][2]);
  return dt >= cos(TR_SIMP_FLIP_FOLD_DEG * M_PI / 180) * l;
}

tr_status tr_simp_try_flip(tr_simp_edit *c, uint32_t a, uint32_t b, int *done)
{
  *done = 0;
  if (tr_simp_is_frozen(c, a) || tr_simp_is_frozen(c, b) || tr_simp_is_feat(c, a, b))
    return TR_OK;
  uint32_t two[2], n = 0;
  for (uint32_t i = 0; i < c->ninc[a]; i++)
    if (tr_simp_has(c->tri + 3 * (size_t)c->inc[a][i], b) && n++ < 2)
      two[n - 1] = c->inc[a][i];
  if (n != 2)
    return TR_OK;
  if (!runs(c->tri + 3 * (size_t)two[0], a, b)) {
    uint32_t x = two[0];
    two[0] = two[1], two[1] = x;
  }
  const uint32_t *t0 = c->tri + 3 * (size_t)two[0], *t1 = c->tri + 3 * (size_t)two[1];
  if (!runs(t0, a, b) || !runs(t1, b, a))
    return TR_OK;
  uint32_t p = apex(t0, a, b), q = apex(t1, a, b);
  if (p == q || tr_simp_is_frozen(c, p) || tr_simp_is_frozen(c, q))
    return TR_OK;
  for (uint32_t i = 0; i < c->ninc[p]; i++)
    if (tr_simp_has(c->tri + 3 * (size_t)c->inc[p][i], q))
      return TR_OK;
  const uint32_t nv[2][3] = {{a, q, p}, {b, p, q}};
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) {
      const uint32_t *o = j ? t1 : t0;
      if (tr_simp_normal_dot_sign(tr_simp_at(c, o[0]), tr_simp_at(c, o[1]), tr_simp_at(c, o[2]),
                                  tr_simp_at(c, nv[i][0]), tr_simp_at(c, nv[i][1]),
                                  tr_simp_at(c, nv[i][2])) <= 0)
        return TR_OK;
    }
  if (!flat_enough(c, nv[0], nv[1]))
    return TR_OK;
  double old_min = fmin(tr_simp_tri_angle(c, two[0]), tr_simp_tri_angle(c, two[1]));
  double new_min = 180;
  for (int i = 0; i < 2; i++)
    new_min = fmin(new_min, tr_simp_min_angle(tr_simp_at(c, nv[i][0]), tr_simp_at(c, nv[i][1]),
                                              tr_simp_at(c, nv[i][2])));
  if (!(new_min > old_min))
    return TR_OK;
  uint32_t nt0 = c->nt, id, orig[2] = {c->orig[two[0]], c->orig[two[1]]};
  tr_status st = TR_OK;
  for (int i = 0; i < 2 && st == TR_OK; i++)
    st = tr_simp_new_slot(c, nv[i], orig[i], &id);
  const uint32_t quad[4] = {a, b, p, q};
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 3; k++) {
      lo[k] = fmin(lo[k], tr_simp_at(c, quad[i])[k]);
      hi[k] = fmax(hi[k], tr_simp_at(c, quad[i])[k]);
    }
  int ok = 0;
  if (st == TR_OK)
    st = tr_simp_envelope(c, two, 2, nt0, quad, 4, lo, hi, &ok);
  if (st != TR_OK || !ok) {
    c->nt = nt0;
    return st;
  }
  st = tr_simp_commit(c, two, 2, nt0);
  *done = st == TR_OK;
  return st;
}
