/* The sliver stage's savings that must not change its result (src/sliver): the smoothing
 * pass walks only the stars of the vertices of a tet under the bound, and the flip pass
 * skips a tet that found no flip while no tet at its vertices changed (the stamps of
 * tr_sliver_touch). Each is run against the search it saves, on the same refined
 * surface meshed twice (the pipeline is deterministic): the same moves, the same mesh,
 * byte for byte, and both validate. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sliver/sliver.h"
#include "../pipeline/tmesh.h"

static const unsigned chk = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T;

/* path refined under 1.414 without the sliver stage, twice: the same mesh in a and b */
static int two_meshes(const char *path, tr_plc **p, tm_run *a, tm_run *b)
{
  *p = tm_read(path);
  tr_options o = tm_refinement(1.414, 0);
  tr_mesh *ma = tm_mesh(a, "copy a", *p, &o, chk);
  tr_mesh *mb = tm_mesh(b, "copy b", *p, &o, chk);
  if (!ma || !mb)
    return 0;
  EXPECT(ma->nv == mb->nv && ma->nt == mb->nt &&
             !memcmp(ma->tv, mb->tv, sizeof *ma->tv * 4 * (size_t)ma->nt) &&
             !memcmp(ma->xyz, mb->xyz, sizeof *ma->xyz * 3 * (size_t)ma->nv),
         "%s: two meshings differ", path);
  return 1;
}

static void same_mesh(const char *what, const tr_mesh *a, const tr_mesh *b)
{
  EXPECT(a->nv == b->nv && a->nt == b->nt, "%s: %u/%u vertices, %u/%u slots", what, a->nv,
         b->nv, a->nt, b->nt);
  if (a->nv != b->nv || a->nt != b->nt)
    return;
  EXPECT(!memcmp(a->tv, b->tv, sizeof *a->tv * 4 * (size_t)a->nt), "%s: the tets differ", what);
  EXPECT(!memcmp(a->xyz, b->xyz, sizeof *a->xyz * 3 * (size_t)a->nv), "%s: the points differ",
         what);
  EXPECT(tr_check_mesh(a, chk, NULL) == TR_OK, "%s: mesh validator: %s", what, tr_last_error());
}

static uint64_t under_bound(const tr_mesh *m)
{
  uint64_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    n += tr_tet_is_real(m, t) &&
         tr_sliver_min_dihedral(m, m->tv[4 * t], m->tv[4 * t + 1], m->tv[4 * t + 2],
                                m->tv[4 * t + 3]) < TR_SLIVER_BOUND;
  return n;
}

/* The smoothing pass (the stars of the vertices of tets under the bound only) and
 * tr_sliver_smooth_vertex on every vertex in index order: the same moves, the same
 * points. */
static void smoothing_walks_only_stars_with_a_tet_under_the_bound(const char *path)
{
  tr_plc *p;
  tm_run a, b;
  if (two_meshes(path, &p, &a, &b)) {
    tr_subfaces none = {0, NULL, NULL};
    tr_sliver_ctx ca, cb;
    tr_sliver_stats sa, sb;
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    uint32_t np = a.st.surface_nodes;
    uint64_t bad = under_bound(a.m);
    tr_status s = tr_sliver_ctx_init(&ca, a.m, &none, NULL, np, TR_SLIVER_BOUND);
    if (s == TR_OK)
      s = tr_sliver_ctx_init(&cb, b.m, &none, NULL, np, TR_SLIVER_BOUND);
    for (int pass = 0; pass < 2 && s == TR_OK; pass++) {
      s = tr_sliver_smooth_pass(&ca, &sa);
      tr_u32buf ball = {0};
      for (uint32_t v = 0; v < b.m->nv && s == TR_OK; v++) {
        int moved;
        s = tr_sliver_smooth_vertex(&cb, v, cb.bound, &ball, &sb, &moved);
      }
      tr_u32buf_free(&ball);
    }
    EXPECT(s == TR_OK, "%s: smoothing: %s", path, tr_last_error());
    EXPECT(bad > 0 && sa.smoothed > 0, "%s: %llu tets under the bound, %llu moves: nothing to "
           "compare", path, (unsigned long long)bad, (unsigned long long)sa.smoothed);
    EXPECT(sa.smoothed == sb.smoothed, "%s: %llu moves against %llu walking every star", path,
           (unsigned long long)sa.smoothed, (unsigned long long)sb.smoothed);
    same_mesh("smoothing", a.m, b.m);
    fprintf(stderr, "%s: %llu tets under %g degrees, %llu moves both ways\n", path,
            (unsigned long long)bad, TR_SLIVER_BOUND, (unsigned long long)sa.smoothed);
    tr_sliver_ctx_free(&ca);
    tr_sliver_ctx_free(&cb);
  }
  tm_free(&a);
  tm_free(&b);
  tr_plc_destroy(p);
}

/* Rounds of (flip pass, smoothing pass, insertion pass) with the flip memo, and the same
 * rounds with every failure forgotten before each flip pass (every tet under the bound
 * searched again): the same flips, moves and points, the same mesh. The memo is in use:
 * after the first pass some slots hold a failure. */
static void a_flip_search_the_memo_skips_finds_no_flip(const char *path)
{
  tr_plc *p;
  tm_run a, b;
  if (two_meshes(path, &p, &a, &b)) {
    tr_subfaces none = {0, NULL, NULL};
    tr_sliver_ctx ca, cb;
    tr_sliver_stats sa, sb;
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    uint32_t np = a.st.surface_nodes;
    tr_status s = tr_sliver_ctx_init(&ca, a.m, &none, NULL, np, TR_SLIVER_BOUND);
    if (s == TR_OK)
      s = tr_sliver_ctx_init(&cb, b.m, &none, NULL, np, TR_SLIVER_BOUND);
    uint64_t remembered = 0;
    for (int round = 0; round < 4 && s == TR_OK; round++) {
      s = tr_sliver_flip_pass(&ca, &sa);
      if (s == TR_OK) {
        tr_sliver_forget_flips(&cb);
        s = tr_sliver_flip_pass(&cb, &sb);
      }
      for (uint32_t t = 0; !round && t < ca.nflip_failed; t++)
        remembered += ca.flip_failed[t] != 0;
      if (s == TR_OK)
        s = tr_sliver_smooth_pass(&ca, &sa);
      if (s == TR_OK)
        s = tr_sliver_smooth_pass(&cb, &sb);
      if (s == TR_OK)
        s = tr_sliver_insert_pass(&ca, &sa);
      if (s == TR_OK)
        s = tr_sliver_insert_pass(&cb, &sb);
    }
    EXPECT(s == TR_OK, "%s: rounds: %s", path, tr_last_error());
    EXPECT(remembered > 0, "%s: no failed flip search remembered", path);
    EXPECT(!memcmp(&sa, &sb, sizeof sa),
           "%s: flips %llu/%llu, moves %llu/%llu, points %llu/%llu with/without the memo", path,
           (unsigned long long)(sa.flips23 + sa.flips32 + sa.flips44 + sa.flipsn),
           (unsigned long long)(sb.flips23 + sb.flips32 + sb.flips44 + sb.flipsn),
           (unsigned long long)sa.smoothed, (unsigned long long)sb.smoothed,
           (unsigned long long)sa.points, (unsigned long long)sb.points);
    EXPECT(sa.flips23 + sa.flips32 + sa.flips44 + sa.flipsn > 0 && sa.points > 0,
           "%s: no flip or no point: nothing to compare", path);
    same_mesh("flip memo", a.m, b.m);
    fprintf(stderr, "%s: %llu failures remembered after the first pass; %llu flips, %llu "
            "moves, %llu points both ways\n", path, (unsigned long long)remembered,
            (unsigned long long)(sa.flips23 + sa.flips32 + sa.flips44 + sa.flipsn),
            (unsigned long long)sa.smoothed, (unsigned long long)sa.points);
    tr_sliver_ctx_free(&ca);
    tr_sliver_ctx_free(&cb);
  }
  tm_free(&a);
  tm_free(&b);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"smooth", NULL, smoothing_walks_only_stars_with_a_tet_under_the_bound},
      {"flips", NULL, a_flip_search_the_memo_skips_finds_no_flip},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
