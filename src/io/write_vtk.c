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

#include "put_number.h"
#include "write.h"

/* One row of n ints: text, or big-endian 4-byte ints. */
static void row(FILE *f, const int64_t *x, int n, int binary)
{
  if (!binary) {
    tr_io_put_ints(f, x, n);
    return;
  }
  unsigned char b[32], *p = b;
  for (int i = 0; i < n && i < 8; i++)
    p = tr_be32(p, (uint32_t)x[i]);
  fwrite(b, 1, (size_t)(p - b), f);
}

static void write_vtk(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *e,
                      int binary)
{
  int tets = m->ntets > 0;
  /* with tets: tets then triangles; without: the triangles, then the edges */
  uint32_t n1 = tets ? m->ntets : m->ntris, n2 = tets ? m->ntris : e->nedges, nc = n1 + n2;
  uint32_t per1 = tets ? 4 : 3, per2 = tets ? 3 : 2;
  const char *nl = binary ? "\n" : ""; /* the newline after a block of binary values */
  fprintf(f, "# vtk DataFile Version 3.0\ntetrec mesh\n%s\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS %u double\n", binary ? "BINARY" : "ASCII", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++) {
    if (!binary) {
      tr_io_put_xyz(f, -1, m->xyz + 3 * (size_t)i, "\n");
      continue;
    }
    unsigned char b[24], *p = b;
    for (int k = 0; k < 3; k++)
      p = tr_be_f64(p, m->xyz[3 * (size_t)i + k]);
    fwrite(b, 1, sizeof b, f);
  }
  uint64_t size = (uint64_t)(per1 + 1) * n1 + (uint64_t)(per2 + 1) * n2;
  fprintf(f, "%sCELLS %u %llu\n", nl, nc, (unsigned long long)size);
  for (uint32_t c = 0; c < nc; c++) {
    uint32_t per = c < n1 ? per1 : per2;
    const uint32_t *v = c < n1 ? (tets ? m->tets : m->tris) + (size_t)per1 * c
                        : (tets ? m->tris : e->edges) + (size_t)per2 * (c - n1);
    int64_t r[5] = {per};
    for (uint32_t k = 0; k < per; k++)
      r[k + 1] = v[k];
    row(f, r, (int)per + 1, binary);
  }
  fprintf(f, "%sCELL_TYPES %u\n", nl, nc);
  for (uint32_t c = 0; c < nc; c++) {
    int64_t t = c < n1 ? (tets ? 10 : 5) : (tets ? 5 : 3);
    row(f, &t, 1, binary);
  }
  fprintf(f, "%sCELL_DATA %u\nSCALARS region int 1\nLOOKUP_TABLE default\n", nl, nc);
  for (uint32_t c = 0; c < nc; c++) {
    const int32_t *d = c < n1 ? (tets ? m->region : m->tri_marker)
                              : (tets ? NULL : e->edge_marker);
    int64_t r = d ? d[c < n1 ? c : c - n1] : 0;
    row(f, &r, 1, binary);
  }
  if (tets) {
    fprintf(f, "%sSCALARS marker int 1\nLOOKUP_TABLE default\n", nl);
    for (uint32_t c = 0; c < nc; c++) {
      int64_t r = c >= n1 && m->tri_marker ? m->tri_marker[c - n1] : 0;
      row(f, &r, 1, binary);
    }
  }
  fputs(nl, f);
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
  write_vtk(f, m, ev ? ev : &none, binary);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
