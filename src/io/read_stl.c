/* STL, ASCII and binary. A binary file is recognised by its size (84 + 50 n bytes for the
 * n in its header), not by its first bytes: many binary STLs start with "solid" too.
 * STL has no shared vertices; they are merged when their coordinates are exactly equal
 * (bitwise after identifying -0.0 with 0.0), never within a tolerance. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "lex.h"
#include "soup.h"

static const double *g_pts; /* qsort has no context argument in C11 */

static int cmp_pt(const void *pa, const void *pb)
{
  uint32_t a = *(const uint32_t *)pa, b = *(const uint32_t *)pb;
  for (int k = 0; k < 3; k++) {
    double x = g_pts[3 * (size_t)a + k], y = g_pts[3 * (size_t)b + k];
    if (x < y)
      return -1;
    if (x > y)
      return 1;
  }
  return (a > b) - (a < b); /* ties by index keep the result deterministic */
}

static int same_pt(const double *raw, uint32_t a, uint32_t b)
{
  /* == identifies -0.0 with 0.0, exactly what we want. */
  return raw[3 * (size_t)a] == raw[3 * (size_t)b] &&
         raw[3 * (size_t)a + 1] == raw[3 * (size_t)b + 1] &&
         raw[3 * (size_t)a + 2] == raw[3 * (size_t)b + 2];
}

/* A hash of the point's coordinates, -0.0 taken as 0.0 so that equal points hash alike. */
static uint64_t pt_hash(const double *p)
{
  uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int k = 0; k < 3; k++) {
    double x = p[k] == 0 ? 0.0 : p[k];
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    h = (h ^ u) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return h;
}

/* rep[i] = the first index whose point equals point i. The points are grouped by a
 * hash with a stable radix sort (a qsort of the points was most of the reading of a
 * large STL), and a group is resolved by comparing its points exactly; a group that
 * is long (colliding hashes, which a crafted file could make) is sorted by the
 * coordinates instead, so that the time stays n log n. The answer does not depend on
 * the grouping: only on which points are equal. */
static tr_status find_reps(const double *raw, uint32_t n, uint32_t *rep)
{
  uint64_t *h = malloc(sizeof *h * (n ? n : 1)), *h2 = malloc(sizeof *h2 * (n ? n : 1));
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1)), *o2 = malloc(sizeof *o2 * (n ? n : 1));
  uint32_t *cnt = malloc(sizeof *cnt * 65536);
  tr_status st = TR_OK;
  if (!h || !h2 || !ord || !o2 || !cnt) {
    st = tr_error(TR_ERR_NOMEM, "out of memory merging STL vertices");
    goto done;
  }
  for (uint32_t i = 0; i < n; i++) {
    h[i] = pt_hash(raw + 3 * (size_t)i);
    ord[i] = i;
  }
  for (int pass = 0; pass < 4; pass++) {
    int sh = 16 * pass;
    memset(cnt, 0, sizeof *cnt * 65536);
    for (uint32_t i = 0; i < n; i++)
      cnt[(h[i] >> sh) & 0xffff]++;
    for (uint32_t d = 0, sum = 0; d < 65536; d++) {
      uint32_t c = cnt[d];
      cnt[d] = sum;
      sum += c;
    }
    for (uint32_t i = 0; i < n; i++) {
      uint32_t k = cnt[(h[i] >> sh) & 0xffff]++;
      h2[k] = h[i];
      o2[k] = ord[i];
    }
    uint64_t *th = h;
    h = h2;
    h2 = th;
    uint32_t *to = ord;
    ord = o2;
    o2 = to;
  }
  for (uint32_t i = 0; i < n;) {
    uint32_t j = i + 1;
    while (j < n && h[j] == h[i])
      j++;
    /* the group ord[i..j) in increasing index (the sort is stable) */
    if (j - i <= 32) {
      for (uint32_t k = i; k < j; k++) {
        rep[ord[k]] = ord[k];
        for (uint32_t q = i; q < k; q++)
          if (same_pt(raw, ord[q], ord[k])) {
            rep[ord[k]] = rep[ord[q]];
            break;
          }
      }
    } else {
      g_pts = raw;
      qsort(ord + i, j - i, sizeof *ord, cmp_pt);
      for (uint32_t a = i; a < j;) {
        uint32_t b = a;
        while (b < j && same_pt(raw, ord[a], ord[b]))
          b++;
        for (uint32_t k = a; k < b; k++)
          rep[ord[k]] = ord[a]; /* sorted by index within the run: ord[a] is the first */
        a = b;
      }
    }
    i = j;
  }
done:
  free(h);
  free(h2);
  free(ord);
  free(o2);
  free(cnt);
  return st;
}

/* raw: 9 doubles per triangle. Builds points (first occurrence order) and triangles. */
static tr_status merge(const double *raw, uint32_t ntri, tr_soup *s, const unsigned long *lines)
{
  uint32_t n = 3 * ntri;
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1)), *rep = malloc(sizeof *rep * (n ? n : 1));
  if (!ord || !rep) {
    free(ord);
    free(rep);
    return tr_error(TR_ERR_NOMEM, "out of memory merging STL vertices");
  }
  tr_status fr = find_reps(raw, n, rep);
  if (fr != TR_OK) {
    free(ord);
    free(rep);
    return fr;
  }
  tr_status st = TR_OK;
  /* Number the points in order of first occurrence. ord is reused as the new id. */
  for (uint32_t i = 0; i < n && st == TR_OK; i++) {
    if (rep[i] == i) {
      ord[i] = s->npoints;
      double p[3];
      for (int k = 0; k < 3; k++)
        p[k] = raw[3 * (size_t)i + k] == 0 ? 0.0 : raw[3 * (size_t)i + k];
      st = tr_soup_add_point(s, p);
    }
  }
  for (uint32_t t = 0; t < ntri && st == TR_OK; t++) {
    st = tr_soup_begin_facet(s, 0, lines ? lines[t] : t);
    if (st == TR_OK)
      st = tr_soup_begin_loop(s);
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = tr_soup_add_index(s, ord[rep[3 * t + k]]);
  }
  free(ord);
  free(rep);
  return st;
}

static tr_status expect(tr_lex *lx, const char *word)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, word);
  if (!tr_lex_is(lx, word))
    return tr_error(TR_ERR_PARSE, "%s:%lu: expected '%s', found '%.*s'", lx->name, lx->tokline,
                    word, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
  return TR_OK;
}

static tr_status parse_ascii(const char *buf, size_t len, const char *name, tr_soup *s)
{
  tr_lex lx;
  tr_lex_init(&lx, buf, len, name, 0);
  double *raw = NULL;
  unsigned long *lines = NULL;
  uint32_t n = 0, cap = 0;
  tr_status st = TR_OK;
  int in_solid = 0;
  while (st == TR_OK && tr_lex_next(&lx)) {
    if (tr_lex_is(&lx, "solid")) {
      if (in_solid) {
        st = tr_error(TR_ERR_PARSE, "%s:%lu: 'solid' inside a solid", lx.name, lx.tokline);
        break;
      }
      in_solid = 1;
      tr_lex_skip_line(&lx); /* the solid's name */
      continue;
    }
    if (tr_lex_is(&lx, "endsolid")) {
      if (!in_solid) {
        st = tr_error(TR_ERR_PARSE, "%s:%lu: 'endsolid' without 'solid'", lx.name, lx.tokline);
        break;
      }
      in_solid = 0;
      tr_lex_skip_line(&lx);
      continue;
    }
    if (!tr_lex_is(&lx, "facet") || !in_solid) {
      st = tr_error(TR_ERR_PARSE, "%s:%lu: expected 'facet' or 'endsolid', found '%.*s'",
                    lx.name, lx.tokline, (int)(lx.toklen > 40 ? 40 : lx.toklen), lx.tok);
      break;
    }
    unsigned long line = lx.tokline;
    if (n == cap) {
      if (cap >= TR_IO_MAX_COUNT / 3) {
        st = tr_error(TR_ERR_NOMEM, "%s: too many triangles", lx.name);
        break;
      }
      cap = cap ? 2 * cap : 64;
      double *r = realloc(raw, sizeof *raw * 9 * cap);
      if (r)
        raw = r;
      unsigned long *l = realloc(lines, sizeof *lines * cap);
      if (l)
        lines = l;
      if (!r || !l) {
        st = tr_error(TR_ERR_NOMEM, "out of memory reading %s", lx.name);
        break;
      }
    }
    double nrm;
    st = expect(&lx, "normal");
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = tr_lex_double(&lx, "a normal component", &nrm);
    if (st == TR_OK)
      st = expect(&lx, "outer");
    if (st == TR_OK)
      st = expect(&lx, "loop");
    for (int v = 0; v < 3 && st == TR_OK; v++) {
      st = expect(&lx, "vertex");
      for (int k = 0; k < 3 && st == TR_OK; k++)
        st = tr_lex_double(&lx, "a vertex coordinate", &raw[9 * (size_t)n + 3 * v + k]);
    }
    if (st == TR_OK)
      st = expect(&lx, "endloop");
    if (st == TR_OK)
      st = expect(&lx, "endfacet");
    lines[n++] = line;
  }
  if (st == TR_OK && in_solid)
    st = tr_error(TR_ERR_PARSE, "%s:%lu: file ends inside a solid (missing 'endsolid')", lx.name,
                  lx.line);
  if (st == TR_OK)
    st = merge(raw, n, s, lines);
  free(raw);
  free(lines);
  return st;
}

static double le_float(const unsigned char *p)
{
  uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
  float f;
  memcpy(&f, &u, 4);
  return (double)f; /* float -> double is exact */
}

static tr_status parse_binary(const unsigned char *b, uint32_t n, const char *name, tr_soup *s)
{
  double *raw = malloc(sizeof *raw * 9 * (size_t)(n ? n : 1));
  if (!raw)
    return tr_error(TR_ERR_NOMEM, "out of memory reading %s", name);
  for (uint32_t t = 0; t < n; t++) {
    const unsigned char *r = b + 84 + 50 * (size_t)t + 12; /* skip the normal */
    for (int k = 0; k < 9; k++) {
      double x = le_float(r + 4 * k);
      if (!isfinite(x)) {
        free(raw);
        return tr_error(TR_ERR_INPUT, "%s: triangle %u: coordinate is NaN or infinite", name, t);
      }
      raw[9 * (size_t)t + k] = x;
    }
  }
  tr_status st = merge(raw, n, s, NULL);
  free(raw);
  return st;
}

tr_status tr_read_stl_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  tr_soup s;
  tr_status st;
  if (!name)
    name = "<buffer>";
  tr_soup_init(&s, name);
  const unsigned char *b = (const unsigned char *)buf;
  uint64_t n = len >= 84 ? ((uint32_t)b[80] | (uint32_t)b[81] << 8 | (uint32_t)b[82] << 16 |
                            (uint32_t)b[83] << 24)
                         : 0;
  size_t i = 0;
  while (i < len && (buf[i] == ' ' || buf[i] == '\t' || buf[i] == '\r' || buf[i] == '\n'))
    i++;
  int starts_solid = len - i >= 5 && strncmp(buf + i, "solid", 5) == 0;
  if (len >= 84 && 84 + 50 * n == len) {
    if (n > TR_IO_MAX_COUNT / 3)
      return tr_error(TR_ERR_NOMEM, "%s: %llu triangles exceed the limit", name,
                      (unsigned long long)n);
    st = parse_binary(b, (uint32_t)n, name, &s);
  } else if (starts_solid)
    st = parse_ascii(buf, len, name, &s);
  else if (len >= 84)
    st = tr_error(TR_ERR_PARSE, "%s: binary STL header declares %llu triangles but the file has "
                  "room for at most %llu", name, (unsigned long long)n,
                  (unsigned long long)((len - 84) / 50));
  else
    st = tr_error(TR_ERR_PARSE, "%s: not an STL file (too short for binary, no 'solid')", name);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  tr_soup_free(&s);
  return st;
}
