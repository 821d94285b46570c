/* Rounds of parallel insertion (src/refine/rounds.c): refinement of a box under a volume
 * bound, with rounds from 256 queued bad tets on (the default threshold needs a mesh of
 * millions of tets), on 1, 2 and 3 threads. The three stores are the same byte for byte
 * (vertices, tets, neighbours, sub-faces), rounds inserted at least a third of the points, and each
 * mesh goes through the mesh validator (links, exact orientation, v2t), the exact
 * conformity validator with the box's exact volume, and the exact volume bound.
 * scripts/tsan.sh runs the 'threads' case under ThreadSanitizer. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/check.h"
#include "mesh/conform.h"
#include "outer/color.h"
#include "refine/refine.h"
#include "../pipeline/tmesh.h"
#include "../pipeline/tplc.h"
#include "../pipeline/trecover.h"
#include "tvolume.h"

typedef struct {
  trec_run r;
  tr_refine_stats st;
  int ok;
} run_t;

/* The box [0,2]x[0,1]x[0,1] refined under R = 1.414, V = vmax on nth threads. */
static void refine_box(tr_plc *plc, double vmax, int nth, run_t *x)
{
  memset(x, 0, sizeof *x);
  tr_status s = trec_to_recovery(plc, &x->r);
  uint32_t nreg = 0;
  if (s == TR_OK)
    s = tr_outer_color(x->r.m, &x->r.sub, 0, NULL, &nreg);
  tr_refine_params par;
  memset(&par, 0, sizeof par);
  par.ratio = 1.414;
  par.max_volume = vmax;
  par.spacing_radii = 1;
  par.wedge_grading = 1;
  par.flat_splits = 1;
  par.threads = nth;
  par.round_min = 256;
  if (s == TR_OK)
    s = tr_refine(x->r.m, plc, &x->r.sub, &par, &x->st);
  EXPECT(s == TR_OK, "%d threads: refinement: %s", nth, tr_last_error());
  if (s != TR_OK)
    return;
  x->ok = 1;
  const tr_mesh *m = x->r.m;
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL);
  EXPECT(s == TR_OK, "%d threads: mesh validator: %s", nth, tr_last_error());
  mpq_t v6;
  mpq_init(v6);
  mpq_set_ui(v6, 12, 1); /* 6 x the box's volume 2 */
  s = tr_check_conformity(m, plc, v6, 0);
  EXPECT(s == TR_OK, "%d threads: exact conformity and volume: %s", nth, tr_last_error());
  mpq_clear(v6);
  uint32_t counted = 0, over = tv_count_over(m, vmax, UINT32_MAX, &counted);
  EXPECT(over == 0, "%d threads: %u of %u tets over the volume bound", nth, over, counted);
}

static int same_store(const tr_mesh *a, const tr_mesh *b)
{
  return a->nv == b->nv && a->nt == b->nt && !memcmp(a->xyz, b->xyz, 24 * (size_t)a->nv) &&
         !memcmp(a->tv, b->tv, 16 * (size_t)a->nt) && !memcmp(a->tn, b->tn, 16 * (size_t)a->nt) &&
         !memcmp(a->v2t, b->v2t, 4 * (size_t)a->nv);
}

static int same_subfaces(const tr_subfaces *a, const tr_subfaces *b)
{
  return a->n == b->n && !memcmp(a->v, b->v, 12 * (size_t)a->n) &&
         !memcmp(a->tri, b->tri, 4 * (size_t)a->n);
}

static void threads(double vmax, uint64_t min_points)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {2, 1, 1};
  tr_plc *plc = tm_box(lo, hi);
  run_t x[3];
  for (int i = 0; i < 3; i++)
    refine_box(plc, vmax, i + 1, &x[i]);
  if (x[0].ok) {
    const tr_refine_stats *s = &x[0].st;
    EXPECT(s->points >= min_points, "%llu points, fewer than %llu", (unsigned long long)s->points,
           (unsigned long long)min_points);
    EXPECT(s->rounds > 0 && 3 * s->round_points > s->points,
           "%llu rounds inserted %llu of %llu points: not a third", (unsigned long long)s->rounds,
           (unsigned long long)s->round_points, (unsigned long long)s->points);
    fprintf(stderr, "box, V = %g: %llu points, %llu of them in %llu rounds, %llu round tets "
            "left to the serial loop; %u tet slots\n", vmax, (unsigned long long)s->points,
            (unsigned long long)s->round_points, (unsigned long long)s->rounds,
            (unsigned long long)s->round_serial, x[0].r.m->nt);
  }
  for (int i = 1; i < 3; i++)
    if (x[0].ok && x[i].ok) {
      EXPECT(same_store(x[0].r.m, x[i].r.m), "%d threads: the store differs from 1 thread's",
             i + 1);
      EXPECT(same_subfaces(&x[0].r.sub, &x[i].r.sub),
             "%d threads: the sub-faces differ from 1 thread's", i + 1);
      EXPECT(!memcmp(&x[0].st, &x[i].st, sizeof x[0].st),
             "%d threads: the refinement counts differ from 1 thread's", i + 1);
    }
  for (int i = 0; i < 3; i++)
    trec_free(&x[i].r);
  tr_plc_destroy(plc);
}

static void threads_small(void)
{
  threads(5e-4, 1000);
}

static void threads_large(void)
{
  threads(1e-4, 6000);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"threads", threads_small, NULL},
      {"threads_large", threads_large, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
