/* The edge recovery tests' deterministic generator: a 64-bit LCG, seeded by each test. */
#ifndef TR_TEST_TRAND_H
#define TR_TEST_TRAND_H

#include <stdint.h>

static uint64_t rng;
static inline uint32_t next_u32(void)
{
  rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
  return (uint32_t)(rng >> 33);
}

#endif
