/* Medit ASCII .mesh (MeshVersionFormatted 2: double coordinates), readable by meshio,
 * Gmsh and Medit. Tetrahedra carry their region as reference, triangles their marker.
 * Doubles are written with %.17g, which reads back to the same double. The sections are
 * formatted in blocks, on m->threads threads (blocks.h). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "blocks.h"
#include "put_number.h"
#include "write.h"

static char *vertex_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, -1, m->xyz + 3 * (size_t)i, " 0\n");
  return p;
}

static char *tet_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t t = i0; t < i1; t++) {
    const uint32_t *v = m->tets + 4 * (size_t)t;
    int64_t row[5] = {(int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                      (int64_t)v[3] + 1, m->region ? m->region[t] : 0};
    p = tr_io_fmt_ints(p, row, 5);
  }
  return p;
}

static char *tri_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t t = i0; t < i1; t++) {
    const uint32_t *v = m->tris + 3 * (size_t)t;
    int64_t row[4] = {(int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                      m->tri_marker ? m->tri_marker[t] : 0};
    p = tr_io_fmt_ints(p, row, 4);
  }
  return p;
}

tr_status tr_write_medit(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  fprintf(f, "MeshVersionFormatted 2\nDimension 3\n");
  fprintf(f, "Vertices\n%u\n", m->nverts);
  tr_status st = tr_io_write_blocks(f, m->nverts, TR_IO_XYZ_MAX, vertex_rows, m, m->threads);
  if (st == TR_OK && m->ntets) {
    fprintf(f, "Tetrahedra\n%u\n", m->ntets);
    st = tr_io_write_blocks(f, m->ntets, 5 * TR_IO_INT_MAX, tet_rows, m, m->threads);
  }
  if (st == TR_OK && m->ntris) {
    fprintf(f, "Triangles\n%u\n", m->ntris);
    st = tr_io_write_blocks(f, m->ntris, 4 * TR_IO_INT_MAX, tri_rows, m, m->threads);
  }
  fprintf(f, "End\n");
  int bad = ferror(f);
  if ((fclose(f) != 0 || bad) && st == TR_OK)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return st;
}
