/* VTK XML UnstructuredGrid (.vtu), ASCII. Cells are the tetrahedra (VTK type 10), or the
 * triangles (type 5) when there are no tetrahedra; cell data "region" holds the region
 * of each tet (or the marker of each triangle). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io.h"

tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  int tets = m->ntets > 0;
  uint32_t nc = tets ? m->ntets : m->ntris, per = tets ? 4 : 3;
  const uint32_t *cv = tets ? m->tets : m->tris;
  const int32_t *cd = tets ? m->region : m->tri_marker;
  fprintf(f, "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
             "  <UnstructuredGrid>\n"
             "    <Piece NumberOfPoints=\"%u\" NumberOfCells=\"%u\">\n"
             "      <Points>\n"
             "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
          m->nverts, nc);
  for (uint32_t i = 0; i < m->nverts; i++)
    fprintf(f, "%.17g %.17g %.17g\n", m->xyz[3 * (size_t)i], m->xyz[3 * (size_t)i + 1],
            m->xyz[3 * (size_t)i + 2]);
  fprintf(f, "        </DataArray>\n      </Points>\n      <Cells>\n"
             "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (uint32_t c = 0; c < nc; c++) {
    for (uint32_t k = 0; k < per; k++)
      fprintf(f, k ? " %u" : "%u", cv[per * (size_t)c + k]);
    fputc('\n', f);
  }
  fprintf(f, "        </DataArray>\n"
             "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (uint32_t c = 0; c < nc; c++)
    fprintf(f, "%llu\n", (unsigned long long)per * (c + 1));
  fprintf(f, "        </DataArray>\n"
             "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (uint32_t c = 0; c < nc; c++)
    fprintf(f, "%d\n", tets ? 10 : 5);
  fprintf(f, "        </DataArray>\n      </Cells>\n"
             "      <CellData Scalars=\"region\">\n"
             "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n");
  for (uint32_t c = 0; c < nc; c++)
    fprintf(f, "%d\n", cd ? (int)cd[c] : 0);
  fprintf(f, "        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n"
             "</VTKFile>\n");
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
