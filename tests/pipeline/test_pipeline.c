/* End-to-end tests of tr_mesh_plc on PLCs built here: every output goes through the mesh
 * validator (topology, exact orientation) and the exact conformity validator, and the
 * expected region counts, volumes and statistics are checked exactly. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "delaunay/delaunay.h"
#include "outer/color.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "smooth/smooth.h"

#include "texpect.h"
#include "trecover.h"

/* What tr_check_mesh checks; the Euler test assumes a ball (not true with a cavity). */
static unsigned chk_what = TR_CHK_TOPOLOGY;

/* ---- PLC builders ---- */
typedef struct {
  double *x;
  uint32_t np, capp;
  uint32_t *t;
  uint32_t nt, capt;
} builder;

static uint32_t pt(builder *b, double x, double y, double z)
{
  for (uint32_t i = 0; i < b->np; i++)
    if (b->x[3 * i] == x && b->x[3 * i + 1] == y && b->x[3 * i + 2] == z)
      return i;
  if (b->np == b->capp) {
    b->capp = b->capp ? 2 * b->capp : 64;
    b->x = realloc(b->x, sizeof *b->x * 3 * b->capp);
  }
  b->x[3 * b->np] = x;
  b->x[3 * b->np + 1] = y;
  b->x[3 * b->np + 2] = z;
  return b->np++;
}

static void tri(builder *b, uint32_t p, uint32_t q, uint32_t r)
{
  if (b->nt == b->capt) {
    b->capt = b->capt ? 2 * b->capt : 64;
    b->t = realloc(b->t, sizeof *b->t * 3 * b->capt);
  }
  b->t[3 * b->nt] = p;
  b->t[3 * b->nt + 1] = q;
  b->t[3 * b->nt + 2] = r;
  b->nt++;
}

/* The axis-aligned box [lo, hi] with each face split into n x n squares, 2 triangles
 * each (orientation left to tr_plc_validate). skip_face: -1, or a face (0..5 = -x +x -y
 * +y -z +z) not to emit (for boxes sharing a face). */
static void box(builder *b, const double lo[3], const double hi[3], int n, int skip_face)
{
  for (int f = 0; f < 6; f++) {
    if (f == skip_face)
      continue;
    int ax = f / 2, u = (ax + 1) % 3, v = (ax + 2) % 3;
    double c = f % 2 ? hi[ax] : lo[ax];
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++) {
        uint32_t q[4];
        for (int k = 0; k < 4; k++) {
          double p[3];
          int di = k == 1 || k == 2, dj = k >= 2;
          p[ax] = c;
          p[u] = lo[u] + (hi[u] - lo[u]) * (i + di) / n;
          p[v] = lo[v] + (hi[v] - lo[v]) * (j + dj) / n;
          q[k] = pt(b, p[0], p[1], p[2]);
        }
        tri(b, q[0], q[1], q[2]);
        tri(b, q[0], q[2], q[3]);
      }
  }
}

static tr_plc *make(builder *b)
{
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, b->x, b->np, b->t, b->nt, NULL) != TR_OK) {
    fprintf(stderr, "cannot build PLC: %s\n", tr_last_error());
    exit(1);
  }
  free(b->x);
  free(b->t);
  memset(b, 0, sizeof *b);
  return p;
}

/* Meshes plc and runs both validators; vol6 = expected 6 * volume (0: from the
 * surface); returns the number of regions, -1 on failure. */
static int run(const char *name, tr_plc *plc, int allow_open, int smooth, double vol6,
               tr_stats *st_out, uint32_t *ntets)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.allow_open = allow_open;
  opt.smooth = smooth;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  tr_status s = tr_mesh_plc_ex(plc, &opt, &m, &st, &used);
  if (s != TR_OK) {
    EXPECT(0, "%s: tr_mesh_plc failed: %s: %s", name, tr_status_name(s), tr_last_error());
    return -1;
  }
  int ret = 0;
  s = tr_check_mesh(m, chk_what, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  mpq_t v;
  mpq_init(v);
  mpq_set_d(v, vol6);
  unsigned cf = allow_open ? TR_CONF_OPEN : 0;
  s = tr_check_conformity(m, used, vol6 != 0 ? v : NULL, cf);
  EXPECT(s == TR_OK, "%s: conformity: %s", name, tr_last_error());
  if (!smooth || st.surface_swaps == 0) {
    /* nothing was swapped: the mesh must conform to the caller's own PLC too (whose
     * orientation may not be repaired: take the volume from the meshed one) */
    if (vol6 == 0)
      tr_input_domain_volume6(used, v);
    s = tr_check_conformity(m, plc, v, cf);
    EXPECT(s == TR_OK, "%s: conformity to the original PLC: %s", name, tr_last_error());
  }
  mpq_clear(v);
  uint32_t maxr = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    EXPECT(m->region && m->region[t] >= 1, "%s: tet %u has no region", name, t);
    if (m->region && m->region[t] > maxr)
      maxr = m->region[t];
  }
  EXPECT(st.volume_elements == tr_mesh_num_tets(m) && st.volume_nodes == m->nv,
         "%s: stats volume rows disagree with the mesh", name);
  EXPECT(st.total_seconds > 0 && st.peak_memory_bytes > 0, "%s: time / memory not measured",
         name);
  ret = (int)maxr;
  if (st_out)
    *st_out = st;
  if (ntets)
    *ntets = tr_mesh_num_tets(m);
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  return ret;
}

static void t_tet(void)
{
  builder b = {0};
  uint32_t a = pt(&b, 0, 0, 0), c = pt(&b, 1, 0, 0), d = pt(&b, 0, 1, 0), e = pt(&b, 0, 0, 1);
  tri(&b, a, d, c);
  tri(&b, a, c, e);
  tri(&b, a, e, d);
  tri(&b, c, d, e);
  tr_plc *p = make(&b);
  uint32_t nt = 0;
  tr_stats st = {.size = sizeof st};
  int r = run("tetrahedron", p, 0, 1, 0, &st, &nt);
  EXPECT(r == 1 && nt == 1, "tetrahedron: expected 1 region / 1 tet, got %d / %u", r, nt);
  EXPECT(st.missing_edges == 0 && st.missing_facets == 0 && st.surface_nodes == 4 &&
             st.surface_facets == 4,
         "tetrahedron: Table 14 rows wrong");
  tr_plc_destroy(p);
}

static void t_cube(int n)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  box(&b, lo, hi, n, -1);
  tr_plc *p = make(&b);
  char name[64];
  snprintf(name, sizeof name, "cube_%dx%d", n, n);
  tr_stats st = {.size = sizeof st};
  int r = run(name, p, 0, 0, 0, &st, NULL);
  EXPECT(r == 1, "%s: expected 1 region, got %d", name, r);
  EXPECT(st.surface_nodes == (uint64_t)(6 * n * n + 2), "%s: surface nodes %llu", name,
         (unsigned long long)st.surface_nodes);
  EXPECT(st.surface_swaps == 0, "%s: %llu swaps without smoothing", name,
         (unsigned long long)st.surface_swaps);
  r = run(name, p, 0, 1, 0, &st, NULL);
  EXPECT(r == 1, "%s (smoothed): expected 1 region, got %d", name, r);
  /* squares are cocircular: strict incircle never swaps them, so every swap is one
   * towards the Delaunay mesh's own diagonal, and then no edge is missing */
  EXPECT(st.missing_edges == 0 && st.points_added_for_edges == 0,
         "%s: %llu edges missing after %llu swaps towards the mesh on cocircular squares",
         name, (unsigned long long)st.missing_edges, (unsigned long long)st.surface_swaps);
  tr_plc_destroy(p);
}

/* Schoenhardt's twisted prism: no tetrahedralization without a Steiner point. */
static void t_schoenhardt(void)
{
  builder b = {0};
  /* bottom triangle, and the top one rotated by 30 degrees (exact doubles are fine:
   * every decision is exact on whatever doubles these are) */
  const double c = 0.8660254037844386; /* ~cos 30 */
  uint32_t A[3], B[3];
  A[0] = pt(&b, 1, 0, 0);
  A[1] = pt(&b, -0.5, c, 0);
  A[2] = pt(&b, -0.5, -c, 0);
  B[0] = pt(&b, c, 0.5, 1);
  B[1] = pt(&b, -c, 0.5, 1);
  B[2] = pt(&b, 0, -1, 1);
  tri(&b, A[0], A[2], A[1]);
  tri(&b, B[0], B[1], B[2]);
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3;
    /* the diagonal that makes every side reflex (the twist) */
    tri(&b, A[i], A[j], B[j]);
    tri(&b, A[i], B[j], B[i]);
  }
  tr_plc *p = make(&b);
  tr_stats st = {.size = sizeof st};
  uint32_t nt = 0;
  int r = run("schoenhardt", p, 0, 1, 0, &st, &nt);
  EXPECT(r == 1, "schoenhardt: expected 1 region, got %d", r);
  EXPECT(st.points_added_for_edges + st.points_added_for_facets >= 1,
         "schoenhardt: meshed without a Steiner point (%u tets)", nt);
  EXPECT(st.missing_edges + st.missing_facets >= 1, "schoenhardt: nothing was missing");
  tr_plc_destroy(p);
}

static void t_nested(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {4, 4, 4}, lo2[3] = {1, 1, 1}, hi2[3] = {3, 3, 3};
  box(&b, lo, hi, 1, -1);
  box(&b, lo2, hi2, 1, -1);
  tr_plc *p = make(&b);
  /* tr_plc_validate orients the inner shell into the cavity: the domain is the shell
   * between the cubes, 64 - 8, which is also what the triangles enclose */
  chk_what = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T;
  uint32_t nt = 0;
  int r = run("nested_cubes", p, 0, 1, 6.0 * 56, NULL, &nt);
  r = run("nested_cubes", p, 0, 1, 0, NULL, &nt);
  chk_what = TR_CHK_TOPOLOGY;
  EXPECT(r == 1, "nested_cubes: expected 1 region (a cavity), got %d", r);
  tr_plc_destroy(p);
}

static void t_two_boxes(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, lo2[3] = {1, 0, 0}, hi2[3] = {2, 1, 1};
  box(&b, lo, hi, 1, -1);
  box(&b, lo2, hi2, 1, 0); /* the shared face x = 1 once */
  tr_plc *p = make(&b);
  /* edges of the shared face have 3 triangles: a valid PLC without allow_open; the
   * conformity volume comes from the input's cell analysis (vol6 = 0) and must agree */
  int r = run("two_boxes_shared_face", p, 0, 1, 6.0 * 2, NULL, NULL);
  EXPECT(r == 2, "two_boxes_shared_face: expected 2 regions, got %d", r);
  r = run("two_boxes_shared_face", p, 0, 1, 0, NULL, NULL);
  EXPECT(r == 2, "two_boxes_shared_face: expected 2 regions, got %d", r);
  tr_plc_destroy(p);
}

/* Outer removal with the hints of facet recovery, without them, with hints that are
 * wrong (any slot, some past the end: tets without the face, ghosts, free slots), with
 * hints for only the first half and with the other real tet of each face: the same regions and, for every
 * sub-face, the same tet, the first real one in slot order with the face. A box with a
 * cavity and two boxes sharing a face (two regions). */
static void t_color_hints(void)
{
  for (int c = 0; c < 2; c++) {
    builder b = {0};
    double lo[3] = {0, 0, 0}, hi[3] = {4, 4, 4}, lo2[3] = {1, 1, 1}, hi2[3] = {3, 3, 3};
    double lo3[3] = {4, 0, 0}, hi3[3] = {6, 4, 4};
    box(&b, lo, hi, 2, -1);
    if (c == 0)
      box(&b, lo2, hi2, 1, -1);
    else
      box(&b, lo3, hi3, 2, 0);
    tr_plc *plc = make(&b);
    trec_run r;
    tr_status s = trec_to_recovery(plc, &r);
    EXPECT(s == TR_OK && r.sub.n > 0 && r.hint, "color_hints %d: up to recovery, with hints: %s",
           c, tr_last_error());
    if (s != TR_OK || !r.hint) {
      trec_free(&r);
      tr_plc_destroy(plc);
      continue;
    }
    struct tr_mesh *m = r.m;
    uint32_t n = r.sub.n, nt = m->nt, used = 0;
    for (uint32_t j = 0; j < n; j++)
      used += r.hint[j] < nt && tr_tet_is_real(m, r.hint[j]) &&
              tr_fcode(m, r.hint[j], r.sub.v[3 * j], r.sub.v[3 * j + 1], r.sub.v[3 * j + 2]) >= 0;
    /* most facets are faces after edge recovery; the flips for the others may take
     * away some of their faces' tets (then the hint is stale, and looked past) */
    EXPECT(2 * used > n, "color_hints %d: only %u of %u hints name a tet with the face", c,
           used, n);
    /* bad: any slot; other: the tet across the face from the hinted one, when real */
    uint32_t *bad = malloc(sizeof *bad * n), *other = malloc(sizeof *other * n), *seen[5],
             nreg[5], *reg[5];
    for (uint32_t j = 0; j < n; j++) {
      bad[j] = (uint32_t)(((uint64_t)j * 2654435761u) % (nt + 3));
      uint32_t t = r.hint[j];
      int k = t < nt && tr_tet_is_real(m, t)
                  ? tr_fcode(m, t, r.sub.v[3 * j], r.sub.v[3 * j + 1], r.sub.v[3 * j + 2])
                  : -1;
      uint32_t o = k >= 0 ? TR_NEIG(m, t, k) : TR_NONE;
      other[j] = o != TR_NONE && tr_tet_is_real(m, o) ? o : t;
    }
    for (int h = 0; h < 5; h++) {
      const uint32_t *hint = h == 1 ? NULL : h == 2 ? bad : h == 4 ? other : r.hint;
      seen[h] = malloc(sizeof *seen[h] * n);
      reg[h] = malloc(sizeof *reg[h] * nt);
      s = tr_outer_color_ex(m, &r.sub, 0, NULL, &nreg[h], seen[h], hint, h == 3 ? n / 2 : n);
      EXPECT(s == TR_OK && nreg[h] == 1u + (c == 1), "color_hints %d/%d: %u regions: %s", c, h,
             nreg[h], tr_last_error());
      memcpy(reg[h], m->region, sizeof *reg[h] * nt);
    }
    for (int h = 1; h < 5; h++) {
      int same = nreg[h] == nreg[0] && !memcmp(seen[h], seen[0], sizeof *seen[0] * n);
      for (uint32_t t = 0; t < nt; t++)
        same = same && (tr_tet_is_free(m, t) || reg[h][t] == reg[0][t]);
      EXPECT(same, "color_hints %d: hints %d give other regions or tets than the right ones",
             c, h);
    }
    for (uint32_t j = 0; j < n; j++) {
      const uint32_t *a = r.sub.v + 3 * j;
      uint32_t t = seen[0][j];
      EXPECT(t < nt && tr_tet_is_real(m, t) && tr_fcode(m, t, a[0], a[1], a[2]) >= 0,
             "color_hints %d: sub-face %u: tet %u lacks it", c, j, t);
      for (uint32_t u = 0; u < t && u < nt; u++)
        EXPECT(!tr_tet_is_real(m, u) || tr_fcode(m, u, a[0], a[1], a[2]) < 0,
               "color_hints %d: sub-face %u: real tet %u before tet %u has it", c, j, u, t);
    }
    EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL) == TR_OK,
           "color_hints %d: mesh validator: %s", c, tr_last_error());
    for (int h = 0; h < 5; h++) {
      free(seen[h]);
      free(reg[h]);
    }
    free(bad);
    free(other);
    trec_free(&r);
    tr_plc_destroy(plc);
  }
}

/* Outer removal with sub-faces listed more than once (the first and a shared one, twice
 * and three times): the same regions as with each listed once, and every copy answered
 * with the same tet, the first real one in slot order with the face. Two boxes sharing a
 * face, so the repeated faces separate two regions and the outside. */
static void t_color_repeats(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, lo2[3] = {1, 0, 0}, hi2[3] = {2, 1, 1};
  box(&b, lo, hi, 1, -1);
  box(&b, lo2, hi2, 1, 0);
  tr_plc *plc = make(&b);
  trec_run r;
  tr_status s = trec_to_recovery(plc, &r);
  struct tr_mesh *m = r.m;
  tr_subfaces sub = r.sub;
  EXPECT(s == TR_OK && sub.n > 2, "color_repeats: up to recovery: %s", tr_last_error());
  if (s != TR_OK || sub.n <= 2) {
    trec_free(&r);
    tr_plc_destroy(plc);
    return;
  }
  /* the shared face x = 1 is the one with all three vertices at x = 1 in both boxes */
  uint32_t shared = sub.n;
  for (uint32_t f = 0; f < sub.n && shared == sub.n; f++) {
    int on = 1;
    for (int i = 0; i < 3; i++)
      on &= m->xyz[3 * (size_t)sub.v[3 * f + i]] == 1.0;
    shared = on ? f : shared;
  }
  EXPECT(shared < sub.n, "color_repeats: a sub-face on the shared face");
  uint32_t extra[3] = {0, shared, shared}, n2 = sub.n + 3;
  tr_subfaces rep = {n2, malloc(sizeof(uint32_t) * 3 * n2), malloc(sizeof(uint32_t) * n2)};
  uint32_t *seen1 = malloc(sizeof *seen1 * sub.n), *seen2 = malloc(sizeof *seen2 * n2);
  uint32_t *reg1 = malloc(sizeof *reg1 * m->nt), nreg1 = 0, nreg2 = 0;
  memcpy(rep.v, sub.v, sizeof(uint32_t) * 3 * sub.n);
  memcpy(rep.tri, sub.tri, sizeof(uint32_t) * sub.n);
  for (int k = 0; k < 3; k++) {
    memcpy(rep.v + 3 * (size_t)(sub.n + k), sub.v + 3 * (size_t)extra[k], 3 * sizeof(uint32_t));
    rep.tri[sub.n + k] = sub.tri[extra[k]];
  }
  s = tr_outer_color_ex(m, &sub, 0, NULL, &nreg1, seen1, r.hint, r.hint ? sub.n : 0);
  EXPECT(s == TR_OK && nreg1 == 2, "color_repeats: once each: %u regions: %s", nreg1,
         tr_last_error());
  memcpy(reg1, m->region, sizeof *reg1 * m->nt);
  s = tr_outer_color_ex(m, &rep, 0, NULL, &nreg2, seen2, NULL, 0);
  EXPECT(s == TR_OK && nreg2 == nreg1, "color_repeats: repeated: %u regions: %s", nreg2,
         tr_last_error());
  for (uint32_t t = 0; t < m->nt; t++)
    EXPECT(tr_tet_is_free(m, t) || m->region[t] == reg1[t], "color_repeats: tet %u region %u, "
           "once each %u", t, m->region[t], reg1[t]);
  for (uint32_t f = 0; f < n2; f++) {
    uint32_t g = f < sub.n ? f : extra[f - sub.n], t = seen2[f];
    EXPECT(t == seen1[g], "color_repeats: sub-face %u: tet %u, once each %u", f, t, seen1[g]);
    for (uint32_t u = 0; u < t; u++)
      EXPECT(!tr_tet_is_real(m, u) || tr_fcode(m, u, rep.v[3 * f], rep.v[3 * f + 1],
                                              rep.v[3 * f + 2]) < 0,
             "color_repeats: sub-face %u: real tet %u before tet %u has it", f, u, t);
  }
  EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL) == TR_OK, "color_repeats: mesh validator: %s",
         tr_last_error());
  free(rep.v);
  free(rep.tri);
  free(seen1);
  free(seen2);
  free(reg1);
  trec_free(&r);
  tr_plc_destroy(plc);
}

static void t_fin(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {2, 2, 2};
  box(&b, lo, hi, 2, -1);
  /* an internal facet floating in the box, in no plane of the grid points */
  uint32_t q0 = pt(&b, 0.5, 0.5, 0.75), q1 = pt(&b, 1.5, 0.5, 0.75), q2 = pt(&b, 1.5, 1.5, 1.25),
           q3 = pt(&b, 0.5, 1.5, 1.25);
  tri(&b, q0, q1, q2);
  tri(&b, q0, q2, q3);
  tr_plc *p = make(&b);
  /* a crack strictly inside the box: valid without allow_open */
  int r = run("box_with_internal_facet", p, 0, 1, 6.0 * 8, NULL, NULL);
  EXPECT(r == 1, "box_with_internal_facet: expected 1 region, got %d", r);
  r = run("box_with_internal_facet", p, 0, 1, 0, NULL, NULL);
  EXPECT(r == 1, "box_with_internal_facet: expected 1 region, got %d", r);
  tr_plc_destroy(p);
}

/* Exact coplanar incircle against values computed with rationals (plane z = x + y,
 * where the projection onto xy does NOT preserve the incircle sign). */
static void t_incircle(void)
{
  const double A[3] = {0, 0, 0}, B[3] = {2, 0, 2}, C[3] = {0, 2, 2};
  const struct {
    double d[3];
    int inside;
  } cs[] = {{{2, 2, 4}, 0},       /* projection: on the circle */
            {{1.5, 1.5, 3}, 0},   /* projection: inside */
            {{1.75, 1.75, 3.5}, 0},
            {{2, 1, 3}, 0},
            {{1, 1, 2}, 1},
            {{2.25, 2.25, 4.5}, 0},
            {{0.5, 2.5, 3}, 0}};
  for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
    int got = tr_coplanar_incircle(A, B, C, cs[i].d);
    EXPECT(got == cs[i].inside, "coplanar incircle of (%g,%g,%g): got %d want %d", cs[i].d[0],
           cs[i].d[1], cs[i].d[2], got, cs[i].inside);
    EXPECT(tr_coplanar_incircle(B, A, C, cs[i].d) == cs[i].inside,
           "coplanar incircle depends on the triangle's orientation");
  }
}

/* A pyramid on a thin rhombus split along its long diagonal: one swap to the short one. */
static void t_smooth(void)
{
  builder b = {0};
  uint32_t A = pt(&b, 0, 0, 0), B = pt(&b, 2, -1, 0), C = pt(&b, 4, 0, 0), D = pt(&b, 2, 1, 0),
           E = pt(&b, 2, 0, 3);
  tri(&b, A, C, B);
  tri(&b, A, D, C);
  tri(&b, A, B, E);
  tri(&b, B, C, E);
  tri(&b, C, D, E);
  tri(&b, D, A, E);
  tr_plc *p = make(&b);
  EXPECT(tr_plc_validate(p, NULL) == TR_OK, "smoothing input invalid: %s", tr_last_error());
  mpq_t v0, v1;
  mpq_init(v0);
  mpq_init(v1);
  tr_input_volume6(p, v0);
  uint64_t n = 0;
  EXPECT(tr_smooth_surface(p, &n) == TR_OK && n == 1, "smoothing: %llu swaps, want 1",
         (unsigned long long)n);
  int has_bd = 0;
  for (uint32_t t = 0; t < p->ntris; t++) {
    const uint32_t *v = p->tris + 3 * t;
    int hb = v[0] == B || v[1] == B || v[2] == B, hd = v[0] == D || v[1] == D || v[2] == D;
    has_bd += hb && hd && v[0] != E && v[1] != E && v[2] != E;
  }
  EXPECT(has_bd == 2, "smoothing: the base is not split along BD");
  tr_input_volume6(p, v1);
  EXPECT(mpq_equal(v0, v1), "smoothing changed the enclosed volume");
  EXPECT(tr_smooth_surface(p, &n) == TR_OK && n == 0, "smoothing is not at a fixed point");
  EXPECT(tr_plc_validate(p, NULL) == TR_OK, "smoothed surface invalid: %s", tr_last_error());
  mpq_clear(v0);
  mpq_clear(v1);
  tr_plc_destroy(p);
  /* end to end with and without smoothing */
  b = (builder){0};
  A = pt(&b, 0, 0, 0), B = pt(&b, 2, -1, 0), C = pt(&b, 4, 0, 0), D = pt(&b, 2, 1, 0),
  E = pt(&b, 2, 0, 3);
  tri(&b, A, C, B);
  tri(&b, A, D, C);
  tri(&b, A, B, E);
  tri(&b, B, C, E);
  tri(&b, C, D, E);
  tri(&b, D, A, E);
  p = make(&b);
  tr_stats st = {.size = sizeof st};
  EXPECT(run("pyramid_smoothed", p, 0, 1, 0, &st, NULL) == 1 && st.surface_swaps == 1,
         "pyramid_smoothed: want 1 region and 1 surface swap");
  EXPECT(run("pyramid_unsmoothed", p, 0, 0, 0, &st, NULL) == 1 && st.surface_swaps == 0,
         "pyramid_unsmoothed: want 1 region and no swap");
  tr_plc_destroy(p);
}

/* Same input twice -> the same mesh, vertex for vertex and tet for tet. */
static void t_determinism(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {3, 2, 1};
  box(&b, lo, hi, 3, -1);
  tr_plc *p = make(&b);
  tr_mesh *m[2] = {NULL, NULL};
  for (int i = 0; i < 2; i++) {
    tr_options opt;
    tr_options_default(&opt);
    opt.verbose = 0;
    EXPECT(tr_mesh_plc(p, &opt, &m[i], NULL) == TR_OK, "determinism: %s", tr_last_error());
  }
  if (m[0] && m[1]) {
    EXPECT(m[0]->nv == m[1]->nv && m[0]->nt == m[1]->nt &&
               !memcmp(m[0]->xyz, m[1]->xyz, sizeof(double) * 3 * m[0]->nv) &&
               !memcmp(m[0]->tv, m[1]->tv, sizeof(uint32_t) * 4 * m[0]->nt) &&
               !memcmp(m[0]->tn, m[1]->tn, sizeof(uint32_t) * 4 * m[0]->nt),
           "determinism: two runs differ");
    /* input points first, in input order */
    for (uint32_t i = 0; i < p->npoints; i++)
      EXPECT(!memcmp(m[0]->xyz + 3 * i, p->xyz + 3 * i, 3 * sizeof(double)),
             "determinism: input point %u is not mesh vertex %u", i, i);
  }
  tr_mesh_destroy(m[0]);
  tr_mesh_destroy(m[1]);
  tr_plc_destroy(p);
}

static void t_errors(void)
{
  builder b = {0};
  uint32_t a = pt(&b, 0, 0, 0), c = pt(&b, 1, 0, 0), d = pt(&b, 0, 1, 0), e = pt(&b, 0, 0, 1);
  tri(&b, a, d, c);
  tri(&b, a, c, e);
  tri(&b, a, e, d);
  tr_plc *p = make(&b);
  tr_mesh *m = NULL;
  tr_status s = tr_mesh_plc(p, NULL, &m, NULL);
  EXPECT(s == TR_ERR_OPEN && m == NULL && strstr(tr_last_error(), "open"),
         "open surface: want TR_ERR_OPEN, got %s (%s)", tr_status_name(s), tr_last_error());
  s = tr_mesh_plc(p, NULL, NULL, NULL);
  EXPECT(s == TR_ERR_USAGE, "NULL out: want TR_ERR_USAGE, got %s", tr_status_name(s));
  tr_plc_destroy(p);
  /* an open surface with allow_open: its convex hull is meshed */
  b = (builder){0};
  a = pt(&b, 0, 0, 0), c = pt(&b, 1, 0, 0), d = pt(&b, 0, 1, 0), e = pt(&b, 0, 0, 1);
  tri(&b, a, d, c);
  tri(&b, a, c, e);
  tri(&b, a, e, d);
  p = make(&b);
  EXPECT(run("open_tetrahedron_hull", p, 1, 1, 1.0, NULL, NULL) == 1,
         "open surface with allow_open: want the hull as 1 region");
  /* validated as open (tetrec mesh validates before meshing): a closed-surface call must
   * validate again and refuse it, not trust the earlier validation */
  tr_options o;
  tr_options_default(&o);
  o.verbose = 0;
  o.allow_open = 1;
  EXPECT(tr_plc_validate(p, &o) == TR_OK, "open surface validates with allow_open");
  o.allow_open = 0;
  s = tr_mesh_plc(p, &o, &m, NULL);
  EXPECT(s == TR_ERR_OPEN && m == NULL,
         "validated with allow_open, meshed without: want TR_ERR_OPEN, got %s",
         tr_status_name(s));
  tr_plc_destroy(p);
}

/* The conformity validator is not vacuous: each kind of violation is reported. */
static void t_conform_negative(void)
{
  builder b = {0};
  double lo[3] = {0, 0, 0}, hi[3] = {2, 2, 2};
  box(&b, lo, hi, 1, -1);
  tr_plc *p1 = make(&b);
  box(&b, lo, hi, 2, -1);
  tr_plc *p2 = make(&b);
  double lo3[3] = {0, 0, 0}, hi3[3] = {2, 2, 3};
  box(&b, lo3, hi3, 1, -1);
  tr_plc *p3 = make(&b);
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  if (tr_mesh_plc_ex(p1, &opt, &m, NULL, &used) != TR_OK) {
    EXPECT(0, "conform_negative: meshing the cube failed: %s", tr_last_error());
    return;
  }
  EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_OK, "conform_negative: good mesh rejected");
  /* p2 has face-centre vertices the mesh lacks */
  EXPECT(tr_check_conformity(m, p2, NULL, 0) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "is not a mesh vertex"),
         "conform_negative: missing vertex not reported (%s)", tr_last_error());
  mpq_t v;
  mpq_init(v);
  mpq_set_ui(v, 47, 1);
  EXPECT(tr_check_conformity(m, used, v, 0) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "volume"),
         "conform_negative: wrong volume not reported (%s)", tr_last_error());
  mpq_clear(v);
  /* p3 is taller: its top corners are not in the mesh */
  EXPECT(tr_check_conformity(m, p3, NULL, 0) == TR_ERR_INVALID_MESH,
         "conform_negative: other box not reported");
  /* one tet dropped: its faces become boundary faces inside the cube */
  m->flags[0] |= TR_TF_OUTER;
  EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_ERR_INVALID_MESH,
         "conform_negative: hole in the mesh not reported");
  m->flags[0] &= (uint8_t)~TR_TF_OUTER;
  /* an inverted tet */
  uint32_t x = m->tv[0];
  m->tv[0] = m->tv[1];
  m->tv[1] = x;
  EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "not positive"),
         "conform_negative: inverted tet not reported (%s)", tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p1);
  tr_plc_destroy(p2);
  tr_plc_destroy(p3);
}

int main(int argc, char **argv)
{
  const char *w = argc > 1 ? argv[1] : "all";
  int all = !strcmp(w, "all");
  if (all || !strcmp(w, "tet"))
    t_tet();
  if (all || !strcmp(w, "cube")) {
    t_cube(1);
    t_cube(3);
  }
  if (all || !strcmp(w, "schoenhardt"))
    t_schoenhardt();
  if (all || !strcmp(w, "nested"))
    t_nested();
  if (all || !strcmp(w, "two_boxes"))
    t_two_boxes();
  if (all || !strcmp(w, "fin"))
    t_fin();
  if (all || !strcmp(w, "color_repeats"))
    t_color_repeats();
  if (all || !strcmp(w, "color_hints"))
    t_color_hints();
  if (all || !strcmp(w, "incircle"))
    t_incircle();
  if (all || !strcmp(w, "smooth"))
    t_smooth();
  if (all || !strcmp(w, "determinism"))
    t_determinism();
  if (all || !strcmp(w, "conform_negative"))
    t_conform_negative();
  if (all || !strcmp(w, "errors"))
    t_errors();
  if (failures)
    fprintf(stderr, "%d failure(s)\n", failures);
  return failures ? 1 : 0;
}
