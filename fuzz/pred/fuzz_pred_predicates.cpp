// libFuzzer target: adaptive double predicates, symbolic perturbation and the
// predicates on rational points, against CGAL (Epick and Epeck must both agree).
// Byte 0 picks the check, the rest drives the generator (fuzz/oracle/gen.hpp).
#include "checks.hpp"

#include <cstdlib>

bool tro::g_also_epeck = true;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static tro::Case c;  // keeps its rational pool between runs
  if (size == 0)
    return 0;
  tro::Bytes b{data + 1, size - 1};
  int r;
  switch (data[0] % 7) {
  case 0: r = tro::check_orient2d(b, c); break;
  case 1: r = tro::check_orient2d_proj(b, c); break;
  case 2: r = tro::check_incircle(b, c); break;
  case 3: r = tro::check_orient3d(b, c); break;
  case 4: r = tro::check_insphere(b, c); break;
  case 5: r = tro::check_sos(b, c); break;
  default: r = tro::check_qpoint_predicates(b, c); break;
  }
  if (r == 0)
    abort();
  return 0;
}
