/* Removal of an interior Steiner point by flips (issue 16), for the points the cone from
 * a star vertex cannot take out (their star is not visible from any one of its vertices).
 *
 * The link of an interior point p is a triangulated sphere; with V link vertices, p has
 * 2V - 4 tets. Removing an edge pq (edge removal n -> 2n-4 of flip.h, the shell of pq
 * being the tets on p and q) takes q out of the link: p then has 2 tets fewer. At V = 4
 * the four tets of p fill the tet of its link and a 4-1 flip replaces them: p is gone.
 * An edge pq that cannot be removed as it is may become removable after Swap23 on the
 * faces (p, q, r) of its shell (tr_flip_remove_edge_nm, depth 2). The edges are tried in
 * the order of their shell size, then vertex id (deterministic).
 *
 * Only simplices on p are ever deleted (the guard refuses the others): the link, and so
 * every constraint face and edge around p, stays as it is, and all the flips stay inside
 * p's star. A tet without p, once made, is never deleted again, so the journal's measure
 * (1 for a made tet without p that is not positive with its vertices at their doubles)
 * counts exactly the new tets that rounding would have to repair; with dbl, an edge
 * removal that makes one is undone and the next edge is tried. Every new tet is exactly
 * positive (flip.h checks each). If p cannot be brought down to four tets, every flip
 * is undone and p stays. */
#include <stdlib.h>
#include <string.h>

#include "recover_edges/flip.h"
#include "suppress_int.h"

/* the depth of the flipnm recursion and the cap on edge removals per point (each removal
 * takes one link vertex out, so a star of V link vertices needs V - 4) */
#define SUP_FLIP_DEPTH 2
#define SUP_FLIP_MAX_LINK 96

static int p_guard(void *ud, const uint32_t *v, int nv)
{
  uint32_t p = *(const uint32_t *)ud;
  for (int i = 0; i < nv; i++)
    if (v[i] == p)
      return 0;
  return 1;
}

typedef struct measure_ud {
  uint32_t p;
} measure_ud;

static int dbl_positive(const struct tr_mesh *m, const uint32_t v[4])
{
  tr_point q[4];
  for (int k = 0; k < 4; k++)
    q[k] = tr_pt_d(m->xyz + 3 * (size_t)v[k]);
  return tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0;
}

static int flat_in_doubles(void *ud, const struct tr_mesh *m, const uint32_t v[4])
{
  uint32_t p = ((const measure_ud *)ud)->p;
  for (int k = 0; k < 4; k++)
    if (v[k] == p || v[k] == TR_GHOST)
      return 0;
  return !dbl_positive(m, v);
}

typedef struct link_vtx {
  uint32_t v, deg; /* link vertex, number of p's tets on it (the shell size of pv) */
} link_vtx;

static int cmp_link(const void *pa, const void *pb)
{
  const link_vtx *a = pa, *b = pb;
  if (a->deg != b->deg)
    return a->deg < b->deg ? -1 : 1;
  return a->v < b->v ? -1 : a->v > b->v;
}

/* the slots of link_of's table by vertex id: a power of two, over twice the most link
 * vertices, so that a probe run stays short */
#define SUP_LINK_SLOTS 256
_Static_assert(SUP_LINK_SLOTS >= 2 * SUP_FLIP_MAX_LINK && SUP_FLIP_MAX_LINK < 256,
               "link_of's table: short probe runs, lk indices in a byte");

/* The link vertices of p from its ball, each once, with their degrees, in the order of
 * first sight (cmp_link then orders them totally). A vertex is found through a table
 * of lk's indices by vertex id: a linear search of lk for each of the ball's 4n
 * vertices was 9% of suppression's instructions on 65395.stl --keep-surface, where every
 * pass retries the flips of the interior points that stay. */
static tr_status link_of(const struct tr_mesh *m, uint32_t p, const tr_u32buf *ball,
                         link_vtx *lk, uint32_t *n, int *ok)
{
  uint8_t slot[SUP_LINK_SLOTS]; /* 1 + index into lk, 0: empty */
  memset(slot, 0, sizeof slot);
  *n = 0;
  *ok = 1;
  for (size_t i = 0; i < ball->n && *ok; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    for (int k = 0; k < 4; k++) {
      uint32_t v = tv[k], h = (v * 2654435761u) >> 24;
      if (v == p)
        continue;
      while (slot[h] && lk[slot[h] - 1].v != v)
        h = (h + 1) & (SUP_LINK_SLOTS - 1);
      if (!slot[h]) {
        if (*n == SUP_FLIP_MAX_LINK) {
          *ok = 0;
          break;
        }
        lk[*n].v = v;
        lk[*n].deg = 0;
        slot[h] = (uint8_t)++*n;
      }
      lk[slot[h] - 1].deg++;
    }
  }
  return TR_OK;
}

/* The region of the new tets: the flips reuse slots, which keep the region they held, and
 * an undo may move a tet to another slot, so the tets that now fill p's old star are
 * found from the last one through the faces that are not on its boundary (link). */
static tr_status paint(struct tr_mesh *m, uint32_t t0, const tr_sxset *link, uint32_t region)
{
  tr_u32buf todo = {0};
  tr_status st = tr_u32buf_push(&todo, t0);
  m->region[t0] = region;
  m->flags[t0] |= TR_TF_MARK;
  for (size_t i = 0; i < todo.n && st == TR_OK; i++) {
    uint32_t t = todo.a[i];
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      uint32_t w[3], nb = m->tn[4 * (size_t)t + k];
      for (int a = 0; a < 3; a++)
        w[a] = m->tv[4 * (size_t)t + tr_face_vtx[k][a]];
      if (nb == TR_NONE || tr_sxset_has(link, w) || (m->flags[nb >> 2] & TR_TF_MARK))
        continue;
      m->region[nb >> 2] = region;
      m->flags[nb >> 2] |= TR_TF_MARK;
      st = tr_u32buf_push(&todo, nb >> 2);
    }
  }
  for (size_t i = 0; i < todo.n; i++)
    m->flags[todo.a[i]] &= (uint8_t)~TR_TF_MARK;
  tr_u32buf_free(&todo);
  return st;
}

tr_status sup_flip_out(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t region,
                       int dbl, int *done)
{
  *done = 0;
  tr_u32buf ball = {0};
  link_vtx *lk = malloc(sizeof *lk * SUP_FLIP_MAX_LINK);
  measure_ud mu = {p};
  tr_flip_journal j = {0};
  j.measure = flat_in_doubles;
  j.mud = &mu;
  tr_status st = lk ? TR_OK : tr_error(TR_ERR_NOMEM, "out of memory removing a point");
  int stuck = 0;
  uint32_t nl = 0;
  tr_sxset link = {0};
  /* p's link faces, the boundary of the region the flips retriangulate */
  if (st == TR_OK)
    st = tr_ball(m, p, 1, &ball);
  for (size_t i = 0; i < ball.n && st == TR_OK; i++) {
    uint32_t t = ball.a[i], w[3];
    int k = tr_ncode(m, t, p);
    for (int a = 0; a < 3; a++)
      w[a] = m->tv[4 * (size_t)t + tr_face_vtx[k][a]];
    if (tr_sxset_add(&link, w) < 0)
      st = TR_ERR_NOMEM;
  }
  while (st == TR_OK && !stuck) {
    int ok = 0;
    if ((st = tr_ball(m, p, 1, &ball)) != TR_OK)
      break;
    if ((st = link_of(m, p, &ball, lk, &nl, &ok)) != TR_OK)
      break;
    for (size_t i = 0; i < ball.n && ok; i++)
      ok = tr_tet_is_real(m, ball.a[i]);
    if (!ok || ball.n == 4) {
      stuck = !ok;
      break;
    }
    qsort(lk, nl, sizeof *lk, cmp_link);
    int gone = 0;
    for (uint32_t i = 0; i < nl && !gone && st == TR_OK; i++) {
      uint32_t n0 = j.n;
      long d0 = j.delta;
      st = tr_flip_remove_edge_nm(m, p, lk[i].v, TR_NONE, SUP_FLIP_DEPTH, p_guard, &mu.p,
                                  &j, &gone);
      if (st == TR_OK && (!gone || (dbl && j.delta > d0))) {
        gone = 0;
        st = tr_flip_journal_undo(m, &j, n0);
      }
    }
    stuck = !gone;
  }
  /* Stuck above four tets: the smaller star may be retriangulable without p, expanded
   * like the whole star's (star.c). Its tets are painted first, while the link still
   * bounds them (the flips reuse slots of other regions); the retriangulation paints its
   * own, and the tets it expands over are of p's region. */
  uint32_t tf = TR_NONE;
  int filled = 0;
  if (st == TR_OK && stuck && j.n && (st = tr_ball(m, p, 1, &ball)) == TR_OK) {
    /* The passes retry p while anything changed anywhere, and its flips get stuck on
     * the same smaller star again: its retriangulation (the costliest part, a local
     * Delaunay mesh) would fail the same way, as the whole star's would (star.c). */
    uint64_t key = c && c->ftried ? sup_star_key(m, p, &ball, (unsigned)dbl) : 0;
    if (m->region && ball.n)
      st = paint(m, ball.a[0], &link, region);
    int by_dbl = 1;
    if (st == TR_OK && (!key || c->ftried[2 * (size_t)p + (dbl != 0)] != key))
      st = sup_star_fill(m, c, p, region, dbl, SUP_FILL_EXPAND, &tf, &filled, &by_dbl);
    if (st == TR_OK && filled)
      *done = 1;
    else if (st == TR_OK && key) {
      c->ftried[2 * (size_t)p + (dbl != 0)] = key;
      /* refused whatever dbl: the same star at dbl = 0 would redo it */
      if (dbl && !by_dbl)
        c->ftried[2 * (size_t)p] = sup_star_key(m, p, &ball, 0);
    }
  }
  /* the 4-1 flip: the vertex of the link that t0 lacks takes p's place in t0 */
  uint32_t nv[4] = {0, 0, 0, 0};
  if (st == TR_OK && !stuck && ball.n == 4 && nl == 4) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball.a[0];
    uint32_t d = TR_NONE;
    for (uint32_t i = 0; i < nl; i++)
      if (tv[0] != lk[i].v && tv[1] != lk[i].v && tv[2] != lk[i].v && tv[3] != lk[i].v)
        d = lk[i].v;
    for (int k = 0; k < 4; k++)
      nv[k] = tv[k] == p ? d : tv[k];
    tr_point q[4];
    for (int k = 0; k < 4; k++)
      q[k] = tr_mesh_point(m, nv[k]);
    stuck = d == TR_NONE || tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) <= 0 ||
            (dbl && !dbl_positive(m, nv));
  } else {
    stuck = 1;
  }
  uint32_t id = TR_NONE;
  if (st == TR_OK && !stuck)
    st = tr_mesh_replace(m, ball.a, 4, nv, 1, &id);
  if (st == TR_OK && !stuck) {
    m->v2t[p] = TR_NONE;
    if (m->region)
      st = paint(m, id, &link, region);
    *done = 1;
  } else if (st == TR_OK && j.n && !filled) {
    /* the undo too puts tets into slots of other regions */
    st = tr_flip_journal_undo(m, &j, 0);
    if (st == TR_OK)
      st = tr_ball(m, p, 1, &ball);
    if (st == TR_OK && m->region && ball.n)
      st = paint(m, ball.a[0], &link, region);
  }
  tr_flip_journal_free(&j);
  tr_sxset_free(&link);
  tr_u32buf_free(&ball);
  free(lk);
  return st;
}
