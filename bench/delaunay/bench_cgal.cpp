// CGAL peer for the Delaunay benchmark: Delaunay_triangulation_3 with Epick, built by
// range insertion (which spatially sorts the points). Reads the .bin of bench_tetrec.
//   bench_cgal in.bin   ->  "cgal n=.. tets=.. dt_seconds=.. dt_cpu=.." (wall, CPU)
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_3<K> DT;

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_cgal in.bin\n");
    return 2;
  }
  FILE *f = std::fopen(argv[1], "rb");
  uint32_t n;
  if (!f || std::fread(&n, 4, 1, f) != 1) {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 1;
  }
  std::vector<double> c(3 * (size_t)n);
  if (std::fread(c.data(), sizeof(double), c.size(), f) != c.size()) {
    std::fprintf(stderr, "short file\n");
    return 1;
  }
  std::fclose(f);
  std::vector<K::Point_3> pts;
  pts.reserve(n);
  for (size_t i = 0; i < n; i++)
    pts.emplace_back(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
  auto t0 = std::chrono::steady_clock::now();
  std::clock_t c0 = std::clock();
  DT dt(pts.begin(), pts.end());
  std::clock_t c1 = std::clock();
  auto t1 = std::chrono::steady_clock::now();
  std::printf("cgal n=%u tets=%zu dt_seconds=%.3f dt_cpu=%.3f\n", n,
              (size_t)dt.number_of_finite_cells(),
              std::chrono::duration<double>(t1 - t0).count(),
              (double)(c1 - c0) / CLOCKS_PER_SEC);
  return 0;
}
