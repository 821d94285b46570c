/* TetGen .mtr files: a target edge length per point (the size field of refinement,
 * tr_options.sizing). First line: the number of points and the number of values per
 * point (1; TetGen reads a missing one as 1); then one value per point, in the point order
 * of the input, whitespace-separated; '#' starts a comment. A value is >= 0, 0 meaning no
 * bound at that point. */
#include <stdlib.h>

#include "io.h"
#include "lex.h"
#include "soup.h"

tr_status tr_read_mtr_buf(const char *buf, size_t len, const char *name, uint32_t npoints,
                          double **out, uint32_t *count)
{
  *out = NULL;
  tr_lex lx;
  tr_lex_init(&lx, buf, len, name, '#');
  int64_t n, per = 1;
  TR_CHECK(tr_lex_i64(&lx, "the point count", &n));
  unsigned long hline = lx.tokline;
  if (!tr_lex_at_eol(&lx))
    TR_CHECK(tr_lex_i64(&lx, "the number of values per point", &per));
  if (!tr_lex_at_eol(&lx))
    return tr_error(TR_ERR_PARSE, "%s:%lu: the first line holds the point count and the number "
                    "of values per point, then nothing", name, hline);
  if (n < 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: point count %lld", name, hline, (long long)n);
  if (per != 1)
    return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: %lld values per point: only 1 (an isotropic "
                    "target edge length) is supported", name, hline, (long long)per);
  if (npoints != UINT32_MAX && (uint64_t)n != npoints)
    return tr_error(TR_ERR_INPUT, "%s:%lu: sizes for %lld points, but the input has %u points "
                    "(one value per input point, in its order)", name, hline, (long long)n,
                    npoints);
  TR_CHECK(tr_check_room(name, hline, (uint64_t)n, "sizes", tr_lex_left(&lx), 2,
                         TR_IO_MAX_COUNT));
  double *h = malloc(sizeof *h * (size_t)(n ? n : 1));
  if (!h)
    return tr_error(TR_ERR_NOMEM, "%s: out of memory for %lld sizes", name, (long long)n);
  for (int64_t i = 0; i < n; i++) {
    tr_status s = tr_lex_double(&lx, "a size", &h[i]);
    if (s == TR_OK && !(h[i] >= 0))
      s = tr_error(TR_ERR_INPUT, "%s:%lu: size %g of point %lld: a target edge length is > 0, "
                   "or 0 for no bound there", name, lx.tokline, h[i], (long long)i);
    if (s != TR_OK) {
      free(h);
      return s;
    }
  }
  if (tr_lex_next(&lx)) {
    free(h);
    return tr_error(TR_ERR_PARSE, "%s:%lu: '%.*s' after the %lld sizes the first line "
                    "announces", name, lx.tokline, (int)(lx.toklen > 40 ? 40 : lx.toklen),
                    lx.tok, (long long)n);
  }
  *out = h;
  *count = (uint32_t)n;
  return TR_OK;
}

tr_status tr_read_mtr_file(const char *path, uint32_t npoints, double **out)
{
  char *buf;
  size_t len;
  *out = NULL;
  TR_CHECK(tr_io_load(path, &buf, &len));
  uint32_t n;
  tr_status s = tr_read_mtr_buf(buf, len, path, npoints, out, &n);
  free(buf);
  return s;
}
