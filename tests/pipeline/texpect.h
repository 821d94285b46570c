/* The counting check of the tests: a failed EXPECT prints where and why and counts, the
 * case goes on so that one run reports every violated property; main returns
 * failures != 0. A test of one translation unit gets its own static counter; a test
 * split over several (tests/api) defines TEXPECT_SHARED_COUNTER before including this
 * and defines `int failures;` once, in the file holding main. */
#ifndef TR_TESTS_PIPELINE_TEXPECT_H
#define TR_TESTS_PIPELINE_TEXPECT_H

#include <stdio.h>

#ifdef TEXPECT_SHARED_COUNTER
extern int failures;
#else
static int failures;
#endif
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
