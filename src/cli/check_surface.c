/* `tetrec check-surface IN [-o FILE]`: every defect of a surface at once, where
 * tr_plc_validate stops at the first: those of src/input/defects.c (exact duplicate
 * vertices merged first, then triangles of zero area, duplicate triangles, open edges and
 * non-manifold edges, the latter valid for `tetrec mesh` as internal facets between
 * regions but listed because they are often a modelling slip, every self-intersecting
 * pair), then every input polygon that cannot be triangulated in its plane (listed with
 * the fan --resolve reads instead), then every non-planar one (polytri.c). Numbers are those of IN:
 * triangles after polygon triangulation, the input face each came from, vertices
 * 0-based. A surface without defects gets a note when triangles of it have a corner
 * under 10 degrees: valid, but the tets refinement puts on them stay thin
 * (src/refine/thin.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/plc.h"
#include "input/defects.h"
#include "io/io.h"
#include "refine/quality.h"

enum { ISSUE_SELFINT = 1, ISSUE_OPEN = 2, ISSUE_NONMANIFOLD = 3, ISSUE_NONPLANAR = 4,
       ISSUE_ZERO_AREA = 5, ISSUE_DUPLICATE = 6, ISSUE_POLYGON = 7 };

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
  uint32_t open, nonmanifold, nonplanar, zero, duplicate, polygons;
};

/* The defects (src/input/defects.c) printed and listed for the output file, in the order
 * found; then the non-planar polygons, a matter of the file's polygons, not of the
 * triangles. */
static tr_status analyse(const struct tr_plc *plc, struct list *tris, struct list *edges,
                         struct counts *c)
{
  const uint32_t *src = plc->tri_source;
  tr_surface_defects d;
  tr_nonplanar *np = NULL;
  tr_status st = tr_surface_defects_find(plc, &d);
  for (uint32_t i = 0; st == TR_OK && i < d.nzero; i++) {
    uint32_t t = d.zero[i];
    printf("zero-area triangle %u (input face %u): vertices %u %u %u\n", t, src ? src[t] : t,
           plc->tris[3 * (size_t)t], plc->tris[3 * (size_t)t + 1], plc->tris[3 * (size_t)t + 2]);
    st = add(tris, plc->tris + 3 * (size_t)t, ISSUE_ZERO_AREA);
  }
  for (uint32_t i = 0; st == TR_OK && i < d.ndup; i++) {
    uint32_t t = d.dup[2 * (size_t)i], first = d.dup[2 * (size_t)i + 1];
    printf("duplicate triangle %u (input face %u): the vertices of triangle %u\n", t,
           src ? src[t] : t, first);
    st = add(tris, plc->tris + 3 * (size_t)t, ISSUE_DUPLICATE);
  }
  for (uint32_t k = 0; st == TR_OK && k < d.nedges; k++) {
    const uint32_t *e = d.edge + 2 * (size_t)k;
    uint32_t i = d.edge_start[k], j = d.edge_start[k + 1];
    if (j - i == 1) {
      printf("open edge: vertices %u %u (triangle %u only)\n", e[0], e[1], d.edge_tri[i]);
    } else {
      printf("non-manifold edge: vertices %u %u, %u triangles:", e[0], e[1], j - i);
      for (uint32_t x = i; x < j; x++)
        printf(" %u", d.edge_tri[x]);
      printf("\n");
    }
    st = add(edges, e, j - i == 1 ? ISSUE_OPEN : ISSUE_NONMANIFOLD);
  }
  for (size_t i = 0; st == TR_OK && i < d.npairs; i++) {
    uint32_t x = d.pairs[2 * i], y = d.pairs[2 * i + 1];
    printf("self-intersection: triangles %u and %u (input faces %u and %u)\n", x, y,
           src ? src[x] : x, src ? src[y] : y);
    st = add(tris, plc->tris + 3 * (size_t)x, ISSUE_SELFINT);
    if (st == TR_OK)
      st = add(tris, plc->tris + 3 * (size_t)y, ISSUE_SELFINT);
  }
  c->zero = d.nzero;
  c->duplicate = d.ndup;
  c->open = d.nopen;
  c->nonmanifold = d.nnonmanifold;
  c->selfint = d.npairs;
  tr_surface_defects_free(&d);
  /* polygons that cannot be triangulated in their plane, read as fans (tr_plc.read_fans):
   * their triangles are contiguous, in facet order */
  const char *why = plc->fan_notes ? plc->fan_notes : "";
  for (uint32_t f = 0, t = 0; st == TR_OK && src && f < plc->nfans; f++) {
    uint32_t face = plc->fan_facet[f];
    while (t < plc->ntris && src[t] < face)
      t++;
    uint32_t t1 = t;
    while (t1 < plc->ntris && src[t1] == face)
      st = add(tris, plc->tris + 3 * (size_t)t1++, ISSUE_POLYGON);
    const char *nl = strchr(why, '\n');
    int len = *why ? (nl ? (int)(nl - why) : (int)strlen(why)) : 0;
    printf("polygon that cannot be triangulated in its plane: input face %u (triangles %u..%u, "
           "its fan as --resolve reads it)%s%.*s\n", face, t, t1 - 1, len ? ": " : "", len, why);
    why += len + (nl && len ? 1 : 0);
    t = t1;
  }
  c->polygons = plc->nfans;
  uint32_t nnp = 0;
  if (st == TR_OK)
    st = tr_plc_nonplanar(plc, &np, &nnp);
  uint32_t kept = 0; /* a fanned polygon is listed above, not again as non-planar */
  for (uint32_t i = 0, f = 0; st == TR_OK && i < nnp; i++) {
    while (f < plc->nfans && plc->fan_facet[f] < np[i].facet)
      f++;
    if (f == plc->nfans || plc->fan_facet[f] != np[i].facet)
      np[kept++] = np[i];
  }
  nnp = kept;
  for (uint32_t i = 0; st == TR_OK && i < nnp; i++) {
    printf("non-planar polygon: input face %u (triangles %u..%u): a vertex lies %.17g from "
           "the plane of its largest triangle (%.3g of its bounding box diagonal)\n",
           np[i].facet, np[i].first_tri, np[i].first_tri + np[i].ntris - 1, np[i].deviation,
           np[i].relative);
    for (uint32_t t = np[i].first_tri; st == TR_OK && t < np[i].first_tri + np[i].ntris; t++)
      st = add(tris, plc->tris + 3 * (size_t)t, ISSUE_NONPLANAR);
  }
  c->nonplanar = nnp;
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
  TR_CHECK(tr_plc_read_fans(in, &plc, 1, 1)); /* every such polygon listed, not the first */
  struct list tris = {NULL, NULL, 0, 0, 3}, edges = {NULL, NULL, 0, 0, 2};
  struct counts c = {0, 0, 0, 0, 0, 0, 0};
  tr_status st = analyse(plc, &tris, &edges, &c);
  if (st == TR_OK && out) {
    struct tr_mesh_view v = {plc->npoints, plc->xyz, NULL, 0, NULL, NULL, tris.n, tris.a,
                             tris.mark, 1};
    struct tr_edge_view e = {edges.n, edges.a, edges.mark};
    st = tr_io_out_format(out) == TR_OUT_VTK ? tr_write_vtk_edges(&v, &e, out)
                                             : tr_write_msh_edges(&v, &e, out, msh_version);
  }
  if (st == TR_OK) {
    int any = c.selfint || c.open || c.nonmanifold || c.nonplanar || c.zero || c.duplicate ||
              c.polygons;
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
    char polygons[96];
    snprintf(polygons, sizeof polygons, ", %u polygons that cannot be triangulated in their "
             "plane", c.polygons);
    if (any)
      st = tr_error(c.selfint ? TR_ERR_SELF_INTERSECT
                    : c.open || c.nonmanifold ? TR_ERR_OPEN : TR_ERR_INPUT,
                    "%s: %zu self-intersecting pairs, %u open edges, %u non-manifold edges, "
                    "%u non-planar polygons, %u zero-area triangles, %u duplicate triangles%s",
                    in, c.selfint, c.open, c.nonmanifold, c.nonplanar, c.zero, c.duplicate,
                    c.polygons ? polygons : "");
  }
  free(tris.a);
  free(tris.mark);
  free(edges.a);
  free(edges.mark);
  tr_plc_destroy(plc);
  return st;
}
