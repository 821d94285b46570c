/* Insertion order for Bowyer-Watson: duplicates removed, then BRIO (biased randomized
 * insertion order, Amenta-Choi-Rote) with every round sorted along a Hilbert curve, so
 * consecutive points are close (short walks, warm cache) while the rounds keep the
 * randomness that bounds the expected cavity sizes.
 *
 * One radix sort does all of it: a point's round comes from a hash of its coordinates
 * (round r from the end with probability 7/8^(r+1), the BRIO sample), and the key is
 * (round, Hilbert index). Equal points hash alike, so they share round and key and end
 * up next to each other, where the duplicates are found. The hash is of the coordinate
 * bits: same input, same order, on every machine. */
#include "delaunay.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#define KEY_BITS 16      /* per axis: 48-bit Hilbert indices */
#define ROUND_SHIFT 48   /* the round above them: at most 7 radix passes of 8 bits */
#define BRIO_RATIO 8     /* each round is 1/8 of the points that follow it */
#define BRIO_MIN 64      /* the first round holds about this many points or fewer */

/* The low 21 bits of x spread to every third bit (bit b to bit 3b). */
static inline uint64_t spread3(uint32_t x)
{
  uint64_t v = x & 0x1fffffu;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

/* Skilling's transposed Hilbert index ("Programming the Hilbert curve", 2004): undo the
 * excess work of the Gray code level by level, then Gray-encode; the transposed bits
 * interleaved from the top give the position along the curve. */
uint64_t tr_hilbert_key(uint32_t x, uint32_t y, uint32_t z, int bits)
{
  uint32_t X[3] = {x, y, z}, M = 1u << (bits - 1), t;
  for (uint32_t Q = M; Q > 1; Q >>= 1) {
    uint32_t P = Q - 1;
    for (int i = 0; i < 3; i++) {
      /* branch-free form of: if (X[i] & Q) X[0] ^= P; else swap the low bits of X[0]
       * and X[i] where they differ (the bits are data, so branches mispredict) */
      uint32_t set = 0u - ((X[i] & Q) != 0);
      t = (X[0] ^ X[i]) & P & ~set;
      X[0] ^= (P & set) | t;
      X[i] ^= t;
    }
  }
  X[1] ^= X[0];
  X[2] ^= X[1];
  /* t ^= Q - 1 for every set bit Q > 1 of X[2]: bit j of t is the parity of the bits of
   * X[2] above j, a suffix XOR of X[2] >> 1 */
  t = X[2] >> 1;
  t ^= t >> 1;
  t ^= t >> 2;
  t ^= t >> 4;
  t ^= t >> 8;
  t ^= t >> 16;
  X[0] ^= t;
  X[1] ^= t;
  X[2] ^= t;
  /* interleave from the top bit down, x first: bit b of X[i] goes to bit 3b + 2 - i */
  return spread3(X[0]) << 2 | spread3(X[1]) << 1 | spread3(X[2]);
}

typedef struct kv {
  uint64_t key;
  uint32_t idx;
} kv;

/* Stable LSD radix sort of a[0..n) by key (tmp: n entries). One read counts the digits
 * of every pass; passes whose digit is the same for every entry are skipped. */
static void radix_sort(kv *a, kv *tmp, size_t n)
{
  if (n < 32) {
    for (size_t i = 1; i < n; i++) {
      kv x = a[i];
      size_t j = i;
      while (j > 0 && a[j - 1].key > x.key) {
        a[j] = a[j - 1];
        j--;
      }
      a[j] = x;
    }
    return;
  }
  enum { PASSES = 7 };
  static_assert(ROUND_SHIFT + 4 <= 8 * PASSES, "the key fits the passes");
  uint32_t (*cnt)[256] = calloc(PASSES, sizeof *cnt);
  kv *src = a, *dst = tmp;
  if (!cnt) { /* no room for the tables: count pass by pass on the stack */
    for (int pass = 0; pass < PASSES; pass++) {
      uint32_t c1[256] = {0};
      const int sh = 8 * pass;
      for (size_t i = 0; i < n; i++)
        c1[(src[i].key >> sh) & 255]++;
      if (c1[(src[0].key >> sh) & 255] == n)
        continue;
      uint32_t sum = 0;
      for (int d = 0; d < 256; d++) {
        uint32_t c = c1[d];
        c1[d] = sum;
        sum += c;
      }
      for (size_t i = 0; i < n; i++)
        dst[c1[(src[i].key >> sh) & 255]++] = src[i];
      kv *s = src;
      src = dst;
      dst = s;
    }
  } else {
    for (size_t i = 0; i < n; i++) {
      const uint64_t k = a[i].key;
      for (int pass = 0; pass < PASSES; pass++)
        cnt[pass][(k >> 8 * pass) & 255]++;
    }
    for (int pass = 0; pass < PASSES; pass++) {
      uint32_t *c1 = cnt[pass];
      const int sh = 8 * pass;
      if (c1[(src[0].key >> sh) & 255] == n)
        continue;
      uint32_t sum = 0;
      for (int d = 0; d < 256; d++) {
        uint32_t c = c1[d];
        c1[d] = sum;
        sum += c;
      }
      for (size_t i = 0; i < n; i++)
        dst[c1[(src[i].key >> sh) & 255]++] = src[i];
      kv *s = src;
      src = dst;
      dst = s;
    }
    free(cnt);
  }
  if (src != a)
    memcpy(a, src, n * sizeof *a);
}

/* Lexicographic (x, y, z, index) order, for grouping exact duplicates. */
static int less_xyz(const double *xyz, uint32_t a, uint32_t b)
{
  const double *p = xyz + 3 * (size_t)a, *q = xyz + 3 * (size_t)b;
  for (int i = 0; i < 3; i++)
    if (p[i] != q[i])
      return p[i] < q[i];
  return a < b;
}

static void merge_sort_xyz(const double *xyz, uint32_t *a, uint32_t *tmp, size_t n)
{
  if (n < 16) {
    for (size_t i = 1; i < n; i++) {
      uint32_t x = a[i];
      size_t j = i;
      while (j > 0 && less_xyz(xyz, x, a[j - 1])) {
        a[j] = a[j - 1];
        j--;
      }
      a[j] = x;
    }
    return;
  }
  size_t h = n / 2;
  merge_sort_xyz(xyz, a, tmp, h);
  merge_sort_xyz(xyz, a + h, tmp, n - h);
  size_t i = 0, j = h, k = 0;
  while (i < h && j < n)
    tmp[k++] = less_xyz(xyz, a[j], a[i]) ? a[j++] : a[i++];
  while (i < h)
    tmp[k++] = a[i++];
  while (j < n)
    tmp[k++] = a[j++];
  memcpy(a, tmp, n * sizeof *a);
}

/* A 64-bit finaliser (the xorshift-multiply mixer of splitmix64): every input bit
 * reaches every output bit. */
static inline uint64_t mix64(uint64_t x)
{
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return x;
}

/* The hash of a point's value: -0.0 counts as 0.0, since those are the same point. */
static inline uint64_t point_hash(const double *p)
{
  uint64_t h = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 3; i++) {
    double x = p[i] == 0 ? 0.0 : p[i];
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    h = mix64(h ^ b);
  }
  return h;
}

tr_status tr_spatial_order(const double *xyz, uint32_t n, uint32_t *order, uint32_t *nuniq,
                           uint32_t *dup_map)
{
  *nuniq = 0;
  if (n == 0)
    return TR_OK;
  kv *a = malloc(n * sizeof *a), *tmp = malloc(n * sizeof *tmp);
  if (!a || !tmp) {
    free(a);
    free(tmp);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u points", n);
  }
  double lo[3], hi[3];
  for (int i = 0; i < 3; i++)
    lo[i] = hi[i] = xyz[i];
  for (uint32_t p = 1; p < n; p++)
    for (int i = 0; i < 3; i++) {
      double x = xyz[3 * (size_t)p + (size_t)i];
      if (x < lo[i])
        lo[i] = x;
      if (x > hi[i])
        hi[i] = x;
    }
  /* One scale for all axes keeps the curve's cells cubes in space. The quantisation only
   * steers the order: exactness never depends on it. */
  double ext = 0;
  for (int i = 0; i < 3; i++)
    if (hi[i] - lo[i] > ext)
      ext = hi[i] - lo[i];
  const double cells = (double)((1u << KEY_BITS) - 1);
  double scale = ext > 0 ? cells / ext : 0;
  /* rounds: the last holds 7/8 of the points, the one before 7/64, ...; the first takes
   * the rest, about BRIO_MIN points or fewer */
  uint32_t last = 0;
  for (uint64_t s = n; s > BRIO_MIN; s /= BRIO_RATIO)
    last++;
  for (uint32_t p = 0; p < n; p++) {
    const double *c = xyz + 3 * (size_t)p;
    uint32_t q[3];
    for (int i = 0; i < 3; i++) {
      double t = (c[i] - lo[i]) * scale;
      q[i] = t <= 0 ? 0 : t >= cells ? (uint32_t)cells : (uint32_t)t;
    }
    /* round r from the end iff the hash ends in exactly r zero octal digits: probability
     * 7/8^(r+1) (the first round, r = last, takes every longer run of zeros too) */
    const uint64_t h = point_hash(c);
    uint32_t r = 0;
    while (r < last && ((h >> 3 * r) & 7) == 0)
      r++;
    a[p].key = (uint64_t)(last - r) << ROUND_SHIFT | tr_hilbert_key(q[0], q[1], q[2], KEY_BITS);
    a[p].idx = p;
  }
  radix_sort(a, tmp, n);

  /* Exact duplicates share a key: group each run of equal keys by coordinates. The run
   * is sorted by (x, y, z, index) so the lowest index of a group comes first and is kept. */
  uint32_t *run = (uint32_t *)tmp, *rtmp = run + n; /* tmp has room for 4n uint32 */
  uint32_t m = 0;
  for (uint32_t i = 0; i < n;) {
    uint32_t j = i + 1;
    while (j < n && a[j].key == a[i].key)
      j++;
    if (j == i + 1) {
      dup_map[a[i].idx] = a[i].idx;
      order[m++] = a[i].idx;
      i = j;
      continue;
    }
    for (uint32_t k = i; k < j; k++)
      run[k - i] = a[k].idx;
    merge_sort_xyz(xyz, run, rtmp, j - i);
    for (uint32_t k = i; k < j; k++) {
      uint32_t p = run[k - i];
      /* numeric equality: -0.0 and 0.0 are the same point */
      const double *c = xyz + 3 * (size_t)p, *d = k > i ? xyz + 3 * (size_t)run[k - i - 1] : c;
      if (k > i && c[0] == d[0] && c[1] == d[1] && c[2] == d[2]) {
        dup_map[p] = dup_map[run[k - i - 1]];
      } else {
        dup_map[p] = p;
        order[m++] = p;
      }
    }
    i = j;
  }
  *nuniq = m;
  free(a);
  free(tmp);
  return TR_OK;
}
