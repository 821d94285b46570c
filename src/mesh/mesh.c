/* The mesh store: allocation, vertices, tet slots, export. */
#include "mesh.h"
#include "orient_memo.h"

#include <stdlib.h>
#include <string.h>

tr_status tr_u32buf_reserve(tr_u32buf *b, size_t cap)
{
  if (cap <= b->cap)
    return TR_OK;
  size_t nc = b->cap ? b->cap : 16;
  while (nc < cap)
    nc += nc / 2 + 16;
  uint32_t *a = realloc(b->a, nc * sizeof *a);
  if (!a)
    return tr_error(TR_ERR_NOMEM, "out of memory growing a buffer to %zu entries", nc);
  b->a = a;
  b->cap = nc;
  return TR_OK;
}

tr_status tr_u32buf_push(tr_u32buf *b, uint32_t x)
{
  if (b->n == b->cap)
    TR_CHECK(tr_u32buf_reserve(b, b->n + 1));
  b->a[b->n++] = x;
  return TR_OK;
}

void tr_u32buf_free(tr_u32buf *b)
{
  free(b->a);
  b->a = NULL;
  b->n = b->cap = 0;
}

tr_status tr_mesh_create(uint32_t vcap, uint32_t tcap, struct tr_mesh **out)
{
  *out = NULL;
  struct tr_mesh *m = calloc(1, sizeof *m);
  if (!m)
    return tr_error(TR_ERR_NOMEM, "out of memory creating a mesh");
  m->free_head = TR_NONE;
  tr_status s = tr_mesh_reserve_vertices(m, vcap);
  if (s == TR_OK)
    s = tr_mesh_reserve_tets(m, tcap);
  if (s != TR_OK) {
    tr_mesh_destroy(m);
    return s;
  }
  *out = m;
  return TR_OK;
}

void tr_mesh_destroy(struct tr_mesh *m)
{
  if (!m)
    return;
  if (m->vq) {
    for (uint32_t i = 0; i < m->nv; i++)
      if (m->vq[i]) {
        tr_qpoint_clear(m->vq[i]);
        free(m->vq[i]);
      }
    free(m->vq);
  }
  free(m->xyz);
  free(m->v2t);
  free(m->tv);
  free(m->tn);
  free(m->flags);
  free(m->region);
  free(m->dup_map);
  tr_mesh_attrs_free(m->attrs);
  tr_mesh_orient_memo_off(m);
  free(m);
}

tr_status tr_mesh_attach_dense_tets(struct tr_mesh *m)
{
  struct tr_mesh_attrs *a = m->attrs;
  if (!a && !(a = m->attrs = calloc(1, sizeof *a)))
    return tr_error(TR_ERR_NOMEM, "out of memory for the output attributes");
  free(a->tets);
  a->tets = NULL;
  return tr_mesh_export_tets(m, &a->tets, &a->ntets);
}

void tr_mesh_attrs_free(struct tr_mesh_attrs *a)
{
  if (!a)
    return;
  free(a->tets);
  free(a->faces);
  free(a->face_tri);
  free(a->face_marker);
  free(a->vkind);
  free(a->vindex);
  free(a->edges);
  free(a);
}

uint32_t tr_mesh_num_vertices(const struct tr_mesh *m) { return m ? m->nv : 0; }

uint32_t tr_mesh_num_tets(const struct tr_mesh *m) { return m ? tr_mesh_count_real(m) : 0; }

/* realloc that leaves *p untouched on failure, so a failed growth keeps the mesh valid. */
static int grow(void **p, size_t n, size_t size)
{
  void *q = realloc(*p, n * size);
  if (!q && n)
    return -1;
  *p = q;
  return 0;
}

tr_status tr_mesh_reserve_vertices(struct tr_mesh *m, uint32_t vcap)
{
  if (vcap <= m->cap_v)
    return TR_OK;
  if (grow((void **)&m->xyz, (size_t)vcap * 3, sizeof(double)) ||
      grow((void **)&m->v2t, vcap, sizeof(uint32_t)) ||
      (m->vq && grow((void **)&m->vq, vcap, sizeof(tr_qpoint *))))
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", vcap);
  if (m->dup_map && grow((void **)&m->dup_map, vcap, sizeof(uint32_t)))
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", vcap);
  if (m->vq)
    memset(m->vq + m->cap_v, 0, (size_t)(vcap - m->cap_v) * sizeof *m->vq);
  m->cap_v = vcap;
  return TR_OK;
}

tr_status tr_mesh_reserve_tets(struct tr_mesh *m, uint32_t tcap)
{
  if (tcap <= m->cap_t)
    return TR_OK;
  if (tcap > UINT32_MAX / 4 - 1)
    return tr_error(TR_ERR_NOMEM, "too many tets (%u): the 4*tet+face code overflows", tcap);
  if (grow((void **)&m->tv, (size_t)tcap * 4, sizeof(uint32_t)) ||
      grow((void **)&m->tn, (size_t)tcap * 4, sizeof(uint32_t)) ||
      grow((void **)&m->flags, tcap, 1) ||
      (m->region && grow((void **)&m->region, tcap, sizeof(uint32_t))))
    return tr_error(TR_ERR_NOMEM, "out of memory for %u tets", tcap);
  m->cap_t = tcap;
  return TR_OK;
}

tr_status tr_mesh_enable_regions(struct tr_mesh *m)
{
  if (m->region)
    return TR_OK;
  m->region = calloc(m->cap_t ? m->cap_t : 1, sizeof *m->region);
  if (!m->region)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u region ids", m->cap_t);
  return TR_OK;
}

static tr_status vertex_slot(struct tr_mesh *m, uint32_t *idx)
{
  if (m->nv >= TR_GHOST - 1)
    return tr_error(TR_ERR_NOMEM, "too many vertices");
  if (m->nv == m->cap_v) {
    uint32_t nc = m->cap_v < 16 ? 16 : m->cap_v + m->cap_v / 2;
    if (nc < m->cap_v || nc >= TR_GHOST)
      nc = TR_GHOST - 1;
    TR_CHECK(tr_mesh_reserve_vertices(m, nc));
  }
  *idx = m->nv++;
  m->v2t[*idx] = TR_NONE;
  if (m->vq)
    m->vq[*idx] = NULL;
  if (m->dup_map)
    m->dup_map[*idx] = *idx;
  return TR_OK;
}

tr_status tr_mesh_add_vertex(struct tr_mesh *m, const double xyz[3], uint32_t *idx)
{
  TR_CHECK(vertex_slot(m, idx));
  memcpy(m->xyz + 3 * (size_t)*idx, xyz, 3 * sizeof(double));
  return TR_OK;
}

tr_status tr_mesh_add_steiner(struct tr_mesh *m, tr_qpoint *q, uint32_t *idx)
{
  if (!m->vq) {
    m->vq = calloc(m->cap_v ? m->cap_v : 1, sizeof *m->vq);
    if (!m->vq)
      return tr_error(TR_ERR_NOMEM, "out of memory for exact vertex pointers");
  }
  TR_CHECK(vertex_slot(m, idx));
  memcpy(m->xyz + 3 * (size_t)*idx, q->near, 3 * sizeof(double));
  m->vq[*idx] = q;
  return TR_OK;
}

tr_status tr_mesh_add_constructed(struct tr_mesh *m, tr_qpoint *q, uint32_t *idx)
{
  size_t bits = 0;
  for (int k = 0; k < 3; k++)
    bits += mpz_sizeinbase(mpq_numref(q->c[k]), 2) + mpz_sizeinbase(mpq_denref(q->c[k]), 2);
  if (bits > TR_STEINER_MAX_BITS)
    return tr_error(TR_ERR_UNSUPPORTED,
                    "exact Steiner point %u near (%.17g, %.17g, %.17g) needs %zu bits (limit "
                    "%d): Steiner points built on Steiner points grew too large; this input's "
                    "near-degenerate configuration is beyond this version",
                    m->nv, q->near[0], q->near[1], q->near[2], bits, TR_STEINER_MAX_BITS);
  return tr_mesh_add_steiner(m, q, idx);
}

void tr_mesh_pop_vertex(struct tr_mesh *m)
{
  uint32_t v = m->nv - 1;
  if (m->vq && m->vq[v]) {
    tr_qpoint_clear(m->vq[v]);
    free(m->vq[v]);
    m->vq[v] = NULL;
  }
  m->nv--;
  tr_mesh_orient_memo_forget(m);
}

tr_status tr_tet_new(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                     uint32_t *t)
{
  uint32_t s;
  if (m->free_head != TR_NONE) {
    s = m->free_head;
    m->free_head = m->tn[4 * (size_t)s];
    m->nfree--;
  } else {
    if (m->nt == m->cap_t) {
      uint32_t nc = m->cap_t < 64 ? 64 : m->cap_t + m->cap_t / 2;
      if (nc < m->cap_t || nc > UINT32_MAX / 4 - 1)
        nc = UINT32_MAX / 4 - 1;
      TR_CHECK(tr_mesh_reserve_tets(m, nc));
    }
    s = m->nt++;
  }
  uint32_t *v = m->tv + 4 * (size_t)s;
  v[0] = a;
  v[1] = b;
  v[2] = c;
  v[3] = d;
  for (int k = 0; k < 4; k++) {
    m->tn[4 * (size_t)s + (size_t)k] = TR_NONE;
    if (v[k] != TR_GHOST)
      m->v2t[v[k]] = s;
  }
  m->flags[s] = 0;
  if (m->region)
    m->region[s] = 0;
  *t = s;
  return TR_OK;
}

void tr_tet_free(struct tr_mesh *m, uint32_t t)
{
  uint32_t *v = m->tv + 4 * (size_t)t;
  v[0] = v[1] = v[2] = v[3] = TR_NONE;
  m->tn[4 * (size_t)t] = m->free_head;
  m->tn[4 * (size_t)t + 1] = m->tn[4 * (size_t)t + 2] = m->tn[4 * (size_t)t + 3] = TR_NONE;
  m->flags[t] = 0;
  m->free_head = t;
  m->nfree++;
}

uint32_t tr_mesh_count_real(const struct tr_mesh *m)
{
  uint32_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    n += (uint32_t)tr_tet_is_real(m, t);
  return n;
}

tr_status tr_mesh_export_tets(const struct tr_mesh *m, uint32_t **tets, uint32_t *ntets)
{
  uint32_t n = tr_mesh_count_real(m);
  uint32_t *a = malloc(4 * (size_t)(n ? n : 1) * sizeof *a);
  if (!a)
    return tr_error(TR_ERR_NOMEM, "out of memory exporting %u tets", n);
  uint32_t j = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t)) {
      memcpy(a + 4 * (size_t)j, m->tv + 4 * (size_t)t, 4 * sizeof *a);
      j++;
    }
  *tets = a;
  *ntets = n;
  return TR_OK;
}

void tr_mesh_centroid_q(const struct tr_mesh *m, const uint32_t v[3], tr_qpoint *q)
{
  mpq_t x;
  mpq_init(x);
  for (int i = 0; i < 3; i++) {
    mpq_set_ui(q->c[i], 0, 1);
    for (int j = 0; j < 3; j++) {
      tr_point p = tr_mesh_point(m, v[j]);
      tr_point_get_q(&p, i, x);
      mpq_add(q->c[i], q->c[i], x);
    }
    mpq_set_ui(x, 3, 1);
    mpq_div(q->c[i], q->c[i], x);
  }
  mpq_clear(x);
  tr_qpoint_update(q);
}
