/* The hash map of vertex tuples every stage uses: a key of 1 to 4 vertex ids (a vertex,
 * an edge, a face, a tet listing) to a uint32 value.
 *
 * Keys compare as written: where the orientation must not matter (an edge or a face
 * seen from either side) the caller sorts the tuple first, with tr_vtkey_edge /
 * tr_vtkey_face below, so one map serves both oriented and unoriented keys.
 *
 * Open addressing with linear probing at load <= 1/2, keys and values interleaved so a
 * probe touches one cache line, and a fixed multiplicative hash: no seed, no address,
 * so every run probes the same way. Entries are never removed one by one (a stale entry
 * is the callers' business: they store ids that they can check); tr_vtmap_clear empties
 * the whole map and keeps its memory for the next use. A zeroed struct is an empty map;
 * its arity is fixed by the first insertion or reservation. */
#ifndef TR_CORE_VTMAP_H
#define TR_CORE_VTMAP_H

#include <stdint.h>

#include "core/status.h"

#define TR_VTMAP_NONE UINT32_MAX

typedef struct tr_vtmap {
  uint32_t *slot; /* (arity + 1) per slot: the key, then the value; an empty slot's key
                     starts with TR_VTMAP_NONE (no vertex has that id) */
  uint32_t n, cap; /* cap: 0 or a power of two */
  uint32_t arity;  /* 1..4, 0 while the map has never held anything */
  uint64_t *bits;  /* NULL, or the filter (tr_vtmap_filter): 16 bits per slot pair */
} tr_vtmap;

void tr_vtmap_free(tr_vtmap *m);
/* Empties the map, keeping its memory and arity. */
void tr_vtmap_clear(tr_vtmap *m);
/* dst = an exact copy of src (same slots, filter and capacity: the same probes and
 * the same order of keys); dst's memory is freed first. */
tr_status tr_vtmap_copy(tr_vtmap *dst, const tr_vtmap *src);
/* Room for n keys of the given arity without growing (a hint: put grows anyway). */
tr_status tr_vtmap_reserve(tr_vtmap *m, uint32_t arity, uint32_t n);
/* Turns on a filter for maps probed mostly for absent keys (every face of a mesh against
 * its few sub-faces): one bit per key's hash in a table of 8 bits per slot, which stays
 * in cache where the slots do not, so most misses cost one bit test. Kept up to date by
 * every insertion and growth. Call it after tr_vtmap_reserve or a first insertion. */
tr_status tr_vtmap_filter(tr_vtmap *m);
/* Inserts key -> val unless the key is there. *stored (may be NULL) receives the value
 * the map holds for the key afterwards: val, or the older value that was kept. */
tr_status tr_vtmap_put(tr_vtmap *m, uint32_t arity, const uint32_t *key, uint32_t val,
                       uint32_t *stored);
/* Inserts or overwrites. */
tr_status tr_vtmap_set(tr_vtmap *m, uint32_t arity, const uint32_t *key, uint32_t val);
/* The probe sequence, inline so that a call with a constant arity compiles to a
 * straight comparison (the face map of tr_mesh_find_faces is probed for every face of
 * every tet). */
static inline uint64_t tr_vtmap_hash_(const uint32_t *key, uint32_t arity)
{
  static const uint64_t mult[4] = {0x9e3779b97f4a7c15ull, 0xc2b2ae3d27d4eb4full,
                                   0x165667b19e3779f9ull, 0xd6e8feb86659fd93ull};
  uint64_t h = 0;
  for (uint32_t i = 0; i < arity; i++)
    h ^= (key[i] + 1ull) * mult[i];
  return h;
}
/* The slot a probe starts at: the high bits of the hash mix every key bit (the low ones
 * of a product do not); the filter takes its bit from the low half. */
static inline uint32_t tr_vtmap_home_(const uint32_t *key, uint32_t arity, uint32_t cap)
{
  return (uint32_t)(tr_vtmap_hash_(key, arity) >> 32) & (cap - 1);
}
static inline uint32_t tr_vtmap_bit_(const uint32_t *key, uint32_t arity, uint32_t cap)
{
  return (uint32_t)tr_vtmap_hash_(key, arity) & (8 * cap - 1);
}
static inline uint32_t *tr_vtmap_find_(const tr_vtmap *m, uint32_t arity, const uint32_t *key)
{
  uint32_t w = arity + 1, mask = m->cap - 1;
  for (uint32_t i = tr_vtmap_home_(key, arity, m->cap);; i = (i + 1) & mask) {
    uint32_t *s = m->slot + (uint64_t)i * w, same = 1;
    for (uint32_t j = 0; j < arity; j++)
      same &= s[j] == key[j];
    if (same || s[0] == TR_VTMAP_NONE)
      return s;
  }
}
/* The value of key, TR_VTMAP_NONE if absent. m may be NULL (empty). */
static inline uint32_t tr_vtmap_get(const tr_vtmap *m, uint32_t arity, const uint32_t *key)
{
  if (!m || !m->cap || m->arity != arity)
    return TR_VTMAP_NONE;
  if (m->bits) {
    uint32_t b = tr_vtmap_bit_(key, arity, m->cap);
    if (!(m->bits[b >> 6] >> (b & 63) & 1))
      return TR_VTMAP_NONE;
  }
  return tr_vtmap_find_(m, arity, key)[arity];
}
/* Iteration: slots 0..cap-1; tr_vtmap_key is NULL for an empty slot. */
static inline const uint32_t *tr_vtmap_key(const tr_vtmap *m, uint32_t slot)
{
  const uint32_t *s = m->slot + (uint64_t)slot * (m->arity + 1);
  return s[0] == TR_VTMAP_NONE ? (const uint32_t *)0 : s;
}
static inline uint32_t tr_vtmap_val(const tr_vtmap *m, uint32_t slot)
{
  return m->slot[(uint64_t)slot * (m->arity + 1) + m->arity];
}

/* Canonical unoriented keys. */
static inline void tr_vtkey_edge(uint32_t u, uint32_t v, uint32_t k[2])
{
  k[0] = u < v ? u : v;
  k[1] = u < v ? v : u;
}
static inline void tr_vtkey_face(uint32_t a, uint32_t b, uint32_t c, uint32_t k[3])
{
  if (a > b) { uint32_t t = a; a = b; b = t; }
  if (b > c) { uint32_t t = b; b = c; c = t; }
  if (a > b) { uint32_t t = a; a = b; b = t; }
  k[0] = a;
  k[1] = b;
  k[2] = c;
}

#endif
