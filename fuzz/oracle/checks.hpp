// One check per tetrec function family: generate a case from a source of decisions
// (seeded PRNG in tests/cgal, fuzz bytes in fuzz/pred), ask tetrec and the CGAL
// oracle, compare. Each check returns 1 (agree), 0 (mismatch: the case and both
// answers are printed to stderr, coordinates in %a so the case can be replayed) or -1
// (the generated input is outside the function's contract, e.g. a zero-length
// segment after an ulp perturbation; nothing was compared).
#ifndef TETREC_ORACLE_CHECKS_HPP
#define TETREC_ORACLE_CHECKS_HPP

#include "gen.hpp"

#include <iostream>

namespace tro {

// How often each oracle answer occurred (signs: -1/0/+1 in buckets 0/1/2; classifiers:
// the type of the first end; constructions: 0 no point / 1 a point), so the tests can
// show that the degenerate answers are well represented.
inline long long g_hist[5];
inline void note(int bucket) { g_hist[bucket < 0 ? 0 : (bucket > 4 ? 4 : bucket)]++; }

inline int mismatch(const char *what, const Case &c, long got, long want)
{
  fprintf(stderr, "MISMATCH %s: tetrec %ld, CGAL exact %ld\n", what, got, want);
  c.print(stderr);
  return 0;
}

inline Ki::Point_2 ki2(const double *p) { return Ki::Point_2(p[0], p[1]); }
inline Ki::Point_3 ki3(const double *p) { return Ki::Point_3(p[0], p[1], p[2]); }
inline P2 ke2(const double *p) { return P2(p[0], p[1]); }

// When set, the double-input predicates are also compared with Epeck (slower than
// Epick on degenerate input; the fuzz targets always do it).
extern bool g_also_epeck;

// ---- adaptive predicates on doubles ----
template <class S> int check_orient2d(S &s, Case &c)
{
  gen_points(s, c, 3, 2, false);
  int got = tr_sign(tr_orient2d(c.d[0], c.d[1], c.d[2]));
  int want = (int)CGAL::orientation(ki2(c.d[0]), ki2(c.d[1]), ki2(c.d[2]));
  if (got != want)
    return mismatch("tr_orient2d(p0,p1,p2) [x,y only]", c, got, want);
  if (g_also_epeck && want != o_orient2d(ke2(c.d[0]), ke2(c.d[1]), ke2(c.d[2])))
    return mismatch("Epick vs Epeck orient2d (oracle disagreement)", c, want, -want);
  note(want + 1);
  return 1;
}

template <class S> int check_orient2d_proj(S &s, Case &c)
{
  gen_points(s, c, 3, 3, false);
  int drop = (int)below(s, 3);
  int got = tr_sign(tr_orient2d_proj(c.d[0], c.d[1], c.d[2], drop));
  int want = o_orient2d(o_project(c.cg[0], drop), o_project(c.cg[1], drop), o_project(c.cg[2], drop));
  if (got != want) {
    fprintf(stderr, "  drop = %d\n", drop);
    return mismatch("tr_orient2d_proj(p0,p1,p2,drop)", c, got, want);
  }
  note(want + 1);
  return 1;
}

template <class S> int check_incircle(S &s, Case &c)
{
  gen_points(s, c, 4, 2, false);
  int got = tr_sign(tr_incircle(c.d[0], c.d[1], c.d[2], c.d[3]));
  int want = (int)CGAL::side_of_oriented_circle(ki2(c.d[0]), ki2(c.d[1]), ki2(c.d[2]), ki2(c.d[3]));
  if (got != want)
    return mismatch("tr_incircle(p0,p1,p2,p3) [x,y only]", c, got, want);
  if (g_also_epeck && want != o_incircle(ke2(c.d[0]), ke2(c.d[1]), ke2(c.d[2]), ke2(c.d[3])))
    return mismatch("Epick vs Epeck incircle (oracle disagreement)", c, want, -want);
  note(want + 1);
  return 1;
}

template <class S> int check_orient3d(S &s, Case &c)
{
  gen_points(s, c, 4, 3, false);
  int got = tr_sign(tr_orient3d(c.d[0], c.d[1], c.d[2], c.d[3]));
  int want = (int)CGAL::orientation(ki3(c.d[0]), ki3(c.d[1]), ki3(c.d[2]), ki3(c.d[3]));
  if (got != want)
    return mismatch("tr_orient3d(p0,p1,p2,p3)", c, got, want);
  if (g_also_epeck && want != o_orient3d(c.cg[0], c.cg[1], c.cg[2], c.cg[3]))
    return mismatch("Epick vs Epeck orient3d (oracle disagreement)", c, want, -want);
  note(want + 1);
  return 1;
}

template <class S> int check_insphere(S &s, Case &c)
{
  gen_points(s, c, 5, 3, false);
  int got = tr_sign(tr_insphere(c.d[0], c.d[1], c.d[2], c.d[3], c.d[4]));
  int want = (int)CGAL::side_of_oriented_sphere(ki3(c.d[0]), ki3(c.d[1]), ki3(c.d[2]),
                                                ki3(c.d[3]), ki3(c.d[4]));
  if (got != want)
    return mismatch("tr_insphere(p0,p1,p2,p3,p4)", c, got, want);
  if (g_also_epeck && want != o_insphere(c.cg[0], c.cg[1], c.cg[2], c.cg[3], c.cg[4]))
    return mismatch("Epick vs Epeck insphere (oracle disagreement)", c, want, -want);
  note(want + 1);
  return 1;
}

// ---- symbolic perturbation: agrees with the exact sign where that is not zero, is
// deterministic, and is an alternating function of its (point, index) arguments ----
template <class S> int check_sos(S &s, Case &c)
{
  bool sphere = coin(s, 1, 2);
  int n = sphere ? 5 : 4;
  gen_points(s, c, n, 3, false);
  uint32_t idx[5];
  uint32_t base = (uint32_t)s.bits(32), stride = (uint32_t)s.bits(8) | 1;
  for (int i = 0; i < 5; i++)
    idx[i] = base + (uint32_t)i * stride;
  for (int i = 4; i > 0; i--) {  // shuffle so the index order differs from the argument order
    int j = (int)below(s, (uint64_t)i + 1);
    uint32_t t = idx[i];
    idx[i] = idx[j];
    idx[j] = t;
  }
  const double *p[5] = {c.d[0], c.d[1], c.d[2], c.d[3], sphere ? c.d[4] : c.d[0]};
  auto eval = [&](const double *const *q, const uint32_t *ix) {
    return sphere ? tr_insphere_sos(q[0], q[1], q[2], q[3], q[4], ix[0], ix[1], ix[2], ix[3], ix[4])
                  : tr_orient3d_sos(q[0], q[1], q[2], q[3], ix[0], ix[1], ix[2], ix[3]);
  };
  int got = eval(p, idx);
  int exact = sphere ? o_insphere(c.cg[0], c.cg[1], c.cg[2], c.cg[3], c.cg[4])
                     : o_orient3d(c.cg[0], c.cg[1], c.cg[2], c.cg[3]);
  const char *name = sphere ? "tr_insphere_sos" : "tr_orient3d_sos";
  char what[160];
  if (got < -1 || got > 1 || (exact != 0 && got != exact)) {
    fprintf(stderr, "  indices %u %u %u %u %u\n", idx[0], idx[1], idx[2], idx[3], idx[4]);
    snprintf(what, sizeof what, "%s must equal the exact sign when that is non-zero", name);
    return mismatch(what, c, got, exact);
  }
  // perturb.c: orient3d_sos is never 0 for distinct indices; insphere_sos is 0
  // exactly when all five points are coplanar.
  bool flat = false;
  if (sphere) {
    const P3 *g = c.cg;
    flat = CGAL::coplanar(g[0], g[1], g[2], g[3]) && CGAL::coplanar(g[0], g[1], g[2], g[4]) &&
           CGAL::coplanar(g[0], g[1], g[3], g[4]) && CGAL::coplanar(g[0], g[2], g[3], g[4]) &&
           CGAL::coplanar(g[1], g[2], g[3], g[4]);
  }
  if ((got == 0) != flat) {
    fprintf(stderr, "  indices %u %u %u %u %u\n", idx[0], idx[1], idx[2], idx[3], idx[4]);
    snprintf(what, sizeof what, "%s is 0 iff %s", name,
             sphere ? "the five points are coplanar" : "never (distinct indices)");
    return mismatch(what, c, got, flat ? 0 : 1);
  }
  if (eval(p, idx) != got) {
    snprintf(what, sizeof what, "%s is not deterministic", name);
    return mismatch(what, c, got, -got);
  }
  // swap two arguments together with their indices: the sign must flip
  int i = (int)below(s, (uint64_t)n), j = (int)below(s, (uint64_t)n - 1);
  if (j >= i)
    j++;
  const double *q[5] = {p[0], p[1], p[2], p[3], p[4]};
  uint32_t jx[5] = {idx[0], idx[1], idx[2], idx[3], idx[4]};
  std::swap(q[i], q[j]);
  std::swap(jx[i], jx[j]);
  int swapped = eval(q, jx);
  if (swapped != -got) {
    fprintf(stderr, "  indices %u %u %u %u %u, swapped arguments %d and %d\n", idx[0], idx[1],
            idx[2], idx[3], idx[4], i, j);
    snprintf(what, sizeof what, "%s must change sign when two arguments swap", name);
    return mismatch(what, c, swapped, -got);
  }
  note(exact + 1);
  return 1;
}

// ---- filtered predicates on tr_point (double and rational points mixed) ----
template <class S> int check_qpoint_predicates(S &s, Case &c)
{
  gen_points(s, c, 5, 3, true);
  for (int i = 0; i < 5; i++)
    if (c.isq[i]) {
      int e = qpoint_box_error(c.q[i].q);
      if (e) {
        fprintf(stderr, "  p%d:\n", i);
        print_qpoint_box(c.q[i].q);
      }
      if (e)
        return mismatch("tr_qpoint_update: lo/hi/near not the tight box and nearest double of "
                        "c[coordinate-1]",
                        c, e, 0);
    }
  const tr_point *t = c.tp;
  const P3 *g = c.cg;
  int got = tr_orient3d_p(&t[0], &t[1], &t[2], &t[3]);
  int want = o_orient3d(g[0], g[1], g[2], g[3]);
  if (got != want)
    return mismatch("tr_orient3d_p(p0,p1,p2,p3)", c, got, want);
  const int o3 = want;
  got = tr_insphere_p(&t[0], &t[1], &t[2], &t[3], &t[4]);
  want = o_insphere(g[0], g[1], g[2], g[3], g[4]);
  if (got != want)
    return mismatch("tr_insphere_p(p0,p1,p2,p3,p4)", c, got, want);
  int drop = (int)below(s, 3);
  got = tr_orient2d_proj_p(&t[0], &t[1], &t[2], drop);
  want = o_orient2d(o_project(g[0], drop), o_project(g[1], drop), o_project(g[2], drop));
  if (got != want) {
    fprintf(stderr, "  drop = %d\n", drop);
    return mismatch("tr_orient2d_proj_p(p0,p1,p2,drop)", c, got, want);
  }
  int i = (int)below(s, 5), j = (int)below(s, 5), k = (int)below(s, 3);
  got = tr_cmp_coord_p(&t[i], &t[j], k);
  want = (int)CGAL::compare(o_coord(g[i], k), o_coord(g[j], k));
  if (got != want) {
    fprintf(stderr, "  tr_cmp_coord_p(p%d, p%d, %d)\n", i, j, k);
    return mismatch("tr_cmp_coord_p", c, got, want);
  }
  got = tr_equal_p(&t[i], &t[j]) != 0;
  want = g[i] == g[j];
  if (got != want) {
    fprintf(stderr, "  tr_equal_p(p%d, p%d)\n", i, j);
    return mismatch("tr_equal_p", c, got, want);
  }
  note(o3 + 1);
  return 1;
}

// ---- constructions ----
// Checks a construction result against the oracle's exact point (or its absence).
inline int compare_construction(const char *what, Case &c, int ret, const K::Point_3 *want)
{
  if (!want) {
    if (ret != -1)
      return mismatch(what, c, ret, -1);
    return 1;
  }
  if (ret != 0)
    return mismatch(what, c, ret, 0);
  if (!qpoint_equals(c.out.q, *want)) {
    fprintf(stderr, "  tetrec point: {");
    for (int j = 0; j < 3; j++)
      gmp_fprintf(stderr, "%Qd%s", c.out.q.c[j], j < 2 ? ", " : "}\n");
    std::cerr << "  CGAL point: {" << CGAL::exact(want->x()) << ", " << CGAL::exact(want->y())
              << ", " << CGAL::exact(want->z()) << "}\n";
    return mismatch(what, c, 1, 0);
  }
  int e = qpoint_box_error(c.out.q);
  if (e) {
    print_qpoint_box(c.out.q);
    return mismatch("constructed point: lo/hi/near not the tight box and nearest double", c, e, 0);
  }
  return 1;
}

template <class R> const P3 *point_of(const R &res)
{
  return res ? boost::get<P3>(&*res) : nullptr;
}

// Line ab against the plane of a frame triangle: crossings at lattice points, lines
// parallel to and inside the plane.
template <class S> int check_line_plane(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[5];
  int perm[3] = {0, 1, 2};
  if (coin(s, 1, 2))
    std::swap(perm[0], perm[(int)irange(s, 1, 2)]);
  for (int i = 0; i < 3; i++) {
    int64_t v[3];
    frame_vertex(f, perm[i], v);
    L[i] = f.at(v[0], v[1], v[2]);
  }
  L[3] = frame_point(s, f, 2, true);
  L[4] = frame_point(s, f, 2, coin(s, 3, 4));
  if (coin(s, 1, 16))  // a repeated vertex: no plane, construct.h promises -1
    L[2] = L[below(s, 2)];
  realize_all(s, c, L, 5, rational);
  const tr_point *t = c.tp;
  const P3 *g = c.cg;
  int ret = tr_construct_line_plane(&t[3], &t[4], &t[0], &t[1], &t[2], &c.out.q);
  if (g[3] == g[4] || CGAL::collinear(g[0], g[1], g[2])) {
    int ok = compare_construction("tr_construct_line_plane with a == b or p,q,r collinear", c,
                                  ret, nullptr);
    if (ok == 1)
      note(0);
    return ok;
  }
  auto res = CGAL::intersection(L3(g[3], g[4]), Pl3(g[0], g[1], g[2]));
  const P3 *x = point_of(res);
  int ok = compare_construction("tr_construct_line_plane(line p3 p4, plane p0 p1 p2)", c, ret, x);
  if (ok == 1)
    note(x != nullptr);
  if (ok != 1 || !x)
    return ok;
  // the Steiner point as an input: exactly on the plane, and located in the triangle
  tr_point X = tr_pt_q(&c.out.q);
  int o = tr_orient3d_p(&t[0], &t[1], &t[2], &X);
  if (o != 0)
    return mismatch("tr_orient3d_p(p0,p1,p2, constructed line-plane point)", c, o, 0);
  tr_hit got = tr_classify_point_triangle(&X, &t[0], &t[1], &t[2]);
  tr_hit want = o_point_triangle(*x, g);
  if (!hit_point_equal(got, want)) {
    print_hit("tetrec", got);
    print_hit("CGAL", want);
    return mismatch("tr_classify_point_triangle(constructed line-plane point, p0,p1,p2)", c,
                    got.type, want.type);
  }
  // construct.h: out may be the qpoint behind an input. Overwrites p3, so last.
  if (c.isq[3] && coin(s, 1, 4)) {
    int ret2 = tr_construct_line_plane(&t[3], &t[4], &t[0], &t[1], &t[2], &c.q[3].q);
    if (ret2 != 0 || !qpoint_equals(c.q[3].q, *x))
      return mismatch("tr_construct_line_plane with out == the qpoint of a (p3, now "
                      "overwritten; rerun the case to see the input)",
                      c, ret2, 0);
  }
  return 1;
}

// Two lines on lattice points of a frame plane (coplanar: crossing, parallel or
// equal), sometimes skew, sometimes through a rational Steiner point that tetrec
// constructed on that plane.
template <class S> int check_line_line(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[6];
  for (int i = 0; i < 4; i++)
    L[i] = frame_point(s, f, 2, false);
  if (coin(s, 1, 8))  // off the plane: skew lines (or not, by luck)
    L[3] = frame_point(s, f, 3, true);
  L[4] = frame_point(s, f, 2, true);  // a line through these two crosses the plane
  L[5] = frame_point(s, f, 2, true);
  realize_all(s, c, L, 6, rational);
  const tr_point *t = c.tp;
  P3 g[4] = {c.cg[0], c.cg[1], c.cg[2], c.cg[3]};
  tr_point tt[4] = {t[0], t[1], t[2], t[3]};
  if (coin(s, 1, 3)) {
    // Replace p0 by the crossing of line p4 p5 with the plane of p1 p2 p3: all four
    // stay coplanar when p1 p2 p3 are.
    if (c.cg[4] == c.cg[5] || CGAL::collinear(g[1], g[2], g[3]))
      return -1;
    auto res = CGAL::intersection(L3(c.cg[4], c.cg[5]), Pl3(g[1], g[2], g[3]));
    const P3 *x = point_of(res);
    int ret = tr_construct_line_plane(&t[4], &t[5], &t[1], &t[2], &t[3], &c.q[MAXP - 1].q);
    if (!x || ret != 0)
      return -1;  // the line_plane check covers these answers
    if (!qpoint_equals(c.q[MAXP - 1].q, *x))
      return mismatch("tr_construct_line_plane(line p4 p5, plane p1 p2 p3) (Steiner input)", c,
                      1, 0);
    g[0] = *x;
    tt[0] = tr_pt_q(&c.q[MAXP - 1].q);
  }
  int ret = tr_construct_line_line(&tt[0], &tt[1], &tt[2], &tt[3], &c.out.q);
  // construct.h: -1 for a == b, c == d, skew (CGAL: no intersection) or parallel lines
  const P3 *x = nullptr;
  decltype(CGAL::intersection(L3(g[0], g[1]), L3(g[2], g[3]))) res;
  if (!(g[0] == g[1] || g[2] == g[3])) {
    res = CGAL::intersection(L3(g[0], g[1]), L3(g[2], g[3]));
    x = point_of(res);
  }
  int ok = compare_construction("tr_construct_line_line(line p0 p1, line p2 p3)", c, ret, x);
  if (ok == 1)
    note(x != nullptr);
  if (ok == 0 && tt[0].q == &c.q[MAXP - 1].q) {
    fprintf(stderr, "  p0 replaced by the Steiner point {");
    for (int j = 0; j < 3; j++)
      gmp_fprintf(stderr, "%Qd%s", c.q[MAXP - 1].q.c[j], j < 2 ? ", " : "}\n");
  }
  return ok;
}

// ---- classifiers ----
template <class S> int check_point_segment(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[3];
  L[0] = f.at(0, 0, 0);
  L[1] = f.at(f.M, 0, 0);
  if (coin(s, 1, 2))
    std::swap(L[0], L[1]);
  L[2] = frame_point(s, f, 1, coin(s, 1, 4));
  realize_all(s, c, L, 3, rational);
  if (c.cg[0] == c.cg[1])
    return -1;
  tr_hit got = tr_classify_point_segment(&c.tp[2], &c.tp[0], &c.tp[1]);
  tr_hit want = o_point_segment(c.cg[2], c.cg[0], c.cg[1]);
  if (!hit_point_equal(got, want)) {
    print_hit("tetrec", got);
    print_hit("CGAL", want);
    return mismatch("tr_classify_point_segment(p2, p0, p1) type", c, got.type, want.type);
  }
  note(want.type);
  return 1;
}

// The frame triangle's vertices in a random order into L[0..2].
template <class S> void frame_triangle(S &s, const Frame &f, LP *L)
{
  int perm[3] = {0, 1, 2};
  for (int i = 2; i > 0; i--)
    std::swap(perm[i], perm[below(s, (uint64_t)i + 1)]);
  for (int i = 0; i < 3; i++) {
    int64_t v[3];
    frame_vertex(f, perm[i], v);
    L[i] = f.at(v[0], v[1], v[2]);
  }
}

template <class S> int check_point_triangle(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[4];
  frame_triangle(s, f, L);
  L[3] = frame_point(s, f, 2, coin(s, 1, 4));
  realize_all(s, c, L, 4, rational);
  if (CGAL::collinear(c.cg[0], c.cg[1], c.cg[2]))
    return -1;
  tr_hit got = tr_classify_point_triangle(&c.tp[3], &c.tp[0], &c.tp[1], &c.tp[2]);
  tr_hit want = o_point_triangle(c.cg[3], c.cg);
  if (!hit_point_equal(got, want)) {
    print_hit("tetrec", got);
    print_hit("CGAL", want);
    return mismatch("tr_classify_point_triangle(p3, p0, p1, p2) type", c, got.type, want.type);
  }
  note(want.type);
  return 1;
}

inline int isect_mismatch(const char *what, Case &c, const tr_isect &got, const tr_isect &want)
{
  print_isect("tetrec", got);
  print_isect("CGAL", want);
  return mismatch(what, c, got.n, want.n);
}

template <class S> int check_segment_segment(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[4];
  bool planar = coin(s, 7, 8);
  for (int i = 0; i < 4; i++)
    L[i] = frame_point(s, f, planar ? 2 : 3, !planar);
  realize_all(s, c, L, 4, rational);
  if (c.cg[0] == c.cg[1] || c.cg[2] == c.cg[3])
    return -1;
  tr_isect got = tr_classify_segment_segment(&c.tp[0], &c.tp[1], &c.tp[2], &c.tp[3]);
  tr_isect want = o_segment_segment(c.cg[0], c.cg[1], c.cg[2], c.cg[3]);
  if (!isect_equal(got, want))
    return isect_mismatch("tr_classify_segment_segment(p0 p1, p2 p3) (n shown)", c, got, want);
  note(want.n ? (int)want.end[0].type : (int)TR_DEG);
  return 1;
}

// Segment endpoints: both free, both in the plane k = 0, or a = q + d, b = q - d
// through a lattice point q (on a vertex, edge or face of the simplex when lucky).
template <class S> void frame_segment(S &s, const Frame &f, int dim, LP *a, LP *b)
{
  int mode = (int)below(s, 3);
  if (mode == 0) {
    *a = frame_point(s, f, 3, true);
    *b = frame_point(s, f, 3, true);
    return;
  }
  if (mode == 1 && dim == 2) {
    *a = frame_point(s, f, 2, false);
    *b = frame_point(s, f, 2, false);
    return;
  }
  int64_t q[3], d[3];
  for (int i = 0; i < 3; i++) {
    q[i] = i < dim ? irange(s, 0, f.M) : 0;
    d[i] = irange(s, -2, 2);
  }
  *a = f.at(q[0] + d[0], q[1] + d[1], q[2] + d[2]);
  *b = f.at(q[0] - d[0], q[1] - d[1], q[2] - d[2]);
}

template <class S> int check_segment_triangle(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[5];
  frame_triangle(s, f, L);
  frame_segment(s, f, 2, &L[3], &L[4]);
  realize_all(s, c, L, 5, rational);
  if (c.cg[3] == c.cg[4] || CGAL::collinear(c.cg[0], c.cg[1], c.cg[2]))
    return -1;
  tr_isect got = tr_classify_segment_triangle(&c.tp[3], &c.tp[4], &c.tp[0], &c.tp[1], &c.tp[2]);
  tr_isect want = o_segment_triangle(c.cg[3], c.cg[4], c.cg);
  if (!isect_equal(got, want))
    return isect_mismatch("tr_classify_segment_triangle(p3 p4, p0 p1 p2) (n shown)", c, got, want);
  note(want.n ? (int)want.end[0].type : (int)TR_DEG);
  return 1;
}

template <class S> int check_segment_tet(S &s, Case &c)
{
  bool rational = coin(s, 1, 2);
  Frame f = gen_frame(s, rational);
  LP L[6];
  int perm[4] = {0, 1, 2, 3};
  for (int i = 3; i > 0; i--)
    std::swap(perm[i], perm[below(s, (uint64_t)i + 1)]);
  for (int i = 0; i < 4; i++) {
    int64_t v[3];
    frame_vertex(f, perm[i], v);
    L[i] = f.at(v[0], v[1], v[2]);
  }
  frame_segment(s, f, 3, &L[4], &L[5]);
  realize_all(s, c, L, 6, rational);
  if (c.cg[4] == c.cg[5])
    return -1;
  int o = o_orient3d(c.cg[0], c.cg[1], c.cg[2], c.cg[3]);
  if (o == 0)
    return -1;
  int i0 = o > 0 ? 0 : 1, i1 = o > 0 ? 1 : 0;  // positive orientation, as the contract says
  const tr_point *tt[4] = {&c.tp[i0], &c.tp[i1], &c.tp[2], &c.tp[3]};
  P3 gt[4] = {c.cg[i0], c.cg[i1], c.cg[2], c.cg[3]};
  tr_isect got = tr_classify_segment_tet(&c.tp[4], &c.tp[5], tt);
  tr_isect want = o_segment_tet(c.cg[4], c.cg[5], gt);
  if (!isect_equal(got, want)) {
    fprintf(stderr, "  tet = (p%d, p%d, p2, p3), segment p4 p5\n", i0, i1);
    return isect_mismatch("tr_classify_segment_tet(p4 p5, tet) (n shown)", c, got, want);
  }
  note(want.n ? (int)want.end[0].type : (int)TR_DEG);
  return 1;
}

}  // namespace tro

#endif
