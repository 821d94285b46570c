/* The fuzz targets' byte stream (fuzz_pipeline, fuzz_resolve): bits in order, least
 * significant first, zeros once the input is exhausted, so every input decodes. */
#ifndef TR_FUZZ_BITRD_H
#define TR_FUZZ_BITRD_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
  const uint8_t *d;
  size_t n, pos;
  uint32_t acc;
  int nacc;
} bitrd;

/* The next k bits (k <= 24). */
static inline uint32_t bits(bitrd *r, int k)
{
  while (r->nacc < k) {
    uint32_t b = r->pos < r->n ? r->d[r->pos] : 0;
    r->pos++;
    r->acc |= b << r->nacc;
    r->nacc += 8;
  }
  uint32_t v = r->acc & ((1u << k) - 1u);
  r->acc >>= k;
  r->nacc -= k;
  return v;
}

#endif
