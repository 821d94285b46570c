/* Mesh store tests: tables against the orientation convention, the paper's codes,
 * tr_mesh_replace (2-3 and 3-2 flips), Ball/Shell, and that the validator catches each
 * kind of corruption. Usage: test_mesh <case>. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "core/vtmap.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "mesh/mesh.h"
#include "mesh/orient_memo.h"
#include "predicates.h"
#include "tcommon.h"

/* The standard positive tet: orient3d(v0,v1,v2,v3) = det[I] = 1 > 0. */
static const double unit_tet[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

static int face_table_matches_orientation(void)
{
  EXPECT(tr_orient3d(unit_tet[0], unit_tet[1], unit_tet[2], unit_tet[3]) > 0,
         "the reference tet must be positive");
  for (int k = 0; k < 4; k++) {
    const uint8_t *f = tr_face_vtx[k];
    EXPECT(f[0] != k && f[1] != k && f[2] != k && f[0] != f[1] && f[1] != f[2] && f[0] != f[2],
           "face %d must list the three other vertices", k);
    double o = tr_orient3d(unit_tet[f[0]], unit_tet[f[1]], unit_tet[f[2]], unit_tet[k]);
    EXPECT(o > 0, "orient3d(face %d, v%d) = %g, must be > 0 (normal into the tet)", k, k, o);
  }
  /* face_rot: face j rotated to start at k */
  for (int k = 0; k < 4; k++)
    for (int j = 0; j < 4; j++) {
      if (j == k)
        continue;
      const uint8_t *f = tr_face_vtx[j];
      int r = f[0] == k ? 0 : f[1] == k ? 1 : 2;
      EXPECT(f[r] == k, "face %d must contain vertex %d", j, k);
      EXPECT(tr_face_rot[k][j][0] == f[(r + 1) % 3] && tr_face_rot[k][j][1] == f[(r + 2) % 3],
             "tr_face_rot[%d][%d] = {%d,%d}, expected {%d,%d}", k, j, tr_face_rot[k][j][0],
             tr_face_rot[k][j][1], f[(r + 1) % 3], f[(r + 2) % 3]);
    }
  /* edge table is the paper's order and ECode packing */
  static const int codes[6] = {0 | 1 << 2, 0 | 2 << 2, 0 | 3 << 2, 1 | 2 << 2, 1 | 3 << 2, 2 | 3 << 2};
  for (int e = 0; e < 6; e++)
    EXPECT((tr_edge_vtx[e][0] | tr_edge_vtx[e][1] << 2) == codes[e], "edge %d code", e);
  return 0;
}

static tr_status two_tets(struct tr_mesh **out, uint32_t t[2])
{
  /* tets (0,1,2,3) and (0,2,1,4): share face 012, 4 below it, 3 above */
  static const double pts[5][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 3}, {0.5, 0.5, -3}};
  struct tr_mesh *m;
  TR_CHECK(tr_mesh_create(0, 0, &m));
  uint32_t id;
  for (int i = 0; i < 5; i++)
    TR_CHECK(tr_mesh_add_vertex(m, pts[i], &id));
  TR_CHECK(tr_tet_new(m, 0, 1, 2, 3, &t[0]));
  TR_CHECK(tr_tet_new(m, 0, 2, 1, 4, &t[1]));
  tr_glue(m, t[0], 3, t[1], 3);
  *out = m;
  return TR_OK;
}

static int codes_are_the_papers(void)
{
  struct tr_mesh *m;
  uint32_t t[2];
  EXPECT_OK(two_tets(&m, t), "build");
  EXPECT(tr_ncode(m, t[1], 0) == 0 && tr_ncode(m, t[1], 2) == 1 && tr_ncode(m, t[1], 4) == 3 &&
             tr_ncode(m, t[1], 3) == -1,
         "NCode is the slot of the vertex, -1 when absent");
  EXPECT(tr_tet_ecode(m, t[1], 1, 0) == (0 | 2 << 2), "ECode(0-1 in (0,2,1,4)) = 0|2<<2, got %d",
         tr_tet_ecode(m, t[1], 1, 0));
  EXPECT(tr_tet_ecode(m, t[1], 4, 2) == (1 | 3 << 2), "ECode(2-4) = 1|3<<2");
  EXPECT(tr_tet_ecode(m, t[1], 4, 3) == -1, "ECode of a non-edge is -1");
  EXPECT(tr_fcode(m, t[0], 2, 0, 1) == 3 && tr_fcode(m, t[1], 4, 0, 1) == 1,
         "FCode is the slot of the vertex not on the face");
  EXPECT(TR_NEIG(m, t[0], 3) == t[1] && TR_NEIG(m, t[1], 3) == t[0] &&
             TR_NEIG(m, t[0], 0) == TR_NONE,
         "NEIG follows the glued face and is TR_NONE elsewhere");
  /* edge 0-1 lies in both tets and on the boundary: an open Shell of 2 tets */
  tr_u32buf sh = {0};
  int closed = -1;
  EXPECT_OK(tr_shell(m, 0, 1, TR_NONE, &sh, &closed), "open shell");
  EXPECT(sh.n == 2 && closed == 0 && sh.a[0] != sh.a[1] &&
             (sh.a[0] == t[0] || sh.a[0] == t[1]) && (sh.a[1] == t[0] || sh.a[1] == t[1]),
         "Shell(0,1) of two glued tets is open with both tets (n = %zu, closed = %d)", sh.n,
         closed);
  /* right-handed about 0->1: orient3d(0, 1, c, 2) > 0 for c the vertex of the first tet
   * off the shared face 012; here that is vertex 4, so the Shell is (t[1], t[0]) */
  EXPECT(sh.a[0] == t[1], "open Shell(0,1) turns right-handed: starts at the tet with vertex 4");
  tr_u32buf_free(&sh);
  tr_mesh_destroy(m);
  return 0;
}

static int replace_flips_keep_volume_and_links(void)
{
  struct tr_mesh *m;
  uint32_t t[2];
  EXPECT_OK(two_tets(&m, t), "build");
  mpq_t v0;
  mpq_init(v0);
  tr_mesh_volume6(m, v0);
  EXPECT(mpq_cmp_si(v0, 24, 1) == 0, "6*volume of the two tets is exactly 24, got %g",
         mpq_get_d(v0));
  EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, v0), "two tets valid");
  /* 2-3 flip: edge 3-4 replaces face 012 */
  uint32_t nv[12] = {0, 1, 4, 3, 1, 2, 4, 3, 2, 0, 4, 3}, ids[3];
  for (int i = 0; i < 3; i++) {
    const double *x = m->xyz;
    EXPECT(tr_orient3d(x + 3 * nv[4 * i], x + 3 * nv[4 * i + 1], x + 3 * nv[4 * i + 2],
                       x + 3 * nv[4 * i + 3]) > 0,
           "new tet %d of the 2-3 flip must be positive (test data)", i);
  }
  EXPECT_OK(tr_mesh_replace(m, t, 2, nv, 3, ids), "2-3 flip");
  EXPECT(tr_mesh_count_real(m) == 3, "3 tets after 2-3");
  EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, v0), "valid after 2-3, same exact volume");
  for (int i = 0; i < 3; i++)
    EXPECT(TR_NEIG(m, ids[i], 0) != TR_NONE && TR_NEIG(m, ids[i], 1) != TR_NONE,
           "each new tet is glued to two others");
  /* a wrong replacement is refused and leaves the mesh as it was */
  uint32_t bad[4] = {0, 1, 2, 3};
  tr_status s = tr_mesh_replace(m, ids, 3, bad, 1, NULL);
  EXPECT(s == TR_ERR_INTERNAL, "replace with a region of another shape must fail, got %s",
         tr_status_name(s));
  EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, v0), "unchanged after a refused replace");
  /* 3-2 back */
  uint32_t back[8] = {0, 1, 2, 3, 0, 2, 1, 4};
  EXPECT_OK(tr_mesh_replace(m, ids, 3, back, 2, NULL), "3-2 flip");
  EXPECT(tr_mesh_count_real(m) == 2 && m->nfree == 1, "2 tets and one free slot after 3-2");
  EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, v0), "valid after 3-2");
  /* the free slot is reused */
  uint32_t nt = m->nt, t2;
  EXPECT_OK(tr_tet_new(m, 0, 1, 3, 2, &t2), "new");
  EXPECT(m->nt == nt && m->nfree == 0, "tr_tet_new takes the free slot first");
  mpq_clear(v0);
  tr_mesh_destroy(m);
  return 0;
}

static int validator_catches_corruption(void)
{
  struct tr_mesh *m;
  uint32_t t[2];
  EXPECT_OK(two_tets(&m, t), "build");
  /* inverted tet */
  uint32_t save = m->tv[1];
  m->tv[1] = m->tv[2];
  m->tv[2] = save;
  EXPECT(tr_check_mesh(m, TR_CHK_ORIENT, NULL) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "inverted"),
         "an inverted tet is reported: %s", tr_last_error());
  m->tv[2] = m->tv[1];
  m->tv[1] = save;
  /* one-sided link */
  m->tn[4 * t[1] + 3] = TR_NONE;
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS, NULL) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "link back"),
         "an asymmetric link is reported: %s", tr_last_error());
  tr_glue(m, t[0], 3, t[1], 3);
  /* a link between faces that differ */
  tr_glue(m, t[0], 0, t[1], 0);
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS, NULL) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "not the same face"),
         "a link across different faces is reported: %s", tr_last_error());
  m->tn[4 * t[0]] = m->tn[4 * t[1]] = TR_NONE;
  /* stale v2t */
  m->v2t[3] = t[1];
  EXPECT(tr_check_mesh(m, TR_CHK_V2T, NULL) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "v2t"),
         "a stale vertex->tet entry is reported: %s", tr_last_error());
  m->v2t[3] = t[0];
  /* wrong volume */
  mpq_t v;
  mpq_init(v);
  mpq_set_si(v, 25, 1);
  EXPECT(tr_check_mesh(m, 0, v) == TR_ERR_INVALID_MESH, "a volume mismatch is reported");
  mpq_set_si(v, 24, 1);
  EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, v), "repaired mesh is valid");
  /* a face in three tets: a third tet on face 012 (same side as tet 1) */
  uint32_t t3, id;
  static const double below[3] = {1, 1, -5};
  EXPECT_OK(tr_mesh_add_vertex(m, below, &id), "add");
  EXPECT_OK(tr_tet_new(m, 0, 2, 1, id, &t3), "third tet");
  EXPECT(tr_check_mesh(m, TR_CHK_V2T, NULL) == TR_ERR_INVALID_MESH &&
             strstr(tr_last_error(), "more than two"),
         "a face in three tets is reported: %s", tr_last_error());
  mpq_clear(v);
  tr_mesh_destroy(m);
  return 0;
}

/* The Delaunay mesh of the 4x4x4 integer grid (cospherical everywhere), validated; NULL
 * on failure. */
/* 1 iff the two stores hold the same tets in the same slots, linked alike, with the same
 * v2t and free list. */
static int same_store(const struct tr_mesh *a, const struct tr_mesh *b)
{
  return a->nt == b->nt && a->nfree == b->nfree && a->free_head == b->free_head &&
         a->nv == b->nv && !memcmp(a->tv, b->tv, 4 * (size_t)a->nt * sizeof *a->tv) &&
         !memcmp(a->tn, b->tn, 4 * (size_t)a->nt * sizeof *a->tn) &&
         !memcmp(a->flags, b->flags, a->nt) && !memcmp(a->v2t, b->v2t, a->nv * sizeof *a->v2t);
}

/* tr_mesh_replace reads the links of a 2-3 or 3-2 flip off the two configurations (not
 * through the face table of other replacements): on every valid 2-3 flip of a Delaunay
 * mesh and its undo (3-2), the store must end up as the general matching leaves it
 * (tr_mesh_replace_open, which always matches faces), slot for slot; a list of the
 * right size but another shape must still be refused with the mesh unchanged. */
static int replace_flip_links_equal_general_matching(void)
{
  double pts[40 * 3];
  for (int i = 0; i < 40 * 3; i++)
    pts[i] = t_unif();
  struct tr_mesh *a, *b;
  EXPECT_OK(tr_delaunay_build(pts, 40, &a), "Delaunay A");
  EXPECT_OK(tr_delaunay_build(pts, 40, &b), "Delaunay B");
  EXPECT(same_store(a, b), "the same points give the same store");
  mpq_t v0;
  mpq_init(v0);
  tr_mesh_volume6(a, v0);
  uint32_t flips = 0, refused = 0, nt0 = a->nt;
  for (uint32_t t = 0; t < nt0; t++)
    for (int k = 0; k < 4; k++) {
      if (!tr_tet_is_real(a, t))
        break;
      uint32_t c = a->tn[4 * t + k];
      if (c == TR_NONE || !tr_tet_is_real(a, c >> 2))
        continue;
      uint32_t u = c >> 2, p = a->tv[4 * t + k], q = a->tv[4 * u + (c & 3)], f[3];
      for (int i = 0; i < 3; i++)
        f[i] = a->tv[4 * t + tr_face_vtx[k][i]];
      int sg[3];
      for (int i = 0; i < 3; i++)
        sg[i] = tr_mesh_orient(a, p, q, f[i], f[(i + 1) % 3]);
      if (!sg[0] || sg[1] != sg[0] || sg[2] != sg[0])
        continue; /* pq does not cross the open face */
      if (sg[0] < 0) {
        uint32_t x = p;
        p = q;
        q = x;
      }
      uint32_t old[2] = {t, u}, nv[12], ida[3], idb[3], oldv[8];
      memcpy(oldv, a->tv + 4 * t, 4 * sizeof *oldv);
      memcpy(oldv + 4, a->tv + 4 * u, 4 * sizeof *oldv);
      for (int i = 0; i < 3; i++) {
        /* rotate the listing with i so that the slots of p and q vary over the flips */
        uint32_t v[4] = {p, q, f[i], f[(i + 1) % 3]}, r[4];
        static const int even[3][4] = {{0, 1, 2, 3}, {2, 0, 1, 3}, {1, 2, 0, 3}};
        for (int j = 0; j < 4; j++)
          r[j] = v[even[(i + t) % 3][j]];
        memcpy(nv + 4 * i, r, sizeof r);
      }
      /* a wrong shape of the same size: one new tet takes a vertex from outside */
      uint32_t bad[12];
      memcpy(bad, nv, sizeof bad);
      for (uint32_t w = 0; w < a->nv; w++)
        if (w != p && w != q && w != f[0] && w != f[1] && w != f[2]) {
          bad[4 * 2 + 3] = w;
          break;
        }
      tr_status s = tr_mesh_replace(a, old, 2, bad, 3, NULL);
      EXPECT(s == TR_ERR_INTERNAL && same_store(a, b),
             "a 2-3 list with vertex %u from outside is refused, store unchanged (%s)",
             bad[11], tr_status_name(s));
      refused++;
      EXPECT_OK(tr_mesh_replace(a, old, 2, nv, 3, ida), "2-3 flip");
      EXPECT_OK(tr_mesh_replace_open(b, old, 2, nv, 3, idb), "2-3 flip, general matching");
      EXPECT(same_store(a, b) && !memcmp(ida, idb, sizeof ida),
             "2-3 flip of face %u:%d: the same store as the general matching", t, k);
      EXPECT_OK(tr_check_mesh(a, TR_CHK_TOPOLOGY, v0), "valid after the 2-3 flip");
      /* the undo, a 3-2 flip; its wrong shape: the edge pq kept in one tet */
      uint32_t bad2[8] = {oldv[0], oldv[1], oldv[2], oldv[3], p, q, f[0], f[1]};
      s = tr_mesh_replace(a, ida, 3, bad2, 2, NULL);
      EXPECT(s == TR_ERR_INTERNAL && same_store(a, b),
             "a 3-2 list keeping edge pq is refused, store unchanged (%s)", tr_status_name(s));
      EXPECT_OK(tr_mesh_replace(a, ida, 3, oldv, 2, NULL), "3-2 flip");
      EXPECT_OK(tr_mesh_replace_open(b, idb, 3, oldv, 2, NULL), "3-2 flip, general matching");
      EXPECT(same_store(a, b), "3-2 flip back to face %u:%d: the same store as the general "
             "matching", t, k);
      EXPECT_OK(tr_check_mesh(a, TR_CHK_TOPOLOGY, v0), "valid after the 3-2 flip");
      flips++;
      break; /* one flip per tet */
    }
  EXPECT(flips > 20 && refused == flips, "2-3 and 3-2 flips compared: %u", flips);
  mpq_clear(v0);
  tr_mesh_destroy(a);
  tr_mesh_destroy(b);
  return 0;
}

static struct tr_mesh *grid4_delaunay(void)
{
  double pts[64 * 3];
  int n = 0;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      for (int k = 0; k < 4; k++) {
        pts[3 * n] = i;
        pts[3 * n + 1] = j;
        pts[3 * n + 2] = k;
        n++;
      }
  struct tr_mesh *m;
  if (tr_delaunay_build(pts, (uint32_t)n, &m) != TR_OK)
    return NULL;
  if (tr_check_mesh(m, TR_CHK_ALL_DELAUNAY, NULL) != TR_OK) {
    tr_mesh_destroy(m);
    return NULL;
  }
  return m;
}

/* Ball and Shell on the Delaunay mesh of a 4x4x4 grid, against brute force. */
static int ball_and_shell_match_brute_force(void)
{
  int n = 64;
  struct tr_mesh *m = grid4_delaunay();
  EXPECT(m != NULL, "Delaunay mesh of the 4x4x4 grid, valid: %s", tr_last_error());
  tr_u32buf ball = {0}, shell = {0};
  for (uint32_t v = 0; v < (uint32_t)n; v++) {
    EXPECT_OK(tr_ball(m, v, 1, &ball), "ball");
    uint32_t cnt = 0;
    for (uint32_t t = 0; t < m->nt; t++)
      cnt += !tr_tet_is_free(m, t) && tr_ncode(m, t, v) >= 0;
    EXPECT(ball.n == cnt, "Ball(%u) has %zu tets, brute force %u", v, ball.n, cnt);
    for (size_t i = 0; i < ball.n; i++)
      EXPECT(tr_ncode(m, ball.a[i], v) >= 0 && !(m->flags[ball.a[i]] & TR_TF_MARK),
             "Ball tets contain the vertex and are left unmarked");
  }
  /* every edge of every real tet: Shell closed (ghosts included), right-handed order */
  uint32_t nedges = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    for (int e = 0; e < 6; e++) {
      uint32_t a = m->tv[4 * t + tr_edge_vtx[e][0]], b = m->tv[4 * t + tr_edge_vtx[e][1]];
      int closed;
      EXPECT_OK(tr_shell(m, a, b, t, &shell, &closed), "shell");
      EXPECT(closed, "Shell(%u,%u) closes with ghosts", a, b);
      uint32_t cnt = 0;
      for (uint32_t u = 0; u < m->nt; u++)
        cnt += !tr_tet_is_free(m, u) && tr_tet_ecode(m, u, a, b) >= 0;
      EXPECT(shell.n == cnt, "Shell(%u,%u) has %zu tets, brute force %u", a, b, shell.n, cnt);
      EXPECT(shell.a[0] == t, "Shell starts at the given tet");
      for (size_t i = 0; i + 1 < shell.n; i++) {
        uint32_t x = shell.a[i], y = shell.a[i + 1];
        if (tr_tet_is_ghost(m, x) || tr_tet_is_ghost(m, y))
          continue;
        /* c: third vertex of x left behind, d: the one x and y share besides a, b;
         * right-handed about a->b means orient3d(a, b, c, d) > 0 */
        uint32_t c = TR_NONE, d = TR_NONE;
        for (int k = 0; k < 4; k++) {
          uint32_t w = m->tv[4 * x + k];
          if (tr_ncode(m, y, w) < 0)
            c = w;
          else if (w != a && w != b)
            d = w;
        }
        EXPECT(c != TR_NONE && d != TR_NONE, "consecutive Shell tets share a face");
        const double *X = m->xyz;
        EXPECT(tr_orient3d(X + 3 * a, X + 3 * b, X + 3 * c, X + 3 * d) > 0,
               "Shell(%u,%u) turns right-handed about a->b", a, b);
      }
      nedges++;
    }
  }
  EXPECT(nedges > 0, "edges visited");
  tr_u32buf_free(&ball);
  tr_u32buf_free(&shell);
  tr_mesh_destroy(m);
  return 0;
}

static int hilbert_curve_is_continuous(void)
{
  /* walking the 8^3 cells in key order, each step moves to a face-adjacent cell */
  enum { B = 3, S = 1 << B };
  static int seen[S * S * S][3];
  static int filled[S * S * S];
  for (int x = 0; x < S; x++)
    for (int y = 0; y < S; y++)
      for (int z = 0; z < S; z++) {
        uint64_t k = tr_hilbert_key((uint32_t)x, (uint32_t)y, (uint32_t)z, B);
        EXPECT(k < S * S * S && !filled[k], "key %llu is a bijection onto [0, 512)",
               (unsigned long long)k);
        filled[k] = 1;
        seen[k][0] = x;
        seen[k][1] = y;
        seen[k][2] = z;
      }
  for (int k = 1; k < S * S * S; k++) {
    int d = abs(seen[k][0] - seen[k - 1][0]) + abs(seen[k][1] - seen[k - 1][1]) +
            abs(seen[k][2] - seen[k - 1][2]);
    EXPECT(d == 1, "cells %d and %d of the curve are not neighbours", k - 1, k);
  }
  return 0;
}

/* tr_ball_find against brute force on the Delaunay mesh of a 4x4x4 grid (cospherical
 * everywhere): every vertex pair and every triple of a sample, found iff some real tet has
 * them all, and the tet it names has them; marks are left clear. */
static int ball_find_matches_brute_force(void)
{
  int n = 64;
  struct tr_mesh *m = grid4_delaunay();
  EXPECT(m != NULL, "Delaunay mesh of the 4x4x4 grid, valid: %s", tr_last_error());
  uint32_t found = 0, absent = 0, *tri = malloc(sizeof *tri * 3 * 64 * 64 * 64), ntri = 0;
  uint8_t *want3 = malloc(64 * 64 * 64);
  for (uint32_t a = 0; a < (uint32_t)n; a++)
    for (uint32_t b = 0; b < (uint32_t)n; b++)
      for (uint32_t c = 0; c <= (uint32_t)n; c++) {
        uint32_t cc = c == (uint32_t)n ? TR_NONE : c; /* TR_NONE: the edge question */
        if (b == a || cc == a || cc == b || (cc != TR_NONE && (a * 7 + b * 3 + c) % 5))
          continue;
        int want = 0;
        for (uint32_t t = 0; t < m->nt && !want; t++)
          want = tr_tet_is_real(m, t) && tr_ncode(m, t, a) >= 0 && tr_ncode(m, t, b) >= 0 &&
                 (cc == TR_NONE || tr_ncode(m, t, cc) >= 0);
        uint32_t t;
        EXPECT_OK(tr_ball_find(m, a, b, cc, &t), "ball_find");
        EXPECT((t != TR_NONE) == want, "ball_find(%u, %u, %u): %s, brute force %s", a, b, c,
               t != TR_NONE ? "found" : "absent", want ? "present" : "absent");
        if (t != TR_NONE)
          EXPECT(tr_tet_is_real(m, t) && tr_ncode(m, t, a) >= 0 && tr_ncode(m, t, b) >= 0 &&
                     (cc == TR_NONE || tr_ncode(m, t, cc) >= 0),
                 "ball_find(%u, %u, %u) names a real tet holding them", a, b, c);
        found += want;
        absent += !want;
        if (cc != TR_NONE) {
          tri[3 * ntri] = a;
          tri[3 * ntri + 1] = b;
          tri[3 * ntri + 2] = cc;
          want3[ntri++] = (uint8_t)want;
        }
      }
  /* the batch form answers the same for every sampled triple (repeats included) */
  uint32_t *tet = malloc(sizeof *tet * (ntri ? ntri : 1));
  EXPECT_OK(tr_mesh_find_faces(m, tri, ntri, tet), "find_faces");
  for (uint32_t i = 0; i < ntri; i++) {
    uint32_t t = tet[i];
    EXPECT((t != TR_NONE) == want3[i], "find_faces(%u %u %u): %s, brute force %s", tri[3 * i],
           tri[3 * i + 1], tri[3 * i + 2], t != TR_NONE ? "found" : "absent",
           want3[i] ? "present" : "absent");
    if (t != TR_NONE)
      EXPECT(tr_tet_is_real(m, t) && tr_fcode(m, t, tri[3 * i], tri[3 * i + 1], tri[3 * i + 2]) >= 0,
             "find_faces names a real tet with the face");
    /* and the first such tet in slot order (what makes the callers deterministic) */
    for (uint32_t u = 0; t != TR_NONE && u < t; u++)
      EXPECT(!tr_tet_is_real(m, u) || tr_fcode(m, u, tri[3 * i], tri[3 * i + 1], tri[3 * i + 2]) < 0,
             "find_faces(%u %u %u) names tet %u, but real tet %u before it has the face",
             tri[3 * i], tri[3 * i + 1], tri[3 * i + 2], t, u);
  }
  EXPECT(ntri > 1000, "triples sampled: %u", ntri);
  free(tet);
  free(tri);
  free(want3);
  for (uint32_t t = 0; t < m->nt; t++)
    EXPECT(!(m->flags[t] & TR_TF_MARK), "tet %u left marked", t);
  EXPECT(found > 1000 && absent > 1000, "both answers exercised (%u found, %u absent)", found,
         absent);
  tr_mesh_destroy(m);
  return 0;
}

/* tr_mesh_find_edges against brute force on the same mesh: every ordered vertex pair at
 * once, present iff some real tet has both ends; a pair that is not two vertices of the
 * mesh is refused. */
static int find_edges_matches_brute_force(void)
{
  uint32_t n = 64;
  struct tr_mesh *m = grid4_delaunay();
  EXPECT(m != NULL, "Delaunay mesh of the 4x4x4 grid, valid: %s", tr_last_error());
  uint32_t *e = malloc(sizeof *e * 2 * n * n), ne = 0, found = 0;
  uint8_t *yes = malloc(n * n);
  EXPECT(e && yes, "malloc");
  for (uint32_t a = 0; a < n; a++)
    for (uint32_t b = 0; b < n; b++)
      if (a != b) {
        e[2 * ne] = a;
        e[2 * ne + 1] = b;
        ne++;
      }
  EXPECT_OK(tr_mesh_find_edges(m, e, ne, yes), "find_edges");
  for (uint32_t i = 0; i < ne; i++) {
    int want = 0;
    for (uint32_t t = 0; t < m->nt && !want; t++)
      want = tr_tet_is_real(m, t) && tr_ncode(m, t, e[2 * i]) >= 0 &&
             tr_ncode(m, t, e[2 * i + 1]) >= 0;
    EXPECT(yes[i] == want, "find_edges(%u, %u): %d, brute force %d", e[2 * i], e[2 * i + 1],
           yes[i], want);
    found += want;
  }
  EXPECT(found > 100 && found < ne - 100, "both answers exercised (%u of %u present)", found,
         ne);
  uint32_t bad[2][2] = {{3, 3}, {5, 64}};
  for (int k = 0; k < 2; k++)
    EXPECT(tr_mesh_find_edges(m, bad[k], 1, yes) == TR_ERR_INTERNAL,
           "pair %u-%u refused", bad[k][0], bad[k][1]);
  free(e);
  free(yes);
  tr_mesh_destroy(m);
  return 0;
}

/* The random find_edges / find_faces tests' generator step (xorshift64). */
static unsigned long long xorshift(unsigned long long *r)
{
  *r ^= *r << 13, *r ^= *r >> 7, *r ^= *r << 17;
  return *r;
}

/* *m: the Delaunay mesh of np points drawn by xorshift on the grid {0..8}^3 (coplanar
 * and cospherical sets, repeated points merged); 1 on a failure. */
static int grid_delaunay(unsigned long long *r, uint32_t np, struct tr_mesh **m)
{
  double *x = malloc(sizeof *x * 3 * np);
  EXPECT(x != NULL, "malloc");
  for (uint32_t i = 0; i < 3 * np; i++)
    x[i] = (double)(xorshift(r) % 9);
  tr_status s = tr_delaunay_build(x, np, m);
  free(x);
  EXPECT_OK(s, "Delaunay mesh");
  return 0;
}

/* tr_mesh_find_edges on random Delaunay meshes (points on a coarse grid: coplanar and
 * cospherical sets) against a vertex adjacency matrix of every real tet edge, for edge
 * lists like the callers' (mesh edges and absent pairs, sorted or not, either order,
 * repeated): the one pass over the tets against the asked edges answers every index. */
static int find_edges_matches_adjacency_on_random_meshes(void)
{
  unsigned long long r = 88172645463325252ull;
  uint32_t checked = 0, found = 0;
  for (int round = 0; round < 6; round++) {
    struct tr_mesh *m;
    /* repeated points are merged: nv counts the distinct ones */
    EXPECT(grid_delaunay(&r, 40 + 60 * (uint32_t)round, &m) == 0, "grid mesh");
    uint32_t nv = m->nv;
    uint8_t *adj = calloc((size_t)nv * nv, 1);
    EXPECT(adj != NULL, "malloc");
    for (uint32_t t = 0; t < m->nt; t++)
      for (int i = 0; tr_tet_is_real(m, t) && i < 4; i++)
        for (int j = 0; j < 4; j++)
          if (i != j)
            adj[(size_t)m->tv[4 * t + i] * nv + m->tv[4 * t + j]] = 1;
    uint32_t ne = 4 * nv, *e = malloc(sizeof *e * 2 * ne);
    uint8_t *yes = malloc(ne);
    EXPECT(e && yes, "malloc");
    for (uint32_t i = 0; i < ne; i++) {
      xorshift(&r);
      uint32_t a, b;
      if (i > 0 && r % 7 == 0) { /* a repeat, maybe reversed */
        uint32_t k = (uint32_t)(r >> 8) % i;
        a = e[2 * k + (r >> 40 & 1)];
        b = e[2 * k + 1 - (r >> 40 & 1)];
      } else if (r % 2) { /* an edge of a random real tet */
        uint32_t t = (uint32_t)(r >> 8) % m->nt;
        while (!tr_tet_is_real(m, t))
          t = (t + 1) % m->nt;
        int k = (int)(r >> 40) % 6;
        a = m->tv[4 * t + tr_edge_vtx[k][0]];
        b = m->tv[4 * t + tr_edge_vtx[k][1]];
      } else { /* a random pair */
        a = (uint32_t)(r >> 8) % nv;
        b = (a + 1 + (uint32_t)(r >> 40) % (nv - 1)) % nv;
      }
      e[2 * i] = a;
      e[2 * i + 1] = b;
    }
    /* sorted (a < b, lexicographic) like edge recovery's list in even rounds */
    for (uint32_t i = 0; round % 2 == 0 && i < ne; i++)
      if (e[2 * i] > e[2 * i + 1]) {
        uint32_t tmp = e[2 * i];
        e[2 * i] = e[2 * i + 1];
        e[2 * i + 1] = tmp;
      }
    memset(yes, 7, ne);
    EXPECT_OK(tr_mesh_find_edges(m, e, ne, yes), "find_edges");
    for (uint32_t i = 0; i < ne; i++) {
      uint8_t want = adj[(size_t)e[2 * i] * nv + e[2 * i + 1]];
      EXPECT(yes[i] == want, "round %d, edge %u (%u-%u): %d, adjacency %d", round, i,
             e[2 * i], e[2 * i + 1], yes[i], want);
      found += want;
    }
    checked += ne;
    free(adj);
    free(e);
    free(yes);
    tr_mesh_destroy(m);
  }
  EXPECT(found > checked / 4 && found < checked - checked / 4,
         "both answers exercised (%u of %u present)", found, checked);
  return 0;
}

/* tr_mesh_find_faces as it was before its vertex-tet lists: a hash of the triangles
 * probed for every face of every real tet, the first in slot order kept. */
static void find_faces_by_hash(const struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                               uint32_t *tet)
{
  tr_vtmap faces = {0};
  for (uint32_t i = 0; i < n; i++) {
    uint32_t k[3];
    tr_vtkey_face(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], k);
    tr_vtmap_put(&faces, 3, k, i, NULL);
    tet[i] = TR_NONE;
  }
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int f = 0; f < 4; f++) {
      uint32_t k[3];
      tr_vtkey_face(tv[tr_face_vtx[f][0]], tv[tr_face_vtx[f][1]], tv[tr_face_vtx[f][2]], k);
      uint32_t i = tr_vtmap_get(&faces, 3, k);
      if (i != TR_VTMAP_NONE && tet[i] == TR_NONE)
        tet[i] = t;
    }
  }
  for (uint32_t i = 0; i < n; i++) {
    uint32_t k[3];
    tr_vtkey_face(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], k);
    uint32_t first = tr_vtmap_get(&faces, 3, k);
    if (first != i)
      tet[i] = tet[first];
  }
  tr_vtmap_free(&faces);
}

/* tr_mesh_find_faces (the tets of each vertex, scanned from the triangle's vertex with
 * the fewest) names the very tets of the hash over every tet face it replaced, on random
 * Delaunay meshes (grid points: coplanar and cospherical sets) with free slots left by
 * flips, for faces of real tets in every rotation and orientation, hull faces, repeats,
 * absent and degenerate triples and ids past the mesh's vertices. */
static int find_faces_equals_the_hash_on_random_meshes(void)
{
  unsigned long long r = 0x2545f4914f6cdd1dull;
  uint32_t checked = 0, found = 0, freed = 0, free_left = 0;
  for (int round = 0; round < 6; round++) {
    struct tr_mesh *m;
    EXPECT(grid_delaunay(&r, 40 + 60 * (uint32_t)round, &m) == 0, "grid mesh");
    /* 2-3 flips where they apply: new tets in new or reused slots, free slots */
    for (int f = 0; f < 40; f++) {
      xorshift(&r);
      uint32_t t = (uint32_t)(r % m->nt), u;
      int k = (int)(r >> 40) % 4;
      if (!tr_tet_is_real(m, t) || (u = TR_NEIG(m, t, k)) == TR_NONE || !tr_tet_is_real(m, u))
        continue;
      const uint32_t *tv = m->tv + 4 * (size_t)t;
      uint32_t d = tv[k], e = m->tv[4 * (size_t)u + (m->tn[4 * (size_t)t + k] & 3)];
      uint32_t a = tv[tr_face_vtx[k][0]], b = tv[tr_face_vtx[k][1]], c = tv[tr_face_vtx[k][2]];
      /* d above face abc (into t), e below: the three tets around edge de */
      uint32_t nv3[12] = {a, b, d, e, b, c, d, e, c, a, d, e};
      const double *X = m->xyz;
      int ok = 1;
      for (int flip = 0; flip < 2; flip++) { /* the ring abc either way round */
        ok = 1;
        for (int q = 0; q < 3 && ok; q++)
          ok = tr_orient3d(X + 3 * (size_t)nv3[4 * q], X + 3 * (size_t)nv3[4 * q + 1],
                           X + 3 * (size_t)nv3[4 * q + 2], X + 3 * (size_t)nv3[4 * q + 3]) > 0;
        if (ok)
          break;
        for (int q = 0; q < 3; q++) {
          uint32_t y = nv3[4 * q];
          nv3[4 * q] = nv3[4 * q + 1];
          nv3[4 * q + 1] = y;
        }
      }
      uint32_t old[2] = {t, u}, ids[3], two[8];
      memcpy(two, m->tv + 4 * (size_t)t, sizeof two / 2);
      memcpy(two + 4, m->tv + 4 * (size_t)u, sizeof two / 2);
      if (!ok || tr_mesh_replace(m, old, 2, nv3, 3, ids) != TR_OK)
        continue;
      /* every other one back by a 3-2 flip: the same two tets, a slot left free */
      uint32_t back[2];
      if (f % 2 == 0 && tr_mesh_replace(m, ids, 3, two, 2, back) == TR_OK)
        freed++;
    }
    uint32_t nfree = 0;
    for (uint32_t t = 0; t < m->nt; t++)
      nfree += tr_tet_is_free(m, t);
    EXPECT_OK(tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL), "mesh after the flips");
    uint32_t nv = m->nv, ne = 6 * nv, *tri = malloc(sizeof *tri * 3 * ne);
    uint32_t *got = malloc(sizeof *got * ne), *want = malloc(sizeof *want * ne);
    EXPECT(tri && got && want, "malloc");
    for (uint32_t i = 0; i < ne; i++) {
      xorshift(&r);
      uint32_t *T = tri + 3 * i;
      if (i > 0 && r % 9 == 0) { /* a repeat, rotated */
        uint32_t k = (uint32_t)(r >> 8) % i;
        for (int q = 0; q < 3; q++)
          T[q] = tri[3 * k + (q + (r >> 40)) % 3];
      } else if (r % 9 == 1) { /* degenerate or past the mesh */
        T[0] = (uint32_t)(r >> 8) % nv;
        T[1] = r >> 40 & 1 ? T[0] : nv + (uint32_t)(r >> 20) % 3;
        T[2] = (uint32_t)(r >> 30) % nv;
      } else if (r % 9 < 6) { /* a face of a live tet (a ghost: its hull face), any order */
        uint32_t t = (uint32_t)(r >> 8) % m->nt;
        while (tr_tet_is_free(m, t))
          t = (t + 1) % m->nt;
        int k = tr_tet_is_ghost(m, t) ? 3 : (int)(r >> 40) % 4;
        for (int q = 0; q < 3; q++)
          T[q] = m->tv[4 * (size_t)t + tr_face_vtx[k][(q + (r >> 50)) % 3]];
        if (r >> 60 & 1) {
          uint32_t y = T[0];
          T[0] = T[1];
          T[1] = y;
        }
      } else { /* three random vertices */
        for (int q = 0; q < 3; q++)
          T[q] = (uint32_t)(r >> (8 + 16 * q)) % nv;
      }
    }
    EXPECT_OK(tr_mesh_find_faces(m, tri, ne, got), "find_faces");
    find_faces_by_hash(m, tri, ne, want);
    for (uint32_t i = 0; i < ne; i++) {
      EXPECT(got[i] == want[i], "round %d, triangle %u (%u %u %u): tet %u, the hash's %u",
             round, i, tri[3 * i], tri[3 * i + 1], tri[3 * i + 2], got[i], want[i]);
      found += got[i] != TR_NONE;
    }
    checked += ne;
    free_left += nfree;
    free(tri);
    free(got);
    free(want);
    tr_mesh_destroy(m);
  }
  EXPECT(found > checked / 3 && found < checked - checked / 10 && freed > 10 && free_left > 0,
         "both answers exercised (%u of %u found), %u slots freed, %u left free", found,
         checked, freed, free_left);
  return 0;
}

/* A constructed Steiner point past TR_STEINER_MAX_BITS is refused with
 * TR_ERR_UNSUPPORTED and left to the caller; one just under it is stored. The sizes are
 * those of the coordinates' numerators and denominators summed over the three axes. */
static int steiner_size_guard_refuses_past_the_limit(void)
{
  struct tr_mesh *m;
  EXPECT_OK(tr_mesh_create(0, 0, &m), "create");
  uint32_t id = TR_NONE, nv0;
  static const double origin[3] = {0, 0, 0};
  EXPECT_OK(tr_mesh_add_vertex(m, origin, &id), "input vertex");
  nv0 = m->nv;
  for (int over = 0; over < 2; over++) {
    tr_qpoint *q = malloc(sizeof *q);
    EXPECT(q != NULL, "malloc");
    tr_qpoint_init(q);
    /* x = 1/2^k with 1 + (k + 1) + 2 * 2 bits in all: at the limit, or one past it */
    mp_bitcnt_t k = (mp_bitcnt_t)TR_STEINER_MAX_BITS - 6 + (mp_bitcnt_t)over;
    mpq_set_ui(q->c[0], 1, 1);
    mpq_div_2exp(q->c[0], q->c[0], k);
    tr_qpoint_update(q);
    tr_status s = tr_mesh_add_constructed(m, q, &id);
    if (over) {
      EXPECT(s == TR_ERR_UNSUPPORTED && strstr(tr_last_error(), "bits (limit"),
             "one bit past the limit: %s: %s", tr_status_name(s), tr_last_error());
      EXPECT(m->nv == nv0 + 1, "the refused point is not stored (%u vertices)", m->nv);
      tr_qpoint_clear(q);
      free(q);
    } else {
      EXPECT(s == TR_OK && id == nv0 && m->vq[id] == q, "at the limit: %s: %s",
             tr_status_name(s), tr_last_error());
    }
  }
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  const char *c = argv[1];
  if (!strcmp(c, "face_table"))
    return face_table_matches_orientation();
  if (!strcmp(c, "codes"))
    return codes_are_the_papers();
  if (!strcmp(c, "replace"))
    return replace_flips_keep_volume_and_links();
  if (!strcmp(c, "replace_fast"))
    return replace_flip_links_equal_general_matching();
  if (!strcmp(c, "validator"))
    return validator_catches_corruption();
  if (!strcmp(c, "ball_shell"))
    return ball_and_shell_match_brute_force();
  if (!strcmp(c, "ball_find"))
    return ball_find_matches_brute_force();
  if (!strcmp(c, "find_edges"))
    return find_edges_matches_brute_force();
  if (!strcmp(c, "find_faces_random"))
    return find_faces_equals_the_hash_on_random_meshes();
  if (!strcmp(c, "find_edges_random"))
    return find_edges_matches_adjacency_on_random_meshes();
  if (!strcmp(c, "steiner_guard"))
    return steiner_size_guard_refuses_past_the_limit();
  if (!strcmp(c, "hilbert"))
    return hilbert_curve_is_continuous();
  fprintf(stderr, "unknown case %s\n", c);
  return 2;
}
