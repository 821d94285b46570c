/* The refinement loop (refine.h): queues of encroached sub-segments, encroached sub-faces
 * and bad tets, served in that order (Shewchuk 1998: constraints are split before the
 * tets they would otherwise spoil).
 *
 * Encroachment is tested only for a point about to be inserted (a circumcentre, a facet
 * split point), never for the vertices already in the mesh against the pieces around
 * them: a point on an input edge always lies in the diametral sphere of one of the other
 * two edges of a triangle it splits (its two angles there sum to 180 degrees), so on a
 * curved surface, where every triangle edge is a segment, that rule split edge after edge
 * along the surface (elephant.off: 12,257 edge points of 17,505, against 137 of 762
 * without it). The mesh is constrained, not conforming Delaunay, so an encroached piece
 * needs no split for the mesh to hold it; a vertex that spoils a tet near it makes that
 * tet bad, and its circumcentre, which then encroaches the piece, splits it. */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "refine/quality.h"
#include "refine/refine_impl.h"

uint64_t tr_refine_default_budget(uint32_t npoints, double domain_volume, double max_volume)
{
  double b = 100.0 * npoints + 100000;
  if (max_volume > 0 && domain_volume > 0)
    b += 20.0 * domain_volume / max_volume;
  /* a point costs about 1.2 KB and 60 us: past the ceiling a default run would fill the
   * memory of most machines for hours (-a 1e-300 asked for 4e9 points); a larger mesh
   * takes an explicit budget */
  double ceiling = 8.0 * npoints > TR_REFINE_BUDGET_CEILING ? 8.0 * npoints
                                                            : TR_REFINE_BUDGET_CEILING;
  return b > ceiling ? (uint64_t)ceiling : (uint64_t)b;
}

double tr_refine_region_bound_of(const uint32_t *ids, const double *bounds, uint32_t n,
                                 double max_volume, uint32_t region)
{
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (ids[mid] < region)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo < n && ids[lo] == region && (!(max_volume > 0) || bounds[lo] < max_volume))
    return bounds[lo];
  return max_volume;
}

double tr_refine_tet_bound(const tr_refine_params *par, const struct tr_mesh *m, uint32_t t)
{
  if (!par->nregion_bounds || !m->region)
    return par->max_volume;
  return tr_refine_region_bound_of(par->region_id, par->region_max_volume, par->nregion_bounds,
                                   par->max_volume, m->region[t]);
}

/* Radius-edge ratio in doubles (a measure: it only decides which tets get a point); the
 * volume bound exactly, so that "every tet's volume is at most V" holds as stated. */
static int too_big(const rf_ctx *c, uint32_t t)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double bound = tr_refine_tet_bound(&c->par, m, t);
  if (!(bound > 0))
    return 0;
  tr_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = tr_mesh_point(m, v[i]);
  return rf_volume_above(&p[0], &p[1], &p[2], &p[3], bound);
}

static int tet_bad(const rf_ctx *c, uint32_t t)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double ratio, vol;
  tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1], m->xyz + 3 * (size_t)v[2],
               m->xyz + 3 * (size_t)v[3], &ratio, &vol, NULL, NULL);
  return (c->par.ratio > 0 && !c->volume_only && ratio > c->par.ratio) || too_big(c, t) ||
         rf_sizing_tet_over(c, t);
}

static tr_status push_tet(rf_ctx *c, uint32_t t)
{
  if (!tet_bad(c, t))
    return TR_OK;
  TR_CHECK(tr_u32buf_push(&c->qtet, t));
  for (int i = 0; i < 4; i++)
    TR_CHECK(tr_u32buf_push(&c->qtet, c->m->tv[4 * (size_t)t + i]));
  return TR_OK;
}

/* The sub-segments of t that a vertex of t off them encroaches, queued for splitting
 * (*pushed = 1 when one was; left as it was otherwise): with wedge_only 0 each one not
 * protected near a small input angle, or protected but one that wedge grading may split
 * (angles.c, rf_wedge_split); with wedge_only 1 only the ones wedge grading may split.
 * Those wedge grading takes are counted in st->wedge_splits. */
static tr_status encroached_segments(rf_ctx *c, uint32_t t, int wedge_only, int *pushed)
{
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  for (int e = 0; e < 6; e++) {
    uint32_t g = rf_subseg_of(c, v[tr_edge_vtx[e][0]], v[tr_edge_vtx[e][1]]);
    if (g == TR_NONE || c->ssnosplit[g])
      continue;
    tr_point a = tr_mesh_point(c->m, c->ssv[2 * (size_t)g]),
             b = tr_mesh_point(c->m, c->ssv[2 * (size_t)g + 1]);
    for (int k = 0; k < 4; k++) {
      if (k == tr_edge_vtx[e][0] || k == tr_edge_vtx[e][1])
        continue;
      tr_point p = tr_mesh_point(c->m, v[k]);
      if (!rf_in_diametral(&a, &b, &p))
        continue;
      int wedge = wedge_only || rf_protected(c, 1, g, v[k]);
      if (wedge && !(c->par.wedge_grading && rf_wedge_split(c, g, v[k])))
        continue;
      TR_CHECK(tr_u32buf_push(&c->qseg, g));
      c->st->wedge_splits += (uint64_t)wedge;
      *pushed = 1;
      break;
    }
  }
  return TR_OK;
}

/* The fallback for a bad tet whose circumcentre cannot be used (it lies beyond a sub-face,
 * on a constraint, or encroaches a piece that may not be split): the constraints of t its
 * own vertices encroach, each sub-face by the vertex opposite it, each sub-segment by the
 * two vertices off it, are queued for splitting, unless protected near a small input
 * angle (a sub-segment then still is where wedge grading lets it be, angles.c: joint.off
 * 0.19% -> 0.06% of tets under 10 degrees, smallest angle 2.6 -> 7.3). *pushed = 1 when
 * one was. */
static tr_status own_encroached(rf_ctx *c, uint32_t t, int *pushed)
{
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  *pushed = 0;
  for (int k = 0; k < 4; k++) {
    uint32_t f = rf_subface_of(c, v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]);
    if (f == TR_NONE || c->sfnosplit[f])
      continue;
    tr_point a = tr_mesh_point(c->m, c->sfv[3 * (size_t)f]),
             b = tr_mesh_point(c->m, c->sfv[3 * (size_t)f + 1]),
             d = tr_mesh_point(c->m, c->sfv[3 * (size_t)f + 2]), p = tr_mesh_point(c->m, v[k]);
    if (rf_in_equatorial(&a, &b, &d, &p) && !rf_protected(c, 0, f, v[k])) {
      TR_CHECK(tr_u32buf_push(&c->qface, f));
      *pushed = 1;
    }
  }
  return encroached_segments(c, t, 0, pushed);
}

static tr_status refine_tet(rf_ctx *c, uint32_t t, int at_centroid);

/* Bad tet t is left as it is, unless its own vertices encroach a constraint piece that
 * can be split (then t comes back after that split), or it is over the volume bound: then
 * its centroid, which lies inside it, is tried instead of its circumcentre. */
static tr_status leave_tet(rf_ctx *c, uint32_t t, int at_centroid)
{
  int pushed;
  TR_CHECK(own_encroached(c, t, &pushed));
  if (pushed)
    return push_tet(c, t);
  if (!at_centroid && too_big(c, t))
    return refine_tet(c, t, 1);
  c->st->skipped_other++;
  return TR_OK;
}

/* Would the point at p (doubles) lie closer to a vertex of the tets (the cavity) than
 * that vertex's insertion radius (its spacing while c->spacing_on, see rf_after_insert),
 * or than cap if that is smaller (rf_sizing_cap: a tet over the size field)?
 * Such a point would make an edge shorter than the one its neighbour was inserted to
 * fix, and the next round of bad tets around it a finer one still: the cascade that ends
 * only at the budget (Shewchuk 1998, insertion radii; TetGen rejects such circumcentres
 * the same way, Si 2015). A measure in doubles: it only chooses which points are
 * inserted. */
static int too_close(const rf_ctx *c, const uint32_t *tets, size_t n, const double *p,
                     double cap)
{
  const struct tr_mesh *m = c->m;
  for (size_t i = 0; i < n; i++) {
    const uint32_t *v = m->tv + 4 * (size_t)tets[i];
    for (int j = 0; j < 4; j++) {
      double r = v[j] < c->capv ? c->vrad[v[j]] : 0;
      if (c->spacing_on && v[j] < c->capv && c->vspace[v[j]] > 0 && c->vspace[v[j]] < r)
        r = c->vspace[v[j]];
      r = r < cap ? r : cap;
      if (r > 0 && rf_dist2(p, m->xyz + 3 * (size_t)v[j]) < r * r)
        return 1;
    }
  }
  return 0;
}

/* rad: an upper bound of the new point's insertion radius (the shortest edge of the tet
 * it refines), INFINITY if none; its distance to the nearest vertex of its new tets is
 * taken when smaller.
 *
 * While c->spacing_on (par.spacing_radii), the spacing of every refinement vertex of the
 * new tets shrinks to its distance to the new point when that is smaller: its current
 * spacing, not the one it had when inserted. A point split into a long sub-segment keeps
 * the sub-segment's half as its insertion radius after its neighbours on the adjacent
 * input edges came within a tenth of that, and the insertion-radius rule refuses every
 * circumcentre within that half (pipe.off: 977 bad tets left so, most beside 40 input
 * edges of length 1 with points 0.05 apart around them). With spacings the rule still
 * refuses a point that would make an edge shorter than every edge at such a vertex; it
 * is no proof of termination: merged_facet_notch.off splits facets to any budget with it
 * (and, once it has started, with the insertion radii too), so the stage ends at
 * spacing_cap points, its mesh valid and the bad tets left. */
tr_status rf_after_insert(rf_ctx *c, uint32_t pid, int kind, uint32_t own, double rad)
{
  TR_CHECK(rf_vertex_room(c, pid + 1));
  TR_CHECK(rf_sizing_vertex(c, pid));
  c->vkind[pid] = (uint8_t)kind;
  c->vown[pid] = own;
  const double *x = c->m->xyz + 3 * (size_t)pid;
  double r2 = rad * rad;
  for (size_t i = 0; i < c->newtets.n; i++) {
    const uint32_t *v = c->m->tv + 4 * (size_t)c->newtets.a[i];
    for (int j = 0; j < 4; j++)
      if (v[j] != pid) {
        double d = rf_dist2(x, c->m->xyz + 3 * (size_t)v[j]);
        r2 = d < r2 ? d : r2;
        if (c->spacing_on && c->vrad[v[j]] > 0) {
          double *s = c->vspace + v[j];
          if (!(*s > 0))
            *s = c->vrad[v[j]];
          if (d < *s * *s)
            *s = sqrt(d);
        }
      }
  }
  c->vrad[pid] = isfinite(r2) ? sqrt(r2) : 0;
  if (c->spacing_on)
    c->vspace[pid] = c->vrad[pid];
  c->st->points++;
  for (size_t i = 0; i < c->newtets.n; i++) {
    TR_CHECK(push_tet(c, c->newtets.a[i]));
  }
  return TR_OK;
}

/* A tet whose shortest edge joins points on two constraints that meet at an input vertex
 * under a small angle (angles.c): its quality is forced by that angle, it is left as is. */
static int forced_by_angle(const rf_ctx *c, uint32_t t)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  int best = 0;
  double lmin = INFINITY;
  for (int e = 0; e < 6; e++) {
    const double *x = m->xyz + 3 * (size_t)v[tr_edge_vtx[e][0]],
                 *y = m->xyz + 3 * (size_t)v[tr_edge_vtx[e][1]];
    double l = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
               (x[2] - y[2]) * (x[2] - y[2]);
    if (l < lmin) {
      lmin = l;
      best = e;
    }
  }
  return rf_small_angle_edge(c, v[tr_edge_vtx[best][0]], v[tr_edge_vtx[best][1]]);
}

#ifndef NDEBUG
/* The close shortcut of refine_tet against the cavity it skips: where that cavity is
 * built, p is too close to one of its vertices and encroaches no piece to split. */
static tr_status check_close_skip(rf_ctx *c, uint32_t found, const tr_point *p, double emin,
                                  double cap)
{
  struct tr_mesh *m = c->m;
  int ok = 0;
  c->split_seg = TR_NONE;
  TR_CHECK(rf_cavity(c, found, p, m->nv, 0, &ok));
  if (!ok)
    return TR_OK;
  assert(too_close(c, c->cav.a, c->cav.n, p->d, cap));
  for (size_t i = 0; c->close_splits && i < c->cav.n; i++) {
    const uint32_t *w = m->tv + 4 * (size_t)c->cav.a[i];
    for (int e = 0; e < 6; e++) {
      uint32_t g = rf_subseg_of(c, w[tr_edge_vtx[e][0]], w[tr_edge_vtx[e][1]]);
      if (g == TR_NONE || !rf_close_split(c, g, emin))
        continue;
      tr_point a = tr_mesh_point(m, c->ssv[2 * (size_t)g]), b = tr_mesh_point(m, c->ssv[2 * (size_t)g + 1]);
      assert(!rf_in_diametral(&a, &b, p));
    }
  }
  rf_cavity_release(c);
  return TR_OK;
}
#endif

/* Wedge grading (angles.c, rf_wedge_split) for a bad tet t that forced_by_angle exempts
 * (own_encroached does the same for the tets it works on):
 * when t has a dihedral angle under RF_WEDGE_DIHEDRAL, the sub-segments of t that a
 * vertex of t off them encroaches across a small-angle wedge and that rf_wedge_split
 * lets grade it are queued (*pushed = 1); t comes back after their splits. Tets that only
 * miss the radius-edge bound are not worth the points (rotor_small.off with them, measured
 * before the 3-degree floor: 12% more tets, for 0.34% of tets under 10 degrees against
 * 0.43%). */
#define RF_WEDGE_DIHEDRAL 10.0
static tr_status wedge_encroached(rf_ctx *c, uint32_t t, int *pushed)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  *pushed = 0;
  double r, w;
  if (!(tr_tet_min_dihedral(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                            m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &r, &w) <
        RF_WEDGE_DIHEDRAL))
    return TR_OK;
  return encroached_segments(c, t, 1, pushed);
}

static tr_status refine_tet(rf_ctx *c, uint32_t t, int at_centroid)
{
  struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double ratio, vol, cc[3], emin = INFINITY;
  for (int e = 0; e < 6; e++) {
    double d = rf_dist2(m->xyz + 3 * (size_t)v[tr_edge_vtx[e][0]], m->xyz + 3 * (size_t)v[tr_edge_vtx[e][1]]);
    emin = d < emin ? d : emin;
  }
  if (!tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1], m->xyz + 3 * (size_t)v[2],
                    m->xyz + 3 * (size_t)v[3], &ratio, &vol, NULL, cc)) {
    c->st->skipped_other++;
    return TR_OK;
  }
  if (at_centroid)
    for (int i = 0; i < 3; i++)
      cc[i] = 0.25 * (m->xyz[3 * (size_t)v[0] + i] + m->xyz[3 * (size_t)v[1] + i] +
                      m->xyz[3 * (size_t)v[2] + i] + m->xyz[3 * (size_t)v[3] + i]);
  int big = too_big(c, t); /* a volume bound is met whatever the edges it makes */
  if (!big && forced_by_angle(c, t)) {
    int pushed = 0;
    if (c->par.wedge_grading)
      TR_CHECK(wedge_encroached(c, t, &pushed));
    if (pushed)
      return push_tet(c, t);
    c->st->skipped_small_angle++;
    return TR_OK;
  }
  tr_point p = tr_pt_d(cc);
  uint32_t found, blocker;
  TR_CHECK(rf_locate(c, t, &p, &found, &blocker));
  if (found == TR_NONE) {
    /* beyond a sub-face: split it if the circumcentre encroaches it */
    if (blocker != TR_NONE && !c->sfnosplit[blocker]) {
      const uint32_t *S = c->sfv + 3 * (size_t)blocker;
      tr_point a = tr_mesh_point(m, S[0]), b = tr_mesh_point(m, S[1]), d = tr_mesh_point(m, S[2]);
      if (rf_in_equatorial(&a, &b, &d, &p)) {
        TR_CHECK(tr_u32buf_push(&c->qface, blocker));
        return push_tet(c, t);
      }
    }
    return leave_tet(c, t, at_centroid);
  }
  /* A circumcentre too close to a vertex of the tet holding it is too close to a vertex
   * of its cavity, which keeps that tet: unless it encroaches a long piece (longs.c), its
   * cavity would only be built to be released below (most of them: cheese.off 60k of
   * 115k cavities). Only where that cavity fails (3 of those 60k there) does this
   * decide otherwise: skipped as too close, not left to leave_tet. */
  double cap = rf_sizing_cap(c, t);
  if (!big && too_close(c, &found, 1, cc, cap)) {
    int maybe = 0;
    if (c->close_splits)
      TR_CHECK(rf_longs_near(c, cc, emin, &maybe));
    if (!maybe) {
#ifndef NDEBUG
      TR_CHECK(check_close_skip(c, found, &p, emin, cap));
#endif
      c->st->skipped_close++;
      return TR_OK;
    }
  }
  int ok = 0;
  c->split_seg = TR_NONE;
  TR_CHECK(rf_cavity(c, found, &p, m->nv, 0, &ok));
  if (!ok)
    return leave_tet(c, t, at_centroid);
  /* constraints the circumcentre encroaches are split instead; if one of them cannot be
   * split (protected near a small input angle, or refused), the tet is left as it is: a
   * point inserted that close to a constraint would only make worse tets there. The
   * centroid of a tet over the volume bound is the exception (must): the bound is the
   * user's hard limit, so a piece that cannot be split does not stop it, nor does the
   * cone check below (found by fuzz_pipeline_quality: tests/data/volume_blocked.off).
   *
   * A circumcentre too close to a new vertex is not inserted, but the long sub-segments
   * it encroaches are still split (close splits, rf_close_split): a point on a long input
   * edge keeps half its first piece as insertion radius after points came near it on
   * neighbouring edges, and refusing every circumcentre within that radius left the tets
   * standing on the long thin sub-faces between them (oblong.off: 236 tets under 10
   * degrees, 19 with close splits; pipe.off 7 -> 0; the long box of test_merge: worst
   * ratio 2.598 -> 1.436). The length bounds keep such splits from cascading: with every
   * encroached piece split, femur.off ran past 300 s and merged_facet_notch.off to the
   * budget; with any piece twice the shortest edge, CPU on the CGAL bench went from 68 to
   * 99 s. Encroached sub-faces are not split for a close circumcentre (couplingdown.off,
   * pieces twice the shortest edge: 83.6k tets in 5.2 s with them, 70.8k in 3.9 s
   * without, 392 against 433 tets under 10 degrees). After spacing_cap points the close
   * splits stop (run), a guard. */
  int must = at_centroid && big;
  int pushed = 0, blocked = 0, close = !big && too_close(c, c->cav.a, c->cav.n, cc, cap);
  if (close && !c->close_splits) {
    rf_cavity_release(c);
    c->st->skipped_close++;
    return TR_OK;
  }
  tr_status st = TR_OK;
  for (size_t i = 0; st == TR_OK && i < c->cav.n && !blocked; i++) {
    const uint32_t *w = m->tv + 4 * (size_t)c->cav.a[i];
    for (int k = 0; k < 4 && st == TR_OK && !blocked && !close; k++) {
      uint32_t f = rf_subface_of(c, w[tr_face_vtx[k][0]], w[tr_face_vtx[k][1]], w[tr_face_vtx[k][2]]);
      if (f == TR_NONE)
        continue;
      const uint32_t *S = c->sfv + 3 * (size_t)f;
      tr_point a = tr_mesh_point(m, S[0]), b = tr_mesh_point(m, S[1]), d = tr_mesh_point(m, S[2]);
      if (!rf_in_equatorial(&a, &b, &d, &p))
        continue;
      if (c->sfnosplit[f])
        blocked = !must;
      else {
        st = tr_u32buf_push(&c->qface, f);
        pushed = 1;
      }
    }
    for (int e = 0; e < 6 && st == TR_OK && !blocked; e++) {
      uint32_t g = rf_subseg_of(c, w[tr_edge_vtx[e][0]], w[tr_edge_vtx[e][1]]);
      if (g == TR_NONE)
        continue;
      if (close && !rf_close_split(c, g, emin))
        continue; /* first: the exact test costs far more */
      tr_point a = tr_mesh_point(m, c->ssv[2 * (size_t)g]), b = tr_mesh_point(m, c->ssv[2 * (size_t)g + 1]);
      if (!rf_in_diametral(&a, &b, &p))
        continue;
      if (c->ssnosplit[g])
        blocked = !must;
      else {
        st = tr_u32buf_push(&c->qseg, g);
        pushed = 1;
      }
    }
  }
  if (close && (blocked || !pushed)) {
    rf_cavity_release(c);
    TR_CHECK(st);
    c->st->skipped_close++;
    return TR_OK;
  }
  if (st != TR_OK || blocked || pushed) {
    rf_cavity_release(c);
    TR_CHECK(st);
    if (blocked)
      return leave_tet(c, t, at_centroid);
    return push_tet(c, t);
  }
  /* a cavity shrunk to be star-shaped can leave a face the point sees almost edge-on:
   * the cone would hold a tet far worse than the one being refined; leave that one */
  for (size_t i = 0; !must && i < c->bfaces.n; i++) {
    uint32_t u = c->bfaces.a[i] >> 2;
    int k = (int)(c->bfaces.a[i] & 3);
    const double *x[3];
    for (int j = 0; j < 3; j++)
      x[j] = m->xyz + 3 * (size_t)m->tv[4 * (size_t)u + tr_face_vtx[k][j]];
    double r2, v2;
    tr_tet_shape(x[0], x[1], x[2], cc, &r2, &v2, NULL, NULL);
    if (!(r2 <= 1000) || !(r2 <= 100 * ratio)) {
      rf_cavity_release(c);
      if (big) /* its centroid then, whose cone is not checked */
        return refine_tet(c, t, 1);
      c->st->skipped_other++;
      return TR_OK;
    }
  }
  uint32_t pid, was[4];
  memcpy(was, v, sizeof was);
  TR_CHECK(tr_mesh_add_vertex(m, cc, &pid));
  TR_CHECK(rf_insert(c, pid, &ok));
  if (!ok) {
    c->st->skipped_other++;
    return TR_OK;
  }
  c->st->inside++;
  TR_CHECK(rf_after_insert(c, pid, RF_FREE, TR_NONE, sqrt(emin)));
  /* a circumcentre beyond a sub-face from t, or dropped from its cavity by visibility,
   * leaves t whole: over the volume bound it goes back in the queue (next time its
   * circumcentre is a vertex and its centroid is taken; joint.off under -a 0.0002 once
   * kept 8 tets over the bound so). A bad ratio alone is not retried. */
  if (big && !tr_tet_is_free(m, t) && !memcmp(m->tv + 4 * (size_t)t, was, sizeof was))
    return push_tet(c, t);
  return TR_OK;
}

int rf_tet_bad(const rf_ctx *c, uint32_t t)
{
  return tet_bad(c, t);
}
int rf_too_big(const rf_ctx *c, uint32_t t)
{
  return too_big(c, t);
}
int rf_forced_by_angle(const rf_ctx *c, uint32_t t)
{
  return forced_by_angle(c, t);
}
int rf_too_close(const rf_ctx *c, const uint32_t *tets, size_t n, const double *p, double cap)
{
  return too_close(c, tets, n, p, cap);
}
tr_status rf_push_tet(rf_ctx *c, uint32_t t)
{
  return push_tet(c, t);
}
tr_status rf_refine_tet(rf_ctx *c, uint32_t t)
{
  return refine_tet(c, t, 0);
}

/* Outer and ghost tets are freed; the faces they shared with inner tets become TR_NONE. */
static void discard_outer(struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && (tr_tet_is_ghost(m, t) || (m->flags[t] & TR_TF_OUTER)))
      m->flags[t] |= TR_TF_MARK;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t) || (m->flags[t] & TR_TF_MARK))
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t n = TR_NEIG(m, t, k);
      if (n != TR_NONE && (m->flags[n] & TR_TF_MARK))
        m->tn[4 * (size_t)t + k] = TR_NONE;
    }
  }
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && (m->flags[t] & TR_TF_MARK)) {
      m->flags[t] = 0;
      tr_tet_free(m, t);
    }
  for (uint32_t v = 0; v < m->nv; v++)
    m->v2t[v] = TR_NONE;
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t))
      for (int i = 0; i < 4; i++)
        m->v2t[m->tv[4 * (size_t)t + i]] = t;
}

static void ctx_free(rf_ctx *c)
{
  rf_rounds_free(c);
  rf_longs_free(&c->longs);
  free(c->vrad);
  free(c->ssfoot);
  free(c->vspace);
  free(c->vh);
  tr_u32buf *b[] = {&c->qseg, &c->qface, &c->qtet, &c->cav, &c->init, &c->bfaces,
                    &c->stack, &c->newsf, &c->tmp, &c->newtets};
  for (size_t i = 0; i < sizeof b / sizeof *b; i++)
    tr_u32buf_free(b[i]);
  free(c->tstate);
  free(c->vcone);
  free(c->vhead);
  tr_u32buf_free(&c->cnext);
  rf_tables_free(c); /* last: it zeroes the whole context */
}

static size_t left(const tr_u32buf *q, size_t head, size_t w)
{
  return (q->n - head) / w;
}

/* Drops the served prefix of a queue once it is most of it. */
static void compact_queue(tr_u32buf *q, size_t *head)
{
  if (*head > 4096 && *head * 2 > q->n) {
    memmove(q->a, q->a + *head, (q->n - *head) * sizeof *q->a);
    q->n -= *head;
    *head = 0;
  }
}

/* The points refinement may add with spacings (par.spacing_radii): 20 per input point
 * plus 10,000, or twice the points a size field is expected to ask for (par.size_points)
 * when that is more, at most half the budget. Reaching it ends the stage (see
 * rf_after_insert). Without the field's share a graded mesh ended its radius-edge
 * refinement a tenth of the way (elephant.off graded 0.005 to 0.03: at 65,500 of 96,000
 * points, 3,396 tets left over the ratio bound). */
static uint64_t spacing_cap(const rf_ctx *c)
{
  uint64_t cap = 20 * (uint64_t)c->plc->npoints + 10000;
  if (cap < 2 * c->par.size_points)
    cap = 2 * c->par.size_points;
  return cap < c->par.budget / 2 ? cap : c->par.budget / 2;
}

/* The points a round (rounds.c) may add: the budget's and, while the spacings or the close
 * splits are on, spacing_cap's, so that the loop switches them off at the same point
 * count as without rounds. */
static uint64_t round_room(const rf_ctx *c)
{
  uint64_t room = c->par.budget > c->st->points ? c->par.budget - c->st->points : 0;
  uint64_t cap = spacing_cap(c);
  if ((c->spacing_on || c->close_splits) && cap - c->st->points < room)
    room = cap > c->st->points ? cap - c->st->points : 0;
  return room;
}

/* Serves the queues until they are empty; the caller seeds them. */
static tr_status run(rf_ctx *c)
{
  struct tr_mesh *m = c->m;
  for (;;) {
    TR_CHECK(rf_subshape_scan(c));
    TR_CHECK(rf_sizing_scan(c));
    if (c->spacing_on && c->st->points >= spacing_cap(c)) {
      c->spacing_on = 0; /* a cascade the spacings let through: see rf_after_insert */
      c->st->spacing_stopped = 1;
      /* ratio refinement ends here; the volume bounds and the size field do not: their
       * tets go on being refined, with the insertion radii (it once stopped with half the
       * tets of a cube under -a 1e-4 over the bound) */
      if (!(c->par.max_volume > 0) && !c->par.nregion_bounds && !c->par.sizing)
        return TR_OK;
      c->volume_only = 1;
    }
    if (c->close_splits && c->st->points >= spacing_cap(c))
      c->close_splits = 0; /* refine_tet */
    if (c->st->points >= c->par.budget && (left(&c->qseg, c->hseg, 1) || left(&c->qface, c->hface, 1) ||
                                            left(&c->qtet, c->htet, 5)))
      return tr_error(TR_ERR_NOMEM,
                      "refinement stopped at its point budget of %llu points (%llu on input "
                      "edges, %llu on input faces, %llu inside) with %zu bad tets and %zu "
                      "encroached constraint pieces still queued: an input angle too small "
                      "for the bound, or a part of the domain much thinner than its faces "
                      "are wide (its faces need points about as close as it is thin)? raise "
                      "--refine-budget, relax -q/-a, or keep the surface as given "
                      "(--keep-surface: interior points only)",
                      (unsigned long long)c->par.budget, (unsigned long long)c->st->on_segments,
                      (unsigned long long)c->st->on_facets, (unsigned long long)c->st->inside,
                      left(&c->qtet, c->htet, 5),
                      left(&c->qseg, c->hseg, 1) + left(&c->qface, c->hface, 1));
    if (c->hseg < c->qseg.n) {
      uint32_t g = c->qseg.a[c->hseg++];
      compact_queue(&c->qseg, &c->hseg);
      if (!c->ssdead[g] && !c->ssnosplit[g])
        TR_CHECK(rf_split_segment(c, g));
    } else if (c->hface < c->qface.n) {
      uint32_t f = c->qface.a[c->hface++];
      compact_queue(&c->qface, &c->hface);
      if (!c->sfdead[f] && !c->sfnosplit[f])
        TR_CHECK(rf_split_facet(c, f));
    } else if (rf_round_wanted(c) && round_room(c) >= RF_ROUND_LEAST) {
      TR_CHECK(rf_round(c, round_room(c)));
      if (c->htet > 5 * 4096 && c->htet * 2 > c->qtet.n) {
        memmove(c->qtet.a, c->qtet.a + c->htet, (c->qtet.n - c->htet) * sizeof *c->qtet.a);
        c->qtet.n -= c->htet;
        c->htet = 0;
      }
    } else if (c->htet < c->qtet.n) {
      uint32_t it[5];
      memcpy(it, c->qtet.a + c->htet, sizeof it);
      c->htet += 5;
      if (c->htet > 5 * 4096 && c->htet * 2 > c->qtet.n) {
        memmove(c->qtet.a, c->qtet.a + c->htet, (c->qtet.n - c->htet) * sizeof *c->qtet.a);
        c->qtet.n -= c->htet;
        c->htet = 0;
      }
      if (it[0] < m->nt && !tr_tet_is_free(m, it[0]) &&
          !memcmp(m->tv + 4 * (size_t)it[0], it + 1, 4 * sizeof *it) && tet_bad(c, it[0]))
        TR_CHECK(refine_tet(c, it[0], 0));
    } else
      return TR_OK;
  }
}

static tr_status seed_all(rf_ctx *c)
{
  for (uint32_t t = 0; t < c->m->nt; t++)
    if (!tr_tet_is_free(c->m, t))
      TR_CHECK(push_tet(c, t));
  return TR_OK;
}

static void ctx_setup(rf_ctx *c, struct tr_mesh *m, const struct tr_plc *plc,
                      const tr_refine_params *par, tr_refine_stats *st)
{
  memset(st, 0, sizeof *st);
  memset(c, 0, sizeof *c);
  c->m = m;
  c->plc = plc;
  c->par = *par;
  c->st = st;
  c->split_seg = TR_NONE;
  if (!c->par.budget)
    c->par.budget = tr_refine_default_budget(plc->npoints, 0, 0);
}

/* Flat sub-faces (flat.c): one scan of what the loop left, then the loop again for the
 * splits it queued and the tets they make; none once the loop stopped at its point cap
 * (the loop would go on with the insertion radii, and merged_facet_notch.off's facet
 * splits then ran to the budget). */
static tr_status flat_pass(rf_ctx *c)
{
  if (c->st->spacing_stopped)
    return TR_OK;
  int pushed;
  TR_CHECK(rf_flat_scan(c, &pushed));
  return pushed ? run(c) : TR_OK;
}

/* A tet of the sliver stage's list: the pieces its own vertices encroach, else the
 * sub-faces it lies on (a flat tet on a sub-face is opened only by a point on it; the
 * split point, the sub-face's circumcentre, goes to a sub-segment it encroaches first,
 * as any facet split does). */
static tr_status open_pinned(rf_ctx *c, uint32_t t)
{
  int pushed;
  TR_CHECK(own_encroached(c, t, &pushed));
  if (pushed)
    return TR_OK;
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++) {
    uint32_t f = rf_subface_of(c, v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]);
    if (f != TR_NONE && !c->sfnosplit[f] && !rf_protected(c, 0, f, v[k]))
      TR_CHECK(tr_u32buf_push(&c->qface, f));
  }
  return TR_OK;
}

tr_status tr_refine_open_pinned(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *tets,
                                uint32_t ntets, tr_refine_stats *st)
{
  discard_outer(m); /* none after tr_refine; a mesh given directly may have them */
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  for (uint32_t i = 0; s == TR_OK && i < ntets; i++)
    if (tets[i] < m->nt && !tr_tet_is_free(m, tets[i]))
      s = open_pinned(&c, tets[i]);
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_OK && par->flat_splits)
    s = flat_pass(&c); /* most flat sub-faces come from the splits above (flat.c) */
  if (s == TR_ERR_NOMEM && st->points >= c.par.budget) {
    tr_error_clear();
    s = TR_OK; /* the budget is the sliver stage's: what was split stays */
  }
  if (s == TR_OK)
    s = rf_subs_export(&c, sub);
  ctx_free(&c);
  return s;
}

/* The sliver polish's hook (sliver/caps.c): one named piece is split, a sub-segment
 * (nv = 2) or a sub-face (nv = 3), as an encroached one would be, and the cascade it
 * starts runs within par->budget (reaching it is no error). Nothing when the piece is
 * no constraint or may not be split. */
tr_status tr_refine_split_piece(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *v, int nv,
                                tr_refine_stats *st)
{
  discard_outer(m);
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  if (s == TR_OK && nv == 2) {
    uint32_t g = rf_subseg_of(&c, v[0], v[1]);
    if (g != TR_NONE && !c.ssnosplit[g])
      s = tr_u32buf_push(&c.qseg, g);
  } else if (s == TR_OK && nv == 3) {
    uint32_t f = rf_subface_of(&c, v[0], v[1], v[2]);
    if (f != TR_NONE && !c.sfnosplit[f])
      s = tr_u32buf_push(&c.qface, f);
  }
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_ERR_NOMEM && st->points >= c.par.budget) {
    tr_error_clear();
    s = TR_OK;
  }
  if (s == TR_OK && st->points)
    s = rf_subs_export(&c, sub);
  ctx_free(&c);
  return s;
}

tr_status tr_refine(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                    const tr_refine_params *par, tr_refine_stats *st)
{
  tr_refine_stats local;
  if (!st)
    st = &local;
  memset(st, 0, sizeof *st);
  if (plc->nsegs)
    return tr_error(TR_ERR_UNSUPPORTED, "quality refinement of inputs with free segments is "
                    "not supported yet (%u segments)", plc->nsegs);
  struct timespec t0;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
  discard_outer(m);
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  /* off by default: on CGAL's models it costs more CPU and tets than it gains
   * (subshape.c) */
  c.shape_on = par->subface_ratio > 0;
  c.spacing_on = par->spacing_radii;
  c.close_splits = 1;
  c.rounds_on = 1; /* rounds.c: not in the sliver stage's hooks */
  c.shape_bound = par->subface_ratio;
  if (s == TR_OK)
    s = rf_sizing_init(&c);
  if (s == TR_OK && par->keep_surface) { /* the input triangles stay the boundary faces */
    memset(c.ssnosplit, 1, c.nss);
    memset(c.sfnosplit, 1, c.nsf);
  }
  if (s == TR_OK)
    s = seed_all(&c);
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_OK && par->flat_splits)
    s = flat_pass(&c);
  if (s == TR_ERR_NOMEM && par->partial && st->points >= c.par.budget) {
    /* the loop stops between insertions, so the mesh holds every constraint: an
     * encroached piece left unsplit is still a chain of mesh edges or faces */
    if (par->verbose >= 1)
      fprintf(stderr, "tetrec: warning: %s; the mesh made so far is kept (sliver removal "
              "adds no point to it)\n", tr_last_error());
    tr_error_clear();
    st->budget_reached = 1;
    s = TR_OK;
  }
  if (s == TR_OK)
    s = rf_subs_export(&c, sub);
  if (par->verbose >= 2) {
    struct timespec t1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    fprintf(stderr, "tetrec: refinement CPU (every thread): %.3f s\n",
            (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
  }
  if (par->verbose >= 1 && st->rounds)
    fprintf(stderr, "tetrec: refinement rounds: %llu, %llu points inserted in them on %d "
            "threads, %llu of their tets left to the serial loop\n",
            (unsigned long long)st->rounds, (unsigned long long)st->round_points,
            par->threads > 1 ? par->threads : 1, (unsigned long long)st->round_serial);
  if (par->verbose >= 1 && (s == TR_OK || s == TR_ERR_NOMEM))
    fprintf(stderr,
            "tetrec: refinement added %llu points (%llu on edges, %llu on facets, %llu "
            "inside; %llu times pieces queued to grade a small-angle wedge); bad tets left: %llu "
            "for small input angles, %llu whose circumcentre lies too close to a new vertex, "
            "%llu otherwise; %u input edges inside exactly "
            "planar facets merged away (--keep-edges keeps them)%s%s\n",
            (unsigned long long)st->points, (unsigned long long)st->on_segments,
            (unsigned long long)st->on_facets, (unsigned long long)st->inside,
            (unsigned long long)st->wedge_splits, (unsigned long long)st->skipped_small_angle,
            (unsigned long long)st->skipped_close,
            (unsigned long long)st->skipped_other, st->merged_edges,
            st->spacing_stopped ? "; the radius-edge refinement stopped at the point cap of "
                                  "--spacing-radii (volume bounds still met)" : "",
            par->keep_surface ? "; --keep-surface: no point on the surface, so a bad tet whose "
                                "circumcentre encroaches it is left" : "");
  ctx_free(&c);
  return s;
}
