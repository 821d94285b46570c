/* Sub-faces split for their own shape (issue 17; tr_refine_params.subface_ratio, off by
 * default). A tet standing on a sub-face with a small angle has a small dihedral angle at
 * the edge from that corner to its apex unless the apex stands high over the face, and
 * the points that would fix it must lie on the facet, where tet refinement puts them only
 * for encroachment. So, as in Shewchuk's (1998) and TetGen's (Si 2015) refinement, a
 * sub-face whose 2D radius-edge ratio (circumradius / shortest edge) exceeds the bound
 * is split at its circumcentre, through the facet split path of split.c (the exact
 * dyadic barycentric point, the sub-segments that point encroaches split first), before
 * the bad tets.
 *
 * Termination, and angles the input forces:
 *  - a sub-face whose smallest angle lies between two sub-segments is a corner of its
 *    input triangle (two sub-segments of one sub-face meet at an input vertex, or are
 *    collinear): that angle is the input's, no split improves it;
 *  - a sub-face whose shortest edge joins two constraints that meet at an input vertex
 *    under a small angle (angles.c: two edges of a triangle at a corner under 30
 *    degrees, constraints of different triangles under 60) spans that wedge and is left
 *    as the bad tets of refine.c are;
 *  - the shortest edge is taken at least as long as the insertion radii of its two ends
 *    (refine_impl.h, vrad): a vertex placed next to an older one for another reason (a
 *    sub-segment split, whose position is fixed) does not make the sub-faces around the
 *    older one "bad" in turn, the cascade of ever shorter edges that does not end
 *    (Shewchuk 1998, insertion radii);
 *  - near a small angle the facet split path refuses points that would encroach a
 *    protected sub-segment (angles.c), and the sub-face is left, unless
 *    rf_subshape_may_split below allows that split.
 * Measured on 12 CGAL models (docs/refinement.md): at S = R = 1.414 it costs 41% more CPU and 26% more
 * tets for 3.87% of tets under 10 degrees against 3.95%; most thin sub-faces there lie
 * across the wedges of thin input triangles, which the second rule leaves.
 * Whole bench (bench/quality, 74 models, same tree and load): off, targets met on 54 in
 * 76.7 s; on without the lineage bound of rf_subshape_may_split, 58 in 98.8 s (+29%). The
 * extra cost was sub-segment points, not facet points:
 * f's circumcentre lies beyond a protected sub-segment that rf_subshape_may_split lets it
 * split (cheese 14,610 -> 42,049 edge points for 4,736 -> 8,021 facet points; pinion 3,076
 * -> 5,729 for 0 -> 22), and that is also where every gain comes from: without the
 * may_split allowance beam, horizons-domain, torus_quad and oblong are as with it off.
 * Splitting only a sub-face under a bad tet that refinement leaves (every tet on a sub-face
 * over S >= R is over R: its circumsphere holds the sub-face's circumcircle) pays less:
 * 54 models in 120.7 s, the splits coming late among more points; the input's sub-faces
 * scanned and the later ones only under a left tet: 56 in 93.6 s (mpi: 51% -> 31% of tets
 * under 10 degrees, the only model it helps more than the scan).
 * Measured in doubles: the shape only chooses which sub-faces get a point; where the
 * point lies and how the mesh changes is decided exactly by the facet split path. */
#include <math.h>

#include "refine/refine_impl.h"

static double len2(const double *a, const double *b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
         (a[2] - b[2]) * (a[2] - b[2]);
}

int rf_subface_shape_bad(const rf_ctx *c, uint32_t f, double bound)
{
  const uint32_t *v = c->sfv + 3 * (size_t)f;
  const double *x[3];
  for (int i = 0; i < 3; i++)
    x[i] = c->m->xyz + 3 * (size_t)v[i];
  /* l[i]: squared length of the edge opposite vertex i */
  double l[3] = {len2(x[1], x[2]), len2(x[2], x[0]), len2(x[0], x[1])};
  int s = 0;
  for (int i = 1; i < 3; i++)
    s = l[i] < l[s] ? i : s;
  /* circumradius R = abc / (4 area), |u x w| = 2 area */
  double u[3], w[3], n[3];
  for (int i = 0; i < 3; i++) {
    u[i] = x[1][i] - x[0][i];
    w[i] = x[2][i] - x[0][i];
  }
  n[0] = u[1] * w[2] - u[2] * w[1];
  n[1] = u[2] * w[0] - u[0] * w[2];
  n[2] = u[0] * w[1] - u[1] * w[0];
  double a2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(a2 > 0))
    return 0; /* degenerate in doubles: nothing this measure can say */
  /* R^2 = l0 l1 l2 / (4 |n|^2) */
  double R2 = l[0] * l[1] * l[2] / (4 * a2);
  uint32_t p = v[(s + 1) % 3], q = v[(s + 2) % 3];
  double e2 = l[s];
  double rp = p < c->capv ? c->vrad[p] : 0, rq = q < c->capv ? c->vrad[q] : 0;
  e2 = fmax(e2, fmax(rp * rp, rq * rq));
  if (!(R2 > bound * bound * e2))
    return 0;
  /* the smallest angle (at vertex s, opposite the shortest edge) between two
   * sub-segments: an input corner */
  if (rf_subseg_of(c, v[s], p) != TR_NONE && rf_subseg_of(c, v[s], q) != TR_NONE)
    return 0;
  /* the shortest edge spans a wedge: its ends lie on two constraints that meet at an
   * input vertex under a small angle (angles.c), where the sub-faces across the wedge can
   * be no wider than the wedge; making them rounder takes points graded down to the
   * corner (measured: twice the tets on pinion and joint for a few points of share) */
  return !rf_small_angle_edge(c, p, q);
}

tr_status rf_subshape_scan(rf_ctx *c)
{
  if (!c->shape_on)
    return TR_OK;
  for (; c->shape_next < c->nsf; c->shape_next++) {
    uint32_t f = c->shape_next;
    if (!c->sfdead[f] && !c->sfnosplit[f] && rf_subface_shape_bad(c, f, c->shape_bound))
      TR_CHECK(tr_u32buf_push(&c->qface, f));
  }
  return TR_OK;
}

/* Near a sharp corner of f's own input triangle (under 30 degrees, angles.c) the
 * sub-segments on that triangle's edges are protected from the triangle's facet points,
 * which would otherwise split them towards the corner without end; that also leaves the
 * sub-faces there as thin as the triangle's sides are long. For a sub-segment g on an edge
 * of f's input triangle, encroached by f's split point or lying between f and its
 * circumcentre: g is split when a vertex of f encroaches it (unless the small-angle rules
 * protect g from that vertex), or when the new vertex's insertion radius (at most half of
 * g) is at least f's shortest edge, the one f's split is meant to lengthen (Shewchuk's
 * rule for small angles in 2D, 2002): a split that would make a shorter edge than f's is
 * refused, so the splits do not follow the corner down.
 * Either way only while g is at least half its input edge: the bound on g's lineage. Each
 * such split lets f's pieces, thin again along the new halves, split them in turn, and
 * that chain of sub-segment points was the option's whole cost (see the top: cheese
 * 14,610 -> 42,049 edge points); the first split of an input edge is where its gains come
 * from (beam, horizons-domain, torus_quad meet the targets with it). Whole bench with the
 * bound: targets met on 57 of 74 (54 off, 58 unbounded) for 5% more CPU than off (29%
 * unbounded); mpi 50.7% -> 33.8% of tets under 10 degrees. */
int rf_subshape_may_split(const rf_ctx *c, uint32_t f, uint32_t g)
{
  const uint32_t *T = c->plc->tris + 3 * (size_t)c->sftri[f];
  uint32_t A = c->ssab[2 * (size_t)g], B = c->ssab[2 * (size_t)g + 1];
  int ha = 0, hb = 0;
  for (int i = 0; i < 3; i++) {
    ha |= T[i] == A;
    hb |= T[i] == B;
  }
  if (!ha || !hb)
    return 0;
  const double *pa = c->plc->xyz + 3 * (size_t)A, *pb = c->plc->xyz + 3 * (size_t)B;
  if (4 * len2(c->m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g],
               c->m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g + 1]) < len2(pa, pb))
    return 0;
  const uint32_t *v = c->sfv + 3 * (size_t)f;
  /* a vertex of f inside g's diametral sphere: the facet's triangulation is not Delaunay
   * there (recovery leaves it constrained), and a flat f's circumcentre lies far beyond g
   * without encroaching it; g is split as Delaunay refinement would have split it for
   * that vertex, unless the vertex is one the small-angle rules protect it from */
  tr_point ga = tr_mesh_point(c->m, c->ssv[2 * (size_t)g]),
           gb = tr_mesh_point(c->m, c->ssv[2 * (size_t)g + 1]);
  for (int i = 0; i < 3; i++) {
    if (v[i] == c->ssv[2 * (size_t)g] || v[i] == c->ssv[2 * (size_t)g + 1])
      continue;
    tr_point pv = tr_mesh_point(c->m, v[i]);
    if (rf_in_diametral(&ga, &gb, &pv) && !rf_protected(c, 1, g, v[i]))
      return 1;
  }
  const double *x[3];
  for (int i = 0; i < 3; i++)
    x[i] = c->m->xyz + 3 * (size_t)v[i];
  double e2 = fmin(len2(x[0], x[1]), fmin(len2(x[1], x[2]), len2(x[2], x[0])));
  double g2 = len2(c->m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g],
                   c->m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g + 1]);
  return g2 >= 4 * e2;
}
