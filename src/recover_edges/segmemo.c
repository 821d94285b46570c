/* Memo of segment-tet classifications (see segmemo.h). */
#include "recover_edges/segmemo.h"

#include <stdlib.h>
#include <string.h>

#include "mesh/orient_memo.h"

void tr_segmemo_init(tr_segmemo *g, const struct tr_mesh *m, uint32_t a, uint32_t b)
{
  (void)m;
  memset(g, 0, sizeof *g);
  g->a = a;
  g->b = b;
}

void tr_segmemo_free(tr_segmemo *g)
{
  tr_vtmap_free(&g->map);
}

/* n: 2 bits; per end: type 3 bits, code 4 bits (ECodes reach 15). */
static uint16_t pack(const tr_isect *x)
{
  unsigned r = (unsigned)x->n;
  for (int e = 0; e < 2; e++)
    r |= ((unsigned)x->end[e].type & 7u) << (2 + 7 * e) | ((unsigned)x->end[e].code & 15u)
                                                              << (5 + 7 * e);
  return (uint16_t)r;
}

static tr_isect unpack(uint16_t r)
{
  tr_isect x;
  memset(&x, 0, sizeof x);
  x.n = r & 3;
  for (int e = 0; e < 2; e++) {
    x.end[e].type = (uint8_t)((r >> (2 + 7 * e)) & 7u);
    x.end[e].code = (uint8_t)((r >> (5 + 7 * e)) & 15u);
  }
  return x;
}

/* The tet's vertices and the segment's ends by the numbers of tr_classify_segment_tet_o. */
typedef struct ids6 {
  const struct tr_mesh *m;
  uint32_t v[6];
} ids6;

static int o3_ids(void *ud, int p, int q, int r, int s)
{
  const ids6 *x = ud;
  return tr_mesh_orient(x->m, x->v[p], x->v[q], x->v[r], x->v[s]);
}

tr_isect tr_segmemo_classify_ids(const struct tr_mesh *m, uint32_t a, uint32_t b,
                                 const uint32_t v[4])
{
  ids6 x = {m, {v[0], v[1], v[2], v[3], a, b}};
  int sa = -1, sb = -1;
  for (int k = 0; k < 4; k++) {
    if (v[k] == a)
      sa = k;
    if (v[k] == b)
      sb = k;
  }
  return tr_classify_segment_tet_o(o3_ids, &x, sa, sb);
}

tr_isect tr_segmemo_classify(tr_segmemo *g, const struct tr_mesh *m, const uint32_t v[4])
{
  uint32_t known = tr_vtmap_get(&g->map, 4, v);
  if (known != TR_VTMAP_NONE)
    return unpack((uint16_t)known);
  tr_isect x = tr_segmemo_classify_ids(m, g->a, g->b, v);
  uint16_t r = pack(&x);
  /* a pipe's collection classifies some sixty tets: growing from 8 keys rehashed them
   * three times (failure leaves the map as it was: the put below grows it) */
  if (!g->map.cap)
    (void)tr_vtmap_reserve(&g->map, 4, 64);
  (void)tr_vtmap_put(&g->map, 4, v, r, NULL); /* no room: recomputed next time */
  return unpack(r);
}

void tr_segmemo_take(tr_segmemo_store *s, tr_segmemo *g, const struct tr_mesh *m, uint32_t a,
                     uint32_t b)
{
  tr_segmemo_free(g);
  tr_segmemo_init(g, m, a, b);
  uint32_t key[2] = {a, b}, i = tr_vtmap_get(&s->idx, 2, key);
  if (i == TR_VTMAP_NONE || !s->g[i].map.cap)
    return;
  *g = s->g[i];
  s->entries -= g->map.n;
  memset(&s->g[i], 0, sizeof s->g[i]);
}

void tr_segmemo_park(tr_segmemo_store *s, tr_segmemo *g)
{
  uint32_t a = g->a, b = g->b, key[2] = {a, b}, i = tr_vtmap_get(&s->idx, 2, key);
  int room = g->map.n && s->entries + g->map.n <= TR_SEGMEMO_STORE_MAX;
  if (room && i == TR_VTMAP_NONE) {
    if (s->n == s->cap) {
      uint32_t nc = s->cap ? 2 * s->cap : 64;
      tr_segmemo *q = realloc(s->g, nc * sizeof *q);
      room = q != NULL;
      if (q) {
        s->g = q;
        s->cap = nc;
      }
    }
    if (room && tr_vtmap_put(&s->idx, 2, key, s->n, NULL) == TR_OK) {
      i = s->n++;
      memset(&s->g[i], 0, sizeof s->g[i]);
    } else {
      room = 0;
    }
  }
  if (room && !s->g[i].map.cap) {
    s->g[i] = *g;
    s->entries += g->map.n;
    memset(g, 0, sizeof *g);
  }
  tr_segmemo_free(g);
  tr_segmemo_init(g, NULL, a, b);
}

void tr_segmemo_store_free(tr_segmemo_store *s)
{
  for (uint32_t i = 0; i < s->n; i++)
    tr_segmemo_free(&s->g[i]);
  free(s->g);
  tr_vtmap_free(&s->idx);
  memset(s, 0, sizeof *s);
}
