/* `tetrec check-surface IN [-o FILE]`: every defect of a surface at once, where
 * tr_plc_validate stops at the first. Exact duplicate vertices are merged first (as the
 * validator does), so that coincident copies are not read as open edges or intersections;
 * then the list: triangles of zero area (exact, they are left out of the other tests),
 * duplicate triangles (the same three vertices; only the first copy goes on),
 * open edges (one triangle) and non-manifold edges (three or more: valid for `tetrec mesh`
 * as internal facets between regions, listed because they are often a modelling slip),
 * every self-intersecting pair (selfint.c, collect-all variant), every non-planar input
 * polygon (polytri.c). Numbers are those of IN: triangles after polygon triangulation, the
 * input face each came from, vertices 0-based. A surface without defects gets a note when
 * triangles of it have a corner under 10 degrees: valid, but the tets refinement puts on
 * them stay thin (src/refine/thin.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/edgesort.h"
#include "core/plc.h"
#include "input/validate.h"
#include "io/io.h"
#include "predicates.h"
#include "refine/quality.h"

enum { ISSUE_SELFINT = 1, ISSUE_OPEN = 2, ISSUE_NONMANIFOLD = 3, ISSUE_NONPLANAR = 4,
       ISSUE_ZERO_AREA = 5, ISSUE_DUPLICATE = 6 };

static int cmp_xyz(const void *ctx, uint32_t a, uint32_t b)
{
  const double *x = ctx, *p = x + 3 * (size_t)a, *q = x + 3 * (size_t)b;
  for (int k = 0; k < 3; k++)
    if (p[k] != q[k])
      return p[k] < q[k] ? -1 : 1;
  return 0;
}

/* Triangles by their sorted vertex triple (ids after merging). */
static int cmp_tri(const void *ctx, uint32_t a, uint32_t b)
{
  const uint32_t *k = ctx;
  for (int i = 0; i < 3; i++)
    if (k[3 * (size_t)a + i] != k[3 * (size_t)b + i])
      return k[3 * (size_t)a + i] < k[3 * (size_t)b + i] ? -1 : 1;
  return 0;
}

static int zero_area(const double *x, const uint32_t *t)
{
  const double *a = x + 3 * (size_t)t[0], *b = x + 3 * (size_t)t[1], *c = x + 3 * (size_t)t[2];
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj(a, b, c, k) != 0)
      return 0;
  return 1;
}

struct list {
  uint32_t *a;
  int32_t *mark;
  uint32_t n, cap, per;
};

static tr_status add(struct list *l, const uint32_t *v, int32_t mark)
{
  if (l->n == l->cap) {
    uint32_t nc = l->cap ? 2 * l->cap : 64;
    uint32_t *na = realloc(l->a, sizeof *na * l->per * nc);
    if (na)
      l->a = na;
    int32_t *nm = na ? realloc(l->mark, sizeof *nm * nc) : NULL;
    if (!na || !nm)
      return tr_error(TR_ERR_NOMEM, "out of memory listing surface defects");
    l->mark = nm;
    l->cap = nc;
  }
  memcpy(l->a + l->per * (size_t)l->n, v, sizeof *v * l->per);
  l->mark[l->n++] = mark;
  return TR_OK;
}

struct counts {
  size_t selfint;
  uint32_t open, nonmanifold, nonplanar, zero, duplicate;
};

static tr_status analyse(const struct tr_plc *plc, struct list *tris, struct list *edges,
                         struct counts *c)
{
  uint32_t nv = plc->npoints, nt = plc->ntris;
  const uint32_t *src = plc->tri_source;
  uint32_t *ord = malloc(sizeof *ord * (nv ? nv : 1)), *rep = malloc(sizeof *rep * (nv ? nv : 1));
  uint32_t *keep = malloc(sizeof *keep * (nt ? nt : 1));
  struct tr_plc w;
  memset(&w, 0, sizeof w);
  w.tris = malloc(sizeof *w.tris * 3 * (size_t)(nt ? nt : 1));
  uint32_t *slots = malloc(sizeof *slots * 3 * (size_t)(nt ? nt : 1)), *pairs = NULL;
  tr_nonplanar *np = NULL;
  tr_status st = ord && rep && keep && w.tris && slots ? TR_OK
                                                       : tr_error(TR_ERR_NOMEM, "out of memory");
  /* exact duplicates -> the first of their copies in coordinate order, smallest index */
  for (uint32_t i = 0; st == TR_OK && i < nv; i++)
    ord[i] = i;
  if (st == TR_OK)
    st = tr_sort_ids(ord, nv, cmp_xyz, plc->xyz);
  for (uint32_t i = 0; st == TR_OK && i < nv; i++)
    rep[ord[i]] = i && cmp_xyz(plc->xyz, ord[i - 1], ord[i]) == 0 ? rep[ord[i - 1]] : ord[i];
  w.npoints = nv;
  w.xyz = plc->xyz;
  for (uint32_t t = 0; st == TR_OK && t < nt; t++) {
    uint32_t v[3];
    for (int k = 0; k < 3; k++)
      v[k] = rep[plc->tris[3 * (size_t)t + k]];
    if (zero_area(plc->xyz, v)) {
      printf("zero-area triangle %u (input face %u): vertices %u %u %u\n", t, src ? src[t] : t,
             plc->tris[3 * (size_t)t], plc->tris[3 * (size_t)t + 1], plc->tris[3 * (size_t)t + 2]);
      st = add(tris, plc->tris + 3 * (size_t)t, ISSUE_ZERO_AREA);
      c->zero++;
      continue;
    }
    memcpy(w.tris + 3 * (size_t)w.ntris, v, sizeof v);
    keep[w.ntris++] = t;
  }
  /* duplicates (the same three vertices, either orientation): listed, and only the first
   * copy goes on, so that a repeated triangle is not also read as non-manifold edges */
  uint32_t *key = st == TR_OK ? malloc(sizeof *key * 3 * (size_t)(w.ntris ? w.ntris : 1)) : NULL;
  uint32_t *tord = st == TR_OK ? malloc(sizeof *tord * (w.ntris ? w.ntris : 1)) : NULL;
  if (st == TR_OK && (!key || !tord))
    st = tr_error(TR_ERR_NOMEM, "out of memory");
  for (uint32_t t = 0; st == TR_OK && t < w.ntris; t++) {
    uint32_t *k = key + 3 * (size_t)t;
    memcpy(k, w.tris + 3 * (size_t)t, 3 * sizeof *k);
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2 - i; j++)
        if (k[j] > k[j + 1]) {
          uint32_t x = k[j];
          k[j] = k[j + 1];
          k[j + 1] = x;
        }
    tord[t] = t;
  }
  if (st == TR_OK)
    st = tr_sort_ids(tord, w.ntris, cmp_tri, key);
  if (st == TR_OK) {
    char *dup = calloc(w.ntris ? w.ntris : 1, 1);
    if (!dup)
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    for (uint32_t i = 1; st == TR_OK && i < w.ntris; i++)
      if (cmp_tri(key, tord[i - 1], tord[i]) == 0)
        dup[tord[i]] = 1; /* the stable sort keeps the first copy first */
    uint32_t n = 0;
    for (uint32_t i = 0, j = 1; st == TR_OK && i < w.ntris; i = j) {
      for (j = i + 1; j < w.ntris && cmp_tri(key, tord[i], tord[j]) == 0; j++) {
        printf("duplicate triangle %u (input face %u): the vertices of triangle %u\n",
               keep[tord[j]], src ? src[keep[tord[j]]] : keep[tord[j]], keep[tord[i]]);
        st = add(tris, plc->tris + 3 * (size_t)keep[tord[j]], ISSUE_DUPLICATE);
        c->duplicate++;
      }
    }
    for (uint32_t t = 0; st == TR_OK && t < w.ntris; t++)
      if (!dup[t]) {
        memmove(w.tris + 3 * (size_t)n, w.tris + 3 * (size_t)t, 3 * sizeof *w.tris);
        keep[n++] = keep[t];
      }
    if (st == TR_OK)
      w.ntris = n;
    free(dup);
  }
  free(key);
  free(tord);
  /* edge census on the merged triangles */
  if (st == TR_OK)
    st = tr_edge_slots_sorted(w.tris, w.ntris, nv, slots);
  for (uint32_t i = 0, j; st == TR_OK && i < 3 * w.ntris; i = j) {
    uint32_t s = slots[i], a = w.tris[s], b = w.tris[s / 3 * 3 + (s % 3 + 1) % 3];
    for (j = i + 1; j < 3 * w.ntris; j++) {
      uint32_t s2 = slots[j], a2 = w.tris[s2], b2 = w.tris[s2 / 3 * 3 + (s2 % 3 + 1) % 3];
      if ((a2 < b2 ? a2 : b2) != (a < b ? a : b) || (a2 < b2 ? b2 : a2) != (a < b ? b : a))
        break;
    }
    if (j - i == 2)
      continue;
    uint32_t e[2] = {a < b ? a : b, a < b ? b : a};
    if (j - i == 1) {
      printf("open edge: vertices %u %u (triangle %u only)\n", e[0], e[1], keep[s / 3]);
      c->open++;
    } else {
      printf("non-manifold edge: vertices %u %u, %u triangles:", e[0], e[1], j - i);
      for (uint32_t k = i; k < j; k++)
        printf(" %u", keep[slots[k] / 3]);
      printf("\n");
      c->nonmanifold++;
    }
    st = add(edges, e, j - i == 1 ? ISSUE_OPEN : ISSUE_NONMANIFOLD);
  }
  size_t npairs = 0;
  if (st == TR_OK)
    st = tr_input_self_intersection_pairs(&w, TR_SELFINT_AUTO, &pairs, &npairs);
  for (size_t i = 0; st == TR_OK && i < npairs; i++) {
    uint32_t x = keep[pairs[2 * i]], y = keep[pairs[2 * i + 1]];
    printf("self-intersection: triangles %u and %u (input faces %u and %u)\n", x, y,
           src ? src[x] : x, src ? src[y] : y);
    st = add(tris, plc->tris + 3 * (size_t)x, ISSUE_SELFINT);
    if (st == TR_OK)
      st = add(tris, plc->tris + 3 * (size_t)y, ISSUE_SELFINT);
  }
  c->selfint = npairs;
  uint32_t nnp = 0;
  if (st == TR_OK)
    st = tr_plc_nonplanar(plc, &np, &nnp);
  for (uint32_t i = 0; st == TR_OK && i < nnp; i++) {
    printf("non-planar polygon: input face %u (triangles %u..%u): a vertex lies %.17g from "
           "the plane of its largest triangle (%.3g of its bounding box diagonal)\n",
           np[i].facet, np[i].first_tri, np[i].first_tri + np[i].ntris - 1, np[i].deviation,
           np[i].relative);
    for (uint32_t t = np[i].first_tri; st == TR_OK && t < np[i].first_tri + np[i].ntris; t++)
      st = add(tris, plc->tris + 3 * (size_t)t, ISSUE_NONPLANAR);
  }
  c->nonplanar = nnp;
  free(ord);
  free(rep);
  free(keep);
  free(w.tris);
  free(slots);
  free(pairs);
  free(np);
  return st;
}

tr_status tr_cli_check_surface(const char *in, const char *out, int msh_version, int quiet)
{
  if (out) {
    enum tr_out_format f = tr_io_out_format(out);
    if (f != TR_OUT_VTK && f != TR_OUT_MSH)
      return tr_error(TR_ERR_USAGE, "%s: check-surface writes .vtk or .msh files", out);
    TR_CHECK(tr_io_check_writable(out));
  }
  tr_plc *plc = NULL;
  TR_CHECK(tr_plc_read(in, &plc));
  struct list tris = {NULL, NULL, 0, 0, 3}, edges = {NULL, NULL, 0, 0, 2};
  struct counts c = {0, 0, 0, 0, 0, 0};
  tr_status st = analyse(plc, &tris, &edges, &c);
  if (st == TR_OK && out) {
    struct tr_mesh_view v = {plc->npoints, plc->xyz, NULL, 0, NULL, NULL, tris.n, tris.a,
                             tris.mark, 1};
    struct tr_edge_view e = {edges.n, edges.a, edges.mark};
    st = tr_io_out_format(out) == TR_OUT_VTK ? tr_write_vtk_edges(&v, &e, out)
                                             : tr_write_msh_edges(&v, &e, out, msh_version);
  }
  if (st == TR_OK) {
    int any = c.selfint || c.open || c.nonmanifold || c.nonplanar || c.zero || c.duplicate;
    if (!quiet && !any)
      fprintf(stderr, "tetrec: %s: %u vertices, %u triangles: no defect found\n", in,
              plc->npoints, plc->ntris);
    /* not a defect, but what refinement cannot mend (src/refine/thin.c): said once */
    tr_quality_thin thin;
    if (!quiet && !any && (st = tr_plc_thin_triangles(plc, 0, 10, NULL, &thin)) == TR_OK &&
        thin.triangles)
      fprintf(stderr, "tetrec: note: %llu triangles have a corner under 10 degrees (the "
              "thinnest, triangle %u of input face %u, has %.3g degrees at vertex %u): valid, "
              "but tetrec keeps every input triangle, so under --quality the tets on them "
              "stay thin (--stats: tets_dihedral_below_10_on_thin_input)\n",
              (unsigned long long)thin.triangles, thin.thinnest,
              plc->tri_source ? plc->tri_source[thin.thinnest] : thin.thinnest,
              thin.thinnest_angle, thin.thinnest_vertex);
    if (any)
      st = tr_error(c.selfint ? TR_ERR_SELF_INTERSECT
                    : c.open || c.nonmanifold ? TR_ERR_OPEN : TR_ERR_INPUT,
                    "%s: %zu self-intersecting pairs, %u open edges, %u non-manifold edges, "
                    "%u non-planar polygons, %u zero-area triangles, %u duplicate triangles",
                    in, c.selfint, c.open, c.nonmanifold, c.nonplanar, c.zero, c.duplicate);
  }
  free(tris.a);
  free(tris.mark);
  free(edges.a);
  free(edges.mark);
  tr_plc_destroy(plc);
  return st;
}
