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
