/* Shared by the unit tests of interior point removal (test_flipout.c, test_starfill.c,
 * test_merge.c, test_retry.c): the Delaunay tetrahedralization of integer points in a box,
 * every tet in region 7, with the box's volume, and the mesh as a sorted list of sorted
 * tets, to compare meshes up to slot order. */
#ifndef TR_TESTS_SUPPRESS_TSTAR_H
#define TR_TESTS_SUPPRESS_TSTAR_H

#include <stdlib.h>

#include "delaunay/delaunay.h"
#include "mesh/mesh.h"

#include "../pipeline/texpect.h"

static int cmp_tet(const void *pa, const void *pb)
{
  const uint32_t *a = pa, *b = pb;
  for (int i = 0; i < 4; i++)
    if (a[i] != b[i])
      return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* The real tets as sorted vertex lists, in sorted order: the mesh up to slot order. */
static uint32_t *canon(const struct tr_mesh *m, uint32_t *n)
{
  uint32_t *t = NULL;
  if (tr_mesh_export_tets(m, &t, n) != TR_OK)
    return NULL;
  for (uint32_t i = 0; i < *n; i++) {
    uint32_t *v = t + 4 * (size_t)i;
    for (int a = 1; a < 4; a++)
      for (int b = a; b > 0 && v[b - 1] > v[b]; b--) {
        uint32_t x = v[b];
        v[b] = v[b - 1];
        v[b - 1] = x;
      }
  }
  qsort(t, *n, 4 * sizeof *t, cmp_tet);
  return t;
}

/* n points: 8 corners of the box [0, 64]^3, then n - 8 integer points strictly inside it
 * (a fixed linear congruential sequence from seed). */
static double *points(uint32_t n, uint32_t seed)
{
  double *x = malloc(sizeof *x * 3 * (size_t)n);
  if (!x)
    return NULL;
  for (uint32_t i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? 64 : 0;
  uint32_t s = seed;
  for (uint32_t i = 8; i < n; i++)
    for (int k = 0; k < 3; k++) {
      s = s * 1103515245u + 12345u;
      x[3 * (size_t)i + k] = 1 + (double)((s >> 16) % 63);
    }
  return x;
}

/* Their Delaunay mesh, every tet in region 7, or NULL (counted as a failure). */
static struct tr_mesh *mesh_of(uint32_t n, uint32_t seed)
{
  double *x = points(n, seed);
  struct tr_mesh *m = NULL;
  EXPECT(x && tr_delaunay_build(x, n, &m) == TR_OK, "delaunay: %s", tr_last_error());
  free(x);
  if (!m)
    return NULL;
  /* the inner points play the Steiner points the suppression removes: no duplicate map,
   * whose rule is that every input point stays in some tet */
  free(m->dup_map);
  m->dup_map = NULL;
  EXPECT(tr_mesh_enable_regions(m) == TR_OK, "regions");
  for (uint32_t t = 0; t < m->nt; t++)
    m->region[t] = 7;
  return m;
}

/* mesh_of, and vol initialised to six times the box's volume (the validator's measure,
 * which point removal must keep) when the mesh is made */
static struct tr_mesh *box_mesh(uint32_t n, uint32_t seed, mpq_t vol)
{
  struct tr_mesh *m = mesh_of(n, seed);
  if (m) {
    mpq_init(vol);
    mpq_set_ui(vol, 6 * 64 * 64 * 64, 1);
  }
  return m;
}

#endif
