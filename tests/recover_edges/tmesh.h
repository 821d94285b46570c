/* Helpers shared by the hand-built mesh tests of edge recovery (test_mesh_ops.c: swaps
 * and pipels; test_flip.c: the flip primitive): failure macros that return 1 with a
 * message, the validator checks every result goes through, face gluing for tiny
 * hand-made meshes and an edge lookup. Header-only: each test is one executable. */
#ifndef TR_TEST_TMESH_H
#define TR_TEST_TMESH_H

#include <gmp.h>
#include <stdio.h>

#include "mesh/check.h"
#include "mesh/mesh.h"

#define FAIL(...)                         \
  do {                                    \
    fprintf(stderr, __VA_ARGS__);         \
    fputc('\n', stderr);                  \
    return 1;                             \
  } while (0)
#define CK(expr)                                                                       \
  do {                                                                                 \
    tr_status s_ = (expr);                                                             \
    if (s_ != TR_OK)                                                                   \
      FAIL("%s:%d: %s -> %s: %s", __FILE__, __LINE__, #expr, tr_status_name(s_),      \
           tr_last_error());                                                           \
  } while (0)

static const unsigned CHECKS = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER;

/* Glues every pair of faces with the same three vertices (tiny meshes only: quadratic). */
static inline void glue_all(struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++)
    for (int k = 0; k < 4; k++) {
      if (tr_tet_is_free(m, t) || m->tn[4 * t + k] != TR_NONE)
        continue;
      const uint32_t *v = m->tv + 4 * t;
      for (uint32_t u = t + 1; u < m->nt; u++) {
        if (tr_tet_is_free(m, u))
          continue;
        int fk = tr_fcode(m, u, v[(k + 1) & 3], v[(k + 2) & 3], v[(k + 3) & 3]);
        if (fk >= 0 && m->tn[4 * u + fk] == TR_NONE) {
          tr_glue(m, t, k, u, fk);
          break;
        }
      }
    }
}

/* 1 iff some tet has both a and b (then ab is a mesh edge). */
static inline int has_edge(const struct tr_mesh *m, uint32_t a, uint32_t b)
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && tr_ncode(m, t, a) >= 0 && tr_ncode(m, t, b) >= 0)
      return 1;
  return 0;
}

/* The validator with CHECKS and, when vol0 is not NULL, the exact total volume. */
static inline int validate(struct tr_mesh *m, mpq_t vol0, const char *what)
{
  if (tr_check_mesh(m, CHECKS, vol0) != TR_OK)
    FAIL("%s: validator: %s", what, tr_last_error());
  return 0;
}

#endif
