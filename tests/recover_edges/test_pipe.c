/* Pipe(E) and whole-edge recovery on Delaunay meshes.
 * Usage: test_pipe random <npoints> <nsegments> <seed> [coordinate range] | grid
 *
 * random: Delaunay mesh of random integer points, then segments between random vertex
 *   pairs that are not mesh edges are recovered one after the other. After each one the
 *   validator runs (links, exact orientation, v2t, Euler, exact volume unchanged), and at
 *   the end every recovered segment must be a chain of mesh edges: the mesh vertices
 *   lying exactly on it (found by brute force, exact) sorted along it, with each
 *   consecutive pair a mesh edge.
 * grid: a 4x4x4 integer grid, where segments run through existing vertices and along
 *   faces (the degenerate pipel types, chains through vertices). */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/pipe.h"

static const unsigned CHECKS = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER;

static uint64_t rng;
static uint32_t next_u32(void)
{
  rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
  return (uint32_t)(rng >> 33);
}

/* Mesh vertices exactly on segment ab, sorted along it; checks consecutive edges. */
static int check_chain(struct tr_mesh *m, uint32_t a, uint32_t b)
{
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  uint32_t *on = malloc((m->nv + 2) * sizeof *on);
  uint32_t n = 0;
  on[n++] = a;
  for (uint32_t v = 0; v < m->nv; v++) {
    if (v == a || v == b || m->v2t[v] == TR_NONE)
      continue;
    tr_point pv = tr_mesh_point(m, v);
    tr_hit h = tr_classify_point_segment(&pv, &pa, &pb);
    if (h.type == TR_EDG)
      on[n++] = v;
  }
  on[n++] = b;
  /* insertion sort along the dominant axis of ab (exact coordinate comparisons) */
  int axis = tr_pipe_long_axis(&pa, &pb);
  if (axis < 0) {
    fprintf(stderr, "chain %u-%u: the two ends are the same point\n", a, b);
    free(on);
    return 1;
  }
  int dir = tr_cmp_coord_p(&pa, &pb, axis);
  for (uint32_t i = 2; i + 1 < n; i++)
    for (uint32_t j = i; j > 1; j--) {
      tr_point x = tr_mesh_point(m, on[j - 1]), y = tr_mesh_point(m, on[j]);
      if (tr_cmp_coord_p(&x, &y, axis) == dir)
        break;
      uint32_t t = on[j];
      on[j] = on[j - 1];
      on[j - 1] = t;
    }
  int bad = 0;
  for (uint32_t i = 0; i + 1 < n && !bad; i++) {
    int yes;
    if (tr_mesh_has_edge(m, on[i], on[i + 1], &yes) != TR_OK || !yes) {
      fprintf(stderr, "segment %u-%u: %u-%u (links %u of %u) is not a mesh edge\n", a, b,
              on[i], on[i + 1], i + 1, n - 1);
      bad = 1;
    }
  }
  free(on);
  return bad;
}

static int recover_all(struct tr_mesh *m, const uint32_t *seg, int nseg, const char *what)
{
  mpq_t vol;
  mpq_init(vol);
  if (tr_mesh_volume6(m, vol) != TR_OK) {
    fprintf(stderr, "%s: volume: %s\n", what, tr_last_error());
    return 1;
  }
  tr_edge_stats st;
  memset(&st, 0, sizeof st);
  int bad = 0;
  for (int i = 0; i < nseg && !bad; i++) {
    tr_status s = tr_recover_edge(m, seg[2 * i], seg[2 * i + 1], &st);
    if (s != TR_OK) {
      fprintf(stderr, "%s: segment %d (%u-%u): %s: %s\n", what, i, seg[2 * i], seg[2 * i + 1],
              tr_status_name(s), tr_last_error());
      bad = 1;
    } else if (tr_check_mesh(m, CHECKS, vol) != TR_OK) {
      fprintf(stderr, "%s: after segment %d (%u-%u): %s\n", what, i, seg[2 * i],
              seg[2 * i + 1], tr_last_error());
      bad = 1;
    } else {
      bad |= check_chain(m, seg[2 * i], seg[2 * i + 1]);
    }
  }
  /* later recoveries must not have broken earlier chains */
  for (int i = 0; i < nseg && !bad; i++)
    bad |= check_chain(m, seg[2 * i], seg[2 * i + 1]);
  mpq_clear(vol);
  if (!bad)
    printf("%s: %d segments recovered as chains (already %u, swap23 %u, swap44 %u, pipels "
           "%u, split at vertices %u, Steiner points %u); mesh valid after each\n",
           what, nseg, st.already, st.by_swap23, st.by_swap44, st.by_pipels,
           st.split_at_vertex, st.steiner_points);
  return bad;
}

static int test_random(uint32_t np, int nseg, uint64_t seed, uint32_t range)
{
  rng = seed;
  double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
  for (uint32_t i = 0; i < 3 * np; i++)
    xyz[i] = (double)(next_u32() % range);
  struct tr_mesh *m;
  tr_status s = tr_delaunay_build(xyz, np, &m);
  free(xyz);
  if (s != TR_OK) {
    fprintf(stderr, "delaunay: %s\n", tr_last_error());
    return 1;
  }
  uint32_t *seg = malloc(2 * (size_t)nseg * sizeof *seg);
  for (int i = 0; i < nseg; i++) {
    uint32_t a, b;
    int yes = 1;
    do {
      a = next_u32() % np;
      b = next_u32() % np;
      if (a != b && m->v2t[a] != TR_NONE && m->v2t[b] != TR_NONE &&
          tr_mesh_has_edge(m, a, b, &yes) != TR_OK)
        return 1;
      /* a PLC's edges do not cross: keep the segments pairwise disjoint except at shared
       * endpoints (the paper's Swap44 removes the crossed edge) */
      if (!yes && a != b) {
        tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
        for (int j = 0; j < i && !yes; j++) {
          tr_point pc = tr_mesh_point(m, seg[2 * j]), pd = tr_mesh_point(m, seg[2 * j + 1]);
          tr_isect x = tr_classify_segment_segment(&pa, &pb, &pc, &pd);
          for (int e = 0; e < x.n; e++)
            if (x.end[e].type != TR_NOD || x.end[e].on_seg == TR_SEG_IN)
              yes = 1;
        }
      }
    } while (a == b || yes || m->v2t[a] == TR_NONE || m->v2t[b] == TR_NONE);
    seg[2 * i] = a;
    seg[2 * i + 1] = b;
  }
  char what[64];
  snprintf(what, sizeof what, "random n=%u range=%u seed=%llu", np, range,
           (unsigned long long)seed);
  int bad = recover_all(m, seg, nseg, what);
  free(seg);
  tr_mesh_destroy(m);
  return bad;
}

static int test_grid(void)
{
  double xyz[64 * 3];
  for (int i = 0; i < 64; i++) {
    xyz[3 * i] = i % 4;
    xyz[3 * i + 1] = (i / 4) % 4;
    xyz[3 * i + 2] = i / 16;
  }
  struct tr_mesh *m;
  if (tr_delaunay_build(xyz, 64, &m) != TR_OK) {
    fprintf(stderr, "delaunay: %s\n", tr_last_error());
    return 1;
  }
  /* (0,0,0)-(3,3,3) through (1,1,1),(2,2,2); (0,0,1)-(3,1,2); (1,0,0)-(2,3,0) in the
   * bottom face; (0,1,1)-(3,2,2) */
  uint32_t seg[] = {0, 63, 16, 3 + 4 + 32, 1, 2 + 12, 4 + 16, 3 + 8 + 32};
  int bad = recover_all(m, seg, 4, "grid 4x4x4");
  tr_mesh_destroy(m);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc >= 5 && !strcmp(argv[1], "random") && argc <= 6)
    return test_random((uint32_t)atoi(argv[2]), atoi(argv[3]), (uint64_t)atoll(argv[4]),
                       argc == 6 ? (uint32_t)atoi(argv[5]) : 1000);
  if (argc == 2 && !strcmp(argv[1], "grid"))
    return test_grid();
  fprintf(stderr, "usage: test_pipe random <n> <nseg> <seed> [range] | grid\n");
  return 2;
}
