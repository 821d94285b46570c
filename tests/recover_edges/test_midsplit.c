/* The split of a missing sub-segment at one exact point (tr_pipe_split_mid, midsplit.c)
 * when the segment winds around a hub edge: every tet of its pipe has the hub, and the
 * segment passes the hub closer than the middle-part search resolves (2^-96 of its
 * length), as a diagonal of an ulp-bumpy facet passes an edge lying in the facet.
 *
 * The configuration: hub u-w on the y axis, its shell a bipyramid over the ring
 * a, c1, c2, b, d in the xz plane; a and b sit h above the hub, so ab crosses the faces
 * (u, w, c1) and (u, w, c2) at a distance of about h from it, at 1/3 of its length (no
 * dyadic point of ab is that close to the hub). Every result goes through the validator
 * with the exact volume.
 * Usage: test_midsplit thin | guarded | wide
 *   thin:    h = 2^-110: M is where ab leaves a's star, exactly on ab and on the open
 *            face (u, w, c1); the hub is removed; a-M and M-b are mesh edges.
 *   guarded: the same with the hub protected: the split is made, the hub stays.
 *   wide:    h = 2^-20: the middle part is found, the hub stays (the common path). */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "classify.h"
#include "recover_edges/pipe.h"
#include "tmesh.h"

enum { U, W, A, C1, C2, B, D, NV };

static tr_status build(double h, struct tr_mesh **out)
{
  const double p[NV][3] = {{0, -1, 0}, {0, 1, 0}, {-1, 0, h}, {-1, 0, 1},
                           {1, 0, 1},  {2, 0, h}, {0, 0, -1}};
  const uint32_t ring[5] = {A, C1, C2, B, D};
  struct tr_mesh *m;
  TR_CHECK(tr_mesh_create(64, 64, &m));
  for (int i = 0; i < NV; i++) {
    uint32_t id;
    TR_CHECK(tr_mesh_add_vertex(m, p[i], &id));
  }
  for (int i = 0; i < 5; i++) {
    uint32_t x = ring[i], y = ring[(i + 1) % 5], t;
    tr_point q[4] = {tr_mesh_point(m, U), tr_mesh_point(m, W), tr_mesh_point(m, x),
                     tr_mesh_point(m, y)};
    if (tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0)
      TR_CHECK(tr_tet_new(m, U, W, x, y, &t));
    else
      TR_CHECK(tr_tet_new(m, W, U, x, y, &t));
  }
  glue_all(m);
  *out = m;
  return TR_OK;
}

static int guard_hub(void *ud, const uint32_t *v, int nv)
{
  (void)ud;
  return nv == 2 && ((v[0] == U && v[1] == W) || (v[0] == W && v[1] == U));
}

static int run(const char *mode)
{
  int thin = strcmp(mode, "wide") != 0, guarded = !strcmp(mode, "guarded");
  struct tr_mesh *m;
  CK(build(ldexp(1, thin ? -110 : -20), &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  if (validate(m, vol, "bipyramid"))
    return 1;
  tr_pipe pipe = {0};
  uint32_t via, mid, nreal = 0;
  CK(tr_pipe_collect(m, A, B, &pipe, &via));
  for (uint32_t i = 0; i < pipe.n; i++)
    nreal += !pipe.pl[i].ghost;
  if (via != TR_NONE || nreal != 3)
    FAIL("%s: pipe of a-b: %u real pipels, via %u (expected 3 around the hub)", mode, nreal,
         via);
  int ok;
  CK(tr_pipe_split_mid(m, A, B, &pipe, guarded ? guard_hub : NULL, NULL, &mid, &ok));
  int want = thin && !guarded ? 2 : 1;
  if (ok != want)
    FAIL("%s: split result %d, expected %d", mode, ok, want);
  if (validate(m, vol, "after the split"))
    return 1;
  tr_point pm = tr_mesh_point(m, mid), pa = tr_mesh_point(m, A), pb = tr_mesh_point(m, B);
  if (tr_classify_point_segment(&pm, &pa, &pb).type != TR_EDG)
    FAIL("%s: M is not exactly inside a-b", mode);
  if (has_edge(m, U, W) != (want == 1))
    FAIL("%s: the hub is %s", mode, want == 1 ? "gone" : "still there");
  if (thin) {
    tr_point pu = tr_mesh_point(m, U), pw = tr_mesh_point(m, W), pc = tr_mesh_point(m, C1);
    if (tr_classify_point_triangle(&pm, &pu, &pw, &pc).type != TR_FAC)
      FAIL("%s: M is not on the open face (u, w, c1) where a-b leaves a's star", mode);
  }
  if (want == 2 && (!has_edge(m, A, mid) || !has_edge(m, mid, B)))
    FAIL("%s: a-M or M-b is not a mesh edge after the hub removal", mode);
  printf("%s: split at M, hub %s, %u tets, valid, volume kept\n", mode,
         want == 2 ? "removed" : "kept", tr_mesh_count_real(m));
  tr_pipe_free(&pipe);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc == 2 && (!strcmp(argv[1], "thin") || !strcmp(argv[1], "guarded") ||
                    !strcmp(argv[1], "wide")))
    return run(argv[1]);
  fprintf(stderr, "usage: test_midsplit thin | guarded | wide\n");
  return 2;
}
