// Predicate peer benchmark: tetrec's tr_orient3d / tr_insphere against CGAL Epick's
// filtered Orientation_3 / Side_of_oriented_sphere_3 (called through the kernel
// functors on Point_3 built once), on the same inputs:
//   random:     uniform in [0,1)^3 (the floating filter decides);
//   degenerate: integer points exactly on common planes / spheres (the determinant is
//               0, so both libraries run their exact stage).
// Every query's sign is compared between the two libraries first (untimed); the timed
// loops accumulate a checksum of signs so nothing is optimised away.
// Usage: bench_predicates [queries (default 2000000)] [repeats (default 5)]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "predicates.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

namespace {

struct Rng {
  uint64_t s;
  uint64_t next()
  {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return (double)(next() >> 11) * 0x1p-53; }
  int range(int lo, int hi) { return lo + (int)(next() % (uint64_t)(hi - lo + 1)); }
};

// A query uses np consecutive entries of a point list.
struct Input {
  std::vector<double> xyz;  // 3 per point
  std::vector<Point> pts;   // the same points as CGAL objects
  void add(double x, double y, double z)
  {
    xyz.push_back(x);
    xyz.push_back(y);
    xyz.push_back(z);
    pts.push_back(Point(x, y, z));
  }
};

Input make_random(int nq, int np, uint64_t seed)
{
  Rng r{seed};
  Input in;
  for (int i = 0; i < nq * np; i++) {
    double x = r.unit(), y = r.unit(), z = r.unit();
    in.add(x, y, z);
  }
  return in;
}

// Coplanar quadruples: o + s u + t v with small integers.
Input make_coplanar(int nq, uint64_t seed)
{
  Rng r{seed};
  Input in;
  for (int q = 0; q < nq; q++) {
    int o[3], u[3], v[3];
    for (int j = 0; j < 3; j++) {
      o[j] = r.range(-100, 100);
      u[j] = r.range(-9, 9);
      v[j] = r.range(-9, 9);
    }
    for (int i = 0; i < 4; i++) {
      int s = r.range(-20, 20), t = r.range(-20, 20);
      in.add(o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1], o[2] + s * u[2] + t * v[2]);
    }
  }
  return in;
}

// Cospherical quintuples: integer points of x^2+y^2+z^2 = 1225 around an integer
// center.
Input make_cospherical(int nq, uint64_t seed)
{
  std::vector<int> sph;
  for (int x = -35; x <= 35; x++)
    for (int y = -35; y <= 35; y++)
      for (int z = -35; z <= 35; z++)
        if (x * x + y * y + z * z == 1225) {
          sph.push_back(x);
          sph.push_back(y);
          sph.push_back(z);
        }
  const int ns = (int)sph.size() / 3;
  Rng r{seed};
  Input in;
  for (int q = 0; q < nq; q++) {
    int c[3] = {r.range(-100, 100), r.range(-100, 100), r.range(-100, 100)};
    for (int i = 0; i < 5; i++) {
      int k = r.range(0, ns - 1);
      in.add(c[0] + sph[3 * k], c[1] + sph[3 * k + 1], c[2] + sph[3 * k + 2]);
    }
  }
  return in;
}

int sgn(double x) { return (x > 0) - (x < 0); }

template <class F>
double time_ns(int nq, int reps, F f, long *checksum)
{
  double best = 1e300;
  for (int rep = 0; rep < reps; rep++) {
    auto t0 = std::chrono::steady_clock::now();
    long c = f();
    auto t1 = std::chrono::steady_clock::now();
    *checksum = c;
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / nq);
  }
  return best;
}

int run_orient(const char *label, const Input &in, int nq, int reps)
{
  K::Orientation_3 orient = K().orientation_3_object();
  const double *p = in.xyz.data();
  const Point *P = in.pts.data();
  for (int q = 0; q < nq; q++) {
    const double *a = p + 12 * q;
    int s = sgn(tr_orient3d(a, a + 3, a + 6, a + 9));
    int c = (int)orient(P[4 * q], P[4 * q + 1], P[4 * q + 2], P[4 * q + 3]);
    if (s != c) {
      std::fprintf(stderr, "orient3d %s query %d: tetrec %d, CGAL %d\n", label, q, s, c);
      return 1;
    }
  }
  long ct = 0, cc = 0;
  double tt = time_ns(nq, reps, [&] {
    long sum = 0;
    for (int q = 0; q < nq; q++) {
      const double *a = p + 12 * q;
      sum += sgn(tr_orient3d(a, a + 3, a + 6, a + 9)) * (q % 7 + 1);
    }
    return sum;
  }, &ct);
  double tc = time_ns(nq, reps, [&] {
    long sum = 0;
    for (int q = 0; q < nq; q++)
      sum += (int)orient(P[4 * q], P[4 * q + 1], P[4 * q + 2], P[4 * q + 3]) * (q % 7 + 1);
    return sum;
  }, &cc);
  std::printf("orient3d %s: tetrec %.2f ns, CGAL %.2f ns, ratio %.3f (checksums %ld %ld)\n",
              label, tt, tc, tt / tc, ct, cc);
  return ct != cc;
}

int run_insphere(const char *label, const Input &in, int nq, int reps)
{
  K::Side_of_oriented_sphere_3 side = K().side_of_oriented_sphere_3_object();
  const double *p = in.xyz.data();
  const Point *P = in.pts.data();
  for (int q = 0; q < nq; q++) {
    const double *a = p + 15 * q;
    int s = sgn(tr_insphere(a, a + 3, a + 6, a + 9, a + 12));
    int c = (int)side(P[5 * q], P[5 * q + 1], P[5 * q + 2], P[5 * q + 3], P[5 * q + 4]);
    if (s != c) {
      std::fprintf(stderr, "insphere %s query %d: tetrec %d, CGAL %d\n", label, q, s, c);
      return 1;
    }
  }
  long ct = 0, cc = 0;
  double tt = time_ns(nq, reps, [&] {
    long sum = 0;
    for (int q = 0; q < nq; q++) {
      const double *a = p + 15 * q;
      sum += sgn(tr_insphere(a, a + 3, a + 6, a + 9, a + 12)) * (q % 7 + 1);
    }
    return sum;
  }, &ct);
  double tc = time_ns(nq, reps, [&] {
    long sum = 0;
    for (int q = 0; q < nq; q++)
      sum += (int)side(P[5 * q], P[5 * q + 1], P[5 * q + 2], P[5 * q + 3], P[5 * q + 4]) *
             (q % 7 + 1);
    return sum;
  }, &cc);
  std::printf("insphere %s: tetrec %.2f ns, CGAL %.2f ns, ratio %.3f (checksums %ld %ld)\n",
              label, tt, tc, tt / tc, ct, cc);
  return ct != cc;
}

}  // namespace

int main(int argc, char **argv)
{
  int nq = argc > 1 ? std::atoi(argv[1]) : 2000000;
  int reps = argc > 2 ? std::atoi(argv[2]) : 5;
  if (nq < 1 || reps < 1) {
    std::fprintf(stderr, "usage: bench_predicates [queries] [repeats]\n");
    return 2;
  }
  // The exact stages are much slower than the filters: fewer degenerate queries keep
  // the run short without changing the per-call figures.
  int nd = std::max(1, nq / 10);
  int bad = 0;
  bad |= run_orient("random", make_random(nq, 4, 1), nq, reps);
  bad |= run_orient("degenerate", make_coplanar(nd, 2), nd, reps);
  bad |= run_insphere("random", make_random(nq, 5, 3), nq, reps);
  bad |= run_insphere("degenerate", make_cospherical(nd, 4), nd, reps);
  return bad;
}
