// The predicate headers compile and link as C++ (extern "C" guards): calls one
// function of each so a missing guard shows up as a link error.
#include <cstdio>

#include "classify.h"
#include "construct.h"
#include "predicates.h"
#include "qpoint.h"

int main()
{
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  tr_point A = tr_pt_d(a), B = tr_pt_d(b), C = tr_pt_d(c), D = tr_pt_d(d);
  tr_qpoint x;
  tr_qpoint_init(&x);
  int ok = tr_orient3d_p(&A, &B, &C, &D) == 1 && tr_sign(tr_orient3d(a, b, c, d)) == 1;
  ok = ok && tr_construct_line_plane(&A, &D, &A, &B, &C, &x) == 0;
  tr_point X = tr_pt_q(&x);
  ok = ok && tr_classify_point_segment(&X, &A, &D).type == TR_NOD;
  tr_qpoint_clear(&x);
  tr_exact_scratch_free();
  if (!ok) {
    std::fprintf(stderr, "FAIL [headers_compile_as_cpp]: wrong results through C++\n");
    return 1;
  }
  std::printf("headers_compile_as_cpp: ok\n");
  return 0;
}
