/* Tiny test harness for tests/exact: each executable runs one named property chosen by
 * argv[1]; CHECK prints the property and the failing condition and counts failures. */
#ifndef TR_TESTS_EXACT_CHECK_H
#define TR_TESTS_EXACT_CHECK_H

#include <stdio.h>
#include <string.h>

static int check_failures;
static int check_count;
static const char *check_property = "";

#define CHECK(cond, ...)                                                                \
  do {                                                                                  \
    check_count++;                                                                      \
    if (!(cond)) {                                                                      \
      check_failures++;                                                                 \
      if (check_failures <= 20) {                                                       \
        fprintf(stderr, "FAIL [%s] %s:%d: %s: ", check_property, __FILE__, __LINE__,    \
                #cond);                                                                 \
        fprintf(stderr, __VA_ARGS__);                                                   \
        fputc('\n', stderr);                                                            \
      }                                                                                 \
    }                                                                                   \
  } while (0)

typedef struct check_case {
  const char *name;
  void (*fn)(void);
} check_case;

/* Runs the case named argv[1] (all cases without argument). */
static int check_main(int argc, char **argv, const check_case *cases, int n)
{
  int ran = 0;
  for (int i = 0; i < n; i++) {
    if (argc > 1 && strcmp(argv[1], cases[i].name) != 0)
      continue;
    check_property = cases[i].name;
    int before = check_count;
    cases[i].fn();
    ran++;
    if (check_count == before) {
      fprintf(stderr, "FAIL [%s]: asserted nothing\n", cases[i].name);
      check_failures++;
    }
  }
  if (!ran) {
    fprintf(stderr, "unknown property '%s'\n", argc > 1 ? argv[1] : "");
    return 2;
  }
  if (check_failures) {
    fprintf(stderr, "%d of %d checks failed\n", check_failures, check_count);
    return 1;
  }
  printf("%d checks passed\n", check_count);
  return 0;
}

/* Deterministic xorshift64* generator (same sequence everywhere). */
static unsigned long long check_rng_state = 0x9E3779B97F4A7C15ull;
static inline unsigned long long check_rand(void)
{
  unsigned long long x = check_rng_state;
  x ^= x >> 12;
  x ^= x << 25;
  x ^= x >> 27;
  check_rng_state = x;
  return x * 0x2545F4914F6CDD1Dull;
}
/* uniform integer in [lo, hi] */
static inline long check_irand(long lo, long hi)
{
  return lo + (long)(check_rand() % (unsigned long long)(hi - lo + 1));
}

#endif
