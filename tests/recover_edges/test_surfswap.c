/* What edge recovery learns of the surface's flat regions (src/recover_edges/surfswap.c),
 * on a box [0,2]^3 whose faces are 2x2 grids of unit squares, each cut by a diagonal:
 * every square's four corners are cocircular, so the smoothing before Delaunay leaves
 * them and the Delaunay mesh picks its own diagonals.
 *
 * Usage: test_surfswap MODE
 *   flat:  tr_flat_edges flags exactly the edges inside a face (not on a box edge), an
 *          edge between two markers of one face is no flat edge, nor is a segment;
 *   swaps: tr_surface_swaps_to_mesh leaves no input edge inside a face missing from the
 *          Delaunay mesh (every square takes the mesh's diagonal), every triangle stays
 *          in its face with its marker, the triangles tile each face (exact area), and a
 *          second call swaps nothing; with the marker split, no swap crosses it;
 *   phases: edge recovery given the surface (its flat edges after the others) recovers
 *          every input edge as a chain of mesh edges on the same surface moved off the
 *          grid (points nudged inside their faces, so edges go missing), and the mesh
 *          passes the validator with its exact volume unchanged. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "predicates.h"
#include "recover_edges/recover_edges.h"
#include "tedges.h"

#define FAIL(...)                                                                          \
  do {                                                                                     \
    fprintf(stderr, "FAIL: " __VA_ARGS__);                                                 \
    fprintf(stderr, "\n");                                                                 \
    return 1;                                                                              \
  } while (0)

/* The grid box: points with coordinates in {0, 1, 2} on the boundary (26), and per face
 * 8 triangles, outward. Face f = 2 * axis + side. marker_split: the triangles of face 0
 * with z < 1 get marker 7 (the others 0). nudge: interior face points moved by a small
 * dyadic step inside their face (still exactly coplanar), so that the squares are no
 * longer cocircular. */
typedef struct grid {
  double xyz[3 * 26];
  uint32_t np, tris[3 * 48], face[48];
  int32_t marker[48];
} grid;

static uint32_t point_id(grid *g, const double p[3])
{
  for (uint32_t i = 0; i < g->np; i++)
    if (g->xyz[3 * i] == p[0] && g->xyz[3 * i + 1] == p[1] && g->xyz[3 * i + 2] == p[2])
      return i;
  memcpy(g->xyz + 3 * g->np, p, 3 * sizeof *p);
  return g->np++;
}

static void build(grid *g, int marker_split, int nudge)
{
  memset(g, 0, sizeof *g);
  uint32_t nt = 0;
  for (int f = 0; f < 6; f++) {
    int ax = f / 2, side = f % 2, u = (ax + 1) % 3, v = (ax + 2) % 3;
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2; j++) {
        uint32_t c[4];
        const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
        for (int k = 0; k < 4; k++) {
          double p[3];
          p[ax] = 2.0 * side;
          p[u] = i + du[k];
          p[v] = j + dv[k];
          c[k] = point_id(g, p);
        }
        /* (u, v, ax) is right-handed: counter-clockwise in (u, v) faces +ax */
        uint32_t t[2][3] = {{c[0], c[1], c[2]}, {c[0], c[2], c[3]}};
        for (int h = 0; h < 2; h++) {
          uint32_t *T = g->tris + 3 * nt;
          T[0] = t[h][0];
          T[1] = side ? t[h][1] : t[h][2];
          T[2] = side ? t[h][2] : t[h][1];
          g->face[nt] = (uint32_t)f;
          g->marker[nt] = marker_split && f == 0 && j == 0 ? 7 : 0;
          nt++;
        }
      }
  }
  if (nudge)
    for (uint32_t i = 0; i < g->np; i++) {
      double *p = g->xyz + 3 * i;
      int on = 0, ax = -1;
      for (int k = 0; k < 3; k++)
        if (p[k] == 0 || p[k] == 2) {
          on++;
          ax = k;
        }
      if (on == 1) /* the centre of a face: moved inside it */
        p[(ax + 1) % 3] += 0.125 * (1 + (int)(i % 3));
    }
}

static tr_plc *make_plc(const grid *g, int markers)
{
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK ||
      tr_plc_set(p, g->xyz, g->np, g->tris, 48, markers ? g->marker : NULL) != TR_OK)
    return NULL;
  return p;
}

static uint32_t list_edges(const tr_plc *p, uint32_t *e)
{
  for (uint32_t t = 0; t < p->ntris; t++)
    for (int k = 0; k < 3; k++) {
      e[6 * t + 2 * k] = p->tris[3 * t + k];
      e[6 * t + 2 * k + 1] = p->tris[3 * t + (k + 1) % 3];
    }
  return sort_edges(e, 3 * p->ntris);
}

/* An edge on a box edge: its two ends share two coordinates in {0, 2}. */
static int on_box_edge(const grid *g, uint32_t a, uint32_t b)
{
  int n = 0;
  for (int k = 0; k < 3; k++) {
    double x = g->xyz[3 * a + k], y = g->xyz[3 * b + k];
    n += x == y && (x == 0 || x == 2);
  }
  return n >= 2;
}

static int test_flat(void)
{
  grid g;
  uint32_t e[2 * 144];
  uint8_t flat[144];
  for (int split = 0; split < 2; split++) {
    build(&g, split, 0);
    tr_plc *p = make_plc(&g, split);
    if (!p)
      FAIL("plc");
    uint32_t ne = list_edges(p, e), nflat = 0;
    if (tr_flat_edges(p, e, ne, flat) != TR_OK)
      FAIL("tr_flat_edges: %s", tr_last_error());
    for (uint32_t i = 0; i < ne; i++) {
      uint32_t a = e[2 * i], b = e[2 * i + 1];
      /* the marker border of face 0 (x = 0): the edge between z < 1 and z > 1 */
      int border = split && g.xyz[3 * a] == 0 && g.xyz[3 * b] == 0 &&
                   g.xyz[3 * a + 2] == 1 && g.xyz[3 * b + 2] == 1;
      int want = !on_box_edge(&g, a, b) && !border;
      if (flat[i] != want)
        FAIL("split %d: edge %u-%u flagged %d, want %d", split, a, b, flat[i], want);
      nflat += flat[i];
    }
    /* 6 faces x (4 inner grid edges + 4 diagonals), less the 2 on the marker border */
    if (nflat != (split ? 46u : 48u))
      FAIL("split %d: %u flat edges", split, nflat);
    tr_plc_destroy(p);
  }
  /* a segment along a flat edge makes it a feature */
  build(&g, 0, 0);
  tr_plc *p = make_plc(&g, 0);
  uint32_t ne = list_edges(p, e), k = 0;
  while (k < ne && on_box_edge(&g, e[2 * k], e[2 * k + 1]))
    k++;
  p->segs = malloc(2 * sizeof *p->segs);
  p->segs[0] = e[2 * k + 1];
  p->segs[1] = e[2 * k];
  p->nsegs = 1;
  if (tr_flat_edges(p, e, ne, flat) != TR_OK || flat[k])
    FAIL("the segment %u-%u is flagged flat", e[2 * k], e[2 * k + 1]);
  tr_plc_destroy(p);
  printf("flat edges: the inner edges of each face, not a marker border nor a segment\n");
  return 0;
}

/* Twice the area of triangle t projected along its face's axis, exactly in doubles (the
 * coordinates are small integers). */
static double area2(const grid *g, const uint32_t *t, int ax)
{
  int u = (ax + 1) % 3, v = (ax + 2) % 3;
  const double *a = g->xyz + 3 * t[0], *b = g->xyz + 3 * t[1], *c = g->xyz + 3 * t[2];
  double s = (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
  return s < 0 ? -s : s;
}

static int test_swaps(void)
{
  for (int split = 0; split < 2; split++) {
    grid g;
    build(&g, split, 0);
    tr_plc *p = make_plc(&g, split);
    struct tr_mesh *m = NULL;
    if (!p || tr_delaunay_build(p->xyz, p->npoints, &m) != TR_OK)
      FAIL("setup: %s", tr_last_error());
    uint32_t e[2 * 144];
    uint8_t there[144];
    uint32_t ne = list_edges(p, e), miss0 = 0, miss1 = 0;
    if (tr_mesh_find_edges(m, e, ne, there) != TR_OK)
      FAIL("find edges");
    for (uint32_t i = 0; i < ne; i++)
      miss0 += !there[i];
    uint64_t n = 0, n2 = 0;
    if (tr_surface_swaps_to_mesh(p, m, e, ne, &n) != TR_OK)
      FAIL("swaps: %s", tr_last_error());
    ne = list_edges(p, e);
    if (tr_surface_swaps_to_mesh(p, m, e, ne, &n2) != TR_OK)
      FAIL("swaps: %s", tr_last_error());
    if (tr_mesh_find_edges(m, e, ne, there) != TR_OK)
      FAIL("find edges");
    /* the swaps answer for the flat edges; a box edge or the marker border may still be
     * missing (edge recovery's business) */
    uint8_t flat[144];
    if (tr_flat_edges(p, e, ne, flat) != TR_OK)
      FAIL("flat: %s", tr_last_error());
    for (uint32_t i = 0; i < ne; i++)
      miss1 += !there[i] && flat[i];
    if (!split && (miss0 == 0 || n == 0))
      FAIL("the Delaunay mesh has every diagonal (%u missing, %llu swaps): nothing shown",
           miss0, (unsigned long long)n);
    if (miss1 || n2)
      FAIL("split %d: %u edges missing after %llu swaps (second call: %llu)", split, miss1,
           (unsigned long long)n, (unsigned long long)n2);
    double cover[6] = {0};
    for (uint32_t t = 0; t < 48; t++) {
      const uint32_t *T = p->tris + 3 * t;
      int f = (int)g.face[t], ax = f / 2;
      for (int k = 0; k < 3; k++)
        if (p->xyz[3 * T[k] + ax] != 2.0 * (f % 2))
          FAIL("triangle %u left face %d", t, f);
      if ((p->tri_marker ? p->tri_marker[t] : 0) != g.marker[t])
        FAIL("triangle %u changed marker", t);
      /* the marker border x = 0, z = 1 stays an edge: no triangle of face 0 crosses it */
      if (split && f == 0) {
        int lo = 0, hi = 0;
        for (int k = 0; k < 3; k++) {
          lo |= p->xyz[3 * T[k] + 2] < 1;
          hi |= p->xyz[3 * T[k] + 2] > 1;
        }
        if (lo && hi)
          FAIL("triangle %u crosses the marker border", t);
      }
      /* orientation kept: outward normal along +-ax */
      double n3[3];
      const double *a = p->xyz + 3 * T[0], *b = p->xyz + 3 * T[1], *c = p->xyz + 3 * T[2];
      n3[ax] = (b[(ax + 1) % 3] - a[(ax + 1) % 3]) * (c[(ax + 2) % 3] - a[(ax + 2) % 3]) -
               (b[(ax + 2) % 3] - a[(ax + 2) % 3]) * (c[(ax + 1) % 3] - a[(ax + 1) % 3]);
      if ((n3[ax] > 0) != (f % 2 == 1))
        FAIL("triangle %u turned inward", t);
      cover[f] += area2(&g, T, ax);
    }
    for (int f = 0; f < 6; f++)
      if (cover[f] != 8.0)
        FAIL("face %d: twice the area covered is %g, want 8", f, cover[f]);
    printf("swaps (marker split %d): %u of the input edges missing from the Delaunay mesh, "
           "%llu swaps, none missing after\n", split, miss0, (unsigned long long)n);
    tr_mesh_destroy(m);
    tr_plc_destroy(p);
  }
  return 0;
}

static int test_phases(void)
{
  grid g;
  build(&g, 0, 1);
  tr_plc *p = make_plc(&g, 0);
  struct tr_mesh *m = NULL;
  if (!p || tr_delaunay_build(p->xyz, p->npoints, &m) != TR_OK)
    FAIL("setup: %s", tr_last_error());
  uint32_t e[2 * 144];
  uint8_t flat[144];
  uint32_t ne = list_edges(p, e), nflat = 0;
  if (tr_flat_edges(p, e, ne, flat) != TR_OK)
    FAIL("flat: %s", tr_last_error());
  for (uint32_t i = 0; i < ne; i++)
    nflat += flat[i];
  mpq_t vol;
  mpq_init(vol);
  tr_edge_chains ch;
  tr_edge_recovery_stats st;
  tr_edge_recovery_opts opt = {0, 0, 0, p, 0};
  tr_status s = tr_mesh_volume6(m, vol);
  if (s == TR_OK)
    s = tr_recover_edges_ex(m, e, ne, &opt, &ch, &st);
  if (s == TR_OK)
    s = tr_check_mesh(m, TR_CHK_TOPOLOGY, vol);
  mpq_clear(vol);
  if (s != TR_OK)
    FAIL("recovery or validator: %s", tr_last_error());
  if (nflat != 48 || st.missing_edges == 0)
    FAIL("%u flat edges, %llu missing: the case shows nothing", nflat,
         (unsigned long long)st.missing_edges);
  /* every chain runs between its input edge's ends along collinear mesh edges: the walk
   * of build_chains proved it; here, that each has its two ends */
  for (uint32_t i = 0; i < ne; i++)
    if (ch.v[ch.start[i]] != e[2 * i] || ch.v[ch.start[i + 1] - 1] != e[2 * i + 1])
      FAIL("chain %u does not join %u and %u", i, e[2 * i], e[2 * i + 1]);
  printf("phases: %llu of %u edges missing after Delaunay (%u flat), recovered with %llu "
         "Steiner points, mesh valid\n", (unsigned long long)st.missing_edges, ne, nflat,
         (unsigned long long)st.points_added);
  tr_edge_chains_free(&ch);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc == 2 && !strcmp(argv[1], "flat"))
    return test_flat();
  if (argc == 2 && !strcmp(argv[1], "swaps"))
    return test_swaps();
  if (argc == 2 && !strcmp(argv[1], "phases"))
    return test_phases();
  fprintf(stderr, "usage: %s flat|swaps|phases\n", argv[0]);
  return 2;
}
