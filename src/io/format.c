/* Output formats chosen by name, decided before any work so that a typo in `-o` is a usage
 * error at once rather than TetGen files with a surprising name after the whole mesh is
 * built.
 *
 * The extension of a name is what follows the last '.' of its last path component. It
 * selects the format when it has a letter in it; a name without one ("out", "cube.1", the
 * TetGen convention) is a TetGen base name. An extension tetrec does not write is an error
 * (TR_ERR_USAGE) naming the supported ones. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io.h"

static const struct {
  const char *ext;
  enum tr_out_format fmt;
} known[] = {{".mesh", TR_OUT_MEDIT}, {".vtu", TR_OUT_VTU},     {".vtk", TR_OUT_VTK},
             {".msh", TR_OUT_MSH},    {".node", TR_OUT_TETGEN}, {".ele", TR_OUT_TETGEN},
             {".face", TR_OUT_TETGEN}, {".off", TR_OUT_OFF}};

/* The extension of path (with its dot), or NULL when path is a TetGen base name. */
static const char *extension(const char *path)
{
  const char *slash = strrchr(path, '/');
  const char *dot = strrchr(slash ? slash + 1 : path, '.');
  if (!dot)
    return NULL;
  for (const char *c = dot + 1; *c; c++)
    if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z'))
      return dot;
  return NULL;
}

enum tr_out_format tr_io_out_format(const char *path)
{
  if (!extension(path))
    return TR_OUT_TETGEN;
  for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
    if (tr_io_has_ext(path, known[i].ext))
      return known[i].fmt;
  return TR_OUT_UNKNOWN;
}

tr_status tr_io_check_out_name(const char *path, int surface)
{
  enum tr_out_format f = tr_io_out_format(path);
  if (f == TR_OUT_UNKNOWN || (f == TR_OUT_OFF && !surface)) {
    const char *e = extension(path);
    return tr_error(TR_ERR_USAGE,
                    "%s: tetrec does not write '%s' files (supported: .mesh .vtu .vtk .msh "
                    ".node/.ele/.face%s, or a TetGen base name without extension)",
                    path, e ? e : "", surface ? " .off" : "");
  }
  return TR_OK;
}

/* Creating the file is the only check that answers for every reason (directory missing or
 * read-only, name is a directory, disk quota): create it and remove it again unless it
 * existed, so that a failed run leaves nothing behind. */
tr_status tr_io_check_file_writable(const char *file)
{
  int existed = access(file, F_OK) == 0;
  FILE *f = fopen(file, "a");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", file, strerror(errno));
  fclose(f);
  if (!existed)
    remove(file);
  return TR_OK;
}

tr_status tr_io_check_writable(const char *path)
{
  if (tr_io_out_format(path) != TR_OUT_TETGEN)
    return tr_io_check_file_writable(path);
  /* The three files of a TetGen base name. */
  size_t n = strlen(path);
  const char *base_end = path + n;
  if (tr_io_has_ext(path, ".node") || tr_io_has_ext(path, ".ele") || tr_io_has_ext(path, ".face"))
    base_end = strrchr(path, '.');
  size_t b = (size_t)(base_end - path);
  char *p = malloc(b + 6);
  if (!p)
    return tr_error(TR_ERR_NOMEM, "out of memory");
  static const char *exts[3] = {".node", ".ele", ".face"};
  tr_status s = TR_OK;
  for (int i = 0; i < 3 && s == TR_OK; i++) {
    memcpy(p, path, b);
    strcpy(p + b, exts[i]);
    s = tr_io_check_file_writable(p);
  }
  free(p);
  return s;
}

tr_status tr_write_mesh_view_as(const struct tr_mesh_view *m, const char *path, int exact,
                                int msh_version)
{
  switch (tr_io_out_format(path)) {
  case TR_OUT_MEDIT: return tr_write_medit(m, path);
  case TR_OUT_VTU: return tr_write_vtu(m, path);
  case TR_OUT_VTK: return tr_write_vtk(m, path);
  case TR_OUT_MSH: return tr_write_msh(m, path, msh_version);
  case TR_OUT_OFF: return tr_write_off(m, path);
  case TR_OUT_TETGEN: break;
  default: return tr_io_check_out_name(path, 1);
  }
  if (!extension(path))
    return tr_write_tetgen(m, path, exact);
  size_t n = strlen(path);
  char *base = malloc(n + 1);
  if (!base)
    return tr_error(TR_ERR_NOMEM, "out of memory");
  memcpy(base, path, n + 1);
  *strrchr(base, '.') = '\0';
  tr_status st = tr_write_tetgen(m, base, exact);
  free(base);
  return st;
}

tr_status tr_write_mesh_view(const struct tr_mesh_view *m, const char *path, int exact)
{
  return tr_write_mesh_view_as(m, path, exact, 41);
}
