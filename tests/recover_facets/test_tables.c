/* Tables 10, 11, 12 and the SZZS mirror case, verified by verify() (verify.c) on a fixed
 * configuration and many random exact ones per case, plus every single-entry mutant of
 * every table rejected. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dectable.h"
#include "qgeom.h"
#include "recover_facets/cluster_tables.h"
#include "recover_facets/dtype.h"
#include "verify.h"

/* ---- configurations ---- */

static void random_positive_tet(uint64_t *rs, config *cf, long range)
{
  for (;;) {
    for (int i = TR_DV_A; i <= TR_DV_D; i++)
      qv_set_si(&cf->p[i], rng_range(rs, -range, range), rng_range(rs, -range, range),
                rng_range(rs, -range, range));
    int o = qv_orient(&cf->p[TR_DV_A], &cf->p[TR_DV_B], &cf->p[TR_DV_C], &cf->p[TR_DV_D]);
    if (o == 0)
      continue;
    if (o < 0) { /* swap A and B: an odd relabeling flips the orientation */
      qv tmp;
      qv_init(&tmp);
      qv_set(&tmp, &cf->p[TR_DV_A]);
      qv_set(&cf->p[TR_DV_A], &cf->p[TR_DV_B]);
      qv_set(&cf->p[TR_DV_B], &tmp);
      qv_clear(&tmp);
    }
    return;
  }
}

/* Steiner points from parameters s[] in (0,1): THR_EDG P1 = A + s0 (D - A) etc.;
 * FOU_EDG P1 on AD, P2 on BD, P3 on BC from s[], P4 where their plane meets AC. */
static void place_steiner(config *cf, int four, mpq_t s[3])
{
  qv *P = cf->p;
  if (!four) {
    qv_lerp(&P[TR_DV_P1], &P[TR_DV_A], &P[TR_DV_D], s[0]);
    qv_lerp(&P[TR_DV_P2], &P[TR_DV_B], &P[TR_DV_D], s[1]);
    qv_lerp(&P[TR_DV_P3], &P[TR_DV_C], &P[TR_DV_D], s[2]);
    cf->npoly = 3;
    cf->poly[0] = TR_DV_P1, cf->poly[1] = TR_DV_P2, cf->poly[2] = TR_DV_P3;
    return;
  }
  qv_lerp(&P[TR_DV_P1], &P[TR_DV_A], &P[TR_DV_D], s[0]);
  qv_lerp(&P[TR_DV_P2], &P[TR_DV_B], &P[TR_DV_D], s[1]);
  qv_lerp(&P[TR_DV_P3], &P[TR_DV_B], &P[TR_DV_C], s[2]);
  /* t = f(A) / (f(A) - f(C)) with f(X) = n.(X - P1): A and C are on opposite sides
   * (A opposite D via P1, B opposite D via P2, B opposite C via P3). */
  qv n, u, v;
  qv_init(&n), qv_init(&u), qv_init(&v);
  qv_sub(&u, &P[TR_DV_P2], &P[TR_DV_P1]);
  qv_sub(&v, &P[TR_DV_P3], &P[TR_DV_P1]);
  qv_cross(&n, &u, &v);
  mpq_t fa, fc, t;
  mpq_init(fa), mpq_init(fc), mpq_init(t);
  qv_sub(&u, &P[TR_DV_A], &P[TR_DV_P1]);
  qv_dot(fa, &n, &u);
  qv_sub(&u, &P[TR_DV_C], &P[TR_DV_P1]);
  qv_dot(fc, &n, &u);
  mpq_sub(t, fa, fc);
  mpq_div(t, fa, t);
  qv_lerp(&P[TR_DV_P4], &P[TR_DV_A], &P[TR_DV_C], t);
  mpq_clear(fa), mpq_clear(fc), mpq_clear(t);
  qv_clear(&n), qv_clear(&u), qv_clear(&v);
  cf->npoly = 4;
  for (int i = 0; i < 4; i++)
    cf->poly[i] = (uint8_t)(TR_DV_P1 + i);
}


/* Fixed special configurations first (midpoints, extreme parameters), then random ones
 * in a fixed sequence. */
static int make_cluster_config(config *cf, const tr_cluster_case *c, int four, int iter)
{
  uint64_t rs = 0x9e3779b97f4a7c15ull ^ (uint64_t)(iter + 1) * 0x100000001b3ull;
  for (int i = 0; i < 3; i++)
    rng_next(&rs);
  mpq_t s[3];
  for (int i = 0; i < 3; i++)
    mpq_init(s[i]);
  if (iter == 0) {
    qv_set_si(&cf->p[TR_DV_A], 0, 0, 0), qv_set_si(&cf->p[TR_DV_B], 1, 0, 0);
    qv_set_si(&cf->p[TR_DV_C], 0, 1, 0), qv_set_si(&cf->p[TR_DV_D], 0, 0, 1);
    for (int i = 0; i < 3; i++)
      mpq_set_si(s[i], 1, 2);
  } else {
    random_positive_tet(&rs, cf, iter < 100 ? 5 : 1000);
    for (int i = 0; i < 3; i++) {
      if (iter % 7 == 1)
        mpq_set_si(s[i], (i & 1) ? 1 : 999, 1000); /* slivers next to the vertices */
      else
        rng_open01(&rs, s[i]);
    }
  }
  place_steiner(cf, four, s);
  for (int i = 0; i < 3; i++)
    mpq_clear(s[i]);
  return place_h(cf, c);
}

static int check_cluster_case(const tr_cluster_case *c, int four, int iters)
{
  config cf;
  config_init(&cf);
  char what[128];
  int fails = 0;
  for (int it = 0; it < iters && fails < 5; it++) {
    snprintf(what, sizeof what, "%s (%s) configuration %d", c->table->name, c->name, it);
    if (make_cluster_config(&cf, c, four, it)) {
      fprintf(stderr, "FAIL %s: H not placed: %s\n", what, tr_last_error());
      fails++;
      continue;
    }
    fails += verify(c->table, &cf, c->dtype, what);
  }
  config_clear(&cf);
  return fails;
}

/* Swap32: AB pierces the interior of CDE. */
static void make_swap32_config(config *cf, int iter)
{
  uint64_t rs = 0x51ed270b7a3c9d1full ^ (uint64_t)(iter + 1) * 0x9e3779b97f4a7c15ull;
  qv *P = cf->p;
  for (;;) {
    long r = iter < 100 ? 6 : 1000;
    for (int i = TR_DV_C; i <= TR_DV_E; i++)
      qv_set_si(&P[i], rng_range(&rs, -r, r), rng_range(&rs, -r, r), rng_range(&rs, -r, r));
    /* Q: an interior point of CDE (positive barycentric weights). */
    long w0 = rng_range(&rs, 1, 9), w1 = rng_range(&rs, 1, 9), w2 = rng_range(&rs, 1, 9);
    qv q, dir;
    qv_init(&q), qv_init(&dir);
    mpq_t x, y;
    mpq_init(x), mpq_init(y);
    for (int k = 0; k < 3; k++) {
      mpq_set_si(x, w0, 1);
      mpq_mul(q.c[k], P[TR_DV_C].c[k], x);
      mpq_set_si(x, w1, 1);
      mpq_mul(y, P[TR_DV_D].c[k], x);
      mpq_add(q.c[k], q.c[k], y);
      mpq_set_si(x, w2, 1);
      mpq_mul(y, P[TR_DV_E].c[k], x);
      mpq_add(q.c[k], q.c[k], y);
      mpq_set_si(x, w0 + w1 + w2, 1);
      mpq_div(q.c[k], q.c[k], x);
    }
    qv_set_si(&dir, rng_range(&rs, -r, r), rng_range(&rs, -r, r), rng_range(&rs, -r, r));
    mpq_set_si(y, rng_range(&rs, 1, 20), (unsigned long)rng_range(&rs, 1, 20));
    mpq_canonicalize(y); /* GMP's mpq arithmetic requires canonical operands */
    for (int k = 0; k < 3; k++) {
      mpq_add(P[TR_DV_A].c[k], q.c[k], dir.c[k]);
      mpq_mul(x, dir.c[k], y);
      mpq_sub(P[TR_DV_B].c[k], q.c[k], x);
    }
    mpq_clear(x), mpq_clear(y);
    qv_clear(&q), qv_clear(&dir);
    int o = qv_orient(&P[TR_DV_C], &P[TR_DV_D], &P[TR_DV_E], &P[TR_DV_A]);
    if (o == 0)
      continue;
    if (qv_orient(&P[TR_DV_A], &P[TR_DV_B], &P[TR_DV_C], &P[TR_DV_D]) < 0) {
      /* Swapping A and B flips all three old tets around AB at once. */
      qv tmp;
      qv_init(&tmp);
      qv_set(&tmp, &P[TR_DV_A]);
      qv_set(&P[TR_DV_A], &P[TR_DV_B]);
      qv_set(&P[TR_DV_B], &tmp);
      qv_clear(&tmp);
    }
    break;
  }
  cf->npoly = 3;
  cf->poly[0] = TR_DV_E, cf->poly[1] = TR_DV_C, cf->poly[2] = TR_DV_D;
}

static int check_swap32(int iters)
{
  config cf;
  config_init(&cf);
  char what[128];
  int fails = 0;
  for (int it = 0; it < iters && fails < 5; it++) {
    snprintf(what, sizeof what, "Table 10 Swap32 configuration %d", it);
    make_swap32_config(&cf, it);
    fails += verify(&tr_table10_swap32, &cf, NULL, what);
  }
  config_clear(&cf);
  return fails;
}

/* ---- mutants: every single-entry change of every table must be rejected ---- */

static int mutant_rejected(const tr_dectable *orig, const tr_dtet *tets, const config *cf,
                           const int8_t *dtype)
{
  tr_dectable m = *orig;
  m.tets = tets;
  verify_quiet = 1;
  int r = verify(&m, cf, dtype, "mutant");
  verify_quiet = 0;
  return r != 0;
}

static int check_mutants_of(const tr_dectable *t, const config *cf, const int8_t *dtype,
                            long *count)
{
  tr_dtet buf[16];
  int fails = 0;
  char what[128];
  snprintf(what, sizeof what, "%s (unmutated)", t->name);
  if (verify(t, cf, dtype, what))
    return 1;
  /* The names a vertex may be replaced by: every name the table uses. */
  uint8_t names[TR_DV_COUNT];
  int nn = 0;
  for (uint8_t x = 0; x < TR_DV_COUNT; x++) {
    int used = 0;
    for (int r = 0; r < t->nnew; r++)
      for (int i = 0; i < 4; i++)
        used |= t->tets[r].v[i] == x;
    if (used)
      names[nn++] = x;
  }
  for (int r = 0; r < t->nnew; r++) {
    for (int i = 0; i < 4; i++) {
      /* a vertex replaced */
      for (int q = 0; q < nn; q++) {
        if (names[q] == t->tets[r].v[i])
          continue;
        memcpy(buf, t->tets, t->nnew * sizeof *buf);
        buf[r].v[i] = names[q];
        ++*count;
        if (!mutant_rejected(t, buf, cf, dtype)) {
          fprintf(stderr, "FAIL %s row %d: vertex %d -> %s accepted\n", t->name, r + 1, i,
                  tr_dv_name(names[q]));
          fails++;
        }
      }
      /* two vertices swapped (with their neighbour columns: only the orientation
       * changes) */
      for (int k = i + 1; k < 4; k++) {
        memcpy(buf, t->tets, t->nnew * sizeof *buf);
        uint8_t x = buf[r].v[i];
        buf[r].v[i] = buf[r].v[k];
        buf[r].v[k] = x;
        tr_dnb y = buf[r].n[i];
        buf[r].n[i] = buf[r].n[k];
        buf[r].n[k] = y;
        ++*count;
        if (!mutant_rejected(t, buf, cf, dtype)) {
          fprintf(stderr, "FAIL %s row %d: swapping vertices %d,%d accepted\n", t->name,
                  r + 1, i, k);
          fails++;
        }
      }
      /* a neighbour spec replaced: other internal tet, other Phi vertex, other NG */
      tr_dnb alt[32];
      int na = 0;
      const tr_dnb *n = &t->tets[r].n[i];
      for (int q = 0; q < t->nnew; q++)
        if (q != r && !(n->kind == TR_DNB_INTERNAL && n->tet == q))
          alt[na++] = (tr_dnb)TR_DEC_IN(q);
      for (uint8_t x = TR_DV_A; x <= TR_DV_F; x++) {
        if (n->kind == TR_DNB_PHI) {
          if (x != n->vtx && tr_dectable_old_index(t, 0, x) >= 0)
            alt[na++] = (tr_dnb)TR_DEC_PHI(x, n->fac[0], n->fac[1], n->fac[2]);
        } else {
          for (int j = 0; j < t->nold; j++)
            if (tr_dectable_old_index(t, j, x) >= 0 &&
                !(n->kind == TR_DNB_NG && n->tet == j && n->vtx == x))
              alt[na++] = (tr_dnb)TR_DEC_NG(j + 1, x);
        }
      }
      for (int q = 0; q < na; q++) {
        memcpy(buf, t->tets, t->nnew * sizeof *buf);
        buf[r].n[i] = alt[q];
        ++*count;
        if (!mutant_rejected(t, buf, cf, dtype)) {
          fprintf(stderr, "FAIL %s row %d N%d: replacement %d accepted\n", t->name, r + 1,
                  i + 1, q);
          fails++;
        }
      }
    }
  }
  /* a wrong S/Z claim */
  if (dtype)
    for (int x = 0; x < 4; x++) {
      if (dtype[x] == TR_DTYPE_NONE)
        continue;
      int8_t d2[4];
      memcpy(d2, dtype, 4);
      d2[x] = (int8_t)(1 - d2[x]);
      ++*count;
      if (!mutant_rejected(t, t->tets, cf, d2)) {
        fprintf(stderr, "FAIL %s: flipped S/Z claim for face %d accepted\n", t->name, x);
        fails++;
      }
    }
  return fails;
}

static int check_mutants(void)
{
  config cf;
  config_init(&cf);
  int fails = 0;
  long count = 0;
  make_swap32_config(&cf, 3);
  fails += check_mutants_of(&tr_table10_swap32, &cf, NULL, &count);
  for (int c = 0; c < TR_NUM_THR_EDG; c++) {
    make_cluster_config(&cf, &tr_thr_edg_cases[c], 0, 5);
    fails += check_mutants_of(tr_thr_edg_cases[c].table, &cf, tr_thr_edg_cases[c].dtype,
                              &count);
  }
  for (int c = 0; c < TR_NUM_FOU_EDG; c++) {
    make_cluster_config(&cf, &tr_fou_edg_cases[c], 1, 5);
    fails += check_mutants_of(tr_fou_edg_cases[c].table, &cf, tr_fou_edg_cases[c].dtype,
                              &count);
  }
  config_clear(&cf);
  printf("%ld mutants checked\n", count);
  return fails;
}

static const tr_cluster_case *find_case(const char *name, int *four)
{
  for (int c = 0; c < TR_NUM_THR_EDG; c++)
    if (!strcmp(tr_thr_edg_cases[c].name, name)) {
      *four = 0;
      return &tr_thr_edg_cases[c];
    }
  for (int c = 0; c < TR_NUM_FOU_EDG; c++)
    if (!strcmp(tr_fou_edg_cases[c].name, name)) {
      *four = 1;
      return &tr_fou_edg_cases[c];
    }
  return NULL;
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s swap32 | mutants | <case name> [configurations]\n", argv[0]);
    return 2;
  }
  int iters = argc > 2 ? atoi(argv[2]) : 300;
  int fails;
  if (!strcmp(argv[1], "swap32")) {
    fails = check_swap32(iters);
  } else if (!strcmp(argv[1], "mutants")) {
    fails = check_mutants();
  } else {
    int four;
    const tr_cluster_case *c = find_case(argv[1], &four);
    if (!c) {
      fprintf(stderr, "unknown case %s\n", argv[1]);
      return 2;
    }
    fails = check_cluster_case(c, four, iters);
  }
  if (fails) {
    fprintf(stderr, "%s: %d failure(s)\n", argv[1], fails);
    return 1;
  }
  printf("%s: ok\n", argv[1]);
  return 0;
}
