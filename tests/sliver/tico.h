/* The regular icosahedron for the sliver tests: its 12 vertices (0, +-1, +-phi) and their
 * cyclic permutations, and its 20 faces oriented outward. test_sliver.c meshes it as it
 * is, test_ratio.c subdivides it onto its circumsphere. */
#ifndef TR_TESTS_SLIVER_TICO_H
#define TR_TESTS_SLIVER_TICO_H

#include <math.h>
#include <stdint.h>

#include "core/status.h"

/* x[36]: the vertices; t[60]: the faces (their vertex triples, outward). */
static inline tr_status tico_icosahedron(double x[36], uint32_t t[60])
{
  const double f = (1 + sqrt(5.0)) / 2;
  for (int i = 0; i < 12; i++) {
    double a[3] = {0, i & 1 ? -1 : 1, i & 2 ? -f : f};
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = a[(k + 3 - i / 4) % 3];
  }
  uint32_t n = 0;
  for (uint32_t a = 0; a < 12; a++)
    for (uint32_t b = a + 1; b < 12; b++)
      for (uint32_t c = b + 1; c < 12; c++) {
        const double *p[3] = {x + 3 * a, x + 3 * b, x + 3 * c};
        int edges = 0; /* the 30 edges have length 2, every other pair is longer */
        for (int i = 0; i < 3; i++) {
          double d = 0;
          for (int k = 0; k < 3; k++)
            d += (p[i][k] - p[(i + 1) % 3][k]) * (p[i][k] - p[(i + 1) % 3][k]);
          edges += d < 4.5;
        }
        if (edges < 3 || n >= 60)
          continue;
        double u[3], v[3], nn = 0;
        for (int k = 0; k < 3; k++)
          u[k] = p[1][k] - p[0][k], v[k] = p[2][k] - p[0][k];
        for (int k = 0; k < 3; k++) /* outward: the normal points away from the origin */
          nn += (u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3]) * p[0][k];
        t[n++] = a, t[n++] = nn > 0 ? b : c, t[n++] = nn > 0 ? c : b;
      }
  if (n != 60)
    return tr_error(TR_ERR_INTERNAL, "icosahedron: %u faces", n / 3);
  return TR_OK;
}

#endif
