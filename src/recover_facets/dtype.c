/* DType of a table's face and the choice of a clusterel case (see dtype.h). */
#include "recover_facets/dtype.h"

int tr_perm_parity_even(const uint8_t p[4])
{
  int seen = 0, inv = 0;
  for (int i = 0; i < 4; i++) {
    if (p[i] > 3 || (seen >> p[i]) & 1)
      return -1;
    seen |= 1 << p[i];
    for (int j = 0; j < i; j++)
      inv += p[j] > p[i];
  }
  return !(inv & 1);
}

/* Outward order of the face of a positive tet (0,1,2,3) opposite index k: the three
 * other indices (a,b,c) such that (a,b,c,k) is an odd permutation, i.e.
 * orient3d(a,b,c,k) < 0 and the right-hand normal of abc points away from k. */
static void outward_face(int k, uint8_t f[3])
{
  int m = 0;
  for (int i = 0; i < 4; i++)
    if (i != k)
      f[m++] = (uint8_t)i;
  uint8_t p[4] = {f[0], f[1], f[2], (uint8_t)k};
  if (tr_perm_parity_even(p) == 1) {
    uint8_t t = f[1];
    f[1] = f[2];
    f[2] = t;
  }
}

static int face_has(const tr_dtet *d, int k, uint8_t x, uint8_t y)
{
  int hx = 0, hy = 0;
  for (int i = 0; i < 4; i++) {
    if (i == k)
      continue;
    hx |= d->v[i] == x;
    hy |= d->v[i] == y;
  }
  return hx && hy;
}

/* The Steiner point of t on the open edge {x, y}, or TR_DV_NONE. */
static uint8_t steiner_on_edge(const tr_dectable *t, uint8_t x, uint8_t y)
{
  for (int i = 0; i < t->nsteiner; i++) {
    const tr_dsteiner *s = &t->steiner[i];
    if (s->ncar == 2 && ((s->car[0] == x && s->car[1] == y) || (s->car[0] == y && s->car[1] == x)))
      return s->name;
  }
  return TR_DV_NONE;
}

int tr_dtype_of_table(const tr_dectable *t, uint8_t opp)
{
  int k = tr_dectable_old_index(t, 0, opp);
  if (k < 0)
    return TR_DTYPE_NONE;
  uint8_t f[3];
  outward_face(k, f);
  for (int i = 0; i < 3; i++)
    f[i] = t->old[0][f[i]];
  /* Find the apex: the face vertex whose two face edges are both cut, the third edge
   * being uncut. */
  int apex = -1;
  for (int i = 0; i < 3; i++) {
    uint8_t x = f[i], u = f[(i + 1) % 3], v = f[(i + 2) % 3];
    int cut_xu = steiner_on_edge(t, x, u) != TR_DV_NONE;
    int cut_xv = steiner_on_edge(t, x, v) != TR_DV_NONE;
    int cut_uv = steiner_on_edge(t, u, v) != TR_DV_NONE;
    if (cut_xu && cut_xv && !cut_uv)
      apex = i;
  }
  if (apex < 0)
    return TR_DTYPE_NONE;
  uint8_t x = f[apex], u = f[(apex + 1) % 3], v = f[(apex + 2) % 3];
  uint8_t pu = steiner_on_edge(t, x, u), pv = steiner_on_edge(t, x, v);
  int s = 0, z = 0;
  for (int r = 0; r < t->nnew; r++) {
    const tr_dtet *d = &t->tets[r];
    for (int c = 0; c < 4; c++) {
      const tr_dnb *n = &d->n[c];
      int on_face = (n->kind == TR_DNB_PHI && n->vtx == opp) ||
                    (n->kind == TR_DNB_NG && n->tet == 0 && n->vtx == opp);
      if (!on_face)
        continue;
      s |= face_has(d, c, v, pu);
      z |= face_has(d, c, u, pv);
    }
  }
  if (s == z)
    return TR_DTYPE_NONE;
  return s ? TR_DTYPE_S : TR_DTYPE_Z;
}

static int edge_cut(int ncut, const uint8_t *ecodes, int a, int b)
{
  for (int i = 0; i < ncut; i++) {
    int s = ecodes[i] & 3, e = (ecodes[i] >> 2) & 3;
    if ((s == a && e == b) || (s == b && e == a))
      return 1;
  }
  return 0;
}

/* The positive labelings of a clusterel that put its cut edges where the tables expect
 * them; at most 4. Returns their number (0: unexpected cut-edge set). */
static int labelings(int ncut, const uint8_t *ecodes, uint8_t lab[4][4])
{
  int nl = 0;
  if (ncut == 3) {
    /* D = the vertex on all three cut edges; A, B, C its three rotations. */
    for (int d = 0; d < 4; d++) {
      int all = 1;
      for (int o = 0; o < 4; o++)
        if (o != d && !edge_cut(ncut, ecodes, d, o))
          all = 0;
      if (!all)
        continue;
      uint8_t r[3];
      int m = 0;
      for (int o = 0; o < 4; o++)
        if (o != d)
          r[m++] = (uint8_t)o;
      for (int s = 0; s < 3; s++) {
        uint8_t p[4] = {r[s], r[(s + 1) % 3], r[(s + 2) % 3], (uint8_t)d};
        if (tr_perm_parity_even(p) != 1) {
          uint8_t t = p[1];
          p[1] = p[2];
          p[2] = t;
        }
        for (int i = 0; i < 4; i++)
          lab[nl][i] = p[i];
        nl++;
      }
      return nl;
    }
    return 0;
  }
  if (ncut == 4) {
    /* AB and CD are the two uncut edges, which must be opposite. */
    for (int a = 0; a < 4; a++)
      for (int b = 0; b < 4; b++) {
        if (a == b || edge_cut(ncut, ecodes, a, b))
          continue;
        uint8_t p[4] = {(uint8_t)a, (uint8_t)b, 0, 0};
        int m = 2;
        for (int o = 0; o < 4; o++)
          if (o != a && o != b)
            p[m++] = (uint8_t)o;
        if (edge_cut(ncut, ecodes, p[2], p[3]))
          continue;
        for (int o = 0; o < 2; o++)
          for (int q = 2; q < 4; q++)
            if (!edge_cut(ncut, ecodes, p[o], p[q]))
              return 0;
        if (tr_perm_parity_even(p) != 1) {
          uint8_t t = p[2];
          p[2] = p[3];
          p[3] = t;
        }
        for (int i = 0; i < 4; i++)
          lab[nl][i] = p[i];
        nl++;
      }
    return nl == 4 ? nl : 0;
  }
  return 0;
}

tr_status tr_cluster_match(int ncut, const uint8_t *ecodes, const int8_t want[4],
                           const tr_cluster_case **out, uint8_t perm[4])
{
  uint8_t lab[4][4];
  int nl = labelings(ncut, ecodes, lab);
  if (nl == 0)
    return tr_error(TR_ERR_INTERNAL, "clusterel with %d cut edges in an impossible position",
                    ncut);
  const tr_cluster_case *cases = ncut == 3 ? tr_thr_edg_cases : tr_fou_edg_cases;
  int ncases = ncut == 3 ? TR_NUM_THR_EDG : TR_NUM_FOU_EDG;
  /* Cases are stored in preference order (no H first), so the first fit wins. */
  for (int c = 0; c < ncases; c++)
    for (int l = 0; l < nl; l++) {
      int ok = 1;
      for (int x = 0; x < 4 && ok; x++) {
        int dt = cases[c].dtype[x];
        int w = want[lab[l][x]];
        if (dt != TR_DTYPE_NONE && w != TR_DTYPE_ANY && w != dt)
          ok = 0;
      }
      if (ok) {
        *out = &cases[c];
        for (int i = 0; i < 4; i++)
          perm[i] = lab[l][i];
        return TR_OK;
      }
    }
  return tr_error(TR_ERR_INTERNAL, "no clusterel case fits the S/Z requirements (%d cut edges)",
                  ncut);
}
