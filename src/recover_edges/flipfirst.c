/* Recovery of one missing sub-segment ab by flips that remove its crossings one at a time
 * from an end (TetGen's recoveredgebyflips, Si 2015), before the pipel-count search of
 * flipseg.c.
 *
 * The simplex ab crosses nearest to a (the far face or edge of the pipel at a) is
 * removed: a crossed face by Swap23, or else by removing one of its edges; a crossed edge
 * by edge removal with the bounded recursion of flip.h. When nothing at a's end can be
 * removed, the crossing nearest to b is tried, and the next rounds start at b's end
 * until it is stuck in turn. Every flip, including those inside the
 * recursion, is admitted only if ab crosses none of the faces and edges it creates
 * (TetGen's flip eligibility): crossed simplices then only disappear, so each removal
 * lowers their number, the loop ends, and a removal is kept even when ab does not appear
 * at the end. That is the difference from flipseg.c, which undoes an attempt unless the
 * pipel count drops: a crossed face turned into a crossed edge keeps the count (the edge's
 * tets all count), and the edge's removal that would follow is never reached. On the
 * CAD surfaces of STLCutters.jl most feature edges that flipseg.c left to Steiner points
 * are recovered this way.
 */
#include <string.h>

#include "classify.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/flip.h"
#include "recover_edges/pipe.h"

static int cons_guard(void *ud, const uint32_t *v, int nv)
{
  return nv == 2 && tr_edgeset_get(ud, v[0], v[1]) != TR_EDGESET_NONE;
}

static int has2(const uint32_t *t, uint32_t x, uint32_t y)
{
  int n = 0;
  for (int i = 0; i < 4; i++)
    n += t[i] == x || t[i] == y;
  return n == 2;
}

static int has3(const uint32_t *t, const uint32_t f[3])
{
  int n = 0;
  for (int i = 0; i < 4; i++)
    n += t[i] == f[0] || t[i] == f[1] || t[i] == f[2];
  return n == 3;
}

/* The admission rule (flip.h's tr_flip_accept): refuse a flip when ab meets the interior
 * of a face shared by two new tets, or the interior of an edge no old tet had. Those are
 * the simplices a flip creates; its region's boundary is the old one. */
static int eligible(void *ud, const struct tr_mesh *m, const tr_flip_rec *r)
{
  tr_segmemo *g = ud;
  for (uint32_t i = 0; i < r->nnew; i++) {
    const uint32_t *v = r->newv + 4 * (size_t)i;
    if (v[3] == TR_GHOST)
      continue;
    tr_isect x = tr_segmemo_classify(g, m, v);
    for (int e = 0; e < x.n; e++) {
      if (x.end[e].type == TR_FAC) {
        uint32_t f[3];
        for (int q = 0; q < 3; q++)
          f[q] = v[tr_face_vtx[x.end[e].code][q]];
        for (uint32_t k = 0; k < r->nnew; k++)
          if (k != i && has3(r->newv + 4 * (size_t)k, f))
            return 0;
      } else if (x.end[e].type == TR_EDG) {
        uint32_t p = v[tr_ecode_start(x.end[e].code)], q = v[tr_ecode_end(x.end[e].code)];
        int old = 0;
        for (uint32_t k = 0; k < r->nold && !old; k++)
          old = has2(r->oldv + 4 * (size_t)k, p, q);
        if (!old)
          return 0;
      }
    }
  }
  return 1;
}

/* Removes the face (code k of t) or edge (ECode) ab crosses; *done = 1 if it is gone. The
 * flips made stay in j also when it is not: they created nothing ab crosses, and a shell
 * shrunk by them is where the next, deeper try starts (TetGen keeps them too). */
static tr_status remove_crossing(struct tr_mesh *m, uint32_t t, int type, int code,
                                 const struct tr_edgeset *cons, int depth, tr_flip_journal *j,
                                 int *done)
{
  *done = 0;
  uint32_t tv[4];
  memcpy(tv, m->tv + 4 * (size_t)t, sizeof tv);
  tr_flip_guard guard = cons ? cons_guard : NULL;
  if (type == TR_EDG) {
    TR_CHECK(tr_flip_remove_edge_nm(m, tv[tr_ecode_start(code)], tv[tr_ecode_end(code)], t,
                                    depth, guard, (void *)cons, j, done));
    return TR_OK;
  }
  uint32_t be[3][2];
  int nb = tr_flip23_blockers(m, t, code, be);
  TR_CHECK(tr_flip23_jb(m, t, code, nb, guard, (void *)cons, j, done));
  for (int e = 0; e < nb && !*done && !(j->budget && j->tries >= j->budget); e++) {
    TR_CHECK(tr_flip_remove_edge_nm(m, be[e][0], be[e][1], TR_NONE, depth, guard,
                                    (void *)cons, j, done));
  }
  return TR_OK;
}

/* TR_FLIPFIRST_RETRY only where the first search left a pipe of at most this many real
 * tets: the search without the rule is the dear one the rule was brought in to avoid.
 * Plain, whole corpus: of 268 retries without a bound, 6 recovered their edge, all from
 * pipes of 3 to 5 tets; the others only moved tets (and the later points with them:
 * 85 -> 78 left, but cheese.off +6.0% instructions, 65395.stl +2.1%). The bound 3 keeps
 * three of the six for cheese.off +0.05%, 65395.stl +0.7%; 5 keeps them all for +1.7%
 * and +0.5%. */
#define TR_FLIPFIRST_RETRY_TETS 3

/* One search (tr_pipe_flip_first without the retry); *pruned: the branches the star
 * rule cut */
static tr_status search(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                        const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                        uint32_t budget, unsigned mode, tr_edge_stats *st, int *done,
                        uint32_t *pruned)
{
  *done = 0;
  tr_segmemo own;
  if (!memo) {
    tr_segmemo_init(&own, m, a, b);
    memo = &own;
  }
  tr_flip_journal j;
  memset(&j, 0, sizeof j);
  j.accept = eligible;
  j.aud = memo;
  j.budget = budget;
  j.pivot = 1;
  j.tetgen_flips = (mode & TR_FLIPFIRST_TETGEN) != 0;
  /* TetGen's star rule (flip.h): on the corpus the flip attempts fell by two thirds
   * (plain 2.48 -> 0.75 million, --keep-surface 5.03 -> 1.74 million) and the Steiner
   * points left by 23% (111 -> 85, keep 542 -> 423). It is a pruning, not a rule of
   * validity (see TR_FLIPFIRST_RETRY). */
  j.stars = !(mode & TR_FLIPFIRST_NO_STARS);
  tr_status s = TR_OK;
  /* The rounds go on at the end that last lost a crossing, the other end being tried
   * only when that one is stuck (TetGen works from one end until stuck, then from the
   * other): going back to a stuck end first in every round repeated its failed search
   * each time (on the corpus, --keep-surface, with the 4-4 of flip.c: 6.0 -> 4.75
   * million flip attempts, 1419 -> 1326 points added for edges). */
  int end = 0;
  /* The crossing at an end is read off the end's star: collecting the whole pipe after
   * every removal made each segment cost the square of its pipe (on 65395.stl of the
   * corpus a tenth of the run). The collection is still made where the star alone does
   * not decide tr_pipe_end's choice, so the flips made are the same. */
  tr_u32buf ball = {0};
  /* each removal takes away a crossed simplex and creates none: the count of crossed
   * faces and edges bounds the rounds; the cap only guards that argument */
  for (uint32_t round = 0, cap = 8 * p->n + 64; round < cap && s == TR_OK; round++) {
    int gone = 0;
    for (int k = 0; k < 2 && !gone && s == TR_OK; k++) {
      uint32_t t, via;
      int type, code, found, side = k ? !end : end;
      if ((s = tr_pipe_end_star(m, a, b, side == 0, memo, &ball, &t, &type, &code,
                                &found)) != TR_OK)
        break;
#ifndef NDEBUG
      /* debug builds check the star's answer against the collection's */
      int dtype = -1, dcode = -1, want = found;
      uint32_t dt = TR_NONE;
      if ((s = tr_pipe_collect_memo(m, a, b, p, &via, memo)) != TR_OK)
        break;
      int dpi = tr_pipe_end(m, p, a, b, side == 0, &dtype, &dcode);
      if (dpi >= 0)
        dt = p->pl[dpi].iEle;
      if (want >= 0 && (want ? dpi < 0 || dt != t || dtype != type || dcode != code : dpi >= 0)) {
        s = tr_error(TR_ERR_INTERNAL, "flips: segment %u-%u: the star of its end disagrees "
                     "with its pipe", a, b);
        break;
      }
#endif
      if (found < 0) {
        /* a failed try at the first end may have moved tets to other slots */
        if ((s = tr_pipe_collect_memo(m, a, b, p, &via, memo)) != TR_OK)
          break;
        int pi = tr_pipe_end(m, p, a, b, side == 0, &type, &code);
        if (pi < 0)
          continue;
        t = p->pl[pi].iEle;
      } else if (!found) {
        continue;
      }
      s = remove_crossing(m, t, type, code, cons, depth, &j, &gone);
      if (gone)
        end = side;
    }
    tr_pipe_count_flips(&j, st);
    if (s != TR_OK || !gone)
      break;
    int yes;
    if ((s = tr_mesh_has_edge(m, a, b, &yes)) != TR_OK)
      break;
    if (yes) {
      *done = 1;
      st->by_flips++;
      break;
    }
  }
  tr_u32buf_free(&ball);
  if (s == TR_OK && !*done) {
    uint32_t via; /* flips, kept or refused, may have moved tets to other slots */
    s = tr_pipe_collect_memo(m, a, b, p, &via, memo);
  }
  *pruned = j.pruned;
  tr_flip_journal_free(&j);
  if (memo == &own)
    tr_segmemo_free(&own);
  return s;
}

tr_status tr_pipe_flip_first(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                             const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                             uint32_t budget, unsigned mode, tr_edge_stats *st, int *done)
{
  uint32_t pruned = 0;
  TR_CHECK(search(m, a, b, p, cons, memo, depth, budget, mode, st, done, &pruned));
  if (*done || !(mode & TR_FLIPFIRST_RETRY) || (mode & TR_FLIPFIRST_NO_STARS) || !pruned)
    return TR_OK;
  uint32_t nreal = 0;
  for (uint32_t k = 0; k < p->n; k++)
    nreal += !p->pl[k].ghost;
  if (nreal > TR_FLIPFIRST_RETRY_TETS)
    return TR_OK;
  /* the flips of the first search stay (they created nothing ab crosses): the second
   * starts where it got stuck, with a budget of its own */
  return search(m, a, b, p, cons, memo, depth, budget, mode | TR_FLIPFIRST_NO_STARS, st,
                done, &pruned);
}
