/* Memo of segment-tet classifications (see segmemo.h). */
#include "recover_edges/segmemo.h"

#include <stdlib.h>
#include <string.h>

void tr_segmemo_init(tr_segmemo *g, const struct tr_mesh *m, uint32_t a, uint32_t b)
{
  memset(g, 0, sizeof *g);
  g->pa = tr_mesh_point(m, a);
  g->pb = tr_mesh_point(m, b);
}

void tr_segmemo_free(tr_segmemo *g)
{
  free(g->key);
  free(g->val);
  g->key = NULL;
  g->val = NULL;
  g->cap = g->n = 0;
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

static uint32_t slot(const tr_segmemo *g, const uint32_t v[4])
{
  uint64_t x = ((uint64_t)v[0] << 32 | v[1]) * 0x9E3779B97F4A7C15ull ^
               ((uint64_t)v[2] << 32 | v[3]) * 0xC2B2AE3D27D4EB4Full;
  uint32_t i = (uint32_t)(x >> 32) & (g->cap - 1);
  while (g->key[i][0] != TR_NONE && memcmp(g->key[i], v, 4 * sizeof *v) != 0)
    i = (i + 1) & (g->cap - 1);
  return i;
}

static void put(tr_segmemo *g, const uint32_t v[4], uint16_t r)
{
  if (2 * (g->n + 1) > g->cap) {
    uint32_t nc = g->cap ? 2 * g->cap : 256;
    tr_segmemo h = {g->pa, g->pb, malloc(nc * sizeof *h.key), malloc(nc * sizeof *h.val), nc,
                    0};
    if (!h.key || !h.val) {
      free(h.key);
      free(h.val);
      return;
    }
    memset(h.key, 0xff, nc * sizeof *h.key);
    for (uint32_t i = 0; i < g->cap; i++)
      if (g->key[i][0] != TR_NONE) {
        uint32_t k = slot(&h, g->key[i]);
        memcpy(h.key[k], g->key[i], sizeof h.key[k]);
        h.val[k] = g->val[i];
        h.n++;
      }
    free(g->key);
    free(g->val);
    *g = h;
  }
  uint32_t i = slot(g, v);
  if (g->key[i][0] == TR_NONE) {
    memcpy(g->key[i], v, sizeof g->key[i]);
    g->n++;
  }
  g->val[i] = r;
}

tr_isect tr_segmemo_classify(tr_segmemo *g, const struct tr_mesh *m, const uint32_t v[4])
{
  if (g->cap) {
    uint32_t i = slot(g, v);
    if (g->key[i][0] != TR_NONE)
      return unpack(g->val[i]);
  }
  tr_point p[4];
  const tr_point *pp[4];
  for (int k = 0; k < 4; k++) {
    p[k] = tr_mesh_point(m, v[k]);
    pp[k] = &p[k];
  }
  tr_isect x = tr_classify_segment_tet(&g->pa, &g->pb, pp);
  uint16_t r = pack(&x);
  put(g, v, r);
  return unpack(r);
}
