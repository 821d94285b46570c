/* Binary Medit .meshb (libMeshb's Gamma Mesh Format), versions 1 to 4: what the text
 * reader takes from a .mesh. Vertices; Triangles and Quadrilaterals (as polygons) with
 * their references as markers, the surface input; Tetrahedra into plc->tets for `tetrec
 * check`.
 *
 * Layout: the int 1, whose bytes give the file's byte order (a big-endian file is refused
 * by name), the version, then keywords until End: the keyword's code (a 4-byte int), the
 * file offset of the next keyword, the number of lines for keywords that have lines, the
 * lines. Reals are floats in version 1, doubles after; offsets are 4 bytes up to version 2,
 * 8 after; ints and line counts are 4 bytes up to version 3, 8 in version 4. Codes:
 * Dimension 3, Vertices 4, Triangles 6, Quadrilaterals 7, Tetrahedra 8, End 54. Any other
 * keyword is stepped over by its next-keyword offset, which must move forward within the
 * file (so a damaged offset cannot loop); a file without End is refused as truncated.
 * Every line count is checked against the bytes its lines take before anything is
 * allocated for it; messages give byte offsets. */
#include <math.h>
#include <string.h>

#include "io.h"
#include "put_number.h"
#include "soup.h"

enum {
  KW_DIMENSION = 3, KW_VERTICES = 4, KW_TRIANGLES = 6, KW_QUADRILATERALS = 7,
  KW_TETRAHEDRA = 8, KW_END = 54
};

struct cur {
  const unsigned char *b, *p, *end;
  const char *name;
  int isize, rsize, psize; /* bytes of an int, a real, an offset */
};

static unsigned long at(const struct cur *c) { return (unsigned long)(c->p - c->b); }

static tr_status need(const struct cur *c, uint64_t n, const char *what)
{
  if ((uint64_t)(c->end - c->p) < n)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: file ends inside %s", c->name, at(c), what);
  return TR_OK;
}

/* An int of the file's width (4 bytes, 8 in version 4), sign-extended. */
static tr_status get_int(struct cur *c, const char *what, int64_t *x)
{
  TR_CHECK(need(c, (uint64_t)c->isize, what));
  *x = c->isize == 8 ? (int64_t)tr_get_le64(c->p) : (int64_t)(int32_t)tr_get_le32(c->p);
  c->p += c->isize;
  return TR_OK;
}

/* A line count, checked against the bytes left for lines of `per` bytes. */
static tr_status lines(struct cur *c, uint64_t per, const char *what, uint64_t *n)
{
  int64_t v;
  unsigned long where = at(c);
  TR_CHECK(get_int(c, what, &v));
  uint64_t left = (uint64_t)(c->end - c->p);
  if (v < 0)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: negative number of %s (%lld)", c->name, where,
                    what, (long long)v);
  if ((uint64_t)v > left / per)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: %lld %s declared but the file has room for at "
                    "most %llu", c->name, where, (long long)v, what,
                    (unsigned long long)(left / per));
  if ((uint64_t)v > TR_IO_MAX_COUNT / 4)
    return tr_error(TR_ERR_NOMEM, "%s: byte %lu: %lld %s exceed the limit of %lu", c->name, where,
                    (long long)v, what, (unsigned long)(TR_IO_MAX_COUNT / 4));
  *n = (uint64_t)v;
  return TR_OK;
}

static tr_status vertex_index(struct cur *c, uint64_t nv, const char *what, uint32_t *out)
{
  int64_t v;
  unsigned long where = at(c);
  TR_CHECK(get_int(c, what, &v));
  if (v < 1 || (uint64_t)v > nv)
    return tr_error(TR_ERR_INPUT, "%s: byte %lu: %s index %lld out of range (1..%llu)", c->name,
                    where, what, (long long)v, (unsigned long long)nv);
  *out = (uint32_t)(v - 1);
  return TR_OK;
}

static tr_status vertices(struct cur *c, tr_soup *s, uint64_t *nv)
{
  uint64_t n;
  TR_CHECK(lines(c, 3 * (uint64_t)c->rsize + (uint64_t)c->isize, "vertices", &n));
  TR_CHECK(tr_soup_reserve_points(s, (uint32_t)n));
  for (uint64_t i = 0; i < n; i++) {
    double p[3];
    for (int k = 0; k < 3; k++) {
      p[k] = c->rsize == 4 ? (double)tr_get_le_f32(c->p) : tr_get_le_f64(c->p);
      if (!isfinite(p[k]))
        return tr_error(TR_ERR_INPUT, "%s: byte %lu: vertex coordinate is NaN or infinite",
                        c->name, at(c));
      c->p += c->rsize;
    }
    c->p += c->isize; /* the vertex's reference: not used */
    TR_CHECK(tr_soup_add_point(s, p));
  }
  *nv = n;
  return TR_OK;
}

/* Triangles (k = 3) or quadrilaterals (k = 4) as facets, their reference the marker. */
static tr_status faces(struct cur *c, tr_soup *s, uint64_t nv, int k)
{
  uint64_t n;
  const char *what = k == 3 ? "triangle vertex" : "quadrilateral vertex";
  TR_CHECK(lines(c, (uint64_t)(k + 1) * (uint64_t)c->isize,
                 k == 3 ? "triangles" : "quadrilaterals", &n));
  for (uint64_t i = 0; i < n; i++) {
    uint32_t v[4];
    int64_t ref;
    unsigned long where = at(c);
    for (int j = 0; j < k; j++)
      TR_CHECK(vertex_index(c, nv, what, &v[j]));
    TR_CHECK(get_int(c, "a reference", &ref));
    if (ref < INT32_MIN || ref > INT32_MAX)
      return tr_error(TR_ERR_INPUT, "%s: byte %lu: reference %lld out of the 32-bit range",
                      c->name, at(c) - (unsigned long)c->isize, (long long)ref);
    TR_CHECK(tr_soup_begin_facet(s, (int32_t)ref, where));
    TR_CHECK(tr_soup_begin_loop(s));
    for (int j = 0; j < k; j++)
      TR_CHECK(tr_soup_add_index(s, v[j]));
  }
  return TR_OK;
}

static tr_status tetrahedra(struct cur *c, tr_soup *s, uint64_t nv)
{
  uint64_t n;
  TR_CHECK(lines(c, 5 * (uint64_t)c->isize, "tetrahedra", &n));
  TR_CHECK(tr_u32vec_reserve(&s->tets, (uint32_t)(4 * n)));
  for (uint64_t i = 0; i < n; i++) {
    for (int j = 0; j < 4; j++) {
      uint32_t v;
      TR_CHECK(vertex_index(c, nv, "tetrahedron vertex", &v));
      TR_CHECK(tr_u32vec_push(&s->tets, v));
    }
    c->p += c->isize; /* the reference (region): not used, as in the text reader */
  }
  return TR_OK;
}

static tr_status parse(struct cur *c, tr_soup *s)
{
  if (c->end - c->p < 8)
    return tr_error(TR_ERR_PARSE, "%s: %lu bytes: too short for a .meshb header", c->name,
                    (unsigned long)(c->end - c->p));
  uint32_t one = tr_get_le32(c->p), ver = tr_get_le32(c->p + 4);
  if (one == 0x01000000u)
    return tr_error(TR_ERR_UNSUPPORTED, "%s: big-endian .meshb not supported (its first int "
                    "reads 16777216 little-endian, not 1)", c->name);
  if (one != 1)
    return tr_error(TR_ERR_PARSE, "%s: not a binary Medit file (its first int is %lu, not 1)",
                    c->name, (unsigned long)one);
  if (ver < 1 || ver > 4)
    return tr_error(TR_ERR_UNSUPPORTED, "%s: .meshb version %lu not supported (1 to 4)",
                    c->name, (unsigned long)ver);
  c->rsize = ver == 1 ? 4 : 8;
  c->psize = ver >= 3 ? 8 : 4;
  c->isize = ver == 4 ? 8 : 4;
  c->p += 8;
  uint64_t nv = 0;
  int have_dim = 0, have_vertices = 0;
  for (;;) {
    if (c->p == c->end)
      return tr_error(TR_ERR_PARSE, "%s: byte %lu: file ends without the End keyword "
                      "(truncated?)", c->name, at(c));
    unsigned long kw_at = at(c);
    TR_CHECK(need(c, 4, "a keyword code"));
    int32_t code = (int32_t)tr_get_le32(c->p);
    c->p += 4;
    if (code == KW_END)
      return have_vertices ? TR_OK
                           : tr_error(TR_ERR_PARSE, "%s: no Vertices keyword", c->name);
    TR_CHECK(need(c, (uint64_t)c->psize, "a keyword's next-keyword offset"));
    uint64_t next = c->psize == 8 ? tr_get_le64(c->p) : tr_get_le32(c->p);
    c->p += c->psize;
    switch (code) {
    case KW_DIMENSION: {
      TR_CHECK(need(c, 4, "the dimension"));
      int32_t d = (int32_t)tr_get_le32(c->p);
      c->p += 4;
      if (d != 3)
        return tr_error(TR_ERR_UNSUPPORTED, "%s: byte %lu: Dimension %ld (only 3 is supported)",
                        c->name, at(c) - 4, (long)d);
      have_dim = 1;
      break;
    }
    case KW_VERTICES:
      if (!have_dim)
        return tr_error(TR_ERR_PARSE, "%s: byte %lu: Vertices before Dimension", c->name,
                        kw_at);
      if (have_vertices)
        return tr_error(TR_ERR_PARSE, "%s: byte %lu: a second Vertices keyword", c->name,
                        kw_at);
      TR_CHECK(vertices(c, s, &nv));
      have_vertices = 1;
      break;
    case KW_TRIANGLES:
    case KW_QUADRILATERALS:
      TR_CHECK(faces(c, s, nv, code == KW_TRIANGLES ? 3 : 4));
      break;
    case KW_TETRAHEDRA: TR_CHECK(tetrahedra(c, s, nv)); break;
    default:
      /* a keyword we do not read: its lines' layout is not needed, only where it ends */
      if (next <= (uint64_t)at(c) || next > (uint64_t)(c->end - c->b))
        return tr_error(TR_ERR_PARSE, "%s: byte %lu: keyword %ld cannot be skipped: its "
                        "next-keyword offset %llu is not forward within the file (%lu bytes)",
                        c->name, kw_at, (long)code, (unsigned long long)next,
                        (unsigned long)(c->end - c->b));
      c->p = c->b + next;
      break;
    }
  }
}

tr_status tr_read_meshb_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  struct cur c = {(const unsigned char *)buf, (const unsigned char *)buf,
                  (const unsigned char *)buf + len, name ? name : "<buffer>", 4, 8, 4};
  tr_soup s;
  tr_soup_init(&s, c.name);
  tr_status st = parse(&c, &s);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  tr_soup_free(&s);
  if (st != TR_OK)
    tr_plc_clear(plc);
  return st;
}
