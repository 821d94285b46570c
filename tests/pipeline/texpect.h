/* The counting check of the tests: a failed EXPECT prints where and why and counts, the
 * case goes on so that one run reports every violated property; main returns
 * failures != 0. A test of one translation unit gets its own static counter; a test
 * split over several (tests/api) defines TEXPECT_SHARED_COUNTER before including this
 * and defines `int failures;` once, in the file holding main. */
#ifndef TR_TESTS_PIPELINE_TEXPECT_H
#define TR_TESTS_PIPELINE_TEXPECT_H

#include <stdio.h>
#include <string.h>

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

/* The cases of a test executable by name, for its main: `test name [arg]`. A case runs
 * with no argument (run) or with the one argument its meson entry passes (run_arg, e.g.
 * tests/data; missing: the case is not found). */
typedef struct {
  const char *name;
  void (*run)(void);
  void (*run_arg)(const char *);
} texpect_case;

/* Runs the case argv[1] names and returns main's status: failures != 0, or 2 when no
 * case has that name. */
static inline int texpect_main(int argc, char **argv, const texpect_case *cases, size_t n)
{
  const char *c = argc > 1 ? argv[1] : "";
  for (size_t i = 0; i < n; i++) {
    if (strcmp(c, cases[i].name) || (cases[i].run_arg && argc < 3))
      continue;
    if (cases[i].run_arg)
      cases[i].run_arg(argv[2]);
    else
      cases[i].run();
    return failures != 0;
  }
  fprintf(stderr, "unknown case '%s'\n", c);
  return 2;
}

#endif
