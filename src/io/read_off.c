/* OFF (Geomview object file format): [ST][C][N]OFF header, counts, vertices, polygons.
 * Extra per-vertex data (colors, normals, texture coordinates) and per-face colors are
 * skipped: a variant header promises one vertex per line, and face colors follow the
 * indices on the face's line. 4D and n-dimensional variants are rejected. */
#include <string.h>

#include "io.h"
#include "lex.h"
#include "soup.h"

static tr_status parse(tr_lex *lx, tr_soup *s)
{
  int extra = 0;
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, "the OFF header");
  /* The keyword is optional; when present it may carry variant prefixes. */
  if ((lx->tok[0] >= 'A' && lx->tok[0] <= 'Z') || (lx->tok[0] >= 'a' && lx->tok[0] <= 'z')) {
    const char *t = lx->tok;
    size_t n = lx->toklen - 3, i = 0;
    if (lx->toklen < 3 || memcmp(t + lx->toklen - 3, "OFF", 3) != 0)
      return tr_error(TR_ERR_PARSE, "%s:%lu: not an OFF file (header '%.*s')", lx->name,
                      lx->tokline, (int)(lx->toklen > 20 ? 20 : lx->toklen), t);
    if (i + 2 <= n && strncmp(t, "ST", 2) == 0)
      i += 2, extra = 1;
    if (i < n && t[i] == 'C')
      i++, extra = 1;
    if (i < n && t[i] == 'N')
      i++, extra = 1;
    if (i != n)
      return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: OFF variant '%.*s' is not supported", lx->name,
                      lx->tokline, (int)lx->toklen, t);
    if (!tr_lex_next(lx))
      return tr_lex_eof(lx, "the vertex count");
  }
  int64_t nv, nf, ne;
  TR_CHECK(tr_lex_tok_i64(lx, "the vertex count", &nv));
  unsigned long hline = lx->tokline;
  TR_CHECK(tr_lex_i64(lx, "the face count", &nf));
  TR_CHECK(tr_lex_i64(lx, "the edge count", &ne));
  (void)ne;
  if (nv < 0 || nf < 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: negative count in the OFF header", lx->name, hline);
  TR_CHECK(tr_check_room(lx->name, hline, (uint64_t)nv, "vertices", tr_lex_left(lx), 6,
                         TR_IO_MAX_COUNT / 3));
  TR_CHECK(tr_check_room(lx->name, hline, (uint64_t)nf, "faces", tr_lex_left(lx), 8,
                         TR_IO_MAX_COUNT / 3));
  if ((uint64_t)nv * 6 + (uint64_t)nf * 8 > tr_lex_left(lx) + 1)
    return tr_error(TR_ERR_PARSE,
                    "%s:%lu: header declares %lld vertices and %lld faces but the file has "
                    "room for at most %llu bytes of them",
                    lx->name, hline, (long long)nv, (long long)nf,
                    (unsigned long long)tr_lex_left(lx));
  TR_CHECK(tr_soup_reserve_points(s, (uint32_t)nv));
  if (extra)
    tr_lex_skip_line(lx);
  for (int64_t i = 0; i < nv; i++) {
    double p[3];
    TR_CHECK(tr_lex_double(lx, "a vertex coordinate", &p[0]));
    TR_CHECK(tr_lex_double(lx, "a vertex coordinate", &p[1]));
    TR_CHECK(tr_lex_double(lx, "a vertex coordinate", &p[2]));
    TR_CHECK(tr_soup_add_point(s, p));
    if (extra)
      tr_lex_skip_line(lx);
  }
  for (int64_t f = 0; f < nf; f++) {
    int64_t n;
    TR_CHECK(tr_lex_i64(lx, "a face size", &n));
    unsigned long line = lx->tokline;
    if (n < 3)
      return tr_error(TR_ERR_INPUT, "%s:%lu: face %lld has %lld vertices (at least 3 needed)",
                      lx->name, line, (long long)f, (long long)n);
    if ((uint64_t)n > tr_lex_left(lx))
      return tr_error(TR_ERR_PARSE, "%s:%lu: face %lld declares %lld vertices but the file has "
                      "room for at most %llu", lx->name, line, (long long)f, (long long)n,
                      (unsigned long long)tr_lex_left(lx));
    TR_CHECK(tr_soup_begin_facet(s, 0, line));
    TR_CHECK(tr_soup_begin_loop(s));
    for (int64_t k = 0; k < n; k++) {
      int64_t v;
      TR_CHECK(tr_lex_i64(lx, "a vertex index", &v));
      if (v < 0 || v >= nv)
        return tr_error(TR_ERR_INPUT,
                        "%s:%lu: face %lld: vertex index %lld out of range (0..%lld)",
                        lx->name, lx->tokline, (long long)f, (long long)v, (long long)nv - 1);
      TR_CHECK(tr_soup_add_index(s, (uint32_t)v));
    }
    /* Whatever follows on the line is a face color. */
    if (!tr_lex_at_eol(lx))
      tr_lex_skip_line(lx);
  }
  /* More than the header declares is a malformed file: reading on would guess, and
   * stopping silently would drop elements the user wrote. */
  if (tr_lex_next(lx))
    return tr_error(TR_ERR_PARSE,
                    "%s:%lu: unexpected '%.*s' after the %lld faces the header (line %lu) "
                    "declares", lx->name, lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen),
                    lx->tok, (long long)nf, hline);
  return TR_OK;
}

tr_status tr_read_off_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  return tr_soup_read_text(buf, len, name, '#', parse, plc);
}
