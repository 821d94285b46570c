/* TetGen files: .node (points), .poly (facets = polygons with hole points), .smesh
 * (facets = single polygons), .ele (tetrahedra, for `tetrec check`). The volume hole
 * and region lists after the facets of .poly and .smesh go to tr_plc_add_hole /
 * tr_plc_add_region.
 *
 * Indices may start at 0 or 1: the first point's number decides, as in TetGen.
 * Coordinates may be written as exact rationals "num/den" (tetrec's --exact output);
 * the readers round them to the nearest double, ties to even, and
 * tr_read_node_exact_buf (for `tetrec check`) keeps them exact. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "io.h"
#include "lex.h"
#include "soup.h"

/* Nearest double to q (ties to even). mpq_get_d truncates, so compare the truncation
 * and its neighbour away from zero exactly. */
static double q_nearest(const mpq_t q)
{
  double t = mpq_get_d(q);
  if (!isfinite(t))
    return t;
  mpq_t d, e;
  mpq_inits(d, e, NULL);
  mpq_set_d(d, t);
  if (mpq_equal(d, q)) {
    mpq_clears(d, e, NULL);
    return t;
  }
  double u = nextafter(t, mpq_sgn(q) > 0 ? INFINITY : -INFINITY);
  if (!isfinite(u)) {
    mpq_clears(d, e, NULL);
    return u;
  }
  mpq_sub(d, q, d); /* q - t */
  mpq_abs(d, d);
  mpq_set_d(e, u);
  mpq_sub(e, e, q); /* u - q */
  mpq_abs(e, e);
  int c = mpq_cmp(d, e);
  mpq_clears(d, e, NULL);
  if (c < 0)
    return t;
  if (c > 0)
    return u;
  uint64_t bt;
  memcpy(&bt, &t, 8);
  return (bt & 1) ? u : t;
}

/* The current token, [-]digits/digits or [-]digits, as an exact rational (canonical).
 * mpq_set_str accepts leading blanks and a sign only on the numerator; keep to this form
 * so junk cannot slip through. */
static tr_status rational_tok(tr_lex *lx, mpq_t q)
{
  char buf[4096];
  if (lx->toklen >= sizeof buf)
    return tr_error(TR_ERR_PARSE, "%s:%lu: rational coordinate too long", lx->name, lx->tokline);
  memcpy(buf, lx->tok, lx->toklen);
  buf[lx->toklen] = '\0';
  size_t i = buf[0] == '-' ? 1 : 0, ndig = 0, ddig = 0;
  for (; buf[i] >= '0' && buf[i] <= '9'; i++)
    ndig++;
  int slash = buf[i] == '/';
  if (slash)
    for (i++; buf[i] >= '0' && buf[i] <= '9'; i++)
      ddig++;
  if (buf[i] != '\0' || !ndig || (slash && !ddig) ||
      mpq_set_str(q, buf, 10) != 0 || mpz_sgn(mpq_denref(q)) == 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: bad rational coordinate '%.40s'", lx->name,
                    lx->tokline, buf);
  mpq_canonicalize(q);
  return TR_OK;
}

/* 1 iff the current token is an integer or a fraction (exact in rationals, possibly not
 * in doubles). */
static int rational_form(const tr_lex *lx)
{
  size_t i = lx->toklen && lx->tok[0] == '-' ? 1 : 0;
  if (i >= lx->toklen)
    return 0;
  for (; i < lx->toklen; i++)
    if (!((lx->tok[i] >= '0' && lx->tok[i] <= '9') || lx->tok[i] == '/'))
      return 0;
  return 1;
}

static tr_status coord(tr_lex *lx, double *out)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, "a point coordinate");
  const char *slash = memchr(lx->tok, '/', lx->toklen);
  if (!slash)
    return tr_lex_tok_double(lx, "a point coordinate", out);
  mpq_t q;
  mpq_init(q);
  tr_status st = rational_tok(lx, q);
  if (st == TR_OK) {
    *out = q_nearest(q);
    if (!isfinite(*out))
      st = tr_error(TR_ERR_INPUT, "%s:%lu: rational coordinate overflows a double", lx->name,
                    lx->tokline);
  }
  mpq_clear(q);
  return st;
}

/* Parallel reading of a node list that ends the buffer (a .node file): on 4x10^6 points
 * (270 MB) tokenising and converting the coordinates took 2 s of CPU, more than a tenth
 * of a whole `tetrec delaunay` run on one core.
 *
 * The rest of the buffer is cut at line ends into one chunk per thread. Each thread counts
 * the lines of its chunk that hold something other than a comment -- one point each, if
 * every point is one line "id x y z [more]" -- which places its first point; then it
 * reads its chunk with the serial code (tr_lex, coord(): the same doubles, exactly)
 * straight into the points. The result is taken only when it is what the serial reading
 * gives: every counted line a point, ids from 0 or 1 counting up by one, exactly n points.
 * Any other file -- a point split over lines, more or fewer points, anything after them,
 * any error -- is read again serially, which gives its exact message; nothing is lost but
 * the time of the attempt. */
#define PAR_MIN_BYTES ((size_t)1 << 22) /* below it the threads' start costs more */

typedef struct node_chunk {
  const char *b, *e; /* whole lines */
  const char *name;
  double *xyz;     /* where its first point goes */
  uint64_t lines;  /* lines holding a token */
  int64_t id0;     /* the id its first point must have */
  int ok;
} node_chunk;

static void *node_chunk_count(void *arg)
{
  node_chunk *c = arg;
  for (const char *p = c->b; p < c->e;) {
    while (p < c->e && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' || *p == '\v'))
      p++;
    c->lines += p < c->e && *p != '\n' && *p != '#';
    const char *nl = p < c->e ? memchr(p, '\n', (size_t)(c->e - p)) : NULL;
    p = nl ? nl + 1 : c->e;
  }
  return NULL;
}

static void *node_chunk_read(void *arg)
{
  node_chunk *c = arg;
  tr_lex lx;
  tr_lex_init(&lx, c->b, (size_t)(c->e - c->b), c->name, '#');
  uint64_t n = 0;
  c->ok = 1;
  while (c->ok && tr_lex_next(&lx)) {
    unsigned long line = lx.tokline;
    int64_t id;
    double *p = c->xyz + 3 * n;
    c->ok = n < c->lines && tr_lex_tok_i64(&lx, "a point number", &id) == TR_OK &&
            id == c->id0 + (int64_t)n;
    for (int k = 0; k < 3 && c->ok; k++)
      c->ok = coord(&lx, &p[k]) == TR_OK && lx.tokline == line;
    n++;
    if (c->ok && !tr_lex_at_eol(&lx))
      tr_lex_skip_line(&lx); /* attributes and marker */
  }
  c->ok &= n == c->lines;
  return NULL;
}

/* The n points after lx into s on up to `threads` threads; 1 if done (lx then at the end
 * of the buffer), 0 if the serial reading is to go ahead from lx. */
static int node_points_parallel(tr_lex *lx, tr_soup *s, int64_t n, int64_t *base, int threads)
{
  size_t left = tr_lex_left(lx);
  if (threads < 2 || n < 2 || left < PAR_MIN_BYTES || s->npoints)
    return 0;
  int nth = threads > 64 ? 64 : threads;
  if ((size_t)nth > left / (PAR_MIN_BYTES / 4))
    nth = (int)(left / (PAR_MIN_BYTES / 4));
  node_chunk c[64];
  const char *at = lx->p;
  for (int j = 0; j < nth; j++) {
    const char *e = j == nth - 1 ? lx->end : lx->p + left / (size_t)nth * (size_t)(j + 1);
    if (e < at)
      e = at;
    const char *nl = e < lx->end ? memchr(e, '\n', (size_t)(lx->end - e)) : NULL;
    e = j == nth - 1 || !nl ? lx->end : nl + 1;
    c[j] = (node_chunk){at, e, lx->name, NULL, 0, 0, 0};
    at = e;
  }
  tr_dt_run_jobs(node_chunk_count, c, sizeof *c, nth);
  /* the first point's id is the base, 0 or 1: read it as the serial code does */
  tr_lex first = *lx;
  int64_t id0;
  if (!tr_lex_next(&first) || tr_lex_tok_i64(&first, "a point number", &id0) != TR_OK ||
      (id0 != 0 && id0 != 1)) {
    tr_error_clear();
    return 0;
  }
  uint64_t total = 0;
  for (int j = 0; j < nth; j++) {
    c[j].xyz = s->xyz + 3 * total; /* room for the n points is reserved */
    c[j].id0 = id0 + (int64_t)total;
    total += c[j].lines;
  }
  if (total != (uint64_t)n)
    return 0;
  tr_dt_run_jobs(node_chunk_read, c, sizeof *c, nth);
  int ok = 1;
  for (int j = 0; j < nth; j++)
    ok &= c[j].ok;
  tr_error_clear(); /* a failed attempt's message; the serial reading says its own */
  if (!ok)
    return 0;
  s->npoints = (uint32_t)n;
  *base = id0;
  lx->p = lx->end;
  return 1;
}

/* Reads a node list (header + points) into s; *base = first index (0 or 1). threads > 1:
 * the list ends the buffer and may be read in parallel (node_points_parallel). */
static tr_status node_list(tr_lex *lx, tr_soup *s, int64_t *base, int threads)
{
  int64_t n, dim, nattr, nbm;
  TR_CHECK(tr_lex_i64(lx, "the point count", &n));
  unsigned long hline = lx->tokline;
  TR_CHECK(tr_lex_i64(lx, "the dimension", &dim));
  TR_CHECK(tr_lex_i64(lx, "the attribute count", &nattr));
  TR_CHECK(tr_lex_i64(lx, "the boundary marker flag", &nbm));
  if (n < 0 || nattr < 0 || nbm < 0 || nbm > 1)
    return tr_error(TR_ERR_PARSE, "%s:%lu: bad node list header", lx->name, hline);
  if (n > 0 && dim != 3)
    return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: dimension %lld (only 3 is supported)", lx->name,
                    hline, (long long)dim);
  TR_CHECK(tr_check_room(lx->name, hline, (uint64_t)n, "points", tr_lex_left(lx), 8,
                         TR_IO_MAX_COUNT / 3));
  TR_CHECK(tr_soup_reserve_points(s, (uint32_t)n));
  if (node_points_parallel(lx, s, n, base, threads))
    return TR_OK;
  for (int64_t i = 0; i < n; i++) {
    int64_t id;
    double p[3];
    TR_CHECK(tr_lex_i64(lx, "a point number", &id));
    if (i == 0) {
      if (id != 0 && id != 1)
        return tr_error(TR_ERR_INPUT, "%s:%lu: first point is numbered %lld (0 or 1 expected)",
                        lx->name, lx->tokline, (long long)id);
      *base = id;
    } else if (id != *base + i)
      return tr_error(TR_ERR_INPUT, "%s:%lu: point number %lld out of sequence (%lld expected)",
                      lx->name, lx->tokline, (long long)id, (long long)(*base + i));
    for (int k = 0; k < 3; k++)
      TR_CHECK(coord(lx, &p[k]));
    TR_CHECK(tr_soup_add_point(s, p));
    if (!tr_lex_at_eol(lx))
      tr_lex_skip_line(lx); /* attributes and marker */
  }
  return TR_OK;
}

static tr_status vindex(tr_lex *lx, const tr_soup *s, int64_t base, uint32_t *out)
{
  int64_t v;
  TR_CHECK(tr_lex_i64(lx, "a vertex number", &v));
  if (v < base || v - base >= (int64_t)s->npoints)
    return tr_error(TR_ERR_INPUT, "%s:%lu: vertex number %lld out of range (%lld..%lld)",
                    lx->name, lx->tokline, (long long)v, (long long)base,
                    (long long)(base + s->npoints - 1));
  *out = (uint32_t)(v - base);
  return TR_OK;
}

static tr_status polygon(tr_lex *lx, tr_soup *s, int64_t base, unsigned long *line)
{
  int64_t k;
  TR_CHECK(tr_lex_i64(lx, "a polygon size", &k));
  *line = lx->tokline;
  if (k < 1 || (uint64_t)k > tr_lex_left(lx))
    return tr_error(TR_ERR_INPUT, "%s:%lu: polygon with %lld vertices", lx->name, lx->tokline,
                    (long long)k);
  if (k < 3)
    return tr_error(TR_ERR_UNSUPPORTED,
                    "%s:%lu: polygon with %lld vertices (segments and isolated points in "
                    "facets are not supported)", lx->name, lx->tokline, (long long)k);
  TR_CHECK(tr_soup_begin_loop(s));
  for (int64_t j = 0; j < k; j++) {
    uint32_t v = 0;
    TR_CHECK(vindex(lx, s, base, &v));
    TR_CHECK(tr_soup_add_index(s, v));
  }
  return TR_OK;
}

static tr_status facets(tr_lex *lx, tr_soup *s, int64_t base, int smesh)
{
  int64_t nf, nbm = 0;
  TR_CHECK(tr_lex_i64(lx, "the facet count", &nf));
  unsigned long hline = lx->tokline;
  if (!tr_lex_at_eol(lx))
    TR_CHECK(tr_lex_i64(lx, "the facet marker flag", &nbm));
  if (nf < 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: negative facet count", lx->name, hline);
  TR_CHECK(tr_check_room(lx->name, hline, (uint64_t)nf, "facets", tr_lex_left(lx), 8,
                         TR_IO_MAX_COUNT / 3));
  for (int64_t f = 0; f < nf; f++) {
    int64_t npoly = 1, nholes = 0, marker = 0;
    unsigned long line = lx->line;
    if (smesh) {
      TR_CHECK(tr_soup_begin_facet(s, 0, line));
      TR_CHECK(polygon(lx, s, base, &line));
      if (nbm && !tr_lex_at_eol(lx)) {
        TR_CHECK(tr_lex_i64(lx, "a facet marker", &marker));
        s->facet_marker.a[s->facet_marker.n - 1] = (uint32_t)(int32_t)marker;
      }
      s->facet_line.a[s->facet_line.n - 1] = (uint32_t)line;
      if (!tr_lex_at_eol(lx))
        tr_lex_skip_line(lx);
      continue;
    }
    TR_CHECK(tr_lex_i64(lx, "a facet's polygon count", &npoly));
    line = lx->tokline;
    if (!tr_lex_at_eol(lx))
      TR_CHECK(tr_lex_i64(lx, "a facet's hole count", &nholes));
    if (nbm && !tr_lex_at_eol(lx))
      TR_CHECK(tr_lex_i64(lx, "a facet marker", &marker));
    if (npoly < 0 || nholes < 0 || (uint64_t)npoly > tr_lex_left(lx) ||
        (uint64_t)nholes > tr_lex_left(lx))
      return tr_error(TR_ERR_PARSE, "%s:%lu: bad facet header", lx->name, line);
    TR_CHECK(tr_soup_begin_facet(s, (int32_t)marker, line));
    for (int64_t p = 0; p < npoly; p++) {
      unsigned long pl;
      TR_CHECK(polygon(lx, s, base, &pl));
      if (!tr_lex_at_eol(lx))
        tr_lex_skip_line(lx);
    }
    for (int64_t h = 0; h < nholes; h++) {
      int64_t id;
      double q[3];
      TR_CHECK(tr_lex_i64(lx, "a hole number", &id));
      for (int k = 0; k < 3; k++)
        TR_CHECK(coord(lx, &q[k]));
      TR_CHECK(tr_soup_add_hole(s, q));
    }
  }
  return TR_OK;
}

/* The hole and region points that follow the facets of a .poly or .smesh file; both
 * sections are optional at the end of the file. */
typedef struct {
  uint32_t nholes, nregions;
  double *holes;   /* 3 per hole */
  double *regions; /* 5 per region: x y z attribute max_volume */
} volume_points;

static int more_tokens(const tr_lex *lx)
{
  tr_lex peek = *lx;
  return tr_lex_next(&peek);
}

static tr_status point_section(tr_lex *lx, const char *what, int per, uint32_t *n, double **out)
{
  int64_t count;
  TR_CHECK(tr_lex_i64(lx, what, &count));
  unsigned long hline = lx->tokline;
  if (count < 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: negative %s", lx->name, hline, what);
  TR_CHECK(tr_check_room(lx->name, hline, (uint64_t)count, per == 3 ? "hole points" :
                         "region points", tr_lex_left(lx), 8, TR_IO_MAX_COUNT / 8));
  double *a = malloc(sizeof *a * (size_t)per * (size_t)(count ? count : 1));
  if (!a)
    return tr_error(TR_ERR_NOMEM, "out of memory reading %s", lx->name);
  tr_status st = TR_OK;
  for (int64_t i = 0; i < count && st == TR_OK; i++) {
    int64_t id;
    double *p = a + (size_t)per * (size_t)i;
    st = tr_lex_i64(lx, per == 3 ? "a hole number" : "a region number", &id);
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = coord(lx, &p[k]);
    if (st == TR_OK && per == 5) {
      /* TetGen's regional attribute is a number; tetrec's region ids are int32 */
      st = tr_lex_double(lx, "a region attribute", &p[3]);
      if (st == TR_OK && !(p[3] == floor(p[3]) && p[3] >= INT32_MIN && p[3] <= INT32_MAX))
        st = tr_error(TR_ERR_UNSUPPORTED,
                      "%s:%lu: region attribute %.17g is not a 32-bit integer (region ids are "
                      "integers)", lx->name, lx->tokline, p[3]);
      p[4] = 0;
      if (st == TR_OK && !tr_lex_at_eol(lx))
        st = tr_lex_double(lx, "a region's maximum volume", &p[4]);
    }
    if (st == TR_OK && !tr_lex_at_eol(lx))
      st = tr_error(TR_ERR_PARSE, "%s:%lu: unexpected text after %s %lld", lx->name, lx->line,
                    per == 3 ? "hole point" : "region point", (long long)id);
  }
  if (st != TR_OK) {
    free(a);
    return st;
  }
  *n = (uint32_t)count;
  *out = a;
  return TR_OK;
}

static tr_status volume_sections(tr_lex *lx, volume_points *vp)
{
  if (!more_tokens(lx))
    return TR_OK;
  TR_CHECK(point_section(lx, "the hole count", 3, &vp->nholes, &vp->holes));
  if (!more_tokens(lx))
    return TR_OK;
  TR_CHECK(point_section(lx, "the region count", 5, &vp->nregions, &vp->regions));
  if (more_tokens(lx))
    return tr_error(TR_ERR_PARSE, "%s:%lu: unexpected text after the region list", lx->name,
                    lx->line);
  return TR_OK;
}

static tr_status parse(enum tr_tetgen_kind kind, tr_lex *lx, tr_lex *nodes, tr_soup *s,
                       volume_points *vp, int threads)
{
  int64_t base = 0;
  /* only a .node file's list ends its buffer */
  TR_CHECK(node_list(lx, s, &base, kind == TR_TETGEN_NODE ? threads : 1));
  if (kind == TR_TETGEN_NODE)
    return TR_OK;
  if (s->npoints == 0) {
    if (!nodes)
      return tr_error(TR_ERR_INPUT, "%s: the point list is empty and no .node file was found",
                      lx->name);
    TR_CHECK(node_list(nodes, s, &base, threads));
  }
  TR_CHECK(facets(lx, s, base, kind == TR_TETGEN_SMESH));
  return volume_sections(lx, vp);
}

tr_status tr_read_tetgen_buf(enum tr_tetgen_kind kind, const char *buf, size_t len,
                             const char *name, const char *node_buf, size_t node_len,
                             const char *node_name, struct tr_plc *plc)
{
  return tr_read_tetgen_buf_threads(kind, buf, len, name, node_buf, node_len, node_name, plc,
                                    1);
}

tr_status tr_read_tetgen_buf_threads(enum tr_tetgen_kind kind, const char *buf, size_t len,
                                     const char *name, const char *node_buf, size_t node_len,
                                     const char *node_name, struct tr_plc *plc, int threads)
{
  tr_lex lx, nl;
  tr_soup s;
  if (kind == TR_TETGEN_ELE)
    return tr_read_ele_buf(buf, len, name, plc);
  tr_lex_init(&lx, buf, len, name, '#');
  if (node_buf)
    tr_lex_init(&nl, node_buf, node_len, node_name, '#');
  tr_soup_init(&s, lx.name);
  volume_points vp = {0, 0, NULL, NULL};
  tr_status st = parse(kind, &lx, node_buf ? &nl : NULL, &s, &vp, threads);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  for (uint32_t i = 0; st == TR_OK && i < vp.nholes; i++) {
    const double *h = vp.holes + 3 * (size_t)i;
    st = tr_plc_add_hole(plc, h[0], h[1], h[2]);
  }
  for (uint32_t i = 0; st == TR_OK && i < vp.nregions; i++) {
    const double *r = vp.regions + 5 * (size_t)i;
    st = tr_plc_add_region(plc, r[0], r[1], r[2], (int32_t)r[3], r[4]);
  }
  free(vp.holes);
  free(vp.regions);
  tr_soup_free(&s);
  return st;
}

tr_status tr_read_ele_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  tr_lex lx;
  tr_lex_init(&lx, buf, len, name, '#');
  int64_t n, per, nattr = 0, base = 0;
  TR_CHECK(tr_lex_i64(&lx, "the tetrahedron count", &n));
  unsigned long hline = lx.tokline;
  TR_CHECK(tr_lex_i64(&lx, "the nodes per tetrahedron", &per));
  if (!tr_lex_at_eol(&lx))
    TR_CHECK(tr_lex_i64(&lx, "the attribute count", &nattr));
  if (n < 0 || (per != 4 && per != 10))
    return tr_error(TR_ERR_PARSE, "%s:%lu: bad .ele header", lx.name, hline);
  TR_CHECK(tr_check_room(lx.name, hline, (uint64_t)n, "tetrahedra", tr_lex_left(&lx), 10,
                         TR_IO_MAX_COUNT / 4));
  uint32_t *t = malloc(sizeof *t * 4 * (size_t)(n ? n : 1));
  if (!t)
    return tr_error(TR_ERR_NOMEM, "out of memory reading %s", lx.name);
  tr_status st = TR_OK;
  for (int64_t i = 0; i < n && st == TR_OK; i++) {
    int64_t id, v;
    st = tr_lex_i64(&lx, "a tetrahedron number", &id);
    if (st == TR_OK && i == 0)
      base = id == 1 ? 1 : 0;
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      st = tr_lex_i64(&lx, "a vertex number", &v);
      if (st == TR_OK && (v < base || v - base >= (int64_t)plc->npoints))
        st = tr_error(TR_ERR_INPUT, "%s:%lu: tetrahedron %lld: vertex number %lld out of range",
                      lx.name, lx.tokline, (long long)id, (long long)v);
      if (st == TR_OK)
        t[4 * i + k] = (uint32_t)(v - base);
    }
    if (st == TR_OK && !tr_lex_at_eol(&lx))
      tr_lex_skip_line(&lx);
  }
  if (st != TR_OK) {
    free(t);
    return st;
  }
  free(plc->tets);
  plc->tets = t;
  plc->ntets = (uint32_t)n;
  return TR_OK;
}

/* The exact reading of a .node file for `tetrec check` (declared in src/cli/cli.h). */
static void free_points(tr_qpoint **q, uint32_t n)
{
  for (uint32_t i = 0; q && i < n; i++)
    if (q[i]) {
      tr_qpoint_clear(q[i]);
      free(q[i]);
    }
  free(q);
}

tr_status tr_read_node_exact_buf(const char *buf, size_t len, const char *name,
                                 tr_qpoint ***out, uint32_t *npoints, int *exact_file)
{
  static const char mark[] = "# tetrec exact rationals";
  *out = NULL;
  *npoints = 0;
  *exact_file = len >= sizeof mark - 1 && !memcmp(buf, mark, sizeof mark - 1);
  tr_lex lx;
  tr_lex_init(&lx, buf, len, name, '#');
  int64_t n, dim, nattr, nbm;
  TR_CHECK(tr_lex_i64(&lx, "the point count", &n));
  unsigned long hline = lx.tokline;
  TR_CHECK(tr_lex_i64(&lx, "the dimension", &dim));
  TR_CHECK(tr_lex_i64(&lx, "the attribute count", &nattr));
  TR_CHECK(tr_lex_i64(&lx, "the boundary marker flag", &nbm));
  if (n < 0 || (n > 0 && dim != 3))
    return tr_error(TR_ERR_PARSE, "%s:%lu: bad node list header", lx.name, hline);
  TR_CHECK(tr_check_room(lx.name, hline, (uint64_t)n, "points", tr_lex_left(&lx), 8,
                         TR_IO_MAX_COUNT / 3));
  tr_qpoint **q = calloc(n ? (size_t)n : 1, sizeof *q);
  tr_qpoint *cur = malloc(sizeof *cur);
  if (!q || !cur) {
    free(q);
    free(cur);
    return tr_error(TR_ERR_NOMEM, "out of memory reading %s", lx.name);
  }
  tr_qpoint_init(cur);
  tr_status st = TR_OK;
  for (int64_t i = 0; i < n && st == TR_OK; i++) {
    int64_t id;
    st = tr_lex_i64(&lx, "a point number", &id);
    for (int k = 0; k < 3 && st == TR_OK; k++) {
      double d;
      if (!tr_lex_next(&lx))
        st = tr_lex_eof(&lx, "a point coordinate");
      else if (rational_form(&lx)) {
        st = rational_tok(&lx, cur->c[k]);
        *exact_file |= memchr(lx.tok, '/', lx.toklen) != NULL;
      } else if ((st = tr_lex_tok_double(&lx, "a point coordinate", &d)) == TR_OK)
        mpq_set_d(cur->c[k], d);
    }
    if (st != TR_OK)
      break;
    tr_qpoint_update(cur);
    int is_double = 1;
    for (int k = 0; k < 3; k++)
      is_double &= cur->lo[k] == cur->hi[k];
    /* a point that is a double stays a plain point (as an input point would) */
    if (!is_double) {
      q[i] = cur;
      if (!(cur = malloc(sizeof *cur))) {
        st = tr_error(TR_ERR_NOMEM, "out of memory reading %s", lx.name);
        break;
      }
      tr_qpoint_init(cur);
    }
    if (!tr_lex_at_eol(&lx))
      tr_lex_skip_line(&lx);
  }
  if (cur) {
    tr_qpoint_clear(cur);
    free(cur);
  }
  if (st != TR_OK) {
    free_points(q, (uint32_t)n);
    return st;
  }
  *out = q;
  *npoints = (uint32_t)n;
  return TR_OK;
}
