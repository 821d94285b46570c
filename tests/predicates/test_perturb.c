/* Symbolic perturbation: tr_insphere_sos and tr_orient3d_sos against the explicitly
 * perturbed determinants evaluated with exact rationals for a concrete small eps,
 * antisymmetry under permutations of (point, index) pairs, agreement with the plain
 * predicates when those are nonzero, and never-zero guarantees.
 * Usage: test_perturb <property>. */
#include "predicates.h"
#include "ref.h"

#include <stdlib.h>

static int fails;

enum { R3 = 1225 };
static int sphere[512][3], nsphere;

static void init_sphere(void)
{
  for (int x = -35; x <= 35; x++)
    for (int y = -35; y <= 35; y++)
      for (int z = -35; z <= 35; z++)
        if (x * x + y * y + z * z == R3 && nsphere < 512) {
          sphere[nsphere][0] = x;
          sphere[nsphere][1] = y;
          sphere[nsphere++][2] = z;
        }
}

/* Five cospherical integer points, sometimes with coplanar subsets, sometimes with
 * the last point moved off the sphere. */
static void gen_cospherical(rng_t *r, double p[5][3])
{
  int off[3] = {rng_int(r, -9, 9), rng_int(r, -9, 9), rng_int(r, -9, 9)};
  for (int i = 0; i < 5; i++) {
    const int *s = sphere[rng_int(r, 0, nsphere - 1)];
    if (i > 0 && rng_int(r, 0, 9) == 0) /* a repeated point forces zeros below */
      s = sphere[rng_int(r, 0, 3)];
    for (int j = 0; j < 3; j++)
      p[i][j] = s[j] + off[j];
  }
  if (rng_int(r, 0, 3) == 0) /* four coplanar: the same z */
    for (int i = 1; i < 4; i++)
      p[i][2] = p[0][2];
  if (rng_int(r, 0, 4) == 0)
    p[4][rng_int(r, 0, 2)] += 1;
}

/* distinct indices from [0, 15] */
static void gen_ids(rng_t *r, uint32_t *id, int n)
{
  for (int i = 0; i < n; i++) {
    int ok;
    do {
      id[i] = (uint32_t)rng_int(r, 0, 15);
      ok = 1;
      for (int j = 0; j < i; j++)
        ok &= id[j] != id[i];
    } while (!ok);
  }
}

/* -det[[p - e, |p - e|^2 + d_p - d_e]] (the lifted determinant of the points with
 * lifts |p|^2 + d_p, after subtracting row e and the column operations that turn
 * l_p - l_e into |p - e|^2), d_i = eps^(16 - id_i), eps = 2^-64. */
static int explicit_insphere_sos(double p[5][3], const uint32_t id[5])
{
  mpq_t m[16], x, y, out, de;
  for (int i = 0; i < 16; i++)
    mpq_init(m[i]);
  mpq_inits(x, y, out, de, NULL);
  mpq_set_ui(de, 1, 1);
  mpq_div_2exp(de, de, 64 * (16 - id[4]));
  for (int i = 0; i < 4; i++) {
    mpq_set_ui(m[4 * i + 3], 1, 1);
    mpq_div_2exp(m[4 * i + 3], m[4 * i + 3], 64 * (16 - id[i]));
    mpq_sub(m[4 * i + 3], m[4 * i + 3], de);
    for (int j = 0; j < 3; j++) {
      mpq_set_d(x, p[i][j]);
      mpq_set_d(y, p[4][j]);
      mpq_sub(m[4 * i + j], x, y);
      mpq_mul(x, m[4 * i + j], m[4 * i + j]);
      mpq_add(m[4 * i + 3], m[4 * i + 3], x);
    }
  }
  ref_det(4, m, out);
  int s = -mpq_sgn(out);
  for (int i = 0; i < 16; i++)
    mpq_clear(m[i]);
  mpq_clears(x, y, out, de, NULL);
  return s;
}

/* det[b'-a'; c'-a'; d'-a'] with coordinate j of the point of index i moved by
 * eps^(2^(3i+j)), eps = 2^-30 (indices are 0..3 here, so exponents stay below
 * 30 * 2^11 bits). */
static int explicit_orient3d_sos(double p[4][3], const uint32_t id[4])
{
  mpq_t q[4][3], m[9], out;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 3; j++) {
      mpq_init(q[i][j]);
      mpq_set_ui(q[i][j], 1, 1);
      mpq_div_2exp(q[i][j], q[i][j], 30u << (3 * id[i] + (uint32_t)j));
      mpq_t t;
      mpq_init(t);
      mpq_set_d(t, p[i][j]);
      mpq_add(q[i][j], q[i][j], t);
      mpq_clear(t);
    }
  for (int i = 0; i < 9; i++)
    mpq_init(m[i]);
  mpq_init(out);
  for (int i = 1; i < 4; i++)
    for (int j = 0; j < 3; j++)
      mpq_sub(m[3 * (i - 1) + j], q[i][j], q[0][j]);
  ref_det(3, m, out);
  int s = mpq_sgn(out);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(q[i][j]);
  for (int i = 0; i < 9; i++)
    mpq_clear(m[i]);
  mpq_clear(out);
  return s;
}

static int sos_is(double p[5][3], const uint32_t id[5])
{
  return tr_insphere_sos(p[0], p[1], p[2], p[3], p[4], id[0], id[1], id[2], id[3], id[4]);
}
static int sos_o3(double p[4][3], const uint32_t id[4])
{
  return tr_orient3d_sos(p[0], p[1], p[2], p[3], id[0], id[1], id[2], id[3]);
}

/* Random permutation of n (point, index) pairs; returns its parity. */
static int permute(rng_t *r, int n, double p[][3], uint32_t *id, double q[][3], uint32_t *qid)
{
  int perm[5] = {0, 1, 2, 3, 4}, parity = 1;
  for (int a = n - 1; a > 0; a--) {
    int b = rng_int(r, 0, a);
    if (b != a) {
      int t = perm[a];
      perm[a] = perm[b];
      perm[b] = t;
      parity = -parity;
    }
  }
  for (int a = 0; a < n; a++) {
    memcpy(q[a], p[perm[a]], sizeof q[a]);
    qid[a] = id[perm[a]];
  }
  return parity;
}

static void prop_insphere(void)
{
  rng_t r = {71};
  double p[5][3], q[5][3];
  uint32_t id[5], qid[5];
  int resolved = 0;
  for (int i = 0; i < 20000; i++) {
    gen_cospherical(&r, p);
    gen_ids(&r, id, 5);
    int s = sos_is(p, id), plain = sgn(tr_insphere(p[0], p[1], p[2], p[3], p[4]));
    CHECK(s == explicit_insphere_sos(p, id),
          "insphere_sos must equal the sign of the explicitly perturbed determinant");
    CHECK(plain == 0 || s == plain, "insphere_sos must equal insphere when that is nonzero");
    if (sgn(tr_orient3d(p[0], p[1], p[2], p[3])) != 0)
      CHECK(s != 0, "insphere_sos must not be 0 when a, b, c, d are not coplanar");
    resolved += plain == 0 && s != 0;
    int parity = permute(&r, 5, p, id, q, qid);
    CHECK(sos_is(q, qid) == parity * s,
          "insphere_sos must be antisymmetric under permutations of (point, index)");
  }
  CHECK(resolved > 5000, "too few cospherical cases were exercised (%d)", resolved);
  /* Worked examples (perturb.c): cube corners on one sphere. */
  double c[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  uint32_t i1[5] = {0, 1, 2, 3, 4}, i2[5] = {3, 2, 1, 4, 0};
  CHECK(sos_is(c, i1) == -1, "largest index last: e is lifted most, so it is outside");
  CHECK(sos_is(c, i2) == -1, "d's term vanishes (abce coplanar); a's term decides: -1");
}

static void prop_orient3d(void)
{
  rng_t r = {73};
  double p[4][3], q[4][3];
  uint32_t id[4], qid[4];
  int resolved = 0;
  for (int i = 0; i < 20000; i++) {
    /* coplanar, collinear or coincident integer points, sometimes not degenerate */
    int u[3] = {rng_int(&r, -3, 3), rng_int(&r, -3, 3), rng_int(&r, -3, 3)};
    int v[3] = {rng_int(&r, -3, 3), rng_int(&r, -3, 3), rng_int(&r, -3, 3)};
    int mode = rng_int(&r, 0, 4);
    for (int a = 0; a < 4; a++) {
      int s = rng_int(&r, -2, 2), t = mode >= 2 ? 0 : rng_int(&r, -2, 2);
      if (mode == 3)
        s = 0;
      for (int j = 0; j < 3; j++)
        p[a][j] = s * u[j] + t * v[j] + (mode == 4 ? rng_int(&r, -1, 1) : 0);
    }
    for (int a = 0; a < 4; a++) { /* a permutation of 0..3 */
      id[a] = (uint32_t)a;
    }
    for (int a = 3; a > 0; a--) {
      int b = rng_int(&r, 0, a);
      uint32_t t = id[a];
      id[a] = id[b];
      id[b] = t;
    }
    int s = sos_o3(p, id), plain = sgn(tr_orient3d(p[0], p[1], p[2], p[3]));
    if (i % 10 == 0) /* the explicit determinant has 60000-bit rationals: slow */
      CHECK(s == explicit_orient3d_sos(p, id),
            "orient3d_sos must equal the sign of the explicitly perturbed determinant");
    CHECK(s != 0, "orient3d_sos must never be 0 for distinct indices");
    CHECK(plain == 0 || s == plain, "orient3d_sos must equal orient3d when that is nonzero");
    resolved += plain == 0;
    uint32_t big[4];
    for (int a = 0; a < 4; a++)
      big[a] = 1000 + 77 * id[a];
    CHECK(sos_o3(p, big) == s, "orient3d_sos must depend only on the order of the indices");
    double t[4][3];
    for (int a = 0; a < 4; a++)
      for (int j = 0; j < 3; j++)
        t[a][j] = p[a][j] + (j + 1) * 1024.0;
    CHECK(sos_o3(t, id) == s, "orient3d_sos must be invariant under exact translation");
    int parity = permute(&r, 4, p, id, q, qid);
    CHECK(sos_o3(q, qid) == parity * s,
          "orient3d_sos must be antisymmetric under permutations of (point, index)");
  }
  CHECK(resolved > 5000, "too few degenerate cases were exercised (%d)", resolved);
  double sq[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  uint32_t i0[4] = {0, 1, 2, 3};
  CHECK(sos_o3(sq, i0) == 1, "unit square, a has the smallest index: a's z decides, +1");
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  init_sphere();
  if (!strcmp(argv[1], "insphere_sos"))
    prop_insphere();
  else if (!strcmp(argv[1], "orient3d_sos"))
    prop_orient3d();
  else
    return 2;
  if (fails)
    fprintf(stderr, "%s: %d failures\n", argv[1], fails);
  return fails ? 1 : 0;
}
