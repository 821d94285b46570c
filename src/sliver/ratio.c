/* The ratio pass, last of the sliver stage (sliver.h): moves of interior vertices that
 * take the tets of their star back under the radius-edge bound.
 *
 * Why: the rounds may leave a new tet over the ratio bound when it has no angle under the
 * stage's bound (tr_sliver_keeps_bounds), and on smooth models that is where nearly all
 * the tets over the bound come from (refinement alone leaves none on sphere.off; the
 * stage left 4.7% of its tets over 1.414). Holding the rounds themselves to the ratio
 * costs them their angles (docs/sliver.md); a move afterwards costs little.
 *
 * A movable vertex of a tet over the bound goes to the trial position whose star has the
 * smallest largest ratio, when that is under the star's largest ratio as it is, every tet
 * of the star is exactly positive with the new point and within its volume bound (so the
 * point stays strictly inside its link and reaches no constraint), and no tet of the star
 * gets an angle under min(q0, F), q0 the star's smallest angle as it is: F is the stage's
 * bound when the move takes the whole star under the ratio bound, else the larger of that
 * bound and the mesh's smallest angle. So no star's largest ratio rises, the mesh's
 * smallest angle drops only where it is over the stage's bound (and not under it), and
 * only for a star the move brings within the ratio bound. The trials: the centroid of the
 * link, the volume-weighted mean of the star's circumcentres (the optimal Delaunay
 * position, which rounds the star towards Delaunay tets of small ratio), and half-way to
 * each. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/quality.h"
#include "sliver/sliver.h"

#define SL_RATIO_PASSES 2 /* vertex order, twice: a move can open its neighbours' moves */
#define SL_RATIO_TRIALS 4

/* The star's largest ratio and smallest angle with v at x (NULL: as it is); 0 when a tet
 * is flat, its angle is under `floor` or its ratio at least `cap` (the trial is of no use
 * then: it cannot beat the best so far). */
static int star_at(const tr_sliver_ctx *c, const tr_u32buf *ball, uint32_t v, const double *x,
                   double floor, double cap, double *top, double *low)
{
  *top = 0;
  *low = INFINITY;
  for (size_t i = 0; i < ball->n; i++) {
    double r, q;
    if (x)
      q = tr_sliver_min_dihedral_at(c->m, c->m->tv + 4 * (size_t)ball->a[i], v, x, &r);
    else
      q = tr_sliver_tet_min(c, ball->a[i], &r);
    if (!(q > 0) || !(q >= floor) || !(r < cap))
      return 0;
    *top = fmax(*top, r);
    *low = fmin(*low, q);
  }
  return 1;
}

/* The trial positions of v; returns how many. */
static int trials(const struct tr_mesh *m, const tr_u32buf *ball, uint32_t v,
                  double out[SL_RATIO_TRIALS][3])
{
  const double *x0 = m->xyz + 3 * (size_t)v;
  double cen[3] = {0, 0, 0}, odt[3] = {0, 0, 0}, wsum = 0;
  size_t nl = 0;
  for (size_t i = 0; i < ball->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    const double *p[4];
    for (int k = 0; k < 4; k++) {
      p[k] = m->xyz + 3 * (size_t)tv[k];
      if (tv[k] != v) {
        for (int j = 0; j < 3; j++)
          cen[j] += p[k][j];
        nl++;
      }
    }
    double r, vol, cc[3];
    if (tr_tet_shape(p[0], p[1], p[2], p[3], &r, &vol, NULL, cc) && vol > 0) {
      for (int j = 0; j < 3; j++)
        odt[j] += vol * cc[j];
      wsum += vol;
    }
  }
  int n = 0;
  if (nl) {
    for (int j = 0; j < 3; j++) {
      out[n][j] = cen[j] / (double)nl;
      out[n + 1][j] = 0.5 * (x0[j] + out[n][j]);
    }
    n += 2;
  }
  if (wsum > 0 && isfinite(wsum)) {
    for (int j = 0; j < 3; j++) {
      out[n][j] = odt[j] / wsum;
      out[n + 1][j] = 0.5 * (x0[j] + out[n][j]);
    }
    if (isfinite(out[n][0]) && isfinite(out[n][1]) && isfinite(out[n][2]))
      n += 2;
  }
  return n;
}

static tr_status ratio_vertex(tr_sliver_ctx *c, uint32_t v, double keep, tr_u32buf *ball,
                             int *moved)
{
  struct tr_mesh *m = c->m;
  *moved = 0;
  TR_CHECK(tr_ball(m, v, 0, ball));
  if (!ball->n || !tr_sliver_star_closed(m, ball, v))
    return TR_OK; /* v on the mesh's boundary: no move */
  double was, q0;
  if (!star_at(c, ball, v, NULL, 0, INFINITY, &was, &q0) || !(was > c->keep.ratio))
    return TR_OK;
  /* F of the header: a trial that takes the whole star under the ratio bound may go
   * down to the stage's bound, one that only lowers its largest ratio only to `keep` */
  double lo = fmin(q0, c->bound), hi = fmin(q0, keep);
  double trial[SL_RATIO_TRIALS][3], top[SL_RATIO_TRIALS];
  int nt = trials(m, ball, v, trial);
  double best = was; /* a trial is measured only while it can beat the best so far */
  for (int i = 0; i < nt; i++) {
    double low;
    if (!star_at(c, ball, v, trial[i], lo, best, &top[i], &low) ||
        (top[i] > c->keep.ratio && !(low >= hi)))
      top[i] = INFINITY;
    else
      best = top[i];
  }
  /* the best trial that is exactly valid, ties to the earlier one (one cut by a better
   * trial is not tried when that one fails the exact test: a double measure and an exact
   * sign disagree only on nearly flat tets, which no trial kept here has) */
  for (;;) {
    int b = -1;
    for (int i = 0; i < nt; i++)
      if (top[i] < was && (b < 0 || top[i] < top[b]))
        b = i;
    if (b < 0)
      return TR_OK;
    if (tr_sliver_star_valid(c, ball, v, trial[b], was, NULL)) {
      memcpy(m->xyz + 3 * (size_t)v, trial[b], sizeof trial[b]);
      for (size_t i = 0; i < ball->n; i++)
        tr_sliver_forget(c, ball->a[i]);
      TR_CHECK(tr_sliver_touch_tets(c, ball->a, ball->n));
      if (m->vq && m->vq[v]) /* the exact point is the double from now on */
        tr_qpoint_set_d(m->vq[v], trial[b]);
      *moved = 1;
      return TR_OK;
    }
    top[b] = INFINITY;
  }
}

tr_status tr_sliver_ratio_pass(tr_sliver_ctx *c, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  if (!(c->keep.ratio > 0) || !m->nv)
    return TR_OK;
  /* the vertices to try, marked from the tets over the bound each pass: a ball per
   * movable vertex of the mesh cost 8% of the whole run on bunny00.off */
  uint8_t *mark = malloc(m->nv);
  if (!mark)
    return tr_error(TR_ERR_NOMEM, "out of memory for the ratio pass of %u vertices", m->nv);
  /* `keep`: the angle under which a move that leaves its star over the bound takes no
   * tet, the mesh's smallest angle when that is above the stage's bound (torus_quad.off:
   * such moves took its 27.1 degrees to 20.3, under TetGen's 21.3) */
  double keep = INFINITY;
  tr_u32buf ball = {0};
  tr_status s = TR_OK;
  for (int pass = 0; pass < SL_RATIO_PASSES && s == TR_OK; pass++) {
    memset(mark, 0, m->nv);
    int any = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
      if (!tr_tet_is_real(m, t))
        continue;
      double r, q = tr_sliver_tet_min(c, t, &r);
      if (!pass)
        keep = fmin(keep, q);
      if (r > c->keep.ratio)
        for (int k = 0; k < 4; k++) {
          uint32_t v = m->tv[4 * (size_t)t + (size_t)k];
          mark[v] = c->movable[v];
          any |= mark[v];
        }
    }
    if (!pass)
      keep = fmax(keep, c->bound);
    if (!any)
      break;
    uint64_t before = st->smoothed;
    for (uint32_t v = 0; v < m->nv && s == TR_OK; v++) {
      if (!mark[v])
        continue;
      int moved;
      s = ratio_vertex(c, v, keep, &ball, &moved);
      st->smoothed += (uint64_t)moved;
    }
    if (st->smoothed == before)
      break;
  }
  tr_u32buf_free(&ball);
  free(mark);
  return s;
}
