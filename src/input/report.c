#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "validate.h"

#define MAX_LINES 10

static void append(tr_report *r, const char *text)
{
  size_t k = strlen(text);
  if (r->n + k + 2 > r->cap) {
    size_t c = r->cap ? r->cap : 256;
    while (c < r->n + k + 2)
      c *= 2;
    char *s = realloc(r->s, c);
    if (!s)
      return; /* the log is advisory: losing it must not fail validation */
    r->s = s;
    r->cap = c;
  }
  memcpy(r->s + r->n, text, k);
  r->n += k;
  r->s[r->n++] = '\n';
  r->s[r->n] = '\0';
}

void tr_report_add(tr_report *r, int kind, const char *fmt, ...)
{
  if (r->lines[kind] >= MAX_LINES) {
    r->dropped[kind]++;
    return;
  }
  r->lines[kind]++;
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  append(r, buf);
}

char *tr_report_finish(tr_report *r)
{
  static const char *what[] = {"duplicate vertices", "duplicate triangles", "flipped triangles",
                               "nested shells"};
  for (int k = 0; k < 4; k++)
    if (r->dropped[k]) {
      char buf[128];
      snprintf(buf, sizeof buf, "... and %u more %s", r->dropped[k], what[k]);
      append(r, buf);
    }
  char *s = r->s;
  memset(r, 0, sizeof *r);
  return s;
}

tr_status tr_sort_ids(uint32_t *ids, uint32_t n, int (*cmp)(const void *, uint32_t, uint32_t),
                      const void *ctx)
{
  if (n < 2)
    return TR_OK;
  uint32_t *tmp = malloc(sizeof *tmp * n);
  if (!tmp)
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u items", n);
  /* Bottom-up merge sort: stable, so equal keys keep index order (determinism). */
  uint32_t *a = ids, *b = tmp;
  for (uint32_t w = 1; w < n; w *= 2) {
    for (uint32_t lo = 0; lo < n; lo += 2 * w) {
      uint32_t mid = lo + w < n ? lo + w : n, hi = lo + 2 * w < n ? lo + 2 * w : n;
      uint32_t i = lo, j = mid, k = lo;
      while (i < mid && j < hi)
        b[k++] = cmp(ctx, a[j], a[i]) < 0 ? a[j++] : a[i++];
      while (i < mid)
        b[k++] = a[i++];
      while (j < hi)
        b[k++] = a[j++];
    }
    uint32_t *t = a;
    a = b;
    b = t;
    if (w > n / 2)
      break;
  }
  if (a != ids)
    memcpy(ids, a, sizeof *ids * n);
  free(tmp);
  return TR_OK;
}
