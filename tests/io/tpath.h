/* DIR/NAME for the io tests (test_io, test_formats): four rotating static buffers, so a
 * call may take up to four paths at once (e.g. a conversion's input and output). */
#ifndef TR_TESTS_IO_TPATH_H
#define TR_TESTS_IO_TPATH_H

#include <stdio.h>

static inline const char *tpath(const char *dir, const char *name)
{
  static char buf[4][1024];
  static int k;
  k = (k + 1) % 4;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

#endif
