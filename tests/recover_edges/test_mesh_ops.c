/* Swap23 / Swap44 and table instantiation on real mesh stores, every result through the
 * validator (src/mesh/check.h): links symmetric, every tet strictly positive (exact),
 * v2t consistent, Euler characteristic of a ball, exact volume unchanged, and the
 * recovered (sub-)segments present as mesh edges.
 * Usage: test_mesh_ops swap23 | swap44 | swap23_nonconvex | case1_shell | case3_pair |
 *        dtype_pair | single */
#include <gmp.h>

#include "classify.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/check.h"
#include "mesh/mesh.h"
#include "recover_edges/decompose.h"
#include "recover_edges/dtype.h"
#include "recover_edges/edge_tables.h"
#include "recover_edges/pipe.h"
#include "recover_edges/pipel.h"
#include "recover_edges/swap.h"
#include "tmesh.h"

/* Caps every open face with a tet whose apex is (a+b+c) - 2d, outside the face. */
static tr_status cap_open_faces(struct tr_mesh *m)
{
  uint32_t nt = m->nt;
  for (uint32_t t = 0; t < nt; t++)
    for (int k = 0; k < 4; k++) {
      if (tr_tet_is_free(m, t) || m->tn[4 * t + k] != TR_NONE)
        continue;
      const uint8_t *f = tr_face_vtx[k];
      uint32_t a = m->tv[4 * t + f[0]], b = m->tv[4 * t + f[1]], c = m->tv[4 * t + f[2]],
               d = m->tv[4 * t + k];
      double x[3];
      for (int i = 0; i < 3; i++)
        x[i] = m->xyz[3 * a + i] + m->xyz[3 * b + i] + m->xyz[3 * c + i] -
               2 * m->xyz[3 * d + i];
      uint32_t e, cap;
      TR_CHECK(tr_mesh_add_vertex(m, x, &e));
      TR_CHECK(tr_tet_new(m, a, c, b, e, &cap));
      tr_glue(m, t, k, cap, 3);
    }
  return TR_OK;
}

static tr_status add_pts(struct tr_mesh *m, const double (*p)[3], int n)
{
  for (int i = 0; i < n; i++) {
    uint32_t id;
    TR_CHECK(tr_mesh_add_vertex(m, p[i], &id));
  }
  return TR_OK;
}

/* Exact point sum_i w[i] * vertex[v[i]] / den, added as a Steiner vertex. */
static tr_status add_steiner(struct tr_mesh *m, int n, const uint32_t *v, const long *w,
                             long den, uint32_t *id)
{
  tr_qpoint *q = malloc(sizeof *q);
  if (!q)
    return TR_ERR_NOMEM;
  tr_qpoint_init(q);
  mpq_t t;
  mpq_init(t);
  for (int j = 0; j < 3; j++) {
    mpq_set_ui(q->c[j], 0, 1);
    for (int i = 0; i < n; i++) {
      tr_point p = tr_mesh_point(m, v[i]);
      tr_point_get_q(&p, j, t);
      mpq_t wq;
      mpq_init(wq);
      mpq_set_si(wq, w[i], (unsigned long)den);
      mpq_canonicalize(wq);
      mpq_mul(t, t, wq);
      mpq_add(q->c[j], q->c[j], t);
      mpq_clear(wq);
    }
  }
  mpq_clear(t);
  tr_qpoint_update(q);
  return tr_mesh_add_steiner(m, q, id);
}

/* ---- Swap23 on the Table 3 configuration, capped so that NG links go somewhere ---- */
static int test_swap23(int nonconvex)
{
  /* A B C D E; AB pierces CDE (or, nonconvex, passes outside it) */
  double p[5][3] = {{1, 1, -3}, {2, 1, 4}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0}};
  if (nonconvex)
    p[1][0] = 9; /* AB now misses triangle CDE */
  struct tr_mesh *m;
  CK(tr_mesh_create(16, 16, &m));
  CK(add_pts(m, p, 5));
  uint32_t t1, t2;
  CK(tr_tet_new(m, 0, 2, 3, 4, &t1)); /* ACDE */
  CK(tr_tet_new(m, 1, 3, 2, 4, &t2)); /* BDCE */
  glue_all(m);
  CK(cap_open_faces(m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  if (validate(m, vol, "swap23 input"))
    return 1;
  uint32_t out[3];
  int done;
  CK(tr_swap23(m, t1, tr_ncode(m, t1, 0), out, &done));
  int bad = 0;
  if (nonconvex) {
    if (done)
      FAIL("swap23: performed on a non-convex pair (AB misses CDE)");
    bad |= validate(m, vol, "swap23 refused");
    if (!bad)
      printf("swap23 refuses a non-convex pair and leaves the mesh valid\n");
  } else {
    if (!done)
      FAIL("swap23: refused on a convex pair");
    bad |= validate(m, vol, "swap23 result");
    if (!has_edge(m, 0, 1))
      FAIL("swap23: AB is not an edge after the swap");
    if (tr_mesh_count_real(m) != 3 + 6)
      FAIL("swap23: %u tets, expected 3 + 6 caps", tr_mesh_count_real(m));
    if (!bad)
      printf("swap23 recovers AB; mesh valid, volume unchanged\n");
  }
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

/* ---- Swap44: ABCD coplanar, AB crosses CD ---- */
static int test_swap44(void)
{
  double p[6][3] = {{-2, 0, 0}, {3, 1, 0}, {0, -2, 0}, {1, 4, 0}, {1, 0, 3}, {0, 1, -2}};
  struct tr_mesh *m;
  CK(tr_mesh_create(32, 32, &m));
  CK(add_pts(m, p, 6));
  uint32_t t;
  CK(tr_tet_new(m, 0, 2, 3, 4, &t)); /* ACDE */
  CK(tr_tet_new(m, 0, 3, 2, 5, &t)); /* ADCF */
  CK(tr_tet_new(m, 1, 3, 2, 4, &t)); /* BDCE */
  CK(tr_tet_new(m, 1, 2, 3, 5, &t)); /* BCDF */
  glue_all(m);
  CK(cap_open_faces(m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  if (validate(m, vol, "swap44 input"))
    return 1;
  uint32_t out[4];
  int done;
  CK(tr_swap44(m, 0, 1, 2, 3, out, &done));
  if (!done)
    FAIL("swap44: refused on a valid configuration");
  int bad = validate(m, vol, "swap44 result");
  if (!has_edge(m, 0, 1) || has_edge(m, 2, 3))
    FAIL("swap44: AB must be an edge and CD must be gone");
  if (!bad)
    printf("swap44 recovers AB and removes CD; mesh valid, volume unchanged\n");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

/* Decomposes pipel pl with table t given its Steiner points (local carriers). */
static tr_status decompose(struct tr_mesh *m, const tr_dectable *t, tr_pipel *pipe,
                           uint32_t npipe, tr_pipel *pl, int nst, const uint8_t car[][4],
                           const uint8_t *ncar, const uint32_t *sid, int prefer)
{
  uint32_t ids[TR_DV_COUNT];
  if (!tr_dec_match(t, m->tv + 4 * pl->iEle, nst, car, ncar, sid, prefer, ids))
    return tr_error(TR_ERR_INTERNAL, "%s does not fit pipel %u", t->name, pl->iEle);
  uint32_t old = pl->iEle;
  TR_CHECK(tr_dec_apply(m, t, &old, ids, pipe, npipe, pl->dectets));
  pl->nTets = t->nnew;
  return TR_OK;
}

/* ---- Case 1 on a whole shell: ABCD coplanar, AB through P on CD; 4 pipels ---- */
static int test_case1_shell(void)
{
  double p[6][3] = {{-2, 0, 0}, {3, 1, 0}, {0, -2, 0}, {1, 4, 0}, {1, 0, 3}, {0, 1, -2}};
  struct tr_mesh *m;
  CK(tr_mesh_create(32, 32, &m));
  CK(add_pts(m, p, 6));
  uint32_t t[4];
  CK(tr_tet_new(m, 0, 2, 3, 4, &t[0]));
  CK(tr_tet_new(m, 0, 3, 2, 5, &t[1]));
  CK(tr_tet_new(m, 1, 3, 2, 4, &t[2]));
  CK(tr_tet_new(m, 1, 2, 3, 5, &t[3]));
  glue_all(m);
  CK(cap_open_faces(m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  /* AB meets CD at s = 14/29 along AB, i.e. P = C + 12/29 (D - C) */
  uint32_t pid, cd[2] = {2, 3};
  long w[2] = {17, 12};
  CK(add_steiner(m, 2, cd, w, 29, &pid));
  tr_pipel pipe[4];
  memset(pipe, 0, sizeof pipe);
  for (int i = 0; i < 4; i++)
    pipe[i].iEle = t[i];
  int bad = 0;
  for (int i = 0; i < 4; i++) {
    uint8_t car[1][4] = {{(uint8_t)tr_ncode(m, t[i], 2), (uint8_t)tr_ncode(m, t[i], 3)}};
    uint8_t ncar = 2;
    int prefer = tr_ncode(m, t[i], i < 2 ? 0 : 1);
    CK(decompose(m, &tr_table5_case1, pipe, 4, &pipe[i], 1, car, &ncar, &pid, prefer));
  }
  bad |= validate(m, vol, "case1 shell");
  if (!has_edge(m, 0, pid) || !has_edge(m, pid, 1) || has_edge(m, 2, 3))
    FAIL("case1 shell: A-P and P-B must be edges, CD split");
  if (!bad)
    printf("Table 5 on the 4 pipels around CD recovers A-P-B; mesh valid, volume unchanged\n");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

/* ---- Case 3 twice: AB through P in face CDE, pipels ACDE (NOD_FAC) and BDCE ---- */
static int test_case3_pair(void)
{
  double p[5][3] = {{1, 1, -3}, {2, 1, 4}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0}};
  struct tr_mesh *m;
  CK(tr_mesh_create(16, 16, &m));
  CK(add_pts(m, p, 5));
  uint32_t t[2];
  CK(tr_tet_new(m, 0, 2, 3, 4, &t[0]));
  CK(tr_tet_new(m, 1, 3, 2, 4, &t[1]));
  glue_all(m);
  CK(cap_open_faces(m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  /* AB meets z = 0 at (10/7, 1, 0) = (5/14) C + (1/4) D + rest E: exact barycentrics
   * (x/4, y/4): C weight 10/28, D weight 7/28, E weight 11/28 */
  uint32_t pid, cde[3] = {2, 3, 4};
  long w[3] = {10, 7, 11};
  CK(add_steiner(m, 3, cde, w, 28, &pid));
  tr_pipel pipe[2];
  memset(pipe, 0, sizeof pipe);
  pipe[0].iEle = t[0];
  pipe[1].iEle = t[1];
  for (int i = 0; i < 2; i++) {
    uint8_t car[1][4] = {{(uint8_t)tr_ncode(m, t[i], 2), (uint8_t)tr_ncode(m, t[i], 3),
                          (uint8_t)tr_ncode(m, t[i], 4)}};
    uint8_t ncar = 3;
    CK(decompose(m, &tr_table7_case3, pipe, 2, &pipe[i], 1, car, &ncar, &pid, -1));
  }
  int bad = validate(m, vol, "case3 pair");
  if (!has_edge(m, 0, pid) || !has_edge(m, pid, 1))
    FAIL("case3 pair: A-P and P-B must be edges");
  if (!bad)
    printf("Table 7 on both pipels recovers A-P-B; Phi links glued; mesh valid\n");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

/* A new tet on (a,b,c,d), with c and d exchanged if needed to make it positive. */
static tr_status new_pos_tet(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                             uint32_t *t)
{
  tr_point p[4] = {tr_mesh_point(m, a), tr_mesh_point(m, b), tr_mesh_point(m, c),
                   tr_mesh_point(m, d)};
  int s = tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
  if (s == 0)
    return tr_error(TR_ERR_INTERNAL, "flat test tet");
  return s > 0 ? tr_tet_new(m, a, b, c, d, t) : tr_tet_new(m, a, b, d, c, t);
}

static int ecode_of(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b)
{
  int i = tr_ncode(m, t, a), j = tr_ncode(m, t, b);
  return i < j ? tr_ecode(i, j) : tr_ecode(j, i);
}

/* The 4th vertex code of t missing from {a,b,c}. */
static int fcode_of(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c)
{
  return tr_fcode(m, t, a, b, c);
}

/* ---- DType rule: two Case 2 II pipels sharing the face with both cut edges ---- */
static int test_dtype_pair(int first_z)
{
  /* A B C D (positive), E beyond face ABD. The missing edge runs in plane ABD through
   * P1 on AD and P2 on BD, so both tets are EDG_EDG pipels with neighbouring edges. */
  double p[5][3] = {{0, 0, 0}, {5, 1, 0}, {1, 4, 1}, {2, 1, 6}, {5, -6, 4}};
  struct tr_mesh *m;
  CK(tr_mesh_create(16, 16, &m));
  CK(add_pts(m, p, 5));
  uint32_t t[2];
  CK(new_pos_tet(m, 0, 1, 2, 3, &t[0]));
  CK(new_pos_tet(m, 0, 1, 3, 4, &t[1]));
  glue_all(m);
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  uint32_t p1, p2, ad[2] = {0, 3}, bd[2] = {1, 3};
  long w1[2] = {2, 3}, w2[2] = {3, 4};
  CK(add_steiner(m, 2, ad, w1, 5, &p1));
  CK(add_steiner(m, 2, bd, w2, 7, &p2));
  tr_pipel pipe[2];
  memset(pipe, 0, sizeof pipe);
  for (int i = 0; i < 2; i++) {
    pipe[i].iEle = t[i];
    pipe[i].type = TR_PIPEL_TYPE(TR_EDG, TR_EDG);
    pipe[i].iNod1 = p1;
    pipe[i].iCod1 = (uint8_t)ecode_of(m, t[i], 0, 3);
    pipe[i].iNod2 = p2;
    pipe[i].iCod2 = (uint8_t)ecode_of(m, t[i], 1, 3);
  }
  int kf0 = fcode_of(m, t[0], 0, 1, 3), kf1 = fcode_of(m, t[1], 0, 1, 3);
  if (first_z) {
    /* decompose pipel 0 by hand with Z, then let the rule choose for pipel 1 */
    uint8_t car[2][4] = {{(uint8_t)tr_ncode(m, t[0], 0), (uint8_t)tr_ncode(m, t[0], 3)},
                         {(uint8_t)tr_ncode(m, t[0], 1), (uint8_t)tr_ncode(m, t[0], 3)}};
    uint8_t ncar[2] = {2, 2};
    uint32_t sid[2] = {p1, p2};
    CK(decompose(m, &tr_table6_case2_2z, pipe, 2, &pipe[0], 2, car, ncar, sid, -1));
    pipe[0].type |= (uint8_t)(1u << (4 + kf0));
  } else {
    CK(tr_pipel_decompose(m, pipe, 2, &pipe[0]));
  }
  CK(tr_pipel_decompose(m, pipe, 2, &pipe[1]));
  int bad = validate(m, vol, "dtype pair");
  int z0 = (pipe[0].type >> (4 + kf0)) & 1, z1 = (pipe[1].type >> (4 + kf1)) & 1;
  if (z0 != first_z || z0 == z1)
    FAIL("dtype pair: DType of the shared face must be %s in pipel 0 and the other type in "
         "pipel 1 (got %d, %d)", first_z ? "Z" : "S", z0, z1);
  if (!has_edge(m, p1, p2))
    FAIL("dtype pair: P1P2 is not an edge");
  if (!bad)
    printf("neighbour decomposed %s-type -> this pipel takes %s-type; shared face conforms\n",
           first_z ? "Z" : "S", first_z ? "S" : "Z");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

/* The wrong DType on the second pipel must be refused, mesh untouched. */
static int test_dtype_mismatch(void)
{
  double p[5][3] = {{0, 0, 0}, {5, 1, 0}, {1, 4, 1}, {2, 1, 6}, {5, -6, 4}};
  struct tr_mesh *m;
  CK(tr_mesh_create(16, 16, &m));
  CK(add_pts(m, p, 5));
  uint32_t t[2];
  CK(new_pos_tet(m, 0, 1, 2, 3, &t[0]));
  CK(new_pos_tet(m, 0, 1, 3, 4, &t[1]));
  glue_all(m);
  uint32_t p1, p2, ad[2] = {0, 3}, bd[2] = {1, 3};
  long w1[2] = {2, 3}, w2[2] = {3, 4};
  CK(add_steiner(m, 2, ad, w1, 5, &p1));
  CK(add_steiner(m, 2, bd, w2, 7, &p2));
  tr_pipel pipe[2];
  memset(pipe, 0, sizeof pipe);
  pipe[0].iEle = t[0];
  pipe[1].iEle = t[1];
  for (int i = 0; i < 2; i++) {
    uint8_t car[2][4] = {{(uint8_t)tr_ncode(m, t[i], 0), (uint8_t)tr_ncode(m, t[i], 3)},
                         {(uint8_t)tr_ncode(m, t[i], 1), (uint8_t)tr_ncode(m, t[i], 3)}};
    uint8_t ncar[2] = {2, 2};
    uint32_t sid[2] = {p1, p2};
    /* both sides S: in the shared face these are different diagonals */
    tr_status s = decompose(m, &tr_table6_case2_2s, pipe, 2, &pipe[i], 2, car, ncar, sid, -1);
    if (i == 0 && s != TR_OK)
      FAIL("dtype mismatch: first decomposition failed: %s", tr_last_error());
    if (i == 1) {
      if (s != TR_ERR_INTERNAL)
        FAIL("dtype mismatch: S on both sides of the shared face was accepted");
      if (pipe[1].nTets != 0 || tr_tet_is_free(m, t[1]))
        FAIL("dtype mismatch: the refused pipel was modified");
    }
  }
  printf("S on both sides of a shared face is refused and the mesh is left unchanged\n");
  tr_mesh_destroy(m);
  return 0;
}

/* ---- every case on one tet through tr_pipel_decompose (no neighbours) ---- */
static int test_single(void)
{
  double p[4][3] = {{0, 0, 0}, {5, 1, 0}, {1, 4, 1}, {2, 1, 6}};
  /* ends: type, the entity's vertices (1, 2 or 3 of them), weights / den */
  struct end { int ty, n; uint32_t v[3]; long w[3], den; };
  struct pcase { const char *name; int ncase; struct end e[2]; int nnew; } cases[] = {
    {"NOD_EDG", 1, {{TR_NOD, 1, {0}, {1}, 1}, {TR_EDG, 2, {1, 3}, {2, 3}, 5}}, 2},
    {"EDG_NOD", 1, {{TR_EDG, 2, {0, 2}, {1, 4}, 5}, {TR_NOD, 1, {3}, {1}, 1}}, 2},
    {"NOD_FAC", 3, {{TR_NOD, 1, {2}, {1}, 1}, {TR_FAC, 3, {0, 1, 3}, {2, 2, 1}, 5}}, 3},
    {"EDG_DEG", 1, {{TR_EDG, 2, {1, 2}, {1, 2}, 3}, {TR_DEG, 0, {0}, {0}, 1}}, 2},
    {"EDG_EDG opposite", 2, {{TR_EDG, 2, {0, 3}, {2, 3}, 5}, {TR_EDG, 2, {1, 2}, {1, 3}, 4}}, 4},
    {"EDG_EDG neighbouring", 2,
     {{TR_EDG, 2, {0, 3}, {2, 3}, 5}, {TR_EDG, 2, {1, 3}, {3, 4}, 7}}, 3},
    {"FAC_NOD", 3, {{TR_FAC, 3, {1, 2, 3}, {1, 2, 4}, 7}, {TR_NOD, 1, {0}, {1}, 1}}, 3},
    {"EDG_FAC", 4, {{TR_EDG, 2, {0, 3}, {2, 3}, 5}, {TR_FAC, 3, {1, 2, 3}, {1, 2, 4}, 7}}, 4},
    {"FAC_EDG", 4, {{TR_FAC, 3, {0, 2, 3}, {3, 1, 1}, 5}, {TR_EDG, 2, {1, 2}, {1, 1}, 2}}, 4},
    {"FAC_FAC", 5, {{TR_FAC, 3, {0, 1, 3}, {1, 2, 4}, 7}, {TR_FAC, 3, {1, 2, 3}, {3, 1, 1}, 5}}, 5},
  };
  int bad = 0;
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    struct tr_mesh *m;
    CK(tr_mesh_create(8, 8, &m));
    CK(add_pts(m, p, 4));
    uint32_t t;
    CK(tr_tet_new(m, 0, 1, 2, 3, &t));
    mpq_t vol;
    mpq_init(vol);
    CK(tr_mesh_volume6(m, vol));
    tr_pipel pl;
    memset(&pl, 0, sizeof pl);
    pl.iEle = t;
    pl.iNod1 = pl.iNod2 = TR_NONE;
    uint32_t nodes[2] = {TR_NONE, TR_NONE};
    for (int e = 0; e < 2; e++) {
      const struct end *en = &cases[c].e[e];
      int code = 0;
      if (en->ty == TR_NOD) {
        nodes[e] = en->v[0];
        code = (int)en->v[0];
      } else if (en->ty == TR_EDG) {
        CK(add_steiner(m, 2, en->v, en->w, en->den, &nodes[e]));
        code = tr_ecode((int)en->v[0], (int)en->v[1]);
      } else if (en->ty == TR_FAC) {
        CK(add_steiner(m, 3, en->v, en->w, en->den, &nodes[e]));
        code = 6 - (int)(en->v[0] + en->v[1] + en->v[2]);
      }
      if (e == 0) {
        pl.iNod1 = nodes[e];
        pl.iCod1 = (uint8_t)code;
      } else {
        pl.iNod2 = nodes[e];
        pl.iCod2 = (uint8_t)code;
      }
    }
    pl.type = TR_PIPEL_TYPE(cases[c].e[0].ty, cases[c].e[1].ty);
    if (tr_pipel_case(pl.type) != cases[c].ncase)
      FAIL("%s: Table 2 case %d, expected %d", cases[c].name, tr_pipel_case(pl.type),
           cases[c].ncase);
    CK(tr_pipel_decompose(m, &pl, 1, &pl));
    if (validate(m, vol, cases[c].name))
      bad = 1;
    if (pl.nTets != cases[c].nnew || tr_mesh_count_real(m) != (uint32_t)cases[c].nnew)
      FAIL("%s: %d new tets, expected %d", cases[c].name, pl.nTets, cases[c].nnew);
    if (nodes[1] != TR_NONE && !has_edge(m, nodes[0], nodes[1]))
      FAIL("%s: the recovered sub-segment is not an edge", cases[c].name);
    mpq_clear(vol);
    tr_mesh_destroy(m);
  }
  if (tr_pipel_case(TR_PIPEL_TYPE(TR_NOD, TR_NOD)) != 0 ||
      tr_pipel_case(TR_PIPEL_TYPE(TR_NOD, TR_DEG)) != 0 ||
      tr_pipel_case(TR_PIPEL_TYPE(TR_FAC, TR_DEG)) != -1)
    FAIL("degenerate raw types are not classified as such");
  if (!bad)
    printf("all 11 raw pipel types map to Table 2; each case decomposes one tet validly\n");
  return bad;
}

/* The checks have teeth: after decomposing only one of two pipels sharing a split face
 * the mesh is NOT valid (the other still points at a freed tet). */
static int test_phi_pending(void)
{
  double p[5][3] = {{1, 1, -3}, {2, 1, 4}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0}};
  struct tr_mesh *m;
  CK(tr_mesh_create(16, 16, &m));
  CK(add_pts(m, p, 5));
  uint32_t t[2];
  CK(tr_tet_new(m, 0, 2, 3, 4, &t[0]));
  CK(tr_tet_new(m, 1, 3, 2, 4, &t[1]));
  glue_all(m);
  uint32_t pid, cde[3] = {2, 3, 4};
  long w[3] = {10, 7, 11};
  CK(add_steiner(m, 3, cde, w, 28, &pid));
  tr_pipel pipe[2];
  memset(pipe, 0, sizeof pipe);
  for (int i = 0; i < 2; i++) {
    pipe[i].iEle = t[i];
    pipe[i].type = TR_PIPEL_TYPE(TR_NOD, TR_FAC);
    pipe[i].iNod1 = (uint32_t)i;
    pipe[i].iCod1 = (uint8_t)tr_ncode(m, t[i], (uint32_t)i);
    pipe[i].iNod2 = pid;
    pipe[i].iCod2 = (uint8_t)tr_ncode(m, t[i], (uint32_t)i);
  }
  CK(tr_pipel_decompose(m, pipe, 2, &pipe[0]));
  if (tr_check_mesh(m, CHECKS, NULL) == TR_OK)
    FAIL("phi pending: half-decomposed pipe passes the validator");
  CK(tr_pipel_decompose(m, pipe, 2, &pipe[1]));
  if (tr_check_mesh(m, CHECKS, NULL) != TR_OK)
    FAIL("phi pending: validator after both pipels: %s", tr_last_error());
  printf("a half-decomposed pipe is invalid; decomposing the neighbour glues the Phi faces\n");
  tr_mesh_destroy(m);
  return 0;
}

/* tr_recover_edge picks the paper's swaps when the pipe allows them (no Steiner point). */
static int test_recover_by_swap(int use44)
{
  double p23[5][3] = {{1, 1, -3}, {2, 1, 4}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0}};
  double p44[6][3] = {{-2, 0, 0}, {3, 1, 0}, {0, -2, 0}, {1, 4, 0}, {1, 0, 3}, {0, 1, -2}};
  struct tr_mesh *m;
  CK(tr_mesh_create(32, 32, &m));
  uint32_t t;
  if (use44) {
    CK(add_pts(m, p44, 6));
    CK(tr_tet_new(m, 0, 2, 3, 4, &t));
    CK(tr_tet_new(m, 0, 3, 2, 5, &t));
    CK(tr_tet_new(m, 1, 3, 2, 4, &t));
    CK(tr_tet_new(m, 1, 2, 3, 5, &t));
  } else {
    CK(add_pts(m, p23, 5));
    CK(tr_tet_new(m, 0, 2, 3, 4, &t));
    CK(tr_tet_new(m, 1, 3, 2, 4, &t));
  }
  glue_all(m);
  CK(cap_open_faces(m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  uint32_t nv = m->nv;
  tr_edge_stats st;
  memset(&st, 0, sizeof st);
  CK(tr_recover_edge(m, 0, 1, &st));
  int bad = validate(m, vol, use44 ? "recover by swap44" : "recover by swap23");
  if ((use44 ? st.by_swap44 : st.by_swap23) != 1 || st.steiner_points != 0 || m->nv != nv ||
      !has_edge(m, 0, 1))
    FAIL("recover_edge: expected exactly one %s and no Steiner point (swap23 %u, swap44 %u, "
         "Steiner %u)", use44 ? "Swap44" : "Swap23", st.by_swap23, st.by_swap44,
         st.steiner_points);
  if (!bad)
    printf("tr_recover_edge recovers AB by one %s, no Steiner point\n",
           use44 ? "Swap44" : "Swap23");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 2)
    return 2;
  const char *w = argv[1];
  if (!strcmp(w, "swap23"))
    return test_swap23(0);
  if (!strcmp(w, "swap23_nonconvex"))
    return test_swap23(1);
  if (!strcmp(w, "swap44"))
    return test_swap44();
  if (!strcmp(w, "case1_shell"))
    return test_case1_shell();
  if (!strcmp(w, "case3_pair"))
    return test_case3_pair();
  if (!strcmp(w, "dtype_pair_s"))
    return test_dtype_pair(0);
  if (!strcmp(w, "dtype_pair_z"))
    return test_dtype_pair(1);
  if (!strcmp(w, "dtype_mismatch"))
    return test_dtype_mismatch();
  if (!strcmp(w, "recover_swap23"))
    return test_recover_by_swap(0);
  if (!strcmp(w, "recover_swap44"))
    return test_recover_by_swap(1);
  if (!strcmp(w, "single"))
    return test_single();
  if (!strcmp(w, "phi_pending"))
    return test_phi_pending();
  fprintf(stderr, "unknown test %s\n", w);
  return 2;
}
