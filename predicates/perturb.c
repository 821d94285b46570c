/* Symbolic perturbation of orient3d and insphere (simulation of simplicity).
 *
 * Both predicates are signs of determinants of matrices with one row per point. We
 * replace every point by a perturbed point that depends only on the point's global
 * index i (never on its argument position), with perturbations that are powers of an
 * infinitesimal eps > 0, and answer the sign of the perturbed determinant as eps -> 0+.
 * That sign is the sign of the lowest-order nonzero coefficient of a polynomial in
 * eps, which we evaluate exactly with the exact predicates on smaller determinants.
 *
 * Consistency: the answer is the sign of a determinant of perturbed points, so
 *  - the same points with the same indices give the same answer in every call;
 *  - permuting the arguments permutes rows: the answer changes sign exactly with the
 *    parity of the permutation, like the unperturbed predicate;
 *  - when the unperturbed sign is nonzero it is returned unchanged (the perturbation
 *    is infinitesimal).
 * Distinct points must have distinct indices. Two arguments with the same index are
 * the same perturbed point, whose determinant is identically 0: both functions
 * return 0 then.
 *
 * ---- insphere (the Delaunay cavity test) ----
 * Only the lifted coordinate is perturbed: point i is lifted to |p_i|^2 + eps^(N - i)
 * (N larger than every index), so a larger index means a larger perturbation (in the
 * spirit of Devillers and Teillaud, "Perturbations for Delaunay and weighted Delaunay
 * 3D triangulations"). The lifted determinant is linear in the lift column, so with
 * tr_insphere = sum_k (-1)^(k+1) l_k orient3d(the other four, in order) (insphere.c),
 *   perturbed = tr_insphere + sum_k (-1)^(k+1) eps^(N - i_k) orient3d(others of k).
 * Its sign: tr_insphere if nonzero, else, for the arguments k taken by decreasing
 * global index, the first nonzero (-1)^(k+1) orient3d(the four others). When a,b,c,d
 * are not coplanar the term of e is nonzero, so the answer is never 0; it is 0 only
 * when all five points are coplanar (then the lifted determinant and every orient3d
 * term vanish), or when two indices are equal.
 *
 * ---- orient3d ----
 * Edelsbrunner and Muecke's scheme: coordinate j of the point with global index i is
 * perturbed by eps^(2^(3i + j)). Every monomial of the perturbed 4x4 determinant
 * det[[x y z 1]] corresponds to a set S of perturbed entries with at most one per row
 * and per column, and its exponent is sum_{(i,j) in S} 2^(3i+j): distinct sets have
 * distinct exponents, and the most significant nonzero term is the set with the
 * smallest binary number. Only the relative order of the positions 3i + j matters for
 * that comparison, so we number positions by the rank of the index among the four
 * points: bit 3*rank + j, and walk the sets in increasing order. The coefficient of S
 * is the determinant with the rows of S replaced by the unit vectors of their columns
 * (multilinearity in the rows); after Laplace expansion along those unit rows it is
 * +-orient2d of a projection (|S| = 1), +-a coordinate difference (|S| = 2), or +-1
 * (|S| = 3). A set with three entries always exists, so the answer is never 0 for
 * distinct indices, even for coincident points.
 */
#include "predicates.h"

static int distinct_ids(const uint32_t *id, int n)
{
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++)
      if (id[i] == id[j])
        return 0;
  return 1;
}

int tr_insphere_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    const double e[3], uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                    uint32_t ie)
{
  int s = tr_sign(tr_insphere(a, b, c, d, e));
  if (s != 0)
    return s;
  const double *p[5] = {a, b, c, d, e};
  const uint32_t ix[5] = {ia, ib, ic, id, ie};
  if (!distinct_ids(ix, 5))
    return 0;
  int ord[5] = {0, 1, 2, 3, 4};
  for (int i = 1; i < 5; i++) /* by decreasing index: insertion sort */
    for (int j = i; j > 0 && ix[ord[j]] > ix[ord[j - 1]]; j--) {
      int t = ord[j];
      ord[j] = ord[j - 1];
      ord[j - 1] = t;
    }
  for (int m = 0; m < 5; m++) {
    const int k = ord[m];
    const double *q[4];
    int n = 0;
    for (int j = 0; j < 5; j++)
      if (j != k)
        q[n++] = p[j];
    int o = tr_sign(tr_orient3d(q[0], q[1], q[2], q[3]));
    if (o != 0)
      return (k % 2 == 1) ? o : -o;
  }
  return 0;
}

/* Sign of the coefficient of the perturbation set given by col[r] (-1: row r keeps its
 * coordinates; 0..2: row r replaced by the unit vector of that column) in
 * det[[x y z 1]] of the rows p[0..3]. */
static int sos_coefficient(const double *const p[4], const int col[4])
{
  int rows[4], nr = 0, cols[4] = {0, 1, 2, 3}, nc = 4, sign = 1;
  for (int r = 0; r < 4; r++)
    rows[nr++] = r;
  /* Laplace expansion along each unit row: the entry 1 sits at (row position,
   * column position) in the current submatrix; remove both. */
  for (int r = 0; r < 4; r++) {
    if (col[r] < 0)
      continue;
    int pr = 0, pc = 0;
    while (rows[pr] != r)
      pr++;
    while (cols[pc] != col[r])
      pc++;
    if ((pr + pc) % 2)
      sign = -sign;
    for (int i = pr; i + 1 < nr; i++)
      rows[i] = rows[i + 1];
    nr--;
    for (int i = pc; i + 1 < nc; i++)
      cols[i] = cols[i + 1];
    nc--;
  }
  /* The remaining columns are some coordinates followed by the column of ones. */
  if (nr == 3) {
    const int u = cols[0], v = cols[1];
    const double q0[2] = {p[rows[0]][u], p[rows[0]][v]};
    const double q1[2] = {p[rows[1]][u], p[rows[1]][v]};
    const double q2[2] = {p[rows[2]][u], p[rows[2]][v]};
    return sign * tr_sign(tr_orient2d(q0, q1, q2)); /* det[[u v 1]] = orient2d */
  }
  if (nr == 2) {
    const double x0 = p[rows[0]][cols[0]], x1 = p[rows[1]][cols[0]];
    return sign * ((x0 > x1) - (x0 < x1)); /* det[[x0 1];[x1 1]] */
  }
  return sign; /* nr == 1: the remaining entry is a 1 */
}

int tr_orient3d_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id)
{
  int s = tr_sign(tr_orient3d(a, b, c, d));
  if (s != 0)
    return s;
  const double *const p[4] = {a, b, c, d};
  const uint32_t ix[4] = {ia, ib, ic, id};
  if (!distinct_ids(ix, 4))
    return 0;
  int row_of_rank[4];
  for (int r = 0; r < 4; r++) {
    int rank = 0;
    for (int q = 0; q < 4; q++)
      rank += ix[q] < ix[r];
    row_of_rank[rank] = r;
  }
  for (unsigned mask = 1; mask < (1u << 12); mask++) {
    int col[4] = {-1, -1, -1, -1}, used = 0, ok = 1;
    for (int bit = 0; bit < 12 && ok; bit++) {
      if (!(mask >> bit & 1))
        continue;
      const int r = row_of_rank[bit / 3], j = bit % 3;
      if (col[r] >= 0 || (used >> j & 1))
        ok = 0;
      col[r] = j;
      used |= 1 << j;
    }
    if (!ok)
      continue;
    int cs = sos_coefficient(p, col);
    if (cs != 0)
      return -cs; /* tr_orient3d = -det[[x y z 1]] */
  }
  return 0; /* not reached: a three-entry set has coefficient +-1 */
}
