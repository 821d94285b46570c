/* Shared by the flip tests on Delaunay meshes of random points (test_flipfirst.c,
 * test_deepflip.c, test_segmemo.c): the validator checks every mesh goes through and the
 * mesh-edge test by the library's own lookup (these meshes are too large for tmesh.h's
 * scan of every tet). Header-only: each test is one executable. */
#ifndef TR_TEST_TDFLIP_H
#define TR_TEST_TDFLIP_H

#include "mesh/check.h"
#include "mesh/mesh.h"

static const unsigned CHECKS = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER;

/* 1 iff ab is a mesh edge */
static inline int has_edge(struct tr_mesh *m, uint32_t a, uint32_t b)
{
  int yes = 0;
  return tr_mesh_has_edge(m, a, b, &yes) == TR_OK && yes;
}

#endif
