/* FLAGE (Table 13): the transcription of the printed table, its correction, and the
 * checks of the corrected table against the parity rule and the exact geometry, for all
 * 24 code permutations; and the paper's sub-facet rule against the geometry. */
#include <stdio.h>
#include <string.h>

#include "outer/flage.h"
#include "qgeom.h"

static int fails;

#define CHECK(cond, ...)            \
  do {                              \
    if (!(cond)) {                  \
      fprintf(stderr, "FAIL: ");    \
      fprintf(stderr, __VA_ARGS__); \
      fputc('\n', stderr);          \
      fails++;                      \
    }                               \
  } while (0)

/* Table 13 as printed (OCR text): each row gives three alternatives "x/y/z" per column;
 * alternative k of a row is (ia, ib, ic) = (ia[k], ib[k], ic[k]). */
typedef struct t13_row {
  int id, ia[3], ib[3], ic[3], etype;
} t13_row;
static const t13_row table13_printed[8] = {
  {0, {1, 3, 2}, {2, 1, 3}, {3, 2, 1}, TR_OUTER}, /* Table 13 row 1 */
  {0, {3, 1, 2}, {2, 3, 1}, {1, 2, 3}, TR_INNER}, /* Table 13 row 2 */
  {1, {0, 2, 3}, {3, 0, 2}, {2, 3, 0}, TR_OUTER}, /* Table 13 row 3 */
  {1, {2, 0, 3}, {3, 2, 0}, {0, 3, 2}, TR_INNER}, /* Table 13 row 4 */
  {2, {0, 3, 1}, {1, 0, 3}, {3, 1, 0}, TR_OUTER}, /* Table 13 row 5 */
  {2, {3, 0, 1}, {1, 3, 0}, {0, 1, 3}, TR_INNER}, /* Table 13 row 6 */
  {3, {0, 1, 2}, {2, 0, 1}, {1, 2, 0}, TR_OUTER}, /* Table 13 row 7 */
  {3, {1, 0, 2}, {2, 1, 0}, {0, 2, 1}, TR_INNER}, /* Table 13 row 8 */
};

/* Correction. Every printed OUTER entry is an odd permutation and every INNER entry an
 * even one; e.g. row 8 lists (ia,ib,ic,id) = (0,1,2,3) as INNER. With the paper's
 * hypotheses (facet ABC's right-hand normal points out of the domain; in every tet the
 * right-hand normal of v0v1v2 points to v3, which Tables 3-12 obey), A,B,C,D = v0..v3
 * puts D beyond ABC's outward normal: the tet is OUTER. So the printed etype column is
 * inverted in all 8 rows, consistently (not a scattered OCR slip): it matches inward
 * facet normals. The corrected table swaps OUTER and INNER in every row. */
static int table13_corrected(const t13_row *r) { return 1 - r->etype; }

static void test_table13(void)
{
  int seen[4][4][4][4];
  memset(seen, 0, sizeof seen);
  int n = 0;
  for (int r = 0; r < 8; r++)
    for (int k = 0; k < 3; k++) {
      const t13_row *t = &table13_printed[r];
      int ia = t->ia[k], ib = t->ib[k], ic = t->ic[k], id = t->id;
      CHECK(tr_flage(ia, ib, ic, id) >= 0, "Table 13 row %d alt %d: not a permutation", r + 1,
            k + 1);
      if (tr_flage(ia, ib, ic, id) < 0)
        continue;
      seen[ia][ib][ic][id]++;
      n++;
      CHECK(tr_flage(ia, ib, ic, id) == table13_corrected(t),
            "Table 13 row %d (%d,%d,%d,%d): corrected table says %d, FLAGE parity %d", r + 1,
            ia, ib, ic, id, table13_corrected(t), tr_flage(ia, ib, ic, id));
      CHECK(t->etype != tr_flage(ia, ib, ic, id),
            "Table 13 row %d (%d,%d,%d,%d): printed entry agrees, expected the complement",
            r + 1, ia, ib, ic, id);
    }
  CHECK(n == 24, "Table 13 has %d entries, expected 24", n);
  for (int a = 0; a < 4; a++)
    for (int b = 0; b < 4; b++)
      for (int c = 0; c < 4; c++)
        for (int d = 0; d < 4; d++) {
          int perm = a != b && a != c && a != d && b != c && b != d && c != d;
          CHECK(seen[a][b][c][d] == perm, "(%d,%d,%d,%d) appears %d times in Table 13", a, b,
                c, d, seen[a][b][c][d]);
          if (!perm)
            CHECK(tr_flage(a, b, c, d) == -1, "tr_flage accepts non-permutation");
        }
}

/* Geometry: for random positive tets and all 24 labelings (A,B,C,D) = (v_ia,...,v_id),
 * the tet is OUTER iff D lies beyond ABC's right-hand normal (exact mpq orientation),
 * and both tr_flage and tr_etype_geom agree. */
static void test_geometry(void)
{
  uint64_t rs = 0x243f6a8885a308d3ull;
  qv v[4];
  for (int i = 0; i < 4; i++)
    qv_init(&v[i]);
  tr_qpoint q[4];
  for (int i = 0; i < 4; i++)
    tr_qpoint_init(&q[i]);
  for (int it = 0; it < 50; it++) {
    int o;
    do {
      for (int i = 0; i < 4; i++)
        qv_set_si(&v[i], rng_range(&rs, -99, 99), rng_range(&rs, -99, 99),
                  rng_range(&rs, -99, 99));
      o = qv_orient(&v[0], &v[1], &v[2], &v[3]);
    } while (o <= 0);
    for (int i = 0; i < 4; i++) {
      for (int k = 0; k < 3; k++)
        mpq_set(q[i].c[k], v[i].c[k]);
      tr_qpoint_update(&q[i]);
    }
    for (int p = 0; p < 256; p++) {
      int ia = p & 3, ib = (p >> 2) & 3, ic = (p >> 4) & 3, id = p >> 6;
      if (tr_flage(ia, ib, ic, id) < 0)
        continue;
      int truth = qv_orient(&v[ia], &v[ib], &v[ic], &v[id]) > 0 ? TR_OUTER : TR_INNER;
      CHECK(tr_flage(ia, ib, ic, id) == truth, "tet %d labeling (%d,%d,%d,%d): FLAGE %d, "
            "geometry %d", it, ia, ib, ic, id, tr_flage(ia, ib, ic, id), truth);
      tr_point a = tr_pt_q(&q[ia]), b = tr_pt_q(&q[ib]), c = tr_pt_q(&q[ic]),
               d = tr_pt_q(&q[id]);
      CHECK(tr_etype_geom(&a, &b, &c, &d) == truth, "tet %d labeling (%d,%d,%d,%d): "
            "tr_etype_geom disagrees with exact geometry", it, ia, ib, ic, id);
    }
  }
  for (int i = 0; i < 4; i++) {
    qv_clear(&v[i]);
    tr_qpoint_clear(&q[i]);
  }
}

/* Sub-facets: ABC inside the surface facet EFG (outward), in either orientation; D off
 * the plane on either side; the tet's codes a random positive ordering of A,B,C,D. The
 * paper's two-step rule (FLAGE, then reverse if ABC's normal opposes EFG's) must say
 * OUTER exactly when D is beyond EFG's outward normal. */
static void test_subfacet(void)
{
  uint64_t rs = 0x13198a2e03707344ull;
  enum { E, F, G, A, B, C, D, NP };
  qv p[NP];
  tr_qpoint q[NP];
  for (int i = 0; i < NP; i++) {
    qv_init(&p[i]);
    tr_qpoint_init(&q[i]);
  }
  mpq_t w[3], x;
  for (int i = 0; i < 3; i++)
    mpq_init(w[i]);
  mpq_init(x);
  int reversed = 0, outer = 0, total = 0;
  for (int it = 0; it < 400; it++) {
    do {
      for (int i = E; i <= G; i++)
        qv_set_si(&p[i], rng_range(&rs, -50, 50), rng_range(&rs, -50, 50),
                  rng_range(&rs, -50, 50));
      qv_set_si(&p[D], rng_range(&rs, -50, 50), rng_range(&rs, -50, 50),
                rng_range(&rs, -50, 50));
    } while (qv_orient(&p[E], &p[F], &p[G], &p[D]) == 0);
    /* A, B, C: points with positive barycentric weights in EFG (distinct, not collinear
     * by construction of distinct weight vectors checked below). */
    for (int k = A; k <= C; k++) {
      long a = rng_range(&rs, 1, 20), b = rng_range(&rs, 1, 20), c = rng_range(&rs, 1, 20);
      for (int j = 0; j < 3; j++) {
        mpq_set_si(w[0], a, 1), mpq_set_si(w[1], b, 1), mpq_set_si(w[2], c, 1);
        mpq_mul(w[0], w[0], p[E].c[j]);
        mpq_mul(w[1], w[1], p[F].c[j]);
        mpq_mul(w[2], w[2], p[G].c[j]);
        mpq_add(x, w[0], w[1]);
        mpq_add(x, x, w[2]);
        mpq_set_si(w[0], a + b + c, 1);
        mpq_div(p[k].c[j], x, w[0]);
      }
    }
    if (qv_orient(&p[A], &p[B], &p[C], &p[D]) == 0)
      continue; /* collinear A, B, C */
    for (int i = 0; i < NP; i++) {
      for (int k = 0; k < 3; k++)
        mpq_set(q[i].c[k], p[i].c[k]);
      tr_qpoint_update(&q[i]);
    }
    /* The tet: a random ordering of A,B,C,D fixed up to positive. */
    int ord[4] = {A, B, C, D};
    for (int i = 3; i > 0; i--) {
      int j = (int)rng_range(&rs, 0, i), t = ord[i];
      ord[i] = ord[j];
      ord[j] = t;
    }
    if (qv_orient(&p[ord[0]], &p[ord[1]], &p[ord[2]], &p[ord[3]]) < 0) {
      int t = ord[0];
      ord[0] = ord[1];
      ord[1] = t;
    }
    int code[NP];
    for (int i = 0; i < 4; i++)
      code[ord[i]] = i;
    tr_point P[NP];
    for (int i = 0; i < NP; i++)
      P[i] = tr_pt_q(&q[i]);
    int truth = qv_orient(&p[E], &p[F], &p[G], &p[D]) > 0 ? TR_OUTER : TR_INNER;
    int et = -1;
    tr_status st = tr_etype_subfacet(code[A], code[B], code[C], code[D], &P[A], &P[B], &P[C],
                                     &P[D], &P[E], &P[F], &P[G], &et);
    CHECK(st == TR_OK, "case %d: %s", it, tr_last_error());
    CHECK(et == truth, "case %d: sub-facet rule gives %d, geometry %d", it, et, truth);
    reversed += qv_orient(&p[A], &p[B], &p[C], &p[D]) != qv_orient(&p[E], &p[F], &p[G], &p[D]);
    outer += truth == TR_OUTER;
    total++;
  }
  CHECK(total > 300 && reversed > 50 && reversed < total - 50 && outer > 50 &&
            outer < total - 50,
        "sub-facet cases not varied enough: %d cases, %d reversed, %d outer", total, reversed,
        outer);
  /* A sub-facet off the facet's plane is rejected. */
  qv_set_si(&p[A], 1000, 1000, 1000);
  for (int k = 0; k < 3; k++)
    mpq_set(q[A].c[k], p[A].c[k]);
  tr_qpoint_update(&q[A]);
  tr_point P[NP];
  for (int i = 0; i < NP; i++)
    P[i] = tr_pt_q(&q[i]);
  int et;
  if (qv_orient(&p[E], &p[F], &p[G], &p[A]) != 0)
    CHECK(tr_etype_subfacet(0, 1, 2, 3, &P[A], &P[B], &P[C], &P[D], &P[E], &P[F], &P[G],
                            &et) == TR_ERR_INTERNAL,
          "a sub-facet off the plane of its facet was accepted");
  for (int i = 0; i < 3; i++)
    mpq_clear(w[i]);
  mpq_clear(x);
  for (int i = 0; i < NP; i++) {
    qv_clear(&p[i]);
    tr_qpoint_clear(&q[i]);
  }
}

int main(int argc, char **argv)
{
  const char *m = argc > 1 ? argv[1] : "all";
  int all = !strcmp(m, "all");
  if (all || !strcmp(m, "table13"))
    test_table13();
  if (all || !strcmp(m, "geometry"))
    test_geometry();
  if (all || !strcmp(m, "subfacet"))
    test_subfacet();
  if (fails) {
    fprintf(stderr, "%s: %d failure(s)\n", m, fails);
    return 1;
  }
  printf("%s: ok\n", m);
  return 0;
}
