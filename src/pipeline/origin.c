/* Where each vertex of the working mesh comes from (tr_mesh_vertex_origin), read off the
 * recovery's own records instead of recomputed: the chains of the recovered edges list
 * every vertex lying on an input edge, and since the mesh conforms, a vertex inside an
 * input triangle is a vertex of one of that triangle's sub-faces (otherwise it would
 * lie inside a mesh face). What is on neither (the points H of the clusterels, strictly
 * inside a region) is interior. An input edge takes precedence over the triangles
 * around it. tests/api checks every label exactly against the geometry. */
#include <stdlib.h>

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
