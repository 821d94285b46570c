/* Facet recovery by flips (see flipfacet.h). Candidates are listed by vertex ids in
 * Cluster order (sorted by tet index: deterministic) and checked again before use, since
 * an undo may put tets in other slots. A candidate whose attempt was undone is skipped
 * until a round finds nothing among the others; then all are tried again. Retrying every
 * failed candidate after each kept attempt made the search quadratic in the cluster
 * (Chazelle's polyhedron with 8 grooves: 132k flips made and undone, 1.2 s). Every round
 * either lowers the number of crossing clusterels (a natural number) or ends the loop at
 * the latest one round after it retried everything. */
#include "recover_facets/flipfacet.h"

#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "recover_facets/cluster.h"

/* Recursion depth of edge removal (flip.h, tr_flip_remove_edge_nm). */
#define TR_FLIPFACET_DEPTH 3

typedef struct fcand {
  uint32_t t;
  uint32_t v[3]; /* edge: v[2] = TR_NONE */
  int k;         /* face code in t */
} fcand;

static tr_status push(fcand **a, uint32_t *n, uint32_t *cap, tr_sxset *seen, const fcand *c)
{
  int added = tr_sxset_add(seen, c->v);
  if (added < 0)
    return TR_ERR_NOMEM;
  if (!added)
    return TR_OK;
  if (*n == *cap) {
    uint32_t nc = *cap ? 2 * *cap : 32;
    fcand *q = realloc(*a, nc * sizeof *q);
    if (!q)
      return tr_error(TR_ERR_NOMEM, "out of memory for facet flip candidates");
    *a = q;
    *cap = nc;
  }
  (*a)[(*n)++] = *c;
  return TR_OK;
}

/* Edges first (edge removal takes a crossing edge away directly), then the faces with two
 * crossed edges (Swap23 there replaces them by the edge between the apexes). */
static tr_status list(const struct tr_mesh *m, const tr_clusterel *cl, uint32_t ncl,
                      fcand **a, uint32_t *n, uint32_t *cap, tr_sxset *seen, uint32_t *ncross)
{
  *n = 0;
  tr_sxset_clear(seen);
  *ncross = 0;
  for (int pass = 0; pass < 2; pass++)
    for (uint32_t i = 0; i < ncl; i++) {
      if (cl[i].type == TR_CO_PLAN)
        continue;
      *ncross += pass == 0;
      const uint32_t *tv = m->tv + 4 * (size_t)cl[i].iele;
      uint8_t infc[4] = {0, 0, 0, 0}; /* per face: crossed edges on it */
      for (int j = 0; j < cl[i].nnodes; j++) {
        if (cl[i].ntypes[j] != TR_NOD_MID)
          continue;
        int s0 = tr_ecode_start(cl[i].codes[j]), s1 = tr_ecode_end(cl[i].codes[j]);
        for (int k = 0; k < 4; k++)
          infc[k] += k != s0 && k != s1;
        if (pass == 0) {
          fcand c = {cl[i].iele, {tv[s0], tv[s1], TR_NONE}, -1};
          TR_CHECK(push(a, n, cap, seen, &c));
        }
      }
      for (int k = 0; pass == 1 && k < 4; k++) {
        if (infc[k] != 2)
          continue;
        fcand c = {cl[i].iele, {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]],
                                tv[tr_face_vtx[k][2]]}, k};
        TR_CHECK(push(a, n, cap, seen, &c));
      }
    }
  return TR_OK;
}

/* Memo of exact results for one facet: the measure is evaluated on the same vertices and
 * edges over and over (every flip made and undone re-measures the old and new tets), and
 * the points never move during flips, so each answer is computed once. Keys: a vertex v
 * as v + 1 (high word 0), an edge {x < y} as (x + 1) << 32 | y (high word nonzero). Open
 * addressing, linear probing, key 0 = empty. On allocation failure the memo is skipped. */
typedef struct memo {
  uint64_t *key;
  int8_t *val;
  uint32_t cap, n; /* cap: 0 or a power of two */
} memo;

static uint32_t memo_slot(const memo *h, uint64_t k)
{
  uint64_t x = k * 0x9E3779B97F4A7C15ull;
  uint32_t i = (uint32_t)(x >> 32) & (h->cap - 1);
  while (h->key[i] && h->key[i] != k)
    i = (i + 1) & (h->cap - 1);
  return i;
}

static int memo_get(const memo *h, uint64_t k, int *v)
{
  if (!h->cap)
    return 0;
  uint32_t i = memo_slot(h, k);
  if (!h->key[i])
    return 0;
  *v = h->val[i];
  return 1;
}

static void memo_put(memo *h, uint64_t k, int v)
{
  if (2 * (h->n + 1) > h->cap) {
    uint32_t nc = h->cap ? 2 * h->cap : 256;
    memo g = {calloc(nc, sizeof *g.key), malloc(nc * sizeof *g.val), nc, 0};
    if (!g.key || !g.val) {
      free(g.key);
      free(g.val);
      return;
    }
    for (uint32_t i = 0; i < h->cap; i++)
      if (h->key[i]) {
        uint32_t j = memo_slot(&g, h->key[i]);
        g.key[j] = h->key[i];
        g.val[j] = h->val[i];
        g.n++;
      }
    free(h->key);
    free(h->val);
    *h = g;
  }
  uint32_t i = memo_slot(h, k);
  if (!h->key[i]) {
    h->key[i] = k;
    h->n++;
  }
  h->val[i] = (int8_t)v;
}

static void memo_free(memo *h)
{
  free(h->key);
  free(h->val);
  memset(h, 0, sizeof *h);
}

typedef struct tri {
  tr_point e, f, g;
  memo side; /* vertex: side of plane efg; edge: 1 iff it crosses the open triangle */
} tri;

static int o3(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d)
{
  return tr_orient3d_p(a, b, c, d);
}

static int vertex_side(tri *T, const struct tr_mesh *m, uint32_t v)
{
  int s;
  uint64_t k = (uint64_t)v + 1;
  if (memo_get(&T->side, k, &s))
    return s;
  tr_point p = tr_mesh_point(m, v);
  s = o3(&T->e, &T->f, &T->g, &p);
  memo_put(&T->side, k, s);
  return s;
}

/* Edge xy with ends strictly on both sides: does its line pass strictly inside the three
 * sides? Symmetric in x, y (swapping them flips all three signs). */
static int edge_crosses(tri *T, const struct tr_mesh *m, uint32_t x, uint32_t y)
{
  if (x > y) {
    uint32_t t = x;
    x = y;
    y = t;
  }
  int r;
  uint64_t k = ((uint64_t)x + 1) << 32 | y;
  if (memo_get(&T->side, k, &r))
    return r;
  tr_point px = tr_mesh_point(m, x), py = tr_mesh_point(m, y);
  int s1 = o3(&px, &py, &T->e, &T->f), s2 = o3(&px, &py, &T->f, &T->g),
      s3 = o3(&px, &py, &T->g, &T->e);
  r = s1 != 0 && s1 == s2 && s2 == s3;
  memo_put(&T->side, k, r);
  return r;
}

/* 1 iff the tet with vertices v has an edge crossing the open triangle at an interior
 * point of the edge (a crossing clusterel, cluster.h): its ends strictly on both sides of
 * the plane and the line through it strictly inside the three sides. */
static int crossing_measure(void *ud, const struct tr_mesh *m, const uint32_t v[4])
{
  tri *T = ud;
  if (v[3] == TR_GHOST)
    return 0;
  int side[4];
  for (int k = 0; k < 4; k++)
    side[k] = vertex_side(T, m, v[k]);
  for (int i = 0; i < 6; i++) {
    int x = tr_edge_vtx[i][0], y = tr_edge_vtx[i][1];
    if (side[x] * side[y] >= 0)
      continue;
    if (edge_crosses(T, m, v[x], v[y]))
      return 1;
  }
  return 0;
}

tr_status tr_facet_try_flips(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                             tr_flip_guard guard, void *ud, tr_facet_flip_stats *st,
                             int *changed, int *clear)
{
  *changed = 0;
  *clear = 0;
  tri T = {tr_mesh_point(m, e), tr_mesh_point(m, f), tr_mesh_point(m, g), {0}};
  tr_clusterel *cl = NULL;
  uint32_t ncl = 0, n = 0, cap = 0, ncross = 0;
  fcand *cs = NULL;
  tr_sxset seen = {0}, failed = {0};
  tr_cluster_memo cm;
  memset(&cm, 0, sizeof cm);
  tr_flip_journal j;
  memset(&j, 0, sizeof j);
  j.measure = crossing_measure;
  j.mud = &T;
  tr_status s = TR_OK;
  for (int progress = 1, skipped = 0; (progress || skipped) && s == TR_OK;) {
    if (!progress)
      tr_sxset_clear(&failed); /* stuck on the fresh candidates: retry the failed ones */
    progress = 0;
    skipped = 0;
    free(cl);
    cl = NULL;
    if ((s = tr_cluster_collect_memo(m, e, f, g, &cl, &ncl, &cm)) != TR_OK ||
        (s = list(m, cl, ncl, &cs, &n, &cap, &seen, &ncross)) != TR_OK)
      break;
    if (ncross == 0) {
      *clear = 1;
      break;
    }
    for (uint32_t i = 0; i < n && !progress && s == TR_OK; i++) {
      const fcand *c = &cs[i];
      if (tr_sxset_has(&failed, c->v)) {
        skipped = 1;
        continue;
      }
      int ok = 0;
      if (c->v[2] != TR_NONE) {
        if (!tr_tet_is_free(m, c->t) && tr_fcode(m, c->t, c->v[0], c->v[1], c->v[2]) == c->k)
          s = tr_flip23_j(m, c->t, c->k, guard, ud, &j, &ok);
      } else {
        uint32_t t0 = c->t;
        if (tr_tet_is_free(m, t0) || tr_tet_ecode(m, t0, c->v[0], c->v[1]) < 0)
          t0 = TR_NONE;
        s = tr_flip_remove_edge_nm(m, c->v[0], c->v[1], t0, TR_FLIPFACET_DEPTH, guard, ud, &j,
                                   &ok);
      }
      if (s != TR_OK)
        break;
      if (j.n && j.delta < 0) {
        *changed = 1;
        progress = 1;
        if (st) {
          st->flip23 += j.flips[0];
          st->flip32 += j.flips[1];
          st->flip44 += j.flips[2];
          st->flipn += j.flips[3] + j.flips[4];
        }
        memset(j.flips, 0, sizeof j.flips);
        j.n = 0;
        j.delta = 0;
        break;
      }
      if (st)
        st->undone += j.n;
      /* an undo may put the old tets in other slots: the caller's cluster is stale */
      *changed |= j.n > 0;
      if ((s = tr_flip_journal_undo(m, &j, 0)) == TR_OK && tr_sxset_add(&failed, c->v) < 0)
        s = TR_ERR_NOMEM;
    }
  }
  tr_flip_journal_free(&j);
  tr_sxset_free(&seen);
  tr_sxset_free(&failed);
  tr_cluster_memo_free(&cm);
  memo_free(&T.side);
  free(cl);
  free(cs);
  return s;
}
