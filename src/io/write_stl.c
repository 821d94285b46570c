/* Binary STL of the triangles of a view (a surface output, like .off): an 80-byte header,
 * the number of triangles, then per triangle its unit normal, its three corners and a
 * 2-byte attribute (0), all little-endian. STL stores floats: every coordinate is rounded
 * to the nearest float, so a surface reads back exactly only when its coordinates are
 * floats (integers below 2^24, binary fractions of few bits); markers are not kept, the
 * format has none. Binary rather than ASCII: a fifth of the size, and the ASCII form holds
 * the same floats. The header does not start with "solid", which readers that sniff the
 * first bytes would take for ASCII. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "put_number.h"
#include "write.h"

tr_status tr_write_stl(const struct tr_mesh_view *m, const char *path)
{
  FILE *f = fopen(path, "wb");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  unsigned char b[84], *p;
  memset(b, ' ', 80);
  static const char head[] = "binary STL written by tetrec";
  memcpy(b, head, sizeof head - 1);
  p = tr_le32(b + 80, m->ntris);
  fwrite(b, 1, (size_t)(p - b), f);
  for (uint32_t t = 0; t < m->ntris; t++) {
    float c[3][3];
    for (int k = 0; k < 3; k++)
      for (int j = 0; j < 3; j++)
        c[k][j] = (float)m->xyz[3 * (size_t)m->tris[3 * (size_t)t + k] + j];
    /* the normal of the float triangle, in doubles: (c1-c0) x (c2-c0), normalised; zero
     * for a triangle that rounding made flat */
    double u[3], v[3], n[3];
    for (int j = 0; j < 3; j++) {
      u[j] = (double)c[1][j] - c[0][j];
      v[j] = (double)c[2][j] - c[0][j];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    p = b;
    for (int j = 0; j < 3; j++)
      p = tr_le_f32(p, len > 0 ? (float)(n[j] / len) : 0.0f);
    for (int k = 0; k < 3; k++)
      for (int j = 0; j < 3; j++)
        p = tr_le_f32(p, c[k][j]);
    p = tr_le16(p, 0);
    fwrite(b, 1, (size_t)(p - b), f);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
