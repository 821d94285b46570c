/* Cluster(F) collection and clusterel classification (see cluster.h). Every decision is
 * an exact orientation sign; nothing is constructed here. */
#include "recover_facets/cluster.h"

#include <stdlib.h>
#include <string.h>

#include "classify.h"

/* Where the crossing point of edge uv (u, v strictly on opposite sides of the plane efg)
 * lies: 1 inside the open triangle, 0 outside the closed triangle, -1 on its boundary.
 * The point is inside iff it is on the same side of the three planes through uv and
 * an edge of efg. */
static int crossing_in_triangle(const tr_point *u, const tr_point *v, const tr_point *e,
                                const tr_point *f, const tr_point *g)
{
  int o1 = tr_orient3d_p(u, v, e, f);
  int o2 = tr_orient3d_p(u, v, f, g);
  int o3 = tr_orient3d_p(u, v, g, e);
  if ((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0))
    return 0;
  if (o1 == 0 || o2 == 0 || o3 == 0)
    return -1;
  return 1;
}

static int in_closed_triangle(const tr_point *p, const tr_point *e, const tr_point *f,
                              const tr_point *g)
{
  return tr_classify_point_triangle(p, e, f, g).type != TR_DEG;
}

/* Per-collection memo of each vertex's side of the plane and, for vertices on it,
 * whether it lies in the closed triangle. A vertex is shared by ~20 tets of the search
 * and the on-plane answers (the facet's own boundary vertices, often rational Steiner
 * points) always need the exact evaluation, so this removes most of the exact work. */

/* Memo of crossing_in_triangle by edge {u, v} (the answer is symmetric in u, v: swapping
 * them negates all three signs), stored as w + 1: the facet flip driver collects the
 * cluster again after every kept flip, and most edges are unchanged. When the map cannot
 * grow the answer is just not kept (the memo only saves work). */
static int crossing_memo(tr_cluster_memo *c, uint32_t u, uint32_t v, const tr_point *pu,
                         const tr_point *pv, const tr_point *e, const tr_point *f,
                         const tr_point *g)
{
  if (!c)
    return crossing_in_triangle(pu, pv, e, f, g);
  uint32_t k = tr_edgeset_get(&c->e, u, v);
  if (k != TR_EDGESET_NONE)
    return (int)k - 1;
  int w = crossing_in_triangle(pu, pv, e, f, g);
  (void)tr_edgeset_put(&c->e, u, v, (uint32_t)(w + 1));
  return w;
}

/* Side of vertex v (point p) and, on the plane, membership in the closed triangle. */
static tr_status vertex_side(tr_vtmap *c, uint32_t v, const tr_point *p, const tr_point *e,
                             const tr_point *f, const tr_point *g, int *side, int *in)
{
  uint32_t r = c ? tr_vtmap_get(c, 1, &v) : TR_VTMAP_NONE;
  if (r != TR_VTMAP_NONE) {
    *side = (int)(r & 3) - 1;
    *in = (int)(r >> 2);
    return TR_OK;
  }
  if (tr_pt_same(p, e) || tr_pt_same(p, f) || tr_pt_same(p, g)) {
    /* a corner of the facet: an exact zero costs the most */
    *side = 0;
    *in = 1;
  } else {
    *side = tr_orient3d_p(e, f, g, p);
    *in = *side == 0 && in_closed_triangle(p, e, f, g);
  }
  return c ? tr_vtmap_put(c, 1, &v, (uint32_t)((*side + 1) | (*in << 2)), NULL) : TR_OK;
}

/* Classification plus the "touches the closed triangle" answer the search needs. */
static tr_status classify(const struct tr_mesh *m, uint32_t t, const tr_point *e,
                          const tr_point *f, const tr_point *g, tr_clusterel *out,
                          int *member, int *touch, tr_cluster_memo *mc, int s[4])
{
  tr_vtmap *vc = mc ? &mc->v : NULL;
  tr_point p[4];
  int n0 = 0, nin = 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  *member = 0;
  *touch = 0;
  for (int k = 0; k < 4; k++) {
    p[k] = tr_mesh_point(m, tv[k]);
    int in;
    TR_CHECK(vertex_side(vc, tv[k], &p[k], e, f, g, &s[k], &in));
    if (s[k] == 0) {
      n0++;
      if (in) {
        nin++;
        *touch = 1;
      }
    }
  }
  if (n0 == 4)
    return tr_error(TR_ERR_INVALID_MESH, "cluster: tet %u is flat", t);
  memset(out, 0, sizeof *out); /* padding too: results compare bytewise */
  out->iele = t;
  out->face = -1;
  for (int i = 0; i < 4; i++)
    out->nodes[i] = TR_NONE;
  if (n0 == 3) {
    if (nin == 3) {
      out->type = TR_CO_PLAN;
      for (int k = 0; k < 4; k++)
        if (s[k] != 0)
          out->face = (int8_t)k;
      *member = 1;
    }
    return TR_OK;
  }
  int ncross_in = 0, ncross_out = 0;
  for (int a = 0; a < 4; a++)
    for (int b = a + 1; b < 4; b++) {
      if (s[a] * s[b] >= 0)
        continue;
      int w = crossing_memo(mc, tv[a], tv[b], &p[a], &p[b], e, f, g);
      if (w < 0)
        return tr_error(TR_ERR_INVALID_MESH,
                        "cluster: edge %u-%u of tet %u crosses the boundary of the missing "
                        "facet (its edges must be mesh edges)", tv[a], tv[b], t);
      if (w == 0) {
        ncross_out++;
        continue;
      }
      ncross_in++;
      out->codes[out->nnodes] = (uint8_t)tr_ecode(a, b);
      out->ntypes[out->nnodes] = TR_NOD_MID;
      out->nnodes++;
    }
  if (ncross_in == 0)
    return TR_OK;
  *touch = 1;
  if (ncross_out > 0)
    return tr_error(TR_ERR_INVALID_MESH,
                    "cluster: tet %u crosses the missing facet's plane both inside and "
                    "outside the facet", t);
  for (int k = 0; k < 4; k++) {
    if (s[k] != 0)
      continue;
    int in;
    TR_CHECK(vertex_side(vc, tv[k], &p[k], e, f, g, &s[k], &in));
    if (!in)
      return tr_error(TR_ERR_INVALID_MESH,
                      "cluster: tet %u crosses the missing facet but its vertex %u on the "
                      "plane is outside the facet", t, tv[k]);
    int j = 0;
    while (s[j] == 0)
      j++;
    out->codes[out->nnodes] = (uint8_t)(k < j ? tr_ecode(k, j) : tr_ecode(j, k));
    out->ntypes[out->nnodes] = k < j ? TR_NOD_BEG : TR_NOD_END;
    out->nodes[out->nnodes] = tv[k];
    out->nnodes++;
  }
  out->type = (uint8_t)ncross_in;
  *member = 1;
  return TR_OK;
}

tr_status tr_clusterel_classify(const struct tr_mesh *m, uint32_t t, const tr_point *e,
                                const tr_point *f, const tr_point *g, tr_clusterel *out,
                                int *member)
{
  int touch;
  int side[4];
  return classify(m, t, e, f, g, out, member, &touch, NULL, side);
}

static int cmp_clusterel(const void *a, const void *b)
{
  uint32_t x = ((const tr_clusterel *)a)->iele, y = ((const tr_clusterel *)b)->iele;
  return (x > y) - (x < y);
}

static tr_status collect(struct tr_mesh *m, const tr_point *pe, const tr_point *pf,
                         const tr_point *pg, tr_u32buf *queue, tr_clusterel **out,
                         uint32_t *n, tr_cluster_memo *mc)
{
  size_t cap = 0;
  tr_status st = TR_OK;
  /* queue->a[0..n) are the seeds, already marked; the queue grows behind them. */
  for (size_t head = 0; head < queue->n; head++) {
    uint32_t t = queue->a[head];
    tr_clusterel c;
    int member, touch;
    int side[4];
    st = classify(m, t, pe, pf, pg, &c, &member, &touch, mc, side);
    if (st != TR_OK)
      break;
    if (member) {
      if (*n == cap) {
        size_t nc = cap ? 2 * cap : 16;
        tr_clusterel *r = realloc(*out, nc * sizeof *r);
        if (!r) {
          st = tr_error(TR_ERR_NOMEM, "cluster: out of memory");
          break;
        }
        *out = r;
        cap = nc;
      }
      (*out)[(*n)++] = c;
    }
    if (!touch)
      continue;
    /* Tets touching the closed triangle are face-connected through faces that touch it
     * too (the star of any point of the triangle is, through faces holding the point),
     * so expanding only from them, across faces not strictly on one side of its plane,
     * reaches every clusterel. The order of the search does not matter: the clusterels
     * are sorted. (Every tet of e's star touches at e: expanding across all their faces
     * classified the whole second ring.) */
    for (int k = 0; k < 4; k++) {
      int pos = 0, neg = 0;
      for (int q = 0; q < 4; q++)
        if (q != k)
          pos += side[q] > 0, neg += side[q] < 0;
      if (pos == 3 || neg == 3)
        continue;
      uint32_t u = TR_NEIG(m, t, k);
      if (u == TR_NONE || tr_tet_is_ghost(m, u) || (m->flags[u] & TR_TF_MARK))
        continue;
      m->flags[u] |= TR_TF_MARK;
      st = tr_u32buf_push(queue, u);
      if (st != TR_OK)
        break;
    }
    if (st != TR_OK)
      break;
  }
  return st;
}

void tr_cluster_memo_free(tr_cluster_memo *c)
{
  tr_vtmap_free(&c->v);
  tr_edgeset_free(&c->e);
  memset(c, 0, sizeof *c);
}

int tr_cluster_side(const struct tr_mesh *m, uint32_t v, const tr_point *e, const tr_point *f,
                    const tr_point *g, tr_cluster_memo *mc)
{
  tr_point p = tr_mesh_point(m, v);
  int side, in;
  if (vertex_side(&mc->v, v, &p, e, f, g, &side, &in) != TR_OK)
    vertex_side(NULL, v, &p, e, f, g, &side, &in); /* no room to keep it: just compute */
  return side;
}

int tr_cluster_crossing(const struct tr_mesh *m, uint32_t u, uint32_t v, const tr_point *e,
                        const tr_point *f, const tr_point *g, tr_cluster_memo *mc)
{
  tr_point pu = tr_mesh_point(m, u), pv = tr_mesh_point(m, v);
  return crossing_memo(mc, u, v, &pu, &pv, e, f, g);
}

tr_status tr_cluster_collect(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                             tr_clusterel **out, uint32_t *n)
{
  tr_cluster_memo mc;
  memset(&mc, 0, sizeof mc);
  tr_status st = tr_cluster_collect_memo(m, e, f, g, out, n, &mc);
  tr_cluster_memo_free(&mc);
  return st;
}

tr_status tr_cluster_collect_memo(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                                  tr_clusterel **out, uint32_t *n, tr_cluster_memo *mc)
{
  *out = NULL;
  *n = 0;
  tr_u32buf queue = {0};
  tr_status st = tr_ball(m, e, 0, &queue);
  if (st != TR_OK) {
    tr_u32buf_free(&queue);
    return st;
  }
  for (size_t i = 0; i < queue.n; i++)
    m->flags[queue.a[i]] |= TR_TF_MARK;
  tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
  st = collect(m, &pe, &pf, &pg, &queue, out, n, mc);
  /* The mark bit is scratch: clear it on every visited tet, also after a failure. */
  for (size_t i = 0; i < queue.n; i++)
    m->flags[queue.a[i]] &= (uint8_t)~TR_TF_MARK;
  tr_u32buf_free(&queue);
  if (st != TR_OK) {
    free(*out);
    *out = NULL;
    *n = 0;
    return st;
  }
  if (*n > 1)
    qsort(*out, *n, sizeof **out, cmp_clusterel);
  return TR_OK;
}
