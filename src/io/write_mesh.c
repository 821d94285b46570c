/* Public writers: tr_mesh_write (from the mesh store) and tr_plc_write (a surface), both
 * through struct tr_mesh_view so that the format writers never see the store. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format_name.h"
#include "write.h"
#include "core/plc.h"
#include "core/vtmap.h"
#include "mesh/mesh.h"
#include "output/round.h"

/* Faces written: those of include/tetrec.h's tr_mesh_boundary_faces with their markers
 * for a tr_mesh_plc mesh (input_faces); for other meshes (tr_delaunay's) the boundary
 * faces of the kept tets: a face is written when the tet across it is missing, a ghost,
 * or outside the domain, or belongs to another region, listed as seen from its tet
 * (right-hand normal pointing out of it), marker 1. */
static int keep(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags && (m->flags[t] & TR_TF_OUTER));
}

/* The faces a tr_mesh_plc mesh writes: the faces on input triangles with their markers
 * (m->attrs, include/tetrec.h's boundary faces), then any other face on the boundary of
 * the kept tets (the convex hull of an open input meshed with allow_open) with marker
 * 0, as seen from its tet. kept[t] = keep(m, t), read for the tet across each face: one
 * byte per tet stays in cache where the neighbour's own fields do not. */
static tr_status input_faces(const struct tr_mesh *m, const uint8_t *kept, uint32_t **tris,
                             int32_t **mark, uint32_t *nf)
{
  const struct tr_mesh_attrs *a = m->attrs;
  uint32_t n = a->nfaces;
  tr_vtmap key = {0}; /* the input faces, unoriented: a set */
  tr_u32buf extra = {0};
  tr_status st = tr_vtmap_reserve(&key, 3, n);
  if (st == TR_OK)
    st = tr_vtmap_filter(&key); /* most boundary faces are input faces, but not all */
  for (uint32_t f = 0; f < n && st == TR_OK; f++) {
    uint32_t q[3];
    tr_vtkey_face(a->faces[3 * (size_t)f], a->faces[3 * (size_t)f + 1],
                  a->faces[3 * (size_t)f + 2], q);
    st = tr_vtmap_put(&key, 3, q, 0, NULL);
  }
  for (uint32_t t = 0; t < m->nt && st == TR_OK; t++) {
    if (!kept[t])
      continue;
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o != TR_NONE && kept[o])
        continue;
      /* tr_face_vtx order has the normal pointing into the tet: reverse it. */
      uint32_t w[3] = {m->tv[4 * (size_t)t + tr_face_vtx[k][0]],
                       m->tv[4 * (size_t)t + tr_face_vtx[k][2]],
                       m->tv[4 * (size_t)t + tr_face_vtx[k][1]]};
      uint32_t q[3];
      tr_vtkey_face(w[0], w[1], w[2], q);
      if (tr_vtmap_get(&key, 3, q) != TR_VTMAP_NONE)
        continue;
      for (int i = 0; i < 3 && st == TR_OK; i++)
        st = tr_u32buf_push(&extra, w[i]);
    }
  }
  tr_vtmap_free(&key);
  uint32_t ne = (uint32_t)(extra.n / 3);
  *tris = NULL;
  *mark = NULL;
  if (st == TR_OK) {
    *tris = malloc(sizeof **tris * 3 * (size_t)(n + ne ? n + ne : 1));
    *mark = malloc(sizeof **mark * (n + ne ? n + ne : 1));
    if (!*tris || !*mark)
      st = tr_error(TR_ERR_NOMEM, "out of memory for %u faces", n + ne);
  }
  if (st != TR_OK) {
    free(*tris);
    free(*mark);
    *tris = NULL;
    *mark = NULL;
    tr_u32buf_free(&extra);
    return st;
  }
  memcpy(*tris, a->faces, sizeof **tris * 3 * (size_t)n);
  memcpy(*mark, a->face_marker, sizeof **mark * n);
  if (ne)
    memcpy(*tris + 3 * (size_t)n, extra.a, sizeof **tris * 3 * (size_t)ne);
  for (uint32_t f = 0; f < ne; f++)
    (*mark)[n + f] = 0;
  tr_u32buf_free(&extra);
  *nf = n + ne;
  return TR_OK;
}

tr_status tr_mesh_write(const tr_mesh *mesh, const char *path, int exact)
{
  return tr_mesh_write_ex(mesh, path, exact, 41);
}

tr_status tr_mesh_write_ex(const tr_mesh *mesh, const char *path, int exact, int msh_version)
{
  tr_error_clear();
  const struct tr_mesh *m = mesh;
  if (!m)
    return tr_error(TR_ERR_USAGE, "tr_mesh_write: no mesh");
  TR_CHECK(tr_io_check_out_name(path, 0));
  if (msh_version & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  /* A mesh that tr_mesh_plc returned under TR_PIPE_KEEP_EXACT may have tets that are flat
   * or inverted on the doubles: only its exact TetGen output is a valid mesh. */
  uint32_t bad;
  if (!(exact && tr_io_out_format(path) == TR_OUT_TETGEN) &&
      tr_round_count_nonpositive(m, &bad) > 0)
    return tr_error(TR_ERR_INVALID_MESH,
                    "%s: tet %u is flat or inverted once its Steiner points are written as "
                    "doubles; only the exact output (--exact, .node) is valid for this mesh",
                    path, bad);
  uint32_t nt = 0, nf = 0;
  int from_input = m->attrs && m->attrs->faces;
  uint8_t *kept = malloc(m->nt ? m->nt : 1);
  if (!kept)
    return tr_error(TR_ERR_NOMEM, "out of memory writing %s", path);
  for (uint32_t t = 0; t < m->nt; t++)
    nt += kept[t] = (uint8_t)keep(m, t);
  for (uint32_t t = 0; t < m->nt && !from_input; t++)
    for (int k = 0; k < 4 && kept[t]; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o == TR_NONE || !kept[o] || (m->region && m->region[o] != m->region[t] && o > t))
        nf++;
    }
  uint32_t *tets = malloc(sizeof *tets * 4 * (size_t)(nt ? nt : 1));
  int32_t *reg = m->region ? malloc(sizeof *reg * (nt ? nt : 1)) : NULL;
  uint32_t *tris = NULL;
  int32_t *mark = NULL;
  tr_status st = TR_OK;
  if (from_input)
    st = input_faces(m, kept, &tris, &mark, &nf);
  else {
    tris = malloc(sizeof *tris * 3 * (size_t)(nf ? nf : 1));
    mark = calloc(nf ? nf : 1, sizeof *mark);
  }
  if (st != TR_OK || !tets || (m->region && !reg) || !tris || !mark) {
    free(kept);
    free(tets);
    free(reg);
    free(tris);
    free(mark);
    return st != TR_OK ? st : tr_error(TR_ERR_NOMEM, "out of memory writing %s", path);
  }
  uint32_t i = 0, f = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!kept[t])
      continue;
    memcpy(tets + 4 * (size_t)i, m->tv + 4 * (size_t)t, 4 * sizeof *tets);
    if (reg)
      reg[i] = (int32_t)m->region[t];
    i++;
    for (int k = 0; k < 4 && !from_input; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o == TR_NONE || !kept[o] || (m->region && m->region[o] != m->region[t] && o > t)) {
        /* tr_face_vtx order has the normal pointing into the tet: reverse it. */
        tris[3 * (size_t)f] = m->tv[4 * (size_t)t + tr_face_vtx[k][0]];
        tris[3 * (size_t)f + 1] = m->tv[4 * (size_t)t + tr_face_vtx[k][2]];
        tris[3 * (size_t)f + 2] = m->tv[4 * (size_t)t + tr_face_vtx[k][1]];
        mark[f] = 1;
        f++;
      }
    }
  }
  struct tr_mesh_view v = {m->nv, m->xyz, (const tr_qpoint *const *)m->vq, nt, tets, reg,
                           nf, tris, mark};
  st = tr_write_mesh_view_as(&v, path, exact, msh_version);
  free(kept);
  free(tets);
  free(reg);
  free(tris);
  free(mark);
  return st;
}

tr_status tr_plc_write(const tr_plc *plc, const char *path)
{
  return tr_plc_write_ex(plc, path, 41);
}

tr_status tr_plc_write_ex(const tr_plc *plc, const char *path, int msh_version)
{
  tr_error_clear();
  TR_CHECK(tr_io_check_out_name(path, 1));
  if (msh_version & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  struct tr_mesh_view v = {plc->npoints, plc->xyz, NULL, plc->ntets, plc->tets, NULL,
                           plc->ntris, plc->tris, plc->tri_marker};
  return tr_write_mesh_view_as(&v, path, 0, msh_version);
}
