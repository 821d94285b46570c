#include "status.h"

#include <stdarg.h>
#include <stdio.h>

/* One buffer per thread: a library embedded in a threaded program must not mix the
 * messages of two calls. */
static _Thread_local char tr_message[1024];

tr_status tr_error(tr_status s, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(tr_message, sizeof tr_message, fmt, ap);
  va_end(ap);
  return s;
}

void tr_error_clear(void) { tr_message[0] = '\0'; }

const char *tr_last_error(void) { return tr_message; }

const char *tr_status_name(tr_status s)
{
  switch (s) {
  case TR_OK: return "TR_OK";
  case TR_ERR_USAGE: return "TR_ERR_USAGE";
  case TR_ERR_IO: return "TR_ERR_IO";
  case TR_ERR_PARSE: return "TR_ERR_PARSE";
  case TR_ERR_INPUT: return "TR_ERR_INPUT";
  case TR_ERR_DEGENERATE: return "TR_ERR_DEGENERATE";
  case TR_ERR_OPEN: return "TR_ERR_OPEN";
  case TR_ERR_SELF_INTERSECT: return "TR_ERR_SELF_INTERSECT";
  case TR_ERR_NOMEM: return "TR_ERR_NOMEM";
  case TR_ERR_INVALID_MESH: return "TR_ERR_INVALID_MESH";
  case TR_ERR_INTERNAL: return "TR_ERR_INTERNAL";
  case TR_ERR_UNSUPPORTED: return "TR_ERR_UNSUPPORTED";
  case TR_ERR_CANCELLED: return "TR_ERR_CANCELLED";
  }
  return "TR_ERR_UNKNOWN";
}
