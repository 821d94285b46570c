/* Unit test of the projections into a star's kernel (sup_relax, src/suppress/star.c):
 * its shortcut, which stops once the point is back, bit for bit, where it was one or two
 * steps before and takes the point the 400 steps would end on, must return exactly what
 * the 400 steps return. Checked against the plain loop written out here, on random plane
 * sets (random normals through random points, most kernels empty or thinner than the
 * margin) and on slabs thinner than twice the margin between two opposite planes (a
 * 2-cycle from the first steps), every pass's margin; the results compared bit for bit.
 * The count of runs whose plain loop revisits a point shows the shortcut was taken. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "suppress/suppress_int.h"

#include "../pipeline/texpect.h"

/* the loop as it was before the shortcut; *cycled = 1 if a point came back */
static void plain_relax(const sup_kplane *pl, size_t nf, int e, double L, const double g[3],
                        double q[3], int pass, int *cycled)
{
  double x[3], seen[401][3];
  double tau = L / (double)(8 << (3 * pass));
  int ns = 0;
  *cycled = 0;
  for (int k = 0; k < 3; k++)
    x[k] = ldexp(g[k], -e);
  memcpy(seen[ns++], x, sizeof x);
  for (int it = 0; it < 400; it++) {
    double worst = 0, wn[3] = {0, 0, 0};
    int found = 0;
    for (size_t i = 0; i < nf; i++) {
      const double *n = pl[i].n, *a = pl[i].a, len = pl[i].len;
      if (!(len > 0))
        continue;
      double d = (n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2])) / len;
      if (!found || d < worst) {
        found = 1;
        worst = d;
        for (int k = 0; k < 3; k++)
          wn[k] = n[k] / len;
      }
    }
    if (!found || worst >= tau)
      break;
    for (int k = 0; k < 3; k++)
      x[k] += (tau - worst) * wn[k];
    for (int s = ns - 1; s >= 0 && s >= ns - 2 && !*cycled; s--)
      *cycled = !memcmp(seen[s], x, sizeof x);
    memcpy(seen[ns++], x, sizeof x);
  }
  for (int k = 0; k < 3; k++)
    q[k] = ldexp(x[k], e);
}

static uint64_t rng = 0x853C49E6748FEA9Bull;
static double uni(void) /* in [-1, 1) */
{
  rng = rng * 6364136223846793005ull + 1442695040888963407ull;
  return (double)(rng >> 11) * 0x1p-52 - 1.0;
}

static void plane(sup_kplane *p, const double n[3], const double a[3])
{
  memcpy(p->n, n, sizeof p->n);
  memcpy(p->a, a, sizeof p->a);
  p->len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

static void compare(const sup_kplane *pl, size_t nf, int e, double L, const double g[3],
                    uint32_t *runs, uint32_t *cycles)
{
  for (int pass = 0; pass < SUP_RELAX_PASSES; pass++) {
    double q[3], r[3];
    int cyc = 0;
    sup_relax(pl, nf, e, L, g, q, pass);
    plain_relax(pl, nf, e, L, g, r, pass, &cyc);
    EXPECT(!memcmp(q, r, sizeof q),
           "run %u pass %d: (%.17g, %.17g, %.17g), the 400 steps end on (%.17g, %.17g, %.17g)",
           *runs, pass, q[0], q[1], q[2], r[0], r[1], r[2]);
    (*runs)++;
    *cycles += (uint32_t)cyc;
  }
}

int main(void)
{
  uint32_t runs = 0, cycles = 0;
  sup_kplane pl[12];
  for (int t = 0; t < 300; t++) {
    size_t nf = 4 + (size_t)(t % 9);
    int e = t % 3 - 1; /* the frame 2^-e of the caller */
    for (size_t i = 0; i < nf; i++) {
      double n[3] = {uni(), uni(), uni()}, a[3] = {uni(), uni(), uni()};
      plane(&pl[i], n, a);
    }
    if (t % 50 == 0)
      pl[0].len = 0; /* a face of zero length is skipped */
    double g[3] = {ldexp(uni(), e), ldexp(uni(), e), ldexp(uni(), e)};
    compare(pl, nf, e, 2.0, g, &runs, &cycles);
  }
  /* slabs 0 <= x . u <= w, w below twice each pass's margin, and a random third plane */
  for (int t = 0; t < 60; t++) {
    double u[3] = {uni(), uni(), uni()}, o[3] = {uni(), uni(), uni()}, mu[3], b[3];
    double L = 1.0, w = L / (double)(8 << (3 * (t % SUP_RELAX_PASSES))) * (0.25 + 0.01 * t);
    double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++) {
      mu[k] = -u[k];
      b[k] = o[k] + w * u[k] / len;
    }
    plane(&pl[0], u, o);
    plane(&pl[1], mu, b);
    double n2[3] = {uni(), uni(), uni()}, a2[3] = {o[0] - 2, o[1] - 2, o[2] - 2};
    plane(&pl[2], n2, a2);
    double g[3] = {uni(), uni(), uni()};
    compare(pl, 2 + (size_t)(t % 2), 0, L, g, &runs, &cycles);
  }
  fprintf(stderr, "%u runs, %u of them with a point the steps came back to\n", runs, cycles);
  EXPECT(cycles > 0, "no run came back to a point: the shortcut was never taken");
  return failures != 0;
}
