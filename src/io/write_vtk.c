/* Legacy VTK (.vtk), "DATASET UNSTRUCTURED_GRID", ASCII: what ParaView, VisIt and meshio
 * open without the XML reader. A mesh: the tetrahedra (VTK type 10), then its faces on
 * input triangles (type 5), with cell data "region" (a tet's region, 0 for a triangle)
 * and "marker" (a triangle's boundary marker, 0 for a tet), as in the .vtu writer. A
 * surface: the triangles, then the edges (type 3), with "region" = each one's marker.
 * Doubles in %.17g read back bitwise. */
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
  /* with tets: tets then triangles; without: the triangles, then the edges */
  uint32_t n1 = tets ? m->ntets : m->ntris, n2 = tets ? m->ntris : e->nedges, nc = n1 + n2;
  uint32_t per1 = tets ? 4 : 3, per2 = tets ? 3 : 2;
  fprintf(f, "# vtk DataFile Version 3.0\ntetrec mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS %u double\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++)
    tr_io_put_xyz(f, -1, m->xyz + 3 * (size_t)i, "\n");
  uint64_t size = (uint64_t)(per1 + 1) * n1 + (uint64_t)(per2 + 1) * n2;
  fprintf(f, "CELLS %u %llu\n", nc, (unsigned long long)size);
  for (uint32_t c = 0; c < nc; c++) {
    uint32_t per = c < n1 ? per1 : per2;
    const uint32_t *v = c < n1 ? (tets ? m->tets : m->tris) + (size_t)per1 * c
                        : (tets ? m->tris : e->edges) + (size_t)per2 * (c - n1);
    int64_t row[5] = {per};
    for (uint32_t k = 0; k < per; k++)
      row[k + 1] = v[k];
    tr_io_put_ints(f, row, (int)per + 1);
  }
  fprintf(f, "CELL_TYPES %u\n", nc);
  for (uint32_t c = 0; c < nc; c++)
    fputs(c < n1 ? (tets ? "10\n" : "5\n") : (tets ? "5\n" : "3\n"), f);
  fprintf(f, "CELL_DATA %u\nSCALARS region int 1\nLOOKUP_TABLE default\n", nc);
  for (uint32_t c = 0; c < nc; c++) {
    const int32_t *d = c < n1 ? (tets ? m->region : m->tri_marker)
                              : (tets ? NULL : e->edge_marker);
    int64_t r = d ? d[c < n1 ? c : c - n1] : 0;
    tr_io_put_ints(f, &r, 1);
  }
  if (tets) {
    fprintf(f, "SCALARS marker int 1\nLOOKUP_TABLE default\n");
    for (uint32_t c = 0; c < nc; c++) {
      int64_t r = c >= n1 && m->tri_marker ? m->tri_marker[c - n1] : 0;
      tr_io_put_ints(f, &r, 1);
    }
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
