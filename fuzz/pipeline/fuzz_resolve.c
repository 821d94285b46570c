/* libFuzzer target for --resolve and `tetrec resolve` (issue 49 step 5; docs/resolve.md):
 * the bytes choose a soup of overlapping closed shapes on a small integer grid, and every
 * stage's result goes through a validator that does not trust it:
 *
 *  - the arrangement (tr_arrangement_build): tests/resolve/tcheck.h (the pieces of each
 *    triangle cover it exactly, no two pieces meet improperly, vertices distinct and
 *    where they say);
 *  - the solid (tr_solid_classify): TR_ERR_OPEN is an expected outcome only when some
 *    shape was given with a triangle left out (a reversed shape is closed: it subtracts); when every shape is an axis
 *    box and nothing is turned, its exact volume equals the count of unit voxels whose
 *    winding number (boxes containing it, reversed ones counting -1) is >= 1;
 *  - --resolve through the pipeline (tr_mesh_plc), rational corners included
 *    (TR_ERR_UNSUPPORTED, a limit said by name such as coordinates too large for the
 *    rays, is expected): the mesh validator and the exact conformity validator against
 *    the resolved surface, the tets' volume the solid's; an input that validation
 *    accepts (disjoint or nested shapes, some reversed) is meshed as validated: the
 *    same tets and points as without --resolve, the volume its domain's;
 *  - `tetrec resolve` (tr_resolve_snap, doubles or floats): no improper pair in the
 *    result by the all-pairs test (not the grid the rounding loop used), and the result
 *    valid for tr_plc_validate; not converging (TR_ERR_SELF_INTERSECT naming the pair)
 *    and, in floats, a corner beyond their range are expected outcomes (result NULL).
 * Any other status, a validator failure, a crash or a hang is a finding.
 *
 * Bytes: 3 bits for the number of shapes (1 to 6), then per shape 2 bits of kind (axis
 * box, tetrahedron, a box with one face's triangles on the other diagonal, a flat
 * "edge-on-edge" wedge: a tetrahedron with two opposite edges on grid lines), corners on
 * the grid [0, 4]^3, 1 bit "given twice" and 1 bit "reversed" (rare: 1 in 4 inputs may
 * reverse, so the solid is rarely empty), 1 bit "one triangle left out" (1 in 8 inputs).
 * Then 2 bits of transform (none, the rotation Rz(3/5, 4/5), Rz Rx(5/13, 12/13), an axis
 * permutation with a sign), 1 bit of internal facets, 1 bit of floats (STL). An input
 * that ends in '2' '^' e0 e1 is scaled by 2^e, e = (e0 + 256 e1) mod 1201 - 600 (as
 * fuzz_pipeline). TR_FUZZ_DUMP=path writes the soup (.off) first; TR_FUZZ_VERBOSE=1
 * prints a line per input. */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "predicates.h"
#include "resolve/resolve.h"
#include "resolve/snap.h"
#include "tetrec.h"
#include "bitrd.h"
#include "../../tests/resolve/tcheck.h"


enum { MAX_SHAPES = 6, GRID = 5 };

typedef struct {
  double xyz[3 * 8 * 2 * MAX_SHAPES];
  uint32_t np;
  uint32_t tris[3 * 12 * 2 * MAX_SHAPES];
  uint32_t nt;
  /* the voxel count: boxes only, none turned */
  int boxes_only;
  int wind[GRID * GRID * GRID];
  int may_open; /* a triangle left out or reversed: an undefined winding number is fine */
} soup;

static void finding(const char *what)
{
  fprintf(stderr, "fuzz_resolve: %s: %s\n", what, tr_last_error());
  abort();
}

static const uint32_t box_tris[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                      2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
/* the same box, each face split along its other diagonal */
static const uint32_t box_tris_alt[36] = {0, 3, 1, 0, 2, 3, 4, 5, 7, 4, 7, 6, 0, 5, 4, 0, 1, 5,
                                          2, 7, 3, 2, 6, 7, 0, 6, 2, 0, 4, 6, 1, 7, 5, 1, 3, 7};

static void add_shape(soup *s, bitrd *r, int may_reverse, int *left_out)
{
  uint32_t kind = bits(r, 2), base = s->np;
  const uint32_t *t = NULL;
  uint32_t nt = 0;
  static uint32_t tet_tris[12];
  if (kind == 0 || kind == 2) { /* an axis box [lo, lo + size] */
    uint32_t lo[3], sz[3];
    for (int d = 0; d < 3; d++) {
      lo[d] = bits(r, 2);
      sz[d] = 1 + bits(r, 1) + (lo[d] + 2 < GRID - 1 ? bits(r, 1) : 0);
      if (lo[d] + sz[d] > GRID - 1)
        sz[d] = GRID - 1 - lo[d];
    }
    for (int i = 0; i < 8; i++)
      for (int d = 0; d < 3; d++)
        s->xyz[3 * s->np + 3 * (uint32_t)i + (uint32_t)d] = (double)(lo[d] + ((i >> d) & 1) * sz[d]);
    s->np += 8;
    t = kind == 0 ? box_tris : box_tris_alt;
    nt = 12;
  } else { /* a tetrahedron; kind 3: two opposite edges on grid lines, edge on edge */
    double p[4][3];
    double det = 0;
    for (int tries = 0; det == 0; tries++) {
      for (int i = 0; i < 4; i++)
        for (int d = 0; d < 3; d++)
          p[i][d] = (double)(tries < 4 ? bits(r, 2) + (bits(r, 1) && d == 0) : (i == d + 1));
      if (kind == 3 && tries < 4) { /* (a, b) along x, (c, d) along y */
        p[1][1] = p[0][1];
        p[1][2] = p[0][2];
        p[3][0] = p[2][0];
        p[3][2] = p[2][2];
      }
      det = tr_orient3d(p[0], p[1], p[2], p[3]);
    }
    memcpy(s->xyz + 3 * s->np, p, sizeof p);
    s->np += 4;
    const uint32_t f[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    for (int i = 0; i < 4; i++) {
      tet_tris[3 * i] = f[3 * i];
      tet_tris[3 * i + 1] = f[3 * i + (det < 0 ? 2 : 1)];
      tet_tris[3 * i + 2] = f[3 * i + (det < 0 ? 1 : 2)];
    }
    t = tet_tris;
    nt = 4;
    s->boxes_only = 0;
  }
  int twice = (int)bits(r, 1);
  int rev = may_reverse && bits(r, 1);
  for (int copy = 0; copy <= twice; copy++) {
    for (uint32_t i = 0; i < nt; i++) {
      if (*left_out && i == nt - 1 && bits(r, 1)) { /* the last triangle left out */
        *left_out = 0;
        s->may_open = 1;
        continue;
      }
      uint32_t *o = s->tris + 3 * s->nt++;
      o[0] = base + t[3 * i];
      o[1] = base + t[3 * i + (rev ? 2 : 1)];
      o[2] = base + t[3 * i + (rev ? 1 : 2)];
    }
  }
  if (s->boxes_only) {
    const double *x = s->xyz + 3 * base;
    int lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
      lo[d] = (int)x[d];
      hi[d] = (int)x[21 + d]; /* corner 7 */
    }
    for (int a = lo[0]; a < hi[0]; a++)
      for (int b = lo[1]; b < hi[1]; b++)
        for (int c = lo[2]; c < hi[2]; c++)
          s->wind[(a * GRID + b) * GRID + c] += (rev ? -1 : 1) * (1 + twice);
  }
}

static void transform(soup *s, uint32_t which, int scale)
{
  /* Rz(3/5, 4/5), then Rx(5/13, 12/13) for which == 2; each product rounded */
  for (uint32_t i = 0; i < s->np; i++) {
    double *p = s->xyz + 3 * i, x = p[0], y = p[1], z = p[2];
    if (which == 1 || which == 2) {
      p[0] = 0.6 * x - 0.8 * y;
      p[1] = 0.8 * x + 0.6 * y;
      if (which == 2) {
        double y2 = p[1];
        p[1] = (5.0 / 13) * y2 - (12.0 / 13) * z;
        p[2] = (12.0 / 13) * y2 + (5.0 / 13) * z;
      }
    } else if (which == 3) { /* (x, y, z) -> (y, z, -x): a rotation, exact */
      p[0] = y;
      p[1] = z;
      p[2] = -x;
    }
    for (int d = 0; d < 3; d++)
      p[d] = ldexp(p[d], scale);
  }
  if (which)
    s->boxes_only = 0;
}

static int voxels_solid(const soup *s)
{
  int n = 0;
  for (int i = 0; i < GRID * GRID * GRID; i++)
    n += s->wind[i] >= 1;
  return n;
}

static void dump(const tr_plc *p)
{
  const char *path = getenv("TR_FUZZ_DUMP");
  if (path && tr_plc_write(p, path) != TR_OK)
    fprintf(stderr, "fuzz_resolve: TR_FUZZ_DUMP: %s\n", tr_last_error());
}

/* The arrangement and the solid: validated; *v6 = 6V; 1 iff the solid is defined and not
 * empty. */
static int solid(const soup *s, const tr_plc *p, int scale, mpq_t v6)
{
  tr_arrangement a;
  tr_solid sol;
  memset(&sol, 0, sizeof sol);
  if (tr_arrangement_build(p, &a) != TR_OK)
    finding("the arrangement failed");
  if (tc_check("fuzz", p, &a) != 0)
    finding("the arrangement validator");
  tr_status st = tr_solid_classify(p, &a, 0, &sol);
  int ok = 0;
  if (st == TR_ERR_OPEN && !s->may_open)
    finding("TR_ERR_OPEN on closed outward shapes");
  else if (st != TR_OK && st != TR_ERR_OPEN)
    finding("the solid failed");
  if (st == TR_OK && sol.nkept) {
    ok = 1;
    if (tr_solid_volume6(p, &a, &sol, v6) != TR_OK)
      finding("tr_solid_volume6");
    if (s->boxes_only) { /* the voxels, times 2^(3 scale) */
      mpq_t w;
      mpq_init(w);
      mpq_set_ui(w, 6u * (unsigned)voxels_solid(s), 1);
      if (scale >= 0)
        mpq_mul_2exp(w, w, 3u * (unsigned)scale);
      else
        mpq_div_2exp(w, w, 3u * (unsigned)-scale);
      if (!mpq_equal(w, v6)) {
        fprintf(stderr, "fuzz_resolve: 6V %.17g, voxels say %.17g\n", mpq_get_d(v6),
                mpq_get_d(w));
        abort();
      }
      mpq_clear(w);
    }
  }
  if (st == TR_OK && !sol.nkept && s->boxes_only && voxels_solid(s))
    finding("an empty solid where voxels are covered");
  tr_solid_free(&sol);
  tr_arrangement_free(&a);
  return ok;
}

/* The tets and points of m and n are the same, in the same order. */
static int same_mesh(const tr_mesh *m, const tr_mesh *n)
{
  uint32_t nt = tr_mesh_num_tets(m), nv = tr_mesh_num_vertices(m);
  return nt == tr_mesh_num_tets(n) && nv == tr_mesh_num_vertices(n) &&
         !memcmp(tr_mesh_tets(m), tr_mesh_tets(n), sizeof(uint32_t) * 4 * (size_t)nt) &&
         !memcmp(tr_mesh_points(m), tr_mesh_points(n), sizeof(double) * 3 * (size_t)nv);
}

static void mesh(const tr_plc *p, int mode, const mpq_t v6)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.resolve = mode;
  /* an input that validation accepts (its orientation repaired) is meshed as without
   * --resolve: then its domain, not the solid by winding number, is what the tets fill */
  tr_plc *copy = NULL;
  if (tr_plc_copy(p, &copy) != TR_OK)
    finding("tr_plc_copy");
  int valid = tr_plc_validate(copy, &opt) == TR_OK;
  tr_plc_destroy(copy);
  tr_error_clear();
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  /* the exact mesh: doubles that keep every tet positive may not exist at 2^-600 */
  tr_status st = tr_mesh_plc_flags(p, &opt, &m, NULL, &used, TR_PIPE_KEEP_EXACT);
  if (st == TR_ERR_UNSUPPORTED) /* a limit said by name */
    return;
  if (st != TR_OK)
    finding("tr_mesh_plc --resolve");
  if (tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL) != TR_OK)
    finding("the mesh validator");
  if (tr_check_conformity(m, used, valid ? NULL : v6, 0) != TR_OK)
    finding("exact conformity to the resolved surface");
  if (valid) {
    tr_mesh *n = NULL;
    opt.resolve = 0;
    if (tr_mesh_plc_flags(p, &opt, &n, NULL, NULL, TR_PIPE_KEEP_EXACT) != TR_OK ||
        !same_mesh(m, n))
      finding("a valid input meshed otherwise with --resolve than without");
    tr_mesh_destroy(n);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
}

static void snap(const tr_plc *p, int mode, int to_float)
{
  tr_plc *out = NULL;
  tr_snap_info si;
  tr_status st = tr_resolve_snap(p, mode, to_float, TR_SNAP_ROUNDS, &out, &si);
  if (st == TR_ERR_SELF_INTERSECT && !out) /* not converged, said */
    return;
  if (st == TR_ERR_INPUT && to_float && !out && strstr(tr_last_error(), "range of floats"))
    return; /* scaled beyond FLT_MAX: no STL can hold it */
  if (st != TR_OK || !out)
    finding("tr_resolve_snap");
  uint32_t *pairs = NULL;
  size_t np = 0;
  tr_plc *b = NULL;
  if (tr_plc_create(&b) != TR_OK ||
      tr_plc_set(b, out->xyz, out->npoints, out->tris, out->ntris - si.ninternal, NULL) != TR_OK)
    finding("copy");
  if (tr_input_self_intersection_pairs(out, TR_SELFINT_ALL_PAIRS, &pairs, &np) != TR_OK || np)
    finding("the rounded surface intersects itself");
  free(pairs);
  for (uint32_t i = 0; to_float && i < 3 * out->npoints; i++)
    if ((double)(float)out->xyz[i] != out->xyz[i])
      finding("a coordinate is no float");
  if (tr_plc_validate(b, NULL) != TR_OK)
    finding("the rounded boundary is refused by validation");
  tr_plc_destroy(b);
  tr_plc_destroy(out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size == 0 || size > 512)
    return 0;
  int scale = 0;
  if (size >= 4 && data[size - 4] == '2' && data[size - 3] == '^') {
    scale = (int)((data[size - 2] | (unsigned)data[size - 1] << 8) % 1201) - 600;
    size -= 4;
  }
  bitrd r = {data, size, 0, 0, 0};
  static soup s;
  memset(&s, 0, sizeof s);
  s.boxes_only = 1;
  int nshapes = 1 + (int)(bits(&r, 3) % MAX_SHAPES);
  int may_reverse = bits(&r, 2) == 0;
  int left_out = bits(&r, 3) == 0;
  for (int i = 0; i < nshapes; i++)
    add_shape(&s, &r, may_reverse, &left_out);
  uint32_t which = bits(&r, 2);
  int mode = 1 + (int)bits(&r, 1), to_float = (int)bits(&r, 1);
  transform(&s, which, scale);
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, s.xyz, s.np, s.tris, s.nt, NULL) != TR_OK)
    finding("tr_plc_set");
  dump(p);
  if (getenv("TR_FUZZ_VERBOSE"))
    fprintf(stderr, "fuzz_resolve: %d shapes, %u triangles, transform %u, scale 2^%d, mode %d%s\n",
            nshapes, s.nt, which, scale, mode, to_float ? ", floats" : "");
  mpq_t v6;
  mpq_init(v6);
  if (solid(&s, p, scale, v6)) {
    mesh(p, mode, v6);
    snap(p, mode, to_float);
  }
  mpq_clear(v6);
  tr_plc_destroy(p);
  return 0;
}
