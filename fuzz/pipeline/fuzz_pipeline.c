/* libFuzzer target for the whole pipeline (issue 7): the bytes choose a PLC that is valid
 * by construction, tr_mesh_plc meshes it with the default options, and the output must
 * pass the mesh validator and the exact conformity validator. Because every generated
 * input is valid, every error status is a finding, not only TR_ERR_INTERNAL.
 *
 * Byte 0, bit 0 picks the generator:
 *  - voxels (bit 0 = 0): a union of 1-4 axis-aligned boxes (sides 1..4) on the 7x7x7
 *    grid, or (bit 1) a free voxel pattern on a 2^3 or 3^3 grid. Voxels that meet only
 *    along an edge would give an edge with four triangles (rejected as non-manifold), so
 *    such spots are filled with one of the two missing voxels (fuzz-chosen) until none
 *    is left; voxels that meet only at a corner stay (a pinched but valid surface). The
 *    boundary squares are split by fuzz-chosen diagonals, so the coplanar regions hold
 *    cocircular squares with arbitrary diagonals. The grid lines map to strictly
 *    increasing doubles per axis (integers, scaled by 2^k, rounded off + i*step, or
 *    dyadic increments): the boxes stay exactly axis-aligned while the arithmetic is
 *    stressed. Expected volume: the exact sum over the voxels; the Euler test runs when
 *    the voxel set's Euler characteristic is 1.
 *  - star (bit 0 = 1): a star-shaped polyhedron: the rays from the centre through the
 *    integer points of the surface of the cube [-n,n]^3 (n = 1, 2), radii 1..16 from the
 *    bytes, squares split by fuzz-chosen diagonals. Each triangle lies in the cone of its
 *    cube-surface triangle and the cones tile space, so the surface is closed and free
 *    of self-intersections for any radii; near-coplanar and concave spots are everywhere.
 *    Optional 1-ulp moves of the vertices keep it valid (the cones' orientation margin
 *    is far above an ulp).
 * Bit 4 of byte 0 scrambles the triangle orientations (the validator repairs them).
 *
 * Scale (issue 50): an input that ends in the four bytes '2' '^' e0 e1 is the input
 * without them, scaled by 2^e with e = (e0 + 256 e1) mod 1201 - 600, in [-600, 600] (the
 * volume too, exactly). Multiplying by a power of two is exact, so the same geometry meets
 * the code at extreme magnitudes, where double arithmetic on coordinates overflows or
 * underflows (a NaN point once reached GMP in suppression, and every statistic
 * overflowed). A trailer rather than more bits from the stream: the seeds before it
 * (none ends so) keep their meaning, the regression seeds their scale; libFuzzer's
 * comparison tracing finds the two marker bytes, and seeds with it are in the corpus.
 *
 * The mesh is asked with TR_PIPE_KEEP_EXACT, so the validators see the exact mesh even
 * when no doubles keep every tet positive (TR_FUZZ_STRICT_ROUNDING=1 makes that a
 * finding too).
 *
 * Built with TR_FUZZ_QUALITY (the target fuzz_pipeline_quality, issue 17), the first byte
 * switches quality refinement on (the rest of the bytes are read as above): the radius-
 * edge bound R in {1.414, 1.6, 2, 3} and sliver removal -O 0..3 (bits 0-3), with bit 4 a
 * volume bound of 1/40 of the bounding box, bit 5 --spacing-radii (clear:
 * --insertion-radii), bit 6 --subface-quality 1.414 (with its flat splits) and bit 7
 * --keep-edges; the same validators run on the
 * refined mesh, and with the volume bound every tet's exact volume must be at most it.
 * Bit 0 of the second byte adds --keep-surface (without --subface-quality, which it
 * refuses): the boundary must then be the input triangles with no point on them
 * (tests/suppress/keepcheck.h), and a refusal naming a Steiner point is an expected
 * outcome.
 * The point budget is 500 (a box 2^-20 thin and 96 long needs ~10^15 points for
 * R = 1.414, and the default budget would take minutes under the sanitizers): stopping at
 * it with its message is an expected outcome, any other error is a finding. Bit 1 of the
 * second byte sets refine_partial (the CLI's way): the mesh made at the budget is then
 * returned and goes through every check but the volume bound's, with no point added by
 * sliver removal after the stop.
 *
 * TR_FUZZ_DUMP=path writes the generated PLC (.off, .mesh, ...) before meshing, to turn
 * a finding into a regression file; TR_FUZZ_VERBOSE=1 prints one line per input. */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "output/round.h"
#include "pipeline/pipeline.h"
#include "tetrec.h"
#include "bitrd.h"
#ifdef TR_FUZZ_QUALITY
#include "../../tests/refine/tvolume.h"
#include "../../tests/suppress/keepcheck.h"
#endif


/* Recovery under ASan costs about 1 ms per triangle: larger surfaces are skipped so a
 * typical input stays fast and a slow one is a real finding. */
enum { MAX_TRIS = 256 };

/* ---- PLC under construction ---- */
typedef struct {
  double xyz[3 * 512];
  uint32_t np;
  uint32_t tris[3 * 4096];
  uint32_t nt;
  int scramble;
} gen;

static void add_tri(gen *g, bitrd *r, uint32_t a, uint32_t b, uint32_t c)
{
  if (g->nt == 4096)
    abort(); /* the caps below keep every surface far under this */
  uint32_t *t = g->tris + 3 * g->nt++;
  int flip = g->scramble && bits(r, 1);
  t[0] = a;
  t[1] = flip ? c : b;
  t[2] = flip ? b : c;
}

/* Quad q0..q3 counterclockwise seen from outside, split along a fuzz-chosen diagonal. */
static void add_quad(gen *g, bitrd *r, const uint32_t q[4])
{
  if (bits(r, 1)) {
    add_tri(g, r, q[0], q[1], q[2]);
    add_tri(g, r, q[0], q[2], q[3]);
  } else {
    add_tri(g, r, q[0], q[1], q[3]);
    add_tri(g, r, q[1], q[2], q[3]);
  }
}

#ifdef TR_FUZZ_QUALITY
/* the quality bytes of this input (see the top comment) */
static uint32_t quality_sel, keep_sel;

#endif

static void finding(const char *stage, tr_status st, const char *msg)
{
  fprintf(stderr, "fuzz_pipeline: FINDING at %s: %s: %s\n", stage, tr_status_name(st),
          msg && *msg ? msg : "(no message)");
  abort();
}

/* Meshes g and validates the result. vol6 NULL: the volume the surface encloses;
 * euler: also check V - E + F - T == 1 (the domain is a ball or at least has chi 1). */
static int scale_exp; /* e of the trailer, 0 without one */

static void run(const gen *g0, mpq_srcptr vol0, int euler, const char *kind)
{
  if (g0->nt > MAX_TRIS)
    return;
  /* the scale (top comment): the generated points and the volume times 2^e, exactly */
  static gen gs;
  const gen *g = g0;
  mpq_t vol6s;
  mpq_init(vol6s);
  mpq_srcptr vol6 = vol0;
  int e = scale_exp;
  if (e) {
    memcpy(&gs, g0, sizeof gs);
    for (uint32_t i = 0; i < 3 * gs.np; i++)
      gs.xyz[i] = ldexp(gs.xyz[i], e);
    g = &gs;
    if (vol0) {
      if (e > 0)
        mpq_mul_2exp(vol6s, vol0, (mp_bitcnt_t)(3 * e));
      else
        mpq_div_2exp(vol6s, vol0, (mp_bitcnt_t)(-3 * e));
      vol6 = vol6s;
    }
  }
  tr_plc *plc = NULL;
  if (tr_plc_create(&plc) != TR_OK ||
      tr_plc_set(plc, g->xyz, g->np, g->tris, g->nt, NULL) != TR_OK)
    finding("tr_plc_set", TR_ERR_NOMEM, tr_last_error());
  const char *dump = getenv("TR_FUZZ_DUMP");
  if (dump && *dump && tr_plc_write(plc, dump) != TR_OK)
    fprintf(stderr, "fuzz_pipeline: cannot write %s: %s\n", dump, tr_last_error());
  tr_options opt;
  tr_options_default(&opt);
  const char *verbose = getenv("TR_FUZZ_VERBOSE");
  opt.verbose = verbose && *verbose >= '2' ? 2 : 0;
#ifdef TR_FUZZ_QUALITY
  static const double R[4] = {1.414, 1.6, 2.0, 3.0};
  opt.quality_ratio = R[quality_sel & 3];
  opt.optimize = (int)(quality_sel >> 2 & 3);
  double vmax = 0;
  if (quality_sel >> 4 & 1) {
    double lo[3] = {g->xyz[0], g->xyz[1], g->xyz[2]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (uint32_t i = 1; i < g->np; i++)
      for (int k = 0; k < 3; k++) {
        double c = g->xyz[3 * i + (uint32_t)k];
        lo[k] = c < lo[k] ? c : lo[k];
        hi[k] = c > hi[k] ? c : hi[k];
      }
    vmax = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) / 40;
    if (!(vmax > 0) || !isfinite(vmax))
      vmax = 0;
    opt.max_volume = vmax;
  }
  opt.refine_spacing_radii = (int)(quality_sel >> 5 & 1);
  opt.quality_subface_ratio = quality_sel >> 6 & 1 ? 1.414 : 0;
  opt.keep_edges = (int)(quality_sel >> 7 & 1);
  opt.keep_surface = (int)(keep_sel & 1);
  opt.refine_partial = (int)(keep_sel >> 1 & 1);
  if (opt.keep_surface)
    opt.quality_subface_ratio = 0;
  opt.refine_budget = 500;
#endif
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats stats = {.size = sizeof stats};
  /* TR_PIPE_KEEP_EXACT: a Steiner point whose doubles cannot keep its tets positive is
   * a rounding (output) problem, not a recovery one; the exact mesh is still returned and
   * validated, and the rounding failure is a finding only with TR_FUZZ_STRICT_ROUNDING=1
   * (see below), so that one known rounding case does not hide recovery findings. */
  tr_status st = tr_mesh_plc_flags(plc, &opt, &m, &stats, &used, TR_PIPE_KEEP_EXACT);
  if (verbose && *verbose && *verbose != '0')
    fprintf(stderr,
            "fuzz_pipeline: %s at 2^%d: %u points, %u triangles -> %s, %u tets, %llu+%llu "
            "missing edges+facets, %llu+%llu Steiner, %.1f ms\n",
            kind, e, g->np, g->nt, tr_status_name(st), m ? tr_mesh_num_tets(m) : 0,
            (unsigned long long)stats.missing_edges, (unsigned long long)stats.missing_facets,
            (unsigned long long)stats.points_added_for_edges,
            (unsigned long long)stats.points_added_for_facets, 1e3 * stats.total_seconds);
#ifdef TR_FUZZ_QUALITY
  if ((st == TR_ERR_NOMEM && strstr(tr_last_error(), "point budget")) ||
      (st == TR_ERR_UNSUPPORTED && opt.keep_surface &&
       strstr(tr_last_error(), "--keep-surface: Steiner point"))) {
    tr_mesh_destroy(m);
    tr_plc_destroy(used);
    tr_plc_destroy(plc);
    mpq_clear(vol6s);
    return;
  }
#endif
  if (st != TR_OK)
    finding("tr_mesh_plc", st, tr_last_error());
  /* Scrambled orientations can give a cavity mostly facing outward, which makes it an
   * inclusion (a region of its own, src/input/nesting.c): the union's volume then no
   * longer applies, and the cell analysis of the meshed PLC measures the domain. */
  mpq_t dom;
  mpq_init(dom);
  if (vol6 && used->ninclusions) {
    if ((st = tr_input_domain_volume6(used, dom)) != TR_OK)
      finding("tr_input_domain_volume6", st, tr_last_error());
    vol6 = dom;
  }
  unsigned what = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | (euler ? TR_CHK_EULER : 0u);
  st = tr_check_mesh(m, what, vol6);
  if (st != TR_OK)
    finding("tr_check_mesh", st, tr_last_error());
  st = tr_check_conformity(m, used, vol6, 0);
  if (st != TR_OK)
    finding("tr_check_conformity (meshed PLC)", st, tr_last_error());
  if (stats.surface_swaps == 0 && stats.input_edges_merged == 0) {
    /* nothing was smoothed and refinement merged no planar facet (core/facets.h: the
     * facets are those of the meshed PLC, whose orientation the generated one may
     * scramble): the mesh conforms to the generated triangles themselves (the volume
     * comes from the meshed PLC) */
    mpq_t v;
    mpq_init(v);
    if (vol6)
      mpq_set(v, vol6);
    else if ((st = tr_input_volume6(used, v)) != TR_OK)
      finding("tr_input_volume6", st, tr_last_error());
    st = tr_check_conformity(m, plc, v, 0);
    if (st != TR_OK)
      finding("tr_check_conformity (generated PLC)", st, tr_last_error());
    mpq_clear(v);
  }
#ifdef TR_FUZZ_QUALITY
  if (opt.keep_surface) {
    char why[256];
    if (keep_surface_holds(m, used, why, sizeof why) != 0)
      finding("--keep-surface", TR_ERR_INVALID_MESH, why);
  }
  if (stats.refine_budget_reached &&
      (!opt.refine_partial || stats.points_added_for_sliver || stats.points_added_for_quality != 500)) {
    char msg[160];
    snprintf(msg, sizeof msg, "stopped at the budget of 500 with %llu refinement and %llu "
             "sliver points (refine_partial %d)",
             (unsigned long long)stats.points_added_for_quality,
             (unsigned long long)stats.points_added_for_sliver, opt.refine_partial);
    finding("refine_partial", TR_ERR_INVALID_MESH, msg);
  }
  if (vmax > 0 && !stats.refine_budget_reached) {
    uint32_t counted, over = tv_count_over(m, vmax, UINT32_MAX, &counted);
    if (over) {
      char msg[160];
      snprintf(msg, sizeof msg, "%u tets have an exact volume above the bound %.17g", over,
               vmax);
      finding("max_volume", TR_ERR_INVALID_MESH, msg);
    }
  }
#endif
  uint32_t flat = TR_NONE;
  uint64_t nflat = tr_round_count_nonpositive(m, &flat);
  const char *strict = getenv("TR_FUZZ_STRICT_ROUNDING");
  if (nflat && strict && *strict && *strict != '0') {
    char msg[160];
    snprintf(msg, sizeof msg, "%llu tets not strictly positive in doubles (first: tet %u)",
             (unsigned long long)nflat, flat);
    finding("rounding of Steiner points", TR_ERR_INVALID_MESH, msg);
  }
  mpq_clear(dom);
  mpq_clear(vol6s);
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(plc);
}

/* ---- generator 1: voxel sets ---- */
enum { G = 7 };

typedef struct {
  uint8_t occ[G][G][G];
} voxels;

static int vox(const voxels *v, int x, int y, int z)
{
  if (x < 0 || y < 0 || z < 0 || x >= G || y >= G || z >= G)
    return 0;
  return v->occ[x][y][z];
}

/* Fills the diagonal-only pairs around grid edges; returns after a pass without one. */
static void fix_edges(voxels *v, bitrd *r)
{
  for (int changed = 1; changed;) {
    changed = 0;
    for (int a = 0; a < 3; a++) {
      int u = (a + 1) % 3, w = (a + 2) % 3;
      /* the edge along axis a through grid point (.., i on u, j on w), cell index k on a */
      for (int k = 0; k < G; k++)
        for (int i = 1; i < G; i++)
          for (int j = 1; j < G; j++) {
            int c[4][3], o[4];
            for (int q = 0; q < 4; q++) {
              c[q][a] = k;
              c[q][u] = i - 1 + (q == 1 || q == 2);
              c[q][w] = j - 1 + (q >= 2);
              o[q] = vox(v, c[q][0], c[q][1], c[q][2]);
            }
            int n = o[0] + o[1] + o[2] + o[3];
            if (n != 2 || o[0] != o[2])
              continue;
            /* diagonal pair: fill one of the two empty cells */
            int fill = o[0] ? (bits(r, 1) ? 1 : 3) : (bits(r, 1) ? 0 : 2);
            v->occ[c[fill][0]][c[fill][1]][c[fill][2]] = 1;
            changed = 1;
          }
    }
  }
}

/* Euler characteristic of the closed voxel set: vertices - edges + squares - cubes. */
static long voxel_chi(const voxels *v)
{
  long chi = 0;
  for (int x = 0; x <= G; x++)
    for (int y = 0; y <= G; y++)
      for (int z = 0; z <= G; z++) {
        /* cells of dimension d with lower corner (x,y,z): the voxels around them */
        for (int mask = 0; mask < 8; mask++) {
          int dim = (mask & 1) + (mask >> 1 & 1) + (mask >> 2 & 1);
          int d[3] = {mask & 1, mask >> 1 & 1, mask >> 2 & 1};
          int in = 0;
          /* a cell is in the closure iff some voxel containing it is occupied: along a
           * spanned axis the voxel index is fixed, along the others it is x-1 or x */
          for (int s = 0; s < 8 && !in; s++) {
            int p[3] = {x, y, z};
            int ok = 1;
            for (int k = 0; k < 3; k++) {
              if (d[k]) {
                if (s >> k & 1)
                  ok = 0; /* one choice only along a spanned axis */
              } else
                p[k] -= s >> k & 1;
            }
            if (ok && vox(v, p[0], p[1], p[2]))
              in = 1;
          }
          if (in)
            chi += (dim % 2) ? -1 : 1;
        }
      }
  return chi;
}

/* Strictly increasing doubles for grid lines 0..G of one axis. */
static void axis_coords(bitrd *r, int kind, double x[G + 1])
{
  switch (kind) {
  case 1: { /* scaled by a power of two */
    double s = ldexp(1.0, (int)bits(r, 6) - 32);
    for (int i = 0; i <= G; i++)
      x[i] = i * s;
    break;
  }
  case 2: { /* rounded: off + i * step, neither exact in binary */
    double off = ((double)bits(r, 16) - 32768.0) / 10.0;
    double step = (1.0 + bits(r, 4)) / 10.0;
    for (int i = 0; i <= G; i++)
      x[i] = off + i * step;
    break;
  }
  case 3: { /* dyadic increments of different sizes, from a far offset */
    x[0] = ldexp((double)bits(r, 8), (int)bits(r, 5));
    for (int i = 1; i <= G; i++)
      x[i] = x[i - 1] + ldexp(1.0 + bits(r, 4), -(int)bits(r, 3));
    break;
  }
  default:
    for (int i = 0; i <= G; i++)
      x[i] = i;
  }
  for (int i = 0; i < G; i++)
    if (!(x[i] < x[i + 1])) {
      for (int j = 0; j <= G; j++)
        x[j] = j;
      return;
    }
}

static void gen_voxels(bitrd *r, uint32_t b0)
{
  voxels v;
  memset(&v, 0, sizeof v);
  int nvox = 0;
  if (b0 & 2) {
    int n = 2 + (int)bits(r, 1); /* free pattern on an n^3 grid */
    for (int x = 0; x < n; x++)
      for (int y = 0; y < n; y++)
        for (int z = 0; z < n; z++)
          v.occ[x][y][z] = (uint8_t)bits(r, 1);
  } else {
    int nbox = 1 + (int)bits(r, 2);
    for (int b = 0; b < nbox; b++) {
      int lo[3], hi[3];
      for (int k = 0; k < 3; k++) {
        lo[k] = (int)(bits(r, 3) % G);
        hi[k] = lo[k] + 1 + (int)bits(r, 2);
        if (hi[k] > G)
          hi[k] = G;
      }
      for (int x = lo[0]; x < hi[0]; x++)
        for (int y = lo[1]; y < hi[1]; y++)
          for (int z = lo[2]; z < hi[2]; z++)
            v.occ[x][y][z] = 1;
    }
  }
  fix_edges(&v, r);
  for (int x = 0; x < G; x++)
    for (int y = 0; y < G; y++)
      for (int z = 0; z < G; z++)
        nvox += v.occ[x][y][z];
  if (nvox == 0)
    return;
  int ckind = (int)(b0 >> 2 & 3);
  double X[3][G + 1];
  for (int k = 0; k < 3; k++)
    axis_coords(r, ckind, X[k]);

  static gen g;
  memset(&g, 0, sizeof g);
  g.scramble = (b0 >> 4) & 1;
  uint32_t id[G + 1][G + 1][G + 1];
  memset(id, 0xff, sizeof id);
  for (int a = 0; a < 3; a++) {
    int u = (a + 1) % 3, w = (a + 2) % 3;
    for (int p = 0; p <= G; p++)
      for (int i = 0; i < G; i++)
        for (int j = 0; j < G; j++) {
          int below[3], above[3];
          below[a] = p - 1;
          above[a] = p;
          below[u] = above[u] = i;
          below[w] = above[w] = j;
          int ob = vox(&v, below[0], below[1], below[2]);
          int oa = vox(&v, above[0], above[1], above[2]);
          if (ob == oa)
            continue;
          uint32_t q[4];
          for (int c = 0; c < 4; c++) {
            int gp[3];
            gp[a] = p;
            gp[u] = i + (c == 1 || c == 2);
            gp[w] = j + (c >= 2);
            uint32_t *slot = &id[gp[0]][gp[1]][gp[2]];
            if (*slot == UINT32_MAX) {
              *slot = g.np;
              for (int k = 0; k < 3; k++)
                g.xyz[3 * g.np + (uint32_t)k] = X[k][gp[k]];
              g.np++;
            }
            q[c] = *slot;
          }
          /* (u, w, a) is right-handed: q0..q3 turn counterclockwise about +a; the
           * outward normal is +a when the voxel below is the occupied one */
          if (oa) {
            uint32_t t = q[1];
            q[1] = q[3];
            q[3] = t;
          }
          add_quad(&g, r, q);
        }
  }
  mpq_t vol, dv, e;
  mpq_inits(vol, dv, e, NULL);
  for (int x = 0; x < G; x++)
    for (int y = 0; y < G; y++)
      for (int z = 0; z < G; z++) {
        if (!v.occ[x][y][z])
          continue;
        mpq_set_ui(dv, 6, 1);
        int c[3] = {x, y, z};
        for (int k = 0; k < 3; k++) {
          mpq_set_d(e, X[k][c[k] + 1]);
          mpq_t lo;
          mpq_init(lo);
          mpq_set_d(lo, X[k][c[k]]);
          mpq_sub(e, e, lo);
          mpq_clear(lo);
          mpq_mul(dv, dv, e);
        }
        mpq_add(vol, vol, dv);
      }
  run(&g, vol, voxel_chi(&v) == 1, (b0 & 2) ? "voxels" : "boxes");
  mpq_clears(vol, dv, e, NULL);
}

/* ---- generator 2: star-shaped polyhedra ---- */
static void gen_star(bitrd *r, uint32_t b0)
{
  static gen g;
  memset(&g, 0, sizeof g);
  g.scramble = (b0 >> 4) & 1;
  int n = bits(r, 2) == 3 ? 2 : 1; /* n = 3 (432 triangles) is too slow for fuzzing */
  int rkind = (int)bits(r, 2);
  int perturb = (int)bits(r, 1);
  int scale = (int)bits(r, 4) - 8;
  int c[3];
  for (int k = 0; k < 3; k++)
    c[k] = (int)bits(r, 7) - 64;
  enum { W = 7 };
  uint32_t id[W][W][W];
  memset(id, 0xff, sizeof id);
  /* vertices in a fixed order: the points of the cube surface */
  for (int x = -n; x <= n; x++)
    for (int y = -n; y <= n; y++)
      for (int z = -n; z <= n; z++) {
        if (abs(x) != n && abs(y) != n && abs(z) != n)
          continue;
        int rad;
        switch (rkind) {
        case 1: rad = 8 + (int)bits(r, 1); break;
        case 2: rad = 4 + (int)bits(r, 2); break;
        default: rad = 1 + (int)bits(r, 4);
        }
        int d[3] = {x, y, z};
        double *p = g.xyz + 3 * g.np;
        for (int k = 0; k < 3; k++)
          p[k] = ldexp((double)(c[k] + rad * d[k]), scale);
        if (perturb) {
          uint32_t how = bits(r, 3);
          int k = (int)(how % 4);
          if (k < 3 && p[k] != 0)
            p[k] = nextafter(p[k], (how & 4) ? INFINITY : -INFINITY);
        }
        id[x + n][y + n][z + n] = g.np++;
      }
  for (int a = 0; a < 3; a++) {
    int u = (a + 1) % 3, w = (a + 2) % 3;
    for (int s = -1; s <= 1; s += 2)
      for (int i = -n; i < n; i++)
        for (int j = -n; j < n; j++) {
          uint32_t q[4];
          for (int cc = 0; cc < 4; cc++) {
            int d[3];
            d[a] = s * n;
            d[u] = i + (cc == 1 || cc == 2);
            d[w] = j + (cc >= 2);
            q[cc] = id[d[0] + n][d[1] + n][d[2] + n];
          }
          if (s < 0) {
            uint32_t t = q[1];
            q[1] = q[3];
            q[3] = t;
          }
          add_quad(&g, r, q);
        }
  }
  run(&g, NULL, 1, "star");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size == 0 || size > 4096)
    return 0;
  scale_exp = 0;
  if (size >= 4 && data[size - 4] == '2' && data[size - 3] == '^') {
    scale_exp = (int)((data[size - 2] | (unsigned)data[size - 1] << 8) % 1201) - 600;
    size -= 4;
  }
  bitrd r = {data, size, 0, 0, 0};
#ifdef TR_FUZZ_QUALITY
  quality_sel = bits(&r, 8);
  keep_sel = bits(&r, 8);
#endif
  uint32_t b0 = bits(&r, 8);
  if (b0 & 1)
    gen_star(&r, b0);
  else
    gen_voxels(&r, b0);
  return 0;
}
