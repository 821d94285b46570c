/* Which candidate points of the insertion (insert.c) no cavity can take, known before
 * the cavity is built.
 *
 * A cavity of x that keeps sliver t and passes insert.c's tests is star-shaped about x:
 * its boundary faces are all strictly seen from x and their cone is a manifold of
 * positive tets, so the cone tiles the cavity, and every point of the cavity sees x along
 * a segment inside it. The segment from a point g strictly inside t to x therefore lies
 * in the cavity. If that segment leaves the real tets, or crosses a constraint face
 * (a sub-face) through its relative interior, the cavity would hold the tets on both
 * sides of that face, which keeps_subfaces refuses, or a point outside the mesh: the
 * candidate fails whatever the cavity. This walks the segment, tet by tet, and says so.
 *
 * Growing such a cavity cost the most: a circumcentre beyond the boundary or a sub-face
 * floods every tet behind a face it does not see, up to SL_MAX_CAVITY tets, and then
 * fails (65395.stl: 212k of 622k cavities). The walk is as long as the segment.
 *
 * Only the screened candidates (doubles: the geometry of m->xyz) are walked, where the
 * cavity's tests are orientations of the same doubles; any degenerate step (the segment
 * through an edge or a vertex, g not strictly inside t, a walk past SL_REACH_STEPS) says
 * nothing, and the cavity is built as before. The argument needs the cavity's tets
 * positive in doubles too, which a Steiner point's rounded coordinates could break in
 * principle: debug builds build every refused candidate's cavity and assert that it
 * fails (insert.c, try_point), and the outputs were the same with and without the walk
 * on all 155 models of the real-world corpus. */
#include "predicates/predicates.h"
#include "sliver/sliver.h"

#define SL_REACH_STEPS 512

static const double *vx(const struct tr_mesh *m, uint32_t t, int i)
{
  return m->xyz + 3 * (size_t)m->tv[4 * (size_t)t + (size_t)i];
}

/* The face of u (not `entry`) through whose relative interior the line from g to x
 * leaves u while x lies strictly beyond it: its index, -1 when x lies in the closed u,
 * -2 when the line meets u's boundary ahead of g only in an edge or a vertex (or the
 * doubles disagree with themselves: an inverted tet). */
static int exit_face(const struct tr_mesh *m, uint32_t u, int entry, const double g[3],
                     const double x[3])
{
  int beyond = 0;
  for (int k = 0; k < 4; k++) {
    if (k == entry)
      continue;
    const uint8_t *f = tr_face_vtx[k];
    const double *a = vx(m, u, f[0]), *b = vx(m, u, f[1]), *d = vx(m, u, f[2]);
    if (!(tr_orient3d(a, b, d, x) < 0))
      continue;
    beyond = 1;
    /* the line g -> x through the open triangle abd: the three edge orientations agree */
    double s0 = tr_orient3d(g, x, a, b), s1 = tr_orient3d(g, x, b, d),
           s2 = tr_orient3d(g, x, d, a);
    if ((s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0))
      return k;
  }
  return beyond ? -2 : -1;
}

int tr_sliver_segment_blocked(const tr_sliver_ctx *c, uint32_t t, const double x[3])
{
  const struct tr_mesh *m = c->m;
  double g[3];
  for (int j = 0; j < 3; j++)
    g[j] = 0.25 * (vx(m, t, 0)[j] + vx(m, t, 1)[j] + vx(m, t, 2)[j] + vx(m, t, 3)[j]);
  for (int k = 0; k < 4; k++) {
    const uint8_t *f = tr_face_vtx[k];
    if (!(tr_orient3d(vx(m, t, f[0]), vx(m, t, f[1]), vx(m, t, f[2]), g) > 0))
      return 0; /* g not strictly inside t in doubles (a flat tet) */
  }
  uint32_t u = t;
  int entry = -1;
  for (int step = 0; step < SL_REACH_STEPS; step++) {
    int k = exit_face(m, u, entry, g, x);
    if (k < 0)
      return 0; /* x reached, or a degenerate crossing: nothing known */
    uint32_t nb = TR_NEIG(m, u, k);
    const uint8_t *f = tr_face_vtx[k];
    const uint32_t *tv = m->tv + 4 * (size_t)u;
    uint32_t fv[3] = {tv[f[0]], tv[f[1]], tv[f[2]]};
    if (nb == TR_NONE || !tr_tet_is_real(m, nb) || tr_sliver_protected(c, fv, 3))
      return 1;
    entry = (int)(m->tn[4 * (size_t)u + (size_t)k] & 3);
    u = nb;
  }
  return 0;
}
