/* Hard input cases (issue 7), built in memory so the tests need no files and the
 * `gen_hard DIR` tool writes exactly what the tests mesh. Every case is deterministic:
 * only exact double arithmetic (sums and products of small dyadic numbers) and
 * correctly rounded operations, never libm, so the files are the same on every machine.
 *
 * Each case says what tetrec must do with it: mesh it into `regions` regions whose
 * exact 6 * volume is `vol6` (0: the volume the validated surface encloses), or fail
 * with `status`. */
#ifndef TR_TESTS_HARD_CASES_H
#define TR_TESTS_HARD_CASES_H

#include <stdint.h>

#include "tetrec.h"

typedef struct hard_case {
  const char *name;      /* file base name */
  const char *property;  /* what the test checks (its meson test name) */
  tr_status status;      /* TR_OK or the expected error */
  int regions;           /* expected regions when status == TR_OK */
  int allow_open;        /* tr_options.allow_open for this case */
  int ball;              /* the domain is a ball (Euler check applies) */
  int steiner;           /* 1: at least one Steiner point is needed */
  double vol6;           /* exact expected 6 * volume, 0 = from the surface */
  const char *why;       /* one line: what makes the case hard */
  double *xyz;
  uint32_t np;
  uint32_t *tris;
  uint32_t nt;
} hard_case;

/* Number of cases; case i's name without building it. */
int hard_case_count(void);
const char *hard_case_name(int i);
/* Builds case i (0 on success, -1 out of memory). */
int hard_case_build(int i, hard_case *c);
void hard_case_free(hard_case *c);
/* Writes the case as an OFF file (17 significant digits: read back exactly). 0 on
 * success. */
int hard_case_write_off(const hard_case *c, const char *path);

#endif
