/* Hand-built degenerate cases for the exact classifiers, one property per case. The
 * unit tet T = (0,0,0), (1,0,0), (0,1,0), (0,0,1) is positive; face k is opposite
 * vertex k. Every case also runs scaled by 2^-498 and 2^498 (about 1e-150 and 1e150):
 * power-of-two scaling keeps every degeneracy exact. */
#include <math.h>

#include "check.h"
#include "classify.h"
#include "construct.h"
#include "qpoint.h"

static double S = 1.0; /* current scale */
static double P[16][3];
static int np;

static tr_point pt(double x, double y, double z)
{
  double *p = P[np++ % 16];
  p[0] = x * S, p[1] = y * S, p[2] = z * S;
  return tr_pt_d(p);
}

static const char *tname(int t)
{
  static const char *n[] = {"DEG", "NOD", "EDG", "FAC", "INT"};
  return t >= 0 && t <= 4 ? n[t] : "?";
}

static void expect(tr_isect r, int n, int t0, int c0, int s0, int t1, int c1, int s1,
                   const char *what)
{
  int ok = r.n == n;
  if (ok && n >= 1)
    ok = r.end[0].type == t0 && r.end[0].code == c0 && r.end[0].on_seg == s0;
  if (ok && n == 2)
    ok = r.end[1].type == t1 && r.end[1].code == c1 && r.end[1].on_seg == s1;
  CHECK(ok, "%s (scale %g): got n=%d [%s %d seg%d] [%s %d seg%d]", what, S, r.n,
        tname(r.end[0].type), r.end[0].code, r.end[0].on_seg, tname(r.end[1].type),
        r.end[1].code, r.end[1].on_seg);
}

#define E(a, b) tr_ecode(a, b)
enum { A_ = TR_SEG_A, B_ = TR_SEG_B, I_ = TR_SEG_IN };

static tr_isect seg_tet(tr_point a, tr_point b)
{
  tr_point t0 = pt(0, 0, 0), t1 = pt(1, 0, 0), t2 = pt(0, 1, 0), t3 = pt(0, 0, 1);
  const tr_point *t[4] = {&t0, &t1, &t2, &t3};
  return tr_classify_segment_tet(&a, &b, t);
}

static tr_isect seg_tri(tr_point a, tr_point b)
{
  tr_point t0 = pt(0, 0, 0), t1 = pt(1, 0, 0), t2 = pt(0, 1, 0);
  return tr_classify_segment_triangle(&a, &b, &t0, &t1, &t2);
}

static tr_isect seg_seg(tr_point a, tr_point b, tr_point c, tr_point d)
{
  return tr_classify_segment_segment(&a, &b, &c, &d);
}

/* runs body at the three scales */
#define SCALED(...)                               \
  do {                                            \
    static const int ex[3] = {0, -498, 498};      \
    for (int s_ = 0; s_ < 3; s_++) {              \
      S = ldexp(1.0, ex[s_]);                     \
      __VA_ARGS__;                                \
    }                                             \
    S = 1.0;                                      \
  } while (0)

static void seg_tet_through_vertices(void)
{
  SCALED({
    expect(seg_tet(pt(-1, -1, -1), pt(1, 1, 1)), 2, TR_NOD, 0, I_, TR_FAC, 0, I_,
           "enters at vertex 0, leaves through face 0");
    expect(seg_tet(pt(1, 0, 0), pt(0, 0, 1)), 2, TR_NOD, 1, A_, TR_NOD, 3, B_,
           "segment equal to edge 1-3");
    expect(seg_tet(pt(2, -1, 0), pt(-1, 2, 0)), 2, TR_NOD, 1, I_, TR_NOD, 2, I_,
           "line through vertices 1 and 2");
  });
}

static void seg_tet_along_edge(void)
{
  SCALED({
    expect(seg_tet(pt(-1, 0, 0), pt(2, 0, 0)), 2, TR_NOD, 0, I_, TR_NOD, 1, I_,
           "through edge 0-1 from outside to outside");
    expect(seg_tet(pt(0.25, 0, 0), pt(0.75, 0, 0)), 2, TR_EDG, E(0, 1), A_, TR_EDG, E(0, 1), B_,
           "inside edge 0-1");
    expect(seg_tet(pt(0.5, 0, 0), pt(3, 0, 0)), 2, TR_EDG, E(0, 1), A_, TR_NOD, 1, I_,
           "from inside edge 0-1 out through vertex 1");
  });
}

static void seg_tet_crosses_only_an_edge(void)
{
  SCALED({
    expect(seg_tet(pt(0.5, 0.5, -1), pt(0.5, 0.5, 1)), 1, TR_EDG, E(1, 2), I_, 0, 0, 0,
           "EDG_DEG: crosses edge 1-2 only");
    expect(seg_tet(pt(0.5, 0.5, 0), pt(0.5, 0.5, 1)), 1, TR_EDG, E(1, 2), A_, 0, 0, 0,
           "starts on edge 1-2 and leaves");
    expect(seg_tet(pt(-1, 0.5, 0.5), pt(1, 0.5, 0.5)), 1, TR_EDG, E(2, 3), I_, 0, 0, 0,
           "crosses edge 2-3 only");
  });
}

static void seg_tet_touches_a_vertex(void)
{
  SCALED({
    expect(seg_tet(pt(1, -1, -1), pt(1, 1, 1)), 1, TR_NOD, 1, I_, 0, 0, 0,
           "touches vertex 1 only");
    expect(seg_tet(pt(0, 0, 1), pt(1, 1, 2)), 1, TR_NOD, 3, A_, 0, 0, 0,
           "starts at vertex 3 going out");
    expect(seg_tet(pt(-1, -1, -1), pt(0, 0, 0)), 1, TR_NOD, 0, B_, 0, 0, 0,
           "ends at vertex 0 from outside");
  });
}

static void seg_tet_in_face_plane(void)
{
  SCALED({
    expect(seg_tet(pt(-1, 0.25, 0), pt(2, 0.25, 0)), 2, TR_EDG, E(0, 2), I_, TR_EDG, E(1, 2), I_,
           "across face 3 in its plane, edge to edge");
    expect(seg_tet(pt(0.25, 0.25, 0), pt(2, 0.25, 0)), 2, TR_FAC, 3, A_, TR_EDG, E(1, 2), I_,
           "from inside face 3 out through edge 1-2");
    expect(seg_tet(pt(0.1, 0.1, 0), pt(0.2, 0.3, 0)), 2, TR_FAC, 3, A_, TR_FAC, 3, B_,
           "inside face 3");
    expect(seg_tet(pt(-1, 0.5, 0), pt(0.5, -1, 0)), 0, 0, 0, 0, 0, 0, 0,
           "in the plane of face 3, outside it");
    expect(seg_tet(pt(2, -1, 0), pt(-1, 0.5, 0)), 1, TR_NOD, 0, I_, 0, 0, 0,
           "in the plane of face 3, touching vertex 0");
  });
}

static void seg_tet_endpoints_inside(void)
{
  SCALED({
    expect(seg_tet(pt(0.125, 0.125, 0.125), pt(2, 2, 2)), 2, TR_INT, 0, A_, TR_FAC, 0, I_,
           "from inside out through face 0");
    expect(seg_tet(pt(0.125, 0.125, 0.125), pt(0.25, 0.125, 0.25)), 2, TR_INT, 0, A_, TR_INT, 0, B_,
           "entirely inside");
    expect(seg_tet(pt(0.25, 0.25, 0.25), pt(0.25, 0.25, 0.25)), 1, TR_INT, 0, A_, 0, 0, 0,
           "degenerate segment inside");
    expect(seg_tet(pt(0.25, 0.25, 2), pt(0.25, 0.25, -2)), 2, TR_FAC, 0, I_, TR_FAC, 3, I_,
           "through faces 0 and 3");
  });
}

static void seg_tet_one_ulp_off(void)
{
  SCALED({
    double u = nextafter(S, 2 * S) / S; /* 1 + ulp at this scale */
    double d = nextafter(S, 0) / S;     /* 1 - ulp/2 */
    expect(seg_tet(pt(u, -1, -1), pt(u, 1, 1)), 0, 0, 0, 0, 0, 0, 0,
           "one ulp beyond vertex 1: disjoint");
    expect(seg_tet(pt(d, -1, -1), pt(d, 1, 1)), 2, TR_EDG, E(0, 1), I_, TR_FAC, 0, I_,
           "half an ulp inside vertex 1: enters on edge 0-1, leaves by face 0");
    expect(seg_tet(pt(-1, 0, -0x1p-60), pt(2, 0, -0x1p-60)), 0, 0, 0, 0, 0, 0, 0,
           "2^-60 below edge 0-1: disjoint");
  });
}

static void seg_tri_transversal(void)
{
  SCALED({
    expect(seg_tri(pt(0.25, 0.25, -1), pt(0.25, 0.25, 1)), 1, TR_FAC, 3, I_, 0, 0, 0,
           "through the interior");
    expect(seg_tri(pt(0.5, 0, -1), pt(0.5, 0, 1)), 1, TR_EDG, E(0, 1), I_, 0, 0, 0,
           "through edge 0-1");
    expect(seg_tri(pt(0.5, 0.5, -1), pt(0.5, 0.5, 1)), 1, TR_EDG, E(1, 2), I_, 0, 0, 0,
           "through edge 1-2");
    expect(seg_tri(pt(-1, 1, 1), pt(1, 1, -1)), 1, TR_NOD, 2, I_, 0, 0, 0, "through vertex 2");
    expect(seg_tri(pt(0.75, 0.75, -1), pt(0.75, 0.75, 1)), 0, 0, 0, 0, 0, 0, 0,
           "misses outside edge 1-2");
    expect(seg_tri(pt(0.25, 0.25, 0.5), pt(0.25, 0.25, 1)), 0, 0, 0, 0, 0, 0, 0,
           "above the plane");
  });
}

static void seg_tri_touching_endpoint(void)
{
  SCALED({
    expect(seg_tri(pt(0.25, 0.25, 0), pt(3, 1, 1)), 1, TR_FAC, 3, A_, 0, 0, 0,
           "a in the interior");
    expect(seg_tri(pt(3, 1, 1), pt(0, 0.5, 0)), 1, TR_EDG, E(0, 2), B_, 0, 0, 0, "b on edge 0-2");
    expect(seg_tri(pt(1, 0, 0), pt(1, 1, 1)), 1, TR_NOD, 1, A_, 0, 0, 0, "a at vertex 1");
    expect(seg_tri(pt(2, 2, 0), pt(1, 1, 1)), 0, 0, 0, 0, 0, 0, 0, "a in the plane outside");
  });
}

static void seg_tri_coplanar(void)
{
  SCALED({
    expect(seg_tri(pt(-1, 0.25, 0), pt(2, 0.25, 0)), 2, TR_EDG, E(0, 2), I_, TR_EDG, E(1, 2), I_,
           "crossing edge to edge");
    expect(seg_tri(pt(2, 0.25, 0), pt(-1, 0.25, 0)), 2, TR_EDG, E(1, 2), I_, TR_EDG, E(0, 2), I_,
           "reversed: ends swap");
    expect(seg_tri(pt(-1, -1, 0), pt(1, 1, 0)), 2, TR_NOD, 0, I_, TR_EDG, E(1, 2), I_,
           "through vertex 0 and edge 1-2");
    expect(seg_tri(pt(-1, 0, 0), pt(0.5, 0, 0)), 2, TR_NOD, 0, I_, TR_EDG, E(0, 1), B_,
           "along edge 0-1, ending inside it");
    expect(seg_tri(pt(-1, 2, 0), pt(2, -1, 0)), 2, TR_NOD, 2, I_, TR_NOD, 1, I_,
           "along the line of edge 1-2");
    expect(seg_tri(pt(0.125, 0.125, 0), pt(0.25, 0.5, 0)), 2, TR_FAC, 3, A_, TR_FAC, 3, B_,
           "inside");
    expect(seg_tri(pt(-1, 1, 0), pt(1, -1, 0)), 1, TR_NOD, 0, I_, 0, 0, 0,
           "touching vertex 0 only");
    expect(seg_tri(pt(1, 1, 0), pt(2, 0, 0)), 0, 0, 0, 0, 0, 0, 0, "disjoint");
    expect(seg_tri(pt(0.5, 0.5, 0), pt(2, 2, 0)), 1, TR_EDG, E(1, 2), A_, 0, 0, 0,
           "from edge 1-2 outwards");
  });
}

static void seg_seg_crossing_and_touching(void)
{
  SCALED({
    expect(seg_seg(pt(0, 0, 0), pt(2, 2, 2), pt(2, 0, 2), pt(0, 2, 0)), 1, TR_EDG, E(0, 1), I_, 0,
           0, 0, "proper crossing in 3D");
    expect(seg_seg(pt(1, 1, 1), pt(3, 3, 3), pt(2, 0, 2), pt(0, 2, 0)), 1, TR_EDG, E(0, 1), A_, 0,
           0, 0, "T junction at a");
    expect(seg_seg(pt(0, 0, 0), pt(1, 1, 0), pt(1, 1, 0), pt(2, 0, 0)), 1, TR_NOD, 0, B_, 0, 0, 0,
           "shared endpoint b = c");
    expect(seg_seg(pt(0, 0, 0), pt(2, 0, 0), pt(1, -1, 0), pt(1, 1, 0)), 1, TR_EDG, E(0, 1), I_, 0,
           0, 0, "cross");
    expect(seg_seg(pt(0, 0, 0), pt(2, 0, 0), pt(1, 0, 0), pt(1, 1, 0)), 1, TR_NOD, 0, I_, 0, 0, 0,
           "c on the interior of ab");
    expect(seg_seg(pt(0, 0, 0), pt(2, 0, 0), pt(1, 0.5, 0), pt(1, 1, 0)), 0, 0, 0, 0, 0, 0, 0,
           "c off ab");
    expect(seg_seg(pt(0, 0, 0), pt(2, 0, 0), pt(0, 1, 0), pt(2, 1, 0)), 0, 0, 0, 0, 0, 0, 0,
           "parallel");
    expect(seg_seg(pt(0, 0, 0), pt(2, 0, 0), pt(1, -1, 0x1p-70), pt(1, 1, 0x1p-70)), 0, 0, 0, 0,
           0, 0, 0, "skew by 2^-70");
  });
}

static void seg_seg_collinear_overlap(void)
{
  SCALED({
    expect(seg_seg(pt(0, 0, 0), pt(2, 2, 2), pt(1, 1, 1), pt(3, 3, 3)), 2, TR_NOD, 0, I_, TR_EDG,
           E(0, 1), B_, "partial overlap");
    expect(seg_seg(pt(0, 0, 0), pt(4, 0, 0), pt(3, 0, 0), pt(1, 0, 0)), 2, TR_NOD, 1, I_, TR_NOD, 0,
           I_, "cd inside ab, reversed");
    expect(seg_seg(pt(1, 0, 0), pt(2, 0, 0), pt(0, 0, 0), pt(3, 0, 0)), 2, TR_EDG, E(0, 1), A_,
           TR_EDG, E(0, 1), B_, "ab inside cd");
    expect(seg_seg(pt(0, 0, 0), pt(1, 0, 0), pt(0, 0, 0), pt(1, 0, 0)), 2, TR_NOD, 0, A_, TR_NOD, 1,
           B_, "identical");
    expect(seg_seg(pt(0, 0, 0), pt(1, 0, 0), pt(1, 0, 0), pt(0, 0, 0)), 2, TR_NOD, 1, A_, TR_NOD, 0,
           B_, "identical, reversed");
    expect(seg_seg(pt(0, 1, 0), pt(0, 2, 0), pt(0, 2, 0), pt(0, 3, 0)), 1, TR_NOD, 0, B_, 0, 0, 0,
           "collinear touching at one point");
    expect(seg_seg(pt(0, 1, 0), pt(0, 2, 0), pt(0, 3, 0), pt(0, 4, 0)), 0, 0, 0, 0, 0, 0, 0,
           "collinear disjoint");
    double u = nextafter(2 * S, 3 * S) / S;
    expect(seg_seg(pt(0, 1, 0), pt(0, 2, 0), pt(0, u, 0), pt(0, 4, 0)), 0, 0, 0, 0, 0, 0, 0,
           "collinear, one ulp apart");
  });
}

static void point_classifiers(void)
{
  SCALED({
    tr_point a = pt(0, 0, 0), b = pt(2, 2, 2), m = pt(1, 1, 1), o = pt(1, 1, 1.5), f = pt(3, 3, 3);
    tr_hit h = tr_classify_point_segment(&m, &a, &b);
    CHECK(h.type == TR_EDG && h.code == E(0, 1), "midpoint is EDG");
    h = tr_classify_point_segment(&b, &a, &b);
    CHECK(h.type == TR_NOD && h.code == 1, "b is NOD 1");
    h = tr_classify_point_segment(&o, &a, &b);
    CHECK(h.type == TR_DEG, "off the line is DEG");
    h = tr_classify_point_segment(&f, &a, &b);
    CHECK(h.type == TR_DEG, "on the line beyond b is DEG");
    tr_point t0 = pt(0, 0, 0), t1 = pt(1, 0, 0), t2 = pt(0, 1, 0);
    tr_point in = pt(0.25, 0.25, 0), e12 = pt(0.5, 0.5, 0), up = pt(0.25, 0.25, 0x1p-80),
             out = pt(0.75, 0.75, 0);
    h = tr_classify_point_triangle(&in, &t0, &t1, &t2);
    CHECK(h.type == TR_FAC && h.code == 3, "interior is FAC 3");
    h = tr_classify_point_triangle(&e12, &t0, &t1, &t2);
    CHECK(h.type == TR_EDG && h.code == E(1, 2), "on edge 1-2");
    h = tr_classify_point_triangle(&t2, &t0, &t1, &t2);
    CHECK(h.type == TR_NOD && h.code == 2, "vertex 2");
    h = tr_classify_point_triangle(&up, &t0, &t1, &t2);
    CHECK(h.type == TR_DEG, "2^-80 above the plane is DEG");
    h = tr_classify_point_triangle(&out, &t0, &t1, &t2);
    CHECK(h.type == TR_DEG, "outside in the plane is DEG");
  });
}

/* Rational Steiner points built by the constructions classify exactly. */
static void steiner_points_classify_exactly(void)
{
  SCALED({
    tr_point v0 = pt(0, 0, 0), v1 = pt(1, 0, 0), v2 = pt(0, 1, 0), v3 = pt(0, 0, 1);
    const tr_point *t[4] = {&v0, &v1, &v2, &v3};
    /* X = edge v1v2 cut by the plane x = y/2: (1/3, 2/3, 0), not a double */
    tr_point p0 = pt(0, 0, 0), p1 = pt(0, 0, 1), p2 = pt(1, 2, 0);
    tr_qpoint x, y;
    tr_qpoint_init(&x);
    tr_qpoint_init(&y);
    CHECK(tr_construct_line_plane(&v1, &v2, &p0, &p1, &p2, &x) == 0, "construct on edge 1-2");
    CHECK(x.lo[0] < x.hi[0], "the Steiner point is not a double");
    tr_point X = tr_pt_q(&x);
    tr_hit h = tr_classify_point_segment(&X, &v1, &v2);
    CHECK(h.type == TR_EDG, "Steiner point on edge v1v2 is EDG");
    h = tr_classify_point_triangle(&X, &v0, &v1, &v2);
    CHECK(h.type == TR_EDG && h.code == E(1, 2), "Steiner point on triangle edge 1-2");
    expect(tr_classify_segment_tet(&X, &v3, t), 2, TR_EDG, E(1, 2), A_, TR_NOD, 3, B_,
           "segment from the Steiner point to vertex 3 (in face 0)");
    expect(tr_classify_segment_tet(&X, &v0, t), 2, TR_EDG, E(1, 2), A_, TR_NOD, 0, B_,
           "segment from the Steiner point to vertex 0 (in face 3)");
    /* Y = (1/3,1/3,1/3): line v0 -> (1,1,1) cut by the plane of face 0 */
    tr_point g = pt(1, 1, 1);
    CHECK(tr_construct_line_plane(&v0, &g, &v1, &v2, &v3, &y) == 0, "construct in face 0");
    tr_point Y = tr_pt_q(&y);
    h = tr_classify_point_triangle(&Y, &v1, &v2, &v3);
    CHECK(h.type == TR_FAC && h.code == 3, "Steiner point inside triangle v1v2v3");
    expect(tr_classify_segment_tet(&v0, &Y, t), 2, TR_NOD, 0, A_, TR_FAC, 0, B_,
           "vertex 0 to the Steiner point on face 0");
    expect(tr_classify_segment_tet(&X, &Y, t), 2, TR_EDG, E(1, 2), A_, TR_FAC, 0, B_,
           "Steiner point on edge 1-2 to Steiner point on face 0");
    expect(tr_classify_segment_triangle(&X, &Y, &v1, &v2, &v3), 2, TR_EDG, E(0, 1), A_, TR_FAC, 3,
           B_, "both Steiner points in the plane of v1v2v3");
    /* line-line: 2x + y = 2 and y = x meet at (2/3, 2/3, 0), not a double; the Steiner
     * point classifies as EDG on both segments */
    tr_point s0 = pt(1, 0, 0), s1 = pt(0, 2, 0), s2 = pt(0, 0, 0), s3 = pt(1, 1, 0);
    CHECK(tr_construct_line_line(&s0, &s1, &s2, &s3, &x) == 0, "diagonals meet");
    h = tr_classify_point_segment(&X, &s0, &s1);
    CHECK(h.type == TR_EDG, "line-line point on the first segment");
    h = tr_classify_point_segment(&X, &s2, &s3);
    CHECK(h.type == TR_EDG, "line-line point on the second segment");
    CHECK(x.lo[0] < x.hi[0], "the line-line point is not a double");
    expect(tr_classify_segment_segment(&s0, &s1, &X, &s3), 1, TR_NOD, 0, I_, 0, 0, 0,
           "segment from the line-line point touches s0s1 at its start");
    tr_qpoint_clear(&x);
    tr_qpoint_clear(&y);
  });
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"seg_tet_through_vertices", seg_tet_through_vertices},
      {"seg_tet_along_edge", seg_tet_along_edge},
      {"seg_tet_crosses_only_an_edge", seg_tet_crosses_only_an_edge},
      {"seg_tet_touches_a_vertex", seg_tet_touches_a_vertex},
      {"seg_tet_in_face_plane", seg_tet_in_face_plane},
      {"seg_tet_endpoints_inside", seg_tet_endpoints_inside},
      {"seg_tet_one_ulp_off", seg_tet_one_ulp_off},
      {"seg_tri_transversal", seg_tri_transversal},
      {"seg_tri_touching_endpoint", seg_tri_touching_endpoint},
      {"seg_tri_coplanar", seg_tri_coplanar},
      {"seg_seg_crossing_and_touching", seg_seg_crossing_and_touching},
      {"seg_seg_collinear_overlap", seg_seg_collinear_overlap},
      {"point_classifiers", point_classifiers},
      {"steiner_points_classify_exactly", steiner_points_classify_exactly},
  };
  int r = check_main(argc, argv, cases, (int)(sizeof cases / sizeof cases[0]));
  tr_exact_scratch_free();
  return r;
}
