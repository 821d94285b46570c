/* TetGen .node/.ele/.face output, 1-based like TetGen's default.
 *
 * Exact format (--exact): a vertex that has an exact rational position (a Steiner point)
 * has each coordinate written as "num/den" in lowest terms, base 10, den > 0 (den == 1 is
 * written as a plain integer); every other coordinate is the double in %.17g. tetrec's
 * .node reader accepts both forms and rounds a rational to the nearest double. The first
 * line of such a file is the comment "# tetrec exact rationals". */
#include <errno.h>
#include <stdio.h> /* before gmp.h: enables mpq_out_str */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "blocks.h"
#include "put_number.h"
#include "write.h"

static FILE *open_ext(const char *base, const char *ext, tr_status *st)
{
  size_t n = strlen(base);
  char *p = malloc(n + strlen(ext) + 1);
  if (!p) {
    *st = tr_error(TR_ERR_NOMEM, "out of memory");
    return NULL;
  }
  memcpy(p, base, n);
  strcpy(p + n, ext);
  FILE *f = fopen(p, "w");
  if (!f)
    *st = tr_error(TR_ERR_IO, "%s: cannot create: %s", p, strerror(errno));
  free(p);
  return f;
}

/* Closes f; st: how writing it went (a failure before the close is the one reported). */
static tr_status done(FILE *f, tr_status st, const char *base, const char *ext)
{
  int bad = ferror(f);
  if ((fclose(f) != 0 || bad) && st == TR_OK)
    return tr_error(TR_ERR_IO, "%s%s: write failed", base, ext);
  return st;
}

/* The records of the three files, formatted in blocks (blocks.h). */
static char *node_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, (int64_t)i + 1, m->xyz + 3 * (size_t)i, "\n");
  return p;
}

static char *ele_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t t = i0; t < i1; t++) {
    const uint32_t *v = m->tets + 4 * (size_t)t;
    int64_t row[6] = {(int64_t)t + 1, (int64_t)v[0] + 1, (int64_t)v[1] + 1,
                      (int64_t)v[2] + 1, (int64_t)v[3] + 1, m->region ? m->region[t] : 0};
    p = tr_io_fmt_ints(p, row, m->region ? 6 : 5);
  }
  return p;
}

static char *face_rows(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t t = i0; t < i1; t++) {
    const uint32_t *v = m->tris + 3 * (size_t)t;
    int64_t row[5] = {(int64_t)t + 1, (int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                      m->tri_marker ? m->tri_marker[t] : 0};
    p = tr_io_fmt_ints(p, row, 5);
  }
  return p;
}

/* The .node file with exact rationals: a rational's length has no bound, so these rows
 * are not cut into blocks (--exact is for meshes with Steiner points, not for size). */
static void exact_nodes(FILE *f, const struct tr_mesh_view *m)
{
  for (uint32_t i = 0; i < m->nverts; i++) {
    const tr_qpoint *q = m->exact[i];
    if (!q) {
      tr_io_put_xyz(f, (int64_t)i + 1, m->xyz + 3 * (size_t)i, "\n");
      continue;
    }
    fprintf(f, "%u", i + 1);
    for (int k = 0; k < 3; k++) {
      fputc(' ', f);
      mpq_out_str(f, 10, q->c[k]);
    }
    fputc('\n', f);
  }
}

tr_status tr_write_tetgen(const struct tr_mesh_view *m, const char *base, int exact)
{
  tr_status st = TR_OK;
  FILE *f = open_ext(base, ".node", &st);
  if (!f)
    return st;
  if (exact && m->exact) {
    fprintf(f, "# tetrec exact rationals\n%u 3 0 0\n", m->nverts);
    exact_nodes(f, m);
  } else {
    fprintf(f, "%u 3 0 0\n", m->nverts);
    st = tr_io_write_blocks(f, m->nverts, TR_IO_XYZ_MAX, node_rows, m, m->threads);
  }
  TR_CHECK(done(f, st, base, ".node"));
  if (!(f = open_ext(base, ".ele", &st)))
    return st;
  fprintf(f, "%u 4 %d\n", m->ntets, m->region ? 1 : 0);
  st = tr_io_write_blocks(f, m->ntets, 6 * TR_IO_INT_MAX, ele_rows, m, m->threads);
  TR_CHECK(done(f, st, base, ".ele"));
  if (!(f = open_ext(base, ".face", &st)))
    return st;
  fprintf(f, "%u 1\n", m->ntris);
  st = tr_io_write_blocks(f, m->ntris, 5 * TR_IO_INT_MAX, face_rows, m, m->threads);
  return done(f, st, base, ".face");
}
