/* Small test inputs as PLCs: built from arrays (owned, tr_plc_set's copy), the box
 * surface, and a view of caller's arrays for the stages that read a struct tr_plc
 * directly. Shared by the whole-pipeline tests (through tmesh.h) and the facet and input
 * tests; no check macro here, so that tests with either EXPECT can use it. */
#ifndef TR_TESTS_PIPELINE_TPLC_H
#define TR_TESTS_PIPELINE_TPLC_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"

/* The PLC of the points x (np) and triangles t (nt), copied. A test whose input cannot be
 * built is broken, not failing a property: it exits. */
static inline tr_plc *tm_plc(const double *x, uint32_t np, const uint32_t *t, uint32_t nt)
{
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, np, t, nt, NULL) != TR_OK) {
    fprintf(stderr, "cannot build PLC: %s\n", tr_last_error());
    exit(1);
  }
  return p;
}

/* The box [lo, hi] (vertex i at bit k of i: hi[k]), 12 triangles facing inward (meshing
 * repairs the orientation), each side two triangles whose diagonal is an inner edge of
 * that side. */
static inline tr_plc *tm_box(const double lo[3], const double hi[3])
{
  double x[24];
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? hi[k] : lo[k];
  static const uint32_t t[36] = {0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3, 0, 4, 5, 0, 5, 1,
                                 2, 3, 7, 2, 7, 6, 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5};
  return tm_plc(x, 8, t, 12);
}

/* The points x (np) and triangles t (nt, markers mk or NULL) as a struct tr_plc that
 * borrows the arrays: nothing to free, every other field empty. */
static inline struct tr_plc tm_plc_view(double *x, uint32_t np, uint32_t *t, uint32_t nt,
                                        int32_t *mk)
{
  struct tr_plc p;
  memset(&p, 0, sizeof p);
  p.npoints = np;
  p.xyz = x;
  p.ntris = nt;
  p.tris = t;
  p.tri_marker = mk;
  return p;
}

#endif
