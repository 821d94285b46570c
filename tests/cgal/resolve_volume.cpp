// The solid of a soup (src/resolve: arrangement, winding number >= 1) against CGAL's
// exact booleans: the union of the soup's closed parts as Nef polyhedra over Epeck, its
// volume summed exactly, equal as a rational to tr_solid_volume6 (not close: equal).
//
//   cgal_resolve_volume corpus DIR     the resolve corpus (tests/data/resolve_*.off; each
//                                      connected part of a file is one closed shape)
//   cgal_resolve_volume random [N]     N random unions (default 200, $TETREC_RESOLVE_CROSSCHECK_N;
//                                      not the predicates' $TETREC_CROSSCHECK_N, which CI sets
//                                      to 100000: a Nef union costs thousands of those)
//                                      of 2 to 4 boxes and tetrahedra on a small integer
//                                      grid: duplicates, shared faces, edges and corners
//                                      are common; every third union turned by a rational
//                                      rotation and rounded to doubles, every fifth
//                                      scaled by 2^k, k in [-600, 600]
#include "cgal_oracle.hpp"

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include "core/plc.h"
#include "resolve/resolve.h"
}

namespace {

typedef CGAL::Polyhedron_3<tro::K> Poly;
typedef CGAL::Nef_polyhedron_3<tro::K> Nef;
typedef std::vector<std::size_t> Polygon;

int failures = 0;

// 6 times the volume of the marked part of nef, by the divergence theorem over the
// halffacets between a marked and an unmarked volume: a facet in the plane
// a x + b y + c z + d = 0 contributes -d * (2 * its signed area projected along an axis
// whose coefficient k is not 0) / k, the cycles (holes included) as the halffacet orders
// them. Every boundary halffacet is taken from the same side, so the sum is the volume up
// to one sign for all, which the absolute value fixes. Exact (Epeck), no triangulation.
tro::FT nef_volume6(const Nef &nef)
{
  tro::FT total = 0;
  for (Nef::Halffacet_const_iterator f = nef.halffacets_begin(); f != nef.halffacets_end();
       ++f) {
    if (!f->incident_volume()->mark() || f->twin()->incident_volume()->mark())
      continue;
    const tro::K::Plane_3 pl = f->plane();
    tro::FT co[3] = {pl.a(), pl.b(), pl.c()};
    int ax = !CGAL::is_zero(co[2]) ? 2 : !CGAL::is_zero(co[1]) ? 1 : 0;
    int u = (ax + 1) % 3, v = (ax + 2) % 3;
    tro::FT area2 = 0;
    for (Nef::Halffacet_cycle_const_iterator fc = f->facet_cycles_begin();
         fc != f->facet_cycles_end(); ++fc) {
      if (!fc.is_shalfedge())
        continue;
      Nef::SHalfedge_const_handle h = fc;
      Nef::SHalfedge_around_facet_const_circulator c(h), end(c);
      std::vector<tro::P3> cyc;
      CGAL_For_all(c, end) cyc.push_back(c->source()->center_vertex()->point());
      for (size_t i = 0; i < cyc.size(); i++) {
        const tro::P3 &p = cyc[i], &q = cyc[(i + 1) % cyc.size()];
        area2 += p[u] * q[v] - q[u] * p[v];
      }
    }
    total += -pl.d() * area2 / co[ax];
  }
  return CGAL::abs(total);
}

// The union of the closed parts (connected by shared vertex indices) of plc.
Nef union_of_parts(const tr_plc *plc)
{
  uint32_t n = plc->npoints;
  std::vector<uint32_t> par(n);
  for (uint32_t i = 0; i < n; i++)
    par[i] = i;
  auto find = [&](uint32_t x) {
    while (par[x] != x)
      x = par[x] = par[par[x]];
    return x;
  };
  for (uint32_t t = 0; t < plc->ntris; t++)
    for (int k = 1; k < 3; k++) {
      uint32_t a = find(plc->tris[3 * t]), b = find(plc->tris[3 * t + k]);
      if (a != b)
        par[a > b ? a : b] = a < b ? a : b;
    }
  Nef u;
  std::vector<uint32_t> roots;
  for (uint32_t t = 0; t < plc->ntris; t++) {
    uint32_t r = find(plc->tris[3 * t]);
    bool seen = false;
    for (uint32_t x : roots)
      seen |= x == r;
    if (!seen)
      roots.push_back(r);
  }
  for (uint32_t r : roots) {
    std::vector<tro::P3> pts;
    std::vector<Polygon> polys;
    std::vector<std::size_t> id(n, SIZE_MAX);
    for (uint32_t t = 0; t < plc->ntris; t++) {
      if (find(plc->tris[3 * t]) != r)
        continue;
      Polygon p;
      for (int k = 0; k < 3; k++) {
        uint32_t v = plc->tris[3 * t + k];
        if (id[v] == SIZE_MAX) {
          id[v] = pts.size();
          const double *x = plc->xyz + 3 * (size_t)v;
          pts.push_back(tro::P3(x[0], x[1], x[2]));
        }
        p.push_back(id[v]);
      }
      polys.push_back(p);
    }
    Poly poly;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, poly);
    u += Nef(poly);
  }
  return u;
}

// tr_solid_volume6 of plc == 6 * the volume of the union of its parts, exactly.
bool compare(const char *name, const tr_plc *plc)
{
  tr_arrangement a;
  tr_solid s;
  std::memset(&s, 0, sizeof s);
  tro::Q v6;
  tr_status st = tr_arrangement_build(plc, &a);
  if (st == TR_OK)
    st = tr_solid_classify(plc, &a, 0, &s);
  if (st == TR_OK)
    st = tr_solid_volume6(plc, &a, &s, v6.v);
  tr_solid_free(&s);
  tr_arrangement_free(&a);
  if (st != TR_OK) {
    std::fprintf(stderr, "FAIL %s: tetrec: %s\n", name, tr_last_error());
    failures++;
    return false;
  }
  tro::FT w = nef_volume6(union_of_parts(plc));
  if (!tro::ft_equals_mpq(w, v6.v)) {
    std::fprintf(stderr, "FAIL %s: 6V tetrec %.17g, CGAL Nef union %.17g\n", name,
                 mpq_get_d(v6.v), CGAL::to_double(w));
    failures++;
    return false;
  }
  return true;
}

void run_corpus(const char *dir)
{
  static const char *const names[] = {"cubes2", "cubes3", "dupshell", "coplanar", "spheres"};
  static const char *const variants[] = {"", "_rot", "_ulp"};
  int n = 0;
  for (const char *nm : names)
    for (const char *va : variants) {
      std::string path = std::string(dir) + "/resolve_" + nm + va + ".off";
      tr_plc *p = nullptr;
      if (tr_plc_read(path.c_str(), &p) != TR_OK) {
        std::fprintf(stderr, "FAIL %s: %s\n", path.c_str(), tr_last_error());
        failures++;
        continue;
      }
      n += compare(path.c_str(), p);
      tr_plc_destroy(p);
    }
  std::printf("corpus: %d of 15 files: tetrec's solid volume equals CGAL's Nef union exactly\n",
              n);
}

uint64_t next(uint64_t &s)
{
  s = s * 6364136223846793005u + 1442695040888963407u;
  return s >> 33;
}

void run_random(uint64_t count)
{
  static const uint32_t box_tris[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                        2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  // Rz(3/5, 4/5) Rx(5/13, 12/13)
  const double R[3][3] = {{3.0 / 5, -4.0 * 5 / 65, 4.0 * 12 / 65},
                          {4.0 / 5, 3.0 * 5 / 65, -3.0 * 12 / 65},
                          {0, 12.0 / 13, 5.0 / 13}};
  uint64_t seed = 12345, ok = 0;
  for (uint64_t it = 0; it < count; it++) {
    std::vector<double> xyz;
    std::vector<uint32_t> tris;
    int n = 2 + (int)(next(seed) % 3);
    for (int c = 0; c < n; c++) {
      uint32_t base = (uint32_t)(xyz.size() / 3);
      if (next(seed) % 2) { // a box [lo, lo + size]
        double lo[3], sz[3];
        for (int d = 0; d < 3; d++) {
          lo[d] = (double)(next(seed) % 4);
          sz[d] = (double)(1 + next(seed) % 3);
        }
        for (int i = 0; i < 8; i++)
          for (int d = 0; d < 3; d++)
            xyz.push_back(lo[d] + ((i >> d) & 1) * sz[d]);
        for (uint32_t x : box_tris)
          tris.push_back(base + x);
      } else { // a tetrahedron, outward
        double p[4][3];
        double det;
        do {
          for (int i = 0; i < 4; i++)
            for (int d = 0; d < 3; d++)
              p[i][d] = (double)(next(seed) % 5);
          det = tr_orient3d(p[0], p[1], p[2], p[3]);
        } while (det == 0);
        for (int i = 0; i < 4; i++)
          for (int d = 0; d < 3; d++)
            xyz.push_back(p[i][d]);
        // faces seen from outside counterclockwise: with orient3d(a, b, c, d) > 0, d lies
        // on the positive side of (a, b, c)
        uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
        bool flip = det < 0;
        for (auto &t : f) {
          tris.push_back(base + t[0]);
          tris.push_back(base + (flip ? t[2] : t[1]));
          tris.push_back(base + (flip ? t[1] : t[2]));
        }
      }
    }
    if (it % 3 == 1) // turned: rational crossings (the products rounded to doubles)
      for (size_t i = 0; i < xyz.size(); i += 3) {
        double x = xyz[i], y = xyz[i + 1], z = xyz[i + 2];
        for (int d = 0; d < 3; d++)
          xyz[i + d] = R[d][0] * x + R[d][1] * y + R[d][2] * z;
      }
    if (it % 5 == 2) { // scaled by 2^k: the same solid, exponents far from 0
      int k = (int)(next(seed) % 1201) - 600;
      for (double &x : xyz)
        x = std::ldexp(x, k);
    }
    tr_plc *p = nullptr;
    tr_plc_create(&p);
    tr_plc_set(p, xyz.data(), (uint32_t)(xyz.size() / 3), tris.data(),
               (uint32_t)(tris.size() / 3), nullptr);
    char name[64];
    std::snprintf(name, sizeof name, "random union %llu", (unsigned long long)it);
    ok += compare(name, p);
    tr_plc_destroy(p);
  }
  std::printf("random: %llu of %llu unions: tetrec's solid volume equals CGAL's Nef union "
              "exactly\n", (unsigned long long)ok, (unsigned long long)count);
}

} // namespace

int main(int argc, char **argv)
{
  if (argc >= 3 && !std::strcmp(argv[1], "corpus"))
    run_corpus(argv[2]);
  else if (argc >= 2 && !std::strcmp(argv[1], "random")) {
    const char *e = std::getenv("TETREC_RESOLVE_CROSSCHECK_N");
    uint64_t n = argc >= 3 ? std::strtoull(argv[2], nullptr, 10) : e ? std::strtoull(e, nullptr, 10) : 200;
    run_random(n);
  } else {
    std::fprintf(stderr, "usage: cgal_resolve_volume corpus DIR | random [N]\n");
    return 2;
  }
  return failures != 0;
}
