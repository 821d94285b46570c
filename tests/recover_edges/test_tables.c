/* Geometric verification of the paper's Tables 3-9 (src/recover_edges/edge_tables.c) on
 * exact rational configurations. Usage: test_tables <table-index> | carriers | dtype.
 *
 * For a table, with its old tets and Steiner points placed exactly (mpq):
 *  (a) every new tet is positively oriented;
 *  (b) the new tets' signed volumes sum exactly to the old tets';
 *  (c) faces shared by two new tets are exactly the INTERNAL links, the two tets lie on
 *      opposite sides of them, and no face is used by three tets;
 *  (d) NG faces are the named old faces; PHI sub-faces are coplanar with and inside the
 *      original face opposite vtx;
 *  (e) the non-internal sub-faces tile each original boundary face (area identity via
 *      cone volumes with the opposite vertex as apex);
 *  (f) the recovered segment is an edge of a new tet.
 * "carriers" checks that each Steiner carrier recorded in the table is the only edge
 * (face) of the tet for which (a)-(e) hold, i.e. the deduction from the table is forced.
 * The determinant here is our own mpq code, independent of predicates/. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dectable.h"
#include "recover_edges/dtype.h"
#include "recover_facets/dtype.h"
#include "recover_edges/edge_tables.h"

typedef struct config {
  mpq_t x[TR_DV_COUNT][3];
} config;

static int verbose = 1;
#define REPORT(...)                  \
  do {                               \
    if (verbose) {                   \
      fprintf(stderr, __VA_ARGS__);  \
      fputc('\n', stderr);           \
    }                                \
  } while (0)

static void cfg_init(config *c)
{
  for (int i = 0; i < TR_DV_COUNT; i++)
    for (int j = 0; j < 3; j++)
      mpq_init(c->x[i][j]);
}
static void cfg_clear(config *c)
{
  for (int i = 0; i < TR_DV_COUNT; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(c->x[i][j]);
}
static void cfg_set(config *c, int v, long x, long y, long z)
{
  mpq_set_si(c->x[v][0], x, 1);
  mpq_set_si(c->x[v][1], y, 1);
  mpq_set_si(c->x[v][2], z, 1);
}

/* det[b-a; c-a; d-a] (six times the signed volume). */
static void det4(const config *c, int a, int b, int cc, int d, mpq_t out)
{
  mpq_t m[3][3], t, u;
  mpq_init(t);
  mpq_init(u);
  const int r[3] = {b, cc, d};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      mpq_init(m[i][j]);
      mpq_sub(m[i][j], c->x[r[i]][j], c->x[a][j]);
    }
  mpq_set_ui(out, 0, 1);
  for (int j = 0; j < 3; j++) {
    int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    mpq_mul(t, m[1][j1], m[2][j2]);
    mpq_mul(u, m[1][j2], m[2][j1]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, m[0][j]);
    mpq_add(out, out, t);
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(m[i][j]);
  mpq_clear(t);
  mpq_clear(u);
}

static int orient(const config *c, int a, int b, int cc, int d)
{
  mpq_t v;
  mpq_init(v);
  det4(c, a, b, cc, d, v);
  int s = mpq_sgn(v);
  mpq_clear(v);
  return s;
}

/* Places Steiner point s at the weighted barycentre of its carrier. The weights are
 * deliberately uneven so that no symmetry hides a wrong entry. */
static void place(config *c, uint8_t name, int ncar, const uint8_t *car)
{
  static const long w[4][4] = {{0}, {0}, {2, 3}, {1, 2, 4}};
  static const long w4[4] = {1, 2, 3, 4};
  const long *wt = ncar == 4 ? w4 : w[ncar];
  long tot = 0;
  for (int i = 0; i < ncar; i++)
    tot += wt[i];
  mpq_t t;
  mpq_init(t);
  for (int j = 0; j < 3; j++) {
    mpq_set_ui(c->x[name][j], 0, 1);
    for (int i = 0; i < ncar; i++) {
      mpq_set_si(t, wt[i], tot);
      mpq_canonicalize(t);
      mpq_mul(t, t, c->x[car[i]][j]);
      mpq_add(c->x[name][j], c->x[name][j], t);
    }
  }
  mpq_clear(t);
}

/* Old-tet coordinates for each table family. */
static void setup_old(const tr_dectable *t, config *c)
{
  if (t == &tr_table3_swap23) {
    /* AB pierces CDE at (10/7, 1, 0). */
    cfg_set(c, TR_DV_A, 1, 1, -3);
    cfg_set(c, TR_DV_B, 2, 1, 4);
    cfg_set(c, TR_DV_C, 4, 0, 0);
    cfg_set(c, TR_DV_D, 0, 4, 0);
    cfg_set(c, TR_DV_E, 0, 0, 0);
  } else if (t == &tr_table4_swap44) {
    /* ABCD in z = 0, AB crosses CD at s = 14/29; E above, F below. */
    cfg_set(c, TR_DV_A, -2, 0, 0);
    cfg_set(c, TR_DV_B, 3, 1, 0);
    cfg_set(c, TR_DV_C, 0, -2, 0);
    cfg_set(c, TR_DV_D, 1, 4, 0);
    cfg_set(c, TR_DV_E, 1, 0, 3);
    cfg_set(c, TR_DV_F, 0, 1, -2);
  } else {
    /* det = 111 > 0 */
    cfg_set(c, TR_DV_A, 0, 0, 0);
    cfg_set(c, TR_DV_B, 5, 1, 0);
    cfg_set(c, TR_DV_C, 1, 4, 1);
    cfg_set(c, TR_DV_D, 2, 1, 6);
  }
}

/* The recovered segment of each table (the sub-segment of the missing edge). */
static void recovered(const tr_dectable *t, uint8_t seg[2])
{
  seg[0] = TR_DV_P1;
  seg[1] = TR_DV_P2;
  if (t == &tr_table3_swap23 || t == &tr_table4_swap44) {
    seg[0] = TR_DV_A;
    seg[1] = TR_DV_B;
  } else if (t == &tr_table5_case1 || t == &tr_table7_case3) {
    seg[0] = TR_DV_A; /* NOD_EDG / NOD_FAC: the missing edge passes through A */
    seg[1] = TR_DV_P1;
  }
}

static void face_of_old(const tr_dectable *t, int j, int vi, uint8_t f[3])
{
  int m = 0;
  for (int i = 0; i < 4; i++)
    if (i != vi)
      f[m++] = t->old[j][i];
}

static int sorted_eq(uint8_t a[3], uint8_t b[3])
{
  uint8_t x[3] = {a[0], a[1], a[2]}, y[3] = {b[0], b[1], b[2]};
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++) {
      uint8_t s;
      if (x[j] < x[i]) { s = x[i]; x[i] = x[j]; x[j] = s; }
      if (y[j] < y[i]) { s = y[i]; y[i] = y[j]; y[j] = s; }
    }
  return memcmp(x, y, 3) == 0;
}

/* 1 iff point q lies in the closed triangle (u,v,w) (vertex names), whose plane leaves
 * apex x strictly on one side: coplanar and all three sub-orientations agree. */
static int in_face(const config *c, int q, const uint8_t f[3], int x)
{
  int s = orient(c, f[0], f[1], f[2], x);
  if (s == 0 || orient(c, f[0], f[1], f[2], q) != 0)
    return 0;
  int s0 = orient(c, q, f[1], f[2], x), s1 = orient(c, f[0], q, f[2], x),
      s2 = orient(c, f[0], f[1], q, x);
  return s0 * s != -1 && s1 * s != -1 && s2 * s != -1;
}

/* Checks (a)-(f). Returns the number of violations (reported when verbose). */
static int check_geometry(const tr_dectable *t, const tr_dectable *base, const config *c)
{
  int bad = 0;
  const char *nm = t->name;
  /* (a) */
  for (int r = 0; r < t->nnew; r++) {
    const uint8_t *v = t->tets[r].v;
    if (orient(c, v[0], v[1], v[2], v[3]) <= 0) {
      REPORT("%s row %d (%s%s%s%s): (a) new tet not positively oriented", nm, r + 1,
             tr_dv_name(v[0]), tr_dv_name(v[1]), tr_dv_name(v[2]), tr_dv_name(v[3]));
      bad++;
    }
  }
  for (int j = 0; j < t->nold; j++)
    if (orient(c, t->old[j][0], t->old[j][1], t->old[j][2], t->old[j][3]) <= 0) {
      REPORT("%s: configuration error, old tet t%d not positive", nm, j + 1);
      bad++;
    }
  /* (b) */
  mpq_t so, sn, v;
  mpq_inits(so, sn, v, NULL);
  for (int j = 0; j < t->nold; j++) {
    det4(c, t->old[j][0], t->old[j][1], t->old[j][2], t->old[j][3], v);
    mpq_add(so, so, v);
  }
  for (int r = 0; r < t->nnew; r++) {
    const uint8_t *q = t->tets[r].v;
    det4(c, q[0], q[1], q[2], q[3], v);
    mpq_add(sn, sn, v);
  }
  if (!mpq_equal(so, sn)) {
    REPORT("%s: (b) volumes differ: old %s, new %s (x6)", nm, mpq_get_str(NULL, 10, so),
           mpq_get_str(NULL, 10, sn));
    bad++;
  }
  /* (c) every face: count its uses, match INTERNAL links, opposite sides */
  for (int r = 0; r < t->nnew; r++)
    for (int k = 0; k < 4; k++) {
      const tr_dtet *d = &t->tets[r];
      uint8_t f[3];
      tr_dtet_face_sorted(d, k, f);
      int uses = 0, other = -1, ok = -1;
      for (int r2 = 0; r2 < t->nnew; r2++)
        for (int k2 = 0; k2 < 4; k2++) {
          uint8_t g[3];
          tr_dtet_face_sorted(&t->tets[r2], k2, g);
          if (memcmp(f, g, 3) == 0) {
            uses++;
            if (r2 != r) {
              other = r2;
              ok = k2;
            }
          }
        }
      const tr_dnb *n = &d->n[k];
      if (uses > 2) {
        REPORT("%s row %d N%d: (c) face used by %d tets", nm, r + 1, k + 1, uses);
        bad++;
      } else if (uses == 2) {
        if (n->kind != TR_DNB_INTERNAL || n->tet != other) {
          REPORT("%s row %d N%d: (c) face shared with row %d but not linked to it", nm,
                 r + 1, k + 1, other + 1);
          bad++;
        } else if (orient(c, f[0], f[1], f[2], d->v[k]) *
                       orient(c, f[0], f[1], f[2], t->tets[other].v[ok]) != -1) {
          REPORT("%s row %d N%d: (c) row %d is not across the face", nm, r + 1, k + 1,
                 other + 1);
          bad++;
        }
      } else if (n->kind == TR_DNB_INTERNAL) {
        REPORT("%s row %d N%d: (c) INTERNAL link to row %d which lacks the face", nm, r + 1,
               k + 1, n->tet + 1);
        bad++;
      }
    }
  /* (d) + (e) */
  if (t->nold == 1) {
    for (int xi = 0; xi < 4; xi++) {
      uint8_t x = t->old[0][xi], of[3];
      face_of_old(t, 0, xi, of);
      mpq_set_ui(sn, 0, 1);
      for (int r = 0; r < t->nnew; r++)
        for (int k = 0; k < 4; k++) {
          const tr_dtet *d = &t->tets[r];
          const tr_dnb *n = &d->n[k];
          if (n->kind == TR_DNB_INTERNAL || n->vtx != x)
            continue;
          uint8_t f[3];
          tr_dtet_face_sorted(d, k, f);
          if (n->kind == TR_DNB_NG && !sorted_eq(f, of)) {
            REPORT("%s row %d N%d: (d) NG face is not the old face opposite %s", nm, r + 1,
                   k + 1, tr_dv_name(x));
            bad++;
          }
          for (int i = 0; i < 3; i++)
            if (!in_face(c, f[i], of, x)) {
              REPORT("%s row %d N%d: (d) %s is not on the old face opposite %s", nm, r + 1,
                     k + 1, tr_dv_name(f[i]), tr_dv_name(x));
              bad++;
            }
          /* cone over the sub-face with apex x: the new tet with v[k] replaced by x */
          uint8_t w[4];
          memcpy(w, d->v, 4);
          w[k] = x;
          det4(c, w[0], w[1], w[2], w[3], v);
          mpq_add(sn, sn, v);
        }
      if (!mpq_equal(so, sn)) {
        REPORT("%s: (e) sub-faces do not tile the face opposite %s", nm, tr_dv_name(x));
        bad++;
      }
    }
  } else {
    /* Swaps: boundary faces of the old union = faces of old tets used once. Each must be
     * the face of exactly one new tet, linked by NG to that old tet and vertex. */
    for (int j = 0; j < t->nold; j++)
      for (int vi = 0; vi < 4; vi++) {
        uint8_t of[3], g[3];
        face_of_old(t, j, vi, of);
        int shared = 0;
        for (int j2 = 0; j2 < t->nold; j2++)
          for (int v2 = 0; v2 < 4; v2++)
            if (j2 != j) {
              face_of_old(t, j2, v2, g);
              shared |= sorted_eq(of, g);
            }
        if (shared)
          continue;
        int cover = 0;
        for (int r = 0; r < t->nnew; r++)
          for (int k = 0; k < 4; k++) {
            const tr_dnb *n = &t->tets[r].n[k];
            tr_dtet_face_sorted(&t->tets[r], k, g);
            if (sorted_eq(of, g)) {
              if (n->kind == TR_DNB_NG && n->tet == j && n->vtx == t->old[j][vi])
                cover++;
              else {
                REPORT("%s row %d N%d: (d) boundary face of t%d not linked NG(t%d,%s)", nm,
                       r + 1, k + 1, j + 1, j + 1, tr_dv_name(t->old[j][vi]));
                bad++;
              }
            }
          }
        if (cover != 1) {
          REPORT("%s: (e) face of t%d opposite %s covered %d times", nm, j + 1,
                 tr_dv_name(t->old[j][vi]), cover);
          bad++;
        }
      }
    for (int r = 0; r < t->nnew; r++)
      for (int k = 0; k < 4; k++)
        if (t->tets[r].n[k].kind == TR_DNB_PHI) {
          REPORT("%s row %d N%d: (d) PHI in a swap table", nm, r + 1, k + 1);
          bad++;
        }
  }
  mpq_clears(so, sn, v, NULL);
  /* (f) */
  uint8_t seg[2];
  recovered(base, seg);
  int found = 0;
  for (int r = 0; r < t->nnew; r++) {
    int h = 0;
    for (int i = 0; i < 4; i++)
      h += t->tets[r].v[i] == seg[0] || t->tets[r].v[i] == seg[1];
    found |= h == 2;
  }
  if (!found) {
    REPORT("%s: (f) recovered segment %s%s is not an edge of a new tet", nm,
           tr_dv_name(seg[0]), tr_dv_name(seg[1]));
    bad++;
  }
  return bad;
}

static void place_all(const tr_dectable *t, config *c, const uint8_t car[][4])
{
  setup_old(t, c);
  for (int s = 0; s < t->nsteiner; s++)
    place(c, t->steiner[s].name, t->steiner[s].ncar, car[s]);
}

static int run_table(const tr_dectable *t)
{
  config c;
  cfg_init(&c);
  uint8_t car[TR_DEC_MAX_STEINER][4];
  for (int s = 0; s < t->nsteiner; s++)
    memcpy(car[s], t->steiner[s].car, 4);
  place_all(t, &c, car);
  int bad = 0;
  if (tr_dectable_check(t) != TR_OK) {
    fprintf(stderr, "%s: symbolic check: %s\n", t->name, tr_last_error());
    bad++;
  }
  bad += check_geometry(t, t, &c);
  cfg_clear(&c);
  if (!bad)
    printf("%s: %d new tets, all checks (a)-(f) pass\n", t->name, t->nnew);
  return bad;
}

/* Every alternative carrier of the same dimension must break the geometry. */
static int run_carriers(void)
{
  static const uint8_t edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  int bad = 0;
  verbose = 0;
  for (int ti = 0; ti < tr_num_edge_tables; ti++) {
    const tr_dectable *t = tr_edge_tables[ti];
    for (int s = 0; s < t->nsteiner; s++) {
      int nalt = t->steiner[s].ncar == 2 ? 6 : 4, passing = 0;
      for (int a = 0; a < nalt; a++) {
        uint8_t car[TR_DEC_MAX_STEINER][4];
        for (int s2 = 0; s2 < t->nsteiner; s2++)
          memcpy(car[s2], t->steiner[s2].car, 4);
        if (nalt == 6) {
          car[s][0] = edges[a][0];
          car[s][1] = edges[a][1];
        } else {
          for (int i = 0, m = 0; i < 4; i++)
            if (i != a)
              car[s][m++] = (uint8_t)i;
        }
        config c;
        cfg_init(&c);
        place_all(t, &c, car);
        int ok = check_geometry(t, t, &c) == 0;
        cfg_clear(&c);
        uint8_t x[3] = {car[s][0], car[s][1], nalt == 6 ? car[s][0] : car[s][2]};
        uint8_t y[3] = {t->steiner[s].car[0], t->steiner[s].car[1],
                        nalt == 6 ? t->steiner[s].car[0] : t->steiner[s].car[2]};
        int is_recorded = sorted_eq(x, y);
        passing += ok;
        if (ok != is_recorded) {
          fprintf(stderr, "%s: Steiner %s on carrier #%d: geometry %s but table says %s\n",
                  t->name, tr_dv_name(t->steiner[s].name), a, ok ? "valid" : "invalid",
                  is_recorded ? "this carrier" : "another");
          bad++;
        }
      }
      if (passing != 1) {
        fprintf(stderr, "%s: %d carriers valid for %s\n", t->name, passing,
                tr_dv_name(t->steiner[s].name));
        bad++;
      }
    }
  }
  if (!bad)
    printf("every Steiner carrier is the unique one the geometry allows\n");
  return bad;
}

/* DType agrees with Table 6's labels, and flips across a shared face. */
static int run_dtype(void)
{
  int bad = 0;
  /* t = ABCD (codes 0..3), face ABD = face 2, apex D = 3: II-S diagonal from B (1) to P1
   * on AD; II-Z diagonal from A (0) to P2 on BD. */
  if (tr_dtype_of_diagonal(2, 3, 1) != TR_DTYPE_S) {
    fprintf(stderr, "dtype: Table 6 II-S (diagonal B-P1 in ABD of ABCD) is not S\n");
    bad++;
  }
  if (tr_dtype_of_diagonal(2, 3, 0) != TR_DTYPE_Z) {
    fprintf(stderr, "dtype: Table 6 II-Z (diagonal A-P2 in ABD of ABCD) is not Z\n");
    bad++;
  }
  /* The facet module's table-based DType (recover_facets/dtype.h) must agree. */
  if (tr_dtype_of_table(&tr_table6_case2_2s, TR_DV_C) != TR_DTYPE_S ||
      tr_dtype_of_table(&tr_table6_case2_2z, TR_DV_C) != TR_DTYPE_Z) {
    fprintf(stderr, "dtype: recover_facets' tr_dtype_of_table disagrees on Table 6 II\n");
    bad++;
  }
  /* The tables themselves: II-S has edge B-P1 and not A-P2; II-Z the reverse. */
  const tr_dectable *tb[2] = {&tr_table6_case2_2s, &tr_table6_case2_2z};
  for (int i = 0; i < 2; i++) {
    int hasbp1 = 0, hasap2 = 0;
    for (int r = 0; r < tb[i]->nnew; r++) {
      const uint8_t *v = tb[i]->tets[r].v;
      int b = 0, p1 = 0, a = 0, p2 = 0;
      for (int k = 0; k < 4; k++) {
        b |= v[k] == TR_DV_B;
        p1 |= v[k] == TR_DV_P1;
        a |= v[k] == TR_DV_A;
        p2 |= v[k] == TR_DV_P2;
      }
      hasbp1 |= b && p1;
      hasap2 |= a && p2;
    }
    if (hasbp1 != (i == 0) || hasap2 != (i == 1)) {
      fprintf(stderr, "dtype: %s does not use the diagonal its label says\n", tb[i]->name);
      bad++;
    }
  }
  /* Invariance and flip over all 12 even relabelings of a tet and all faces/apexes: the
   * same physical diagonal is S in the tet iff it is Z in the mirrored neighbour (the
   * neighbour across face k sees the face with the opposite orientation; model it as
   * the tet with two face vertices swapped and k's vertex replaced). */
  for (int k = 0; k < 4; k++)
    for (int apex = 0; apex < 4; apex++) {
      if (apex == k)
        continue;
      int x, y;
      tr_dtype_xy(k, apex, &x, &y);
      /* neighbour: same face vertices, swap x and y's slots (odd permutation of the face
       * makes it positive again on the other side) */
      int perm[4] = {0, 1, 2, 3};
      perm[x] = y;
      perm[y] = x;
      /* in the neighbour, physical vertex x sits at local code y */
      int from_s = tr_dtype_diagonal_from(k, apex, TR_DTYPE_S);
      int nb_local = perm[from_s];
      if (tr_dtype_of_diagonal(k, apex, nb_local) != TR_DTYPE_Z) {
        fprintf(stderr, "dtype: face %d apex %d: S diagonal is not Z from the neighbour\n", k,
                apex);
        bad++;
      }
      if (tr_dtype_of_diagonal(k, apex, from_s) != TR_DTYPE_S ||
          tr_dtype_of_diagonal(k, apex, tr_dtype_diagonal_from(k, apex, TR_DTYPE_Z)) !=
              TR_DTYPE_Z) {
        fprintf(stderr, "dtype: face %d apex %d: round trip fails\n", k, apex);
        bad++;
      }
    }
  if (!bad)
    printf("DType matches Table 6 and flips across a shared face\n");
  return bad;
}

/* 1 iff the checks (symbolic + geometric) reject table t, a mutant of base. */
static int geometry_only;
static int rejected(const tr_dectable *t, const tr_dectable *base)
{
  if (tr_dectable_check(t) != TR_OK)
    return 1;
  geometry_only++;
  config c;
  cfg_init(&c);
  uint8_t car[TR_DEC_MAX_STEINER][4];
  for (int s = 0; s < t->nsteiner; s++)
    memcpy(car[s], t->steiner[s].car, 4);
  setup_old(base, &c);
  for (int s = 0; s < t->nsteiner; s++)
    place(&c, t->steiner[s].name, t->steiner[s].ncar, car[s]);
  int bad = check_geometry(t, base, &c);
  cfg_clear(&c);
  return bad > 0;
}

static int spec_eq(const tr_dnb *a, const tr_dnb *b)
{
  return a->kind == b->kind && a->tet == b->tet && a->vtx == b->vtx &&
         memcmp(a->fac, b->fac, 3) == 0;
}

/* The checks must have teeth: every single-entry corruption of every table (a vertex
 * name replaced, two vertices swapped, a neighbour spec replaced by another plausible
 * one) must be rejected. Mutants that are equal to the original are skipped. */
static int run_mutants(void)
{
  int bad = 0, total = 0;
  verbose = 0;
  for (int ti = 0; ti < tr_num_edge_tables; ti++) {
    const tr_dectable *base = tr_edge_tables[ti];
    tr_dtet rows[16];
    tr_dectable m = *base;
    m.tets = rows;
    /* vertex mutations */
    for (int r = 0; r < base->nnew; r++)
      for (int i = 0; i < 4; i++) {
        for (int nv = 0; nv < TR_DV_COUNT; nv++) {
          if (nv == base->tets[r].v[i])
            continue;
          memcpy(rows, base->tets, base->nnew * sizeof rows[0]);
          rows[r].v[i] = (uint8_t)nv;
          total++;
          if (!rejected(&m, base)) {
            fprintf(stderr, "%s row %d: vertex %d -> %s not detected\n", base->name, r + 1,
                    i + 1, tr_dv_name((uint8_t)nv));
            bad++;
          }
        }
        for (int j = i + 1; j < 4; j++) {
          memcpy(rows, base->tets, base->nnew * sizeof rows[0]);
          uint8_t s = rows[r].v[i];
          rows[r].v[i] = rows[r].v[j];
          rows[r].v[j] = s;
          total++;
          if (!rejected(&m, base)) {
            fprintf(stderr, "%s row %d: swap of vertices %d,%d not detected\n", base->name,
                    r + 1, i + 1, j + 1);
            bad++;
          }
        }
      }
    /* neighbour-spec mutations: every spec of the table, moved to every other slot */
    for (int r = 0; r < base->nnew; r++)
      for (int k = 0; k < 4; k++)
        for (int r2 = 0; r2 < base->nnew; r2++)
          for (int k2 = 0; k2 < 4; k2++) {
            if (spec_eq(&base->tets[r].n[k], &base->tets[r2].n[k2]))
              continue;
            memcpy(rows, base->tets, base->nnew * sizeof rows[0]);
            rows[r].n[k] = base->tets[r2].n[k2];
            total++;
            if (!rejected(&m, base)) {
              fprintf(stderr, "%s row %d N%d: spec from row %d N%d not detected\n",
                      base->name, r + 1, k + 1, r2 + 1, k2 + 1);
              bad++;
            }
          }
    /* NG / PHI with the wrong vertex */
    for (int r = 0; r < base->nnew; r++)
      for (int k = 0; k < 4; k++) {
        if (base->tets[r].n[k].kind == TR_DNB_INTERNAL)
          continue;
        for (int x = 0; x < 4; x++) {
          uint8_t nv = base->old[base->tets[r].n[k].tet][x];
          if (nv == base->tets[r].n[k].vtx)
            continue;
          memcpy(rows, base->tets, base->nnew * sizeof rows[0]);
          rows[r].n[k].vtx = nv;
          total++;
          if (!rejected(&m, base)) {
            fprintf(stderr, "%s row %d N%d: vertex -> %s not detected\n", base->name, r + 1,
                    k + 1, tr_dv_name(nv));
            bad++;
          }
        }
      }
  }
  if (!bad)
    printf("all %d single-entry mutants of the tables are rejected (%d pass the symbolic "
           "check and are caught by the geometry)\n", total, geometry_only);
  return bad;
}

/* Whole-table relabelings: apply every permutation of the names the table uses to its
 * new tets (vertices and specs), keeping the old tets and carriers. A relabeled table
 * that passes the symbolic check must be caught by the geometry unless it describes the
 * same set of new tets (a symmetry of the configuration). */
static int next_perm(uint8_t *a, int n)
{
  int i = n - 2;
  while (i >= 0 && a[i] >= a[i + 1])
    i--;
  if (i < 0)
    return 0;
  int j = n - 1;
  while (a[j] <= a[i])
    j--;
  uint8_t t = a[i];
  a[i] = a[j];
  a[j] = t;
  for (int l = i + 1, r = n - 1; l < r; l++, r--) {
    t = a[l];
    a[l] = a[r];
    a[r] = t;
  }
  return 1;
}

/* 1 iff the relabeling `map` is a combinatorial symmetry of the configuration: it
 * permutes the old tets, each by an even permutation, and carries every Steiner carrier
 * onto the carrier of the image point. For a one-tet table, relabeling a valid table by
 * a symmetry gives a valid table (e.g. Table 9 with the roles of P1 and P2 exchanged,
 * the mirror of Scheme 1), so the checks must accept it. */
static int is_symmetry(const tr_dectable *t, const uint8_t map[TR_DV_COUNT])
{
  for (int j = 0; j < t->nold; j++) {
    int ok = 0;
    for (int j2 = 0; j2 < t->nold && !ok; j2++) {
      int pos[4], hit = 0;
      for (int i = 0; i < 4; i++) {
        pos[i] = tr_dectable_old_index(t, j2, map[t->old[j][i]]);
        hit += pos[i] >= 0;
      }
      if (hit != 4)
        continue;
      int inv = 0;
      for (int a = 0; a < 4; a++)
        for (int b = a + 1; b < 4; b++)
          inv += pos[a] > pos[b];
      ok = (inv & 1) == 0;
    }
    if (!ok)
      return 0;
  }
  for (int s = 0; s < t->nsteiner; s++) {
    const tr_dsteiner *img = tr_dectable_steiner(t, map[t->steiner[s].name]);
    if (!img || img->ncar != t->steiner[s].ncar)
      return 0;
    for (int i = 0; i < img->ncar; i++) {
      int found = 0;
      for (int i2 = 0; i2 < img->ncar; i2++)
        found |= map[t->steiner[s].car[i]] == img->car[i2];
      if (!found)
        return 0;
    }
  }
  return 1;
}

/* Index of the old tet whose vertex set is map(old[j]), or j when there is none. */
static uint8_t old_image(const tr_dectable *t, const uint8_t map[TR_DV_COUNT], int j)
{
  for (int j2 = 0; j2 < t->nold; j2++) {
    int hit = 0;
    for (int i = 0; i < 4; i++)
      hit += tr_dectable_old_index(t, j2, map[t->old[j][i]]) >= 0;
    if (hit == 4)
      return (uint8_t)j2;
  }
  return (uint8_t)j;
}

static int run_relabel(void)
{
  int bad = 0, total = 0, symmetric = 0;
  verbose = 0;
  geometry_only = 0;
  for (int ti = 0; ti < tr_num_edge_tables; ti++) {
    const tr_dectable *base = tr_edge_tables[ti];
    uint8_t used[TR_DV_COUNT], n = 0;
    for (int v = 0; v < TR_DV_COUNT; v++) {
      int u = 0;
      for (int r = 0; r < base->nnew; r++)
        for (int i = 0; i < 4; i++)
          u |= base->tets[r].v[i] == v;
      if (u)
        used[n++] = (uint8_t)v;
    }
    uint8_t perm[TR_DV_COUNT];
    memcpy(perm, used, n);
    while (next_perm(perm, n)) {
      uint8_t map[TR_DV_COUNT];
      for (int v = 0; v < TR_DV_COUNT; v++)
        map[v] = (uint8_t)v;
      for (int i = 0; i < n; i++)
        map[used[i]] = perm[i];
      tr_dtet rows[16];
      tr_dectable m = *base;
      m.tets = rows;
      memcpy(rows, base->tets, base->nnew * sizeof rows[0]);
      for (int r = 0; r < base->nnew; r++)
        for (int i = 0; i < 4; i++) {
          rows[r].v[i] = map[rows[r].v[i]];
          if (rows[r].n[i].kind == TR_DNB_NG)
            rows[r].n[i].tet = old_image(base, map, rows[r].n[i].tet);
          if (rows[r].n[i].kind != TR_DNB_INTERNAL) {
            rows[r].n[i].vtx = map[rows[r].n[i].vtx];
            for (int f = 0; f < 3; f++)
              rows[r].n[i].fac[f] = map[rows[r].n[i].fac[f]];
          }
        }
      total++;
      if (is_symmetry(base, map)) {
        symmetric++;
        /* For the swaps, a combinatorial symmetry can break a geometric hypothesis the
         * data does not record (Swap44 needs ABCD coplanar), so only the decomposition
         * tables must accept every symmetry. */
        if (base->nold == 1 && rejected(&m, base)) {
          fprintf(stderr, "%s: a symmetric relabeling is rejected:", base->name);
          for (int i = 0; i < n; i++)
            fprintf(stderr, " %s->%s", tr_dv_name(used[i]), tr_dv_name(perm[i]));
          fputc('\n', stderr);
          bad++;
        }
        continue;
      }
      if (!rejected(&m, base)) {
        fprintf(stderr, "%s: a relabeling passes all checks:", base->name);
        for (int i = 0; i < n; i++)
          fprintf(stderr, " %s->%s", tr_dv_name(used[i]), tr_dv_name(perm[i]));
        fputc('\n', stderr);
        bad++;
      }
    }
  }
  if (!bad)
    printf("of %d relabelings, the %d symmetries of the configuration are accepted and "
           "all others rejected (%d of those only by the geometry)\n",
           total, symmetric, geometry_only);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 2) {
    fprintf(stderr, "usage: test_tables <table index 0..%d> | all | carriers | dtype\n",
            tr_num_edge_tables - 1);
    return 2;
  }
  int bad = 0;
  if (!strcmp(argv[1], "carriers"))
    bad = run_carriers();
  else if (!strcmp(argv[1], "mutants"))
    bad = run_mutants();
  else if (!strcmp(argv[1], "relabel"))
    bad = run_relabel();
  else if (!strcmp(argv[1], "dtype"))
    bad = run_dtype();
  else if (!strcmp(argv[1], "all")) {
    for (int i = 0; i < tr_num_edge_tables; i++)
      bad += run_table(tr_edge_tables[i]);
  } else {
    int i = atoi(argv[1]);
    if (i < 0 || i >= tr_num_edge_tables)
      return 2;
    bad = run_table(tr_edge_tables[i]);
  }
  if (bad)
    fprintf(stderr, "FAILED: %d violation(s)\n", bad);
  return bad ? 1 : 0;
}
