/* The public accessors of an output mesh (include/tetrec.h). They only read: the arrays
 * were built when the mesh was made (compact.c, tr_delaunay), so concurrent calls on one
 * mesh are safe. */
#include <stdio.h> /* before gmp.h */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "pipeline.h"

const double *tr_mesh_points(const tr_mesh *m) { return m ? m->xyz : NULL; }

const uint32_t *tr_mesh_tets(const tr_mesh *m)
{
  if (!m)
    return NULL;
  /* a compact store (tr_mesh_plc's) has neither ghost nor free slots */
  return m->attrs && m->attrs->tets ? m->attrs->tets : m->tv;
}

const int32_t *tr_mesh_tet_regions(const tr_mesh *m)
{
  /* region ids are small non-negative numbers stored as uint32_t; the signed view of
   * the same array is what the writers print */
  return m && m->region && !(m->attrs && m->attrs->tets) ? (const int32_t *)m->region : NULL;
}

uint32_t tr_mesh_num_boundary_faces(const tr_mesh *m)
{
  return m && m->attrs ? m->attrs->nfaces : 0;
}

const uint32_t *tr_mesh_boundary_faces(const tr_mesh *m)
{
  return m && m->attrs && m->attrs->nfaces ? m->attrs->faces : NULL;
}

const int32_t *tr_mesh_boundary_markers(const tr_mesh *m)
{
  return m && m->attrs && m->attrs->nfaces ? m->attrs->face_marker : NULL;
}

const uint32_t *tr_mesh_boundary_triangles(const tr_mesh *m)
{
  return m && m->attrs && m->attrs->nfaces ? m->attrs->face_tri : NULL;
}

tr_status tr_mesh_point_exact(const tr_mesh *m, uint32_t v, char **xyz_text)
{
  tr_error_clear();
  if (!m || !xyz_text)
    return tr_error(TR_ERR_USAGE, "tr_mesh_point_exact: NULL argument");
  *xyz_text = NULL;
  if (v >= m->nv)
    return tr_error(TR_ERR_USAGE, "tr_mesh_point_exact: vertex %u out of range (%u vertices)",
                    v, m->nv);
  char *c[3] = {NULL, NULL, NULL};
  mpq_t d;
  mpq_init(d);
  for (int k = 0; k < 3; k++) {
    const mpq_t *q;
    if (m->vq && m->vq[v])
      q = &m->vq[v]->c[k];
    else {
      mpq_set_d(d, m->xyz[3 * (size_t)v + (size_t)k]); /* exact: a double is a dyadic */
      q = &d;
    }
    /* mpq_get_str allocates with GMP's allocator (malloc by default); copied below so
     * the caller frees with tr_free whatever allocator GMP was given */
    c[k] = mpq_get_str(NULL, 10, *q);
  }
  mpq_clear(d);
  size_t n[3] = {strlen(c[0]), strlen(c[1]), strlen(c[2])};
  char *s = malloc(n[0] + n[1] + n[2] + 3);
  if (s) {
    memcpy(s, c[0], n[0]);
    s[n[0]] = ' ';
    memcpy(s + n[0] + 1, c[1], n[1]);
    s[n[0] + 1 + n[1]] = ' ';
    memcpy(s + n[0] + n[1] + 2, c[2], n[2] + 1);
  }
  void (*gfree)(void *, size_t);
  mp_get_memory_functions(NULL, NULL, &gfree);
  for (int k = 0; k < 3; k++)
    gfree(c[k], n[k] + 1);
  if (!s)
    return tr_error(TR_ERR_NOMEM, "out of memory for the exact point %u", v);
  *xyz_text = s;
  return TR_OK;
}

tr_status tr_mesh_vertex_origin(const tr_mesh *m, uint32_t v, int *kind, uint32_t *index)
{
  tr_error_clear();
  if (!m || !kind || !index)
    return tr_error(TR_ERR_USAGE, "tr_mesh_vertex_origin: NULL argument");
  if (v >= m->nv)
    return tr_error(TR_ERR_USAGE, "tr_mesh_vertex_origin: vertex %u out of range (%u vertices)",
                    v, m->nv);
  if (m->attrs && m->attrs->vkind) {
    *kind = m->attrs->vkind[v];
    *index = m->attrs->vindex[v];
  } else {
    /* no Steiner points: tr_delaunay's meshes, and tr_mesh_plc without recovery stages */
    *kind = TR_VERTEX_INPUT;
    *index = v;
  }
  return TR_OK;
}

uint32_t tr_mesh_num_input_edges(const tr_mesh *m)
{
  return m && m->attrs ? m->attrs->nedges : 0;
}

tr_status tr_mesh_input_edge(const tr_mesh *m, uint32_t k, uint32_t *a, uint32_t *b)
{
  tr_error_clear();
  if (!m || !a || !b)
    return tr_error(TR_ERR_USAGE, "tr_mesh_input_edge: NULL argument");
  if (!m->attrs || k >= m->attrs->nedges)
    return tr_error(TR_ERR_USAGE, "tr_mesh_input_edge: edge %u out of range (%u edges)", k,
                    tr_mesh_num_input_edges(m));
  *a = m->attrs->edges[2 * (size_t)k];
  *b = m->attrs->edges[2 * (size_t)k + 1];
  return TR_OK;
}
