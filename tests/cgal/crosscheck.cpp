// Cross-checks tetrec's predicates, constructions and classifiers against CGAL's exact
// kernels on degenerate-by-construction inputs (see fuzz/oracle/gen.hpp).
//
//   cgal_crosscheck CHECK [N]
//
// runs N cases (default 10^6, or $TETREC_CROSSCHECK_N) and stops at the first mismatch,
// printing the input in %a. Case i is generated from its own seed, so a failure is
// replayed alone with TETREC_CROSSCHECK_FIRST=i TETREC_CROSSCHECK_N=1.
#include "checks.hpp"

#include <cstdlib>
#include <cstring>

bool tro::g_also_epeck = false;

namespace {

typedef int (*check_fn)(tro::Rng &, tro::Case &);

struct Entry {
  const char *name;
  check_fn fn;
  const char *property;
  const char *buckets;
};

const char *const SIGNS = "bucket 0/1/2 = sign -1/0/+1";
const char *const TYPES = "bucket = type DEG/NOD/EDG/FAC/INT (0..4) of the point or first end";
const char *const BUILT = "bucket 0 = undefined (-1), 1 = a point was constructed";

const Entry checks[] = {
    {"orient2d", tro::check_orient2d<tro::Rng>, "tr_orient2d sign == CGAL orientation", SIGNS},
    {"orient2d_proj", tro::check_orient2d_proj<tro::Rng>,
     "tr_orient2d_proj sign == CGAL orientation of the projected points", SIGNS},
    {"incircle", tro::check_incircle<tro::Rng>, "tr_incircle sign == CGAL side_of_oriented_circle", SIGNS},
    {"orient3d", tro::check_orient3d<tro::Rng>, "tr_orient3d sign == CGAL orientation", SIGNS},
    {"insphere", tro::check_insphere<tro::Rng>, "tr_insphere sign == CGAL side_of_oriented_sphere", SIGNS},
    {"sos", tro::check_sos<tro::Rng>,
     "tr_orient3d_sos / tr_insphere_sos: exact sign when non-zero, deterministic, alternating", SIGNS},
    {"qpoint_predicates", tro::check_qpoint_predicates<tro::Rng>,
     "tr_orient3d_p, tr_insphere_p, tr_orient2d_proj_p, tr_cmp_coord_p, tr_equal_p on rational "
     "points == Epeck; tr_qpoint_update boxes tight", SIGNS},
    {"construct_line_plane", tro::check_line_plane<tro::Rng>,
     "tr_construct_line_plane == CGAL intersection(Line_3, Plane_3), exact coordinates", BUILT},
    {"construct_line_line", tro::check_line_line<tro::Rng>,
     "tr_construct_line_line == CGAL intersection(Line_3, Line_3), exact coordinates", BUILT},
    {"classify_point_segment", tro::check_point_segment<tro::Rng>,
     "tr_classify_point_segment == oracle on Epeck", TYPES},
    {"classify_point_triangle", tro::check_point_triangle<tro::Rng>,
     "tr_classify_point_triangle == oracle on Epeck", TYPES},
    {"classify_segment_segment", tro::check_segment_segment<tro::Rng>,
     "tr_classify_segment_segment == oracle on Epeck", TYPES},
    {"classify_segment_triangle", tro::check_segment_triangle<tro::Rng>,
     "tr_classify_segment_triangle == oracle on Epeck", TYPES},
    {"classify_segment_tet", tro::check_segment_tet<tro::Rng>,
     "tr_classify_segment_tet == oracle on Epeck", TYPES},
};

uint64_t env_u64(const char *name, uint64_t dflt)
{
  const char *v = getenv(name);
  if (!v || !*v)
    return dflt;
  return strtoull(v, nullptr, 10);
}

// FNV-1a of the check's name: each check has its own deterministic stream.
uint64_t name_seed(const char *s)
{
  uint64_t h = 1469598103934665603ull;
  for (; *s; s++)
    h = (h ^ (unsigned char)*s) * 1099511628211ull;
  return h;
}

}  // namespace

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s CHECK [N]\nchecks:", argv[0]);
    for (const Entry &e : checks)
      fprintf(stderr, " %s", e.name);
    fprintf(stderr, "\n");
    return 2;
  }
  const Entry *entry = nullptr;
  for (const Entry &e : checks)
    if (strcmp(e.name, argv[1]) == 0)
      entry = &e;
  if (!entry) {
    fprintf(stderr, "unknown check '%s'\n", argv[1]);
    return 2;
  }
  uint64_t n = argc > 2 ? strtoull(argv[2], nullptr, 10) : env_u64("TETREC_CROSSCHECK_N", 1000000);
  uint64_t first = env_u64("TETREC_CROSSCHECK_FIRST", 0);
  tro::g_also_epeck = env_u64("TETREC_CROSSCHECK_EPECK", 0) != 0;
  uint64_t seed = name_seed(entry->name);
  tro::Case c;
  uint64_t compared = 0, skipped = 0;
  for (uint64_t i = first; i < first + n; i++) {
    tro::Rng rng(seed ^ (i * 0xD1342543DE82EF95ull));
    int r = entry->fn(rng, c);
    if (r == 0) {
      fprintf(stderr,
              "FAIL %s: property \"%s\" violated at case %llu\n"
              "  replay: TETREC_CROSSCHECK_FIRST=%llu TETREC_CROSSCHECK_N=1 %s %s\n",
              entry->name, entry->property, (unsigned long long)i, (unsigned long long)i,
              argv[0], entry->name);
      return 1;
    }
    if (r < 0)
      skipped++;
    else
      compared++;
  }
  printf("%s: %llu cases, %llu compared with CGAL, %llu outside the contract, 0 mismatches\n",
         entry->name, (unsigned long long)n, (unsigned long long)compared,
         (unsigned long long)skipped);
  printf("  oracle answers: %s\n", entry->buckets);
  for (int b = 0; b < 5; b++)
    if (tro::g_hist[b])
      printf("    bucket %d: %lld\n", b, tro::g_hist[b]);
  // The point of the generators is degeneracy: exact zeros (and vertex/edge hits, and
  // both construction outcomes) must be well represented, or the test proves little.
  if (n >= 10000) {
    bool thin = false;
    if (entry->buckets == SIGNS)
      thin = tro::g_hist[1] < (long long)(compared / 100);
    else if (entry->buckets == TYPES)
      thin = tro::g_hist[TR_NOD] < (long long)(compared / 100) ||
             tro::g_hist[TR_EDG] < (long long)(compared / 100);
    else
      thin = tro::g_hist[0] < (long long)(compared / 100) || tro::g_hist[1] < (long long)(compared / 100);
    if (thin) {
      fprintf(stderr, "FAIL %s: degenerate answers under 1%% of the cases\n", entry->name);
      return 1;
    }
  }
  // A generator that mostly produces unusable inputs would make the test assert little.
  if (compared < n / 2) {
    fprintf(stderr, "FAIL %s: only %llu of %llu cases were comparable\n", entry->name,
            (unsigned long long)compared, (unsigned long long)n);
    return 1;
  }
  return 0;
}
