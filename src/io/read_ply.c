/* PLY (Stanford polygon format): ascii, binary_little_endian and binary_big_endian.
 * The header lists elements and their properties; we read x, y, z of `vertex`, the index
 * list of `face` (vertex_indices or vertex_index) and of `tristrips` (triangle strips, as
 * in the Stanford and Cyberware scans: -1 ends a strip and starts the next; triangle k of
 * a strip v0 v1 v2 ... is (vk, vk+1, vk+2) for even k and (vk+1, vk, vk+2) for odd k, so
 * the strip keeps one orientation; triangles with a repeated vertex are the joins that
 * stitch strips and are not triangles of the surface), and a face's integer `marker`,
 * `label` or `ref` property as its boundary marker; every other property and element is
 * skipped, so their types must be understood even when unused. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "lex.h"
#include "soup.h"

enum { T_NONE, T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 };
static const int tsize[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};

typedef struct {
  int type;       /* value type, or the item type of a list */
  int count_type; /* T_NONE for a scalar property */
  int role;       /* 0 skip, 1..3 = x,y,z, 4 = face index list, 5 = strip index list,
                     6 = face marker */
} prop;

#define MAX_PROPS 64
#define MAX_ELEMS 16

typedef struct {
  char name[32];
  uint64_t count;
  int nprops;
  prop props[MAX_PROPS];
  unsigned long line;
} elem;

static int type_of(const tr_lex *lx)
{
  static const char *names[][2] = {{"char", "int8"},   {"uchar", "uint8"},  {"short", "int16"},
                                   {"ushort", "uint16"}, {"int", "int32"},   {"uint", "uint32"},
                                   {"float", "float32"}, {"double", "float64"}};
  for (int i = 0; i < 8; i++)
    if (tr_lex_is(lx, names[i][0]) || tr_lex_is(lx, names[i][1]))
      return i + 1;
  return T_NONE;
}

typedef struct {
  const unsigned char *p, *end;
  int big;
} bin;

static int bin_read(bin *b, int type, double *out)
{
  int n = tsize[type];
  if (b->end - b->p < n)
    return -1;
  unsigned char c[8];
  for (int i = 0; i < n; i++)
    c[i] = b->big ? b->p[n - 1 - i] : b->p[i];
  b->p += n;
  uint64_t u = 0;
  for (int i = n - 1; i >= 0; i--)
    u = u << 8 | c[i];
  switch (type) {
  case T_I8: *out = (double)(int8_t)u; break;
  case T_U8: *out = (double)(uint8_t)u; break;
  case T_I16: *out = (double)(int16_t)u; break;
  case T_U16: *out = (double)(uint16_t)u; break;
  case T_I32: *out = (double)(int32_t)u; break;
  case T_U32: *out = (double)(uint32_t)u; break;
  case T_F32: {
    uint32_t w = (uint32_t)u;
    float f;
    memcpy(&f, &w, 4);
    *out = (double)f;
    break;
  }
  default: memcpy(out, &u, 8); break;
  }
  return 0;
}

typedef struct {
  tr_lex lx; /* ascii body and header */
  bin b;
  int binary;
  const char *name;
  uint64_t item; /* element instance, for messages */
} reader;

static tr_status get(reader *r, int type, double *out, const char *what)
{
  if (r->binary) {
    if (bin_read(&r->b, type, out))
      return tr_error(TR_ERR_PARSE, "%s: unexpected end of file while reading %s %llu",
                      r->name, what, (unsigned long long)r->item);
    if (!isfinite(*out))
      return tr_error(TR_ERR_INPUT, "%s: %s %llu: value is NaN or infinite", r->name, what,
                      (unsigned long long)r->item);
    return TR_OK;
  }
  TR_CHECK(tr_lex_double(&r->lx, what, out));
  if (type != T_F32 && type != T_F64 && *out != floor(*out))
    return tr_error(TR_ERR_PARSE, "%s:%lu: %s: integer expected, found '%.*s'", r->name,
                    r->lx.tokline, what, (int)(r->lx.toklen > 40 ? 40 : r->lx.toklen), r->lx.tok);
  return TR_OK;
}

static tr_status read_header(tr_lex *lx, elem *el, int *nel, int *format)
{
  if (!tr_lex_next(lx) || !tr_lex_is(lx, "ply"))
    return tr_error(TR_ERR_PARSE, "%s:1: not a PLY file (no 'ply' magic)", lx->name);
  *format = -1;
  *nel = 0;
  for (;;) {
    if (!tr_lex_next(lx))
      return tr_lex_eof(lx, "the PLY header");
    if (tr_lex_is(lx, "end_header"))
      break;
    if (tr_lex_is(lx, "comment") || tr_lex_is(lx, "obj_info")) {
      tr_lex_skip_line(lx);
    } else if (tr_lex_is(lx, "format")) {
      if (!tr_lex_next(lx))
        return tr_lex_eof(lx, "the PLY format");
      if (tr_lex_is(lx, "ascii"))
        *format = 0;
      else if (tr_lex_is(lx, "binary_little_endian"))
        *format = 1;
      else if (tr_lex_is(lx, "binary_big_endian"))
        *format = 2;
      else
        return tr_error(TR_ERR_PARSE, "%s:%lu: unknown PLY format '%.*s'", lx->name, lx->tokline,
                        (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
      tr_lex_skip_line(lx);
    } else if (tr_lex_is(lx, "element")) {
      if (*nel == MAX_ELEMS)
        return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: more than %d elements", lx->name,
                        lx->tokline, MAX_ELEMS);
      elem *e = &el[(*nel)++];
      memset(e, 0, sizeof *e);
      e->line = lx->tokline;
      if (!tr_lex_next(lx))
        return tr_lex_eof(lx, "an element name");
      size_t n = lx->toklen < sizeof e->name - 1 ? lx->toklen : sizeof e->name - 1;
      memcpy(e->name, lx->tok, n);
      TR_CHECK(tr_lex_u64(lx, "an element count", &e->count));
    } else if (tr_lex_is(lx, "property")) {
      if (*nel == 0)
        return tr_error(TR_ERR_PARSE, "%s:%lu: property before any element", lx->name,
                        lx->tokline);
      elem *e = &el[*nel - 1];
      if (e->nprops == MAX_PROPS)
        return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: more than %d properties", lx->name,
                        lx->tokline, MAX_PROPS);
      prop *p = &e->props[e->nprops++];
      memset(p, 0, sizeof *p);
      if (!tr_lex_next(lx))
        return tr_lex_eof(lx, "a property type");
      if (tr_lex_is(lx, "list")) {
        if (!tr_lex_next(lx))
          return tr_lex_eof(lx, "a list count type");
        p->count_type = type_of(lx);
        if (p->count_type == T_NONE || p->count_type >= T_F32)
          return tr_error(TR_ERR_PARSE, "%s:%lu: bad list count type '%.*s'", lx->name,
                          lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
        if (!tr_lex_next(lx))
          return tr_lex_eof(lx, "a list item type");
      }
      p->type = type_of(lx);
      if (p->type == T_NONE)
        return tr_error(TR_ERR_PARSE, "%s:%lu: unknown property type '%.*s'", lx->name,
                        lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
      if (!tr_lex_next(lx))
        return tr_lex_eof(lx, "a property name");
      if (strcmp(e->name, "vertex") == 0 && !p->count_type) {
        if (tr_lex_is(lx, "x"))
          p->role = 1;
        else if (tr_lex_is(lx, "y"))
          p->role = 2;
        else if (tr_lex_is(lx, "z"))
          p->role = 3;
      }
      if (strcmp(e->name, "face") == 0 && p->count_type &&
          (tr_lex_is(lx, "vertex_indices") || tr_lex_is(lx, "vertex_index")))
        p->role = 4;
      if (strcmp(e->name, "face") == 0 && !p->count_type &&
          (tr_lex_is(lx, "marker") || tr_lex_is(lx, "label") || tr_lex_is(lx, "ref")))
        p->role = 6;
      if (strcmp(e->name, "tristrips") == 0 && p->count_type &&
          (tr_lex_is(lx, "vertex_indices") || tr_lex_is(lx, "vertex_index")))
        p->role = 5;
    } else {
      return tr_error(TR_ERR_PARSE, "%s:%lu: unexpected '%.*s' in the PLY header", lx->name,
                      lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
    }
  }
  if (*format < 0)
    return tr_error(TR_ERR_PARSE, "%s: PLY header has no format line", lx->name);
  /* The body starts after the end_header line. */
  tr_lex_skip_line(lx);
  return TR_OK;
}

/* One tristrips list of n indices (see the top of the file). */
static tr_status strip(reader *r, tr_soup *s, int type, uint64_t n, uint64_t nv, uint64_t item)
{
  uint32_t w[2] = {0, 0};
  uint64_t run = 0; /* vertices of the current strip so far */
  for (uint64_t j = 0; j < n; j++) {
    double v;
    unsigned long line = r->lx.line;
    TR_CHECK(get(r, type, &v, "tristrips"));
    if (v == -1) {
      run = 0;
      continue;
    }
    if (v < 0 || v >= (double)nv || v != floor(v))
      return tr_error(TR_ERR_INPUT, "%s: tristrips %llu: vertex index %.0f out of range "
                      "(0..%llu, or -1 to restart)", r->name, (unsigned long long)item, v,
                      (unsigned long long)nv - 1);
    uint32_t x = (uint32_t)v;
    if (run >= 2 && w[0] != w[1] && w[1] != x && w[0] != x) {
      uint32_t a = run % 2 ? w[1] : w[0], b = run % 2 ? w[0] : w[1];
      TR_CHECK(tr_soup_begin_facet(s, 0, r->binary ? (unsigned long)item : line));
      TR_CHECK(tr_soup_begin_loop(s));
      TR_CHECK(tr_soup_add_index(s, a));
      TR_CHECK(tr_soup_add_index(s, b));
      TR_CHECK(tr_soup_add_index(s, x));
    }
    w[0] = w[1];
    w[1] = x;
    run++;
  }
  return TR_OK;
}

static tr_status parse(reader *r, const char *buf, size_t len, tr_soup *s)
{
  elem el[MAX_ELEMS];
  int nel = 0, format = 0;
  TR_CHECK(read_header(&r->lx, el, &nel, &format));
  r->binary = format != 0;
  r->b.p = (const unsigned char *)r->lx.p;
  r->b.end = (const unsigned char *)buf + len;
  r->b.big = format == 2;
  int seen_vertex = 0;
  uint64_t nv = 0;
  for (int e = 0; e < nel; e++) {
    elem *E = &el[e];
    size_t min = 0;
    int has_xyz = 0, has_face = 0;
    for (int k = 0; k < E->nprops; k++) {
      min += r->binary ? (size_t)tsize[E->props[k].count_type ? E->props[k].count_type
                                                                : E->props[k].type]
                       : 2;
      has_xyz |= 1 << E->props[k].role;
      has_face |= E->props[k].role == 4 || E->props[k].role == 5;
    }
    size_t left = r->binary ? (size_t)(r->b.end - r->b.p) : tr_lex_left(&r->lx);
    TR_CHECK(tr_check_room(r->name, E->line, E->count, E->name, left, min ? min : 1,
                           TR_IO_MAX_COUNT / 3));
    int is_vertex = strcmp(E->name, "vertex") == 0, is_face = strcmp(E->name, "face") == 0;
    int is_strip = strcmp(E->name, "tristrips") == 0;
    if (is_vertex) {
      if ((has_xyz & 0xe) != 0xe)
        return tr_error(TR_ERR_PARSE, "%s:%lu: vertex element lacks x, y or z", r->name, E->line);
      nv = E->count;
      seen_vertex = 1;
      TR_CHECK(tr_soup_reserve_points(s, (uint32_t)nv));
    }
    if ((is_face || is_strip) && !seen_vertex)
      return tr_error(TR_ERR_PARSE, "%s:%lu: %s element before vertex element", r->name,
                      E->line, E->name);
    if ((is_face || is_strip) && !has_face)
      return tr_error(TR_ERR_PARSE, "%s:%lu: %s element has no vertex_indices list", r->name,
                      E->line, E->name);
    for (uint64_t i = 0; i < E->count; i++) {
      double p[3] = {0, 0, 0};
      r->item = i;
      unsigned long line = r->lx.line;
      if (is_face)
        TR_CHECK(tr_soup_begin_facet(s, 0, r->binary ? (unsigned long)i : line));
      for (int k = 0; k < E->nprops; k++) {
        const prop *P = &E->props[k];
        double v;
        if (!P->count_type) {
          TR_CHECK(get(r, P->type, &v, E->name));
          if (is_vertex && P->role)
            p[P->role - 1] = v;
          if (is_face && P->role == 6) {
            if (!(v >= INT32_MIN && v <= INT32_MAX && v == floor(v)))
              return tr_error(TR_ERR_PARSE, "%s: face %llu: marker %g is not a 32-bit integer",
                              r->name, (unsigned long long)i, v);
            s->facet_marker.a[s->facet_marker.n - 1] = (uint32_t)(int32_t)v;
          }
          continue;
        }
        double c;
        TR_CHECK(get(r, P->count_type, &c, E->name));
        if (c < 0 || c > (double)(r->binary ? (size_t)(r->b.end - r->b.p) : tr_lex_left(&r->lx)))
          return tr_error(TR_ERR_PARSE, "%s: %s %llu: list length %.0f exceeds the file", r->name,
                          E->name, (unsigned long long)i, c);
        if (is_face && P->role == 4) {
          if (c < 3)
            return tr_error(TR_ERR_INPUT, "%s: face %llu has %.0f vertices (at least 3 needed)",
                            r->name, (unsigned long long)i, c);
          TR_CHECK(tr_soup_begin_loop(s));
        }
        if (is_strip && P->role == 5) {
          TR_CHECK(strip(r, s, P->type, (uint64_t)c, nv, i));
          continue;
        }
        for (uint64_t j = 0; j < (uint64_t)c; j++) {
          TR_CHECK(get(r, P->type, &v, E->name));
          if (is_face && P->role == 4) {
            if (v < 0 || v >= (double)nv || v != floor(v))
              return tr_error(TR_ERR_INPUT, "%s: face %llu: vertex index %.0f out of range (0..%llu)",
                              r->name, (unsigned long long)i, v, (unsigned long long)nv - 1);
            TR_CHECK(tr_soup_add_index(s, (uint32_t)v));
          }
        }
      }
      if (is_vertex)
        TR_CHECK(tr_soup_add_point(s, p));
    }
  }
  return TR_OK;
}

tr_status tr_read_ply_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  reader r;
  tr_soup s;
  memset(&r, 0, sizeof r);
  tr_lex_init(&r.lx, buf, len, name, 0);
  r.name = r.lx.name;
  tr_soup_init(&s, r.name);
  tr_status st = parse(&r, buf, len, &s);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  tr_soup_free(&s);
  return st;
}
