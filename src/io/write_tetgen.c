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

static tr_status done(FILE *f, const char *base, const char *ext)
{
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s%s: write failed", base, ext);
  return TR_OK;
}

tr_status tr_write_tetgen(const struct tr_mesh_view *m, const char *base, int exact)
{
  tr_status st = TR_OK;
  FILE *f = open_ext(base, ".node", &st);
  if (!f)
    return st;
  if (exact && m->exact)
    fprintf(f, "# tetrec exact rationals\n");
  fprintf(f, "%u 3 0 0\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++) {
    const tr_qpoint *q = exact && m->exact ? m->exact[i] : NULL;
    if (!q) {
      tr_io_put_xyz(f, (int64_t)i + 1, m->xyz + 3 * (size_t)i, "\n");
      continue;
    }
    fprintf(f, "%u", i + 1);
    for (int k = 0; k < 3; k++) {
      if (q) {
        fputc(' ', f);
        mpq_out_str(f, 10, q->c[k]);
      } else
        fprintf(f, " %.17g", m->xyz[3 * (size_t)i + k]);
    }
    fputc('\n', f);
  }
  TR_CHECK(done(f, base, ".node"));
  if (!(f = open_ext(base, ".ele", &st)))
    return st;
  fprintf(f, "%u 4 %d\n", m->ntets, m->region ? 1 : 0);
  for (uint32_t t = 0; t < m->ntets; t++) {
    const uint32_t *v = m->tets + 4 * (size_t)t;
    int64_t row[6] = {(int64_t)t + 1, (int64_t)v[0] + 1, (int64_t)v[1] + 1,
                      (int64_t)v[2] + 1, (int64_t)v[3] + 1, m->region ? m->region[t] : 0};
    tr_io_put_ints(f, row, m->region ? 6 : 5);
  }
  TR_CHECK(done(f, base, ".ele"));
  if (!(f = open_ext(base, ".face", &st)))
    return st;
  fprintf(f, "%u 1\n", m->ntris);
  for (uint32_t t = 0; t < m->ntris; t++) {
    const uint32_t *v = m->tris + 3 * (size_t)t;
    int64_t row[5] = {(int64_t)t + 1, (int64_t)v[0] + 1, (int64_t)v[1] + 1, (int64_t)v[2] + 1,
                      m->tri_marker ? m->tri_marker[t] : 0};
    tr_io_put_ints(f, row, 5);
  }
  return done(f, base, ".face");
}
