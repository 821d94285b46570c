/* Where each vertex of the working mesh comes from (tr_mesh_vertex_origin), read off the
 * recovery's own records instead of recomputed: the chains of the recovered edges list
 * every vertex lying on an input edge, and since the mesh conforms, a vertex inside an
 * input triangle is a vertex of one of that triangle's sub-faces (otherwise it would
 * lie inside a mesh face). What is on neither (the points H of the clusterels, strictly
 * inside a region) is interior. An input edge takes precedence over the triangles
 * around it. tests/api checks every label exactly against the geometry. */
#include <stdlib.h>
#include <string.h>

#include "core/facets.h"
#include "predicates.h"

#include "classify.h"
#include "pipeline.h"

tr_status tr_pipeline_origins(const struct tr_mesh *m, uint32_t npoints,
                              const tr_edge_chains *chains, const tr_subfaces *sub,
                              uint8_t **kind, uint32_t **index)
{
  uint32_t nv = m->nv;
  uint8_t *k = malloc(nv ? nv : 1);
  uint32_t *x = malloc(sizeof *x * (nv ? nv : 1));
  *kind = NULL;
  *index = NULL;
  if (!k || !x) {
    free(k);
    free(x);
    return tr_error(TR_ERR_NOMEM, "out of memory for the origins of %u vertices", nv);
  }
  for (uint32_t v = 0; v < nv; v++) {
    k[v] = v < npoints ? TR_VERTEX_INPUT : TR_VERTEX_INTERIOR;
    x[v] = v;
  }
  for (uint32_t e = 0; chains && e < chains->n; e++)
    for (uint32_t i = chains->start[e]; i < chains->start[e + 1]; i++) {
      uint32_t v = chains->v[i];
      if (v >= npoints && v < nv && k[v] == TR_VERTEX_INTERIOR) {
        k[v] = TR_VERTEX_ON_EDGE;
        x[v] = e;
      }
    }
  for (uint32_t f = 0; sub && f < sub->n; f++)
    for (int j = 0; j < 3; j++) {
      uint32_t v = sub->v[3 * (size_t)f + (size_t)j];
      if (v >= npoints && v < nv && k[v] == TR_VERTEX_INTERIOR) {
        k[v] = TR_VERTEX_ON_TRIANGLE;
        x[v] = sub->tri[f];
      }
    }
  *kind = k;
  *index = x;
  return TR_OK;
}

/* The index of {a,b} in the sorted unique edges (2 per edge, a < b), UINT32_MAX if
 * absent. */
static uint32_t edge_index(const uint32_t *edges, uint32_t ne, uint32_t a, uint32_t b)
{
  uint32_t key[2] = {a < b ? a : b, a < b ? b : a};
  const uint32_t *hit = bsearch(key, edges, ne, 2 * sizeof *edges, tr_cmp_edge_key);
  return hit ? (uint32_t)((hit - edges) / 2) : UINT32_MAX;
}

/* 1 iff p lies in the closed input triangle t (exact). */
static int in_triangle(const struct tr_plc *plc, uint32_t t, const tr_point *p)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  tr_point a = tr_plc_point(plc, T[0]), b = tr_plc_point(plc, T[1]),
           c = tr_plc_point(plc, T[2]);
  if (tr_orient3d_p(&a, &b, &c, p) != 0)
    return 0;
  for (int k = 0; k < 3; k++) {
    int s = tr_orient2d_proj_p(&a, &b, &c, k);
    if (s != 0)
      return s * tr_orient2d_proj_p(&a, &b, p, k) >= 0 &&
             s * tr_orient2d_proj_p(&b, &c, p, k) >= 0 &&
             s * tr_orient2d_proj_p(&c, &a, p, k) >= 0;
  }
  return 0;
}

tr_status tr_pipeline_origins_extend(const struct tr_mesh *m, const struct tr_plc *plc,
                                     const tr_subfaces *sub, const uint32_t *edges,
                                     uint32_t ne, uint32_t nv0, uint8_t **kind,
                                     uint32_t **index)
{
  uint32_t nv = m->nv;
  if (!*kind || nv <= nv0)
    return TR_OK;
  uint8_t *k = realloc(*kind, nv);
  if (k)
    *kind = k;
  uint32_t *x = realloc(*index, sizeof *x * nv);
  if (x)
    *index = x;
  if (!k || !x)
    return tr_error(TR_ERR_NOMEM, "out of memory for the origins of %u vertices", nv);
  for (uint32_t v = nv0; v < nv; v++) {
    k[v] = TR_VERTEX_INTERIOR;
    x[v] = v;
  }
  /* A new point on a sub-face lies in that sub-face's input triangle, or for a merged
   * planar facet (core/facets.h; the sub-face may straddle its inner edges) in the
   * facet's smallest triangle that holds it: on one of its edges (decided exactly) or
   * inside it. */
  tr_facets F;
  memset(&F, 0, sizeof F);
  if (sub && sub->n)
    TR_CHECK(tr_facets_build(plc, 0, &F));
  for (uint32_t f = 0; sub && f < sub->n; f++)
    for (int j = 0; j < 3; j++) {
      uint32_t v = sub->v[3 * (size_t)f + (size_t)j];
      if (v < nv0 || v >= nv || k[v] != TR_VERTEX_INTERIOR)
        continue;
      uint32_t t = sub->tri[f];
      tr_point p = tr_mesh_point(m, v);
      if (tr_facets_size(&F, F.group[t]) > 1 && !in_triangle(plc, t, &p)) {
        uint32_t g = F.group[t];
        for (uint32_t i = F.start[g]; i < F.start[g + 1]; i++)
          if (in_triangle(plc, F.member[i], &p)) {
            t = F.member[i];
            break;
          }
      }
      const uint32_t *T = plc->tris + 3 * (size_t)t;
      k[v] = TR_VERTEX_ON_TRIANGLE;
      x[v] = t;
      for (int e = 0; e < 3; e++) {
        tr_point a = tr_plc_point(plc, T[e]);
        tr_point b = tr_plc_point(plc, T[(e + 1) % 3]);
        uint32_t ei = edge_index(edges, ne, T[e], T[(e + 1) % 3]);
        if (ei != UINT32_MAX && tr_classify_point_segment(&p, &a, &b).type == TR_EDG) {
          k[v] = TR_VERTEX_ON_EDGE;
          x[v] = ei;
          break;
        }
      }
    }
  tr_facets_free(&F);
  return TR_OK;
}
