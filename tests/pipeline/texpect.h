/* The counting check of the end-to-end tests (test_pipeline, test_round, tests/hard): a
 * failed EXPECT prints where and why and counts, the case goes on so that one run
 * reports every violated property; main returns failures != 0. */
#ifndef TR_TESTS_PIPELINE_TEXPECT_H
#define TR_TESTS_PIPELINE_TEXPECT_H

#include <stdio.h>

static int failures;
#define EXPECT(cond, ...)                                               \
  do {                                                                  \
    if (!(cond)) {                                                      \
      fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);              \
      fprintf(stderr, __VA_ARGS__);                                     \
      fprintf(stderr, "\n");                                            \
      failures++;                                                       \
    }                                                                   \
  } while (0)

#endif
