/* The long sub-segments near a point (src/refine/longs.c): rf_longs_near answers "maybe"
 * for every point that the exact test (rf_in_diametral on the exact end points) finds
 * inside the diametral sphere of a live sub-segment a close circumcentre may split
 * (rf_close_split), so refine_tet never skips a cavity that holds such a piece. Checked
 * on pieces with rational end points (thirds of their input edge, whose doubles are off
 * the exact points), pieces far longer than the grid's cell (the wide list), pieces split
 * after the grid was built (rf_subseg_add adds the long halves), and query points exactly
 * on the spheres, one ulp inside and outside, and at random. It must also answer "no"
 * somewhere, or it would skip nothing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "predicates.h"
#include "qpoint.h"
#include "refine/refine_impl.h"
#include "../pipeline/texpect.h"

static double frand(void)
{
  return rand() / (RAND_MAX + 1.0);
}

/* A point at parameter num/den of the segment from vertex a to vertex b, exact. */
static uint32_t point_on(tr_mesh *m, uint32_t a, uint32_t b, long num, long den)
{
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  mpq_t t, u, x;
  mpq_inits(t, u, x, NULL);
  mpq_set_si(t, num, (unsigned long)den);
  mpq_canonicalize(t);
  for (int i = 0; i < 3; i++) {
    mpq_set_d(x, m->xyz[3 * (size_t)a + i]);
    mpq_set_d(u, m->xyz[3 * (size_t)b + i]);
    mpq_sub(u, u, x);
    mpq_mul(u, u, t);
    mpq_add(q->c[i], x, u);
  }
  mpq_clears(t, u, x, NULL);
  tr_qpoint_update(q);
  uint32_t id = TR_NONE;
  tr_status s = tr_mesh_add_steiner(m, q, &id);
  EXPECT(s == TR_OK, "Steiner point: %s", tr_last_error());
  return id;
}

/* The oracle: some live piece with rf_close_split(emin) has p exactly inside its
 * diametral sphere. */
static int oracle(const rf_ctx *c, const double p[3], double emin)
{
  tr_point P = tr_pt_d(p);
  for (uint32_t g = 0; g < c->nss; g++) {
    if (c->ssdead[g] || !rf_close_split(c, g, emin))
      continue;
    tr_point a = tr_mesh_point(c->m, c->ssv[2 * (size_t)g]),
             b = tr_mesh_point(c->m, c->ssv[2 * (size_t)g + 1]);
    if (rf_in_diametral(&a, &b, &P))
      return 1;
  }
  return 0;
}

/* Queries around every live piece and at random; counts the "no" answers. */
static void probe(rf_ctx *c, const char *when, int *no, int *total)
{
  const tr_mesh *m = c->m;
  for (uint32_t g = 0; g < c->nss; g++) {
    if (c->ssdead[g])
      continue;
    const double *u = m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g],
                 *v = m->xyz + 3 * (size_t)c->ssv[2 * (size_t)g + 1];
    double o[3], d[3], l2 = 0;
    for (int j = 0; j < 3; j++) {
      o[j] = 0.5 * (u[j] + v[j]);
      d[j] = v[j] - u[j];
      l2 += d[j] * d[j];
    }
    for (int k = 0; k < 24; k++) {
      /* on the sphere (within rounding) along a random direction, then one ulp each way
       * in every coordinate; the emin that decides rf_close_split's first bound */
      double w[3] = {frand() - 0.5, frand() - 0.5, frand() - 0.5}, wl = 0;
      for (int j = 0; j < 3; j++)
        wl += w[j] * w[j];
      wl = sqrt(wl);
      double p[3];
      for (int j = 0; j < 3; j++)
        p[j] = o[j] + 0.5 * sqrt(l2) * w[j] / wl * (k < 8 ? 1 : k < 16 ? 0.999 : 1.001);
      for (int s = 0; s < 3; s++) {
        double q[3] = {p[0], p[1], p[2]};
        if (s)
          for (int j = 0; j < 3; j++)
            q[j] = nextafter(q[j], s == 1 ? o[j] : (q[j] > o[j] ? INFINITY : -INFINITY));
        double emin = k % 3 == 0 ? l2 / 4 : k % 3 == 1 ? l2 / 4.0000001 : l2 / 16;
        int maybe = -1;
        tr_status st = rf_longs_near(c, q, emin, &maybe);
        EXPECT(st == TR_OK, "%s: %s", when, tr_last_error());
        int want = oracle(c, q, emin);
        EXPECT(!want || maybe == 1, "%s: piece %u, probe %d/%d: a piece to split was missed",
               when, g, k, s);
        *no += maybe == 0;
        (*total)++;
      }
    }
  }
  for (int k = 0; k < 2000; k++) {
    double p[3] = {4 * frand() - 1.5, 4 * frand() - 1.5, 4 * frand() - 1.5}, emin = 1e-4 * frand();
    int maybe = -1;
    tr_status st = rf_longs_near(c, p, emin, &maybe);
    EXPECT(st == TR_OK, "%s: %s", when, tr_last_error());
    EXPECT(!oracle(c, p, emin) || maybe == 1, "%s: random probe %d: a piece to split was missed",
           when, k);
    *no += maybe == 0;
    (*total)++;
  }
}

static void never_misses_a_piece_to_split(void)
{
  tr_mesh *m = NULL;
  tr_status s = tr_mesh_create(64, 64, &m);
  EXPECT(s == TR_OK && m, "mesh: %s", tr_last_error());
  if (!m)
    return;
  rf_ctx c;
  memset(&c, 0, sizeof c);
  c.m = m;
  srand(11);
  /* 60 input edges of lengths 0.01 to 0.1 in the unit cube, and 2 of length about 3 */
  uint32_t A[62], B[62];
  for (int e = 0; e < 62; e++) {
    double x[3], y[3], len = e < 60 ? 0.01 + 0.09 * frand() : 3;
    for (int j = 0; j < 3; j++) {
      x[j] = e < 60 ? frand() : -1 + 0.1 * j;
      y[j] = x[j] + len * (frand() - 0.5);
    }
    if (e >= 60)
      y[e - 60] = x[e - 60] + len;
    s = tr_mesh_add_vertex(m, x, &A[e]);
    if (s == TR_OK)
      s = tr_mesh_add_vertex(m, y, &B[e]);
    EXPECT(s == TR_OK, "vertices: %s", tr_last_error());
  }
  /* every third edge is in three pieces at its thirds (rational ends), the others whole */
  for (int e = 0; e < 62 && s == TR_OK; e++) {
    if (e % 3) {
      s = rf_subseg_add(&c, A[e], B[e], A[e], B[e], NULL);
      continue;
    }
    uint32_t p1 = point_on(m, A[e], B[e], 1, 3), p2 = point_on(m, A[e], B[e], 2, 3);
    s = rf_subseg_add(&c, A[e], p1, A[e], B[e], NULL);
    if (s == TR_OK)
      s = rf_subseg_add(&c, p1, p2, A[e], B[e], NULL);
    if (s == TR_OK)
      s = rf_subseg_add(&c, p2, B[e], A[e], B[e], NULL);
  }
  EXPECT(s == TR_OK, "sub-segments: %s", tr_last_error());
  int no = 0, total = 0;
  probe(&c, "as built", &no, &total);
  EXPECT(c.longs.built && c.longs.wide.n > 0, "the two long edges are not in the wide list");
  /* split half of the whole pieces after the grid was built: at 1/2 (two long halves,
   * added to the grid) or at 1/5 (one long piece, one short) */
  uint32_t n = c.nss;
  for (uint32_t g = 0; g < n && s == TR_OK; g += 2) {
    if (c.ssdead[g] || !rf_piece_long(&c, g))
      continue;
    uint32_t a = c.ssv[2 * (size_t)g], b = c.ssv[2 * (size_t)g + 1];
    uint32_t mid = point_on(m, a, b, 1, g % 4 ? 5 : 2);
    c.ssdead[g] = 1;
    s = rf_subseg_add(&c, a, mid, c.ssab[2 * (size_t)g], c.ssab[2 * (size_t)g + 1], NULL);
    if (s == TR_OK)
      s = rf_subseg_add(&c, mid, b, c.ssab[2 * (size_t)g], c.ssab[2 * (size_t)g + 1], NULL);
  }
  EXPECT(s == TR_OK, "splits: %s", tr_last_error());
  probe(&c, "after splits", &no, &total);
  EXPECT(no > total / 4, "only %d of %d probes answered no: the grid would skip nothing", no,
         total);
  free(c.ssv);
  free(c.ssab);
  free(c.ssdead);
  free(c.ssnosplit);
  tr_edgeset_free(&c.es);
  rf_longs_free(&c.longs);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"near", never_misses_a_piece_to_split, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
