/* A cap flat in doubles (src/sliver/insert.c, insert_at): four points whose exact
 * orientation is positive but whose volume in doubles is 0 in every vertex order, so the
 * tet has no circumcentre in doubles. Such caps stood over creases of pinion.off (two
 * input triangles 1e-16 off coplanar): the insertion pass returned before trying any
 * candidate, and the output kept a tet of 0.000 degrees. The points above the cap's faces
 * and off its plane do not need the circumcentre. Every mesh goes through the mesh
 * validator with its exact volume. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "refine/quality.h"
#include "sliver/sliver.h"
#include "../pipeline/tmesh.h"

/* p q r s: the ridge of tests/sliver/test_sliver.c (a square's halves folded along p q),
 * turned and rounded to six decimals, folded by about 1e-18 (found by a search over turns
 * for a fold whose four doubles have a 0 volume in all 24 orders); u: the apex. */
static const double hull[15] = {0.0,      0.0,       0.0,       0.486262, -0.149821,
                                -0.860873, 0.228275, 0.1694,    -0.481346, 0.257987,
                                -0.319221, -0.379527, 1.114921, 0.075268,  0.035855};

/* 6 times the hull's volume, exactly (the sum of the cap's and the two tets' over it). */
static const char *const six_volume =
    "11692013736617580088855260239266115998067550439639/"
    "23384026197294446691258957323460528314494920687616";

static void valid(const char *when, const tr_mesh *m)
{
  mpq_t six;
  mpq_init(six);
  mpq_set_str(six, six_volume, 10);
  tr_status s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", when, tr_last_error());
  mpq_clear(six);
}

static void a_cap_flat_in_doubles_is_opened_by_a_point_off_its_plane(void)
{
  tr_mesh *m = NULL;
  if (tr_delaunay_build(hull, 5, &m) != TR_OK) {
    EXPECT(0, "Delaunay failed: %s", tr_last_error());
    return;
  }
  valid("setup", m);
  const uint32_t cap[4] = {0, 1, 2, 3};
  uint32_t t = tm_find_tet(m, cap);
  EXPECT(t != TR_NONE, "the cap is not a tet of the Delaunay mesh");
  if (t == TR_NONE) {
    tr_mesh_destroy(m);
    return;
  }
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double r, w, cc[3];
  int finite = tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                            m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &r, &w, NULL, cc);
  EXPECT(!finite && w == 0, "the cap is not flat in doubles (volume %g)", w);
  tr_quality q;
  tr_quality_measure(m, &q);
  const double before = q.min_dihedral;
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 5, TR_SLIVER_BOUND);
  if (s == TR_OK)
    s = tr_sliver_insert_pass(&c, &st);
  tr_sliver_ctx_free(&c);
  EXPECT(s == TR_OK, "insertion: %s", tr_last_error());
  EXPECT(st.points >= 1 && m->nv == 5 + st.points, "%llu points added, %u vertices",
         (unsigned long long)st.points, m->nv);
  EXPECT(tm_find_tet(m, cap) == TR_NONE, "the cap is still there");
  for (uint32_t i = 0; i < 5; i++)
    EXPECT(!memcmp(hull + 3 * i, m->xyz + 3 * (size_t)i, 24), "input point %u moved", i);
  for (uint32_t i = 5; i < m->nv; i++)
    EXPECT(!(m->vq && m->vq[i]) && m->v2t[i] != TR_NONE, "new vertex %u is not a double in the mesh",
           i);
  tr_quality_measure(m, &q);
  EXPECT(q.min_dihedral > before + 1, "smallest dihedral angle %g -> %g: not raised", before,
         q.min_dihedral);
  valid("after the insertion", m);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"flat_cap", a_cap_flat_in_doubles_is_opened_by_a_point_off_its_plane, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
