/* The tet store renumbered along a Hilbert curve before the sliver stage
 * (src/sliver/order.c, renumbered in place): the same tets with the same regions, links
 * and exact volume afterwards, no free slot, and neighbours in the store close in space. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "sliver/sliver.h"
#include "../pipeline/texpect.h"

#define NPTS 600

/* A value from the sorted vertex ids of tet t: what its region is set to. */
static uint32_t tag(const tr_mesh *m, uint32_t t)
{
  uint32_t k[4];
  tr_sliver_tet_key(m->tv + 4 * (size_t)t, k);
  return (k[0] * 2654435761u) ^ (k[1] * 40503u) ^ (k[2] * 97u) ^ k[3];
}

static int key_cmp(const void *a, const void *b)
{
  return memcmp(a, b, 4 * sizeof(uint32_t));
}

/* The sorted keys of the real tets, sorted (4 * count entries). */
static uint32_t *tet_keys(const tr_mesh *m, uint32_t *count)
{
  uint32_t n = 0, *k = malloc(sizeof *k * 4 * ((size_t)m->nt + 1));
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t))
      tr_sliver_tet_key(m->tv + 4 * (size_t)t, k + 4 * (size_t)n++);
  qsort(k, n, 4 * sizeof *k, key_cmp);
  *count = n;
  return k;
}

/* The summed distance between the centroids of tets next to each other in the store. */
static double walk_length(const tr_mesh *m)
{
  double sum = 0, prev[3] = {0, 0, 0};
  int have = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    double c[3] = {0, 0, 0};
    for (int a = 0; a < 4; a++)
      for (int j = 0; j < 3; j++)
        c[j] += m->xyz[3 * (size_t)m->tv[4 * (size_t)t + a] + j] / 4;
    if (have)
      sum += sqrt((c[0] - prev[0]) * (c[0] - prev[0]) + (c[1] - prev[1]) * (c[1] - prev[1]) +
                  (c[2] - prev[2]) * (c[2] - prev[2]));
    memcpy(prev, c, sizeof prev);
    have = 1;
  }
  return sum;
}

/* The Delaunay mesh of the unit cube's corners and NPTS points inside on a grid of
 * 1/1024 (a fixed LCG), with regions. */
static tr_mesh *mesh_with_holes(void)
{
  double x[3 * (NPTS + 8)];
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? 1.0 : 0.0;
  uint32_t s = 12345;
  for (int i = 8; i < NPTS + 8; i++)
    for (int k = 0; k < 3; k++) {
      s = s * 1664525u + 1013904223u;
      x[3 * i + k] = (1 + (s >> 22) % 1022) / 1024.0;
    }
  tr_mesh *m = NULL;
  if (tr_delaunay_build(x, NPTS + 8, &m) != TR_OK) {
    fprintf(stderr, "Delaunay failed: %s\n", tr_last_error());
    exit(1);
  }
  if (tr_mesh_enable_regions(m) != TR_OK)
    exit(1);
  return m;
}

/* Every third real tet moved to a new slot at the end, links, v2t and region following:
 * free slots among the live ones, as refinement leaves them. */
static void punch_holes(tr_mesh *m)
{
  const uint32_t nt0 = m->nt;
  uint32_t *to = malloc(sizeof *to * nt0);
  for (uint32_t t = 0; t < nt0; t++) {
    to[t] = t;
    if (t % 3 == 0 && tr_tet_is_real(m, t)) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      EXPECT(tr_tet_new(m, v[0], v[1], v[2], v[3], &to[t]) == TR_OK, "new: %s", tr_last_error());
    }
  }
  for (uint32_t t = 0; t < nt0; t++) {
    if (to[t] == t)
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t c = m->tn[4 * (size_t)t + k];
      if (c == TR_NONE)
        continue;
      m->tn[4 * (size_t)to[t] + k] = 4 * to[c >> 2] + (c & 3);
      if (to[c >> 2] == c >> 2)
        m->tn[c] = 4 * to[t] + (uint32_t)k;
      uint32_t v = m->tv[4 * (size_t)t + k];
      if (v != TR_GHOST && m->v2t[v] == t)
        m->v2t[v] = to[t];
    }
    m->region[to[t]] = m->region[t];
  }
  for (uint32_t t = 0; t < nt0; t++)
    if (to[t] != t)
      tr_tet_free(m, t);
  free(to);
}

static void the_sort_keeps_the_mesh_and_brings_neighbours_together(void)
{
  tr_mesh *m = mesh_with_holes();
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t))
      m->region[t] = tag(m, t);
  punch_holes(m);
  EXPECT(m->nfree > 0, "no free slot to drop");
  uint32_t n0, n1;
  uint32_t *k0 = tet_keys(m, &n0);
  double before = walk_length(m);
  mpq_t six; /* the cube's volume, times 6 */
  mpq_init(six);
  mpq_set_ui(six, 6, 1);
  EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, six) == TR_OK, "before: %s", tr_last_error());
  EXPECT(tr_sliver_sort_tets(m) == TR_OK, "sort: %s", tr_last_error());
  EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, six) == TR_OK, "after: %s", tr_last_error());
  uint32_t *k1 = tet_keys(m, &n1);
  EXPECT(n0 == n1 && !memcmp(k0, k1, 4 * sizeof *k0 * n0), "the tets changed (%u -> %u)", n0, n1);
  for (uint32_t t = 0; t < m->nt; t++) {
    EXPECT(!tr_tet_is_free(m, t), "slot %u is free after the sort", t);
    if (tr_tet_is_real(m, t)) {
      EXPECT(m->region[t] == tag(m, t), "tet %u lost its region", t);
    }
  }
  EXPECT(m->nfree == 0 && m->free_head == TR_NONE, "a free list is left");
  double after = walk_length(m);
  /* before: the Delaunay store's order (sorted by smallest vertex, whose ids are random
   * here), a third of it moved to the end; 500 -> 262 */
  EXPECT(after < 0.6 * before, "neighbours in the store are not closer: walk %g -> %g", before,
         after);
  /* sorting again changes nothing: the order is a function of the tets */
  uint32_t *tv = malloc(sizeof *tv * 4 * (size_t)m->nt);
  memcpy(tv, m->tv, sizeof *tv * 4 * (size_t)m->nt);
  EXPECT(tr_sliver_sort_tets(m) == TR_OK, "sort again: %s", tr_last_error());
  EXPECT(!memcmp(tv, m->tv, sizeof *tv * 4 * (size_t)m->nt), "a second sort moved tets");
  free(tv);
  free(k0);
  free(k1);
  mpq_clear(six);
  tr_mesh_destroy(m);
}

/* The cap trials' snapshot (caps.c): after tr_sliver_shape_keys the shape cache's entry
 * of every slot holds that slot's vertices, the free ones and the ones whose tets moved
 * since they were measured included, and a real slot's measure is the fresh one. On a
 * mesh with ghost tets there is none (an entry with a ghost's ids would claim a measure). */
static void the_shape_cache_keys_are_a_copy_of_the_tet_store(void)
{
  tr_mesh *m = mesh_with_holes();
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  EXPECT(tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND) == TR_OK, "ctx: %s",
         tr_last_error());
  size_t stride = 0;
  EXPECT(!tr_sliver_shape_keys(&c, &stride), "keys of a mesh with ghost tets");
  for (uint32_t t = 0; t < m->nt; t++) /* every real slot measured */
    if (tr_tet_is_real(m, t))
      tr_sliver_tet_min(&c, t, NULL);
  punch_holes(m); /* then a third of the tets moved, their slots freed */
  EXPECT(m->nfree > 0, "no free slot");
  for (uint32_t t = 0; t < m->nt; t++) /* the ghosts out, the hull faces unlinked */
    if (!tr_tet_is_free(m, t) && tr_tet_is_ghost(m, t)) {
      uint32_t n = m->tn[4 * (size_t)t + 3];
      if (n != TR_NONE)
        m->tn[n] = TR_NONE;
      m->tn[4 * (size_t)t + 3] = TR_NONE;
    }
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && tr_tet_is_ghost(m, t))
      tr_tet_free(m, t);
  const uint32_t *k = tr_sliver_shape_keys(&c, &stride);
  EXPECT(k != NULL, "no keys on a mesh without ghosts");
  for (uint32_t t = 0; k && t < m->nt; t++) {
    EXPECT(!memcmp(k + stride * t, m->tv + 4 * (size_t)t, 4 * sizeof *k),
           "slot %u: the entry's ids are not the slot's", t);
    if (tr_tet_is_real(m, t)) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      double q = tr_sliver_min_dihedral(m, v[0], v[1], v[2], v[3]);
      EXPECT(tr_sliver_tet_min(&c, t, NULL) == q, "slot %u: a stale measure", t);
    }
  }
  tr_sliver_ctx_free(&c);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"sort", the_sort_keeps_the_mesh_and_brings_neighbours_together, NULL},
      {"keys", the_shape_cache_keys_are_a_copy_of_the_tet_store, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
