/* The all-edges driver of edge recovery (see recover_edges.h).
 *
 * Order (the paper's): pass 1 runs over every missing input edge and recovers what the
 * swaps alone can recover (Swap23, Swap44, then the flips of flipfirst.c, which remove
 * the crossed faces and edges from the segment's ends by Swap23 and edge removal with
 * rising recursion depth, level by level over the edges left; with the edge split at
 * existing vertices it passes through); pass 2 recovers what is left with Steiner
 * points, after one deeper flip search (flipfirst.c, and flipseg.c's pipel-count search
 * on a short pipe, TR_EDGE_DEEP_FLIP_TETS): a
 * sub-segment whose pipe has more than two real tets is first split at its exact
 * midpoint (TetGen's way, one point, tr_pipe_split_mid; at most TR_EDGE_MIDPOINT_SPLITS
 * per input edge; when the midpoint lies in the end tets of the pipe, at a point between
 * them instead, or next to a hub edge that is then removed, see midsplit.c), Lawson flips
 * restore the local Delaunay property around the new point (lawson.h: without them the
 * mesh around the segment stays as bad as the split left it and the splits pile up; with
 * them the halves tend to become Delaunay edges and appear by themselves, as in
 * Shewchuk's segment recovery; not after a hub removal, which they could undo), and both
 * halves go
 * through the swaps and flips again; short pipes and what is left after the budget go
 * pipel by pipel, the paper's decomposition (a sub-segment whose pipe admits a swap by
 * then still takes the swap: it costs no point).
 * tr_recover_edges_ex can switch the flips, the midpoint splits and the Lawson flips off
 * (the first two off: the paper's algorithm exactly).
 *
 * Constraint edges: the mesh edges that are pieces of input edges are kept in a hash map
 * (edgeset.h) so that a Swap44 never deletes one and a Steiner point is never put on
 * one. For a valid PLC both are impossible anyway (the swapped / cut edge is crossed by
 * the edge being recovered); for crossing input edges this is where the crossing is
 * found and reported.
 *
 * Chains are computed once at the end, by walking the mesh from each input edge's first
 * end to its second along collinear mesh edges (exact point-on-segment tests). They are
 * not maintained incrementally because the vertex sequence of a recovered edge can still
 * change after its recovery: a later edge may be split at a vertex lying on it, and
 * pipel decompositions of later edges rebuild the tets around it; the mesh is the only
 * source of truth, and a walk over it is cheap (one Ball per chain vertex) and exact. The
 * same walk also proves the result: if an input edge is not a chain of mesh edges at the
 * end, the stage fails naming it.
 */
#include "recover_edges/recover_edges.h"

#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "mesh/orient_memo.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/lawson.h"
#include "recover_edges/pipe.h"

/* The deeper flip search before a Steiner point: pipes of at most this many real tets,
 * edge removals with this recursion depth. On CGAL's models, 8 tets / depth 4 (measured
 * against 6, 10 and every pipe): fewer splits (cube-meshed 12 -> 3) and fewer Steiner
 * points left after suppression, for little CPU. */
#define TR_EDGE_DEEP_FLIP_TETS 8
#define TR_EDGE_DEEP_FLIP_DEPTH 4

/* Flip levels of pass 1 (TetGen's way, Si 2015: the flip level rises round by round
 * over all the edges left): every missing edge is tried at recursion depth
 * TR_EDGE_FLIP_LEVEL_FROM, those left at the next depth, up to TR_EDGE_FLIP_LEVEL_MAX; an
 * edge recovered at one level can unblock another at the next. The levels below the last
 * remove edges only with TetGen's flips (3-2, n-m on a flat ring, its 4-4; flip.h), the
 * last and pass 2 with the general n -> 2n-4: on the whole real-world corpus that took the
 * points added from 486 to 323 and those left from 165 to 104 (Octocat: edges left after the
 * flips 74 -> 34), where general removal at every level chose ring triangulations that
 * blocked later flips; with TetGen's flips alone, cheese.off left 446 edges instead of
 * 260. Pass 2 tries
 * TR_EDGE_STEINER_FLIP_DEPTH before each Steiner point (a midpoint split makes new,
 * shorter sub-segments that often need no more). At most TR_EDGE_FLIP_BUDGET flip
 * attempts per sub-segment and try bound the recursion, which grows exponentially with
 * the depth. Measured on the 51 models of the real-world corpus that need Steiner points
 * for edges (bench/realworld): levels 4..7 and 6 in pass 2 gave 481 points added and 162
 * left after suppression, starting at level 2 608 and 185, stopping at 6 about the
 * same; the budget changes almost nothing but bounds the worst case. */
#define TR_EDGE_FLIP_LEVEL_FROM 4
#define TR_EDGE_FLIP_LEVEL_MAX 7
#define TR_EDGE_STEINER_FLIP_DEPTH 6
#define TR_EDGE_FLIP_BUDGET 20000

/* Midpoint splits allowed per input edge in pass 2 (0: the paper's pipels only). */
#ifndef TR_EDGE_MIDPOINT_SPLITS
#define TR_EDGE_MIDPOINT_SPLITS 64
#endif

_Static_assert(TR_EDGE_PIPEL_KINDS == TR_PK_COUNT, "pipel kinds of recover_edges.h and pipe.h");

typedef struct ctx {
  struct tr_mesh *m;
  const uint32_t *edges;
  uint32_t n;
  tr_edgeset cons;   /* constraint mesh edges -> input edge index */
  tr_u32buf stack;   /* sub-segments still to recover (pairs) */
  tr_u32buf walk;    /* scratch: one chain */
  tr_u32buf ball;    /* scratch: Ball(v) */
  tr_pipe pipe;
  tr_segmemo memo;   /* classifications against the sub-segment being recovered */
  tr_segmemo_store parked; /* memos of the sub-segments pass 1 left, for their next try */
  tr_edge_stats est; /* detailed counters (pipe.h) */
  uint32_t nv0;      /* vertices before the stage: ids from nv0 on are its Steiner points */
  tr_edge_recovery_opts opt;
  tr_lawson law;        /* scratch of the Lawson flips */
  tr_lawson_stats lst;
  int depth;            /* pass 1's flip level (recursion depth of tr_pipe_flip_first) */
  const uint8_t *flat;  /* NULL (one phase of flips), or per input edge: 1 = flat */
} ctx;

/* The Lawson flips may delete neither a constraint edge nor a pending sub-segment of the
 * input edge being recovered (an edge of the stack: it may already be a mesh edge). */
static int lawson_guard(void *ud, const uint32_t *v, int nv)
{
  const ctx *c = ud;
  if (nv != 2)
    return 0;
  if (tr_edgeset_get(&c->cons, v[0], v[1]) != TR_EDGESET_NONE)
    return 1;
  for (size_t i = 0; i + 1 < c->stack.n; i += 2) {
    uint32_t x = c->stack.a[i], y = c->stack.a[i + 1];
    if ((x == v[0] && y == v[1]) || (x == v[1] && y == v[0]))
      return 1;
  }
  return 0;
}

/* Wraps the message of a failure inside the recovery of input edge i with the edge's
 * vertex ids and coordinates, so that a user can locate it in the input. */
static tr_status edge_fail(const ctx *c, uint32_t i, tr_status s)
{
  char inner[768];
  strncpy(inner, tr_last_error(), sizeof inner - 1);
  inner[sizeof inner - 1] = '\0';
  uint32_t a = c->edges[2 * (size_t)i], b = c->edges[2 * (size_t)i + 1];
  const double *pa = c->m->xyz + 3 * (size_t)a, *pb = c->m->xyz + 3 * (size_t)b;
  return tr_error(s, "input edge %u (%u (%.17g, %.17g, %.17g) - %u (%.17g, %.17g, %.17g)): %s",
                  i, a, pa[0], pa[1], pa[2], b, pb[0], pb[1], pb[2], inner);
}

/* The vertices of the chain from a to b: starting at a, the next vertex is the mesh
 * neighbour of the current one lying exactly on the open segment (current, b], the
 * nearest one should there be several (impossible in a valid mesh: two neighbours on
 * one ray would make one edge contain a vertex). Each step strictly advances towards b,
 * so the walk ends after at most nv steps or fails with TR_ERR_INTERNAL. */
static tr_status walk_chain(ctx *c, uint32_t a, uint32_t b, tr_u32buf *out)
{
  struct tr_mesh *m = c->m;
  out->n = 0;
  TR_CHECK(tr_u32buf_push(out, a));
  tr_point pb = tr_mesh_point(m, b);
  /* an axis where a and b differ orders the points of ab exactly */
  tr_point pa = tr_mesh_point(m, a);
  int axis = tr_pipe_long_axis(&pa, &pb);
  if (axis < 0)
    return tr_error(TR_ERR_INTERNAL, "walk %u-%u: the two ends are the same point", a, b);
  int dir = tr_cmp_coord_p(&pa, &pb, axis);
  uint32_t v = a;
  for (uint32_t steps = 0; v != b; steps++) {
    if (steps > m->nv)
      return tr_error(TR_ERR_INTERNAL, "walk %u-%u does not end", a, b);
    /* A mesh edge v-b has no vertex inside it: the chain ends there (most input edges
     * are one mesh edge, and the early-exit search is far cheaper than a ball scan). */
    uint32_t tb;
    TR_CHECK(tr_ball_find(m, v, b, TR_NONE, &tb));
    if (tb != TR_NONE) {
      TR_CHECK(tr_u32buf_push(out, b));
      break;
    }
    TR_CHECK(tr_ball(m, v, 0, &c->ball));
    tr_point pv = tr_mesh_point(m, v);
    uint32_t next = TR_NONE;
    tr_point pn = pv;
    for (size_t i = 0; i < c->ball.n && next != b; i++) {
      const uint32_t *tv = m->tv + 4 * (size_t)c->ball.a[i];
      for (int k = 0; k < 4 && next != b; k++) {
        uint32_t w = tv[k];
        if (w == v || w == next)
          continue;
        if (w == b) {
          next = b;
          break;
        }
        tr_point pw = tr_mesh_point(m, w);
        if (tr_classify_point_segment(&pw, &pv, &pb).type != TR_EDG)
          continue;
        if (next == TR_NONE || tr_cmp_coord_p(&pw, &pn, axis) == -dir) {
          next = w;
          pn = pw;
        }
      }
    }
    if (next == TR_NONE)
      return tr_error(TR_ERR_INTERNAL,
                      "not a chain of mesh edges: vertex %u (piece %zu from %u) has no mesh "
                      "edge along the segment towards %u", v, out->n, a, b);
    TR_CHECK(tr_u32buf_push(out, next));
    v = next;
  }
  return TR_OK;
}

/* Records the current chain of sub-segment v0-v1 of input edge i as constraints. */
static tr_status add_constraints(ctx *c, uint32_t i, uint32_t v0, uint32_t v1)
{
  TR_CHECK(walk_chain(c, v0, v1, &c->walk));
  for (size_t k = 0; k + 1 < c->walk.n; k++)
    TR_CHECK(tr_edgeset_put(&c->cons, c->walk.a[k], c->walk.a[k + 1], i));
  return TR_OK;
}

/* A Steiner point on a constraint edge would split a recovered input edge: that happens
 * only when two input edges cross. */
static tr_status check_cut_edges(ctx *c, uint32_t i)
{
  for (uint32_t p = 0; p < c->pipe.n; p++) {
    const tr_pipel *pl = &c->pipe.pl[p];
    for (int e = 0; e < 2 && !pl->ghost; e++) {
      int ty = e ? (pl->type >> 2) & 3 : pl->type & 3;
      if (ty != TR_EDG)
        continue;
      int code = e ? pl->iCod2 : pl->iCod1;
      const uint32_t *tv = c->m->tv + 4 * (size_t)pl->iEle;
      uint32_t u = tv[tr_ecode_start(code)], w = tv[tr_ecode_end(code)];
      uint32_t j = tr_edgeset_get(&c->cons, u, w);
      if (j != TR_EDGESET_NONE)
        return tr_error(TR_ERR_SELF_INTERSECT,
                        "it crosses input edge %u (%u-%u) at the interior of its piece %u-%u",
                        j, c->edges[2 * (size_t)j], c->edges[2 * (size_t)j + 1], u, w);
    }
  }
  (void)i;
  return TR_OK;
}

/* Recovers input edge i as far as allowed: with steiner == 0 only by swaps (and splits at
 * existing vertices); sub-segments that would need Steiner points are left and *complete
 * is cleared. *npoints counts the Steiner points added. */
static tr_status recover_one(ctx *c, uint32_t i, int steiner, int *complete, uint32_t *npoints)
{
  struct tr_mesh *m = c->m;
  *complete = 1;
  *npoints = 0;
  c->stack.n = 0;
  uint32_t nsplit = 0;
  (void)nsplit;
  TR_CHECK(tr_u32buf_push(&c->stack, c->edges[2 * (size_t)i]));
  TR_CHECK(tr_u32buf_push(&c->stack, c->edges[2 * (size_t)i + 1]));
  while (c->stack.n > 0) {
    uint32_t v1 = c->stack.a[c->stack.n - 1], v0 = c->stack.a[c->stack.n - 2];
    c->stack.n -= 2;
    int yes;
    TR_CHECK(tr_mesh_has_edge(m, v0, v1, &yes));
    if (yes) {
      TR_CHECK(tr_edgeset_put(&c->cons, v0, v1, i));
      continue;
    }
    uint32_t via;
    /* the memo serves the flips below; a new sub-segment starts an empty one, or the one
     * its try at the last flip level left: the walks and flips of the next levels and of
     * pass 2 ask for many of its tets again (--keep-surface instructions: 65395.stl -3%,
     * cheese.off -6%, same output) */
    tr_segmemo_take(&c->parked, &c->memo, m, v0, v1);
    TR_CHECK(tr_pipe_collect_memo(m, v0, v1, &c->pipe, &via, &c->memo));
    if (via != TR_NONE) {
      /* A Steiner point of this stage lies on another input edge: passing through it
       * means crossing that edge. (Input vertices on the edge are fine: the edge is
       * split there, chain A-V-B.) */
      if (via >= c->nv0)
        return tr_error(TR_ERR_SELF_INTERSECT,
                        "it passes through Steiner point %u of another input edge "
                        "(the two input edges cross)", via);
      /* v0-via first: pushed last */
      uint32_t four[4] = {via, v1, v0, via};
      for (int k = 0; k < 4; k++)
        TR_CHECK(tr_u32buf_push(&c->stack, four[k]));
      c->est.split_at_vertex++;
      continue;
    }
    if (c->pipe.n == 0)
      return tr_error(TR_ERR_INTERNAL, "sub-segment %u-%u: empty pipe for a missing edge",
                      v0, v1);
    int done;
    uint32_t budget = c->opt.flip_budget ? c->opt.flip_budget : TR_EDGE_FLIP_BUDGET;
    TR_CHECK(tr_pipe_try_swaps(m, v0, v1, &c->pipe, &c->cons, &c->est, &done));
    /* Before a Steiner point (pass 2) the search goes once more without the star rule
     * where the rule cut a branch and the pipe left is short (TR_FLIPFIRST_RETRY). Whole
     * corpus, plain: points added for edges 293 -> 288, left after suppression 85 -> 82
     * (CGAL's models 35 -> 33); --keep-surface 1275 -> 1263, 423 -> 417. */
    if (!done && !c->opt.no_flips)
      TR_CHECK(tr_pipe_flip_first(m, v0, v1, &c->pipe, &c->cons, &c->memo,
                                  steiner ? TR_EDGE_STEINER_FLIP_DEPTH : c->depth, budget,
                                  steiner ? TR_FLIPFIRST_RETRY
                                  : c->depth < TR_EDGE_FLIP_LEVEL_MAX ? TR_FLIPFIRST_TETGEN
                                                                      : 0,
                                  &c->est, &done));
    if (done) {
      TR_CHECK(tr_edgeset_put(&c->cons, v0, v1, i));
      continue;
    }
    if (!steiner) {
      /* pass 1 adds no point, so the memo names only vertices below nv0, and pass 2
       * takes back (tr_mesh_pop_vertex) only points it added: its ids keep their points */
      tr_segmemo_park(&c->parked, &c->memo);
      *complete = 0;
      continue;
    }
    /* Before a Steiner point: a short pipe gets one deeper flip search (TetGen deepens
     * its flip level for the segments left, Si 2015). Each point saved here is one the
     * suppression need not remove; on long pipes the search costs more than it saves. */
    uint32_t nreal = 0;
    for (uint32_t k = 0; k < c->pipe.n; k++)
      nreal += !c->pipe.pl[k].ghost;
    if (!c->opt.no_flips && nreal <= TR_EDGE_DEEP_FLIP_TETS) {
      TR_CHECK(tr_pipe_try_flips_depth(m, v0, v1, &c->pipe, &c->cons, &c->memo,
                                       TR_EDGE_DEEP_FLIP_DEPTH, &c->est, &done));
      if (done) {
        TR_CHECK(tr_edgeset_put(&c->cons, v0, v1, i));
        continue;
      }
    }
    TR_CHECK(check_cut_edges(c, i));
#if TR_EDGE_MIDPOINT_SPLITS
    /* TetGen's way: one point at the midpoint, then flips on each half, instead of one
     * point per crossed edge / face (the paper's pipels, kept for short pipes and as the
     * fallback once the split budget of this input edge is used up) */
    if (nreal > 2 && nsplit < TR_EDGE_MIDPOINT_SPLITS && !c->opt.no_midpoints) {
      uint32_t mid;
      int ok;
      TR_CHECK(tr_pipe_split_mid(m, v0, v1, &c->pipe, lawson_guard, c, &mid, &ok));
      if (ok) {
        nsplit++;
        *npoints += 1;
        c->est.steiner_points++;
        c->est.midpoints++;
        uint32_t four[4] = {mid, v1, v0, mid};
        for (int k = 0; k < 4; k++)
          TR_CHECK(tr_u32buf_push(&c->stack, four[k]));
        /* after a hub removal M took the hub's place: Lawson flips could bring it back */
        if (!c->opt.no_lawson && ok == 1)
          TR_CHECK(tr_lawson_vertex(m, mid, lawson_guard, c, &c->law, &c->lst));
        continue;
      }
    }
#endif
    uint32_t nadd;
    TR_CHECK(tr_pipe_add_steiner(m, v0, v1, &c->pipe, &nadd));
    *npoints += nadd;
    c->est.steiner_points += nadd;
    TR_CHECK(tr_pipe_decompose(m, &c->pipe, &c->est));
    c->est.by_pipels++;
    TR_CHECK(add_constraints(c, i, v0, v1));
  }
  return TR_OK;
}

static tr_status check_input(const struct tr_mesh *m, const uint32_t *edges, uint32_t n)
{
  for (uint32_t i = 0; i < n; i++) {
    uint32_t a = edges[2 * (size_t)i], b = edges[2 * (size_t)i + 1];
    if (a >= b || b >= m->nv)
      return tr_error(TR_ERR_INPUT, "input edge %u (%u-%u): vertex ids must satisfy a < b < %u",
                      i, a, b, m->nv);
    if (m->v2t[a] == TR_NONE || m->v2t[b] == TR_NONE)
      return tr_error(TR_ERR_INPUT, "input edge %u (%u-%u): a vertex is not in the mesh "
                      "(a dropped duplicate?)", i, a, b);
    if (i > 0 && (edges[2 * (size_t)i - 2] > a ||
                  (edges[2 * (size_t)i - 2] == a && edges[2 * (size_t)i - 1] >= b)))
      return tr_error(TR_ERR_INPUT, "input edges %u and %u are not sorted and unique", i - 1, i);
  }
  return TR_OK;
}

/* there[i]: input edge i was a mesh edge when the last phase of flips began. Such an
 * edge was a constraint from then on (no flip takes it away, no Steiner point splits
 * it), so it is one still: only the others are walked, instead of listing every edge of
 * the mesh once more (debug builds list them and check). */
static tr_status build_chains(ctx *c, tr_edge_chains *ch, const uint8_t *there)
{
  size_t cap = 2 * (size_t)c->n + 16, nv = 0;
  ch->n = c->n;
  ch->start = malloc(((size_t)c->n + 1) * sizeof *ch->start);
  ch->v = malloc(cap * sizeof *ch->v);
  if (!ch->start || !ch->v)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u edge chains", c->n);
  tr_status fs = TR_OK;
#ifndef NDEBUG
  uint8_t *now = malloc(c->n ? c->n : 1);
  if (!now)
    fs = tr_error(TR_ERR_NOMEM, "out of memory for %u input edges", c->n);
  else
    fs = tr_mesh_find_edges(c->m, c->edges, c->n, now);
  for (uint32_t i = 0; i < c->n && fs == TR_OK; i++)
    if (there[i] && !now[i])
      fs = tr_error(TR_ERR_INTERNAL, "input edge %u (%u-%u) was a constraint and is gone", i,
                    c->edges[2 * (size_t)i], c->edges[2 * (size_t)i + 1]);
  free(now);
#endif
  for (uint32_t i = 0; i < c->n && fs == TR_OK; i++) {
    ch->start[i] = (uint32_t)nv;
    uint32_t a = c->edges[2 * (size_t)i], b = c->edges[2 * (size_t)i + 1];
    c->walk.n = 0;
    if (there[i]) {
      if ((fs = tr_u32buf_push(&c->walk, a)) == TR_OK)
        fs = tr_u32buf_push(&c->walk, b);
    } else if ((fs = walk_chain(c, a, b, &c->walk)) != TR_OK) {
      fs = edge_fail(c, i, fs);
    }
    if (fs != TR_OK)
      break;
    if (nv + c->walk.n > cap) {
      while (nv + c->walk.n > cap)
        cap *= 2;
      uint32_t *q = realloc(ch->v, cap * sizeof *q);
      if (!q) {
        fs = tr_error(TR_ERR_NOMEM, "out of memory for edge chains");
        break;
      }
      ch->v = q;
    }
    memcpy(ch->v + nv, c->walk.a, c->walk.n * sizeof *ch->v);
    nv += c->walk.n;
    if (nv >= UINT32_MAX)
      fs = tr_error(TR_ERR_NOMEM, "edge chains: more than 2^32 entries");
  }
  ch->start[c->n] = (uint32_t)nv;
  return fs;
}

/* The flips of one phase (see run): the constraints are put in first, since pass 1 must
 * not swap away an edge that is already there (there[] holds which are); the edges of
 * the phase that are missing are appended to missing[*nmiss..] and go through pass 1
 * (swaps and the general flips), then the deepening pass (every edge still missing again,
 * with deeper flips level by level: an edge recovered at one level can unblock another
 * at the next). left[k] = 1 for those still missing. */
static tr_status flip_phase(ctx *c, int phase, const uint8_t *there, uint32_t *missing,
                            uint32_t *nmiss, uint8_t *left, tr_edge_recovery_stats *st)
{
  const uint8_t *flat = c->flat;
  uint32_t k0 = *nmiss;
  /* the constraints go in by the thousand: grown from 8 keys, the set rehashed them all
   * a dozen times (a hint: the puts below grow the set anyway if it fails) */
  (void)tr_vtmap_reserve(&c->cons.m, 2, c->n);
  for (uint32_t i = 0; i < c->n; i++) {
    int mine = !flat || (phase == 0) == !flat[i];
    if (there[i] && (mine || phase == 1))
      TR_CHECK(tr_edgeset_put(&c->cons, c->edges[2 * (size_t)i], c->edges[2 * (size_t)i + 1], i));
    else if (!there[i] && mine)
      missing[(*nmiss)++] = i;
  }
  /* pass 1: swaps and flips, level by level (the first level also counts how each edge
   * came: by swaps and flips, or only split at vertices on it) */
  for (uint32_t k = k0; k < *nmiss; k++)
    left[k] = 1;
  for (int d = TR_EDGE_FLIP_LEVEL_FROM; d <= TR_EDGE_FLIP_LEVEL_MAX; d++) {
    c->depth = d;
    uint32_t nleft = 0;
    for (uint32_t k = k0; k < *nmiss; k++) {
      if (!left[k])
        continue;
      int complete;
      uint32_t np;
      uint32_t sw = c->est.by_swap23 + c->est.by_swap44 + c->est.by_flips;
      tr_status s = recover_one(c, missing[k], 0, &complete, &np);
      if (s != TR_OK)
        return edge_fail(c, missing[k], s);
      left[k] = !complete;
      nleft += left[k];
      if (complete && (d > TR_EDGE_FLIP_LEVEL_FROM ||
                       c->est.by_swap23 + c->est.by_swap44 + c->est.by_flips > sw))
        st->recovered_by_swap++;
      else if (complete)
        st->through_vertices++;
    }
    if (!nleft || c->opt.no_flips)
      break; /* without flips a second round would repeat the swaps of the first */
  }
  c->depth = 0;
  return TR_OK;
}

static tr_status run(ctx *c, tr_edge_chains *chains, tr_edge_recovery_stats *st)
{
  struct tr_mesh *m = c->m;
  uint32_t *missing = NULL, nmiss = 0;
  uint8_t *left = NULL, *there = NULL, *flat = NULL;
  tr_status s = TR_OK;
  if (c->n) {
    missing = malloc((size_t)c->n * sizeof *missing);
    left = calloc(c->n, 1);
    there = malloc(c->n);
    if (!missing || !left || !there) {
      s = tr_error(TR_ERR_NOMEM, "out of memory for %u input edges", c->n);
      goto done;
    }
    s = tr_mesh_find_edges(m, c->edges, c->n, there);
  }
  /* Two phases of flips when flat edges are flagged and a feature edge is missing
   * (TetGen's order, Si 2015: its segments are the edges between facets, and the edges
   * inside a facet come with the facet's sub-faces after them): phase 0 protects and
   * recovers the feature edges only, so that its flips may take away an edge inside a
   * flat region on the way (CAD surfaces cut their planar faces into fans and grids
   * whose edges block the flips); phase 1 protects every edge that is there then and
   * recovers the flat ones. One phase (1) otherwise. On the Thingi10K models of
   * STLCutters.jl: 2112 -> 2032 Steiner points on edges, 181 -> 161 left after
   * suppression. */
  for (uint32_t i = 0; i < c->n && s == TR_OK; i++)
    st->missing_edges += !there[i];
  uint32_t miss_feature = 0;
  if (s == TR_OK && st->missing_edges && c->opt.surface) {
    if (!(flat = malloc(c->n)))
      s = tr_error(TR_ERR_NOMEM, "out of memory for %u edge flags", c->n);
    else
      s = tr_flat_edges(c->opt.surface, c->edges, c->n, flat);
    for (uint32_t i = 0; i < c->n && s == TR_OK; i++)
      miss_feature += !there[i] && !flat[i];
  }
  c->flat = miss_feature ? flat : NULL;
  for (int phase = c->flat ? 0 : 1; phase < 2 && s == TR_OK; phase++) {
    if (phase == 1 && c->flat)
      s = tr_mesh_find_edges(m, c->edges, c->n, there); /* phase 0 flipped some away */
    if (s == TR_OK)
      s = flip_phase(c, phase, there, missing, &nmiss, left, st);
  }
  /* pass 2: Steiner points for the rest */
  for (uint32_t k = 0; k < nmiss && s == TR_OK; k++) {
    if (!left[k])
      continue;
    int complete;
    uint32_t np;
    if ((s = recover_one(c, missing[k], 1, &complete, &np)) != TR_OK) {
      s = edge_fail(c, missing[k], s);
      break;
    }
    st->points_added += np;
    if (np == 0)
      st->recovered_by_swap++; /* a swap became possible after other edges moved */
    else
      st->recovered_by_steiner++;
  }
  if (s == TR_OK)
    s = build_chains(c, chains, there);
  if (s == TR_OK) {
    st->swap23 = c->est.by_swap23;
    st->swap44 = c->est.by_swap44;
    st->split_at_vertex = c->est.split_at_vertex;
    st->ghosts_split = c->est.ghosts_split;
    st->flip23 = c->est.flip23;
    st->flip32 = c->est.flip32;
    st->flip44 = c->est.flip44;
    st->flipn = c->est.flipn;
    st->flip_hull = c->est.flip_hull;
    st->flips_undone = c->est.flips_undone;
    st->midpoints = c->est.midpoints;
    st->lawson_flip23 = c->lst.flip23;
    st->lawson_flip32 = c->lst.flip32;
    st->lawson_flip44 = c->lst.flip44;
    for (int k = 0; k < TR_PK_COUNT; k++)
      st->pipels[k] = c->est.pipels[k];
    for (int k = 0; k < 16; k++)
      st->pipels_raw[k] = c->est.raw[k];
  }
done:
  free(missing);
  free(left);
  free(there);
  free(flat);
  return s;
}

tr_status tr_recover_edges(struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                           tr_edge_chains *chains, tr_edge_recovery_stats *st)
{
  return tr_recover_edges_ex(m, edges, n, NULL, chains, st);
}

tr_status tr_recover_edges_ex(struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                              const tr_edge_recovery_opts *opt, tr_edge_chains *chains,
                              tr_edge_recovery_stats *st)
{
  memset(chains, 0, sizeof *chains);
  memset(st, 0, sizeof *st);
  TR_CHECK(check_input(m, edges, n));
  ctx c;
  memset(&c, 0, sizeof c);
  c.m = m;
  c.edges = edges;
  c.n = n;
  c.nv0 = m->nv;
  if (opt)
    c.opt = *opt;
  /* points are only added here (tr_mesh_pop_vertex forgets the memo when one is taken back) */
  int memo = !m->omemo;
  tr_status s = memo ? tr_mesh_orient_memo_on(m) : TR_OK;
  if (s == TR_OK)
    s = run(&c, chains, st);
  if (memo)
    tr_mesh_orient_memo_off(m);
  tr_edgeset_free(&c.cons);
  tr_u32buf_free(&c.stack);
  tr_u32buf_free(&c.walk);
  tr_u32buf_free(&c.ball);
  tr_pipe_free(&c.pipe);
  tr_segmemo_free(&c.memo);
  tr_segmemo_store_free(&c.parked);
  tr_lawson_free(&c.law);
  if (s != TR_OK)
    tr_edge_chains_free(chains);
  return s;
}

void tr_edge_chains_free(tr_edge_chains *c)
{
  free(c->start);
  free(c->v);
  memset(c, 0, sizeof *c);
}

uint32_t tr_edge_chains_find(const tr_edge_chains *c, const uint32_t *edges, uint32_t a,
                             uint32_t b)
{
  return tr_edge_index(edges, c->n, a, b);
}

uint32_t tr_edge_index(const uint32_t *edges, uint32_t n, uint32_t a, uint32_t b)
{
  uint32_t lo = 0, hi = n;
  if (a > b) {
    uint32_t t = a;
    a = b;
    b = t;
  }
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    uint32_t x = edges[2 * (size_t)mid], y = edges[2 * (size_t)mid + 1];
    if (x == a && y == b)
      return mid;
    if (x < a || (x == a && y < b))
      lo = mid + 1;
    else
      hi = mid;
  }
  return TR_NONE;
}
