/* Wavefront OBJ: `v x y z [w | r g b]` and `f` with the index forms i, i/t, i//n, i/t/n
 * (1-based; negative = relative to the vertices defined so far). Faces are polygons.
 * Statements that only dress the surface (vt, vn, g, o, s, usemtl, mtllib, ...) are
 * skipped; geometry tetrec cannot take from OBJ (points `p`, polylines `l`, free-form
 * curves and surfaces) is an error, since dropping it would change the domain. */
#include "io.h"
#include "lex.h"
#include "soup.h"

static tr_status face_index(tr_lex *lx, uint32_t nv, uint32_t *out)
{
  /* Only the part before the first '/' is the vertex index. */
  size_t n = 0;
  while (n < lx->toklen && lx->tok[n] != '/')
    n++;
  size_t keep = lx->toklen;
  lx->toklen = n;
  int64_t v;
  tr_status st = tr_lex_tok_i64(lx, "a face vertex index", &v);
  lx->toklen = keep;
  TR_CHECK(st);
  if (v < 0)
    v += (int64_t)nv; /* -1 is the last vertex defined so far */
  else
    v -= 1;
  if (v < 0 || v >= (int64_t)nv)
    return tr_error(TR_ERR_INPUT,
                    "%s:%lu: face vertex '%.*s' is out of range (%u vertices defined so far)",
                    lx->name, lx->tokline, (int)(keep > 40 ? 40 : keep), lx->tok, nv);
  *out = (uint32_t)v;
  return TR_OK;
}

static tr_status parse(tr_lex *lx, tr_soup *s)
{
  while (tr_lex_next(lx)) {
    if (tr_lex_is(lx, "v")) {
      double p[3];
      for (int k = 0; k < 3; k++)
        TR_CHECK(tr_lex_double(lx, "a vertex coordinate", &p[k]));
      TR_CHECK(tr_soup_add_point(s, p));
      if (!tr_lex_at_eol(lx))
        tr_lex_skip_line(lx); /* w or a color */
    } else if (tr_lex_is(lx, "f")) {
      unsigned long line = lx->tokline;
      uint32_t count = 0;
      TR_CHECK(tr_soup_begin_facet(s, 0, line));
      TR_CHECK(tr_soup_begin_loop(s));
      while (!tr_lex_at_eol(lx)) {
        uint32_t v = 0;
        if (!tr_lex_next(lx))
          break;
        TR_CHECK(face_index(lx, s->npoints, &v));
        TR_CHECK(tr_soup_add_index(s, v));
        count++;
      }
      if (count < 3)
        return tr_error(TR_ERR_INPUT, "%s:%lu: face %u has %u vertices (at least 3 needed)",
                        lx->name, line, tr_soup_nfacets(s) - 1, count);
    } else if (tr_lex_is(lx, "p") || tr_lex_is(lx, "l") || tr_lex_is(lx, "curv") ||
               tr_lex_is(lx, "curv2") || tr_lex_is(lx, "surf") || tr_lex_is(lx, "cstype")) {
      return tr_error(TR_ERR_UNSUPPORTED,
                      "%s:%lu: OBJ '%.*s' statements are not supported (only v and f define "
                      "geometry; give segments or isolated points in a TetGen .poly file)",
                      lx->name, lx->tokline, (int)lx->toklen, lx->tok);
    } else if (lx->tok[0] == '\\' || lx->toklen > 64) {
      return tr_error(TR_ERR_PARSE, "%s:%lu: unexpected '%.*s'", lx->name, lx->tokline,
                      (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
    } else {
      tr_lex_skip_line(lx);
    }
  }
  return TR_OK;
}

tr_status tr_read_obj_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  return tr_soup_read_text(buf, len, name, '#', parse, plc);
}
