/* Smoothing of interior vertices (sliver.h): a vertex whose star holds a tet with a
 * dihedral angle under the bound moves, in doubles, along the direction that opens the
 * worst angle of its star, or towards the centroid of its link, to the trial position that
 * gives the star the largest smallest angle; the move is kept only when that beats the
 * star as it is and every tet of the star is exactly positive with the new point, which
 * keeps the point strictly inside its link polyhedron, so it reaches no constraint. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/quality.h"
#include "sliver/sliver.h"

#define SL_STEPS 6 /* trial steps: h/2, h/4, ..., h the shortest edge at the vertex */
#define SL_MOVES 4 /* moves per vertex and pass */
#define SL_STAR_COS 256 /* the largest star whose trial cosines are kept (move) */

/* The smallest dihedral angle of the star as it is; *worst = its tet (ball index). */
static double star_min(const tr_sliver_ctx *c, const tr_u32buf *ball, size_t *worst)
{
  double lo = INFINITY;
  for (size_t i = 0; i < ball->n; i++) {
    double q = tr_sliver_tet_min(c, ball->a[i], NULL);
    if (q < lo) {
      lo = q;
      *worst = i;
    }
  }
  return lo;
}

/* The smallest dihedral angle of the star with v at x (tr_sliver_min_dihedral_at's value),
 * or some angle at most `floor` once a tet is that bad: the caller only looks at values
 * above floor. Ranked by cosine, with one arccosine at the end: the angle is a
 * non-decreasing function of the cosine, so every tet with a cosine at most cf has an
 * angle at most floor. The tets `first` and `second` (ball indices) go first: the worst
 * tet as it is, and the worst of the best trial so far, the likeliest to stop a trial
 * early. *arg = the ball index of the tet that gave the value; cs (may be NULL): the
 * smallest cosine of each tet measured, by ball index (all of them unless it stopped
 * early). */
static double star_min_at(const struct tr_mesh *m, const tr_u32buf *ball, uint32_t v,
                          const double x[3], double floor, double cf, size_t first,
                          size_t second, size_t *arg, double *cs)
{
  double lo = 2;
  int flat = 0;
  size_t head[2] = {first, second}, nh = second == first ? 1 : 2;
  for (size_t j = 0; j < nh + ball->n; j++) {
    size_t i = j < nh ? head[j] : j - nh; /* first, second, then the rest in ball order */
    if (j >= nh && (i == first || i == second))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    const double *p[4];
    for (int k = 0; k < 4; k++)
      p[k] = tv[k] == v ? x : m->xyz + 3 * (size_t)tv[k];
    double w, q = tr_tet_min_cos(p[0], p[1], p[2], p[3], &w);
    if (cs)
      cs[i] = q;
    if (!(w != 0)) {
      if (!flat)
        *arg = i;
      flat = 1; /* angle 0 (tr_sliver_min_dihedral_at) */
    } else if (q < lo) {
      lo = q;
      if (!flat)
        *arg = i;
    }
    if ((flat && 0 <= floor) || lo <= cf)
      break;
  }
  double a = lo <= 1 ? tr_dihedral_of_cos(lo) : INFINITY;
  if (!isfinite(a) && lo <= 1)
    a = 0;
  return flat && !(a < 0) ? 0 : a;
}

/* A cosine cf with tr_dihedral_of_cos(c) <= floor for every c <= cf (-2: none found). */
static double cos_floor(double floor)
{
  double cf = cos(3.14159265358979323846 - floor * (3.14159265358979323846 / 180.0));
  for (int i = 0; i < 64 && cf >= -1; i++) {
    if (!(cf <= 1))
      cf = 1;
    if (tr_dihedral_of_cos(cf) <= floor)
      return cf;
    cf = nextafter(cf, -2.0);
  }
  return -2;
}

/* sliver.h; cs, when given, holds star_min_at's cosines of the trial. */
int tr_sliver_star_valid(const tr_sliver_ctx *c, const tr_u32buf *ball, uint32_t v,
                         const double x[3], double was, const double *cs)
{
  const struct tr_mesh *m = c->m;
  for (size_t i = 0; i < ball->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    tr_point p[4];
    for (int k = 0; k < 4; k++)
      p[k] = tv[k] == v ? tr_pt_d(x) : tr_mesh_point(m, tv[k]);
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) <= 0)
      return 0;
  }
  for (size_t i = 0; i < ball->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    /* the angle as tr_sliver_min_dihedral_at gives it, from the cosine when known; the
     * ratio only where the bound looks at it (the circumsphere costs) */
    double r = 0, q;
    if (cs) {
      q = tr_dihedral_of_cos(cs[i]);
      q = isfinite(q) ? q : 0;
    } else
      q = tr_sliver_min_dihedral_at(m, tv, v, x, NULL);
    if (c->keep.ratio > 0 && !(q >= c->bound))
      r = tr_sliver_ratio_at(m, tv, v, x);
    if (!tr_sliver_keeps_bounds(c, tv, v, x, m->region ? m->region[ball->a[i]] : 0, r, q, was))
      return 0;
  }
  return 1;
}

/* The largest radius-edge ratio of the star as it is. */
static double star_ratio(const tr_sliver_ctx *c, const tr_u32buf *ball)
{
  double was = 0, r;
  for (size_t i = 0; i < ball->n; i++) {
    tr_sliver_tet_min(c, ball->a[i], &r);
    was = fmax(was, r);
  }
  return was;
}

int tr_sliver_star_closed(const struct tr_mesh *m, const tr_u32buf *ball, uint32_t v)
{
  for (size_t i = 0; i < ball->n; i++)
    for (int k = 0; k < 4; k++) {
      uint32_t nb = m->tn[4 * (size_t)ball->a[i] + (size_t)k];
      if (m->tv[4 * (size_t)ball->a[i] + (size_t)k] != v &&
          (nb == TR_NONE || tr_tet_is_ghost(m, nb >> 2)))
        return 0;
    }
  return 1;
}

/* The trial with the largest value over q0, the earlier one on ties; -1 if none. */
static int best_trial(const double *val, int nt, double q0)
{
  int b = -1;
  for (int i = 0; i < nt; i++)
    if (val[i] > q0 && (b < 0 || val[i] > val[b]))
      b = i;
  return b;
}

/* One improving move of v, if there is one (*moved = 1). */
static void move(const tr_sliver_ctx *c, const tr_u32buf *ball, uint32_t v, double q0,
                 size_t worst, double to[3], int *moved)
{
  const struct tr_mesh *m = c->m;
  const double *x0 = m->xyz + 3 * (size_t)v;
  /* the shortest edge at v and the centroid of the link */
  double h = INFINITY, cen[3] = {0, 0, 0};
  size_t nl = 0;
  for (size_t i = 0; i < ball->n; i++)
    for (int k = 0; k < 4; k++) {
      uint32_t w = m->tv[4 * (size_t)ball->a[i] + (size_t)k];
      if (w == v)
        continue;
      const double *y = m->xyz + 3 * (size_t)w;
      double d2 = 0;
      for (int j = 0; j < 3; j++) {
        d2 += (y[j] - x0[j]) * (y[j] - x0[j]);
        cen[j] += y[j];
      }
      h = fmin(h, sqrt(d2));
      nl++;
    }
  *moved = 0;
  if (!(h > 0) || !isfinite(h) || !nl)
    return;
  for (int j = 0; j < 3; j++)
    cen[j] /= (double)nl; /* every link vertex counted once per tet: a weighted centroid */
  /* the gradient of the worst tet's worst angle, by central differences */
  const uint32_t *wt = m->tv + 4 * (size_t)ball->a[worst];
  double g[3], eps = h * 1e-6, gn = 0;
  for (int j = 0; j < 3; j++) {
    double xp[3] = {x0[0], x0[1], x0[2]}, xm[3] = {x0[0], x0[1], x0[2]};
    xp[j] += eps;
    xm[j] -= eps;
    g[j] = tr_sliver_min_dihedral_at(m, wt, v, xp, NULL) -
           tr_sliver_min_dihedral_at(m, wt, v, xm, NULL);
    gn += g[j] * g[j];
  }
  gn = sqrt(gn);
  /* trial positions: SL_STEPS along the gradient, the centroid and half-way to it */
  double trial[SL_STEPS + 2][3], val[SL_STEPS + 2];
  int nt = 0;
  for (int s = 0; s < SL_STEPS && gn > 0 && isfinite(gn); s++, nt++) {
    double step = h / (double)(2 << s);
    for (int j = 0; j < 3; j++)
      trial[nt][j] = x0[j] + step * g[j] / gn;
  }
  for (int j = 0; j < 3; j++) {
    trial[nt][j] = cen[j];
    trial[nt + 1][j] = 0.5 * (x0[j] + cen[j]);
  }
  nt += 2;
  /* Each trial is measured above the best so far (`best`): one that cannot beat it stops
   * at its first tet that bad (its value is then only a bound, `cut`). The best trial is
   * exact, and is the one measuring every trial above q0 would pick, ties to the earlier:
   * a later trial with a larger value never gets that low. */
  double cf = cos_floor(q0), best = q0, cfb = cf;
  size_t second = worst, arg = worst;
  int cut[SL_STEPS + 2], top = -1;
  /* the cosines of the trial being measured and of the best one: its validity check
   * needs its angles again (a star of more than SL_STAR_COS tets measures them anew) */
  double cs[2][SL_STAR_COS], *cur = ball->n <= SL_STAR_COS ? cs[0] : NULL, *kept = cs[1];
  for (int i = 0; i < nt; i++) {
    val[i] = star_min_at(m, ball, v, trial[i], best, cfb, worst, second, &arg, cur);
    cut[i] = best > q0;
    if (val[i] > best) { /* measured whole, every tet not flat */
      best = val[i];
      cfb = cos_floor(best);
      second = arg;
      top = i;
      if (cur) {
        double *sw = kept;
        kept = cur;
        cur = sw;
      }
    }
  }
  double was = star_ratio(c, ball);
  /* the best trial that is exactly valid; ties to the earlier one */
  int pick = -1;
  for (int exact = 0;;) {
    int b = best_trial(val, nt, q0);
    if (b < 0)
      break;
    if (tr_sliver_star_valid(c, ball, v, trial[b], was, b == top && cur ? kept : NULL)) {
      pick = b;
      break;
    }
    val[b] = -1;
    /* the runner-up may be among the cut ones: they are measured above q0 alone now */
    for (int i = 0; i < nt && !exact; i++)
      if (cut[i] && val[i] >= 0)
        val[i] = star_min_at(m, ball, v, trial[i], q0, cf, worst, worst, &arg, NULL);
    exact = 1;
  }
#ifndef NDEBUG
  /* the pick of every trial measured whole above q0, each checked without the kept
   * cosines: the same trial */
  int ref = -1;
  for (int i = 0; i < nt; i++)
    val[i] = star_min_at(m, ball, v, trial[i], q0, cf, worst, worst, &arg, NULL);
  for (;;) {
    int b = best_trial(val, nt, q0);
    if (b < 0 || tr_sliver_star_valid(c, ball, v, trial[b], was, NULL)) {
      ref = b;
      break;
    }
    val[b] = -1;
  }
  assert(ref == pick);
#endif
  if (pick >= 0) {
    memcpy(to, trial[pick], sizeof trial[pick]);
    *moved = 1;
  }
}

tr_status tr_sliver_smooth_vertex(tr_sliver_ctx *c, uint32_t v, double bound, tr_u32buf *ball,
                                  tr_sliver_stats *st, int *moved)
{
  struct tr_mesh *m = c->m;
  *moved = 0;
  if (!c->movable[v])
    return TR_OK;
  TR_CHECK(tr_ball(m, v, 0, ball));
  if (!ball->n || !tr_sliver_star_closed(m, ball, v))
    return TR_OK;
  for (int it = 0; it < SL_MOVES; it++) {
    size_t worst = 0;
    double q0 = star_min(c, ball, &worst);
    if (!(q0 < bound))
      break;
    double to[3];
    int ok;
    move(c, ball, v, q0, worst, to, &ok);
    if (!ok)
      break;
    memcpy(m->xyz + 3 * (size_t)v, to, sizeof to);
    for (size_t i = 0; i < ball->n; i++)
      tr_sliver_forget(c, ball->a[i]);
    TR_CHECK(tr_sliver_touch_tets(c, ball->a, ball->n));
    if (m->vq && m->vq[v]) /* the exact point is the double from now on */
      tr_qpoint_set_d(m->vq[v], to);
    *moved = 1;
  }
  st->smoothed += (uint64_t)*moved;
  return TR_OK;
}

/* Marks in near[] the vertices of the real tets of `tets` (all slots when NULL, else the n
 * listed) whose smallest angle is under the bound. */
static void mark_near(const tr_sliver_ctx *c, const uint32_t *tets, size_t n, uint8_t *near)
{
  const struct tr_mesh *m = c->m;
  for (size_t i = 0; i < n; i++) {
    uint32_t t = tets ? tets[i] : (uint32_t)i;
    if (!tr_tet_is_real(m, t) || !(tr_sliver_tet_min(c, t, NULL) < c->bound))
      continue;
    for (int k = 0; k < 4; k++)
      near[m->tv[4 * (size_t)t + (size_t)k]] = 1;
  }
}

/* A vertex whose star holds no tet under the bound does not move
 * (tr_sliver_smooth_vertex stops at its first q0), and most movable vertices are such
 * (cheese.off: 3 in 4 of the stars walked): only the vertices of a tet under the bound
 * get their star walked, found by one scan of the tets' cached measures. Moves only
 * change the mover's star, whose tets' vertices are marked again after it: the same
 * moves as walking every star. */
tr_status tr_sliver_smooth_pass(tr_sliver_ctx *c, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  tr_u32buf ball = {0};
  tr_status s = TR_OK;
  uint8_t *near = calloc(m->nv ? m->nv : 1, 1);
  if (!near)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex flags", m->nv);
  mark_near(c, NULL, m->nt, near);
  for (uint32_t v = 0; v < m->nv && s == TR_OK; v++) {
    if (!near[v])
      continue;
    int moved;
    s = tr_sliver_smooth_vertex(c, v, c->bound, &ball, st, &moved);
    if (s == TR_OK && moved) /* ball: v's star, the tets whose angles changed */
      mark_near(c, ball.a, ball.n, near);
  }
  free(near);
  tr_u32buf_free(&ball);
  return s;
}
