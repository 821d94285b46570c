/* VTK XML UnstructuredGrid (.vtu), ASCII. Cells are the tetrahedra (VTK type 10) followed
 * by the triangles (type 5): a mesh's faces on input triangles, or a surface's triangles.
 * Cell data: "region" (the region of a tet, 0 for a triangle) and "marker" (the boundary
 * marker of a triangle, 0 for a tet), so the faces keep their markers as in the .mesh
 * and .face outputs. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io.h"

tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  uint32_t nt = m->ntets, ntri = m->ntris;
  unsigned long long nc = (unsigned long long)nt + ntri;
  fprintf(f, "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
             "  <UnstructuredGrid>\n"
             "    <Piece NumberOfPoints=\"%u\" NumberOfCells=\"%llu\">\n"
             "      <Points>\n"
             "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
          m->nverts, nc);
  for (uint32_t i = 0; i < m->nverts; i++)
    tr_io_put_xyz(f, -1, m->xyz + 3 * (size_t)i, "\n");
  fprintf(f, "        </DataArray>\n      </Points>\n      <Cells>\n"
             "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (uint32_t c = 0; c < nt; c++) {
    const uint32_t *v = m->tets + 4 * (size_t)c;
    fprintf(f, "%u %u %u %u\n", v[0], v[1], v[2], v[3]);
  }
  for (uint32_t c = 0; c < ntri; c++) {
    const uint32_t *v = m->tris + 3 * (size_t)c;
    fprintf(f, "%u %u %u\n", v[0], v[1], v[2]);
  }
  fprintf(f, "        </DataArray>\n"
             "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  unsigned long long off = 0;
  for (unsigned long long c = 0; c < nc; c++) {
    off += c < nt ? 4 : 3;
    fprintf(f, "%llu\n", off);
  }
  fprintf(f, "        </DataArray>\n"
             "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (unsigned long long c = 0; c < nc; c++)
    fprintf(f, "%d\n", c < nt ? 10 : 5);
  fprintf(f, "        </DataArray>\n      </Cells>\n"
             "      <CellData Scalars=\"region\">\n"
             "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n");
  for (unsigned long long c = 0; c < nc; c++)
    fprintf(f, "%d\n", c < nt && m->region ? (int)m->region[c] : 0);
  fprintf(f, "        </DataArray>\n"
             "        <DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n");
  for (unsigned long long c = 0; c < nc; c++)
    fprintf(f, "%d\n", c >= nt && m->tri_marker ? (int)m->tri_marker[c - nt] : 0);
  fprintf(f, "        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n"
             "</VTKFile>\n");
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
