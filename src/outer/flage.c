/* FLAGE (Table 13) as a permutation parity, and the sub-facet rule (see flage.h). */
#include "outer/flage.h"

int tr_flage(int ia, int ib, int ic, int id)
{
  int p[4] = {ia, ib, ic, id};
  int seen = 0, inv = 0;
  for (int i = 0; i < 4; i++) {
    if (p[i] < 0 || p[i] > 3 || (seen >> p[i]) & 1)
      return -1;
    seen |= 1 << p[i];
    for (int j = 0; j < i; j++)
      inv += p[j] > p[i];
  }
  /* The tet (v0,v1,v2,v3) is positive, so orient3d(v_ia,v_ib,v_ic,v_id) has the sign of
   * the permutation: positive (D beyond ABC's outward normal) iff it is even. */
  return (inv & 1) ? TR_INNER : TR_OUTER;
}

int tr_etype_geom(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d)
{
  int s = tr_orient3d_p(a, b, c, d);
  return s > 0 ? TR_OUTER : s < 0 ? TR_INNER : -1;
}

tr_status tr_etype_subfacet(int ia, int ib, int ic, int id, const tr_point *a,
                            const tr_point *b, const tr_point *c, const tr_point *d,
                            const tr_point *e, const tr_point *f, const tr_point *g,
                            int *etype)
{
  int et = tr_flage(ia, ib, ic, id);
  if (et < 0)
    return tr_error(TR_ERR_INTERNAL, "FLAGE: codes (%d,%d,%d,%d) are not a permutation", ia,
                    ib, ic, id);
  if (tr_orient3d_p(e, f, g, a) != 0 || tr_orient3d_p(e, f, g, b) != 0 ||
      tr_orient3d_p(e, f, g, c) != 0)
    return tr_error(TR_ERR_INTERNAL, "FLAGE: sub-facet is not in the plane of its facet");
  int sd = tr_orient3d_p(e, f, g, d);
  int sabc = tr_orient3d_p(a, b, c, d);
  if (sd == 0 || sabc == 0)
    return tr_error(TR_ERR_INTERNAL, "FLAGE: the tet is flat against its sub-facet");
  /* Same sign of d against both triangles <=> their normals point the same way. */
  *etype = sd == sabc ? et : 1 - et;
  return TR_OK;
}
