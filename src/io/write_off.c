/* OFF output of a surface (the triangles of a view), for `tetrec convert`. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "put_number.h"
#include "write.h"

tr_status tr_write_off(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  fprintf(f, "OFF\n%u %u 0\n", m->nverts, m->ntris);
  for (uint32_t i = 0; i < m->nverts; i++)
    tr_io_put_xyz(f, -1, m->xyz + 3 * (size_t)i, "\n");
  for (uint32_t t = 0; t < m->ntris; t++)
    fprintf(f, "3 %u %u %u\n", m->tris[3 * (size_t)t], m->tris[3 * (size_t)t + 1],
            m->tris[3 * (size_t)t + 2]);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
