/* The shared vertex-tuple map (src/core/vtmap.h) against a brute-force list. */
#include <stdlib.h>
#include <string.h>

#include "core/vtmap.h"
#include "tcommon.h"

enum { NKEYS = 3000 };

/* Keys from a small id range so that repeats are common; a brute-force list of what the
 * map must hold (put keeps the value present, set overwrites it) decides every answer. */
static int agrees_with_brute_force(uint32_t arity, int filtered)
{
  static uint32_t keys[NKEYS][4], cur[NKEYS];
  tr_vtmap m = {0};
  uint32_t nk = 0;
  if (filtered) {
    EXPECT_OK(tr_vtmap_reserve(&m, arity, 4), "reserve");
    EXPECT_OK(tr_vtmap_filter(&m), "filter"); /* then grown through many rehashes */
  }
  for (int it = 0; it < NKEYS; it++) {
    uint32_t k[4] = {0, 0, 0, 0};
    for (uint32_t i = 0; i < arity; i++)
      k[i] = (uint32_t)(t_next() % 24);
    uint32_t val = (uint32_t)(t_next() % 1000), stored;
    uint32_t j = 0;
    while (j < nk && memcmp(keys[j], k, sizeof k) != 0)
      j++;
    if (j == nk) {
      memcpy(keys[nk], k, sizeof k);
      cur[nk++] = val;
    }
    if (t_next() % 4 == 0) {
      EXPECT_OK(tr_vtmap_set(&m, arity, k, val), "set");
      cur[j] = val;
    } else {
      EXPECT_OK(tr_vtmap_put(&m, arity, k, val, &stored), "put");
      EXPECT(stored == cur[j], "put keeps %u, got %u", cur[j], stored);
    }
  }
  EXPECT(m.n == nk, "%u keys held, %u distinct put", m.n, nk);
  for (uint32_t j = 0; j < nk; j++)
    EXPECT(tr_vtmap_get(&m, arity, keys[j]) == cur[j], "key %u: %u, expected %u", j,
           tr_vtmap_get(&m, arity, keys[j]), cur[j]);
  uint32_t absent[4] = {99, 99, 99, 99};
  EXPECT(tr_vtmap_get(&m, arity, absent) == TR_VTMAP_NONE, "an absent key is NONE");
  /* iteration visits every key once */
  uint32_t seen = 0;
  for (uint32_t s = 0; s < m.cap; s++)
    if (tr_vtmap_key(&m, s)) {
      seen++;
      const uint32_t *k = tr_vtmap_key(&m, s);
      uint32_t kk[4] = {0, 0, 0, 0};
      memcpy(kk, k, arity * sizeof *k);
      EXPECT(tr_vtmap_get(&m, arity, kk) == tr_vtmap_val(&m, s), "slot %u value", s);
    }
  EXPECT(seen == nk, "iteration saw %u of %u keys", seen, nk);
  /* clear keeps the memory and forgets the keys */
  uint32_t cap = m.cap;
  tr_vtmap_clear(&m);
  EXPECT(m.n == 0 && m.cap == cap, "clear: n %u cap %u (was %u)", m.n, m.cap, cap);
  for (uint32_t j = 0; j < nk; j++)
    EXPECT(tr_vtmap_get(&m, arity, keys[j]) == TR_VTMAP_NONE, "cleared key %u", j);
  tr_vtmap_free(&m);
  EXPECT(tr_vtmap_get(&m, arity, keys[0]) == TR_VTMAP_NONE && m.cap == 0, "freed map empty");
  return 0;
}

static int every_arity(void)
{
  for (uint32_t a = 1; a <= 4; a++)
    for (int filtered = 0; filtered < 2; filtered++)
      if (agrees_with_brute_force(a, filtered))
        return 1;
  return 0;
}

/* The filter never hides a key: every present key passes it, after growth and clear. */
static int filter_keeps_every_key(void)
{
  tr_vtmap m = {0};
  uint32_t k[3];
  EXPECT(tr_vtmap_filter(&m) == TR_ERR_INTERNAL, "a filter on a map without room");
  EXPECT_OK(tr_vtmap_reserve(&m, 3, 10), "reserve");
  EXPECT_OK(tr_vtmap_filter(&m), "filter");
  for (int round = 0; round < 2; round++) {
    for (uint32_t i = 0; i < 20000; i++) {
      tr_vtkey_face(i, 3 * i + 1, 7 * i + 2, k);
      EXPECT_OK(tr_vtmap_put(&m, 3, k, i, NULL), "put");
    }
    uint32_t absent_passed = 0;
    for (uint32_t i = 0; i < 20000; i++) {
      tr_vtkey_face(i, 3 * i + 1, 7 * i + 2, k);
      EXPECT(tr_vtmap_get(&m, 3, k) == i, "key %u lost (round %d)", i, round);
      tr_vtkey_face(i, 3 * i + 1, 7 * i + 3, k);
      EXPECT(tr_vtmap_get(&m, 3, k) == TR_VTMAP_NONE, "absent key %u found", i);
      uint32_t b = tr_vtmap_bit_(k, 3, m.cap);
      absent_passed += (uint32_t)(m.bits[b >> 6] >> (b & 63) & 1);
    }
    /* 8 bits per slot, at most half the slots used: at most 1 in 16 bits set */
    EXPECT(absent_passed < 20000 / 8, "the filter passes %u of 20000 absent keys",
           absent_passed);
    tr_vtmap_clear(&m);
    EXPECT(m.n == 0, "clear");
  }
  tr_vtmap_free(&m);
  return 0;
}

/* One map holds one kind of key: mixing edges and faces is a bug, refused. */
static int arity_is_fixed(void)
{
  tr_vtmap m = {0};
  uint32_t e[2] = {1, 2}, f[3] = {1, 2, 3};
  EXPECT_OK(tr_vtmap_put(&m, 2, e, 7, NULL), "edge");
  EXPECT(tr_vtmap_put(&m, 3, f, 8, NULL) == TR_ERR_INTERNAL, "a face in an edge map");
  EXPECT(tr_vtmap_get(&m, 3, f) == TR_VTMAP_NONE, "a face lookup in an edge map");
  EXPECT(tr_vtmap_reserve(&m, 5, 10) == TR_ERR_INTERNAL, "arity 5");
  tr_vtmap_free(&m);
  return 0;
}

/* Same insertions, same table, slot by slot: no seed, no address in the hash. */
static int deterministic_layout(void)
{
  tr_vtmap a = {0}, b = {0};
  for (uint32_t i = 0; i < 5000; i++) {
    uint32_t k[3];
    tr_vtkey_face(i * 7 % 1013, i * 13 % 997, i, k);
    EXPECT_OK(tr_vtmap_put(&a, 3, k, i, NULL), "a");
    EXPECT_OK(tr_vtmap_put(&b, 3, k, i, NULL), "b");
  }
  EXPECT(a.cap == b.cap && memcmp(a.slot, b.slot, (size_t)a.cap * 4 * sizeof *a.slot) == 0,
         "two builds differ");
  tr_vtmap_free(&a);
  tr_vtmap_free(&b);
  return 0;
}

/* A copy has the original's slots and filter, answers alone once the original is gone,
 * grows on its own, and replaces what the destination held. */
static int copy_is_independent(void)
{
  tr_vtmap a = {0}, b = {0};
  uint32_t k[2];
  EXPECT_OK(tr_vtmap_reserve(&a, 2, 64), "reserve");
  EXPECT_OK(tr_vtmap_filter(&a), "filter");
  for (uint32_t i = 0; i < 100; i++) {
    tr_vtkey_edge(i, i + 1, k);
    EXPECT_OK(tr_vtmap_put(&a, 2, k, i, NULL), "a");
  }
  tr_vtkey_edge(7, 70, k);
  EXPECT_OK(tr_vtmap_put(&b, 2, k, 1, NULL), "b before the copy");
  EXPECT_OK(tr_vtmap_copy(&b, &a), "copy");
  EXPECT(b.cap == a.cap && b.n == a.n && b.bits &&
             !memcmp(b.slot, a.slot, (size_t)a.cap * 3 * sizeof *a.slot) &&
             !memcmp(b.bits, a.bits, (size_t)a.cap / 8 * sizeof *a.bits),
         "the copy's table differs");
  EXPECT(tr_vtmap_get(&b, 2, k) == TR_VTMAP_NONE, "the copy kept the destination's key");
  tr_vtmap_free(&a);
  for (uint32_t i = 0; i < 100; i++) {
    tr_vtkey_edge(i + 1, i, k);
    EXPECT(tr_vtmap_get(&b, 2, k) == i, "the copy lost key %u", i);
  }
  for (uint32_t i = 100; i < 1000; i++) { /* past its capacity */
    tr_vtkey_edge(i, i + 1, k);
    EXPECT_OK(tr_vtmap_set(&b, 2, k, i), "grow");
  }
  tr_vtkey_edge(999, 1000, k);
  EXPECT(tr_vtmap_get(&b, 2, k) == 999 && b.n == 1000, "the copy did not grow");
  tr_vtmap empty = {0}, c = {0};
  EXPECT_OK(tr_vtmap_copy(&c, &empty), "copy of an empty map");
  EXPECT(c.n == 0 && !c.slot, "an empty map's copy holds something");
  tr_vtmap_free(&b);
  return 0;
}

/* Unoriented keys: an edge or a face read from either side is one key. */
static int unoriented_keys(void)
{
  uint32_t k1[3], k2[3], e1[2], e2[2];
  tr_vtkey_face(9, 4, 6, k1);
  tr_vtkey_face(6, 9, 4, k2);
  EXPECT(!memcmp(k1, k2, sizeof k1) && k1[0] == 4 && k1[1] == 6 && k1[2] == 9, "face key");
  tr_vtkey_edge(5, 2, e1);
  tr_vtkey_edge(2, 5, e2);
  EXPECT(!memcmp(e1, e2, sizeof e1) && e1[0] == 2, "edge key");
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  const char *c = argv[1];
  if (!strcmp(c, "brute"))
    return every_arity();
  if (!strcmp(c, "filter"))
    return filter_keeps_every_key();
  if (!strcmp(c, "arity"))
    return arity_is_fixed();
  if (!strcmp(c, "layout"))
    return deterministic_layout();
  if (!strcmp(c, "keys"))
    return unoriented_keys();
  if (!strcmp(c, "copy"))
    return copy_is_independent();
  return 2;
}
