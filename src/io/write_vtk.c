/* Legacy VTK (.vtk), "DATASET UNSTRUCTURED_GRID", ASCII: what ParaView, VisIt and meshio
 * open without the XML reader. Cells are the tetrahedra (VTK type 10), or the triangles
 * (type 5) and edges (type 3) when there are none; cell data "region" holds each tet's
 * region (or each triangle's or edge's marker), as in the .vtu writer. Doubles in %.17g read back bitwise. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io.h"

tr_status tr_write_vtk(const struct tr_mesh_view *m, const char *path)
{
  return tr_write_vtk_edges(m, NULL, path);
}

tr_status tr_write_vtk_edges(const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                             const char *path)
{
  static const struct tr_edge_view none = {0, NULL, NULL};
  const struct tr_edge_view *e = ev ? ev : &none;
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  int tets = m->ntets > 0;
  /* without tets: the triangles, then the edges (VTK_LINE, 3) */
  uint32_t ne = tets ? 0 : e->nedges, nc = (tets ? m->ntets : m->ntris) + ne;
  fprintf(f, "# vtk DataFile Version 3.0\ntetrec mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS %u double\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++)
    fprintf(f, "%.17g %.17g %.17g\n", m->xyz[3 * (size_t)i], m->xyz[3 * (size_t)i + 1],
            m->xyz[3 * (size_t)i + 2]);
  uint64_t size = tets ? 5 * (uint64_t)m->ntets : 4 * (uint64_t)m->ntris + 3 * (uint64_t)ne;
  fprintf(f, "CELLS %u %llu\n", nc, (unsigned long long)size);
  for (uint32_t c = 0; c < nc; c++) {
    uint32_t per = tets ? 4 : c < m->ntris ? 3 : 2;
    const uint32_t *v = tets ? m->tets + 4 * (size_t)c
                        : c < m->ntris ? m->tris + 3 * (size_t)c
                                       : e->edges + 2 * (size_t)(c - m->ntris);
    int64_t row[5] = {per};
    for (uint32_t k = 0; k < per; k++)
      row[k + 1] = v[k];
    tr_io_put_ints(f, row, (int)per + 1);
  }
  fprintf(f, "CELL_TYPES %u\n", nc);
  for (uint32_t c = 0; c < nc; c++)
    fputs(tets ? "10\n" : c < m->ntris ? "5\n" : "3\n", f);
  fprintf(f, "CELL_DATA %u\nSCALARS region int 1\nLOOKUP_TABLE default\n", nc);
  for (uint32_t c = 0; c < nc; c++) {
    const int32_t *d = tets ? m->region : c < m->ntris ? m->tri_marker : e->edge_marker;
    uint32_t i = tets || c < m->ntris ? c : c - m->ntris;
    int64_t r = d ? d[i] : 0;
    tr_io_put_ints(f, &r, 1);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
