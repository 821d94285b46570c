/* Formats chosen by name, decided before any work so that a typo in `-o` is a usage error
 * at once rather than TetGen files with a surprising name after the whole mesh is built.
 * The tables below are the only lists of extensions in src/io: the messages that name the
 * supported ones are made from them, so a format added here is announced everywhere. */
#include <stdio.h>
#include <string.h>

#include "format_name.h"

int tr_io_has_ext(const char *path, const char *ext)
{
  size_t n = strlen(path), m = strlen(ext);
  if (n < m)
    return 0;
  for (size_t i = 0; i < m; i++) {
    char a = path[n - m + i], b = ext[i];
    if (a >= 'A' && a <= 'Z')
      a = (char)(a - 'A' + 'a');
    if (a != b)
      return 0;
  }
  return 1;
}

const char *tr_io_extension(const char *path)
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

/* surface: written only for a surface (tr_plc_write), never for a tet mesh, which they
 * cannot hold. binary: the format has a binary form tetrec writes. */
static const struct {
  const char *ext;
  enum tr_out_format fmt;
  unsigned char surface, binary;
} out_known[] = {{".mesh", TR_OUT_MEDIT, 0, 0},  {".meshb", TR_OUT_MESHB, 0, 1},
                 {".vtu", TR_OUT_VTU, 0, 1},     {".vtk", TR_OUT_VTK, 0, 1},
                 {".msh", TR_OUT_MSH, 0, 1},     {".node", TR_OUT_TETGEN, 0, 0},
                 {".ele", TR_OUT_TETGEN, 0, 0},  {".face", TR_OUT_TETGEN, 0, 0},
                 {".off", TR_OUT_OFF, 1, 0},     {".stl", TR_OUT_STL, 1, 1}};
enum { NOUT = sizeof out_known / sizeof out_known[0] };

enum tr_out_format tr_io_out_format(const char *path)
{
  if (!tr_io_extension(path))
    return TR_OUT_TETGEN;
  for (size_t i = 0; i < NOUT; i++)
    if (tr_io_has_ext(path, out_known[i].ext))
      return out_known[i].fmt;
  return TR_OUT_UNKNOWN;
}

/* The extensions of out_known that pass `keep`, space-separated, into buf. */
static const char *out_list(char *buf, size_t cap, int surface, int binary)
{
  size_t n = 0;
  buf[0] = '\0';
  for (size_t i = 0; i < NOUT; i++) {
    if ((out_known[i].surface && !surface) || (binary && !out_known[i].binary))
      continue;
    int w = snprintf(buf + n, cap - n, "%s%s", n ? " " : "", out_known[i].ext);
    if (w < 0 || (size_t)w >= cap - n)
      break;
    n += (size_t)w;
  }
  return buf;
}

tr_status tr_io_check_out_name(const char *path, int surface)
{
  enum tr_out_format f = tr_io_out_format(path);
  int surface_only = 0;
  for (size_t i = 0; i < NOUT; i++)
    if (out_known[i].fmt == f && out_known[i].surface)
      surface_only = 1;
  if (f == TR_OUT_UNKNOWN || (surface_only && !surface)) {
    const char *e = tr_io_extension(path);
    char list[128];
    return tr_error(TR_ERR_USAGE,
                    "%s: tetrec does not write '%s' files%s (supported: %s, or a TetGen base "
                    "name without extension)",
                    path, e ? e : "", surface_only ? " of a tetrahedral mesh" : "",
                    out_list(list, sizeof list, surface, 0));
  }
  return TR_OK;
}

tr_status tr_io_check_binary_name(const char *path)
{
  enum tr_out_format f = tr_io_out_format(path);
  for (size_t i = 0; i < NOUT; i++)
    if (out_known[i].fmt == f && out_known[i].binary)
      return TR_OK;
  const char *e = tr_io_extension(path);
  char list[128];
  return tr_error(TR_ERR_USAGE, "%s: tetrec writes %s files as text only; --binary applies to %s%s",
                  path, e ? e : "TetGen", out_list(list, sizeof list, 1, 1),
                  f == TR_OUT_MEDIT ? " (binary Medit is .meshb)" : "");
}

static const struct {
  const char *ext;
  enum tr_in_format fmt;
} in_known[] = {{".off", TR_IN_OFF},     {".stl", TR_IN_STL},   {".obj", TR_IN_OBJ},
                {".ply", TR_IN_PLY},     {".mesh", TR_IN_MEDIT}, {".meshb", TR_IN_MESHB},
                {".msh", TR_IN_MSH},     {".node", TR_IN_NODE}, {".poly", TR_IN_POLY},
                {".smesh", TR_IN_SMESH}, {".ele", TR_IN_ELE}};
enum { NIN = sizeof in_known / sizeof in_known[0] };

enum tr_in_format tr_io_in_format(const char *path)
{
  for (size_t i = 0; i < NIN; i++)
    if (tr_io_has_ext(path, in_known[i].ext))
      return in_known[i].fmt;
  return TR_IN_UNKNOWN;
}

tr_status tr_io_unknown_input(const char *path)
{
  char list[128];
  size_t n = 0;
  list[0] = '\0';
  for (size_t i = 0; i < NIN; i++) {
    int w = snprintf(list + n, sizeof list - n, "%s%s", n ? " " : "", in_known[i].ext);
    if (w < 0 || (size_t)w >= sizeof list - n)
      break;
    n += (size_t)w;
  }
  return tr_error(TR_ERR_USAGE, "%s: unknown file extension (supported: %s)", path, list);
}
