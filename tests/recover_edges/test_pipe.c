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
#include "trand.h"

static const unsigned CHECKS = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER;

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

/* The Delaunay mesh of the 4x4x4 integer grid (point i at (i%4, (i/4)%4, i/16)), or NULL
 * with the message printed. */
static struct tr_mesh *grid4(void)
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
    return NULL;
  }
  return m;
}

static int test_grid(void)
{
  struct tr_mesh *m = grid4();
  if (!m)
    return 1;
  /* (0,0,0)-(3,3,3) through (1,1,1),(2,2,2); (0,0,1)-(3,1,2); (1,0,0)-(2,3,0) in the
   * bottom face; (0,1,1)-(3,2,2) */
  uint32_t seg[] = {0, 63, 16, 3 + 4 + 32, 1, 2 + 12, 4 + 16, 3 + 8 + 32};
  int bad = recover_all(m, seg, 4, "grid 4x4x4");
  tr_mesh_destroy(m);
  return bad;
}

/* A ghost beyond a pipel's hull face is part of the pipe iff ab meets that face at a
 * point that is not one of its vertices (pipe.c reads this off ab's classification
 * against the pipel; here it is asked of the face itself, tr_classify_segment_triangle),
 * and every pipel's classification is tr_classify_segment_tet's on the points. On the
 * 4x4x4 grid every hull face lies in a cube face's plane: all pairs of hull vertices,
 * many of them segments lying in the hull's planes (exact zeros everywhere). */
static int test_ghosts(void)
{
  struct tr_mesh *m = grid4();
  if (!m)
    return 1;
  tr_pipe pipe = {0};
  uint32_t npipes = 0, nghosts = 0, nflat = 0;
  for (uint32_t a = 0; a < 64; a++)
    for (uint32_t b = a + 1; b < 64; b++) {
      int ia[3] = {a % 4, (a / 4) % 4, a / 16}, ib[3] = {b % 4, (b / 4) % 4, b / 16}, flat = 0;
      int hull_a = 0, hull_b = 0;
      for (int k = 0; k < 3; k++) {
        hull_a |= ia[k] == 0 || ia[k] == 3;
        hull_b |= ib[k] == 0 || ib[k] == 3;
        flat |= ia[k] == ib[k] && (ia[k] == 0 || ia[k] == 3);
      }
      int yes;
      uint32_t via;
      if (!hull_a || !hull_b || tr_mesh_has_edge(m, a, b, &yes) != TR_OK || yes)
        continue;
      if (tr_pipe_collect(m, a, b, &pipe, &via) != TR_OK) {
        fprintf(stderr, "collect %u-%u: %s\n", a, b, tr_last_error());
        return 1;
      }
      if (via != TR_NONE)
        continue;
      npipes++;
      nflat += flat;
      tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
      for (uint32_t i = 0; i < pipe.n; i++) {
        const tr_pipel *pl = &pipe.pl[i];
        if (pl->ghost)
          continue;
        const uint32_t *v = m->tv + 4 * (size_t)pl->iEle;
        tr_point p[4];
        const tr_point *pp[4];
        for (int k = 0; k < 4; k++) {
          p[k] = tr_mesh_point(m, v[k]);
          pp[k] = &p[k];
        }
        tr_isect x = tr_classify_segment_tet(&pa, &pb, pp);
        int ty0 = pl->type & 3, ty1 = (pl->type >> 2) & 3;
        if (x.end[0].type != ty0 || x.end[0].code != pl->iCod1 ||
            (x.n == 2 && (x.end[1].type != ty1 || x.end[1].code != pl->iCod2))) {
          fprintf(stderr, "%u-%u: pipel %u is classified unlike tr_classify_segment_tet\n", a,
                  b, pl->iEle);
          return 1;
        }
        for (int k = 0; k < 4; k++) {
          uint32_t u = TR_NEIG(m, pl->iEle, k);
          if (u == TR_NONE || !tr_tet_is_ghost(m, u))
            continue;
          tr_point f[3];
          for (int q = 0; q < 3; q++)
            f[q] = tr_mesh_point(m, v[tr_face_vtx[k][q]]);
          tr_isect y = tr_classify_segment_triangle(&pa, &pb, &f[0], &f[1], &f[2]);
          int cut = 0, listed = 0;
          for (int e = 0; e < y.n; e++)
            cut |= y.end[e].type == TR_EDG || y.end[e].type == TR_FAC;
          for (uint32_t j = 0; j < pipe.n; j++)
            listed |= pipe.pl[j].ghost && pipe.pl[j].iEle == u;
          if (cut != listed) {
            fprintf(stderr, "%u-%u: ghost %u beyond face %d of pipel %u: %s the pipe, but ab "
                    "%s the hull face off its vertices\n", a, b, u, k, pl->iEle,
                    listed ? "in" : "not in", cut ? "meets" : "does not meet");
            return 1;
          }
          nghosts += listed;
        }
      }
    }
  tr_pipe_free(&pipe);
  tr_mesh_destroy(m);
  /* the figures (1110 pipes, 318 flat, 1188 ghosts on this grid's Delaunay mesh) guard
   * against a test that checks nothing */
  printf("grid 4x4x4: %u pipes between hull vertices (%u in a hull plane), %u ghosts cut\n",
         npipes, nflat, nghosts);
  if (npipes < 100 || nflat < 20 || nghosts < 20) {
    fprintf(stderr, "too few cases: %u pipes, %u flat, %u ghosts\n", npipes, nflat, nghosts);
    return 1;
  }
  return 0;
}

int main(int argc, char **argv)
{
  if (argc >= 5 && !strcmp(argv[1], "random") && argc <= 6)
    return test_random((uint32_t)atoi(argv[2]), atoi(argv[3]), (uint64_t)atoll(argv[4]),
                       argc == 6 ? (uint32_t)atoi(argv[5]) : 1000);
  if (argc == 2 && !strcmp(argv[1], "grid"))
    return test_grid();
  if (argc == 2 && !strcmp(argv[1], "ghosts"))
    return test_ghosts();
  fprintf(stderr, "usage: test_pipe random <n> <nseg> <seed> [range] | grid\n");
  return 2;
}
