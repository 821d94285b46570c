/* Constraint edge hash map (see edgeset.h). */
#include "recover_edges/edgeset.h"

#include <stdlib.h>

static uint64_t edge_key(uint32_t u, uint32_t v)
{
  uint64_t lo = u < v ? u : v, hi = u < v ? v : u;
  return (lo << 32 | hi) + 1;
}

static size_t slot_of(uint64_t k, uint32_t cap)
{
  /* Fibonacci hashing: the high bits of k * 2^64/phi */
  return (size_t)((k * 0x9E3779B97F4A7C15ULL) >> 32) & (cap - 1);
}

void tr_edgeset_free(tr_edgeset *s)
{
  free(s->key);
  free(s->val);
  s->key = NULL;
  s->val = NULL;
  s->n = s->cap = 0;
}

static tr_status grow(tr_edgeset *s)
{
  if (s->cap >= (1u << 30))
    return tr_error(TR_ERR_NOMEM, "constraint edge set: more than 2^29 edges");
  uint32_t nc = s->cap ? 2 * s->cap : 64;
  uint64_t *k = calloc(nc, sizeof *k);
  uint32_t *v = malloc(nc * sizeof *v);
  if (!k || !v) {
    free(k);
    free(v);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u constraint edges", s->n);
  }
  for (uint32_t i = 0; i < s->cap; i++) {
    if (!s->key[i])
      continue;
    size_t j = slot_of(s->key[i], nc);
    while (k[j])
      j = (j + 1) & (nc - 1);
    k[j] = s->key[i];
    v[j] = s->val[i];
  }
  free(s->key);
  free(s->val);
  s->key = k;
  s->val = v;
  s->cap = nc;
  return TR_OK;
}

tr_status tr_edgeset_put(tr_edgeset *s, uint32_t u, uint32_t v, uint32_t val)
{
  /* load factor <= 1/2 keeps probe sequences short */
  if (2 * (s->n + 1) > s->cap)
    TR_CHECK(grow(s));
  uint64_t k = edge_key(u, v);
  size_t j = slot_of(k, s->cap);
  while (s->key[j]) {
    if (s->key[j] == k)
      return TR_OK;
    j = (j + 1) & (s->cap - 1);
  }
  s->key[j] = k;
  s->val[j] = val;
  s->n++;
  return TR_OK;
}

uint32_t tr_edgeset_get(const tr_edgeset *s, uint32_t u, uint32_t v)
{
  if (!s || !s->cap)
    return TR_EDGESET_NONE;
  uint64_t k = edge_key(u, v);
  for (size_t j = slot_of(k, s->cap); s->key[j]; j = (j + 1) & (s->cap - 1))
    if (s->key[j] == k)
      return s->val[j];
  return TR_EDGESET_NONE;
}
