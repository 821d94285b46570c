/* Recovery of one missing sub-segment by general flips (tr_pipe_try_flips, pipe.h).
 *
 * Each round lists the simplices ab crosses in the current pipe (faces for Swap23 or,
 * when that is refused, the removal of an edge of the face; edges for edge removal with
 * the bounded flipnm recursion of flip.h, in pipe order:
 * deterministic) and keeps the first attempt that lowers the number of real pipels; an
 * attempt that does not is undone exactly through its journal. The change is summed over
 * the flipped regions only (tets outside them keep their status). The number of pipels is
 * a natural number that drops every round, so the loop ends; it ends early when ab is a
 * mesh edge. Candidates are remembered by vertex ids, so a slot moved by an undo cannot
 * mislead the next attempt. A candidate whose attempt was undone is skipped until a round
 * finds nothing among the others, then all are tried again on a freshly collected pipe:
 * retrying the failed ones after every kept attempt made the search quadratic.
 */
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/flip.h"
#include "recover_edges/pipe.h"

typedef struct cand {
  uint32_t t;     /* a tet holding the simplex when listed */
  uint32_t v[3];  /* face: 3 ids; edge: v[0], v[1], v[2] = TR_NONE */
  int k;          /* face code in t (faces) */
} cand;

static int cons_guard(void *ud, const uint32_t *v, int nv)
{
  return nv == 2 && tr_edgeset_get(ud, v[0], v[1]) != TR_EDGESET_NONE;
}

/* The crossed faces and edges of the pipe, each once. */
static tr_status list_cands(const struct tr_mesh *m, const tr_pipe *p, cand **out, uint32_t *n,
                            uint32_t *cap, tr_sxset *seen)
{
  *n = 0;
  tr_sxset_clear(seen);
  for (uint32_t i = 0; i < p->n; i++) {
    const tr_pipel *pl = &p->pl[i];
    if (pl->ghost)
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)pl->iEle;
    for (int e = 0; e < 2; e++) {
      int ty = e ? (pl->type >> 2) & 3 : pl->type & 3, code = e ? pl->iCod2 : pl->iCod1;
      cand c;
      c.t = pl->iEle;
      c.k = -1;
      if (ty == TR_FAC) {
        c.k = code;
        for (int j = 0; j < 3; j++)
          c.v[j] = tv[tr_face_vtx[code][j]];
      } else if (ty == TR_EDG) {
        c.v[0] = tv[tr_ecode_start(code)];
        c.v[1] = tv[tr_ecode_end(code)];
        c.v[2] = TR_NONE;
      } else {
        continue;
      }
      int added = tr_sxset_add(seen, c.v);
      if (added < 0)
        return TR_ERR_NOMEM;
      if (!added)
        continue;
      if (*n == *cap) {
        uint32_t nc = *cap ? 2 * *cap : 32;
        cand *q = realloc(*out, nc * sizeof *q);
        if (!q)
          return tr_error(TR_ERR_NOMEM, "out of memory for flip candidates");
        *out = q;
        *cap = nc;
      }
      (*out)[(*n)++] = c;
    }
  }
  return TR_OK;
}

/* Applies candidate c (if its tet still holds it) through the journal: Swap23 for a face
 * (else the removal of one of its edges, recursion depth - 1), edge removal with recursion
 * depth `depth` for an edge. Flips tried and taken back inside are added to *undone. */
#define TR_FLIPSEG_DEPTH 3
static tr_status apply(struct tr_mesh *m, const cand *c, const struct tr_edgeset *cons,
                       int depth, tr_flip_journal *j, uint32_t *undone, int *done)
{
  *done = 0;
  if (c->v[2] != TR_NONE) {
    if (tr_tet_is_free(m, c->t) || tr_fcode(m, c->t, c->v[0], c->v[1], c->v[2]) != c->k)
      return TR_OK;
    TR_CHECK(tr_flip23_j(m, c->t, c->k, NULL, NULL, j, done));
    if (*done || depth < 2)
      return TR_OK;
    /* The Swap23 is refused when the segment between the apexes misses the face: an edge
     * of the face blocks it. Removing that edge (with the same recursion) often takes ab
     * straight in: when ab crosses two faces sharing an edge of degree 3, its Swap32 makes
     * ab. Each edge alone, kept only if the pipe shrinks. On CGAL's cheese this took the
     * edges left to Steiner points from 1795 to 1108 and the points on edges from 2009 to
     * 545. */
    for (int e = 0; e < 3 && !(j->budget && j->tries >= j->budget); e++) {
      uint32_t n0 = j->n;
      long d0 = j->delta;
      int ok;
      TR_CHECK(tr_flip_remove_edge_nm(m, c->v[e], c->v[(e + 1) % 3], TR_NONE, depth - 1,
                                      cons ? cons_guard : NULL, (void *)cons, j, &ok));
      if (j->n > n0 && j->delta < d0) {
        *done = 1;
        return TR_OK;
      }
      *undone += j->n - n0;
      TR_CHECK(tr_flip_journal_undo(m, j, n0));
    }
    return TR_OK;
  }
  uint32_t t0 = c->t;
  if (tr_tet_is_free(m, t0) || tr_tet_ecode(m, t0, c->v[0], c->v[1]) < 0)
    t0 = TR_NONE;
  return tr_flip_remove_edge_nm(m, c->v[0], c->v[1], t0, depth,
                                cons ? cons_guard : NULL, (void *)cons, j, done);
}

/* The measure of a flip attempt: 1 iff the real tet with vertices v meets the open
 * segment ab at a point that is not one of its vertices (a pipel of pipe.h; ghosts count
 * 0). Memoised: every flip made and undone re-measures the same tets, and the memo also
 * serves the re-collection of the pipe after a kept attempt. */
static int pipel_measure(void *ud, const struct tr_mesh *m, const uint32_t v[4])
{
  if (v[3] == TR_GHOST)
    return 0;
  tr_isect x = tr_segmemo_classify(ud, m, v);
  for (int e = 0; e < x.n; e++)
    if (x.end[e].type != TR_NOD)
      return 1;
  return 0;
}

tr_status tr_pipe_try_flips(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                            const struct tr_edgeset *cons, tr_segmemo *memo,
                            tr_edge_stats *st, int *done)
{
  return tr_pipe_try_flips_depth(m, a, b, p, cons, memo, TR_FLIPSEG_DEPTH, st, done);
}

tr_status tr_pipe_try_flips_depth(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                                  const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                                  tr_edge_stats *st, int *done)
{
  return tr_pipe_try_flips_budget(m, a, b, p, cons, memo, depth, 0, st, done);
}

tr_status tr_pipe_try_flips_budget(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                                   const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                                   uint32_t budget, tr_edge_stats *st, int *done)
{
  *done = 0;
  cand *cs = NULL;
  uint32_t nc = 0, cap = 0, via;
  tr_status s = TR_OK;
  tr_segmemo own, *g = memo;
  if (!g) {
    tr_segmemo_init(&own, m, a, b);
    g = &own;
  }
  tr_sxset seen = {0}, failed = {0};
  tr_flip_journal j;
  memset(&j, 0, sizeof j);
  j.measure = pipel_measure;
  j.mud = g;
  j.budget = budget;
  /* The measure is the number of real pipels; the journal adds up its change over the
   * flips of one attempt (pipels among the new tets - among the old ones). */
  for (int progress = 1, skipped = 0; (progress || skipped) && s == TR_OK && !*done;) {
    if (budget && j.tries >= budget)
      break; /* spent: what a retry could find costs more than the point it saves */
    if (!progress) {
      /* stuck on the fresh candidates: retry the failed ones, on a pipe collected again
       * since undos may have moved tets to other slots */
      tr_sxset_clear(&failed);
      if ((s = tr_pipe_collect_memo(m, a, b, p, &via, g)) != TR_OK)
        break;
    }
    progress = 0;
    skipped = 0;
    if ((s = list_cands(m, p, &cs, &nc, &cap, &seen)) != TR_OK)
      break;
    for (uint32_t i = 0; i < nc && !progress && s == TR_OK; i++) {
      int ok;
      if (tr_sxset_has(&failed, cs[i].v)) {
        skipped = 1;
        continue;
      }
      if ((s = apply(m, &cs[i], cons, depth, &j, &st->flips_undone, &ok)) != TR_OK)
        break;
      if (j.n && j.delta < 0) {
        tr_pipe_count_flips(&j, st);
        progress = 1;
        int yes;
        if ((s = tr_mesh_has_edge(m, a, b, &yes)) != TR_OK)
          break;
        if (yes)
          *done = 1;
        else
          s = tr_pipe_collect_memo(m, a, b, p, &via, g);
        if (s == TR_OK && !*done && via != TR_NONE)
          s = tr_error(TR_ERR_INTERNAL, "flips: segment %u-%u now passes through vertex %u",
                       a, b, via);
        break;
      }
      st->flips_undone += j.n;
      if ((s = tr_flip_journal_undo(m, &j, 0)) == TR_OK && tr_sxset_add(&failed, cs[i].v) < 0)
        s = TR_ERR_NOMEM;
    }
  }
  if (*done)
    st->by_flips++;
  else if (s == TR_OK && nc > 0)
    s = tr_pipe_collect_memo(m, a, b, p, &via, g); /* undos may have moved tets to other slots */
  tr_flip_journal_free(&j);
  if (g == &own)
    tr_segmemo_free(&own);
  tr_sxset_free(&seen);
  tr_sxset_free(&failed);
  free(cs);
  return s;
}
