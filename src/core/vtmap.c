/* Vertex-tuple hash map (see vtmap.h). */
#include "core/vtmap.h"

#include <stdlib.h>
#include <string.h>

/* The slot holding key, or the empty slot where it would go. cap > 0. */
static uint32_t *find(const tr_vtmap *m, const uint32_t *key)
{
  switch (m->arity) {
  case 1: return tr_vtmap_find_(m, 1, key);
  case 2: return tr_vtmap_find_(m, 2, key);
  case 3: return tr_vtmap_find_(m, 3, key);
  default: return tr_vtmap_find_(m, 4, key);
  }
}

void tr_vtmap_free(tr_vtmap *m)
{
  free(m->slot);
  free(m->bits);
  memset(m, 0, sizeof *m);
}

void tr_vtmap_clear(tr_vtmap *m)
{
  if (m->slot)
    memset(m->slot, 0xff, (size_t)m->cap * (m->arity + 1) * sizeof *m->slot);
  if (m->bits)
    memset(m->bits, 0, (size_t)m->cap / 8 * sizeof *m->bits);
  m->n = 0;
}

static tr_status check_arity(tr_vtmap *m, uint32_t arity)
{
  if (arity < 1 || arity > 4 || (m->arity && m->arity != arity))
    return tr_error(TR_ERR_INTERNAL, "vertex-tuple map of arity %u used with arity %u",
                    m->arity, arity);
  m->arity = arity;
  return TR_OK;
}

static void mark(tr_vtmap *m, const uint32_t *key)
{
  uint32_t b = tr_vtmap_bit_(key, m->arity, m->cap);
  m->bits[b >> 6] |= 1ull << (b & 63);
}

/* The filter of every key, at the current capacity (cap >= 16: a whole number of words). */
static tr_status refilter(tr_vtmap *m)
{
  uint64_t *bits = calloc(m->cap / 8, sizeof *bits);
  if (!bits)
    return tr_error(TR_ERR_NOMEM, "out of memory for a filter of %u vertex-tuple keys", m->n);
  free(m->bits);
  m->bits = bits;
  for (uint32_t i = 0; i < m->cap; i++) {
    const uint32_t *k = m->slot + (uint64_t)i * (m->arity + 1);
    if (k[0] != TR_VTMAP_NONE)
      mark(m, k);
  }
  return TR_OK;
}

static tr_status rehash(tr_vtmap *m, uint32_t cap)
{
  uint32_t w = m->arity + 1;
  uint32_t *s = malloc((size_t)cap * w * sizeof *s);
  if (!s)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex-tuple keys", m->n);
  memset(s, 0xff, (size_t)cap * w * sizeof *s);
  tr_vtmap g = {s, m->n, cap, m->arity, m->bits};
  for (uint32_t i = 0; i < m->cap; i++) {
    const uint32_t *o = m->slot + (uint64_t)i * w;
    if (o[0] != TR_VTMAP_NONE)
      memcpy(find(&g, o), o, w * sizeof *o);
  }
  free(m->slot);
  *m = g;
  return m->bits ? refilter(m) : TR_OK;
}

tr_status tr_vtmap_copy(tr_vtmap *dst, const tr_vtmap *src)
{
  tr_vtmap_free(dst);
  tr_vtmap d = {NULL, src->n, src->cap, src->arity, NULL};
  size_t ns = (size_t)src->cap * (src->arity + 1);
  if (src->slot && !(d.slot = malloc(ns * sizeof *d.slot)))
    return tr_error(TR_ERR_NOMEM, "out of memory for a copy of %u vertex-tuple keys", src->n);
  if (src->bits && !(d.bits = malloc((size_t)src->cap / 8 * sizeof *d.bits))) {
    free(d.slot);
    return tr_error(TR_ERR_NOMEM, "out of memory for a copy of %u vertex-tuple keys", src->n);
  }
  if (d.slot)
    memcpy(d.slot, src->slot, ns * sizeof *d.slot);
  if (d.bits)
    memcpy(d.bits, src->bits, (size_t)src->cap / 8 * sizeof *d.bits);
  *dst = d;
  return TR_OK;
}

tr_status tr_vtmap_filter(tr_vtmap *m)
{
  if (!m->cap)
    return tr_error(TR_ERR_INTERNAL, "vertex-tuple map: a filter before the map has room");
  return m->bits ? TR_OK : refilter(m);
}

tr_status tr_vtmap_reserve(tr_vtmap *m, uint32_t arity, uint32_t n)
{
  TR_CHECK(check_arity(m, arity));
  if (n > (1u << 29))
    return tr_error(TR_ERR_NOMEM, "vertex-tuple map: %u keys exceed 2^29", n);
  uint32_t cap = 16;
  while (cap < 2 * n)
    cap *= 2;
  return cap > m->cap ? rehash(m, cap) : TR_OK;
}

static tr_status slot_for(tr_vtmap *m, uint32_t arity, const uint32_t *key, uint32_t **s)
{
  TR_CHECK(check_arity(m, arity));
  if (2 * ((uint64_t)m->n + 1) > m->cap) {
    if (m->cap >= (1u << 30))
      return tr_error(TR_ERR_NOMEM, "vertex-tuple map: more than 2^29 keys");
    TR_CHECK(rehash(m, m->cap ? 2 * m->cap : 16));
  }
  *s = find(m, key);
  return TR_OK;
}

tr_status tr_vtmap_put(tr_vtmap *m, uint32_t arity, const uint32_t *key, uint32_t val,
                       uint32_t *stored)
{
  uint32_t *s = NULL;
  TR_CHECK(slot_for(m, arity, key, &s));
  if (s[0] == TR_VTMAP_NONE) {
    memcpy(s, key, arity * sizeof *key);
    s[arity] = val;
    m->n++;
    if (m->bits)
      mark(m, key);
  }
  if (stored)
    *stored = s[arity];
  return TR_OK;
}

tr_status tr_vtmap_set(tr_vtmap *m, uint32_t arity, const uint32_t *key, uint32_t val)
{
  uint32_t *s = NULL;
  TR_CHECK(slot_for(m, arity, key, &s));
  if (s[0] == TR_VTMAP_NONE) {
    memcpy(s, key, arity * sizeof *key);
    m->n++;
    if (m->bits)
      mark(m, key);
  }
  s[arity] = val;
  return TR_OK;
}
