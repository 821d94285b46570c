#define _POSIX_C_SOURCE 200809L /* fileno, fstat */
/* Loading files and choosing the reader by extension (format_name.c). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/hugepage.h"
#include "input/options.h"
#include "io.h"
#include "write.h"

tr_status tr_io_load(const char *path, char **buf, size_t *len)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
  /* A regular file is read into one block of its size: growing a buffer by doubling
   * copied a 270 MB .node twice over and faulted in twice its pages. The loop below still
   * reads to the end, so a file that grows meanwhile, or a pipe, is read whole. */
  struct stat sb;
  size_t cap = 1 << 16, n = 0;
  if (fstat(fileno(f), &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0 &&
      (uint64_t)sb.st_size < ((uint64_t)1 << 40))
    cap = (size_t)sb.st_size + 2; /* + NUL, + 1 so that the end is seen without a regrowth */
  char *b = malloc(cap);
  /* huge pages where the kernel leaves it to the program: loading a 270 MB file faulted
   * in 66k small pages, a third of its reading time on a virtual machine */
  if (b && cap > (1 << 16))
    tr_advise_hugepages(b, cap);
  while (b) {
    size_t r = fread(b + n, 1, cap - n - 1, f);
    n += r;
    if (n + 1 < cap) {
      if (ferror(f)) {
        free(b);
        fclose(f);
        return tr_error(TR_ERR_IO, "%s: read error: %s", path, strerror(errno));
      }
      break;
    }
    char *nb = cap < ((size_t)1 << 40) ? realloc(b, cap * 2) : NULL;
    if (!nb)
      free(b);
    b = nb;
    cap *= 2;
  }
  fclose(f);
  if (!b)
    return tr_error(TR_ERR_NOMEM, "%s: out of memory loading the file", path);
  b[n] = '\0';
  *buf = b;
  *len = n;
  return TR_OK;
}

/* base + new extension, e.g. "cube.poly" -> "cube.node". */
static char *sibling(const char *path, const char *ext)
{
  const char *dot = strrchr(path, '.');
  size_t n = dot ? (size_t)(dot - path) : strlen(path);
  char *s = malloc(n + strlen(ext) + 1);
  if (s) {
    memcpy(s, path, n);
    strcpy(s + n, ext);
  }
  return s;
}

tr_status tr_io_read_file(const char *path, struct tr_plc *plc)
{
  return tr_io_read_file_threads(path, plc, 1);
}

/* the reading entry of the public API lives with the readers, not in core/plc.c, which
 * the readers build on */
tr_status tr_plc_read(const char *path, tr_plc **out) { return tr_plc_read_fans(path, out, 1, 0); }

tr_status tr_plc_read_threads(const char *path, tr_plc **out, int threads)
{
  return tr_plc_read_fans(path, out, threads, 0);
}

tr_status tr_plc_read_options(const char *path, const tr_options *opt, tr_plc **out)
{
  tr_options o;
  tr_options_read(opt, &o);
  if (o.threads < 0) {
    *out = NULL;
    tr_error_clear();
    return tr_error(TR_ERR_USAGE, "threads must be >= 0 (0: every core), not %d", o.threads);
  }
  return tr_plc_read_fans(path, out, tr_io_thread_count(o.threads), o.resolve != 0);
}

tr_status tr_plc_read_fans(const char *path, tr_plc **out, int threads, int fans)
{
  tr_error_clear();
  *out = NULL;
  tr_plc *p;
  TR_CHECK(tr_plc_create(&p));
  p->read_fans = (uint8_t)(fans != 0);
  tr_status st = tr_io_read_file_threads(path, p, threads);
  if (st != TR_OK) {
    tr_plc_destroy(p);
    return st;
  }
  *out = p;
  return TR_OK;
}

tr_status tr_io_read_file_threads(const char *path, struct tr_plc *plc, int threads)
{
  char *buf = NULL, *nbuf = NULL, *npath = NULL;
  size_t len = 0, nlen = 0;
  tr_status st;
  enum tr_in_format kind = tr_io_in_format(path);
  if (kind == TR_IN_UNKNOWN)
    return tr_io_unknown_input(path);
  if (kind == TR_IN_ELE) {
    /* .ele: the points come from the .node next to it. */
    npath = sibling(path, ".node");
    if (!npath)
      return tr_error(TR_ERR_NOMEM, "out of memory");
    st = tr_io_read_file_threads(npath, plc, threads);
    free(npath);
    if (st != TR_OK)
      return st;
    st = tr_io_load(path, &buf, &len);
    if (st == TR_OK)
      st = tr_read_ele_buf(buf, len, path, plc);
    free(buf);
    return st;
  }
  TR_CHECK(tr_io_load(path, &buf, &len));
  switch (kind) {
  case TR_IN_OFF: st = tr_read_off_buf(buf, len, path, plc); break;
  case TR_IN_STL: st = tr_read_stl_buf(buf, len, path, plc); break;
  case TR_IN_OBJ: st = tr_read_obj_buf(buf, len, path, plc); break;
  case TR_IN_PLY: st = tr_read_ply_buf(buf, len, path, plc); break;
  case TR_IN_MEDIT: st = tr_read_medit_buf(buf, len, path, plc); break;
  case TR_IN_MESHB: st = tr_read_meshb_buf(buf, len, path, plc); break;
  case TR_IN_MSH: st = tr_read_msh_buf(buf, len, path, plc); break;
  case TR_IN_NODE:
    st = tr_read_tetgen_buf_threads(TR_TETGEN_NODE, buf, len, path, NULL, 0, NULL, plc,
                                    threads);
    break;
  default: {
    /* A .poly/.smesh may leave its points to the .node of the same name. */
    npath = sibling(path, ".node");
    if (npath) {
      FILE *f = fopen(npath, "rb");
      if (f) {
        fclose(f);
        st = tr_io_load(npath, &nbuf, &nlen);
        if (st != TR_OK) {
          free(buf);
          free(npath);
          return st;
        }
      }
    }
    st = tr_read_tetgen_buf_threads(kind == TR_IN_POLY ? TR_TETGEN_POLY : TR_TETGEN_SMESH,
                                    buf, len, path, nbuf, nlen, npath, plc, threads);
    break;
  }
  }
  free(buf);
  free(nbuf);
  free(npath);
  if (st == TR_OK && !plc->source) {
    size_t n = strlen(path);
    plc->source = malloc(n + 1);
    if (plc->source)
      memcpy(plc->source, path, n + 1);
  }
  return st;
}
