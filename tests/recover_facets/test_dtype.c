/* tr_cluster_match: every S/Z requirement on the cut faces of a THR_EDG / FOU_EDG
 * clusterel, in every position of the cut edges, has a case; the returned relabeling is
 * even, puts the Steiner points on the actual cut edges, and meets every requirement. */
#include <stdio.h>
#include <string.h>

#include "recover_edges/edge_tables.h"
#include "recover_facets/cluster_tables.h"
#include "recover_facets/dtype.h"

static int fails;

#define CHECK(cond, ...)                 \
  do {                                   \
    if (!(cond)) {                       \
      fprintf(stderr, "FAIL: ");         \
      fprintf(stderr, __VA_ARGS__);      \
      fputc('\n', stderr);               \
      fails++;                           \
    }                                    \
  } while (0)

static int has_edge(int ncut, const uint8_t *ec, int a, int b)
{
  for (int i = 0; i < ncut; i++) {
    int s = ec[i] & 3, e = ec[i] >> 2;
    if ((s == a && e == b) || (s == b && e == a))
      return 1;
  }
  return 0;
}

/* Checks one match result against the request. Returns the case index in `cases`. */
static int check_result(int ncut, const uint8_t *ec, const int8_t want[4],
                        const tr_cluster_case *cases, const char *what)
{
  const tr_cluster_case *c = NULL;
  uint8_t perm[4];
  tr_status st = tr_cluster_match(ncut, ec, want, &c, perm);
  CHECK(st == TR_OK, "%s: no case (%s)", what, tr_last_error());
  if (st != TR_OK)
    return -1;
  CHECK(tr_perm_parity_even(perm) == 1, "%s: relabeling is not an even permutation", what);
  /* Steiner carriers of the case land on cut edges, and cover all of them. */
  const tr_dectable *t = c->table;
  int on = 0;
  for (int i = 0; i < t->nsteiner; i++) {
    const tr_dsteiner *s = &t->steiner[i];
    if (s->ncar != 2)
      continue;
    on++;
    CHECK(has_edge(ncut, ec, perm[s->car[0]], perm[s->car[1]]),
          "%s: %s lands on an uncut edge", what, tr_dv_name(s->name));
  }
  CHECK(on == ncut, "%s: case has %d edge points for %d cut edges", what, on, ncut);
  for (int x = 0; x < 4; x++) {
    int dt = c->dtype[x];
    int w = want[perm[x]];
    if (w == TR_DTYPE_ANY)
      continue;
    CHECK(dt == w, "%s: face %d wants %c, case %s gives %d", what, perm[x], w ? 'Z' : 'S',
          c->name, dt);
  }
  /* Faces with < 2 cut edges must be exactly the ones the case leaves untyped. */
  for (int x = 0; x < 4; x++) {
    int ncut_face = 0;
    for (int a = 0; a < 4; a++)
      for (int b = a + 1; b < 4; b++)
        if (a != perm[x] && b != perm[x])
          ncut_face += has_edge(ncut, ec, a, b);
    CHECK((ncut_face == 2) == (c->dtype[x] != TR_DTYPE_NONE),
          "%s: face %d has %d cut edges but case %s types it %d", what, perm[x], ncut_face,
          c->name, c->dtype[x]);
  }
  return (int)(c - cases);
}

static void test_thr_edg(void)
{
  int used[TR_NUM_THR_EDG] = {0}, nh = 0, total = 0;
  for (int d = 0; d < 4; d++) {
    uint8_t ec[3];
    int m = 0;
    for (int o = 0; o < 4; o++)
      if (o != d)
        ec[m++] = (uint8_t)(o < d ? (o | d << 2) : (d | o << 2));
    for (int pat = 0; pat < 8; pat++) {
      int8_t want[4];
      int bit = 0;
      for (int k = 0; k < 4; k++)
        want[k] = k == d ? TR_DTYPE_ANY : (int8_t)((pat >> bit++) & 1);
      char what[64];
      snprintf(what, sizeof what, "THR_EDG apex %d pattern %d", d, pat);
      int c = check_result(3, ec, want, tr_thr_edg_cases, what);
      if (c >= 0) {
        used[c]++;
        nh += tr_thr_edg_cases[c].nh > 0;
      }
      total++;
    }
  }
  /* 8 patterns per apex: SSZ-like (3), SZZ-like (3), SSS, ZZZ. */
  for (int c = 0; c < TR_NUM_THR_EDG; c++)
    CHECK(used[c] == (c < 2 ? 12 : 4), "THR_EDG case %s used %d times of %d",
          tr_thr_edg_cases[c].name, used[c], total);
  CHECK(nh == 8, "THR_EDG: %d of 32 requests need H, expected 8 (SSS and ZZZ)", nh);
}

static void test_fou_edg(void)
{
  int used[TR_NUM_FOU_EDG] = {0};
  /* The three ways to leave two opposite edges uncut. */
  static const int uncut[3][2][2] = {{{0, 1}, {2, 3}}, {{0, 2}, {1, 3}}, {{0, 3}, {1, 2}}};
  for (int u = 0; u < 3; u++) {
    uint8_t ec[4];
    int m = 0;
    for (int a = 0; a < 4; a++)
      for (int b = a + 1; b < 4; b++) {
        int is_uncut = (a == uncut[u][0][0] && b == uncut[u][0][1]) ||
                       (a == uncut[u][1][0] && b == uncut[u][1][1]);
        if (!is_uncut)
          ec[m++] = (uint8_t)(a | b << 2);
      }
    for (int pat = 0; pat < 16; pat++) {
      int8_t want[4];
      for (int k = 0; k < 4; k++)
        want[k] = (int8_t)((pat >> k) & 1);
      char what[64];
      snprintf(what, sizeof what, "FOU_EDG uncut %d pattern %d", u, pat);
      int c = check_result(4, ec, want, tr_fou_edg_cases, what);
      if (c >= 0)
        used[c]++;
    }
  }
  /* Per position of the uncut edges, the 16 patterns fall into orbits under the 4 even
   * relabelings (a regular action on the 4 faces): sizes 1, 4, 2, 2, 4, 1, 2 for SSSS,
   * ZSSS, ZZSS, SZZS, ZZZS, ZZZZ, ZSZS. */
  static const int orbit[TR_NUM_FOU_EDG] = {1, 4, 2, 2, 4, 1, 2};
  for (int c = 0; c < TR_NUM_FOU_EDG; c++)
    CHECK(used[c] == 3 * orbit[c], "FOU_EDG case %s used %d times, expected %d",
          tr_fou_edg_cases[c].name, used[c], 3 * orbit[c]);
}

static void test_any_prefers_no_h(void)
{
  const tr_cluster_case *c;
  uint8_t perm[4];
  int8_t any[4] = {TR_DTYPE_ANY, TR_DTYPE_ANY, TR_DTYPE_ANY, TR_DTYPE_ANY};
  uint8_t thr[3] = {0 | 3 << 2, 1 | 3 << 2, 2 | 3 << 2};
  CHECK(tr_cluster_match(3, thr, any, &c, perm) == TR_OK && c->nh == 0,
        "THR_EDG with free faces chose a case with H");
  uint8_t fou[4] = {0 | 2 << 2, 0 | 3 << 2, 1 | 2 << 2, 1 | 3 << 2};
  CHECK(tr_cluster_match(4, fou, any, &c, perm) == TR_OK && c->nh == 0,
        "FOU_EDG with free faces chose a case with H");
  /* One free face is always enough to avoid H. */
  for (int pat = 0; pat < 16; pat++)
    for (int fr = 0; fr < 4; fr++) {
      int8_t w[4];
      for (int k = 0; k < 4; k++)
        w[k] = k == fr ? TR_DTYPE_ANY : (int8_t)((pat >> k) & 1);
      CHECK(tr_cluster_match(4, fou, w, &c, perm) == TR_OK && c->nh == 0,
            "FOU_EDG pattern %d with face %d free needs H", pat, fr);
    }
}

static void test_rejects_bad_cuts(void)
{
  const tr_cluster_case *c;
  uint8_t perm[4];
  int8_t any[4] = {TR_DTYPE_ANY, TR_DTYPE_ANY, TR_DTYPE_ANY, TR_DTYPE_ANY};
  uint8_t tri[3] = {0 | 1 << 2, 1 | 2 << 2, 0 | 2 << 2}; /* a triangle: no plane cuts it so */
  CHECK(tr_cluster_match(3, tri, any, &c, perm) == TR_ERR_INTERNAL,
        "three edges of one face accepted as THR_EDG");
  uint8_t adj[4] = {0 | 1 << 2, 0 | 2 << 2, 0 | 3 << 2, 1 | 2 << 2}; /* uncut 13, 23 */
  CHECK(tr_cluster_match(4, adj, any, &c, perm) == TR_ERR_INTERNAL,
        "four edges with adjacent uncut edges accepted as FOU_EDG");
  CHECK(tr_cluster_match(2, adj, any, &c, perm) == TR_ERR_INTERNAL, "two edges accepted");
}

/* The S/Z definition of dtype.h reproduces the names of Table 6 II as well. */
static void test_table6_names(void)
{
  CHECK(tr_dtype_of_table(&tr_table6_case2_2s, TR_DV_C) == TR_DTYPE_S,
        "Table 6 II (S-type): ABD is not S by the dtype.h definition");
  CHECK(tr_dtype_of_table(&tr_table6_case2_2z, TR_DV_C) == TR_DTYPE_Z,
        "Table 6 II (Z-type): ABD is not Z by the dtype.h definition");
}

/* The stored patterns equal the symbolic derivation from the tables. */
static void test_stored_patterns(void)
{
  for (int c = 0; c < TR_NUM_THR_EDG + TR_NUM_FOU_EDG; c++) {
    const tr_cluster_case *k =
        c < TR_NUM_THR_EDG ? &tr_thr_edg_cases[c] : &tr_fou_edg_cases[c - TR_NUM_THR_EDG];
    for (uint8_t x = 0; x < 4; x++)
      CHECK(tr_dtype_of_table(k->table, x) == k->dtype[x],
            "case %s face opposite %s: table gives %d, stored %d", k->name, tr_dv_name(x),
            tr_dtype_of_table(k->table, x), k->dtype[x]);
  }
}

int main(int argc, char **argv)
{
  const char *m = argc > 1 ? argv[1] : "all";
  int all = !strcmp(m, "all");
  if (all || !strcmp(m, "thr"))
    test_thr_edg();
  if (all || !strcmp(m, "fou"))
    test_fou_edg();
  if (all || !strcmp(m, "prefer"))
    test_any_prefers_no_h();
  if (all || !strcmp(m, "reject"))
    test_rejects_bad_cuts();
  if (all || !strcmp(m, "names")) {
    test_table6_names();
    test_stored_patterns();
  }
  if (fails) {
    fprintf(stderr, "%s: %d failure(s)\n", m, fails);
    return 1;
  }
  printf("%s: ok\n", m);
  return 0;
}
