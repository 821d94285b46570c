// Inputs on which tetrec once disagreed with the CGAL oracle (found by cgal_crosscheck
// while predicates/ was being written), replayed exactly. The expected answers come
// from the oracle (fuzz/oracle), so each case states the property it checks.
#include "checks.hpp"

#include <cstdlib>

bool tro::g_also_epeck = true;

namespace {

int failures = 0;

void expect(bool ok, const char *property)
{
  printf("%s: %s\n", ok ? "ok  " : "FAIL", property);
  if (!ok)
    failures++;
}

// A point given as three rationals "num/den" (exact) or as doubles.
void set_q(tro::Case &c, int i, const char *x, const char *y, const char *z)
{
  const char *s[3] = {x, y, z};
  for (int j = 0; j < 3; j++) {
    mpq_set_str(c.q[i].q.c[j], s[j], 10);
    mpq_canonicalize(c.q[i].q.c[j]);
  }
  c.set_q_from_c(i);
}

// Five coplanar points (three of them equal, one an ulp off): insphere_sos was 0 for
// one argument order and -1 after swapping arguments 1 and 3.
void sos_coplanar_duplicates()
{
  const double p[5][3] = {{-0x1p+1, 0x1p+0, -0x1p+0},
                          {-0x1.fffffffffffffp+0, 0x1.0000000000002p+0, -0x1p+0},
                          {-0x1p+1, 0x1p+0, -0x1p+0},
                          {-0x1p+0, -0x1p+1, -0x1.8p+1},
                          {-0x1p+1, 0x1p+0, -0x1p+0}};
  const uint32_t id[5] = {1927238444u, 1927238257u, 1927238818u, 1927238631u, 1927238070u};
  int s0 = tr_insphere_sos(p[0], p[1], p[2], p[3], p[4], id[0], id[1], id[2], id[3], id[4]);
  int s1 = tr_insphere_sos(p[0], p[3], p[2], p[1], p[4], id[0], id[3], id[2], id[1], id[4]);
  expect(s1 == -s0, "tr_insphere_sos changes sign when arguments 1 and 3 swap (coplanar, duplicates)");
  expect(s0 == 0, "tr_insphere_sos is 0 on five coplanar points (perturb.c)");
}

// A rational point exactly coplanar with three doubles: tr_orient3d_p said -1.
void orient3d_p_rational_coplanar()
{
  tro::Case c;
  set_q(c, 0, "-70920584449/262144", "-75293433393/131072", "443231522507/1048576");
  c.set_d(1, -0x1.0835cea1b4p+18, -0x1.187ee9143ap+19, 0x1.9ccc37b288p+18);
  c.set_d(2, -0x1.08350c03d4p+18, -0x1.187f5f9b5ap+19, 0x1.9ccaba24ep+18);
  c.set_d(3, -0x1.083422db94p+18, -0x1.187ee2a6bap+19, 0x1.9cca287aap+18);
  int want = tro::o_orient3d(c.cg[0], c.cg[1], c.cg[2], c.cg[3]);
  int got = tr_orient3d_p(&c.tp[0], &c.tp[1], &c.tp[2], &c.tp[3]);
  expect(want == 0 && got == want, "tr_orient3d_p(rational, 3 doubles) == 0 on coplanar points");
}

// Segment from a tet vertex (given as a rational equal to it) into a face: tetrec
// reported the start as EDG 1-2 instead of NOD 2.
void segment_tet_vertex_start()
{
  tro::Case c;
  c.set_d(0, -0x1.b08ccccccccccp+10, -0x1.acb3333333333p+9, 0x1.8999999999999p+8);
  set_q(c, 1, "-8639/5", "-4287/5", "1962/5");
  set_q(c, 2, "-1729", "-858", "393");
  c.set_d(3, -0x1.b0b3333333333p+10, -0x1.adp+9, 0x1.8866666666666p+8);
  set_q(c, 4, "-1729", "-858", "393");
  c.set_d(5, -0x1.b08ccccccccccp+10, -0x1.ac99999999999p+9, 0x1.8899999999999p+8);
  const tr_point *t[4] = {&c.tp[0], &c.tp[1], &c.tp[2], &c.tp[3]};
  tr_isect got = tr_classify_segment_tet(&c.tp[4], &c.tp[5], t);
  tr_isect want = tro::o_segment_tet(c.cg[4], c.cg[5], c.cg);
  bool ok = tro::isect_equal(got, want) && want.n == 2 && want.end[0].type == TR_NOD &&
            want.end[0].code == 2;
  if (!ok) {
    tro::print_isect("tetrec", got);
    tro::print_isect("CGAL", want);
  }
  expect(ok, "tr_classify_segment_tet: a segment starting at vertex 2 starts with NOD 2");
}

}  // namespace

int main()
{
  sos_coplanar_duplicates();
  orient3d_p_rational_coplanar();
  segment_tet_vertex_start();
  return failures ? 1 : 0;
}
