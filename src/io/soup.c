#include "soup.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/hugepage.h"

static tr_status grow(void **a, uint32_t *cap, uint32_t need, size_t elt)
{
  if (need <= *cap)
    return TR_OK;
  if (need > TR_IO_MAX_COUNT)
    return tr_error(TR_ERR_NOMEM, "more than %u elements in one array", TR_IO_MAX_COUNT);
  uint64_t c = *cap ? *cap : 16;
  while (c < need)
    c *= 2;
  if (c > TR_IO_MAX_COUNT)
    c = TR_IO_MAX_COUNT;
  void *p = realloc(*a, (size_t)c * elt);
  if (!p)
    return tr_error(TR_ERR_NOMEM, "out of memory (%llu elements)", (unsigned long long)c);
  /* huge pages for the large arrays (the points of a big .node: 100 MB in 24k small
   * pages otherwise, each a fault) */
  tr_advise_hugepages(p, (size_t)c * elt);
  *a = p;
  *cap = (uint32_t)c;
  return TR_OK;
}

tr_status tr_u32vec_reserve(tr_u32vec *v, uint32_t n)
{
  return grow((void **)&v->a, &v->cap, n, sizeof *v->a);
}

tr_status tr_u32vec_push(tr_u32vec *v, uint32_t x)
{
  if (v->n == v->cap)
    TR_CHECK(grow((void **)&v->a, &v->cap, v->n + 1, sizeof *v->a));
  v->a[v->n++] = x;
  return TR_OK;
}

void tr_u32vec_free(tr_u32vec *v)
{
  free(v->a);
  memset(v, 0, sizeof *v);
}

void tr_soup_init(tr_soup *s, const char *name)
{
  memset(s, 0, sizeof *s);
  s->name = name ? name : "<buffer>";
}

void tr_soup_free(tr_soup *s)
{
  free(s->xyz);
  free(s->holes);
  tr_u32vec_free(&s->facet_loop);
  tr_u32vec_free(&s->facet_hole);
  tr_u32vec_free(&s->facet_line);
  tr_u32vec_free(&s->facet_marker);
  tr_u32vec_free(&s->loop_first);
  tr_u32vec_free(&s->idx);
  tr_u32vec_free(&s->tets);
  s->xyz = s->holes = NULL;
  s->npoints = s->cap_points = s->nholes = s->cap_holes = 0;
}

tr_status tr_soup_reserve_points(tr_soup *s, uint32_t n)
{
  if (n > TR_IO_MAX_COUNT / 3)
    return tr_error(TR_ERR_NOMEM, "%s: %u points exceed the limit", s->name, n);
  return grow((void **)&s->xyz, &s->cap_points, n, 3 * sizeof(double));
}

tr_status tr_soup_add_point(tr_soup *s, const double p[3])
{
  if (s->npoints == s->cap_points)
    TR_CHECK(tr_soup_reserve_points(s, s->npoints + 1));
  memcpy(s->xyz + 3 * (size_t)s->npoints, p, 3 * sizeof(double));
  s->npoints++;
  return TR_OK;
}

tr_status tr_soup_begin_facet(tr_soup *s, int32_t marker, unsigned long line)
{
  TR_CHECK(tr_u32vec_push(&s->facet_loop, s->loop_first.n));
  TR_CHECK(tr_u32vec_push(&s->facet_hole, s->nholes));
  TR_CHECK(tr_u32vec_push(&s->facet_line, line > UINT32_MAX ? UINT32_MAX : (uint32_t)line));
  return tr_u32vec_push(&s->facet_marker, (uint32_t)marker);
}

tr_status tr_soup_begin_loop(tr_soup *s) { return tr_u32vec_push(&s->loop_first, s->idx.n); }

tr_status tr_soup_add_index(tr_soup *s, uint32_t v) { return tr_u32vec_push(&s->idx, v); }

tr_status tr_soup_add_hole(tr_soup *s, const double p[3])
{
  if (s->nholes == s->cap_holes)
    TR_CHECK(grow((void **)&s->holes, &s->cap_holes, s->nholes + 1, 3 * sizeof(double)));
  memcpy(s->holes + 3 * (size_t)s->nholes, p, 3 * sizeof(double));
  s->nholes++;
  return TR_OK;
}

/* Appends line to *notes (malloc'ed, one line each). */
static tr_status add_note(char **notes, const char *line)
{
  size_t a = *notes ? strlen(*notes) : 0, b = strlen(line);
  char *n = realloc(*notes, a + b + 2);
  if (!n)
    return tr_error(TR_ERR_NOMEM, "out of memory");
  memcpy(n + a, line, b);
  n[a + b] = '\n', n[a + b + 1] = 0;
  *notes = n;
  return TR_OK;
}

/* tr_plc.read_fans: the fan of the loop idx[0..n-1] from its first corner, after the
 * exact triangulation refused it for `why` (TR_ERR_INPUT's message). */
static tr_status fan(const uint32_t *idx, uint32_t n, tr_u32vec *tris, const char *why,
                     uint32_t facet, tr_u32vec *fans, char **notes)
{
  if (fans->n < TR_PLC_FAN_NOTES)
    TR_CHECK(add_note(notes, why));
  TR_CHECK(tr_u32vec_push(fans, facet));
  for (uint32_t k = 1; k + 1 < n; k++) {
    TR_CHECK(tr_u32vec_push(tris, idx[0]));
    TR_CHECK(tr_u32vec_push(tris, idx[k]));
    TR_CHECK(tr_u32vec_push(tris, idx[k + 1]));
  }
  return TR_OK;
}

tr_status tr_soup_to_plc(tr_soup *s, struct tr_plc *plc)
{
  tr_u32vec tris = {0}, src = {0}, mark = {0};
  tr_status st = TR_OK;
  int read_fans = plc->read_fans;
  tr_u32vec fans = {0};
  char *notes = NULL;
  uint32_t nf = s->facet_loop.n;
  for (uint32_t i = 0; i < s->idx.n; i++)
    if (s->idx.a[i] >= s->npoints) {
      /* Readers check ranges with their own numbering; this is the safety net. */
      return tr_error(TR_ERR_INPUT, "%s: vertex index %u out of range (%u vertices)", s->name,
                      s->idx.a[i], s->npoints);
    }
  for (uint32_t i = 0; i < s->tets.n; i++)
    if (s->tets.a[i] >= s->npoints)
      return tr_error(TR_ERR_INPUT, "%s: tetrahedron %u references vertex %u, out of range",
                      s->name, i / 4, s->tets.a[i]);
  for (uint32_t f = 0; f < nf && st == TR_OK; f++) {
    uint32_t l0 = s->facet_loop.a[f];
    uint32_t l1 = f + 1 < nf ? s->facet_loop.a[f + 1] : s->loop_first.n;
    uint32_t h0 = s->facet_hole.a[f];
    uint32_t h1 = f + 1 < nf ? s->facet_hole.a[f + 1] : s->nholes;
    uint32_t i0 = l0 < s->loop_first.n ? s->loop_first.a[l0] : s->idx.n;
    uint32_t i1 = l1 < s->loop_first.n ? s->loop_first.a[l1] : s->idx.n;
    uint32_t before = tris.n;
    if (l1 == l0)
      continue; /* an empty facet (TetGen allows 0 polygons) contributes nothing */
    if (l1 - l0 == 1 && i1 - i0 == 3 && h1 == h0) {
      for (uint32_t k = i0; k < i1 && st == TR_OK; k++)
        st = tr_u32vec_push(&tris, s->idx.a[k]);
    } else {
      char what[160];
      snprintf(what, sizeof what, "%s:%u: facet %u", s->name, s->facet_line.a[f], f);
      /* Loop starts relative to the facet's first index. */
      uint32_t lf[64], *lfp = lf;
      uint32_t nl = l1 - l0;
      if (nl > 64) {
        lfp = malloc(sizeof *lfp * nl);
        if (!lfp) {
          st = tr_error(TR_ERR_NOMEM, "out of memory");
          break;
        }
      }
      for (uint32_t l = 0; l < nl; l++)
        lfp[l] = s->loop_first.a[l0 + l] - i0;
      st = tr_triangulate_facet(s->xyz, s->idx.a + i0, lfp, nl, i1 - i0,
                                s->holes ? s->holes + 3 * (size_t)h0 : NULL,
                                h1 - h0, &tris, what);
      if (st == TR_ERR_INPUT && read_fans && nl == 1 && h1 == h0 && i1 - i0 >= 3) {
        tris.n = before; /* whatever the refused triangulation had pushed */
        st = fan(s->idx.a + i0, i1 - i0, &tris, tr_last_error(), f, &fans, &notes);
        tr_error_clear();
      }
      if (lfp != lf)
        free(lfp);
    }
    for (uint32_t t = before / 3; t < tris.n / 3 && st == TR_OK; t++) {
      st = tr_u32vec_push(&src, f);
      if (st == TR_OK)
        st = tr_u32vec_push(&mark, s->facet_marker.a[f]);
    }
  }
  if (st != TR_OK) {
    tr_u32vec_free(&tris);
    tr_u32vec_free(&src);
    tr_u32vec_free(&mark);
    tr_u32vec_free(&fans);
    free(notes);
    return st;
  }
  tr_plc_clear(plc);
  plc->read_fans = (uint8_t)read_fans;
  plc->nfans = fans.n;
  plc->fan_facet = fans.a;
  plc->fan_notes = notes;
  plc->npoints = s->npoints;
  plc->xyz = s->xyz;
  s->xyz = NULL;
  s->npoints = s->cap_points = 0;
  plc->ntris = tris.n / 3;
  plc->tris = tris.a;
  plc->tri_marker = (int32_t *)mark.a;
  plc->tri_source = src.a;
  plc->ntets = s->tets.n / 4;
  plc->tets = s->tets.a;
  memset(&s->tets, 0, sizeof s->tets);
  if (!plc->xyz) {
    plc->xyz = malloc(3 * sizeof(double)); /* keep non-NULL arrays for callers */
    if (!plc->xyz)
      return tr_error(TR_ERR_NOMEM, "out of memory");
  }
  return TR_OK;
}

tr_status tr_soup_read_text(const char *buf, size_t len, const char *name, char comment,
                            tr_soup_parse_fn parse, struct tr_plc *plc)
{
  tr_lex lx;
  tr_soup s;
  tr_lex_init(&lx, buf, len, name, comment);
  tr_soup_init(&s, lx.name);
  tr_status st = parse(&lx, &s);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  tr_soup_free(&s);
  return st;
}
