// libFuzzer target: the five intersection classifiers against an independent
// classification on Epeck (CGAL intersection() plus exact location of each end).
// Byte 0 picks the classifier.
#include "checks.hpp"

#include <cstdlib>

bool tro::g_also_epeck = true;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static tro::Case c;
  if (size == 0)
    return 0;
  tro::Bytes b{data + 1, size - 1};
  int r;
  switch (data[0] % 5) {
  case 0: r = tro::check_point_segment(b, c); break;
  case 1: r = tro::check_point_triangle(b, c); break;
  case 2: r = tro::check_segment_segment(b, c); break;
  case 3: r = tro::check_segment_triangle(b, c); break;
  default: r = tro::check_segment_tet(b, c); break;
  }
  if (r == 0)
    abort();
  return 0;
}
