// Deterministic generators of degenerate point configurations, shared by the CGAL
// cross-check tests (driven by a seeded PRNG) and the fuzz targets (driven by the fuzz
// bytes through the same interface, so every generator mode is reachable by both).
//
// Degeneracy is made exactly in integers or rationals first (small grids, lattice
// planes and lines, lattice points on spheres and circles, duplicates, lattice points
// on the vertices/edges/faces of a simplex), then moved by transforms that keep it
// exact (integer translation, scaling by 2^k) and optionally broken by a few ulps.
#ifndef TETREC_ORACLE_GEN_HPP
#define TETREC_ORACLE_GEN_HPP

#include "cgal_oracle.hpp"

#include <array>
#include <vector>

namespace tro {

// ---- sources of decisions ----
struct Rng {  // splitmix64: tiny, good enough, same sequence everywhere
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next()
  {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint64_t bits(int n) { return n >= 64 ? next() : next() >> (64 - n); }
};

struct Bytes {  // fuzz input; reads as zeros once exhausted
  const uint8_t *p;
  size_t n;
  uint64_t bits(int nb)
  {
    uint64_t v = 0;
    for (int i = 0; i < (nb + 7) / 8; i++) {
      v = (v << 8) | (n ? *p : 0);
      if (n) {
        p++;
        n--;
      }
    }
    return nb >= 64 ? v : v & ((1ull << nb) - 1);
  }
};

template <class S> uint64_t below(S &s, uint64_t n)
{
  int nb = 1;
  while (nb < 63 && (1ull << nb) < n)
    nb++;
  return n <= 1 ? 0 : s.bits(nb) % n;
}
template <class S> int64_t irange(S &s, int64_t lo, int64_t hi)
{
  return lo + (int64_t)below(s, (uint64_t)(hi - lo) + 1);
}
template <class S> bool coin(S &s, int num, int den) { return (int)below(s, (uint64_t)den) < num; }

// uniform in [-1, 1) with 53 random bits
template <class S> double unit(S &s)
{
  return std::ldexp((double)(int64_t)s.bits(54) - (double)(1ll << 53), -53);
}

// ---- lattice points on spheres and circles ----
// Integer points of x^2+y^2+z^2 = R (cospherical sets) and of x^2+y^2 = R.
inline const std::vector<std::array<int, 3>> &sphere_points(int which)
{
  static const int R[] = {3, 9, 25, 50, 75, 169};
  static std::vector<std::array<int, 3>> lists[6];
  static bool done = false;
  if (!done) {
    for (int w = 0; w < 6; w++)
      for (int x = -13; x <= 13; x++)
        for (int y = -13; y <= 13; y++)
          for (int z = -13; z <= 13; z++)
            if (x * x + y * y + z * z == R[w])
              lists[w].push_back({x, y, z});
    done = true;
  }
  return lists[which % 6];
}
inline const std::vector<std::array<int, 2>> &circle_points(int which)
{
  static const int R[] = {1, 2, 5, 25, 50, 65, 325};
  static std::vector<std::array<int, 2>> lists[7];
  static bool done = false;
  if (!done) {
    for (int w = 0; w < 7; w++)
      for (int x = -19; x <= 19; x++)
        for (int y = -19; y <= 19; y++)
          if (x * x + y * y == R[w])
            lists[w].push_back({x, y});
    done = true;
  }
  return lists[which % 7];
}

// A lattice point: exact value (x/m + T) * 2^k, with T and k shared by a case.
struct LP {
  int64_t x[3];
  int64_t m;
};
struct Xform {
  int64_t T[3] = {0, 0, 0};
  int k = 0;
};

template <class S> Xform gen_xform(S &s, bool planar)
{
  Xform t;
  if (coin(s, 1, 4)) {  // large translation, exact while |coordinate| < 2^53
    int b = (int)irange(s, 0, 50);
    for (int i = 0; i < (planar ? 2 : 3); i++)
      t.T[i] = irange(s, -(1ll << b), 1ll << b);
  }
  if (coin(s, 1, 3))
    t.k = (int)irange(s, -500, 500);
  return t;
}

enum { MAXP = 8 };

// The points of one case, each a double point or an exact rational point, mirrored
// as CGAL points with the same exact value.
struct Case {
  int n = 0;
  double d[MAXP][3];
  bool isq[MAXP];
  QPt q[MAXP];
  P3 cg[MAXP];
  tr_point tp[MAXP];
  QPt out;  // construction results
  Q tmp;

  void set_d(int i, double x, double y, double z)
  {
    d[i][0] = x;
    d[i][1] = y;
    d[i][2] = z;
    isq[i] = false;
    cg[i] = P3(x, y, z);
    tp[i] = tr_pt_d(d[i]);
    if (i >= n)
      n = i + 1;
  }
  // the point is q[i].q.c already
  void set_q_from_c(int i)
  {
    tr_qpoint_update(&q[i].q);
    isq[i] = true;
    for (int j = 0; j < 3; j++)
      d[i][j] = q[i].q.near[j];
    cg[i] = p3_from_qpoint(q[i].q);
    tp[i] = tr_pt_q(&q[i].q);
    if (i >= n)
      n = i + 1;
  }
  // Realizes a lattice point as an exact rational (as_q) or as a double; a value the
  // double cannot hold is truncated to one (a near-degenerate input, still valid).
  void realize(int i, const LP &p, const Xform &t, bool as_q)
  {
    if (!as_q && p.m == 1) {
      double v[3];
      for (int j = 0; j < 3; j++)
        v[j] = std::ldexp((double)(p.x[j] + t.T[j]), t.k);
      set_d(i, v[0], v[1], v[2]);
      return;
    }
    double v[3];
    for (int j = 0; j < 3; j++) {
      mpq_t &c = as_q ? q[i].q.c[j] : tmp.v;
      // x/m + T in GMP: x, m and T are each small enough, T*m may not be
      mpz_set_si(mpq_numref(c), (long)t.T[j]);
      mpz_mul_si(mpq_numref(c), mpq_numref(c), (long)p.m);
      if (p.x[j] >= 0)
        mpz_add_ui(mpq_numref(c), mpq_numref(c), (unsigned long)p.x[j]);
      else
        mpz_sub_ui(mpq_numref(c), mpq_numref(c), (unsigned long)-p.x[j]);
      mpz_set_si(mpq_denref(c), (long)p.m);
      mpq_canonicalize(c);
      if (t.k > 0)
        mpq_mul_2exp(c, c, (unsigned long)t.k);
      else if (t.k < 0)
        mpq_div_2exp(c, c, (unsigned long)-t.k);
      v[j] = mpq_get_d(c);
    }
    if (as_q)
      set_q_from_c(i);
    else
      set_d(i, v[0], v[1], v[2]);
  }
  // Moves one coordinate of a double point by 1 or 2 ulps.
  template <class S> void ulp_perturb(S &s, int i)
  {
    if (isq[i])
      return;
    int j = (int)below(s, 3), steps = (int)irange(s, 1, 2);
    double dir = coin(s, 1, 2) ? INFINITY : -INFINITY;
    double x = d[i][j];
    for (int k = 0; k < steps; k++)
      x = std::nextafter(x, dir);
    d[i][j] = x;
    cg[i] = P3(d[i][0], d[i][1], d[i][2]);
  }
  void print(FILE *f) const
  {
    for (int i = 0; i < n; i++) {
      if (!isq[i]) {
        fprintf(f, "  p%d = {%a, %a, %a}\n", i, d[i][0], d[i][1], d[i][2]);
      } else {
        fprintf(f, "  p%d = rational {", i);
        for (int j = 0; j < 3; j++)
          gmp_fprintf(f, "%Qd%s", q[i].q.c[j], j < 2 ? ", " : "}");
        fprintf(f, " ~ {%a, %a, %a}\n", d[i][0], d[i][1], d[i][2]);
      }
    }
  }
};

// ---- point sets for the predicates: n points with a chosen kind of degeneracy ----
// dim 2 keeps z = 0 (the 2D predicates read x, y). rational lets points be exact
// rationals with small denominators (for the tr_point predicates).
template <class S> void gen_points(S &s, Case &c, int n, int dim, bool rational)
{
  LP L[MAXP];
  int64_t m = 1;
  if (rational && coin(s, 3, 4)) {
    static const int64_t dens[] = {2, 3, 5, 6, 7, 49, 1 << 20};
    m = dens[below(s, 7)];
  }
  static const int64_t radii[] = {1, 2, 3, 8, 1000, 1 << 20};
  int64_t r = radii[below(s, 6)];
  int mode = (int)below(s, 8);
  auto rnd = [&](int64_t lo, int64_t hi) { return irange(s, lo, hi); };
  int64_t o[3], u[3], v[3];
  for (int j = 0; j < 3; j++) {
    o[j] = rnd(-r, r);
    u[j] = rnd(-3, 3);
    v[j] = rnd(-3, 3);
  }
  if (dim == 2)
    o[2] = u[2] = v[2] = 0;
  for (int i = 0; i < n; i++) {
    L[i].m = m;
    for (int j = 0; j < 3; j++)
      L[i].x[j] = 0;
    switch (mode) {
    case 0:  // small grid: many exact zeros and sign changes
    case 1:
      for (int j = 0; j < dim; j++)
        L[i].x[j] = rnd(-r * m, r * m);
      break;
    case 2: {  // coplanar (3D) / collinear (2D): o + (a u + b v)/m
      int64_t a = rnd(-2 * m - 1, 2 * m + 1), b = dim == 3 ? rnd(-2 * m - 1, 2 * m + 1) : 0;
      for (int j = 0; j < 3; j++)
        L[i].x[j] = o[j] * m + a * u[j] + b * v[j];
      break;
    }
    case 3: {  // collinear in 3D / duplicates in 2D
      int64_t a = rnd(-2 * m - 1, 2 * m + 1);
      for (int j = 0; j < dim; j++)
        L[i].x[j] = o[j] * m + (dim == 3 ? a * u[j] : (a & 1) * u[j]);
      break;
    }
    case 4:  // cospherical / concyclic around o, on integer points
    case 5:
      if (dim == 3 && mode == 4) {
        const auto &sp = sphere_points((int)o[1] & 0xff);
        const auto &p = sp[below(s, sp.size())];
        for (int j = 0; j < 3; j++)
          L[i].x[j] = (o[j] + p[j]) * m;
      } else {  // a circle in the plane z = o[2]: concyclic, so also coplanar in 3D
        const auto &cp = circle_points((int)o[1] & 0xff);
        const auto &p = cp[below(s, cp.size())];
        L[i].x[0] = (o[0] + p[0]) * m;
        L[i].x[1] = (o[1] + p[1]) * m;
        L[i].x[2] = dim == 3 ? o[2] * m : 0;
      }
      break;
    case 6: {  // duplicates of earlier points, else grid
      if (i > 0 && coin(s, 1, 2)) {
        L[i] = L[below(s, (uint64_t)i)];
      } else {
        for (int j = 0; j < dim; j++)
          L[i].x[j] = rnd(-r * m, r * m);
      }
      break;
    }
    default:  // rational points on a sphere: (2ac, 2bc, a^2+b^2-c^2)/(a^2+b^2+c^2)
      if (dim == 3) {
        int64_t a = rnd(-9, 9), b = rnd(-9, 9), cc = rnd(-9, 9);
        int64_t D = a * a + b * b + cc * cc;
        if (D == 0)
          D = cc = 1;
        int64_t rad = rnd(1, 4);
        int64_t num[3] = {2 * a * cc, 2 * b * cc, a * a + b * b - cc * cc};
        L[i].m = rational ? D : 1;
        for (int j = 0; j < 3; j++)
          L[i].x[j] = rational ? rad * num[j] + o[j] * D : rnd(-r, r);
      } else {
        for (int j = 0; j < 2; j++)
          L[i].x[j] = rnd(-r * m, r * m);
      }
      break;
    }
  }
  Xform t = gen_xform(s, dim == 2);
  bool uniform = coin(s, 1, 8);  // plain random doubles: the common case
  for (int i = 0; i < n; i++) {
    if (uniform) {
      double x = std::ldexp(unit(s), t.k), y = std::ldexp(unit(s), t.k);
      double z = dim == 3 ? std::ldexp(unit(s), t.k) : 0.0;
      c.set_d(i, x, y, z);
      continue;
    }
    bool as_q = rational && coin(s, 1, 2);
    c.realize(i, L[i], t, as_q);
  }
  if (coin(s, 1, 4)) {  // break the degeneracy by an ulp or two
    int k = (int)irange(s, 1, 2);
    for (int i = 0; i < k; i++) {
      int p = (int)below(s, (uint64_t)n);
      if (dim == 2) {  // only x, y matter
        double dir = coin(s, 1, 2) ? INFINITY : -INFINITY;
        int j = (int)below(s, 2);
        if (!c.isq[p]) {
          c.d[p][j] = std::nextafter(c.d[p][j], dir);
          c.cg[p] = P3(c.d[p][0], c.d[p][1], c.d[p][2]);
        }
      } else {
        c.ulp_perturb(s, p);
      }
    }
  }
  c.n = n;
}

// ---- simplices with points on their vertices, edges, faces and planes ----
// Frame: value(i,j,k) = o + (i u + j v + k w)/m; the simplex vertices sit at lattice
// coordinates 0, M e1, M e2, M e3, so small (i,j,k) land on vertices, edges, faces,
// inside, outside and on the supporting lines and planes.
struct Frame {
  int64_t o[3], u[3], v[3], w[3], m, M;
  LP at(int64_t i, int64_t j, int64_t k) const
  {
    LP p;
    p.m = m;
    for (int a = 0; a < 3; a++)
      p.x[a] = o[a] * m + i * u[a] + j * v[a] + k * w[a];
    return p;
  }
};

template <class S> Frame gen_frame(S &s, bool rational)
{
  Frame f;
  static const int64_t radii[] = {0, 1, 5, 1000, 1 << 20};
  int64_t r = radii[below(s, 5)];
  for (;;) {
    for (int a = 0; a < 3; a++) {
      f.o[a] = irange(s, -r, r);
      f.u[a] = irange(s, -3, 3);
      f.v[a] = irange(s, -3, 3);
      f.w[a] = irange(s, -3, 3);
    }
    int64_t det = f.u[0] * (f.v[1] * f.w[2] - f.v[2] * f.w[1]) -
                  f.u[1] * (f.v[0] * f.w[2] - f.v[2] * f.w[0]) +
                  f.u[2] * (f.v[0] * f.w[1] - f.v[1] * f.w[0]);
    if (det != 0)
      break;
    // a fixed fallback keeps the fuzz decoder total when the bytes run out
    if (coin(s, 1, 4)) {
      int64_t I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for (int a = 0; a < 3; a++) {
        f.u[a] = I[0][a];
        f.v[a] = I[1][a];
        f.w[a] = I[2][a];
      }
      break;
    }
  }
  if (rational && coin(s, 3, 4)) {
    static const int64_t dens[] = {2, 3, 5, 7};
    f.m = dens[below(s, 4)];
    f.M = coin(s, 1, 2) ? f.m : irange(s, 1, 4);
  } else {
    f.m = 1;
    f.M = irange(s, 1, 4);
  }
  return f;
}

// Lattice coordinates of vertex `which` (0..3) of the frame's simplex.
inline void frame_vertex(const Frame &f, int which, int64_t ijk[3])
{
  ijk[0] = ijk[1] = ijk[2] = 0;
  if (which > 0)
    ijk[which - 1] = f.M;
}

// A lattice point near the simplex, restricted to its first `dim` axes (dim 1: the
// line of the edge, 2: the plane of the triangle) unless `free`.
template <class S> LP frame_point(S &s, const Frame &f, int dim, bool free)
{
  int64_t c[3] = {0, 0, 0};
  for (int a = 0; a < 3; a++)
    if (free || a < dim)
      c[a] = irange(s, -1, f.M + 1);
  return f.at(c[0], c[1], c[2]);
}

// Realizes lattice points into c: double or rational per point (rational only when
// asked), then an optional ulp perturbation of one double point.
template <class S> void realize_all(S &s, Case &c, const LP *L, int n, bool rational)
{
  Xform t = gen_xform(s, false);
  for (int i = 0; i < n; i++)
    c.realize(i, L[i], t, rational && coin(s, 1, 2));
  c.n = n;
  if (coin(s, 1, 5))
    c.ulp_perturb(s, (int)below(s, (uint64_t)n));
}

}  // namespace tro

#endif
