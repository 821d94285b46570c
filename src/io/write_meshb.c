/* Binary Medit .meshb (the Gamma Mesh Format of INRIA's libMeshb), what the text .mesh
 * writer writes: Vertices, Tetrahedra with their region as reference, Triangles with their
 * marker, then End.
 *
 * Layout: the int 1 (its byte order gives the file's: little-endian here, on every host),
 * the version, then keywords: the keyword's code (a 4-byte int), the file offset of the
 * next keyword, the number of lines for keywords that have lines, the lines. Version 2
 * has double coordinates and 4-byte ints and offsets; a file that would pass 2 GiB is
 * written as version 3 (8-byte offsets), the smallest that holds it, so readers that know
 * only version 2 still open every file they could. Codes: Dimension 3, Vertices 4,
 * Triangles 6, Tetrahedra 8, End 54 (libMeshb's GmfKwdCod). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "blocks.h"
#include "put_number.h"
#include "write.h"

enum { KW_DIMENSION = 3, KW_VERTICES = 4, KW_TRIANGLES = 6, KW_TETRAHEDRA = 8, KW_END = 54 };

struct out {
  FILE *f;
  uint64_t at;  /* bytes written */
  int wide_pos; /* 8-byte offsets (version 3) */
};

static void put(struct out *o, const unsigned char *b, const unsigned char *e)
{
  fwrite(b, 1, (size_t)(e - b), o->f);
  o->at += (uint64_t)(e - b);
}

/* The keyword header: code, offset of the next keyword (this header plus `body` bytes on),
 * and the number of lines when `lines` >= 0. */
static void keyword(struct out *o, int code, int64_t lines, uint64_t body)
{
  unsigned char b[24], *p = tr_le32(b, (uint32_t)code);
  uint64_t head = 4 + (o->wide_pos ? 8 : 4) + (lines >= 0 ? 4 : 0);
  uint64_t next = code == KW_END ? 0 : o->at + head + body;
  p = o->wide_pos ? tr_le64(p, next) : tr_le32(p, (uint32_t)next);
  if (lines >= 0)
    p = tr_le32(p, (uint32_t)lines);
  put(o, b, p);
}

/* The lines of the three keywords, formatted in blocks (blocks.h). */
static char *vertices(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = i0; i < i1; i++) {
    for (int k = 0; k < 3; k++)
      q = tr_le_f64(q, m->xyz[3 * (size_t)i + k]);
    q = tr_le32(q, 0);
  }
  return (char *)q;
}

static char *tetrahedra(const void *ctx, uint64_t t0, uint64_t t1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t t = t0; t < t1; t++) {
    for (int k = 0; k < 4; k++)
      q = tr_le32(q, m->tets[4 * (size_t)t + k] + 1);
    q = tr_le32(q, (uint32_t)(m->region ? m->region[t] : 0));
  }
  return (char *)q;
}

static char *triangles(const void *ctx, uint64_t t0, uint64_t t1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t t = t0; t < t1; t++) {
    for (int k = 0; k < 3; k++)
      q = tr_le32(q, m->tris[3 * (size_t)t + k] + 1);
    q = tr_le32(q, (uint32_t)(m->tri_marker ? m->tri_marker[t] : 0));
  }
  return (char *)q;
}

/* n lines of `size` bytes each */
static tr_status lines(struct out *o, const struct tr_mesh_view *m, uint64_t n, size_t size,
                       tr_io_block_fn fn)
{
  o->at += n * size;
  return tr_io_write_blocks(o->f, n, size, fn, m, TR_IO_BINARY_THREADS);
}

tr_status tr_write_meshb(const struct tr_mesh_view *m, const char *path)
{
  uint64_t nv = m->nverts, nt = m->ntets, ntri = m->ntris;
  if (nv > INT32_MAX || nt > INT32_MAX || ntri > INT32_MAX)
    return tr_error(TR_ERR_UNSUPPORTED, "%s: over 2^31 vertices or elements do not fit a "
                    ".meshb of 4-byte ints", path);
  /* the size with 4-byte offsets decides the version */
  uint64_t size = 8 + 12 + (12 + 28 * nv) + (nt ? 12 + 20 * nt : 0) +
                  (ntri ? 12 + 16 * ntri : 0) + 8;
  struct out o = {NULL, 0, size > INT32_MAX};
  o.f = fopen(path, "wb");
  if (!o.f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  unsigned char b[64], *p;
  p = tr_le32(b, 1);
  put(&o, b, tr_le32(p, o.wide_pos ? 3 : 2));
  keyword(&o, KW_DIMENSION, -1, 4);
  put(&o, b, tr_le32(b, 3));
  keyword(&o, KW_VERTICES, (int64_t)nv, 28 * nv);
  tr_status st = lines(&o, m, nv, 28, vertices);
  if (st == TR_OK && nt) {
    keyword(&o, KW_TETRAHEDRA, (int64_t)nt, 20 * nt);
    st = lines(&o, m, nt, 20, tetrahedra);
  }
  if (st == TR_OK && ntri) {
    keyword(&o, KW_TRIANGLES, (int64_t)ntri, 16 * ntri);
    st = lines(&o, m, ntri, 16, triangles);
  }
  keyword(&o, KW_END, -1, 0);
  int bad = ferror(o.f);
  if ((fclose(o.f) != 0 || bad) && st == TR_OK)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return st;
}
