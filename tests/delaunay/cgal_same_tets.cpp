// Cross-check against CGAL: on random (general position) points the Delaunay
// tetrahedralization is unique, so tetrec's real tets must be exactly CGAL's finite
// cells (as sets of 4 input indices). Usage: cgal_same_tets <npoints> <seed>.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "delaunay/delaunay.h"
#include "mesh/mesh.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_3<unsigned, K> Vb;
typedef CGAL::Triangulation_data_structure_3<Vb> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> DT;
typedef std::array<uint32_t, 4> Tet;

int main(int argc, char **argv)
{
  unsigned n = argc > 1 ? (unsigned)std::atoi(argv[1]) : 1000;
  unsigned long long s = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  std::vector<double> xyz(3 * (size_t)n);
  for (double &x : xyz) {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    x = (double)(s >> 11) * 0x1p-53;
  }
  struct tr_mesh *m;
  tr_status st = tr_delaunay_build(xyz.data(), n, &m);
  if (st != TR_OK) {
    std::fprintf(stderr, "FAILED: tr_delaunay_build: %s\n", tr_last_error());
    return 1;
  }
  uint32_t *tets, nt;
  if (tr_mesh_export_tets(m, &tets, &nt) != TR_OK)
    return 1;
  std::vector<Tet> ours(nt);
  for (uint32_t i = 0; i < nt; i++) {
    std::copy(tets + 4 * (size_t)i, tets + 4 * (size_t)i + 4, ours[i].begin());
    std::sort(ours[i].begin(), ours[i].end());
  }
  std::free(tets);
  tr_mesh_destroy(m);

  std::vector<std::pair<K::Point_3, unsigned>> pts;
  for (unsigned i = 0; i < n; i++)
    pts.push_back({K::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), i});
  DT dt(pts.begin(), pts.end());
  std::vector<Tet> theirs;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    Tet t;
    for (int k = 0; k < 4; k++)
      t[k] = c->vertex(k)->info();
    std::sort(t.begin(), t.end());
    theirs.push_back(t);
  }
  std::sort(ours.begin(), ours.end());
  std::sort(theirs.begin(), theirs.end());
  if (ours.size() != theirs.size()) {
    std::fprintf(stderr, "FAILED: number of finite tets: tetrec %zu, CGAL %zu\n", ours.size(),
                 theirs.size());
    return 1;
  }
  if (ours != theirs) {
    std::fprintf(stderr, "FAILED: same count (%zu) but different tets\n", ours.size());
    return 1;
  }
  std::printf("%u points: %zu tets, identical to CGAL's\n", n, ours.size());
  return 0;
}
