/* Rounding Steiner points to doubles and its repair: see round.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "predicates.h"
#include "round.h"

static int kept(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags && (m->flags[t] & TR_TF_OUTER));
}

static int steiner(const struct tr_mesh *m, uint32_t v)
{
  return m->vq && m->vq[v];
}

static int positive(const struct tr_mesh *m, uint32_t t)
{
  return !tr_round_flat(m, m->tv + 4 * (size_t)t);
}

uint64_t tr_round_count_nonpositive(const struct tr_mesh *m, uint32_t *first)
{
  uint64_t n = 0;
  if (first)
    *first = TR_NONE;
  for (uint32_t t = 0; t < m->nt; t++)
    if (kept(m, t) && !positive(m, t)) {
      if (first && n == 0)
        *first = t;
      n++;
    }
  return n;
}

/* Tets incident to each Steiner vertex, CSR: the tets of v are tet[start[v]..start[v+1]).
 * Built from the tet list rather than by a Ball walk because the kept tets around a point
 * need not be face-connected (two regions touching along an edge). */
typedef struct {
  uint32_t *start, *tet;
  uint64_t *work;  /* star checks so far; past budget every check fails */
  uint64_t budget; /* TR_ROUND_BUDGET unless the caller asked otherwise */
} star_index;

static tr_status stars_build(const struct tr_mesh *m, star_index *S)
{
  S->start = calloc((size_t)m->nv + 1, sizeof *S->start);
  S->tet = NULL;
  if (!S->start)
    return tr_error(TR_ERR_NOMEM, "out of memory indexing Steiner points");
  for (uint32_t t = 0; t < m->nt; t++)
    if (kept(m, t))
      for (int k = 0; k < 4; k++)
        if (steiner(m, m->tv[4 * (size_t)t + k]))
          S->start[m->tv[4 * (size_t)t + k] + 1]++;
  for (uint32_t v = 0; v < m->nv; v++)
    S->start[v + 1] += S->start[v];
  S->tet = malloc(sizeof *S->tet * (S->start[m->nv] ? S->start[m->nv] : 1));
  uint32_t *fill = malloc(sizeof *fill * (m->nv ? m->nv : 1));
  if (!S->tet || !fill) {
    free(fill);
    return tr_error(TR_ERR_NOMEM, "out of memory indexing Steiner points");
  }
  memcpy(fill, S->start, sizeof *fill * m->nv);
  for (uint32_t t = 0; t < m->nt; t++)
    if (kept(m, t))
      for (int k = 0; k < 4; k++) {
        uint32_t v = m->tv[4 * (size_t)t + k];
        if (steiner(m, v))
          S->tet[fill[v]++] = t;
      }
  free(fill);
  return TR_OK;
}

/* The first tet of v's star (from index *hint on, cyclically) that is not strictly
 * positive and does not contain vertex `except` (TR_NONE: none excepted), TR_NONE if
 * there is none. Starting at the last failure makes rejected candidates cheap: the tet
 * that was too thin for the previous one is usually too thin again. */
static uint32_t star_failure(const struct tr_mesh *m, const star_index *S, uint32_t v,
                             uint32_t except, uint32_t *hint)
{
  uint32_t a = S->start[v], n = S->start[v + 1] - a;
  if (++*S->work > S->budget && n > 0)
    return S->tet[a]; /* out of budget: no more moves (tr_round_steiner reports it) */
  for (uint32_t i = 0; i < n; i++) {
    uint32_t j = (*hint + i) % n, t = S->tet[a + j];
    if (except != TR_NONE && tr_ncode(m, t, except) >= 0)
      continue;
    if (!positive(m, t)) {
      *hint = j;
      return t;
    }
  }
  return TR_NONE;
}

/* Offsets (i, j, k) of the search cube, ordered as round.h says, (0,0,0) excluded. */
typedef struct {
  int8_t d[3];
} offset;

static int offset_norm(const offset *o)
{
  return o->d[0] * o->d[0] + o->d[1] * o->d[1] + o->d[2] * o->d[2];
}

static int cmp_offset(const void *pa, const void *pb)
{
  const offset *a = pa, *b = pb;
  int na = offset_norm(a), nb = offset_norm(b);
  if (na != nb)
    return na < nb ? -1 : 1;
  for (int k = 0; k < 3; k++)
    if (a->d[k] != b->d[k])
      return a->d[k] < b->d[k] ? -1 : 1;
  return 0;
}

static tr_status offsets_build(offset **out, size_t *n)
{
  const int R = TR_ROUND_RADIUS, w = 2 * R + 1;
  offset *o = malloc(sizeof *o * (size_t)w * w * w);
  if (!o)
    return tr_error(TR_ERR_NOMEM, "out of memory for the rounding search");
  size_t c = 0;
  for (int i = -R; i <= R; i++)
    for (int j = -R; j <= R; j++)
      for (int k = -R; k <= R; k++)
        if (i || j || k) {
          o[c].d[0] = (int8_t)i;
          o[c].d[1] = (int8_t)j;
          o[c].d[2] = (int8_t)k;
          c++;
        }
  qsort(o, c, sizeof *o, cmp_offset);
  *out = o;
  *n = c;
  return TR_OK;
}

/* The candidate doubles of Steiner vertex v: ax[k][R + s] = its nearest double moved by
 * s ulp steps on axis k. */
typedef double cand_axes[3][2 * TR_ROUND_RADIUS + 1];
static void candidates(const struct tr_mesh *m, uint32_t v, cand_axes ax)
{
  const int R = TR_ROUND_RADIUS;
  const double *near = m->vq[v]->near;
  for (int k = 0; k < 3; k++) {
    ax[k][R] = near[k];
    for (int s = 1; s <= R; s++) {
      ax[k][R + s] = nextafter(ax[k][R + s - 1], INFINITY);
      ax[k][R - s] = nextafter(ax[k][R - s + 1], -INFINITY);
    }
  }
}

/* Puts v at candidate c; 0 if a coordinate is not finite. */
static int place(struct tr_mesh *m, uint32_t v, cand_axes ax, const offset *c)
{
  double *x = m->xyz + 3 * (size_t)v;
  int ok = 1;
  for (int k = 0; k < 3; k++) {
    x[k] = ax[k][TR_ROUND_RADIUS + c->d[k]];
    ok &= isfinite(x[k]) != 0;
  }
  return ok;
}

/* Searches the first of the noff candidates of Steiner vertex v that makes its whole star
 * strictly positive; on success m->xyz of v holds it and 1 is returned, else v is back
 * where it was and 0 is returned. */
static int search(struct tr_mesh *m, const star_index *S, uint32_t v, const offset *off,
                  size_t noff)
{
  cand_axes ax;
  candidates(m, v, ax);
  double *x = m->xyz + 3 * (size_t)v, was[3];
  memcpy(was, x, sizeof was);
  uint32_t hint = 0;
  for (size_t c = 0; c < noff; c++)
    if (place(m, v, ax, &off[c]) && star_failure(m, S, v, TR_NONE, &hint) == TR_NONE)
      return 1;
  memcpy(x, was, sizeof was);
  return 0;
}

/* When v alone cannot be repaired, a Steiner neighbour w may be what leaves no room (a
 * sliver between two Steiner points: v's tets need w farther from their plane). Tries w's
 * candidates that keep w's tets without v positive, each with a search for v, both within
 * the first npair offsets; neighbours in index order. 1 on success (both placed). */
static int search_pair(struct tr_mesh *m, const star_index *S, uint32_t v, const offset *off,
                       size_t npair, uint32_t *moved_w)
{
  uint32_t a = S->start[v], n = S->start[v + 1] - a, last = TR_NONE;
  for (;;) {
    /* the smallest Steiner neighbour above `last` */
    uint32_t w = TR_NONE;
    for (uint32_t i = 0; i < n; i++)
      for (int k = 0; k < 4; k++) {
        uint32_t u = m->tv[4 * (size_t)S->tet[a + i] + k];
        if (u != v && steiner(m, u) && (last == TR_NONE || u > last) && (w == TR_NONE || u < w))
          w = u;
      }
    if (w == TR_NONE)
      return 0;
    last = w;
    cand_axes ax;
    candidates(m, w, ax);
    double *x = m->xyz + 3 * (size_t)w, was[3];
    memcpy(was, x, sizeof was);
    uint32_t hint = 0;
    for (size_t c = 0; c < npair; c++)
      if (place(m, w, ax, &off[c]) && star_failure(m, S, w, v, &hint) == TR_NONE &&
          search(m, S, v, off, npair)) {
        *moved_w = w;
        return 1;
      }
    memcpy(x, was, sizeof was);
  }
}

/* Number of tets of v's star that are not strictly positive, stopping at `cap`. */
static uint32_t star_bad(const struct tr_mesh *m, const star_index *S, uint32_t v, uint32_t cap)
{
  uint32_t n = 0;
  if (++*S->work > S->budget)
    return cap;
  for (uint32_t i = S->start[v]; i < S->start[v + 1] && n < cap; i++)
    n += !positive(m, S->tet[i]);
  return n;
}

/* For a point stuck even with a neighbour: the first candidate with the fewest
 * non-positive tets in its star, taken if that is fewer than now. This lowers the global
 * count too (only v's tets change), and gives the neighbours of a cluster of nearly
 * degenerate Steiner points room one after the other. 1 iff v moved. */
static int descend(struct tr_mesh *m, const star_index *S, uint32_t v, const offset *off,
                   size_t noff)
{
  cand_axes ax;
  candidates(m, v, ax);
  double *x = m->xyz + 3 * (size_t)v, was[3];
  memcpy(was, x, sizeof was);
  uint32_t best = star_bad(m, S, v, UINT32_MAX);
  size_t best_c = noff;
  for (size_t c = 0; c < noff && best > 0; c++)
    if (place(m, v, ax, &off[c])) {
      uint32_t n = star_bad(m, S, v, best);
      if (n < best) {
        best = n;
        best_c = c;
      }
    }
  if (best_c == noff) {
    memcpy(x, was, sizeof was);
    return 0;
  }
  place(m, v, ax, &off[best_c]);
  return 1;
}

/* A failed single search or descent of v is a function of the doubles of the vertices
 * of v's star only, so it fails again until one of them moves: stale[v] has bit
 * STALE_SEARCH / STALE_DESCEND set after such a failure, and every move clears both bits
 * on the vertices of the moved point's star. Skipping the repeats changes no outcome
 * (each would fail and move nothing), only the work: without it, every round of single
 * moves searched each stuck point's 35,936 candidates again (Chazelle's polyhedron moved
 * by ulps spent its 2,000,000 checks, 30 s, mostly on such repeats). Pair moves depend
 * on the neighbours' stars too and are not skipped. */
enum { STALE_SEARCH = 1, STALE_DESCEND = 2 };

typedef struct {
  struct tr_mesh *m;
  const star_index *S;
  const offset *off;
  size_t noff, npair;
  uint8_t *stale;
} search_ctx;

static void moved(const search_ctx *c, uint32_t v)
{
  for (uint32_t i = c->S->start[v]; i < c->S->start[v + 1]; i++)
    for (int k = 0; k < 4; k++)
      c->stale[c->m->tv[4 * (size_t)c->S->tet[i] + k]] = 0;
}

/* For a point stuck after the single moves: min-conflicts along one axis over the
 * Steiner points around it. The tets still stuck then are typically slivers of four
 * points of an input facet that is bumpy below double resolution (a face of a box moved
 * by ulps, or by subnormals at 0), its Steiner points packed in layers; the facet is
 * nearly perpendicular to one axis, and along it such a cluster is positive only for a
 * joint placement of its points: moving one alone always flattens a neighbouring sliver
 * (Chazelle's polyhedron moved by ulps ended with one such tet). Each step takes the
 * first tet that is not strictly positive in the stars of the points involved so far and
 * moves one Steiner vertex of it, along the axis on which the first stuck tet is
 * thinnest, to the offset that leaves the fewest non-positive tets in its star, even if
 * not fewer than now (plateau moves make room), never back to an offset left in the last
 * TR_ROUND_TABU steps; ties go to the smallest step, then the lowest vertex and offset,
 * so it is deterministic. After TR_ROUND_CONFLICT_STEPS steps, or when those stars have
 * no non-positive tet left, the moves are kept if the number of non-positive tets
 * dropped, else all undone: like every other move it lowers the count or changes
 * nothing. 1 iff kept. */
#define TR_ROUND_CONFLICT_STEPS 256
#define TR_ROUND_TABU 16
typedef struct {
  uint32_t v;
  double was[3]; /* its doubles before the first move, to undo */
} conflict_pt;

static int axis_offset(const double *row, double x)
{
  for (int s = -TR_ROUND_RADIUS; s <= TR_ROUND_RADIUS; s++)
    if (row[TR_ROUND_RADIUS + s] == x)
      return s;
  return TR_ROUND_RADIUS + 1; /* off the grid along this axis: every offset is a move */
}

static uint32_t first_bad(const struct tr_mesh *m, const star_index *S, const conflict_pt *pt,
                          uint32_t npt)
{
  for (uint32_t i = 0; i < npt; i++)
    for (uint32_t j = S->start[pt[i].v]; j < S->start[pt[i].v + 1]; j++)
      if (!positive(m, S->tet[j]))
        return S->tet[j];
  return TR_NONE;
}

static int conflicts(const search_ctx *c, uint32_t t0)
{
  struct tr_mesh *m = c->m;
  const star_index *S = c->S;
  conflict_pt pt[4 + TR_ROUND_CONFLICT_STEPS];
  uint32_t npt = 0, tabu_v[TR_ROUND_TABU];
  int tabu_o[TR_ROUND_TABU], ntabu = 0, wtabu = 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t0;
  int axis = 0;
  double spread[3], lo[3], hi[3];
  tr_box_of(m->xyz, tv, 4, lo, hi);
  for (int k = 0; k < 3; k++) {
    spread[k] = hi[k] - lo[k];
    if (spread[k] < spread[axis])
      axis = k;
  }
  for (int i = 0; i < 4; i++)
    if (steiner(m, tv[i])) {
      pt[npt].v = tv[i];
      memcpy(pt[npt++].was, m->xyz + 3 * (size_t)tv[i], sizeof pt[0].was);
    }
  long change = 0;
  uint32_t t = t0;
  for (int step = 0; step < TR_ROUND_CONFLICT_STEPS && t != TR_NONE; step++) {
    if (*S->work > S->budget)
      break;
    const uint32_t *bv = m->tv + 4 * (size_t)t;
    long best_d = 0;
    int best_o = 0, best_s = -1, best_i = -1;
    for (int i = 0; i < 4; i++) {
      uint32_t u = bv[i];
      if (!steiner(m, u))
        continue;
      cand_axes ax;
      candidates(m, u, ax);
      double *x = m->xyz + 3 * (size_t)u, cur = x[axis];
      int at = axis_offset(ax[axis], cur);
      long before = star_bad(m, S, u, UINT32_MAX);
      for (int o = -TR_ROUND_RADIUS; o <= TR_ROUND_RADIUS; o++) {
        int is_tabu = o == at;
        for (int k = 0; k < ntabu && !is_tabu; k++)
          is_tabu = tabu_v[k] == u && tabu_o[k] == o;
        if (is_tabu || !isfinite(ax[axis][TR_ROUND_RADIUS + o]))
          continue;
        x[axis] = ax[axis][TR_ROUND_RADIUS + o];
        long d = (long)star_bad(m, S, u, UINT32_MAX) - before;
        int dist = abs(o - at);
        if (best_i < 0 || d < best_d || (d == best_d && dist < best_s) ||
            (d == best_d && dist == best_s && u < bv[best_i])) {
          best_d = d;
          best_o = o;
          best_s = dist;
          best_i = i;
        }
      }
      x[axis] = cur;
    }
    if (best_i < 0)
      break;
    uint32_t u = bv[best_i];
    cand_axes ax;
    candidates(m, u, ax);
    double *x = m->xyz + 3 * (size_t)u;
    tabu_v[wtabu % TR_ROUND_TABU] = u;
    tabu_o[wtabu++ % TR_ROUND_TABU] = axis_offset(ax[axis], x[axis]);
    ntabu = wtabu < TR_ROUND_TABU ? wtabu : TR_ROUND_TABU;
    uint32_t k = 0;
    while (k < npt && pt[k].v != u)
      k++;
    if (k == npt) {
      pt[npt].v = u;
      memcpy(pt[npt++].was, x, sizeof pt[0].was);
    }
    x[axis] = ax[axis][TR_ROUND_RADIUS + best_o];
    change += best_d;
    t = first_bad(m, S, pt, npt);
  }
  if (change < 0 && *S->work <= S->budget) {
    for (uint32_t i = 0; i < npt; i++)
      moved(c, pt[i].v);
    return 1;
  }
  for (uint32_t i = 0; i < npt; i++)
    memcpy(m->xyz + 3 * (size_t)pt[i].v, pt[i].was, sizeof pt[0].was);
  return 0;
}

/* The kinds of move of a round, in the order they are tried (see round.h). */
enum { MOVE_SINGLE, MOVE_CONFLICTS, MOVE_PAIR, MOVE_DESCEND };

/* One pass over the Steiner points in index order, moving each whose star has a tet that
 * is not strictly positive by one kind of move. Returns whether something moved;
 * *fail_v, *fail_t = the first point left stuck and its bad tet. */
static int one_round(const search_ctx *c, int kind, uint32_t *fail_v, uint32_t *fail_t)
{
  int progress = 0;
  *fail_v = *fail_t = TR_NONE;
  for (uint32_t v = 0; v < c->m->nv; v++) {
    uint32_t hint = 0, t;
    if (!steiner(c->m, v) || (t = star_failure(c->m, c->S, v, TR_NONE, &hint)) == TR_NONE)
      continue;
    uint8_t bit = kind == MOVE_DESCEND ? STALE_DESCEND : kind == MOVE_SINGLE ? STALE_SEARCH : 0;
    uint32_t w = TR_NONE;
    if (!(c->stale[v] & bit) &&
        (kind == MOVE_CONFLICTS ? conflicts(c, t)
         : kind == MOVE_DESCEND ? descend(c->m, c->S, v, c->off, c->noff)
         : kind == MOVE_PAIR    ? search_pair(c->m, c->S, v, c->off, c->npair, &w)
                                : search(c->m, c->S, v, c->off, c->noff))) {
      progress = 1;
      moved(c, v); /* conflicts() also clears the other points it moved */
      if (w != TR_NONE)
        moved(c, w);
      continue;
    }
    c->stale[v] |= bit;
    if (*fail_v == TR_NONE) {
      *fail_v = v;
      *fail_t = t;
    }
  }
  return progress;
}

static int off_nearest(const struct tr_mesh *m, uint32_t v)
{
  return memcmp(m->xyz + 3 * (size_t)v, m->vq[v]->near, 3 * sizeof(double)) != 0;
}

/* Each Steiner point off its nearest double (refinement admitted it next to it) goes back
 * to it where its whole star is strictly positive there, in index order: it was kept off
 * for tets refinement replaced since, or for neighbours that went back before it. Only
 * v's tets change and all end positive, so no tet becomes flat. */
static void back_to_nearest(struct tr_mesh *m, const star_index *S)
{
  for (uint32_t v = 0; v < m->nv; v++) {
    if (!steiner(m, v) || !off_nearest(m, v))
      continue;
    double *x = m->xyz + 3 * (size_t)v, was[3];
    memcpy(was, x, sizeof was);
    memcpy(x, m->vq[v]->near, sizeof was);
    uint32_t hint = 0;
    if (star_failure(m, S, v, TR_NONE, &hint) != TR_NONE)
      memcpy(x, was, sizeof was);
  }
}

/* Why tet tv may have no double position, when a plain reason exists: two of its
 * vertices are distinct exact points with the same nearest double (no rounding to the
 * nearest can separate them, and moving one by ulps leaves the tet thinner than an ulp). */
static void explain(const struct tr_mesh *m, const uint32_t *tv, char *buf, size_t n)
{
  buf[0] = '\0';
  for (int i = 0; i < 4; i++)
    for (int j = i + 1; j < 4; j++) {
      const tr_qpoint *a = m->vq ? m->vq[tv[i]] : NULL, *b = m->vq ? m->vq[tv[j]] : NULL;
      const double *na = a ? a->near : m->xyz + 3 * (size_t)tv[i],
                   *nb = b ? b->near : m->xyz + 3 * (size_t)tv[j];
      if ((a || b) && memcmp(na, nb, 3 * sizeof(double)) == 0) {
        snprintf(buf, n, "; vertices %u and %u are distinct exact points with the same "
                 "nearest double", tv[i], tv[j]);
        return;
      }
    }
}

tr_status tr_round_steiner(struct tr_mesh *m, uint64_t budget, uint64_t *repaired)
{
  *repaired = 0;
  if (!m->vq)
    return TR_OK;
  /* Start from the doubles in xyz (round.h): a point refinement admitted off its nearest
   * double stays there unless its star allows the nearest, since the points after it
   * were admitted against it there; starting from the nearest doubles instead, the moves
   * those points need conflict (stlcutters 1452677.stl under --quality). */
  int admitted_off = 0;
  for (uint32_t v = 0; v < m->nv && !admitted_off; v++)
    admitted_off = steiner(m, v) && off_nearest(m, v);
  uint64_t nbad = tr_round_count_nonpositive(m, NULL);
  if (!admitted_off && nbad == 0)
    return TR_OK;
  uint64_t work = 0;
  star_index S = {NULL, NULL, &work, budget ? budget : TR_ROUND_BUDGET};
  search_ctx c = {m, &S, NULL, 0, 0, calloc(m->nv ? m->nv : 1, 1)};
  offset *off = NULL;
  tr_status st = c.stale ? stars_build(m, &S)
                         : tr_error(TR_ERR_NOMEM, "out of memory for the rounding search");
  if (st == TR_OK && admitted_off)
    back_to_nearest(m, &S);
  if (st == TR_OK && nbad)
    st = offsets_build(&off, &c.noff);
  c.off = off;
  while (c.npair < c.noff && offset_norm(&off[c.npair]) <= TR_ROUND_PAIR_RADIUS2)
    c.npair++;
  uint32_t fail_v = TR_NONE, fail_t = TR_NONE;
  /* Single moves until a round moves nothing; then, if points are stuck, one round of
   * the first other kind of move that helps (min-conflicts, pairs, descent: cheapest
   * first, Chazelle moved by ulps spent 400,000 checks on pairs and 100,000 on the
   * descent before one min-conflicts round of 543 freed it), then single moves again. */
  while (st == TR_OK && nbad) {
    while (one_round(&c, MOVE_SINGLE, &fail_v, &fail_t))
      ;
    if (fail_v == TR_NONE)
      break;
    if (!one_round(&c, MOVE_CONFLICTS, &fail_v, &fail_t) &&
        !one_round(&c, MOVE_PAIR, &fail_v, &fail_t) &&
        !one_round(&c, MOVE_DESCEND, &fail_v, &fail_t))
      break;
  }
  for (uint32_t v = 0; v < m->nv; v++)
    *repaired += steiner(m, v) && off_nearest(m, v);
  if (st == TR_OK && work > S.budget) {
    uint32_t bad = TR_NONE;
    uint64_t left = tr_round_count_nonpositive(m, &bad);
    if (left > 0) {
      const uint32_t *tv = m->tv + 4 * (size_t)bad;
      char why[160];
      explain(m, tv, why, sizeof why);
      st = tr_error(TR_ERR_INVALID_MESH,
                    "rounding Steiner points to doubles: %llu tets stay flat or inverted (the "
                    "first: tet %u (%u %u %u %u) near (%.17g, %.17g, %.17g)%s) after %llu star "
                    "checks, the repair's budget; the exact mesh is valid: write it with "
                    "--exact to a .node file (tr_options.keep_exact)",
                    (unsigned long long)left, bad, tv[0], tv[1], tv[2], tv[3],
                    m->xyz[3 * (size_t)tv[0]], m->xyz[3 * (size_t)tv[0] + 1],
                    m->xyz[3 * (size_t)tv[0] + 2], why, (unsigned long long)S.budget);
    }
  } else if (st == TR_OK && fail_v != TR_NONE) {
    const double *x = m->vq[fail_v]->near;
    const uint32_t *tv = m->tv + 4 * (size_t)fail_t;
    st = tr_error(TR_ERR_INVALID_MESH,
                  "Steiner point %u near (%.17g, %.17g, %.17g): no double point within %d "
                  "ulps per axis keeps its %u tets strictly positive (tet %u (%u %u %u %u) "
                  "stays flat or inverted); the exact mesh is valid: write it with --exact to a "
                  ".node file (tr_options.keep_exact)",
                  fail_v, x[0], x[1], x[2], TR_ROUND_RADIUS,
                  S.start[fail_v + 1] - S.start[fail_v], fail_t, tv[0], tv[1], tv[2], tv[3]);
  }
  free(c.stale);
  free(off);
  free(S.start);
  free(S.tet);
  return st;
}
