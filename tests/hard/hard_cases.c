/* The hard cases of hard_cases.h. Surfaces are built from planar pieces in "raw"
 * coordinates (small dyadic numbers, so every raw computation is exact) and then mapped
 * by the case's transform (rotation, shift, scaling, ulp perturbation), which is where
 * rounding enters on purpose. Triangles are oriented by the raw outward normal of their
 * piece; tetrec would repair a wrong orientation, but the written files should be clean.
 * Built with -ffp-contract=off: a fused multiply-add would change the rounded
 * coordinates from one machine to the next. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hard_cases.h"

enum { XF_NONE, XF_ROTATE, XF_SHIFT_1E8, XF_SCALE_2M27, XF_SCALE_1EM8, XF_ULPS };

typedef struct {
  double *raw, *x;
  uint32_t np, capp;
  uint32_t *t;
  uint32_t nt, capt;
  uint32_t *hash; /* open addressing on the raw bits: index + 1, 0 = empty */
  uint32_t hcap;
  int xf;
  int fail;
} builder;

static uint64_t mix(uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

static uint64_t key(const double *p)
{
  uint64_t h = 0;
  for (int k = 0; k < 3; k++) {
    double v = p[k] == 0 ? 0.0 : p[k]; /* -0 and +0 are the same point */
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    h = mix(h ^ u) + (uint64_t)k;
  }
  return h;
}

/* A generic rotation: the unit quaternion (4, 1, 2, 3) / sqrt(30), as a matrix whose
 * entries are integers / 30 rounded to doubles. */
static void rotate(const double *p, double *q)
{
  const double a = 4, b = 1, c = 2, d = 3, s = 30;
  const double R[3][3] = {
      {(a * a + b * b - c * c - d * d) / s, 2 * (b * c - a * d) / s, 2 * (b * d + a * c) / s},
      {2 * (b * c + a * d) / s, (a * a - b * b + c * c - d * d) / s, 2 * (c * d - a * b) / s},
      {2 * (b * d - a * c) / s, 2 * (c * d + a * b) / s, (a * a - b * b - c * c + d * d) / s}};
  for (int i = 0; i < 3; i++)
    q[i] = R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2];
}

static void transform(const builder *b, uint32_t idx, const double *p, double *q)
{
  switch (b->xf) {
  case XF_ROTATE:
    rotate(p, q);
    return;
  case XF_SHIFT_1E8: /* exact: the raw coordinates need < 20 bits next to 2^27 */
    for (int k = 0; k < 3; k++)
      q[k] = p[k] + 1e8;
    return;
  case XF_SCALE_2M27: /* exact: a power of two */
    for (int k = 0; k < 3; k++)
      q[k] = ldexp(p[k], -27);
    return;
  case XF_SCALE_1EM8: /* rounded, but every point of a coordinate plane stays in it */
    for (int k = 0; k < 3; k++)
      q[k] = p[k] * 1e-8;
    return;
  case XF_ULPS: /* -2..+2 ulps per coordinate, a fixed pattern of the point index */
    for (int k = 0; k < 3; k++) {
      int s = (int)(mix((uint64_t)idx * 3 + (uint64_t)k + 1) % 5) - 2;
      q[k] = p[k];
      for (; s > 0; s--)
        q[k] = nextafter(q[k], INFINITY);
      for (; s < 0; s++)
        q[k] = nextafter(q[k], -INFINITY);
    }
    return;
  default:
    memcpy(q, p, 3 * sizeof *q);
  }
}

static int grow_hash(builder *b)
{
  uint32_t cap = b->hcap ? 2 * b->hcap : 1024;
  uint32_t *h = calloc(cap, sizeof *h);
  if (!h)
    return -1;
  for (uint32_t i = 0; i < b->np; i++) {
    uint32_t s = (uint32_t)(key(b->raw + 3 * (size_t)i) & (cap - 1));
    while (h[s])
      s = (s + 1) & (cap - 1);
    h[s] = i + 1;
  }
  free(b->hash);
  b->hash = h;
  b->hcap = cap;
  return 0;
}

static uint32_t pt(builder *b, double x, double y, double z)
{
  double p[3] = {x, y, z};
  if (b->fail)
    return 0;
  if (2 * (b->np + 1) > b->hcap && grow_hash(b)) {
    b->fail = 1;
    return 0;
  }
  uint32_t s = (uint32_t)(key(p) & (b->hcap - 1));
  for (; b->hash[s]; s = (s + 1) & (b->hcap - 1)) {
    const double *r = b->raw + 3 * (size_t)(b->hash[s] - 1);
    if (r[0] == x && r[1] == y && r[2] == z)
      return b->hash[s] - 1;
  }
  if (b->np == b->capp) {
    uint32_t cap = b->capp ? 2 * b->capp : 256;
    double *raw = realloc(b->raw, sizeof *raw * 3 * cap);
    if (raw)
      b->raw = raw;
    double *xx = realloc(b->x, sizeof *xx * 3 * cap);
    if (xx)
      b->x = xx;
    if (!raw || !xx) {
      b->fail = 1;
      return 0;
    }
    b->capp = cap;
  }
  memcpy(b->raw + 3 * (size_t)b->np, p, sizeof p);
  transform(b, b->np, p, b->x + 3 * (size_t)b->np);
  b->hash[s] = b->np + 1;
  return b->np++;
}

/* Triangle pqr with its right-hand normal turned towards n (raw coordinates: exact). */
static void tri(builder *b, uint32_t p, uint32_t q, uint32_t r, const double n[3])
{
  if (b->fail)
    return;
  const double *P = b->raw + 3 * (size_t)p, *Q = b->raw + 3 * (size_t)q,
               *R = b->raw + 3 * (size_t)r;
  double u[3] = {Q[0] - P[0], Q[1] - P[1], Q[2] - P[2]};
  double v[3] = {R[0] - P[0], R[1] - P[1], R[2] - P[2]};
  double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  if (c[0] * n[0] + c[1] * n[1] + c[2] * n[2] < 0) {
    uint32_t x = q;
    q = r;
    r = x;
  }
  if (b->nt == b->capt) {
    uint32_t cap = b->capt ? 2 * b->capt : 256;
    uint32_t *t = realloc(b->t, sizeof *t * 3 * cap);
    if (!t) {
      b->fail = 1;
      return;
    }
    b->t = t;
    b->capt = cap;
  }
  b->t[3 * (size_t)b->nt] = p;
  b->t[3 * (size_t)b->nt + 1] = q;
  b->t[3 * (size_t)b->nt + 2] = r;
  b->nt++;
}

/* A planar quad p0p1p2p3 (convex, in order) split along p0p2. */
static void quad(builder *b, uint32_t p0, uint32_t p1, uint32_t p2, uint32_t p3, const double n[3])
{
  tri(b, p0, p1, p2, n);
  tri(b, p0, p2, p3, n);
}

/* The grid o + (i/nu) u + (j/nv) v, each cell split by one diagonal: diag 0 always
 * p00-p11, 1 always p10-p01, 2 alternating (checkerboard). */
static void grid(builder *b, const double o[3], const double u[3], const double v[3], int nu,
                 int nv, int diag, const double n[3])
{
  uint32_t *id = malloc(sizeof *id * (size_t)(nu + 1) * (size_t)(nv + 1));
  if (!id) {
    b->fail = 1;
    return;
  }
  for (int j = 0; j <= nv; j++)
    for (int i = 0; i <= nu; i++) {
      double p[3];
      for (int k = 0; k < 3; k++)
        p[k] = o[k] + u[k] * i / nu + v[k] * j / nv;
      id[j * (nu + 1) + i] = pt(b, p[0], p[1], p[2]);
    }
  for (int j = 0; j < nv; j++)
    for (int i = 0; i < nu; i++) {
      uint32_t a = id[j * (nu + 1) + i], c = id[j * (nu + 1) + i + 1],
               d = id[(j + 1) * (nu + 1) + i + 1], e = id[(j + 1) * (nu + 1) + i];
      int dg = diag == 2 ? (i + j) & 1 : diag;
      if (dg == 0)
        quad(b, a, c, d, e, n);
      else
        quad(b, c, d, e, a, n);
    }
  free(id);
}

/* Axis-aligned box [lo, hi] with n x n grid faces; skip: bit f (0..5 = -x,+x,-y,+y,-z,+z)
 * leaves that face out. */
static void box(builder *b, const double lo[3], const double hi[3], int n, int diag, int skip)
{
  for (int f = 0; f < 6; f++) {
    if (skip >> f & 1)
      continue;
    int ax = f / 2, a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
    double o[3], u[3] = {0, 0, 0}, v[3] = {0, 0, 0}, nn[3] = {0, 0, 0};
    memcpy(o, lo, sizeof o);
    o[ax] = f & 1 ? hi[ax] : lo[ax];
    u[a1] = hi[a1] - lo[a1];
    v[a2] = hi[a2] - lo[a2];
    nn[ax] = f & 1 ? 1 : -1;
    grid(b, o, u, v, n, n, diag, nn);
  }
}

/* Reverses the triangles from `first` on: a cavity is given facing into itself (a nested
 * shell given facing outward is an inclusion, a region of its own). */
static void inward(builder *b, uint32_t first)
{
  for (uint32_t t = first; t < b->nt; t++) {
    uint32_t x = b->t[3 * (size_t)t + 1];
    b->t[3 * (size_t)t + 1] = b->t[3 * (size_t)t + 2];
    b->t[3 * (size_t)t + 2] = x;
  }
}

/* Two parallel point chains L and R (same direction) joined by triangles. */
static void zip(builder *b, const uint32_t *L, int nl, const uint32_t *R, int nr, const double n[3])
{
  if (b->fail)
    return;
  int axl = 0, axr = 0;
  const double *L0 = b->raw + 3 * (size_t)L[0], *L1 = b->raw + 3 * (size_t)L[nl - 1];
  const double *R0 = b->raw + 3 * (size_t)R[0], *R1 = b->raw + 3 * (size_t)R[nr - 1];
  for (int k = 1; k < 3; k++) {
    if (fabs(L1[k] - L0[k]) > fabs(L1[axl] - L0[axl]))
      axl = k;
    if (fabs(R1[k] - R0[k]) > fabs(R1[axr] - R0[axr]))
      axr = k;
  }
  int i = 0, j = 0;
  while (i < nl - 1 || j < nr - 1) {
    int left = j == nr - 1;
    if (!left && i < nl - 1) {
      double pl = (b->raw[3 * (size_t)L[i + 1] + axl] - L0[axl]) / (L1[axl] - L0[axl]);
      double pr = (b->raw[3 * (size_t)R[j + 1] + axr] - R0[axr]) / (R1[axr] - R0[axr]);
      left = pl <= pr;
    }
    if (left) {
      tri(b, L[i], L[i + 1], R[j], n);
      i++;
    } else {
      tri(b, L[i], R[j + 1], R[j], n);
      j++;
    }
  }
}

/* Chazelle's polyhedron: g V-grooves cut into the top parallel to x and g into the
 * bottom parallel to y, their ridges 1/32 apart in z: the region between the ridges is
 * a thin twisted slab that any tetrahedralization must cut into Omega(g^2) pieces with
 * Steiner points. Side faces are split into trapezoids at every groove vertex, so the
 * strips of the top and bottom faces carry those vertices too. */
static void chazelle(builder *b, int g)
{
  const double W = 4.0 * g, H = 4, mt = 2 + 1.0 / 64, mb = 2 - 1.0 / 64;
  int ns = 3 * g + 2;
  double *S = malloc(sizeof *S * (size_t)ns); /* 0, then each groove's 3 abscissae, W */
  uint32_t *L = malloc(sizeof *L * (size_t)ns), *R = malloc(sizeof *R * (size_t)ns);
  if (!S || !L || !R) {
    b->fail = 1;
    goto done;
  }
  S[0] = 0;
  for (int k = 0; k < g; k++)
    for (int i = 0; i < 3; i++)
      S[1 + 3 * k + i] = 4.0 * k + 1 + i;
  S[ns - 1] = W;
  const double up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
  /* top strips y in [lo, hi] between grooves; bottom strips x in [lo, hi] */
  for (int s = 0; s <= g; s++) {
    double lo = s == 0 ? 0 : 4.0 * s - 1, hi = s == g ? W : 4.0 * s + 1;
    int nl = 0, nr = 0;
    for (int i = 0; i < ns; i++) {
      if (s == 0 || i == 0 || i == ns - 1)
        L[nl++] = pt(b, S[i], lo, H);
      if (s == g || i == 0 || i == ns - 1)
        R[nr++] = pt(b, S[i], hi, H);
    }
    zip(b, L, nl, R, nr, up);
    nl = nr = 0;
    for (int i = 0; i < ns; i++) {
      if (s == 0 || i == 0 || i == ns - 1)
        L[nl++] = pt(b, lo, S[i], 0);
      if (s == g || i == 0 || i == ns - 1)
        R[nr++] = pt(b, hi, S[i], 0);
    }
    zip(b, L, nl, R, nr, down);
  }
  for (int k = 0; k < g; k++) {
    double c = 4.0 * k + 2;
    const double n1[3] = {0, 1, 1}, n2[3] = {0, -1, 1}, n3[3] = {1, 0, -1}, n4[3] = {-1, 0, -1};
    quad(b, pt(b, 0, c - 1, H), pt(b, W, c - 1, H), pt(b, W, c, mt), pt(b, 0, c, mt), n1);
    quad(b, pt(b, 0, c, mt), pt(b, W, c, mt), pt(b, W, c + 1, H), pt(b, 0, c + 1, H), n2);
    quad(b, pt(b, c - 1, 0, 0), pt(b, c - 1, W, 0), pt(b, c, W, mb), pt(b, c, 0, mb), n3);
    quad(b, pt(b, c, 0, mb), pt(b, c, W, mb), pt(b, c + 1, W, 0), pt(b, c + 1, 0, 0), n4);
  }
  for (int i = 0; i + 1 < ns; i++) {
    double a = S[i], c = S[i + 1];
    /* the middle abscissa of a groove is 2 mod 4 */
    double za = fmod(a, 4) == 2 ? mt : H, zc = fmod(c, 4) == 2 ? mt : H;
    double wa = fmod(a, 4) == 2 ? mb : 0, wc = fmod(c, 4) == 2 ? mb : 0;
    for (int side = 0; side < 2; side++) {
      double x = side ? W : 0;
      const double nx[3] = {side ? 1 : -1, 0, 0}, ny[3] = {0, side ? 1 : -1, 0};
      quad(b, pt(b, x, a, 0), pt(b, x, c, 0), pt(b, x, c, zc), pt(b, x, a, za), nx);
      quad(b, pt(b, a, x, wa), pt(b, c, x, wc), pt(b, c, x, H), pt(b, a, x, H), ny);
    }
  }
done:
  free(S);
  free(L);
  free(R);
}

/* Schoenhardt's twisted prism: the top triangle turned by about 30 degrees and every
 * side quad split by its reflex diagonal, so no tetrahedralization of the six vertices
 * exists. Coordinates are dyadic approximations of the regular ones. */
static void schoenhardt(builder *b)
{
  const double c = 0.875; /* ~ sqrt(3)/2 */
  uint32_t A[3] = {pt(b, 1, 0, 0), pt(b, -0.5, c, 0), pt(b, -0.5, -c, 0)};
  uint32_t B[3] = {pt(b, c, 0.5, 1), pt(b, -c, 0.5, 1), pt(b, 0, -1, 1)};
  const double up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
  tri(b, A[0], A[1], A[2], down);
  tri(b, B[0], B[1], B[2], up);
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3;
    const double *p = b->raw + 3 * (size_t)A[i], *q = b->raw + 3 * (size_t)A[j];
    const double n[3] = {p[0] + q[0], p[1] + q[1], 0}; /* roughly outward */
    tri(b, A[i], A[j], B[j], n);
    tri(b, A[i], B[j], B[i], n);
  }
}

/* A 1 x 1 x t slab: the top is an 8 x 8 grid, the bottom the grid of cell centres joined
 * to the boundary, so nearly every surface edge crosses the Delaunay edges of the
 * flat point set. */
static void slab(builder *b, double t)
{
  enum { N = 8 };
  const double o[3] = {0, 0, t}, u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
  const double up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
  grid(b, o, u, v, N, N, 0, up);
  uint32_t c[N][N], L[N + 1], R[N + 1], T[N + 1];
  for (int i = 0; i < N; i++)
    for (int j = 0; j < N; j++)
      c[i][j] = pt(b, (i + 0.5) / N, (j + 0.5) / N, 0);
  for (int i = 0; i + 1 < N; i++)
    for (int j = 0; j + 1 < N; j++)
      quad(b, c[i][j], c[i + 1][j], c[i + 1][j + 1], c[i][j + 1], down);
  for (int side = 0; side < 4; side++) {
    /* side 0: y = 0, 1: x = 1, 2: y = 1, 3: x = 0 */
    double n[3] = {side == 1 ? 1 : side == 3 ? -1 : 0, side == 2 ? 1 : side == 0 ? -1 : 0, 0};
    for (int i = 0; i <= N; i++) {
      double s = (double)i / N;
      double x = side == 0 || side == 2 ? s : side == 1 ? 1 : 0;
      double y = side == 1 || side == 3 ? s : side == 2 ? 1 : 0;
      L[i] = pt(b, x, y, 0);
      T[i] = pt(b, x, y, t);
      if (i < N)
        R[i] = side == 0 ? c[i][0] : side == 1 ? c[N - 1][i] : side == 2 ? c[i][N - 1] : c[0][i];
    }
    zip(b, L, N + 1, R, N, down);
    zip(b, L, N + 1, T, N + 1, n);
  }
}

enum {
  C_SCHOENHARDT,
  C_CHAZELLE2,
  C_CHAZELLE4,
  C_CHAZELLE8,
  C_GRID4,
  C_GRID16,
  C_GRID32,
  C_GRID16_ROT,
  C_SLAB3,
  C_SLAB6,
  C_SLAB9,
  C_CHAZELLE_SHIFT,
  C_CHAZELLE_SCALE,
  C_GRID_SCALE,
  C_NESTED,
  C_TWO_REGIONS,
  C_TWO_MISMATCH,
  C_CRACK,
  C_FIN,
  C_GRID_ULPS,
  C_CHAZELLE_ULPS,
  C_OPEN_BOX,
  C_CRACK_OUTSIDE,
  C_TWO_TETS_EDGE,
  C_CAVITY_CRACK,
  C_TWO_REGIONS_INV,
  C_TWO_CAVITIES,
  C_GRID_ULPS_ZERO,
  C_SLIT,
  C_COUNT
};

static const char *names[C_COUNT] = {
    "schoenhardt",          "chazelle_g2",          "chazelle_g4",
    "chazelle_g8",          "gridbox_4",            "gridbox_16",
    "gridbox_32",           "gridbox_16_rotated",   "slab_1e-3",
    "slab_1e-6",            "slab_1e-9",            "chazelle_g4_shift_1e8",
    "chazelle_g4_scale_2-27", "gridbox_8_scale_1e-8", "nested_cavity",
    "two_regions_matching", "two_regions_mismatched", "crack_inside_box",
    "fin_attached_inside",  "gridbox_8_ulps",       "chazelle_g4_ulps",
    "open_box",             "crack_outside_box",    "two_tets_sharing_an_edge",
    "cavity_and_crack",     "two_regions_inverted", "two_cavities_sharing_a_face",
    "gridbox_4_ulps_at_zero", "slit_2-20"};

int hard_case_count(void) { return C_COUNT; }
const char *hard_case_name(int i) { return i >= 0 && i < C_COUNT ? names[i] : NULL; }

int hard_case_build(int i, hard_case *c)
{
  builder b;
  memset(&b, 0, sizeof b);
  memset(c, 0, sizeof *c);
  if (i < 0 || i >= C_COUNT)
    return -1;
  c->name = names[i];
  c->status = TR_OK;
  c->regions = 1;
  c->ball = 1;
  const double z[3] = {0, 0, 0}, q4[3] = {4, 4, 4};
  switch (i) {
  case C_SCHOENHARDT:
    c->property = "schoenhardt_prism_gets_a_steiner_point_and_conforms";
    c->why = "no tetrahedralization without a Steiner point";
    c->steiner = 1;
    schoenhardt(&b);
    break;
  case C_CHAZELLE2:
  case C_CHAZELLE4:
  case C_CHAZELLE8: {
    int g = i == C_CHAZELLE2 ? 2 : i == C_CHAZELLE4 ? 4 : 8;
    c->property = g == 2 ? "chazelle_2_grooves_conforms"
                  : g == 4 ? "chazelle_4_grooves_conforms" : "chazelle_8_grooves_conforms";
    c->why = "crossing grooves 1/32 apart: Omega(g^2) Steiner points";
    chazelle(&b, g);
    break;
  }
  case C_GRID4:
  case C_GRID16:
  case C_GRID32:
  case C_GRID16_ROT:
  case C_GRID_SCALE:
  case C_GRID_ULPS: {
    int n = i == C_GRID4 ? 4 : i == C_GRID16 || i == C_GRID16_ROT ? 16 : i == C_GRID32 ? 32 : 8;
    const double hi[3] = {n, n, n};
    c->property = i == C_GRID4    ? "grid_box_4_cospherical_conforms"
                  : i == C_GRID16 ? "grid_box_16_cospherical_conforms"
                  : i == C_GRID32 ? "grid_box_32_cospherical_conforms"
                  : i == C_GRID16_ROT ? "rotated_grid_box_near_coplanar_conforms"
                  : i == C_GRID_SCALE ? "grid_box_scaled_1e-8_conforms"
                                      : "grid_box_ulp_perturbed_conforms";
    c->why = i == C_GRID16_ROT ? "rounded rotation: faces only near-planar"
             : i == C_GRID_SCALE ? "coordinates ~1e-8 (rounded scaling, faces stay planar)"
             : i == C_GRID_ULPS ? "coordinates moved by up to 2 ulps: near-degenerate everywhere"
                                : "every cell cospherical, faces coplanar";
    b.xf = i == C_GRID16_ROT ? XF_ROTATE : i == C_GRID_SCALE ? XF_SCALE_1EM8
           : i == C_GRID_ULPS ? XF_ULPS : XF_NONE;
    if (i == C_GRID_ULPS) { /* away from 0: an ulp of 0 is a subnormal */
      const double lo1[3] = {1, 1, 1}, hi1[3] = {9, 9, 9};
      box(&b, lo1, hi1, n, 2, 0);
    } else
      box(&b, z, hi, n, i == C_GRID4 ? 0 : 2, 0);
    if (b.xf == XF_NONE)
      c->vol6 = 6.0 * n * n * n;
    break;
  }
  case C_SLAB3:
  case C_SLAB6:
  case C_SLAB9: {
    double t = i == C_SLAB3 ? 1e-3 : i == C_SLAB6 ? 1e-6 : 1e-9;
    c->property = i == C_SLAB3 ? "thin_slab_1e-3_conforms"
                  : i == C_SLAB6 ? "thin_slab_1e-6_conforms" : "thin_slab_1e-9_conforms";
    c->why = "flat: top and bottom triangulations cross the Delaunay edges";
    slab(&b, t);
    break;
  }
  case C_CHAZELLE_SHIFT:
  case C_CHAZELLE_SCALE:
  case C_CHAZELLE_ULPS:
    c->property = i == C_CHAZELLE_SHIFT ? "chazelle_translated_1e8_conforms"
                  : i == C_CHAZELLE_SCALE ? "chazelle_scaled_2-27_conforms"
                                          : "chazelle_ulp_perturbed_conforms";
    c->why = i == C_CHAZELLE_SHIFT ? "exact shift by 1e8: 33-bit coordinates, tiny features"
             : i == C_CHAZELLE_SCALE ? "exact scaling by 2^-27 (~7.5e-9)"
                                     : "grooves moved by up to 2 ulps per coordinate";
    b.xf = i == C_CHAZELLE_SHIFT ? XF_SHIFT_1E8 : i == C_CHAZELLE_SCALE ? XF_SCALE_2M27 : XF_ULPS;
    chazelle(&b, 4);
    break;
  case C_NESTED: {
    const double hi[3] = {16, 16, 16}, lo2[3] = {6, 6, 6}, hi2[3] = {11, 11, 11};
    c->property = "nested_box_is_a_cavity_with_mismatched_grids";
    c->why = "16x16 outer faces, 5x5 inner faces, the inner box a cavity";
    c->ball = 0;
    box(&b, z, hi, 16, 2, 0);
    uint32_t first = b.nt;
    box(&b, lo2, hi2, 5, 0, 0);
    inward(&b, first);
    c->vol6 = 6.0 * (16 * 16 * 16 - 5 * 5 * 5);
    break;
  }
  case C_TWO_REGIONS:
  case C_TWO_MISMATCH: {
    const double lo1[3] = {0, 0, 0}, hi1[3] = {2, 2, 2}, lo2[3] = {2, 0, 0}, hi2[3] = {4, 2, 2};
    box(&b, lo1, hi1, 2, 0, 0);
    /* box 2 without its -x face (the shared square) or with it split the other way */
    box(&b, lo2, hi2, 2, 0, 1);
    if (i == C_TWO_MISMATCH) {
      const double o[3] = {2, 0, 0}, u[3] = {0, 2, 0}, v[3] = {0, 0, 2}, n[3] = {-1, 0, 0};
      grid(&b, o, u, v, 2, 2, 1, n);
      c->property = "overlapping_shared_face_is_rejected_naming_triangles";
      c->why = "the shared square triangulated differently on each side: overlapping triangles";
      c->status = TR_ERR_SELF_INTERSECT;
    } else {
      c->property = "two_boxes_sharing_a_face_are_two_regions_without_allow_open";
      c->why = "internal facet: its edges have 3 triangles";
      c->regions = 2;
      c->vol6 = 6.0 * 16;
    }
    break;
  }
  case C_CRACK:
  case C_FIN:
  case C_CRACK_OUTSIDE: {
    box(&b, z, q4, 4, 0, 0);
    const double up[3] = {0, 0, 1}, side[3] = {0, 1, 0};
    if (i == C_CRACK) {
      const double o[3] = {1, 1, 2}, u[3] = {2, 0, 0}, v[3] = {0, 2, 0};
      grid(&b, o, u, v, 2, 2, 0, up);
      c->property = "crack_inside_a_box_is_accepted_and_conforms";
      c->why = "a dangling square strictly inside: open edges inside the domain";
      c->vol6 = 6.0 * 64;
    } else if (i == C_FIN) {
      const double o[3] = {0, 2, 1}, u[3] = {2, 0, 0}, v[3] = {0, 0, 2};
      grid(&b, o, u, v, 2, 2, 0, side);
      c->property = "fin_on_an_inner_wall_is_accepted_and_conforms";
      c->why = "a square glued to a wall along two grid edges (3 triangles each), free inside";
      c->vol6 = 6.0 * 64;
    } else {
      const double o[3] = {5, 1, 2}, u[3] = {2, 0, 0}, v[3] = {0, 2, 0};
      grid(&b, o, u, v, 2, 2, 0, up);
      c->property = "dangling_square_outside_is_rejected_as_open";
      c->why = "a dangling square outside every closed shell encloses nothing";
      c->status = TR_ERR_OPEN;
    }
    break;
  }
  case C_TWO_TETS_EDGE: {
    /* edge (0,1) has four triangles, in two coplanar pairs */
    uint32_t o = pt(&b, 0, 0, 0), x = pt(&b, 1, 0, 0), y = pt(&b, 0, 1, 0), zz = pt(&b, 0, 0, 1);
    uint32_t y2 = pt(&b, 0, -1, 0), z2 = pt(&b, 0, 0, -1);
    const double nx[3] = {-1, 0, 0}, ny[3] = {0, -1, 0}, nz[3] = {0, 0, -1}, nd[3] = {1, 1, 1};
    const double py[3] = {0, 1, 0}, pz[3] = {0, 0, 1}, pd[3] = {1, -1, -1};
    tri(&b, o, x, y, nz);
    tri(&b, o, x, zz, ny);
    tri(&b, o, y, zz, nx);
    tri(&b, x, y, zz, nd);
    tri(&b, o, x, y2, pz);
    tri(&b, o, x, z2, py);
    tri(&b, o, y2, z2, nx);
    tri(&b, x, y2, z2, pd);
    c->property = "two_tets_sharing_only_an_edge_are_two_regions";
    c->why = "an edge of four triangles in two coplanar pairs";
    c->regions = 2;
    c->ball = 0;
    c->vol6 = 2;
    break;
  }
  case C_CAVITY_CRACK: {
    const double hi[3] = {8, 8, 8}, lo2[3] = {2, 2, 2}, hi2[3] = {4, 4, 4};
    const double o[3] = {3, 3, 6}, u[3] = {2, 0, 0}, v[3] = {0, 2, 0}, up[3] = {0, 0, 1};
    box(&b, z, hi, 8, 2, 0);
    uint32_t first = b.nt;
    box(&b, lo2, hi2, 2, 0, 0);
    inward(&b, first);
    grid(&b, o, u, v, 2, 2, 0, up);
    c->property = "cavity_and_crack_in_one_box_give_one_region";
    c->why = "a crack sends the input to the cell analysis, which must find the cavity too";
    c->ball = 0;
    c->vol6 = 6.0 * (8 * 8 * 8 - 2 * 2 * 2);
    break;
  }
  case C_TWO_REGIONS_INV: {
    const double lo1[3] = {0, 0, 0}, hi1[3] = {2, 2, 2}, lo2[3] = {2, 0, 0}, hi2[3] = {4, 2, 2};
    box(&b, lo1, hi1, 2, 2, 0);
    box(&b, lo2, hi2, 2, 2, 1);
    for (uint32_t t = 0; t < b.nt; t++) { /* every triangle facing inward */
      uint32_t x = b.t[3 * (size_t)t + 1];
      b.t[3 * (size_t)t + 1] = b.t[3 * (size_t)t + 2];
      b.t[3 * (size_t)t + 2] = x;
    }
    c->property = "inward_two_regions_are_reoriented_and_conform";
    c->why = "every triangle inward: orientation repair across edges of 3 triangles";
    c->regions = 2;
    c->vol6 = 6.0 * 16;
    break;
  }
  case C_TWO_CAVITIES: {
    const double hi[3] = {8, 8, 8}, lo1[3] = {2, 2, 2}, hi1[3] = {4, 4, 4}, lo2[3] = {4, 2, 2},
                 hi2[3] = {6, 4, 4};
    box(&b, z, hi, 8, 2, 0);
    uint32_t first = b.nt;
    box(&b, lo1, hi1, 2, 0, 0);
    box(&b, lo2, hi2, 2, 0, 1); /* the shared square once */
    inward(&b, first);
    c->property = "two_cavities_sharing_a_face_stay_empty";
    c->why = "an internal facet between two holes: neither side is in the domain";
    c->ball = 0;
    c->vol6 = 6.0 * (8 * 8 * 8 - 16);
    break;
  }
  case C_GRID_ULPS_ZERO:
    /* an ulp of 0 is the smallest subnormal: coordinates 0, +-4.9e-324, +-9.9e-324 */
    b.xf = XF_ULPS;
    box(&b, z, q4, 4, 2, 0);
    c->property = "grid_box_with_subnormal_coordinates_conforms";
    c->why = "coordinates 0 moved by 1-2 ulps become subnormal";
    break;
  case C_SLIT: {
    /* The U-shaped section (x, z) extruded along y over [0, 4]: a box with a slot
     * 2w = 2^-19 wide and 2 deep cut across its top. The slot's walls face each other
     * 2^-19 apart: the cells between them are flat cospherical boxes whose Delaunay tets
     * need not hold the walls' diagonals. All coordinates dyadic: the raw points are
     * exact. */
    const double w = 0x1p-20;
    const double P[8][2] = {{0, 0}, {4, 0}, {4, 4}, {2 + w, 4}, {2 + w, 2}, {2 - w, 2},
                            {2 - w, 4}, {0, 4}}; /* counterclockwise in (x, z) */
    for (int e = 0; e < 8; e++) {
      const double *a = P[e], *d = P[(e + 1) % 8];
      const double o[3] = {a[0], 0, a[1]}, u[3] = {0, 4, 0}, v[3] = {d[0] - a[0], 0, d[1] - a[1]};
      const double n[3] = {d[1] - a[1], 0, a[0] - d[0]}; /* outward for a ccw section */
      grid(&b, o, u, v, 8, 1, 2, n);
    }
    for (int end = 0; end < 2; end++) {
      double y = end ? 4 : 0;
      const double n[3] = {0, end ? 1 : -1, 0};
      uint32_t q[8];
      for (int k = 0; k < 8; k++)
        q[k] = pt(&b, P[k][0], y, P[k][1]);
      /* the part right of the slot as a fan from its reflex corner (2+w, 2), the strip
       * under the slot, and the convex part left of it */
      tri(&b, q[4], q[0], q[1], n);
      tri(&b, q[4], q[1], q[2], n);
      tri(&b, q[4], q[2], q[3], n);
      tri(&b, q[0], q[4], q[5], n);
      quad(&b, q[0], q[5], q[6], q[7], n);
    }
    c->property = "slit_2-19_wide_across_a_box_conforms";
    c->why = "two walls 2^-19 apart facing each other across a slot";
    c->vol6 = 6.0 * (64 - 16 * w);
    break;
  }
  case C_OPEN_BOX:
    box(&b, z, q4, 4, 0, 1 << 5);
    c->property = "box_without_a_face_is_rejected_as_open";
    c->why = "an open surface encloses nothing";
    c->status = TR_ERR_OPEN;
    break;
  }
  free(b.raw);
  free(b.hash);
  if (b.fail) {
    free(b.x);
    free(b.t);
    return -1;
  }
  c->xyz = b.x;
  c->np = b.np;
  c->tris = b.t;
  c->nt = b.nt;
  return 0;
}

void hard_case_free(hard_case *c)
{
  free(c->xyz);
  free(c->tris);
  c->xyz = NULL;
  c->tris = NULL;
}

int hard_case_write_off(const hard_case *c, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return -1;
  fprintf(f, "OFF\n# tetrec hard case %s: %s\n%u %u 0\n", c->name, c->why, c->np, c->nt);
  for (uint32_t i = 0; i < c->np; i++)
    fprintf(f, "%.17g %.17g %.17g\n", c->xyz[3 * (size_t)i], c->xyz[3 * (size_t)i + 1],
            c->xyz[3 * (size_t)i + 2]);
  for (uint32_t t = 0; t < c->nt; t++)
    fprintf(f, "3 %u %u %u\n", c->tris[3 * (size_t)t], c->tris[3 * (size_t)t + 1],
            c->tris[3 * (size_t)t + 2]);
  int bad = ferror(f);
  return fclose(f) == 0 && !bad ? 0 : -1;
}
