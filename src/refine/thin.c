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

/* The smallest corner of input triangle t, in degrees, and the corner's vertex (the
 * angle measure of angles.c). */
static double smallest_corner(const struct tr_plc *plc, uint32_t t, uint32_t *at)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  double hi = -1; /* the largest cosine: the smallest corner */
  *at = T[0];
  for (int k = 0; k < 3; k++) {
    double c = rf_cos_angle(plc->xyz + 3 * (size_t)T[k], plc->xyz + 3 * (size_t)T[(k + 1) % 3],
                            plc->xyz + 3 * (size_t)T[(k + 2) % 3]);
    if (c > hi) {
      hi = c;
      *at = T[k];
    }
  }
  return acos(fmin(hi, 1)) * (180 / 3.14159265358979323846);
}

void tr_facets_thin_triangles(const struct tr_plc *plc, const tr_facets *fc, double corner,
                              uint8_t *thin, tr_quality_thin *out)
{
  out->triangles = 0;
  out->below_on_thin = 0;
  out->thinnest = out->thinnest_vertex = TR_NONE;
  out->thinnest_angle = 180;
  for (uint32_t t = 0; t < plc->ntris; t++) {
    if (thin)
      thin[t] = 0;
    /* a triangle merged into a planar facet is no constraint: its corners bound nothing */
    if (tr_facets_size(fc, fc->group[t]) != 1)
      continue;
    uint32_t at;
    double lo = smallest_corner(plc, t, &at);
    if (!(lo < corner))
      continue;
    if (thin)
      thin[t] = 1;
    out->triangles++;
    if (lo < out->thinnest_angle) {
      out->thinnest_angle = lo;
      out->thinnest = t;
      out->thinnest_vertex = at;
    }
  }
}

tr_status tr_plc_thin_triangles(const struct tr_plc *plc, int keep_edges, double corner,
                                uint8_t *thin, tr_quality_thin *out)
{
  tr_facets fc = {0};
  if (plc->ntris)
    TR_CHECK(tr_facets_build(plc, keep_edges, &fc));
  tr_facets_thin_triangles(plc, &fc, corner, thin, out);
  tr_facets_free(&fc);
  return TR_OK;
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
