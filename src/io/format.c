/* The dispatch from an output name to its writer, and the checks that every file a name
 * would create can be created. Names are decided by format_name.c; the dependency runs one
 * way: this file calls the writers, no writer calls back. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "format_name.h"
#include "write.h"

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
  if (tr_io_extension(path))
    base_end = strrchr(path, '.'); /* .node, .ele or .face */
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
                                int flags)
{
  if (flags & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  switch (tr_io_out_format(path)) {
  case TR_OUT_MEDIT: return tr_write_medit(m, path);
  case TR_OUT_MESHB: return tr_write_meshb(m, path);
  case TR_OUT_VTU: return tr_write_vtu(m, path, flags);
  case TR_OUT_VTK: return tr_write_vtk(m, path, flags);
  case TR_OUT_MSH: return tr_write_msh(m, path, flags);
  case TR_OUT_OFF: return tr_write_off(m, path);
  case TR_OUT_STL: return tr_write_stl(m, path);
  case TR_OUT_TETGEN: break;
  default: return tr_io_check_out_name(path, 1);
  }
  if (!tr_io_extension(path))
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
