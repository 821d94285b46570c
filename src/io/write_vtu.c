/* VTK XML UnstructuredGrid (.vtu), ASCII or binary. Cells are the tetrahedra (VTK type 10)
 * followed by the triangles (type 5): a mesh's faces on input triangles, or a surface's
 * triangles. Cell data: "region" (the region of a tet, 0 for a triangle) and "marker" (the
 * boundary marker of a triangle, 0 for a tet), so the faces keep their markers as in the
 * .mesh and .face outputs.
 *
 * Binary (TR_WRITE_BINARY) is VTK's raw appended data: every array after the XML, in
 * <AppendedData encoding="raw">, each preceded by its size in bytes as a UInt64
 * (header_type="UInt64", so that an array over 4 GiB keeps a true size), little-endian.
 * Raw rather than base64: a third smaller, and written without encoding; ParaView, VTK
 * and meshio read it. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "put_number.h"
#include "write.h"

static void write_ascii(FILE *f, const struct tr_mesh_view *m)
{
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
}

static void put(FILE *f, const unsigned char *b, const unsigned char *e)
{
  fwrite(b, 1, (size_t)(e - b), f);
}

static void write_binary(FILE *f, const struct tr_mesh_view *m)
{
  uint64_t nt = m->ntets, ntri = m->ntris, nc = nt + ntri;
  /* the arrays in order: points, connectivity, offsets, types, region, marker */
  uint64_t size[6] = {24 * (uint64_t)m->nverts, 8 * (4 * nt + 3 * ntri), 8 * nc, nc, 4 * nc,
                      4 * nc};
  uint64_t at[6];
  at[0] = 0;
  for (int i = 1; i < 6; i++)
    at[i] = at[i - 1] + 8 + size[i - 1];
  fprintf(f, "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\">\n"
             "  <UnstructuredGrid>\n"
             "    <Piece NumberOfPoints=\"%u\" NumberOfCells=\"%llu\">\n"
             "      <Points>\n"
             "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
             "offset=\"0\"/>\n"
             "      </Points>\n      <Cells>\n"
             "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
             "offset=\"%llu\"/>\n"
             "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" "
             "offset=\"%llu\"/>\n"
             "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" "
             "offset=\"%llu\"/>\n"
             "      </Cells>\n      <CellData Scalars=\"region\">\n"
             "        <DataArray type=\"Int32\" Name=\"region\" format=\"appended\" "
             "offset=\"%llu\"/>\n"
             "        <DataArray type=\"Int32\" Name=\"marker\" format=\"appended\" "
             "offset=\"%llu\"/>\n"
             "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n"
             "  <AppendedData encoding=\"raw\">\n   _",
          m->nverts, (unsigned long long)nc, (unsigned long long)at[1],
          (unsigned long long)at[2], (unsigned long long)at[3], (unsigned long long)at[4],
          (unsigned long long)at[5]);
  unsigned char b[64], *p;
  put(f, b, tr_le64(b, size[0]));
  for (uint32_t i = 0; i < m->nverts; i++) {
    p = b;
    for (int k = 0; k < 3; k++)
      p = tr_le_f64(p, m->xyz[3 * (size_t)i + k]);
    put(f, b, p);
  }
  put(f, b, tr_le64(b, size[1]));
  for (uint64_t c = 0; c < nc; c++) {
    int per = c < nt ? 4 : 3;
    const uint32_t *v = c < nt ? m->tets + 4 * (size_t)c : m->tris + 3 * (size_t)(c - nt);
    p = b;
    for (int k = 0; k < per; k++)
      p = tr_le64(p, v[k]);
    put(f, b, p);
  }
  put(f, b, tr_le64(b, size[2]));
  uint64_t off = 0;
  for (uint64_t c = 0; c < nc; c++) {
    off += c < nt ? 4 : 3;
    put(f, b, tr_le64(b, off));
  }
  put(f, b, tr_le64(b, size[3]));
  for (uint64_t c = 0; c < nc; c++)
    fputc(c < nt ? 10 : 5, f);
  put(f, b, tr_le64(b, size[4]));
  for (uint64_t c = 0; c < nc; c++)
    put(f, b, tr_le32(b, (uint32_t)(c < nt && m->region ? m->region[c] : 0)));
  put(f, b, tr_le64(b, size[5]));
  for (uint64_t c = 0; c < nc; c++)
    put(f, b, tr_le32(b, (uint32_t)(c >= nt && m->tri_marker ? m->tri_marker[c - nt] : 0)));
  fprintf(f, "\n  </AppendedData>\n</VTKFile>\n");
}

tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path, int flags)
{
  int binary = (flags & TR_WRITE_BINARY) != 0;
  FILE *f = fopen(path, binary ? "wb" : "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  (binary ? write_binary : write_ascii)(f, m);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
