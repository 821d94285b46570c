/* The seed paper's local codes inside a tet: NCode (vertex slot), ECode (edge), FCode
 * (face = slot of the opposite vertex), and the fixed face / edge tables. */
#include "mesh.h"

/* Face k is listed so that its right-hand normal points to vertex k: the permutation
 * (face..., k) of (0,1,2,3) is even, hence orient3d(face, vk) has the tet's sign. */
const uint8_t tr_face_vtx[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

const uint8_t tr_edge_vtx[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/* Derived by hand from tr_face_vtx (rotate face j to start at k); tests/mesh re-derives
 * it from tr_face_vtx and compares. */
const uint8_t tr_face_rot[4][4][2] = {
    {{0, 0}, {2, 3}, {3, 1}, {1, 2}},
    {{3, 2}, {1, 1}, {0, 3}, {2, 0}},
    {{1, 3}, {3, 0}, {2, 2}, {0, 1}},
    {{2, 1}, {0, 2}, {1, 0}, {3, 3}},
};

int tr_ncode(const struct tr_mesh *m, uint32_t t, uint32_t v)
{
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++)
    if (tv[k] == v)
      return k;
  return -1;
}

int tr_tet_even_order(const struct tr_mesh *m, uint32_t t, const uint32_t p[4])
{
  int pos[4], inv = 0;
  for (int i = 0; i < 4; i++)
    if ((pos[i] = tr_ncode(m, t, p[i])) < 0)
      return -1;
  for (int i = 0; i < 4; i++)
    for (int j = i + 1; j < 4; j++)
      inv += pos[i] > pos[j];
  return (inv & 1) == 0;
}

int tr_tet_ecode(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b)
{
  int i = tr_ncode(m, t, a), j = tr_ncode(m, t, b);
  if (i < 0 || j < 0 || i == j)
    return -1;
  return i < j ? (i | j << 2) : (j | i << 2);
}

int tr_fcode(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c)
{
  int i = tr_ncode(m, t, a), j = tr_ncode(m, t, b), k = tr_ncode(m, t, c);
  if (i < 0 || j < 0 || k < 0 || i == j || j == k || i == k)
    return -1;
  return 6 - i - j - k;
}
