// CGAL exact-kernel oracle for the tetrec predicates, constructions and classifiers.
// Shared by the cross-check tests (tests/cgal) and the libFuzzer targets (fuzz/pred).
//
// The oracle answers every question with CGAL's Epeck (exact predicates, exact
// constructions, lazy rationals) and its own classification logic, written from the
// definitions in predicates/classify.h (not from tetrec's implementation): a point is
// located by equality tests, collinear/coplanar ordering and CGAL's has_on; segment
// intersections come from CGAL::intersection and their ends are located the same way.
#ifndef TETREC_CGAL_ORACLE_HPP
#define TETREC_CGAL_ORACLE_HPP

#include <gmp.h>  // before the extern "C" block: gmp.h has C++ overloads of its own

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

extern "C" {
#include "classify.h"
#include "construct.h"
#include "predicates.h"
#include "qpoint.h"
}

namespace tro {

typedef CGAL::Epeck K;
typedef K::FT FT;
typedef K::Point_2 P2;
typedef K::Point_3 P3;
typedef K::Segment_3 S3;
typedef K::Triangle_3 T3;
typedef K::Tetrahedron_3 Tet3;
typedef K::Line_3 L3;
typedef K::Plane_3 Pl3;

// Predicates on double inputs are also asked to Epick: its predicates are exact for
// any finite double input (static filter, interval filter, then exact Mpzf), and it
// is much faster than Epeck on the degenerate inputs that dominate the test mix. The
// cross-check compares tetrec with BOTH and requires all three to agree.
typedef CGAL::Epick Ki;

// ---- conversions between GMP rationals and the kernel's exact number type ----
typedef CGAL::Exact_predicates_exact_constructions_kernel::FT::ET ET;

inline void et_to_mpq(const boost::multiprecision::mpq_rational &e, mpq_t out)
{
  mpq_set(out, e.backend().data());
}
inline void et_from_mpq(boost::multiprecision::mpq_rational &e, const mpq_t in)
{
  mpq_set(e.backend().data(), in);
}
inline void et_to_mpq(const CGAL::Gmpq &e, mpq_t out) { mpq_set(out, e.mpq()); }
inline void et_from_mpq(CGAL::Gmpq &e, const mpq_t in) { e = CGAL::Gmpq(in); }

inline FT ft_from_mpq(const mpq_t q)
{
  ET e;
  et_from_mpq(e, q);
  return FT(e);
}

// RAII holder so a test owns a small pool of tr_qpoints and reuses them.
struct QPt {
  tr_qpoint q;
  QPt() { tr_qpoint_init(&q); }
  ~QPt() { tr_qpoint_clear(&q); }
  QPt(const QPt &) = delete;
  QPt &operator=(const QPt &) = delete;
};

// RAII mpq_t.
struct Q {
  mpq_t v;
  Q() { mpq_init(v); }
  ~Q() { mpq_clear(v); }
  Q(const Q &) = delete;
  Q &operator=(const Q &) = delete;
};

inline P3 p3_from_qpoint(const tr_qpoint &q)
{
  return P3(ft_from_mpq(q.c[0]), ft_from_mpq(q.c[1]), ft_from_mpq(q.c[2]));
}

// 1 iff the exact value of ft equals the rational q.
inline bool ft_equals_mpq(const FT &ft, const mpq_t q)
{
  Q t;
  et_to_mpq(CGAL::exact(ft), t.v);
  return mpq_equal(t.v, q) != 0;
}

// ---- oracle predicates ----
inline int o_orient2d(const P2 &a, const P2 &b, const P2 &c) { return (int)CGAL::orientation(a, b, c); }
inline int o_orient3d(const P3 &a, const P3 &b, const P3 &c, const P3 &d)
{
  return (int)CGAL::orientation(a, b, c, d);
}
inline int o_incircle(const P2 &a, const P2 &b, const P2 &c, const P2 &d)
{
  return (int)CGAL::side_of_oriented_circle(a, b, c, d);
}
inline int o_insphere(const P3 &a, const P3 &b, const P3 &c, const P3 &d, const P3 &e)
{
  return (int)CGAL::side_of_oriented_sphere(a, b, c, d, e);
}

// The 2D point that remains when axis `drop` is removed, with the kept axes in the
// cyclic order ((drop+1)%3, (drop+2)%3) that qpoint.h specifies: the orientation is
// then the sign of component `drop` of the normal (b-a)x(c-a).
inline P2 o_project(const P3 &p, int drop)
{
  if (drop == 0)
    return P2(p.y(), p.z());
  if (drop == 1)
    return P2(p.z(), p.x());
  return P2(p.x(), p.y());
}

inline FT o_coord(const P3 &p, int i) { return i == 0 ? p.x() : (i == 1 ? p.y() : p.z()); }

// ---- oracle classifiers (the vocabulary of classify.h) ----
inline tr_hit mk_hit(int type, int code, int on_seg)
{
  tr_hit h;
  h.type = (uint8_t)type;
  h.code = (uint8_t)code;
  h.on_seg = (uint8_t)on_seg;
  return h;
}

inline tr_hit o_point_segment(const P3 &p, const P3 &a, const P3 &b)
{
  if (p == a)
    return mk_hit(TR_NOD, 0, 0);
  if (p == b)
    return mk_hit(TR_NOD, 1, 0);
  if (CGAL::collinear(a, b, p) && CGAL::collinear_are_strictly_ordered_along_line(a, p, b))
    return mk_hit(TR_EDG, tr_ecode(0, 1), 0);
  return mk_hit(TR_DEG, 0, 0);
}

inline tr_hit o_point_triangle(const P3 &p, const P3 t[3])
{
  if (CGAL::orientation(t[0], t[1], t[2], p) != CGAL::COPLANAR)
    return mk_hit(TR_DEG, 0, 0);
  for (int i = 0; i < 3; i++)
    if (p == t[i])
      return mk_hit(TR_NOD, i, 0);
  static const int E[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int e = 0; e < 3; e++) {
    const P3 &u = t[E[e][0]], &v = t[E[e][1]];
    if (CGAL::collinear(u, v, p) && CGAL::collinear_are_strictly_ordered_along_line(u, p, v))
      return mk_hit(TR_EDG, tr_ecode(E[e][0], E[e][1]), 0);
  }
  if (T3(t[0], t[1], t[2]).has_on(p))
    return mk_hit(TR_FAC, 3, 0);
  return mk_hit(TR_DEG, 0, 0);
}

// Point against a positively oriented closed tet. Face k is opposite vertex k; the
// point is on face k iff replacing vertex k by it gives a flat tet.
inline tr_hit o_point_tet(const P3 &p, const P3 t[4])
{
  int on[4], non = 0;
  for (int k = 0; k < 4; k++) {
    P3 q[4] = {t[0], t[1], t[2], t[3]};
    q[k] = p;
    int s = o_orient3d(q[0], q[1], q[2], q[3]);
    if (s < 0)
      return mk_hit(TR_DEG, 0, 0);
    on[k] = s == 0;
    non += on[k];
  }
  if (non == 0)
    return mk_hit(TR_INT, 0, 0);
  if (non == 1) {
    for (int k = 0; k < 4; k++)
      if (on[k])
        return mk_hit(TR_FAC, k, 0);
  }
  if (non == 2) {
    // on the two faces => on the edge made of the two vertices both faces contain
    int i = -1, j = -1;
    for (int k = 0; k < 4; k++)
      if (!on[k]) {
        if (i < 0)
          i = k;
        else
          j = k;
      }
    return mk_hit(TR_EDG, tr_ecode(i, j), 0);
  }
  for (int k = 0; k < 4; k++)  // three faces: their common vertex
    if (!on[k])
      return mk_hit(TR_NOD, k, 0);
  return mk_hit(TR_DEG, 0, 0);  // four faces: impossible for a non-flat tet
}

inline int o_on_seg(const P3 &x, const P3 &a, const P3 &b)
{
  if (x == a)
    return TR_SEG_A;
  if (x == b)
    return TR_SEG_B;
  return TR_SEG_IN;
}

// The intersection of segment ab with some object as 0, 1 or 2 points ordered from a.
struct Ends {
  int n = 0;
  P3 p[2];
};

template <class R> inline Ends ends_of(const R &res, const P3 &a)
{
  Ends e;
  if (!res)
    return e;
  if (const P3 *p = boost::get<P3>(&*res)) {
    e.n = 1;
    e.p[0] = *p;
  } else if (const S3 *s = boost::get<S3>(&*res)) {
    P3 u = s->source(), v = s->target();
    if (u == v) {
      e.n = 1;
      e.p[0] = u;
    } else {
      e.n = 2;
      if (CGAL::compare_distance_to_point(a, u, v) == CGAL::SMALLER) {
        e.p[0] = u;
        e.p[1] = v;
      } else {
        e.p[0] = v;
        e.p[1] = u;
      }
    }
  }
  return e;
}

inline tr_isect o_segment_segment(const P3 &a, const P3 &b, const P3 &c, const P3 &d)
{
  Ends e = ends_of(CGAL::intersection(S3(a, b), S3(c, d)), a);
  tr_isect r;
  memset(&r, 0, sizeof r);
  r.n = e.n;
  for (int i = 0; i < e.n; i++) {
    r.end[i] = o_point_segment(e.p[i], c, d);
    r.end[i].on_seg = (uint8_t)o_on_seg(e.p[i], a, b);
  }
  return r;
}

inline tr_isect o_segment_triangle(const P3 &a, const P3 &b, const P3 t[3])
{
  Ends e = ends_of(CGAL::intersection(S3(a, b), T3(t[0], t[1], t[2])), a);
  tr_isect r;
  memset(&r, 0, sizeof r);
  r.n = e.n;
  for (int i = 0; i < e.n; i++) {
    r.end[i] = o_point_triangle(e.p[i], t);
    r.end[i].on_seg = (uint8_t)o_on_seg(e.p[i], a, b);
  }
  return r;
}

inline tr_isect o_segment_tet(const P3 &a, const P3 &b, const P3 t[4])
{
  Ends e = ends_of(CGAL::intersection(S3(a, b), Tet3(t[0], t[1], t[2], t[3])), a);
  tr_isect r;
  memset(&r, 0, sizeof r);
  r.n = e.n;
  for (int i = 0; i < e.n; i++) {
    r.end[i] = o_point_tet(e.p[i], t);
    r.end[i].on_seg = (uint8_t)o_on_seg(e.p[i], a, b);
  }
  return r;
}

// ---- comparisons (which fields the contract defines) ----
// A point classifier's code means nothing for TR_DEG and on_seg is not defined.
inline bool hit_point_equal(const tr_hit &x, const tr_hit &y)
{
  return x.type == y.type && (x.type == TR_DEG || x.code == y.code);
}
// An intersection end: type, code (not for TR_INT: it has no sub-simplex) and on_seg.
inline bool hit_end_equal(const tr_hit &x, const tr_hit &y)
{
  return x.type == y.type && x.on_seg == y.on_seg && (x.type == TR_INT || x.code == y.code);
}
inline bool isect_equal(const tr_isect &x, const tr_isect &y)
{
  if (x.n != y.n)
    return false;
  for (int i = 0; i < x.n; i++)
    if (!hit_end_equal(x.end[i], y.end[i]))
      return false;
  return true;
}

inline const char *type_name(int t)
{
  static const char *n[] = {"DEG", "NOD", "EDG", "FAC", "INT"};
  return t >= 0 && t <= 4 ? n[t] : "???";
}
inline const char *seg_name(int s)
{
  static const char *n[] = {"A", "B", "IN"};
  return s >= 0 && s <= 2 ? n[s] : "??";
}
inline void print_hit(const char *what, const tr_hit &h)
{
  fprintf(stderr, "  %s: type %s (%d) code %d on_seg %s (%d)\n", what, type_name(h.type), h.type,
          h.code, seg_name(h.on_seg), h.on_seg);
}
inline void print_isect(const char *what, const tr_isect &r)
{
  fprintf(stderr, "  %s: n = %d\n", what, r.n);
  for (int i = 0; i < r.n && i < 2; i++) {
    char buf[64];
    snprintf(buf, sizeof buf, "%s end[%d]", what, i);
    print_hit(buf, r.end[i]);
  }
}

// ---- exact checks of a constructed tr_qpoint ----
// lo/hi must be the tightest doubles around c and near the rounding to nearest, ties
// to even. Returns 0 when fine, else the coordinate index + 1.
inline int qpoint_box_error(const tr_qpoint &q)
{
  Q t, dl, dh;
  for (int i = 0; i < 3; i++) {
    const double lo = q.lo[i], hi = q.hi[i], nr = q.near[i];
    // Beyond DBL_MAX qpoint.h specifies a saturated box [DBL_MAX, inf] and IEEE
    // overflow for near: inf from DBL_MAX + ulp(DBL_MAX)/2 = DBL_MAX + 2^970 on.
    mpq_set_d(t.v, DBL_MAX);
    int sg = mpq_sgn(q.c[i]);
    mpq_abs(dl.v, q.c[i]);
    if (mpq_cmp(dl.v, t.v) > 0) {
      double big = sg > 0 ? DBL_MAX : -DBL_MAX, inf = sg > 0 ? INFINITY : -INFINITY;
      mpq_set_d(dh.v, std::ldexp(1.0, 970));
      mpq_add(t.v, t.v, dh.v);
      double want = mpq_cmp(dl.v, t.v) >= 0 ? inf : big;
      if ((sg > 0 ? (lo != big || hi != inf) : (lo != inf || hi != big)) || nr != want)
        return i + 1;
      continue;
    }
    if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(nr))
      return i + 1;
    mpq_set_d(dl.v, lo);
    mpq_set_d(dh.v, hi);
    if (mpq_cmp(dl.v, q.c[i]) > 0 || mpq_cmp(dh.v, q.c[i]) < 0)
      return i + 1;
    if (lo == hi) {
      if (!mpq_equal(dl.v, q.c[i]) || nr != lo)
        return i + 1;
      continue;
    }
    // c strictly between two doubles: they must be adjacent and c equal to neither
    if (std::nextafter(lo, INFINITY) != hi || mpq_equal(dl.v, q.c[i]) || mpq_equal(dh.v, q.c[i]))
      return i + 1;
    // nearest: compare c - lo with hi - c
    mpq_sub(dl.v, q.c[i], dl.v);
    mpq_sub(dh.v, dh.v, q.c[i]);
    int cmp = mpq_cmp(dl.v, dh.v);
    double want;
    if (cmp < 0)
      want = lo;
    else if (cmp > 0)
      want = hi;
    else {
      // tie: the one with an even significand (its last bit is 0)
      uint64_t bl;
      memcpy(&bl, &lo, 8);
      want = (bl & 1) == 0 ? lo : hi;
    }
    if (nr != want)
      return i + 1;
  }
  return 0;
}

inline void print_qpoint_box(const tr_qpoint &q)
{
  for (int i = 0; i < 3; i++)
    gmp_fprintf(stderr, "  c[%d] = %Qd: lo %a hi %a near %a\n", i, q.c[i], q.lo[i], q.hi[i],
                q.near[i]);
}

inline bool qpoint_equals(const tr_qpoint &q, const P3 &p)
{
  return ft_equals_mpq(p.x(), q.c[0]) && ft_equals_mpq(p.y(), q.c[1]) && ft_equals_mpq(p.z(), q.c[2]);
}

}  // namespace tro

#endif
