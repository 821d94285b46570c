/* Exact conformity validator: see conform.h. Everything is recomputed from coordinates
 * with exact predicates; nothing the pipeline recorded (chains, sub-faces) is trusted. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "conform.h"
#include "core/facets.h"
#include "input/validate.h"
#include "predicates.h"

static int kept(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER);
}

/* ---- vertices: input point -> mesh vertex with the same coordinates ---- */
typedef struct {
  double x[3];
  uint32_t v;
} vkey;
static int cmp_vkey(const void *pa, const void *pb)
{
  const vkey *a = pa, *b = pb;
  for (int k = 0; k < 3; k++)
    if (a->x[k] != b->x[k])
      return a->x[k] < b->x[k] ? -1 : 1;
  return a->v < b->v ? -1 : a->v > b->v;
}

static int cmp_pt(const double *x, const double *y)
{
  for (int k = 0; k < 3; k++)
    if (x[k] != y[k])
      return x[k] < y[k] ? -1 : 1;
  return 0;
}

/* ---- the uniform grid over the input triangles' boxes ---- */
typedef struct {
  double lo[3], hi[3];
  int g;              /* cells per axis */
  uint32_t *start;    /* g^3 + 1 */
  uint32_t *tri;      /* triangle ids per cell */
} grid;

static int cell(const grid *G, double x, int k)
{
  if (!(G->hi[k] > G->lo[k]))
    return 0;
  double f = floor((x - G->lo[k]) / (G->hi[k] - G->lo[k]) * G->g);
  if (!(f >= 0))
    return 0;
  if (f > G->g - 1)
    return G->g - 1;
  return (int)f;
}

static void tri_box(const struct tr_plc *plc, uint32_t t, double lo[3], double hi[3])
{
  for (int k = 0; k < 3; k++) {
    lo[k] = INFINITY;
    hi[k] = -INFINITY;
    for (int j = 0; j < 3; j++) { /* an exact corner: the box of its rational */
      uint32_t v = plc->tris[3 * (size_t)t + j];
      const tr_qpoint *q = plc->xq ? plc->xq[v] : NULL;
      double x0 = q ? q->lo[k] : plc->xyz[3 * (size_t)v + k], x1 = q ? q->hi[k] : x0;
      lo[k] = x0 < lo[k] ? x0 : lo[k];
      hi[k] = x1 > hi[k] ? x1 : hi[k];
    }
  }
}

static tr_status grid_build(const struct tr_plc *plc, grid *G)
{
  memset(G, 0, sizeof *G);
  uint32_t nt = plc->ntris;
  for (int k = 0; k < 3; k++) {
    G->lo[k] = INFINITY;
    G->hi[k] = -INFINITY;
  }
  for (uint32_t t = 0; t < nt; t++) {
    double lo[3], hi[3];
    tri_box(plc, t, lo, hi);
    for (int k = 0; k < 3; k++) {
      G->lo[k] = lo[k] < G->lo[k] ? lo[k] : G->lo[k];
      G->hi[k] = hi[k] > G->hi[k] ? hi[k] : G->hi[k];
    }
  }
  int g = (int)cbrt((double)nt / 2.0) + 1;
  G->g = g > 64 ? 64 : g;
  size_t nc = (size_t)G->g * G->g * G->g;
  G->start = calloc(nc + 1, sizeof *G->start);
  if (!G->start)
    return tr_error(TR_ERR_NOMEM, "out of memory for the conformity grid");
  for (int pass = 0; pass < 2; pass++) {
    for (uint32_t t = 0; t < nt; t++) {
      double lo[3], hi[3];
      int a[3], b[3];
      tri_box(plc, t, lo, hi);
      for (int k = 0; k < 3; k++) {
        a[k] = cell(G, lo[k], k);
        b[k] = cell(G, hi[k], k);
      }
      for (int i = a[0]; i <= b[0]; i++)
        for (int j = a[1]; j <= b[1]; j++)
          for (int l = a[2]; l <= b[2]; l++) {
            size_t c = ((size_t)i * G->g + j) * G->g + l;
            if (pass == 0)
              G->start[c + 1]++;
            else
              G->tri[G->start[c]++] = t;
          }
    }
    if (pass == 0) {
      for (size_t c = 0; c < nc; c++)
        G->start[c + 1] += G->start[c];
      G->tri = malloc(sizeof *G->tri * (G->start[nc] ? G->start[nc] : 1));
      if (!G->tri)
        return tr_error(TR_ERR_NOMEM, "out of memory for the conformity grid");
    } else {
      for (size_t c = nc; c > 0; c--)
        G->start[c] = G->start[c - 1];
      G->start[0] = 0;
    }
  }
  return TR_OK;
}

/* 1 iff p is in the closed input triangle t (exact). */
static int in_tri(const struct tr_plc *plc, uint32_t t, int ax, const tr_point *p)
{
  const uint32_t *v = plc->tris + 3 * (size_t)t;
  tr_point a = tr_plc_point(plc, v[0]), b = tr_plc_point(plc, v[1]), c = tr_plc_point(plc, v[2]);
  if (tr_orient3d_p(&a, &b, &c, p) != 0)
    return 0;
  int s = tr_orient2d_proj_p(&a, &b, &c, ax);
  return s * tr_orient2d_proj_p(&a, &b, p, ax) >= 0 && s * tr_orient2d_proj_p(&b, &c, p, ax) >= 0 &&
         s * tr_orient2d_proj_p(&c, &a, p, ax) >= 0;
}

/* out = |twice the area of the projection of pqr that drops axis ax| (exact). */
static void area2(const tr_point *p, const tr_point *q, const tr_point *r, int ax, mpq_t out,
                  mpq_t *tmp)
{
  int u = (ax + 1) % 3, w = (ax + 2) % 3;
  /* tmp: 0 pu 1 pw 2 qu 3 qw 4 ru 5 rw */
  tr_point_get_q(p, u, tmp[0]);
  tr_point_get_q(p, w, tmp[1]);
  tr_point_get_q(q, u, tmp[2]);
  tr_point_get_q(q, w, tmp[3]);
  tr_point_get_q(r, u, tmp[4]);
  tr_point_get_q(r, w, tmp[5]);
  mpq_sub(tmp[2], tmp[2], tmp[0]);
  mpq_sub(tmp[3], tmp[3], tmp[1]);
  mpq_sub(tmp[4], tmp[4], tmp[0]);
  mpq_sub(tmp[5], tmp[5], tmp[1]);
  mpq_mul(out, tmp[2], tmp[5]);
  mpq_mul(tmp[0], tmp[3], tmp[4]);
  mpq_sub(out, out, tmp[0]);
  mpq_abs(out, out);
}

typedef struct {
  uint32_t a, b;
} edge;
static int cmp_edge(const void *pa, const void *pb)
{
  const edge *x = pa, *y = pb;
  if (x->a != y->a)
    return x->a < y->a ? -1 : 1;
  return x->b < y->b ? -1 : x->b > y->b;
}

/* An input edge; inner: it lies inside a merged planar facet (core/facets.h). */
typedef struct {
  uint32_t a, b;
  uint32_t inner;
} iedge;
static int cmp_iedge(const void *pa, const void *pb)
{
  const iedge *x = pa, *y = pb;
  if (x->a != y->a)
    return x->a < y->a ? -1 : 1;
  return x->b < y->b ? -1 : x->b > y->b;
}

/* Walks the input edge from mesh vertex s to mesh vertex e through collinear mesh edges,
 * each step strictly closer to e. */
static int chain_ok(const struct tr_mesh *m, const uint32_t *astart, const edge *adj,
                    uint32_t s, uint32_t e)
{
  tr_point E = tr_mesh_point(m, e), S = tr_mesh_point(m, s);
  int ax = 0;
  while (ax < 3 && tr_cmp_coord_p(&S, &E, ax) == 0)
    ax++;
  if (ax == 3)
    return 0;
  uint32_t cur = s;
  for (uint32_t steps = 0; steps <= m->nv; steps++) {
    tr_point C = tr_mesh_point(m, cur);
    int dir = tr_cmp_coord_p(&C, &E, ax);
    uint32_t next = TR_NONE;
    for (uint32_t i = astart[cur]; i < astart[cur + 1]; i++) {
      uint32_t w = adj[i].b;
      if (w == e)
        return 1;
      tr_point W = tr_mesh_point(m, w);
      if (tr_orient2d_proj_p(&S, &E, &W, 0) || tr_orient2d_proj_p(&S, &E, &W, 1) ||
          tr_orient2d_proj_p(&S, &E, &W, 2))
        continue;
      /* strictly between cur and e along ax */
      if (tr_cmp_coord_p(&W, &E, ax) == dir && tr_cmp_coord_p(&C, &W, ax) == dir) {
        next = w;
        break;
      }
    }
    if (next == TR_NONE)
      return 0;
    cur = next;
  }
  return 0;
}

/* Is some vertex list vtri[vstart[v]..] entry a triangle of facet g? */
static int in_facet_list(const tr_facets *F, const uint32_t *vstart, const uint32_t *vtri,
                         uint32_t v, uint32_t g)
{
  for (uint32_t y = vstart[v]; y < vstart[v + 1]; y++)
    if (F->group[vtri[y]] == g)
      return 1;
  return 0;
}

/* Mesh face f (its first vertex in triangle tt of a merged facet g): *in = it lies in the
 * facet, which it then adds to nothing yet: its projected area along g's axis is left in
 * a2. It lies in the facet when its three vertices do (so it lies in the plane) and its
 * exact centroid lies in the closed union of the facet's triangles; the mesh being a
 * tetrahedralization whose faces cannot cross the facet's boundary edges (chains of
 * mesh edges, checked), the face then lies in the facet. Once per facet and face
 * (done[]: the facets already asked about for f). */
static tr_status merged_face(const struct tr_mesh *m, const struct tr_plc *plc,
                             const tr_facets *F, const grid *G, const int *axes,
                             const uint32_t *vstart, const uint32_t *vtri, const uint32_t f[3],
                             uint32_t tt, uint32_t *done, uint32_t *ndone, int *in, mpq_t a2,
                             mpq_t *tmp)
{
  uint32_t g = F->group[tt];
  *in = 0;
  for (uint32_t i = 0; i < *ndone; i++)
    if (done[i] == g)
      return TR_OK;
  if (*ndone < 64)
    done[(*ndone)++] = g;
  if (!in_facet_list(F, vstart, vtri, f[1], g) || !in_facet_list(F, vstart, vtri, f[2], g))
    return TR_OK;
  tr_point p[3];
  for (int i = 0; i < 3; i++)
    p[i] = tr_mesh_point(m, f[i]);
  /* all three in one triangle of the facet: in it */
  int one = 0;
  for (uint32_t x = vstart[f[0]]; x < vstart[f[0] + 1] && !one; x++) {
    uint32_t t = vtri[x];
    if (F->group[t] != g)
      continue;
    int in1 = 0, in2 = 0;
    for (uint32_t y = vstart[f[1]]; y < vstart[f[1] + 1] && !in1; y++)
      in1 = vtri[y] == t;
    for (uint32_t y = vstart[f[2]]; y < vstart[f[2] + 1] && !in2; y++)
      in2 = vtri[y] == t;
    one = in1 && in2;
  }
  if (!one) {
    tr_qpoint q;
    tr_qpoint_init(&q);
    for (int i = 0; i < 3; i++) {
      mpq_set_ui(q.c[i], 0, 1);
      for (int j = 0; j < 3; j++) {
        tr_point_get_q(&p[j], i, tmp[0]);
        mpq_add(q.c[i], q.c[i], tmp[0]);
      }
      mpq_set_ui(tmp[0], 3, 1);
      mpq_div(q.c[i], q.c[i], tmp[0]);
    }
    tr_qpoint_update(&q);
    tr_point c = tr_pt_q(&q);
    int a[3], b[3];
    for (int k = 0; k < 3; k++) {
      a[k] = cell(G, q.lo[k], k);
      b[k] = cell(G, q.hi[k], k);
    }
    for (int i = a[0]; i <= b[0] && !one; i++)
      for (int j = a[1]; j <= b[1] && !one; j++)
        for (int l = a[2]; l <= b[2] && !one; l++) {
          size_t cc = ((size_t)i * G->g + j) * G->g + l;
          for (uint32_t x = G->start[cc]; x < G->start[cc + 1] && !one; x++) {
            uint32_t t = G->tri[x];
            one = F->group[t] == g && in_tri(plc, t, axes[t], &c);
          }
        }
    tr_qpoint_clear(&q);
    if (!one)
      return TR_OK;
  }
  area2(&p[0], &p[1], &p[2], axes[g], a2, tmp);
  *in = 1;
  return TR_OK;
}

static tr_status check_conformity(const struct tr_mesh *m, const struct tr_plc *plc,
                                  mpq_srcptr volume6, unsigned flags)
{
  tr_status st = TR_OK;
  uint32_t np = plc->npoints, ntri = plc->ntris, nv = m->nv;
  uint32_t *pv = malloc(sizeof *pv * (np ? np : 1));
  vkey *ord = malloc(sizeof *ord * (nv ? nv : 1));
  uint8_t *used = calloc(nv ? nv : 1, 1), *need = calloc(np ? np : 1, 1);
  uint32_t *astart = calloc((size_t)nv + 1, sizeof *astart);
  edge *adj = NULL;
  iedge *ie = NULL;
  tr_facets F;
  memset(&F, 0, sizeof F);
  uint32_t gdone[64];
  uint32_t *vstart = NULL, *vtri = NULL, *stamp = NULL;
  mpq_t *acc = NULL, tmp[6], a2, v6, want;
  int *axes = NULL;
  uint32_t nacc = 0;
  grid G;
  memset(&G, 0, sizeof G);
  for (int i = 0; i < 6; i++)
    mpq_init(tmp[i]);
  mpq_init(a2);
  mpq_init(v6);
  mpq_init(want);
  if (!pv || !ord || !used || !need || !astart) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  /* 1. positive tets, used vertices, mesh edges */
  uint32_t nkept = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!kept(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    tr_point p[4];
    for (int i = 0; i < 4; i++) {
      p[i] = tr_mesh_point(m, v[i]);
      used[v[i]] = 1;
    }
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) <= 0) {
      st = tr_error(TR_ERR_INVALID_MESH, "conformity: tet %u (%u %u %u %u) is not positive", t,
                    v[0], v[1], v[2], v[3]);
      goto done;
    }
    nkept++;
  }
  size_t nadj = 12 * (size_t)nkept;
  adj = malloc(sizeof *adj * (nadj ? nadj : 1));
  if (!adj) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  nadj = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!kept(m, t))
      continue;
    for (int e = 0; e < 6; e++) {
      uint32_t a = m->tv[4 * (size_t)t + tr_edge_vtx[e][0]], b = m->tv[4 * (size_t)t + tr_edge_vtx[e][1]];
      adj[nadj].a = a;
      adj[nadj++].b = b;
      adj[nadj].a = b;
      adj[nadj++].b = a;
    }
  }
  qsort(adj, nadj, sizeof *adj, cmp_edge);
  {
    size_t j = 0;
    for (size_t i = 0; i < nadj; i++)
      if (j == 0 || cmp_edge(&adj[j - 1], &adj[i]))
        adj[j++] = adj[i];
    nadj = j;
  }
  for (size_t i = 0; i < nadj; i++)
    astart[adj[i].a + 1]++;
  for (uint32_t v = 0; v < nv; v++)
    astart[v + 1] += astart[v];
  /* 2. input vertices present */
  for (uint32_t i = 0; i < 3 * (size_t)ntri; i++)
    need[plc->tris[i]] = 1;
  for (uint32_t i = 0; i < 2 * (size_t)plc->nsegs; i++)
    need[plc->segs[i]] = 1;
  uint32_t nd = 0;
  for (uint32_t v = 0; v < nv; v++)
    if (used[v] && !(m->vq && m->vq[v])) {
      memcpy(ord[nd].x, m->xyz + 3 * (size_t)v, sizeof ord[nd].x);
      ord[nd++].v = v;
    }
  qsort(ord, nd, sizeof *ord, cmp_vkey);
  /* the exact mesh vertices after them, by nearest double: an exact input point
   * (--resolve's rational corners) is found among those by exact equality */
  uint32_t nq = 0;
  for (uint32_t v = 0; plc->xq && v < nv; v++)
    if (used[v] && m->vq && m->vq[v]) {
      memcpy(ord[nd + nq].x, m->vq[v]->near, sizeof ord[0].x);
      ord[nd + nq++].v = v;
    }
  qsort(ord + nd, nq, sizeof *ord, cmp_vkey);
  for (uint32_t i = 0; i < np; i++) {
    pv[i] = TR_NONE;
    if (!need[i])
      continue;
    const double *x = plc->xyz + 3 * (size_t)i;
    if (plc->xq && plc->xq[i]) {
      tr_point want = tr_pt_q(plc->xq[i]);
      for (uint32_t j = nd; j < nd + nq && pv[i] == TR_NONE; j++) {
        tr_point have = tr_mesh_point(m, ord[j].v);
        if (cmp_pt(ord[j].x, x) == 0 && tr_equal_p(&have, &want))
          pv[i] = ord[j].v;
      }
      if (pv[i] == TR_NONE) {
        st = tr_error(TR_ERR_INVALID_MESH, "conformity: exact input vertex %u (near %.17g, "
                      "%.17g, %.17g) is not a mesh vertex", i, x[0], x[1], x[2]);
        goto done;
      }
      continue;
    }
    uint32_t lo = 0, hi = nd;
    while (lo < hi) {
      uint32_t mid = lo + (hi - lo) / 2;
      if (cmp_pt(ord[mid].x, x) < 0)
        lo = mid + 1;
      else
        hi = mid;
    }
    if (lo == nd || cmp_pt(ord[lo].x, x) != 0) {
      st = tr_error(TR_ERR_INVALID_MESH,
                    "conformity: input vertex %u (%.17g, %.17g, %.17g) is not a mesh vertex", i,
                    x[0], x[1], x[2]);
      goto done;
    }
    pv[i] = ord[lo].v;
  }
  /* 3. input edges are chains of collinear mesh edges */
  size_t nie = 3 * (size_t)ntri + plc->nsegs;
  ie = malloc(sizeof *ie * (nie ? nie : 1));
  if (!ie) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  if ((st = tr_facets_build(plc, (flags & TR_CONF_KEEP_EDGES) != 0, &F)) != TR_OK)
    goto done;
  /* an inner edge of a merged facet (both its triangles say so) need not be a chain */
  for (uint32_t t = 0; t < ntri; t++)
    for (int k = 0; k < 3; k++) {
      uint32_t a = plc->tris[3 * (size_t)t + k], b = plc->tris[3 * (size_t)t + (k + 1) % 3];
      ie[3 * (size_t)t + k].a = a < b ? a : b;
      ie[3 * (size_t)t + k].b = a < b ? b : a;
      ie[3 * (size_t)t + k].inner = F.inner[t] >> k & 1;
    }
  for (uint32_t s = 0; s < plc->nsegs; s++) {
    uint32_t a = plc->segs[2 * (size_t)s], b = plc->segs[2 * (size_t)s + 1];
    ie[3 * (size_t)ntri + s].a = a < b ? a : b;
    ie[3 * (size_t)ntri + s].b = a < b ? b : a;
    ie[3 * (size_t)ntri + s].inner = 0;
  }
  qsort(ie, nie, sizeof *ie, cmp_iedge);
  int manifold = plc->nsegs == 0;
  for (size_t i = 0; i < nie;) {
    size_t j = i + 1;
    while (j < nie && !cmp_iedge(&ie[i], &ie[j]))
      j++;
    if (j - i != 2)
      manifold = 0;
    if (!ie[i].inner && !chain_ok(m, astart, adj, pv[ie[i].a], pv[ie[i].b])) {
      st = tr_error(TR_ERR_INVALID_MESH,
                    "conformity: input edge (%u, %u) is not a chain of collinear mesh edges",
                    ie[i].a, ie[i].b);
      goto done;
    }
    i = j;
  }
  /* 4. triangle coverage through the grid: per used mesh vertex, the input triangles
   * that contain it (CSR), then per mesh face the triangles containing all three. */
  if ((st = grid_build(plc, &G)) != TR_OK)
    goto done;
  axes = malloc(sizeof *axes * (ntri ? ntri : 1));
  stamp = malloc(sizeof *stamp * (ntri ? ntri : 1));
  vstart = calloc((size_t)nv + 1, sizeof *vstart);
  acc = malloc(sizeof *acc * (ntri ? ntri : 1));
  if (!axes || !stamp || !vstart || !acc) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  for (uint32_t t = 0; t < ntri; t++) {
    axes[t] = tr_plc_tri_axis(plc, t);
    stamp[t] = TR_NONE;
    mpq_init(acc[t]);
    nacc++;
  }
  size_t cap = (size_t)nv + 16, nvt = 0;
  vtri = malloc(sizeof *vtri * cap);
  if (!vtri) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  for (uint32_t v = 0; v < nv; v++) {
    vstart[v] = (uint32_t)nvt;
    if (!used[v])
      continue;
    tr_point p = tr_mesh_point(m, v);
    const double *lo = p.q ? p.q->lo : p.d, *hi = p.q ? p.q->hi : p.d;
    int a[3], b[3];
    for (int k = 0; k < 3; k++) {
      a[k] = cell(&G, lo[k], k);
      b[k] = cell(&G, hi[k], k);
    }
    for (int i = a[0]; i <= b[0]; i++)
      for (int j = a[1]; j <= b[1]; j++)
        for (int l = a[2]; l <= b[2]; l++) {
          size_t c = ((size_t)i * G.g + j) * G.g + l;
          for (uint32_t x = G.start[c]; x < G.start[c + 1]; x++) {
            uint32_t t = G.tri[x];
            if (stamp[t] == v || axes[t] < 0)
              continue;
            stamp[t] = v;
            if (!in_tri(plc, t, axes[t], &p))
              continue;
            if (nvt == cap) {
              uint32_t *nb = realloc(vtri, sizeof *vtri * (cap *= 2));
              if (!nb) {
                st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
                goto done;
              }
              vtri = nb;
            }
            vtri[nvt++] = t;
          }
        }
  }
  vstart[nv] = (uint32_t)nvt;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!kept(m, t))
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      int okept = o != TR_NONE && kept(m, o);
      if (okept && o < t)
        continue;
      int boundary = (!okept && !(flags & TR_CONF_OPEN)) ||
                     (okept && m->region && m->region[o] != m->region[t]);
      uint32_t f[3];
      for (int i = 0; i < 3; i++)
        f[i] = m->tv[4 * (size_t)t + tr_face_vtx[k][i]];
      int found = 0;
      uint32_t ndone = 0;
      for (uint32_t x = vstart[f[0]]; x < vstart[f[0] + 1]; x++) {
        uint32_t tt = vtri[x];
        if (tr_facets_size(&F, F.group[tt]) > 1) {
          int in = 0;
          if ((st = merged_face(m, plc, &F, &G, axes, vstart, vtri, f, tt, gdone, &ndone, &in,
                                a2, tmp)) != TR_OK)
            goto done;
          if (in) {
            mpq_add(acc[F.group[tt]], acc[F.group[tt]], a2);
            found = 1;
          }
          continue;
        }
        int in1 = 0, in2 = 0;
        for (uint32_t y = vstart[f[1]]; y < vstart[f[1] + 1] && !in1; y++)
          in1 = vtri[y] == tt;
        for (uint32_t y = vstart[f[2]]; y < vstart[f[2] + 1] && !in2; y++)
          in2 = vtri[y] == tt;
        if (!in1 || !in2)
          continue;
        tr_point p0 = tr_mesh_point(m, f[0]), p1 = tr_mesh_point(m, f[1]),
                 p2 = tr_mesh_point(m, f[2]);
        area2(&p0, &p1, &p2, axes[tt], a2, tmp);
        mpq_add(acc[tt], acc[tt], a2);
        found = 1;
      }
      if (boundary && !found) {
        st = tr_error(TR_ERR_INVALID_MESH,
                      "conformity: boundary face (%u %u %u) of tet %u lies in no input triangle",
                      f[0], f[1], f[2], t);
        goto done;
      }
    }
  }
  for (uint32_t t = 0; t < ntri; t++) {
    const uint32_t *v = plc->tris + 3 * (size_t)t;
    tr_point p0 = tr_plc_point(plc, v[0]), p1 = tr_plc_point(plc, v[1]),
             p2 = tr_plc_point(plc, v[2]);
    if (axes[t] < 0) {
      st = tr_error(TR_ERR_INVALID_MESH, "conformity: input triangle %u is degenerate", t);
      goto done;
    }
    if (F.group[t] != t)
      continue; /* in a merged facet: checked with the facet's first triangle */
    if (tr_facets_size(&F, t) > 1) {
      /* the facet's area: its triangles' along the first one's axis (one plane) */
      mpq_set_ui(want, 0, 1);
      for (uint32_t i = F.start[t]; i < F.start[t + 1]; i++) {
        const uint32_t *u = plc->tris + 3 * (size_t)F.member[i];
        tr_point q0 = tr_plc_point(plc, u[0]), q1 = tr_plc_point(plc, u[1]),
                 q2 = tr_plc_point(plc, u[2]);
        area2(&q0, &q1, &q2, axes[t], a2, tmp);
        mpq_add(want, want, a2);
      }
      if (!mpq_equal(want, acc[t])) {
        st = tr_error(TR_ERR_INVALID_MESH,
                      "conformity: the planar facet of %u input triangles %u (%u %u %u), ... "
                      "is not exactly covered by mesh faces (covered / own projected area = "
                      "%.17g)",
                      tr_facets_size(&F, t), t, v[0], v[1], v[2],
                      mpq_get_d(acc[t]) / mpq_get_d(want));
        goto done;
      }
      continue;
    }
    area2(&p0, &p1, &p2, axes[t], a2, tmp);
    if (!mpq_equal(a2, acc[t])) {
      st = tr_error(TR_ERR_INVALID_MESH,
                    "conformity: input triangle %u (%u %u %u) is not exactly covered by mesh "
                    "faces (covered / own projected area = %.17g)",
                    t, v[0], v[1], v[2], mpq_get_d(acc[t]) / mpq_get_d(a2));
      goto done;
    }
  }
  /* 5. volume */
  if (volume6 || manifold || !(flags & TR_CONF_OPEN)) {
    if (volume6)
      mpq_set(want, volume6);
    else if (manifold && plc->ninclusions == 0 && plc->nholes == 0)
      /* the triangle sum; an inclusion (an outward shell inside the domain) or a hole
       * point's cell make it differ from the domain's volume */
      st = tr_input_volume6(plc, want);
    else
      st = tr_input_domain_volume6(plc, want);
    if (st != TR_OK)
      goto done;
    if ((st = tr_mesh_volume6(m, v6)) != TR_OK)
      goto done;
    if (!mpq_equal(v6, want)) {
      st = tr_error(TR_ERR_INVALID_MESH,
                    "conformity: the tets' volume (6V = %.17g) differs from the enclosed "
                    "volume (6V = %.17g)",
                    mpq_get_d(v6), mpq_get_d(want));
      goto done;
    }
  }
done:
  for (uint32_t t = 0; t < nacc; t++)
    mpq_clear(acc[t]);
  for (int i = 0; i < 6; i++)
    mpq_clear(tmp[i]);
  mpq_clear(a2);
  mpq_clear(v6);
  mpq_clear(want);
  free(pv);
  free(ord);
  free(used);
  free(need);
  free(astart);
  free(adj);
  free(ie);
  free(vstart);
  free(vtri);
  free(stamp);
  free(acc);
  free(axes);
  free(G.start);
  free(G.tri);
  tr_facets_free(&F);
  return st;
}

/* *closed = every triangle edge has exactly two triangles and there are no segments. */
static tr_status census(const struct tr_plc *plc, int *closed)
{
  size_t ne = 3 * (size_t)plc->ntris;
  edge *e = malloc(sizeof *e * (ne ? ne : 1));
  if (!e)
    return tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
  for (uint32_t t = 0; t < plc->ntris; t++)
    for (int k = 0; k < 3; k++) {
      uint32_t a = plc->tris[3 * (size_t)t + k], b = plc->tris[3 * (size_t)t + (k + 1) % 3];
      e[3 * (size_t)t + k].a = a < b ? a : b;
      e[3 * (size_t)t + k].b = a < b ? b : a;
    }
  qsort(e, ne, sizeof *e, cmp_edge);
  *closed = plc->nsegs == 0;
  for (size_t i = 0; i < ne && *closed;) {
    size_t j = i + 1;
    while (j < ne && !cmp_edge(&e[i], &e[j]))
      j++;
    *closed = j - i == 2;
    i = j;
  }
  free(e);
  return TR_OK;
}

/* A triangle with the outside on both of its sides (a facet between two cavities, or a
 * shell a hole point empties) bounds no tet of the domain: its vertices, edges and area
 * are not in the mesh. The checks
 * then run on the other triangles, with the whole input's domain volume. */
tr_status tr_check_conformity(const struct tr_mesh *m, const struct tr_plc *plc,
                              mpq_srcptr volume6, unsigned flags)
{
  int closed = 0;
  if (flags & TR_CONF_OPEN)
    return check_conformity(m, plc, volume6, flags);
  TR_CHECK(census(plc, &closed));
  if (closed && plc->nholes == 0) /* a hole point can empty a whole shell */
    return check_conformity(m, plc, volume6, flags);
  uint8_t *sides = malloc(plc->ntris ? plc->ntris : 1);
  uint32_t *tris = malloc(sizeof *tris * 3 * ((size_t)plc->ntris + 1));
  tr_status st = TR_OK;
  if (!sides || !tris) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking conformity");
    goto done;
  }
  if ((st = tr_input_side_domains(plc, sides)) != TR_OK)
    goto done;
  uint32_t n = 0;
  for (uint32_t t = 0; t < plc->ntris; t++)
    if (sides[t])
      memcpy(tris + 3 * (size_t)n++, plc->tris + 3 * (size_t)t, 3 * sizeof *tris);
  if (n == plc->ntris) {
    st = check_conformity(m, plc, volume6, flags);
    goto done;
  }
  mpq_t want;
  mpq_init(want);
  if (volume6)
    mpq_set(want, volume6);
  else
    st = tr_input_domain_volume6(plc, want);
  if (st == TR_OK) {
    struct tr_plc sub = *plc;
    sub.ntris = n;
    sub.tris = tris;
    sub.tri_marker = NULL;
    sub.tri_source = NULL; /* messages then number the bounding triangles only */
    st = check_conformity(m, &sub, want, flags);
  }
  mpq_clear(want);
done:
  free(sides);
  free(tris);
  return st;
}
