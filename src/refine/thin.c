/* Tets under a dihedral angle that stand on thin input triangles (quality.h,
 * tr_quality_thin_input).
 *
 * tetrec keeps every input triangle: each boundary face of the output lies in one. A
 * triangle with a corner of a few degrees is a wedge along its whole length (its width at
 * distance d from that corner is about d times the angle), so every boundary face inside
 * it has a small angle too, and a tet standing on such a face, or on one of its edges,
 * has a small dihedral angle unless the wedge is refined towards the corner without end;
 * refinement leaves those tets (refine.c, forced_by_angle). On the CGAL models that miss
 * issue 17's per-model targets most tets left under 10 degrees stand so: rotor.off 268 of
 * the 272 boundary faces under such tets lie in input triangles with a corner under 15
 * degrees, 155 of their 157 triangles with no exactly coplanar neighbour to merge with
 * (the long thin triangles of a CAD surface's cylinders, split across nearly planar
 * quads). Saying so tells the user what in the input to change. Angles are measured in
 * doubles: a report, not a decision. */
#include <math.h>
#include <stdlib.h>

#include "core/facets.h"
#include "core/vtmap.h"
#include "refine/quality.h"
#include "refine/refine_impl.h" /* rf_cos_angle */

/* A cosine under this has an angle surely not under `corner` degrees, so its arccosine
 * is not taken (most triangles' smallest corner is far above it). The guard of 1e-6
 * degrees is many orders of magnitude above the error of cos, acos and the product in
 * degrees; at corners near 0 or 180 the slope of the cosine vanishes and the test is
 * left to the arccosine. -2: take every one. */
static double corner_cos_skip(double corner)
{
  if (!(corner > 1e-3 && corner < 179))
    return -2;
  return cos((corner + 1e-6) * (3.14159265358979323846 / 180));
}

/* 1 iff the smallest corner of input triangle t is under `corner` degrees; then *lo = it
 * (the arccosine of the largest cosine, as the angle measure of angles.c) and *at = its
 * vertex. skip: corner_cos_skip(corner). */
static int thin_corner(const struct tr_plc *plc, uint32_t t, double corner, double skip,
                       double *lo, uint32_t *at)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  double c[3], hi = -1; /* the largest cosine: the smallest corner */
  rf_tri_cos_angles(plc->xyz + 3 * (size_t)T[0], plc->xyz + 3 * (size_t)T[1],
                    plc->xyz + 3 * (size_t)T[2], c);
  *at = T[0];
  for (int k = 0; k < 3; k++)
    if (c[k] > hi) {
      hi = c[k];
      *at = T[k];
    }
  if (hi < skip)
    return 0;
  *lo = acos(fmin(hi, 1)) * (180 / 3.14159265358979323846);
  return *lo < corner;
}

static void thin_begin(tr_quality_thin *out)
{
  out->triangles = 0;
  out->below_on_thin = 0;
  out->thinnest = out->thinnest_vertex = TR_NONE;
  out->thinnest_angle = 180;
}

static void thin_count(tr_quality_thin *out, uint32_t t, double lo, uint32_t at)
{
  out->triangles++;
  if (lo < out->thinnest_angle) {
    out->thinnest_angle = lo;
    out->thinnest = t;
    out->thinnest_vertex = at;
  }
}

void tr_facets_thin_triangles(const struct tr_plc *plc, const tr_facets *fc, double corner,
                              uint8_t *thin, tr_quality_thin *out)
{
  thin_begin(out);
  double skip = corner_cos_skip(corner);
  for (uint32_t t = 0; t < plc->ntris; t++) {
    if (thin)
      thin[t] = 0;
    /* a triangle merged into a planar facet is no constraint: its corners bound nothing */
    if (tr_facets_size(fc, fc->group[t]) != 1)
      continue;
    uint32_t at;
    double lo;
    if (!thin_corner(plc, t, corner, skip, &lo, &at))
      continue;
    if (thin)
      thin[t] = 1;
    thin_count(out, t, lo, at);
  }
}

tr_status tr_plc_thin_triangles(const struct tr_plc *plc, int keep_edges, double corner,
                                uint8_t *thin, tr_quality_thin *out)
{
  /* The corners first, the facets only if a triangle has a thin one: most surfaces have
   * none, and the facets (a sort of every edge and an orient3d per coplanar candidate)
   * cost as much as the corners. The same triangles, in the same order, as
   * tr_facets_thin_triangles on built facets. */
  thin_begin(out);
  double skip = corner_cos_skip(corner);
  uint32_t *cand = NULL, ncand = 0;
  for (uint32_t t = 0; t < plc->ntris; t++) {
    if (thin)
      thin[t] = 0;
    uint32_t at;
    double lo;
    if (!thin_corner(plc, t, corner, skip, &lo, &at))
      continue;
    if (!cand && !(cand = malloc(sizeof *cand * (plc->ntris - (size_t)t))))
      return tr_error(TR_ERR_NOMEM, "out of memory for %u thin triangles", plc->ntris - t);
    cand[ncand++] = t;
  }
  if (!ncand)
    return TR_OK;
  tr_facets fc = {0};
  tr_status st = tr_facets_build(plc, keep_edges, &fc);
  for (uint32_t i = 0; st == TR_OK && i < ncand; i++) {
    uint32_t t = cand[i], at;
    double lo;
    if (tr_facets_size(&fc, fc.group[t]) != 1)
      continue;
    thin_corner(plc, t, corner, skip, &lo, &at); /* the same answer again */
    if (thin)
      thin[t] = 1;
    thin_count(out, t, lo, at);
  }
  tr_facets_free(&fc);
  free(cand);
  return st;
}

tr_status tr_quality_thin_input(const struct tr_mesh *m, const struct tr_plc *plc,
                                int keep_edges, double corner, double degrees,
                                tr_quality_thin *out)
{
  const struct tr_mesh_attrs *a = m->attrs;
  uint8_t *thin = malloc(plc->ntris ? plc->ntris : 1);
  if (!thin)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u triangle flags", plc->ntris);
  tr_status st0 = tr_plc_thin_triangles(plc, keep_edges, corner, thin, out);
  if (st0 != TR_OK || !a || !a->nfaces) {
    free(thin);
    return st0;
  }
  /* the edges of the boundary faces that lie in a thin triangle */
  tr_vtmap edges = {0};
  tr_status st = TR_OK;
  if (out->triangles) {
    st = tr_vtmap_reserve(&edges, 2, 3 * a->nfaces / 4 + 1);
    if (st == TR_OK) /* probed for the six edges of every tet: mostly absent */
      st = tr_vtmap_filter(&edges);
  }
  for (uint32_t f = 0; st == TR_OK && out->triangles && f < a->nfaces; f++) {
    if (a->face_tri[f] >= plc->ntris || !thin[a->face_tri[f]])
      continue;
    const uint32_t *v = a->faces + 3 * (size_t)f;
    for (int e = 0; e < 3 && st == TR_OK; e++) {
      uint32_t k[2];
      tr_vtkey_edge(v[e], v[(e + 1) % 3], k);
      st = tr_vtmap_set(&edges, 2, k, f);
    }
  }
  free(thin);
  /* the few tets on such an edge take their angle; the count of all tets under `degrees`
   * is tr_quality_measure's */
  for (uint32_t t = 0; st == TR_OK && out->triangles && t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    int on = 0;
    for (int e = 0; e < 6 && !on; e++) {
      uint32_t k[2];
      tr_vtkey_edge(v[tr_edge_vtx[e][0]], v[tr_edge_vtx[e][1]], k);
      on = tr_vtmap_get(&edges, 2, k) != TR_VTMAP_NONE;
    }
    double ratio, vol;
    out->below_on_thin +=
        on && tr_tet_min_dihedral(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                                  m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &ratio,
                                  &vol) < degrees;
  }
  tr_vtmap_free(&edges);
  return st;
}
