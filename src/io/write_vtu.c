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

#include "blocks.h"
#include "put_number.h"
#include "write.h"

/* The arrays, cell by cell (tets, then triangles), as text lines or little-endian binary,
 * formatted in blocks (blocks.h). */
static char *points(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, -1, m->xyz + 3 * (size_t)i, "\n");
  return p;
}

static char *points_b(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = 3 * i0; i < 3 * i1; i++)
    q = tr_le_f64(q, m->xyz[i]);
  return (char *)q;
}

/* cell c's vertices; *per = their number */
static const uint32_t *cell(const struct tr_mesh_view *m, uint64_t c, int *per)
{
  *per = c < m->ntets ? 4 : 3;
  return c < m->ntets ? m->tets + 4 * (size_t)c : m->tris + 3 * (size_t)(c - m->ntets);
}

/* the end of cell c's vertices in the connectivity */
static uint64_t offset(const struct tr_mesh_view *m, uint64_t c)
{
  return c < m->ntets ? 4 * (c + 1) : 4 * (uint64_t)m->ntets + 3 * (c - m->ntets + 1);
}

static int32_t region(const struct tr_mesh_view *m, uint64_t c)
{
  return c < m->ntets && m->region ? m->region[c] : 0;
}

static int32_t marker(const struct tr_mesh_view *m, uint64_t c)
{
  return c >= m->ntets && m->tri_marker ? m->tri_marker[c - m->ntets] : 0;
}

static char *connectivity(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t c = c0; c < c1; c++) {
    int per;
    const uint32_t *v = cell(m, c, &per);
    int64_t row[4] = {v[0], v[1], v[2], per == 4 ? v[3] : 0};
    p = tr_io_fmt_ints(p, row, per);
  }
  return p;
}

static char *connectivity_b(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t c = c0; c < c1; c++) {
    int per;
    const uint32_t *v = cell(m, c, &per);
    for (int k = 0; k < per; k++)
      q = tr_le64(q, v[k]);
  }
  return (char *)q;
}

/* the one-number-per-cell arrays: offsets, types, region, marker */
enum { A_OFFSETS, A_TYPES, A_REGION, A_MARKER };
struct per_cell {
  const struct tr_mesh_view *m;
  int what;
};

static int64_t per_cell_value(const struct per_cell *a, uint64_t c)
{
  switch (a->what) {
  case A_OFFSETS: return (int64_t)offset(a->m, c);
  case A_TYPES: return c < a->m->ntets ? 10 : 5;
  case A_REGION: return region(a->m, c);
  default: return marker(a->m, c);
  }
}

static char *per_cell_text(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  for (uint64_t c = c0; c < c1; c++) {
    int64_t x = per_cell_value(ctx, c);
    p = tr_io_fmt_ints(p, &x, 1);
  }
  return p;
}

/* binary widths: offsets Int64, types UInt8, region and marker Int32 */
static char *per_cell_b(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  const struct per_cell *a = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t c = c0; c < c1; c++) {
    int64_t x = per_cell_value(a, c);
    if (a->what == A_OFFSETS)
      q = tr_le64(q, (uint64_t)x);
    else if (a->what == A_TYPES)
      *q++ = (unsigned char)x;
    else
      q = tr_le32(q, (uint32_t)x);
  }
  return (char *)q;
}

static const char *const cell_array_head[4] = {
    "        </DataArray>\n"
    "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n",
    "        </DataArray>\n"
    "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n",
    "        </DataArray>\n      </Cells>\n"
    "      <CellData Scalars=\"region\">\n"
    "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n",
    "        </DataArray>\n"
    "        <DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n"};

static tr_status write_ascii(FILE *f, const struct tr_mesh_view *m)
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
  TR_CHECK(tr_io_write_blocks(f, m->nverts, TR_IO_XYZ_MAX, points, m, m->threads));
  fprintf(f, "        </DataArray>\n      </Points>\n      <Cells>\n"
             "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  TR_CHECK(tr_io_write_blocks(f, nc, 4 * TR_IO_INT_MAX, connectivity, m, m->threads));
  for (int a = A_OFFSETS; a <= A_MARKER; a++) {
    struct per_cell A = {m, a};
    fputs(cell_array_head[a], f);
    TR_CHECK(tr_io_write_blocks(f, nc, TR_IO_INT_MAX, per_cell_text, &A, m->threads));
  }
  fprintf(f, "        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n"
             "</VTKFile>\n");
  return TR_OK;
}

static void put(FILE *f, const unsigned char *b, const unsigned char *e)
{
  fwrite(b, 1, (size_t)(e - b), f);
}

static tr_status write_binary(FILE *f, const struct tr_mesh_view *m)
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
  unsigned char b[8];
  put(f, b, tr_le64(b, size[0]));
  TR_CHECK(tr_io_write_blocks(f, m->nverts, 24, points_b, m, TR_IO_BINARY_THREADS));
  put(f, b, tr_le64(b, size[1]));
  TR_CHECK(tr_io_write_blocks(f, nc, 32, connectivity_b, m, TR_IO_BINARY_THREADS));
  static const size_t width[4] = {8, 1, 4, 4};
  for (int a = A_OFFSETS; a <= A_MARKER; a++) {
    struct per_cell A = {m, a};
    put(f, b, tr_le64(b, size[2 + a]));
    TR_CHECK(tr_io_write_blocks(f, nc, width[a], per_cell_b, &A, TR_IO_BINARY_THREADS));
  }
  fprintf(f, "\n  </AppendedData>\n</VTKFile>\n");
  return TR_OK;
}

tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path, int flags)
{
  int binary = (flags & TR_WRITE_BINARY) != 0;
  FILE *f = fopen(path, binary ? "wb" : "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  tr_status st = (binary ? write_binary : write_ascii)(f, m);
  int bad = ferror(f);
  if ((fclose(f) != 0 || bad) && st == TR_OK)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return st;
}
