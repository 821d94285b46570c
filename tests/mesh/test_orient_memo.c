/* The orientation memo (src/mesh/orient_memo.h) against the exact predicate itself. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "mesh/orient_memo.h"
#include "tcommon.h"

static int direct(const struct tr_mesh *m, const uint32_t v[4])
{
  tr_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = tr_mesh_point(m, v[i]);
  return tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
}

/* A Steiner point at (a_i / d_i + b_i) per axis. */
static int add_rational(struct tr_mesh *m, const long a[3], const long d[3], const double b[3],
                        uint32_t *id)
{
  tr_qpoint *q = malloc(sizeof *q);
  EXPECT(q != NULL, "allocation");
  tr_qpoint_init(q);
  mpq_t x;
  mpq_init(x);
  for (int i = 0; i < 3; i++) {
    mpq_set_si(q->c[i], a[i], (unsigned long)d[i]);
    mpq_canonicalize(q->c[i]);
    mpq_set_d(x, b[i]);
    mpq_add(q->c[i], q->c[i], x);
  }
  mpq_clear(x);
  tr_qpoint_update(q);
  EXPECT_OK(tr_mesh_add_steiner(m, q, id), "add a Steiner point");
  return 0;
}

/* Points where the static filter rarely decides: a 6x6 grid in the plane z = x + y / 4
 * (coplanar quadruples, exact zeros), lifted by one ulp here and there, and Steiner
 * points with thirds on and just off that plane. */
static int build(struct tr_mesh **out)
{
  struct tr_mesh *m;
  EXPECT_OK(tr_mesh_create(0, 0, &m), "create");
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++) {
      double p[3] = {i, j, i + j / 4.0}, r[3] = {i, j, nextafter(i + j / 4.0, 100)};
      uint32_t id;
      EXPECT_OK(tr_mesh_add_vertex(m, (i + j) % 5 ? p : r, &id), "add a vertex");
    }
  for (int k = 0; k < 12; k++) {
    /* (k/3, 1/3, k/3 + 1/12) is on the plane; every fourth one is moved off it */
    long a[3] = {k, 1, 4 * k + 1}, d[3] = {3, 3, 12};
    double b[3] = {0, 0, k % 4 ? 0 : 0x1p-40};
    uint32_t id;
    if (add_rational(m, a, d, b, &id) != 0)
      return 1;
  }
  *out = m;
  return 0;
}

/* Every answer equals the predicate's, for tuples in any order, repeats and
 * permutations included, and most of the repeated hard ones come from the memo. */
static int test_signs(void)
{
  struct tr_mesh *m;
  if (build(&m) != 0)
    return 1;
  EXPECT_OK(tr_mesh_orient_memo_on(m), "memo on");
  for (int it = 0; it < 60000; it++) {
    uint32_t v[4];
    for (int i = 0; i < 4; i++)
      v[i] = (uint32_t)(t_next() % (it < 30000 ? 14 : m->nv));
    uint64_t asked = m->omemo->asked;
    int want = direct(m, v), got = tr_mesh_orient(m, v[0], v[1], v[2], v[3]);
    EXPECT(got == want, "orient(%u,%u,%u,%u) = %d from the memo, %d exactly", v[0], v[1], v[2],
           v[3], got, want);
    /* the same tuple again in another order: a hard one now comes from the memo */
    int hard = m->omemo->asked > asked;
    uint64_t found = m->omemo->found;
    uint32_t w[4] = {v[2], v[0], v[3], v[1]}; /* an odd permutation */
    got = tr_mesh_orient(m, w[0], w[1], w[2], w[3]);
    EXPECT(got == -want, "orient(%u,%u,%u,%u) = %d, expected %d", w[0], w[1], w[2], w[3], got,
           -want);
    EXPECT(!hard || v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] ||
               v[1] == v[3] || v[2] == v[3] || m->omemo->found == found + 1,
           "the second ask of a hard tuple came from the memo");
  }
  EXPECT(m->omemo->found > 10000, "the memo answered %llu of %llu hard tuples",
         (unsigned long long)m->omemo->found, (unsigned long long)m->omemo->asked);
  tr_mesh_orient_memo_off(m);
  EXPECT(m->omemo == NULL, "off frees it");
  tr_mesh_destroy(m);
  return 0;
}

/* A vertex id that is taken back (tr_mesh_pop_vertex, which forgets the memo) and given
 * to another point: the memo answers for the new point. */
static int test_forget(void)
{
  struct tr_mesh *m;
  if (build(&m) != 0)
    return 1;
  EXPECT_OK(tr_mesh_orient_memo_on(m), "memo on");
  uint32_t id;
  long on[3] = {1, 1, 5}, d[3] = {3, 3, 12};
  double zero[3] = {0, 0, 0};
  if (add_rational(m, on, d, zero, &id) != 0) /* (1/3, 1/3, 5/12) is on the plane */
    return 1;
  uint32_t g[3] = {1, 8, 13}; /* grid points (0,1), (1,2), (2,1): none lifted */
  int before = tr_mesh_orient(m, g[0], g[1], g[2], id);
  uint32_t v[4] = {g[0], g[1], g[2], id};
  EXPECT(before == direct(m, v) && before == 0, "on the plane: %d", before);
  /* take it back the way edge recovery does (midsplit.c), then reuse the id */
  tr_mesh_pop_vertex(m);
  uint32_t id2;
  long off[3] = {1, 1, 6};
  if (add_rational(m, off, d, zero, &id2) != 0)
    return 1;
  EXPECT(id2 == id, "the id is reused (%u, %u)", id2, id);
  int after = tr_mesh_orient(m, g[0], g[1], g[2], id2);
  EXPECT(after == direct(m, v) && after != 0, "off the plane after forget: %d", after);
  tr_mesh_destroy(m); /* frees the memo too */
  return 0;
}

/* Past TR_ORIENT_MEMO_KEYS distinct hard tuples the memo starts over: it holds at most
 * that many and still answers right. */
static int test_bound(void)
{
  struct tr_mesh *m;
  EXPECT_OK(tr_mesh_create(0, 0, &m), "create");
  for (int i = 0; i < 40; i++)
    for (int j = 0; j < 40; j++) {
      double p[3] = {i, j, 0.5 * i + 0.25 * j}; /* coplanar: every test is a hard zero */
      uint32_t id;
      EXPECT_OK(tr_mesh_add_vertex(m, p, &id), "add a vertex");
    }
  EXPECT_OK(tr_mesh_orient_memo_on(m), "memo on");
  for (uint32_t it = 0; it < TR_ORIENT_MEMO_KEYS + TR_ORIENT_MEMO_KEYS / 2; it++) {
    uint32_t v[4];
    for (int i = 0; i < 4; i++)
      v[i] = (uint32_t)(t_next() % m->nv);
    EXPECT(tr_mesh_orient(m, v[0], v[1], v[2], v[3]) == direct(m, v), "tuple %u", it);
    EXPECT(m->omemo->map.n <= TR_ORIENT_MEMO_KEYS, "%u keys held", m->omemo->map.n);
  }
  tr_mesh_orient_memo_off(m);
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  if (!strcmp(argv[1], "signs"))
    return test_signs();
  if (!strcmp(argv[1], "forget"))
    return test_forget();
  if (!strcmp(argv[1], "bound"))
    return test_bound();
  return 2;
}
