/* Medit ASCII .mesh (MeshVersionFormatted 2: double coordinates), readable by meshio,
 * Gmsh and Medit. Tetrahedra carry their region as reference, triangles their marker.
 * Doubles are written with %.17g, which reads back to the same double. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "put_number.h"
#include "write.h"

tr_status tr_write_medit(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  fprintf(f, "MeshVersionFormatted 2\nDimension 3\n");
  fprintf(f, "Vertices\n%u\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++)
    tr_io_put_xyz(f, -1, m->xyz + 3 * (size_t)i, " 0\n");
  if (m->ntets) {
    fprintf(f, "Tetrahedra\n%u\n", m->ntets);
    for (uint32_t t = 0; t < m->ntets; t++) {
      const uint32_t *v = m->tets + 4 * (size_t)t;
      int64_t row[5] = {(int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                        (int64_t)v[3] + 1, m->region ? m->region[t] : 0};
      tr_io_put_ints(f, row, 5);
    }
  }
  if (m->ntris) {
    fprintf(f, "Triangles\n%u\n", m->ntris);
    for (uint32_t t = 0; t < m->ntris; t++) {
      const uint32_t *v = m->tris + 3 * (size_t)t;
      int64_t row[4] = {(int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                        m->tri_marker ? m->tri_marker[t] : 0};
      tr_io_put_ints(f, row, 4);
    }
  }
  fprintf(f, "End\n");
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
