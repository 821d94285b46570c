/* Medit ASCII .mesh (INRIA): keyword sections with counts. As surface input we use the
 * Triangles (and Quadrilaterals, as polygons) with their refs as markers; Tetrahedra are
 * kept for `tetrec check`. Sections we do not need are skipped by their known arity;
 * an unknown keyword is an error rather than a guess. Indices are 1-based. */
#include <string.h>

#include "io.h"
#include "lex.h"
#include "soup.h"

/* Numbers per entry of sections we skip. */
static const struct {
  const char *kw;
  int arity;
} skipped[] = {{"Edges", 3},         {"Corners", 1},          {"Ridges", 1},
               {"RequiredVertices", 1}, {"RequiredEdges", 1}, {"RequiredTriangles", 1},
               {"Normals", 3},       {"NormalAtVertices", 2}, {"Tangents", 3},
               {"TangentAtVertices", 2}, {"Hexahedra", 9},     {"Prisms", 7},
               {"Pyramids", 6},      {"Crack", 2}};

static tr_status count(tr_lex *lx, const char *what, int per, uint64_t *n)
{
  TR_CHECK(tr_lex_u64(lx, what, n));
  return tr_check_room(lx->name, lx->tokline, *n, what, tr_lex_left(lx), 2 * (size_t)per,
                       TR_IO_MAX_COUNT / 4);
}

static tr_status index_of(tr_lex *lx, uint64_t nv, const char *what, uint32_t *out)
{
  int64_t v;
  TR_CHECK(tr_lex_i64(lx, what, &v));
  if (v < 1 || (uint64_t)v > nv)
    return tr_error(TR_ERR_INPUT, "%s:%lu: %s index %lld out of range (1..%llu)", lx->name,
                    lx->tokline, what, (long long)v, (unsigned long long)nv);
  *out = (uint32_t)(v - 1);
  return TR_OK;
}

static tr_status parse(tr_lex *lx, tr_soup *s)
{
  uint64_t nv = 0;
  int have_vertices = 0;
  while (tr_lex_next(lx)) {
    uint64_t n;
    if (tr_lex_is(lx, "MeshVersionFormatted")) {
      int64_t v;
      TR_CHECK(tr_lex_i64(lx, "the mesh version", &v));
      if (v < 1 || v > 3)
        return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: MeshVersionFormatted %lld not supported",
                        lx->name, lx->tokline, (long long)v);
    } else if (tr_lex_is(lx, "Dimension")) {
      int64_t d;
      TR_CHECK(tr_lex_i64(lx, "the dimension", &d));
      if (d != 3)
        return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: Dimension %lld (only 3 is supported)",
                        lx->name, lx->tokline, (long long)d);
    } else if (tr_lex_is(lx, "Vertices")) {
      if (have_vertices)
        return tr_error(TR_ERR_PARSE, "%s:%lu: a second Vertices section", lx->name, lx->tokline);
      TR_CHECK(count(lx, "vertices", 4, &n));
      TR_CHECK(tr_soup_reserve_points(s, (uint32_t)n));
      for (uint64_t i = 0; i < n; i++) {
        double p[3], ref;
        for (int k = 0; k < 3; k++)
          TR_CHECK(tr_lex_double(lx, "a vertex coordinate", &p[k]));
        TR_CHECK(tr_lex_double(lx, "a vertex reference", &ref));
        TR_CHECK(tr_soup_add_point(s, p));
      }
      nv = n;
      have_vertices = 1;
    } else if (tr_lex_is(lx, "Triangles") || tr_lex_is(lx, "Quadrilaterals")) {
      int k = tr_lex_is(lx, "Triangles") ? 3 : 4;
      const char *what = k == 3 ? "triangle vertex" : "quadrilateral vertex";
      TR_CHECK(count(lx, k == 3 ? "triangles" : "quadrilaterals", k + 1, &n));
      for (uint64_t i = 0; i < n; i++) {
        uint32_t v[4];
        int64_t ref;
        for (int j = 0; j < k; j++)
          TR_CHECK(index_of(lx, nv, what, &v[j]));
        TR_CHECK(tr_lex_i64(lx, "a reference", &ref));
        TR_CHECK(tr_soup_begin_facet(s, (int32_t)ref, lx->tokline));
        TR_CHECK(tr_soup_begin_loop(s));
        for (int j = 0; j < k; j++)
          TR_CHECK(tr_soup_add_index(s, v[j]));
      }
    } else if (tr_lex_is(lx, "Tetrahedra")) {
      TR_CHECK(count(lx, "tetrahedra", 5, &n));
      TR_CHECK(tr_u32vec_reserve(&s->tets, (uint32_t)(4 * n)));
      for (uint64_t i = 0; i < n; i++) {
        int64_t ref;
        for (int j = 0; j < 4; j++) {
          uint32_t v = 0;
          TR_CHECK(index_of(lx, nv, "tetrahedron vertex", &v));
          TR_CHECK(tr_u32vec_push(&s->tets, v));
        }
        TR_CHECK(tr_lex_i64(lx, "a reference", &ref));
      }
    } else if (tr_lex_is(lx, "End")) {
      return TR_OK;
    } else {
      size_t i;
      for (i = 0; i < sizeof skipped / sizeof skipped[0]; i++)
        if (tr_lex_is(lx, skipped[i].kw))
          break;
      if (i == sizeof skipped / sizeof skipped[0])
        return tr_error(TR_ERR_PARSE, "%s:%lu: unknown Medit keyword '%.*s'", lx->name,
                        lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
      TR_CHECK(count(lx, skipped[i].kw, skipped[i].arity, &n));
      for (uint64_t j = 0; j < n * (uint64_t)skipped[i].arity; j++) {
        double x;
        TR_CHECK(tr_lex_double(lx, skipped[i].kw, &x));
      }
    }
  }
  if (!have_vertices)
    return tr_error(TR_ERR_PARSE, "%s: no Vertices section", lx->name);
  return TR_OK;
}

tr_status tr_read_medit_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  return tr_soup_read_text(buf, len, name, '#', parse, plc);
}
