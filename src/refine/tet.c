/* What the refinement loop (refine.c) does with one bad tet: its circumcentre, unless
 * that lies too close to a vertex, a small input angle forbids it, or it encroaches a
 * sub-segment or sub-face, which is queued for splitting instead; and the tests the
 * loop and rounds.c share (bad, over its volume bound, queued).
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

#include "refine/quality.h"
#include "refine/refine_impl.h"

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
tr_status rf_own_encroached(rf_ctx *c, uint32_t t, int *pushed)
{
  return own_encroached(c, t, pushed);
}

