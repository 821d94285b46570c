/* Status propagation, HXT style: every fallible internal function returns tr_status,
 * callers wrap calls in TR_CHECK so the first failure travels up unchanged with the
 * message set where it was detected. */
#ifndef TR_CORE_STATUS_H
#define TR_CORE_STATUS_H

#include "tetrec.h"

#define TR_CHECK(expr)                 \
  do {                                 \
    tr_status tr_check_s_ = (expr);    \
    if (tr_check_s_ != TR_OK)          \
      return tr_check_s_;              \
  } while (0)

#if defined(__GNUC__) || defined(__clang__)
#define TR_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define TR_PRINTF(f, a)
#endif

/* Records a formatted message for tr_last_error() and returns s, so that error sites
 * read `return tr_error(TR_ERR_PARSE, "%s:%lu: ...", ...);`. */
tr_status tr_error(tr_status s, const char *fmt, ...) TR_PRINTF(2, 3);
/* Clears the thread's message (called at API entry points). */
void tr_error_clear(void);

#endif
