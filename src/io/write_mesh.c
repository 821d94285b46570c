/* Public writers: tr_mesh_write (from the mesh store) and tr_plc_write (a surface), both
 * through struct tr_mesh_view so that the format writers never see the store. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "mesh/mesh.h"
#include "output/round.h"

void tr_io_put_ints(FILE *f, const int64_t *x, int n)
{
  char line[24 * 8], *p = line;
  for (int i = 0; i < n && i < 8; i++) {
    char dig[24];
    int k = 0;
    uint64_t u = x[i] < 0 ? 0 - (uint64_t)x[i] : (uint64_t)x[i];
    do
      dig[k++] = (char)('0' + u % 10);
    while (u /= 10);
    if (i)
      *p++ = ' ';
    if (x[i] < 0)
      *p++ = '-';
    while (k)
      *p++ = dig[--k];
  }
  *p++ = '\n';
  fwrite(line, 1, (size_t)(p - line), f);
}

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
 * 0, as seen from its tet. */
static tr_status input_faces(const struct tr_mesh *m, uint32_t **tris, int32_t **mark,
                             uint32_t *nf)
{
  const struct tr_mesh_attrs *a = m->attrs;
  uint32_t n = a->nfaces, extra = 0;
  uint32_t *key = malloc(sizeof *key * 3 * (size_t)(n ? n : 1));
  if (!key)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u faces", n);
  memcpy(key, a->faces, sizeof *key * 3 * (size_t)n);
  for (uint32_t f = 0; f < n; f++)
    tr_sort3(key + 3 * (size_t)f);
  qsort(key, n, 3 * sizeof *key, tr_cmp_face_key);
  for (int pass = 0; pass < 2; pass++) {
    if (pass) {
      *tris = malloc(sizeof **tris * 3 * (size_t)(n + extra ? n + extra : 1));
      *mark = malloc(sizeof **mark * (n + extra ? n + extra : 1));
      if (!*tris || !*mark) {
        free(*tris);
        free(*mark);
        free(key);
        return tr_error(TR_ERR_NOMEM, "out of memory for %u faces", n + extra);
      }
      memcpy(*tris, a->faces, sizeof **tris * 3 * (size_t)n);
      memcpy(*mark, a->face_marker, sizeof **mark * n);
      extra = 0;
    }
    for (uint32_t t = 0; t < m->nt; t++) {
      if (!keep(m, t))
        continue;
      for (int k = 0; k < 4; k++) {
        uint32_t o = TR_NEIG(m, t, k);
        if (o != TR_NONE && keep(m, o))
          continue;
        /* tr_face_vtx order has the normal pointing into the tet: reverse it. */
        uint32_t w[3] = {m->tv[4 * (size_t)t + tr_face_vtx[k][0]],
                         m->tv[4 * (size_t)t + tr_face_vtx[k][2]],
                         m->tv[4 * (size_t)t + tr_face_vtx[k][1]]};
        uint32_t q[3] = {w[0], w[1], w[2]};
        tr_sort3(q);
        if (bsearch(q, key, n, 3 * sizeof *key, tr_cmp_face_key))
          continue;
        if (pass) {
          memcpy(*tris + 3 * (size_t)(n + extra), w, sizeof w);
          (*mark)[n + extra] = 0;
        }
        extra++;
      }
    }
  }
  free(key);
  *nf = n + extra;
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
  for (uint32_t t = 0; t < m->nt; t++)
    if (keep(m, t)) {
      nt++;
      for (int k = 0; k < 4 && !from_input; k++) {
        uint32_t o = TR_NEIG(m, t, k);
        if (o == TR_NONE || !keep(m, o) || (m->region && m->region[o] != m->region[t] && o > t))
          nf++;
      }
    }
  uint32_t *tets = malloc(sizeof *tets * 4 * (size_t)(nt ? nt : 1));
  int32_t *reg = m->region ? malloc(sizeof *reg * (nt ? nt : 1)) : NULL;
  uint32_t *tris = NULL;
  int32_t *mark = NULL;
  tr_status st = TR_OK;
  if (from_input)
    st = input_faces(m, &tris, &mark, &nf);
  else {
    tris = malloc(sizeof *tris * 3 * (size_t)(nf ? nf : 1));
    mark = calloc(nf ? nf : 1, sizeof *mark);
  }
  if (st != TR_OK || !tets || (m->region && !reg) || !tris || !mark) {
    free(tets);
    free(reg);
    free(tris);
    free(mark);
    return st != TR_OK ? st : tr_error(TR_ERR_NOMEM, "out of memory writing %s", path);
  }
  uint32_t i = 0, f = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!keep(m, t))
      continue;
    memcpy(tets + 4 * (size_t)i, m->tv + 4 * (size_t)t, 4 * sizeof *tets);
    if (reg)
      reg[i] = (int32_t)m->region[t];
    i++;
    for (int k = 0; k < 4 && !from_input; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o == TR_NONE || !keep(m, o) || (m->region && m->region[o] != m->region[t] && o > t)) {
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
  struct tr_mesh_view v = {plc->npoints, plc->xyz, NULL, plc->ntets, plc->tets, NULL,
                           plc->ntris, plc->tris, plc->tri_marker};
  return tr_write_mesh_view_as(&v, path, 0, msh_version);
}
