/* DType: see dtype.h. The inward order of a face is a parity question: for a positive
 * tet, orient(v_a, v_b, v_c, v_k) = sign(permutation (a,b,c,k)) * orient(v0..v3). */
#include "recover_edges/dtype.h"

static int perm_even(int a, int b, int c, int d)
{
  int p[4] = {a, b, c, d}, inv = 0;
  for (int i = 0; i < 4; i++)
    for (int j = i + 1; j < 4; j++)
      inv += p[i] > p[j];
  return (inv & 1) == 0;
}

void tr_dtype_xy(int k, int apex, int *x, int *y)
{
  int o[2], m = 0;
  for (int i = 0; i < 4; i++)
    if (i != k && i != apex)
      o[m++] = i;
  if (perm_even(apex, o[0], o[1], k)) {
    *x = o[0];
    *y = o[1];
  } else {
    *x = o[1];
    *y = o[0];
  }
}

int tr_dtype_of_diagonal(int k, int apex, int from)
{
  int x, y;
  tr_dtype_xy(k, apex, &x, &y);
  return from == x ? TR_DTYPE_S : TR_DTYPE_Z;
}

int tr_dtype_diagonal_from(int k, int apex, int dtype)
{
  int x, y;
  tr_dtype_xy(k, apex, &x, &y);
  return dtype == TR_DTYPE_S ? x : y;
}
