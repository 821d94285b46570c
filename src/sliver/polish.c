/* The final polish of the sliver stage (sliver.h): the rounds work on the tets under the
 * bound (20 degrees), so on a small mesh whose worst tet is above it nothing runs, and the
 * smallest angle stays where refinement left it (icosahedron.off: 20.9 degrees, a cube
 * corner: 35.3, while a point at the icosahedron's centre gives 69). Here the globally
 * worst tets, whatever their angle, get the same steps: the best flip of the tet, moves of
 * its movable vertices, a new interior point. Each step is kept only when it strictly
 * raises the smallest angle of the tets it touches and keeps the refinement's bounds, as in
 * the rounds, so the mesh's smallest angle never drops; the worst tet goes first, since
 * a step there is what raises the mesh's minimum. The work is bounded: SL_POLISH_ROUNDS
 * rounds over the SL_POLISH_TETS(nt) worst tets, at most that many points a round. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sliver/sliver.h"

#define SL_POLISH_ROUNDS 8
#define SL_POLISH_TETS(nt) (32u + (nt) / 1024u)
/* constraint pieces tried in all: each trial copies the tet slots and sets refinement up,
 * linear in the mesh, so a large mesh gets fewer (the whole bench: 16 everywhere cost 12%
 * more CPU, over TetGen's) */
#define SL_POLISH_CAP_TRIALS(nt) ((nt) < 16384u ? 16u : 8u)
/* and wide trials (the pieces around the worst tet's vertices on constraints), on small
 * meshes only: on cheese and rotor_small 8 of them cost 2.1 and 0.45 s and opened
 * nothing */
#define SL_POLISH_WIDE_TRIALS(nt) ((nt) < 16384u ? 16u : 0u)

typedef struct worst {
  double q;
  uint32_t t, v[4];
} worst;

/* a before b: the smaller angle, ties to the smaller slot (deterministic) */
static int before(const worst *a, const worst *b)
{
  return a->q < b->q || (a->q == b->q && a->t < b->t);
}

static void sift_down(worst *h, uint32_t n, uint32_t i)
{
  for (;;) { /* a max-heap in `before` order: h[0] the last of the kept ones */
    uint32_t l = 2 * i + 1, r = l + 1, top = i;
    if (l < n && before(&h[top], &h[l]))
      top = l;
    if (r < n && before(&h[top], &h[r]))
      top = r;
    if (top == i)
      return;
    worst x = h[i];
    h[i] = h[top];
    h[top] = x;
    i = top;
  }
}

static void sift_up(worst *h, uint32_t i)
{
  while (i > 0 && before(&h[(i - 1) / 2], &h[i])) {
    worst x = h[i];
    h[i] = h[(i - 1) / 2];
    h[(i - 1) / 2] = x;
    i = (i - 1) / 2;
  }
}

static int cmp_worst(const void *a, const void *b)
{
  return before(a, b) ? -1 : before(b, a) ? 1 : 0;
}

/* The k worst real tets of the mesh, worst first; *n = how many (fewer on a small mesh). */
static void worst_tets(const tr_sliver_ctx *c, worst *h, uint32_t k, uint32_t *n)
{
  const struct tr_mesh *m = c->m;
  uint32_t cnt = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    worst w;
    w.q = tr_sliver_tet_min(c, t, NULL);
    w.t = t;
    memcpy(w.v, m->tv + 4 * (size_t)t, sizeof w.v);
    if (cnt < k) {
      h[cnt] = w;
      sift_up(h, cnt++);
    } else if (before(&w, &h[0])) {
      h[0] = w;
      sift_down(h, cnt, 0);
    }
  }
  qsort(h, cnt, sizeof *h, cmp_worst);
  *n = cnt;
}

tr_status tr_sliver_polish(tr_sliver_ctx *c, tr_subfaces *sub, int level, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  uint32_t k = SL_POLISH_TETS(m->nt);
  worst *h = malloc(sizeof *h * (size_t)k);
  void *scratch = level >= TR_SLIVER_INSERT ? tr_sliver_insert_scratch() : NULL;
  if (!h || (level >= TR_SLIVER_INSERT && !scratch)) {
    free(h);
    free(scratch);
    return tr_error(TR_ERR_NOMEM, "out of memory for the sliver polish");
  }
  tr_u32buf sh = {0}, ball = {0};
  tr_vtmap capped = {0}; /* tets whose constraint pieces opened nothing */
  /* pieces refinement refused to split: each costs a trial's set-up for nothing, and
   * the worst tets share them (part.off: 11 of 17 trials at one small input angle) */
  tr_vtmap refused = {0};
  tr_vtmap fanned = {0}; /* worst tets whose wide trial opened nothing */
  uint32_t trials = 0, max_trials = SL_POLISH_CAP_TRIALS(m->nt);
  uint32_t wide_trials = 0, max_wide = SL_POLISH_WIDE_TRIALS(m->nt);
  tr_status s = TR_OK;
  for (int r = 0; r < SL_POLISH_ROUNDS && s == TR_OK; r++) {
    uint32_t n, changed = 0, points = 0;
    worst_tets(c, h, k, &n);
    for (uint32_t i = 0; i < n && s == TR_OK; i++) {
      uint32_t t = h[i].t;
      /* a step for an earlier tet may have replaced this one */
      if (!tr_tet_is_real(m, t) || memcmp(m->tv + 4 * (size_t)t, h[i].v, sizeof h[i].v))
        continue;
      int done = 0;
      s = tr_sliver_flip_tet(c, t, &sh, st, &done);
      /* moves while the star is no better than the tet was: the star's worst may be
       * another tet, and any move that raises it is kept */
      for (int j = 0; j < 4 && s == TR_OK && !done && level >= TR_SLIVER_SMOOTH; j++)
        s = tr_sliver_smooth_vertex(c, h[i].v[j], INFINITY, &ball, st, &done);
      if (s == TR_OK && !done && scratch && points < k) {
        s = tr_sliver_insert_tet(c, t, scratch, &done);
        points += (uint32_t)done;
        st->points += (uint64_t)done;
      }
      /* pinned between constraints: only a point on one of them opens it; for the
       * round's worst tet, when its own pieces fail, also the pieces around its
       * vertices on constraints (part.off: the worst tet, at an input corner, rises
       * only with a split of another input edge at that corner). Not in the first
       * round: there a wide trial takes a smaller step that the narrow trials of the
       * tets after it would have beaten (corner_with_sharp_edge 35.3 -> 29.8 degrees,
       * pipe 5.99 -> 5.19) */
      uint32_t key[4];
      tr_sliver_tet_key(h[i].v, key);
      for (int wide = 0; wide < 2 && s == TR_OK && !done && scratch && sub && c->keep.plc &&
                         !c->keep.keep_surface;
           wide++) {
        tr_vtmap *memo = wide ? &fanned : &capped;
        if (!(wide ? i == 0 && r > 0 && wide_trials < max_wide : trials < max_trials) ||
            tr_vtmap_get(memo, 4, key) != TR_VTMAP_NONE)
          continue;
        int tried;
        s = tr_sliver_cap_tet(c, sub, t, wide, scratch, &refused, st, &done, &tried);
        *(wide ? &wide_trials : &trials) += (uint32_t)tried;
        if (s == TR_OK && !done)
          s = tr_vtmap_set(memo, 4, key, 0);
      }
      /* last: a pinned tet whose constraint pieces opened nothing either (in the insertion
       * passes this came before the pinned tets' refinement, and took the tets it would
       * have opened better: oblong 19 -> 52 tets under 10 degrees) */
      if (s == TR_OK && !done && scratch && points < k) {
        uint32_t gone = 0;
        s = tr_sliver_insert_last(c, t, scratch, &done, &gone);
        points += (uint32_t)done;
        st->points += (uint64_t)done;
        st->swallowed += gone;
      }
      changed += (uint32_t)done;
    }
    if (!changed)
      break;
  }
  tr_u32buf_free(&sh);
  tr_u32buf_free(&ball);
  tr_vtmap_free(&capped);
  tr_vtmap_free(&refused);
  tr_vtmap_free(&fanned);
  free(scratch);
  free(h);
  return s;
}
