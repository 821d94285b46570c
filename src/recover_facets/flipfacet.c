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

/* The facet's points and its cluster memo, which the measure shares with the cluster
 * collection: every flip made and undone re-measures the old and new tets, and the
 * points never move during flips, so each exact answer is computed once. */
typedef struct tri {
  tr_point e, f, g;
  tr_cluster_memo cm;
} tri;

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
    side[k] = tr_cluster_side(m, v[k], &T->e, &T->f, &T->g, &T->cm);
  for (int i = 0; i < 6; i++) {
    int x = tr_edge_vtx[i][0], y = tr_edge_vtx[i][1];
    if (side[x] * side[y] >= 0)
      continue;
    if (tr_cluster_crossing(m, v[x], v[y], &T->e, &T->f, &T->g, &T->cm) == 1)
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
  tri T;
  memset(&T, 0, sizeof T);
  T.e = tr_mesh_point(m, e);
  T.f = tr_mesh_point(m, f);
  T.g = tr_mesh_point(m, g);
  tr_clusterel *cl = NULL;
  uint32_t ncl = 0, n = 0, cap = 0, ncross = 0;
  fcand *cs = NULL;
  tr_sxset seen = {0}, failed = {0};
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
    if ((s = tr_cluster_collect_memo(m, e, f, g, &cl, &ncl, &T.cm)) != TR_OK ||
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
  tr_cluster_memo_free(&T.cm);
  free(cl);
  free(cs);
  return s;
}
