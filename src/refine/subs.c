/* The constraint tables of the refinement stage: sub-faces (with a face map for "is this
 * mesh face a sub-face?") and sub-segments (tr_edgeset), and what each vertex lies on.
 * Sub-segments are derived from the sub-faces: a sub-face edge whose ends both lie on
 * one edge of its input triangle (exact collinearity) is a piece of that input edge. */
#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_impl.h"

/* The kind of vertex v, RF_INPUT (an unknown kind, no shortcut) past the table. */
static uint8_t kind_of(const rf_ctx *c, uint32_t v)
{
  return v < c->capv ? c->vkind[v] : RF_INPUT;
}

static uint32_t live_face(const rf_ctx *c, uint32_t a, uint32_t b, uint32_t d)
{
  uint32_t f = rf_face_get(&c->fm, a, b, d);
  return f != TR_NONE && !c->sfdead[f] ? f : TR_NONE;
}

static uint32_t live_seg(const rf_ctx *c, uint32_t u, uint32_t v)
{
  uint32_t s = tr_edgeset_get(&c->es, u, v);
  return s != TR_EDGESET_NONE && !c->ssdead[s] ? s : TR_NONE;
}

/* Every vertex of a live sub-face lies on a constraint (build_tables gives the kinds, and
 * a split point has its kind before its insertion makes sub-faces: split.c), while most
 * faces a cavity walks have an interior vertex: those need no key and no probe (the
 * probe's filter bit and slot were cache misses for 6.5% of cheese.off's CPU). */
uint32_t rf_subface_of(const rf_ctx *c, uint32_t a, uint32_t b, uint32_t d)
{
  if (kind_of(c, a) == RF_FREE || kind_of(c, b) == RF_FREE || kind_of(c, d) == RF_FREE) {
    assert(live_face(c, a, b, d) == TR_NONE);
    return TR_NONE;
  }
  return live_face(c, a, b, d);
}

/* Likewise a live sub-segment's ends are input vertices or split points of input edges. */
uint32_t rf_subseg_of(const rf_ctx *c, uint32_t u, uint32_t v)
{
  uint8_t ku = kind_of(c, u), kv = kind_of(c, v);
  if (ku == RF_FREE || ku == RF_FACET || kv == RF_FREE || kv == RF_FACET) {
    assert(live_seg(c, u, v) == TR_NONE);
    return TR_NONE;
  }
  return live_seg(c, u, v);
}

static tr_status grow_arrays(void **arrs, const size_t *sizes, int n, uint32_t *cap,
                             uint32_t need)
{
  if (need <= *cap)
    return TR_OK;
  if (need > (1u << 30))
    return tr_error(TR_ERR_NOMEM, "refinement: more than 2^30 constraint pieces");
  uint32_t nc = *cap ? *cap : 64;
  while (nc < need)
    nc *= 2;
  for (int i = 0; i < n; i++) {
    void *p = realloc(arrs[i], sizes[i] * nc);
    if (!p)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u constraint pieces", need);
    memset((char *)p + sizes[i] * *cap, 0, sizes[i] * (nc - *cap));
    arrs[i] = p;
  }
  *cap = nc;
  return TR_OK;
}

tr_status rf_subface_add(rf_ctx *c, uint32_t a, uint32_t b, uint32_t d, uint32_t tri,
                         uint32_t *id)
{
  void *arrs[5] = {c->sfv, c->sftri, c->sfdead, c->sfnosplit, c->sfexp};
  size_t sizes[5] = {3 * sizeof(uint32_t), sizeof(uint32_t), 1, 1, sizeof(uint32_t)};
  tr_status s = grow_arrays(arrs, sizes, 5, &c->capsf, c->nsf + 1);
  c->sfv = arrs[0];
  c->sftri = arrs[1];
  c->sfdead = arrs[2];
  c->sfnosplit = arrs[3];
  c->sfexp = arrs[4];
  TR_CHECK(s);
  uint32_t f = c->nsf++;
  c->sfv[3 * (size_t)f] = a;
  c->sfv[3 * (size_t)f + 1] = b;
  c->sfv[3 * (size_t)f + 2] = d;
  c->sftri[f] = tri;
  c->sfexp[f] = TR_NONE;
  c->sfdead[f] = c->sfnosplit[f] = 0;
  if (id)
    *id = f;
  return rf_face_set(&c->fm, c->sfv + 3 * (size_t)f, f);
}

tr_status rf_subseg_add(rf_ctx *c, uint32_t u, uint32_t v, uint32_t A, uint32_t B,
                        uint32_t *id)
{
  void *arrs[4] = {c->ssv, c->ssab, c->ssdead, c->ssnosplit};
  size_t sizes[4] = {2 * sizeof(uint32_t), 2 * sizeof(uint32_t), 1, 1};
  tr_status s = grow_arrays(arrs, sizes, 4, &c->capss, c->nss + 1);
  c->ssv = arrs[0];
  c->ssab = arrs[1];
  c->ssdead = arrs[2];
  c->ssnosplit = arrs[3];
  TR_CHECK(s);
  uint32_t g = c->nss++;
  c->ssv[2 * (size_t)g] = u;
  c->ssv[2 * (size_t)g + 1] = v;
  c->ssab[2 * (size_t)g] = A < B ? A : B;
  c->ssab[2 * (size_t)g + 1] = A < B ? B : A;
  if (id)
    *id = g;
  /* tr_edgeset keeps the first value of a key: a split sub-segment's key is never
   * reused (its two ends are no longer joined by a constraint piece), so this is new */
  TR_CHECK(tr_edgeset_put(&c->es, u, v, g));
  return rf_longs_added(c, g);
}

tr_status rf_vertex_room(rf_ctx *c, uint32_t nv)
{
  if (nv <= c->capv)
    return TR_OK;
  uint32_t nc = c->capv ? c->capv : 64;
  while (nc < nv)
    nc = nc > UINT32_MAX / 2 ? UINT32_MAX : 2 * nc;
  uint8_t *k = realloc(c->vkind, nc);
  if (k)
    c->vkind = k;
  uint32_t *o = realloc(c->vown, sizeof *o * nc);
  if (o)
    c->vown = o;
  double *r = realloc(c->vrad, sizeof *r * nc);
  if (r)
    c->vrad = r;
  double *sp = NULL;
  if (c->par.spacing_radii && (sp = realloc(c->vspace, sizeof *sp * nc)))
    c->vspace = sp;
  if (!k || !o || !r || (c->par.spacing_radii && !sp))
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", nv);
  memset(c->vkind + c->capv, RF_FREE, nc - c->capv);
  for (uint32_t i = c->capv; i < nc; i++) {
    c->vown[i] = TR_NONE;
    c->vrad[i] = 0;
    if (sp)
      sp[i] = 0;
  }
  c->capv = nc;
  return TR_OK;
}

/* 1 iff p lies on the line through a and b (exact: every coordinate projection). */
static int on_line(const tr_point *a, const tr_point *b, const tr_point *p)
{
  for (int d = 0; d < 3; d++)
    if (tr_orient2d_proj_p(a, b, p, d) != 0)
      return 0;
  return 1;
}

/* p is not beyond both a and b along any axis: cheaper than on_line, and mostly decides
 * (exact) */
static int in_box(const tr_point *a, const tr_point *b, const tr_point *p)
{
  for (int d = 0; d < 3; d++)
    if (tr_cmp_coord_p(p, a, d) * tr_cmp_coord_p(p, b, d) > 0)
      return 0;
  return 1;
}

/* 1 iff u and w (mesh vertices) lie on the closed input edge AB (exact). line: per vertex
 * the input edge it was found on (its ids sorted), or NULL; a vertex of k sub-faces is
 * asked up to 6k times, and on the line is exactly the case no filter decides (the cost
 * of every set-up, also of each of the sliver polish's trials) */
static int on_input_edge(const rf_ctx *c, uint32_t u, uint32_t w, uint32_t A, uint32_t B,
                         uint32_t *line)
{
  const struct tr_mesh *m = c->m;
  uint32_t np = c->plc->npoints;
  tr_point pa = tr_mesh_point(m, A), pb = tr_mesh_point(m, B);
  uint32_t x[2] = {u, w};
  for (int i = 0; i < 2; i++) {
    if (x[i] == A || x[i] == B)
      continue;
    if (x[i] < np)
      return 0;
    tr_point p = tr_mesh_point(m, x[i]);
    /* the edge as an unordered pair: its two triangles list it both ways */
    uint32_t lo = A < B ? A : B, hi = A < B ? B : A;
    uint32_t *l = line ? line + 2 * (size_t)x[i] : NULL;
    if (l && l[0] != TR_NONE) {
      /* found on the closed input edge {l0,l1} and no input point: inside it, so on no
       * other input edge, which the validated input's edges meet only at their ends (the
       * exact test again for each triangle around x was the bulk of each set-up); and
       * inside AB's box when AB is that edge, so the box test below is not needed */
      int on = l[0] == lo && l[1] == hi;
      /* and a memo kept across runs, the same point */
      assert(on == (in_box(&pa, &pb, &p) && on_line(&pa, &pb, &p)));
      if (!on)
        return 0;
      continue;
    }
    if (!in_box(&pa, &pb, &p) || !on_line(&pa, &pb, &p))
      return 0;
    if (l)
      l[0] = lo, l[1] = hi;
  }
  return 1;
}

/* The sub-segment of the sub-face edge {u,w} of facet g whose input triangle is tri (the
 * one its sub-face lies in, or holds its centroid): the edges of tri first, then, for a
 * merged facet (a sub-face exported by an earlier run may straddle its triangles), the
 * facet's boundary edges. Inner edges of a facet are no constraints. *A = TR_NONE if the
 * edge lies on no constraint. */
static int edge_of_triangle(const rf_ctx *c, uint32_t u, uint32_t w, uint32_t t, uint32_t *A,
                            uint32_t *B, uint32_t *line)
{
  const uint32_t *T = c->plc->tris + 3 * (size_t)t;
  for (int k = 0; k < 3; k++)
    if (!(c->fc.inner[t] >> k & 1) && on_input_edge(c, u, w, T[k], T[(k + 1) % 3], line)) {
      *A = T[k];
      *B = T[(k + 1) % 3];
      return 1;
    }
  return 0;
}

static void input_edge_of(const rf_ctx *c, uint32_t u, uint32_t w, uint32_t tri, int bdry,
                          uint32_t *A, uint32_t *B, uint32_t *line)
{
  const tr_facets *F = &c->fc;
  uint32_t g = F->group[tri];
  *A = *B = TR_NONE;
  if (edge_of_triangle(c, u, w, tri, A, B, line) || !bdry)
    return;
  for (uint32_t i = F->start[g]; i < F->start[g + 1]; i++)
    if (F->member[i] != tri && edge_of_triangle(c, u, w, F->member[i], A, B, line))
      return;
}

#ifndef NDEBUG
/* The same map, slot for slot. */
static int same_map(const tr_vtmap *a, const tr_vtmap *b)
{
  return a->cap == b->cap && a->n == b->n &&
         !memcmp(a->slot, b->slot, sizeof *a->slot * (size_t)a->cap * (a->arity + 1));
}

/* The plc's own tables (facets, triangle map, cap clusters) of f and c are the same, slot
 * for slot: check_copy's and check_plc_tables' comparison. */
static void assert_same_plc_tables(const rf_ctx *f, const rf_ctx *c)
{
  const struct tr_plc *plc = c->plc;
  assert(f->fc.ntris == c->fc.ntris && f->fc.ninner == c->fc.ninner &&
         f->fc.nmerged == c->fc.nmerged &&
         !memcmp(f->fc.group, c->fc.group, sizeof *f->fc.group * f->fc.ntris) &&
         !memcmp(f->fc.member, c->fc.member, sizeof *f->fc.member * f->fc.ntris));
  assert(same_map(&f->trimap, &c->trimap));
  assert(f->caps.n == c->caps.n);
  assert(!f->caps.n ||
         (!memcmp(f->caps.tri, c->caps.tri, sizeof *f->caps.tri * plc->ntris) &&
          !memcmp(f->caps.vert, c->caps.vert, sizeof *f->caps.vert * plc->npoints) &&
          same_map(&f->caps.edge, &c->caps.edge)));
  (void)plc;
}

/* The plc's tables copied from the memo (rf_memo_plc_tables) are those a build makes,
 * slot for slot. */
static void check_plc_tables(const rf_ctx *c)
{
  const struct tr_plc *plc = c->plc;
  rf_ctx f;
  memset(&f, 0, sizeof f);
  f.plc = plc;
  if (tr_facets_build(plc, c->par.keep_edges, &f.fc) != TR_OK ||
      rf_caps_build(&f.caps, plc) != TR_OK || tr_vtmap_reserve(&f.trimap, 3, plc->ntris) != TR_OK) {
    tr_error_clear(); /* out of memory: nothing to compare */
  } else {
    tr_status s = TR_OK;
    for (uint32_t t = 0; t < plc->ntris && s == TR_OK; t++)
      s = rf_face_set(&f.trimap, plc->tris + 3 * (size_t)t, t);
    if (s == TR_OK)
      assert_same_plc_tables(&f, c);
    else
      tr_error_clear();
  }
  rf_tables_free(&f);
}
#endif

static tr_status build_tables(rf_ctx *c, const tr_subfaces *sub)
{
  const struct tr_plc *plc = c->plc;
  struct tr_mesh *m = c->m;
  /* the plc's own tables from the last set-up when it has them (the sliver polish's
   * kept trials change the sub-faces, and each set-up after one comes here; the cap
   * clusters were a fifth of its cost) */
  int have;
  TR_CHECK(rf_memo_plc_tables(c, &have));
  if (!have)
    TR_CHECK(tr_facets_build(plc, c->par.keep_edges, &c->fc));
  c->st->merged_edges = c->fc.ninner;
  TR_CHECK(rf_vertex_room(c, m->nv + 1));
  for (uint32_t v = 0; v < m->nv; v++) {
    c->vkind[v] = v < plc->npoints ? RF_INPUT : RF_FREE;
    c->vown[v] = v < plc->npoints ? v : TR_NONE;
  }
  if (!have) {
    TR_CHECK(tr_vtmap_reserve(&c->trimap, 3, plc->ntris));
    for (uint32_t t = 0; t < plc->ntris; t++)
      TR_CHECK(rf_face_set(&c->trimap, plc->tris + 3 * (size_t)t, t));
    TR_CHECK(rf_caps_build(&c->caps, plc));
  }
#ifndef NDEBUG
  else
    check_plc_tables(c);
#endif
  /* "is this mesh face a sub-face?" is asked of every face the refinement walks */
  TR_CHECK(tr_vtmap_reserve(&c->fm, 3, 2 * sub->n));
  TR_CHECK(tr_vtmap_filter(&c->fm));
  /* and "is this edge a sub-segment?" of every edge of every cavity tet: mostly no */
  TR_CHECK(tr_vtmap_reserve(&c->es.m, 2, sub->n + 1));
  TR_CHECK(tr_vtmap_filter(&c->es.m));
  /* sub-face edges per facet: one sub-face of the facet on an edge puts it on the facet's
   * boundary (the facet's sub-faces tile it), two inside */
  tr_vtmap cnt = {0};
  tr_status s = TR_OK;
  uint32_t *line = rf_memo_line(c->par.memo, m->nv);
  if (c->fc.nmerged) {
    s = tr_vtmap_reserve(&cnt, 3, 3 * (size_t)sub->n / 2 + 1);
    for (uint32_t f = 0; s == TR_OK && f < sub->n; f++) {
      const uint32_t *v = sub->v + 3 * (size_t)f;
      uint32_t g = c->fc.group[sub->tri[f]];
      if (tr_facets_size(&c->fc, g) == 1)
        continue;
      for (int e = 0; e < 3 && s == TR_OK; e++) {
        uint32_t k[3] = {v[e] < v[(e + 1) % 3] ? v[e] : v[(e + 1) % 3],
                         v[e] < v[(e + 1) % 3] ? v[(e + 1) % 3] : v[e], g};
        uint32_t old = tr_vtmap_get(&cnt, 3, k);
        s = tr_vtmap_set(&cnt, 3, k, old == TR_VTMAP_NONE ? 1 : old + 1);
      }
    }
  }
  for (uint32_t f = 0; s == TR_OK && f < sub->n; f++) {
    const uint32_t *v = sub->v + 3 * (size_t)f, tri = sub->tri[f];
    uint32_t g = c->fc.group[tri];
    uint32_t sf;
    if ((s = rf_subface_add(c, v[0], v[1], v[2], g, &sf)) != TR_OK)
      break;
    if (c->par.sub_exported)
      c->sfexp[sf] = tri;
    for (int e = 0; e < 3; e++) {
      uint32_t u = v[e], w = v[(e + 1) % 3];
      if (tr_edgeset_get(&c->es, u, w) != TR_EDGESET_NONE)
        continue;
      int bdry = 0;
      if (tr_facets_size(&c->fc, g) > 1) {
        uint32_t k[3] = {u < w ? u : w, u < w ? w : u, g};
        bdry = tr_vtmap_get(&cnt, 3, k) == 1;
      }
      uint32_t A, B, id;
      input_edge_of(c, u, w, tri, bdry, &A, &B, line);
      if (A == TR_NONE)
        continue;
      if ((s = rf_subseg_add(c, u, w, A, B, &id)) != TR_OK)
        break;
      if (u >= plc->npoints) {
        c->vkind[u] = RF_SEG;
        c->vown[u] = id;
      }
      if (w >= plc->npoints) {
        c->vkind[w] = RF_SEG;
        c->vown[w] = id;
      }
    }
  }
  tr_vtmap_free(&cnt);
  if (!c->par.memo)
    free(line);
  else if (line)
    c->par.memo->n = m->nv;
  TR_CHECK(s);
  for (uint32_t f = 0; f < c->nsf; f++)
    for (int i = 0; i < 3; i++) {
      uint32_t u = c->sfv[3 * (size_t)f + i];
      if (c->vkind[u] == RF_FREE) {
        c->vkind[u] = RF_FACET;
        c->vown[u] = c->sftri[f];
      }
    }
  return TR_OK;
}

#ifndef NDEBUG
/* The copied tables are those a set-up from scratch builds, slot for slot. */
static void check_copy(const rf_ctx *c, const tr_subfaces *sub)
{
  rf_ctx f;
  tr_refine_stats st;
  memset(&f, 0, sizeof f);
  f.m = c->m;
  f.plc = c->plc;
  f.par = c->par;
  f.par.memo = NULL;
  f.st = &st;
  if (build_tables(&f, sub) != TR_OK) {
    tr_error_clear(); /* out of memory: nothing to compare */
    free(f.vrad);
    free(f.vspace);
    rf_tables_free(&f);
    return;
  }
  uint32_t nv = c->m->nv;
  assert(f.nsf == c->nsf && f.nss == c->nss);
  assert(!memcmp(f.sfv, c->sfv, sizeof *f.sfv * 3 * (size_t)f.nsf));
  assert(!memcmp(f.sftri, c->sftri, sizeof *f.sftri * (size_t)f.nsf));
  assert(!memcmp(f.sfexp, c->sfexp, sizeof *f.sfexp * (size_t)f.nsf));
  assert(!memcmp(f.ssv, c->ssv, sizeof *f.ssv * 2 * (size_t)f.nss));
  assert(!memcmp(f.ssab, c->ssab, sizeof *f.ssab * 2 * (size_t)f.nss));
  assert(!memcmp(f.vkind, c->vkind, nv) && !memcmp(f.vown, c->vown, sizeof *f.vown * nv));
  for (uint32_t i = 0; i < f.nsf; i++) /* a build sets no flag */
    assert(!c->sfdead[i] && !c->sfnosplit[i]);
  for (uint32_t i = 0; i < f.nss; i++)
    assert(!c->ssdead[i] && !c->ssnosplit[i]);
  assert_same_plc_tables(&f, c);
  assert(same_map(&f.fm, &c->fm) && same_map(&f.es.m, &c->es.m));
  free(f.vrad);
  free(f.vspace);
  rf_tables_free(&f); /* last: it zeroes f */
}
#endif

tr_status rf_subs_init(rf_ctx *c, const tr_subfaces *sub)
{
  if (!rf_memo_fits(c, sub)) {
    TR_CHECK(build_tables(c, sub));
    rf_memo_keep(c, sub);
    return TR_OK;
  }
  TR_CHECK(rf_vertex_room(c, c->m->nv + 1));
  TR_CHECK(rf_memo_copy(c));
  c->st->merged_edges = c->fc.ninner;
#ifndef NDEBUG
  check_copy(c, sub);
#endif
  return TR_OK;
}

typedef struct {
  uint32_t tri, v[3];
} sf_rec;

static int cmp_sf(const void *pa, const void *pb)
{
  const sf_rec *a = pa, *b = pb;
  if (a->tri != b->tri)
    return a->tri < b->tri ? -1 : 1;
  return tr_cmp_face_key(a->v, b->v);
}

/* The input triangle of sub-face f: its facet's, or for a merged facet the facet's
 * smallest triangle that holds the sub-face's exact centroid (a sub-face may straddle
 * inner edges). */
static tr_status locate_triangle(const rf_ctx *c, uint32_t f, uint32_t *tri)
{
  uint32_t g = c->sftri[f];
  *tri = g;
  if (tr_facets_size(&c->fc, g) == 1)
    return TR_OK;
  tr_qpoint q;
  tr_qpoint_init(&q);
  tr_mesh_centroid_q(c->m, c->sfv + 3 * (size_t)f, &q);
  tr_point p = tr_pt_q(&q);
  *tri = rf_facet_triangle_of(c, g, &p, TR_NONE);
  tr_qpoint_clear(&q);
  if (*tri == TR_NONE)
    return tr_error(TR_ERR_INTERNAL, "refinement: sub-face %u lies outside its facet %u", f, g);
  return TR_OK;
}

/* locate_triangle's answer, known for the sub-faces of an exported input (a debug build
 * checks it) */
static tr_status export_triangle(const rf_ctx *c, uint32_t f, uint32_t *tri)
{
#ifdef NDEBUG
  if (c->sfexp[f] != TR_NONE) {
    *tri = c->sfexp[f];
    return TR_OK;
  }
#endif
  TR_CHECK(locate_triangle(c, f, tri));
  if (c->sfexp[f] != TR_NONE && c->sfexp[f] != *tri)
    return tr_error(TR_ERR_INTERNAL, "refinement: sub-face %u came in on triangle %u but "
                    "lies on %u", f, c->sfexp[f], *tri);
  return TR_OK;
}

tr_status rf_subs_export(const rf_ctx *c, tr_subfaces *out)
{
  uint32_t n = 0;
  for (uint32_t f = 0; f < c->nsf; f++)
    n += !c->sfdead[f];
  sf_rec *r = malloc(sizeof *r * (n ? n : 1));
  uint32_t *v = malloc(sizeof *v * 3 * (size_t)(n ? n : 1));
  uint32_t *tri = malloc(sizeof *tri * (n ? n : 1));
  if (!r || !v || !tri) {
    free(r);
    free(v);
    free(tri);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-faces", n);
  }
  uint32_t k = 0;
  tr_status st = TR_OK;
  for (uint32_t f = 0; f < c->nsf && st == TR_OK; f++)
    if (!c->sfdead[f]) {
      st = export_triangle(c, f, &r[k].tri);
      memcpy(r[k].v, c->sfv + 3 * (size_t)f, sizeof r[k].v);
      tr_rotate_min3(r[k].v); /* same turn: the orientation is kept */
      k++;
    }
  if (st != TR_OK) {
    free(r);
    free(v);
    free(tri);
    return st;
  }
  /* The sub-faces that came in are in their exported order already when they came from an
   * export (the sliver stage's set-ups, one per trial): only the run after the sorted
   * prefix is sorted, then merged with it (the qsort of every record was a tenth of a
   * trial on a mesh of 230k tets). No two records compare equal (distinct sub-faces). */
  uint32_t head = 1;
  while (head < n && cmp_sf(&r[head - 1], &r[head]) < 0)
    head++;
  if (head < n)
    qsort(r + head, n - head, sizeof *r, cmp_sf);
  for (uint32_t i = 0, j = head, o = 0; o < n; o++) {
    const sf_rec *x = j >= n || (i < head && cmp_sf(&r[i], &r[j]) < 0) ? &r[i++] : &r[j++];
    memcpy(v + 3 * (size_t)o, x->v, sizeof x->v);
    tri[o] = x->tri;
  }
  free(r);
  tr_subfaces_free(out);
  out->n = n;
  out->v = v;
  out->tri = tri;
  return TR_OK;
}
