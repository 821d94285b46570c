/* Legacy VTK (.vtk), "DATASET UNSTRUCTURED_GRID", ASCII or binary: what ParaView, VisIt and
 * meshio open without the XML reader. A mesh: the tetrahedra (VTK type 10), then its faces
 * on input triangles (type 5), with cell data "region" (a tet's region, 0 for a triangle)
 * and "marker" (a triangle's boundary marker, 0 for a tet), as in the .vtu writer. A
 * surface: the triangles, then the edges (type 3), with "region" = each one's marker.
 * Doubles in %.17g read back bitwise.
 *
 * Binary (TR_WRITE_BINARY): the same text lines, each followed by its numbers as raw
 * big-endian values (the legacy format's byte order on every host): doubles for the points,
 * 4-byte ints for the cells, types and cell data, then a newline. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "blocks.h"
#include "put_number.h"
#include "write.h"

/* The cells: with tets, the tets then the triangles; without, the triangles then the
 * edges. Each section is formatted in blocks (blocks.h), as text or big-endian binary. */
struct cells {
  const struct tr_mesh_view *m;
  const struct tr_edge_view *e;
  int tets;
  uint32_t n1, per1, per2;
  int what; /* the per-cell array: A_TYPES, A_REGION, A_MARKER */
};
enum { A_TYPES, A_REGION, A_MARKER };

static char *points(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct cells *C = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, -1, C->m->xyz + 3 * (size_t)i, "\n");
  return p;
}

static char *points_b(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct cells *C = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = 3 * i0; i < 3 * i1; i++)
    q = tr_be_f64(q, C->m->xyz[i]);
  return (char *)q;
}

/* cell c as its row: the vertex count, then the vertices; returns the row's length */
static int cell_row(const struct cells *C, uint64_t c, int64_t r[5])
{
  const struct tr_mesh_view *m = C->m;
  uint32_t per = c < C->n1 ? C->per1 : C->per2;
  const uint32_t *v = c < C->n1 ? (C->tets ? m->tets : m->tris) + (size_t)C->per1 * c
                      : (C->tets ? m->tris : C->e->edges) + (size_t)C->per2 * (c - C->n1);
  r[0] = per;
  for (uint32_t k = 0; k < per; k++)
    r[k + 1] = v[k];
  return (int)per + 1;
}

static char *cells_text(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  for (uint64_t c = c0; c < c1; c++) {
    int64_t r[5];
    int n = cell_row(ctx, c, r);
    p = tr_io_fmt_ints(p, r, n);
  }
  return p;
}

static char *cells_b(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  unsigned char *q = (unsigned char *)p;
  for (uint64_t c = c0; c < c1; c++) {
    int64_t r[5];
    int n = cell_row(ctx, c, r);
    for (int i = 0; i < n; i++)
      q = tr_be32(q, (uint32_t)r[i]);
  }
  return (char *)q;
}

static int64_t per_cell_value(const struct cells *C, uint64_t c)
{
  const struct tr_mesh_view *m = C->m;
  if (C->what == A_TYPES)
    return c < C->n1 ? (C->tets ? 10 : 5) : (C->tets ? 5 : 3);
  if (C->what == A_MARKER)
    return c >= C->n1 && m->tri_marker ? m->tri_marker[c - C->n1] : 0;
  const int32_t *d = c < C->n1 ? (C->tets ? m->region : m->tri_marker)
                               : (C->tets ? NULL : C->e->edge_marker);
  return d ? d[c < C->n1 ? c : c - C->n1] : 0;
}

static char *per_cell_text(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  for (uint64_t c = c0; c < c1; c++) {
    int64_t x = per_cell_value(ctx, c);
    p = tr_io_fmt_ints(p, &x, 1);
  }
  return p;
}

static char *per_cell_b(const void *ctx, uint64_t c0, uint64_t c1, char *p)
{
  unsigned char *q = (unsigned char *)p;
  for (uint64_t c = c0; c < c1; c++)
    q = tr_be32(q, (uint32_t)per_cell_value(ctx, c));
  return (char *)q;
}

static tr_status write_vtk(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *e,
                           int binary)
{
  int tets = m->ntets > 0;
  /* with tets: tets then triangles; without: the triangles, then the edges */
  uint32_t n1 = tets ? m->ntets : m->ntris, n2 = tets ? m->ntris : e->nedges, nc = n1 + n2;
  uint32_t per1 = tets ? 4 : 3, per2 = tets ? 3 : 2;
  struct cells C = {m, e, tets, n1, per1, per2, A_TYPES};
  const char *nl = binary ? "\n" : ""; /* the newline after a block of binary values */
  int th = binary ? TR_IO_BINARY_THREADS : m->threads;
  fprintf(f, "# vtk DataFile Version 3.0\ntetrec mesh\n%s\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS %u double\n", binary ? "BINARY" : "ASCII", m->nverts);
  TR_CHECK(tr_io_write_blocks(f, m->nverts, binary ? 24 : TR_IO_XYZ_MAX,
                              binary ? points_b : points, &C, th));
  uint64_t size = (uint64_t)(per1 + 1) * n1 + (uint64_t)(per2 + 1) * n2;
  fprintf(f, "%sCELLS %u %llu\n", nl, nc, (unsigned long long)size);
  TR_CHECK(tr_io_write_blocks(f, nc, binary ? 20 : 5 * TR_IO_INT_MAX,
                              binary ? cells_b : cells_text, &C, th));
  tr_io_block_fn one = binary ? per_cell_b : per_cell_text;
  size_t width = binary ? 4 : TR_IO_INT_MAX;
  fprintf(f, "%sCELL_TYPES %u\n", nl, nc);
  TR_CHECK(tr_io_write_blocks(f, nc, width, one, &C, th));
  fprintf(f, "%sCELL_DATA %u\nSCALARS region int 1\nLOOKUP_TABLE default\n", nl, nc);
  C.what = A_REGION;
  TR_CHECK(tr_io_write_blocks(f, nc, width, one, &C, th));
  if (tets) {
    fprintf(f, "%sSCALARS marker int 1\nLOOKUP_TABLE default\n", nl);
    C.what = A_MARKER;
    TR_CHECK(tr_io_write_blocks(f, nc, width, one, &C, th));
  }
  fputs(nl, f);
  return TR_OK;
}

tr_status tr_write_vtk(const struct tr_mesh_view *m, const char *path, int flags)
{
  return tr_write_vtk_flags(m, NULL, path, flags);
}

tr_status tr_write_vtk_edges(const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                             const char *path)
{
  return tr_write_vtk_flags(m, ev, path, 0);
}

tr_status tr_write_vtk_flags(const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                             const char *path, int flags)
{
  static const struct tr_edge_view none = {0, NULL, NULL};
  int binary = (flags & TR_WRITE_BINARY) != 0;
  if (binary && m->nverts > INT32_MAX)
    return tr_error(TR_ERR_UNSUPPORTED, "%s: over 2^31 points do not fit binary legacy VTK "
                    "(4-byte ints): write .vtu", path);
  FILE *f = fopen(path, binary ? "wb" : "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  tr_status st = write_vtk(f, m, ev ? ev : &none, binary);
  int bad = ferror(f);
  if ((fclose(f) != 0 || bad) && st == TR_OK)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return st;
}
