// libFuzzer target: exact constructions (line-plane, line-line, Steiner points used
// as inputs again) against CGAL intersection() on Epeck, exact coordinates and the
// double box of each constructed point. Byte 0 picks the check.
#include "checks.hpp"

#include <cstdlib>

bool tro::g_also_epeck = true;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static tro::Case c;
  if (size == 0)
    return 0;
  tro::Bytes b{data + 1, size - 1};
  int r = (data[0] & 1) ? tro::check_line_line(b, c) : tro::check_line_plane(b, c);
  if (r == 0)
    abort();
  return 0;
}
