/* The segment walk that spares the sliver insertion its hopeless cavities
 * (src/sliver/reach.c), against brute force on the Delaunay mesh of a random cloud in a
 * box with random protected faces: it answers "blocked" only when the segment from t's
 * centroid to x crosses a protected face or a hull face through its relative interior
 * (sound), and it does answer it for every such segment in general position (complete).
 * Usage: test_reach <case>. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "predicates.h"
#include "sliver/sliver.h"
#include "../mesh/tcommon.h"

enum { NPTS = 120, NPROT = 40, PAIRS = 3000 };

static const double *vx(const tr_mesh *m, uint32_t t, int i)
{
  return m->xyz + 3 * (size_t)m->tv[4 * (size_t)t + (size_t)i];
}

/* the segment g x crosses triangle a b d through its relative interior (strictly) */
static int crosses(const double *g, const double *x, const double *a, const double *b,
                   const double *d)
{
  double og = tr_orient3d(a, b, d, g), ox = tr_orient3d(a, b, d, x);
  if (!((og > 0 && ox < 0) || (og < 0 && ox > 0)))
    return 0;
  double s0 = tr_orient3d(g, x, a, b), s1 = tr_orient3d(g, x, b, d), s2 = tr_orient3d(g, x, d, a);
  return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

static int walk_agrees_with_brute_force(void)
{
  double pts[3 * NPTS];
  for (int i = 0; i < 3 * NPTS; i++)
    pts[i] = t_unif();
  for (int i = 0; i < 8; i++) /* the box's corners: the hull */
    for (int k = 0; k < 3; k++)
      pts[3 * i + k] = (i >> k) & 1;
  tr_mesh *m = NULL;
  EXPECT(tr_delaunay_build(pts, NPTS, &m) == TR_OK, "Delaunay: %s", tr_last_error());
  /* protected faces: random faces between two real tets */
  uint32_t fv[3 * NPROT], tri[NPROT];
  uint32_t np = 0;
  while (np < NPROT) {
    uint32_t t = (uint32_t)(t_next() % m->nt);
    int k = (int)(t_next() % 4);
    uint32_t nb = TR_NEIG(m, t, k);
    if (!tr_tet_is_real(m, t) || nb == TR_NONE || !tr_tet_is_real(m, nb))
      continue;
    for (int j = 0; j < 3; j++)
      fv[3 * np + j] = m->tv[4 * (size_t)t + tr_face_vtx[k][j]];
    tri[np] = np;
    np++;
  }
  tr_subfaces sub = {np, fv, tri};
  tr_sliver_ctx c;
  EXPECT(tr_sliver_ctx_init(&c, m, &sub, NULL, NPTS, TR_SLIVER_BOUND) == TR_OK, "ctx: %s",
         tr_last_error());
  int blocked = 0, open = 0, outside = 0;
  for (int it = 0; it < PAIRS; it++) {
    uint32_t t;
    do
      t = (uint32_t)(t_next() % m->nt);
    while (!tr_tet_is_real(m, t));
    double x[3], g[3];
    for (int k = 0; k < 3; k++) /* some points outside the box */
      x[k] = -0.25 + 1.5 * t_unif();
    for (int k = 0; k < 3; k++)
      g[k] = 0.25 * (vx(m, t, 0)[k] + vx(m, t, 1)[k] + vx(m, t, 2)[k] + vx(m, t, 3)[k]);
    int brute = 0, hull = 0;
    for (uint32_t u = 0; u < m->nt && !brute; u++) {
      if (!tr_tet_is_real(m, u))
        continue;
      for (int k = 0; k < 4 && !brute; k++) {
        uint32_t nb = TR_NEIG(m, u, k);
        const uint32_t *tv = m->tv + 4 * (size_t)u;
        uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
        int wall = nb == TR_NONE || !tr_tet_is_real(m, nb) || tr_sliver_protected(&c, f, 3);
        if (wall && crosses(g, x, m->xyz + 3 * (size_t)f[0], m->xyz + 3 * (size_t)f[1],
                            m->xyz + 3 * (size_t)f[2])) {
          brute = 1;
          hull = nb == TR_NONE || !tr_tet_is_real(m, nb);
        }
      }
    }
    int walk = tr_sliver_segment_blocked(&c, t, x);
    EXPECT(walk == brute, "tet %u, x (%.17g %.17g %.17g): walk says %d, brute force %d", t,
           x[0], x[1], x[2], walk, brute);
    blocked += brute;
    open += !brute;
    outside += hull;
  }
  EXPECT(blocked > PAIRS / 10 && open > PAIRS / 10 && outside > 0,
         "too few of each kind: %d blocked (%d by the hull), %d open", blocked, outside, open);
  tr_sliver_ctx_free(&c);
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  if (!strcmp(argv[1], "brute"))
    return walk_agrees_with_brute_force();
  fprintf(stderr, "unknown case %s\n", argv[1]);
  return 2;
}
