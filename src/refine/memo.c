/* What a tr_refine_memo keeps from one refinement set-up for the next (refine.h,
 * refine_impl.h): per vertex the input edge it was found on, and the tables of the last
 * set-up. Each only saves time: a debug build checks them against the full set-up
 * (subs.c). */
#include <stdlib.h>
#include <string.h>

#include "refine/refine_impl.h"

/* The tables of the last set-up built with a memo, and what they were built from. The
 * sliver polish's trials (caps.c) set up refinement again and again, each trial undone
 * when it opens nothing: 1,418 set-ups on the quality bench's 74 models, 3.0 of its 52 s,
 * 1,079 of them on the same sub-faces as the set-up before, which copy these tables
 * instead (2.2 s then: on the largest meshes most trials are kept, and each kept one
 * changes the sub-faces). */
struct rf_subs_cache {
  int have; /* the tables below are those of sub */
  const struct tr_plc *plc;
  int keep_edges, sub_exported;
  tr_subfaces sub; /* a copy of the sub-faces the tables were built from */
  uint32_t nv;     /* the mesh's vertices then: the kinds and owners of ids below it */
  rf_ctx t;        /* the tables only: fc, the sub-face and sub-segment arrays, fm,
                      trimap, es, and vkind, vown (nv of them) */
};

void rf_tables_free(rf_ctx *t)
{
  tr_facets_free(&t->fc);
  free(t->sfv);
  free(t->sftri);
  free(t->sfexp);
  free(t->sfdead);
  free(t->sfnosplit);
  tr_vtmap_free(&t->fm);
  tr_vtmap_free(&t->trimap);
  rf_caps_free(&t->caps);
  free(t->ssv);
  free(t->ssab);
  free(t->ssdead);
  free(t->ssnosplit);
  tr_edgeset_free(&t->es);
  free(t->vkind);
  free(t->vown);
  memset(t, 0, sizeof *t);
}

static void cache_free(struct rf_subs_cache *k)
{
  if (!k)
    return;
  rf_tables_free(&k->t);
  tr_subfaces_free(&k->sub);
  free(k);
}

void tr_refine_memo_free(tr_refine_memo *memo)
{
  free(memo->line);
  cache_free(memo->subs);
  memset(memo, 0, sizeof *memo);
}

/* *dst = a copy of n elements of size w at src (NULL for none); 0 when out of memory */
static int dup_array(void *dst, const void *src, size_t n, size_t w)
{
  void *p = NULL;
  if (src && n && !(p = malloc(n * w)))
    return 0;
  if (p)
    memcpy(p, src, n * w);
  memcpy(dst, &p, sizeof p);
  return 1;
}

/* The tables of src into dst, whose own are empty; vkind and vown for the ids below nv.
 * to_cache: dst is the cache, whose vertex arrays are allocated here (a context's come
 * from rf_vertex_room). */
static tr_status tables_copy(rf_ctx *dst, const rf_ctx *src, uint32_t nv, int to_cache)
{
  TR_CHECK(tr_facets_copy(&dst->fc, &src->fc));
  size_t f = src->nsf, g = src->nss;
  dst->nsf = dst->capsf = src->nsf;
  dst->nss = dst->capss = src->nss;
  int ok = dup_array(&dst->sfv, src->sfv, 3 * f, sizeof *src->sfv) &&
           dup_array(&dst->sftri, src->sftri, f, sizeof *src->sftri) &&
           dup_array(&dst->sfexp, src->sfexp, f, sizeof *src->sfexp) &&
           dup_array(&dst->sfdead, src->sfdead, f, 1) &&
           dup_array(&dst->sfnosplit, src->sfnosplit, f, 1) &&
           dup_array(&dst->ssv, src->ssv, 2 * g, sizeof *src->ssv) &&
           dup_array(&dst->ssab, src->ssab, 2 * g, sizeof *src->ssab) &&
           dup_array(&dst->ssdead, src->ssdead, g, 1) &&
           dup_array(&dst->ssnosplit, src->ssnosplit, g, 1);
  if (to_cache)
    ok = ok && dup_array(&dst->vkind, src->vkind, nv, 1) &&
         dup_array(&dst->vown, src->vown, nv, sizeof *src->vown);
  else if (nv) {
    memcpy(dst->vkind, src->vkind, nv);
    memcpy(dst->vown, src->vown, sizeof *src->vown * (size_t)nv);
  }
  if (!ok)
    return tr_error(TR_ERR_NOMEM, "out of memory for a copy of %u sub-faces' tables", src->nsf);
  TR_CHECK(tr_vtmap_copy(&dst->fm, &src->fm));
  TR_CHECK(tr_vtmap_copy(&dst->trimap, &src->trimap));
  TR_CHECK(rf_caps_copy(&dst->caps, &src->caps, dst->plc ? dst->plc : src->plc));
  return tr_vtmap_copy(&dst->es.m, &src->es.m);
}

int rf_memo_fits(const rf_ctx *c, const tr_subfaces *sub)
{
  const tr_refine_memo *memo = c->par.memo;
  const struct rf_subs_cache *k = memo ? memo->subs : NULL;
  return k && k->have && k->plc == c->plc && k->keep_edges == c->par.keep_edges &&
         k->sub_exported == c->par.sub_exported && k->nv <= memo->n && k->nv <= c->m->nv &&
         k->sub.n == sub->n &&
         !memcmp(k->sub.v, sub->v, sizeof *sub->v * 3 * (size_t)sub->n) &&
         !memcmp(k->sub.tri, sub->tri, sizeof *sub->tri * (size_t)sub->n);
}

void rf_memo_keep(rf_ctx *c, const tr_subfaces *sub)
{
  tr_refine_memo *memo = c->par.memo;
  if (!memo)
    return;
  if (!memo->subs && !(memo->subs = calloc(1, sizeof *memo->subs)))
    return;
  struct rf_subs_cache *k = memo->subs;
  k->have = 0;
  rf_tables_free(&k->t);
  tr_subfaces_free(&k->sub);
  k->plc = c->plc;
  k->keep_edges = c->par.keep_edges;
  k->sub_exported = c->par.sub_exported;
  k->nv = c->m->nv;
  k->sub.n = sub->n;
  if (!dup_array(&k->sub.v, sub->v, 3 * (size_t)sub->n, sizeof *sub->v) ||
      !dup_array(&k->sub.tri, sub->tri, sub->n, sizeof *sub->tri) ||
      tables_copy(&k->t, c, k->nv, 1) != TR_OK) {
    tr_error_clear();
    rf_tables_free(&k->t);
    tr_subfaces_free(&k->sub);
    return;
  }
  k->have = 1;
}

tr_status rf_memo_plc_tables(rf_ctx *c, int *have)
{
  const tr_refine_memo *memo = c->par.memo;
  const struct rf_subs_cache *k = memo ? memo->subs : NULL;
  *have = 0;
  if (!k || !k->have || k->plc != c->plc || k->keep_edges != c->par.keep_edges)
    return TR_OK;
  TR_CHECK(tr_facets_copy(&c->fc, &k->t.fc));
  TR_CHECK(tr_vtmap_copy(&c->trimap, &k->t.trimap));
  TR_CHECK(rf_caps_copy(&c->caps, &k->t.caps, c->plc));
  *have = 1;
  return TR_OK;
}

tr_status rf_memo_copy(rf_ctx *c)
{
  const struct rf_subs_cache *k = c->par.memo->subs;
  TR_CHECK(tables_copy(c, &k->t, k->nv, 0));
  c->par.memo->copies++;
  /* the vertices since: interior points (every vertex of the sub-faces is older) */
  for (uint32_t v = k->nv; v < c->m->nv; v++) {
    c->vkind[v] = v < c->plc->npoints ? RF_INPUT : RF_FREE;
    c->vown[v] = v < c->plc->npoints ? v : TR_NONE;
  }
  return TR_OK;
}

uint32_t *rf_memo_line(tr_refine_memo *memo, uint32_t nv)
{
  size_t n = nv ? nv : 1;
  if (!memo) {
    uint32_t *l = malloc(sizeof *l * 2 * n);
    if (l)
      memset(l, 0xff, sizeof *l * 2 * n);
    return l;
  }
  if (memo->cap < n) {
    uint32_t *l = realloc(memo->line, sizeof *l * 2 * n);
    if (!l)
      return NULL;
    memo->line = l;
    memo->cap = (uint32_t)n;
  }
  if (memo->n > nv)
    memo->n = nv;
  memset(memo->line + 2 * (size_t)memo->n, 0xff, sizeof *memo->line * 2 * (n - memo->n));
  return memo->line;
}
