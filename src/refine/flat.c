/* Flat sub-faces (issue 17, pinion; tr_refine_params.flat_splits: on for refinement's
 * own loop by default, and after the sliver stage's pinned splits too under
 * --subface-quality). A sub-face with an angle over 120 degrees at a vertex v,
 * opposite a sub-segment g, is the trace of a thin input wedge whose two sides were split
 * at points that do not face each other (midpoints of pieces of different lengths): v, on
 * one side, lies almost on g, on the other. Every tet standing on such a sub-face has a
 * dihedral angle near 180 degrees at g or near 0 at v, whatever its apex, and no interior
 * point repairs it; the small-angle rules (angles.c) protect g from v, so refinement
 * leaves it. TetGen merges such triangles away (-p within 0.1 degree of flat); tetrec
 * keeps every input edge, so here g is split once, at v's foot on g (a dyadic fraction
 * of g, exactly on its input edge): the two new sub-faces have a right angle there
 * instead of the flat one, a rung across the wedge, and no edge shorter than v's distance
 * to g, so nothing is graded towards the wedge's corner.
 * Left as they are: a flat angle opposite an edge inside the facet (no constraint: the
 * facet's pieces are constrained, not split for that), and the pieces of an input
 * triangle that has an angle over 120 degrees itself (the input's own shape: every piece
 * near that corner is flat or thin whatever is split; u.off: 9.75% -> 13.0% of tets under
 * 10 degrees when they were split too).
 *
 * Bounded: rf_flat_scan is one pass over the live sub-faces; each gives at most one split
 * and the sub-faces made after the pass are not scanned again (the tets they make are
 * refined under the usual rules). It runs after tr_refine's loop and after each
 * tr_refine_open_pinned of the sliver stage, whose splits of pinned tets' pieces (at
 * midpoints) make most of the flat sub-faces (pinion: 551 after refinement, 2,078 after
 * the pinned splits). Measured in doubles: the angle only chooses which sub-segments get
 * a point; the point itself is exact (rf_segment_split_point).
 *
 * Cost (bench/quality, 74 models; shares of tets under 10 degrees): on by default (before
 * the input-cap rule) it met issue 17's targets on 2 more models (oblong, rotor) for 11%
 * more CPU (76.1 -> 84.8 s against TetGen's 81.3: 1.04x), so it was left to
 * --subface-quality, where it takes pinion from 11.07% to 6.99% (pinion_small 11.97 ->
 * 8.47, handle 4.71 -> 3.13, anchor 6.13 -> 4.11, rotor 1.61 -> 0.77, cheese 2.09 ->
 * 1.29; worse: u 0.92 -> 2.47, joint 0.68 -> 0.91) for 14% more CPU (90.0 -> 103.0 s),
 * the same models meeting the targets. Once spacing radii and the sliver stage's Hilbert
 * order had made the stage cheaper, refinement's own pass (not the one after the pinned
 * splits) became the default: 0.90% -> 0.80% of all tets under 10 degrees, 3.00M ->
 * 3.18M tets, 68.7 -> 71.9 s of CPU (+5%), targets met on 60 models instead of 59 (rotor
 * 0.87% -> 0.75%, pinion 6.79% -> 4.62%; worse: joint 0.32% -> 0.44%, u 3.53% -> 4.17%,
 * both missing either way). */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_impl.h"

#define RF_FLAT_COS (-0.5) /* cos 120 degrees */

/* Parameter of x's foot on the input edge (A, B) of sub-segment g, along A -> B. */
static double foot_param(const rf_ctx *c, uint32_t g, const double *x)
{
  const double *A = c->plc->xyz + 3 * (size_t)c->ssab[2 * (size_t)g],
               *B = c->plc->xyz + 3 * (size_t)c->ssab[2 * (size_t)g + 1];
  double e[3], d[3];
  for (int i = 0; i < 3; i++) {
    e[i] = B[i] - A[i];
    d[i] = x[i] - A[i];
  }
  double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  return ee > 0 ? (d[0] * e[0] + d[1] * e[1] + d[2] * e[2]) / ee : NAN;
}

/* 1 iff sub-face f's input triangle has an angle over 120 degrees itself. */
static int input_flat(const rf_ctx *c, uint32_t f)
{
  const uint32_t *T = c->plc->tris + 3 * (size_t)c->sftri[f];
  for (int i = 0; i < 3; i++)
    if (rf_cos_angle(c->plc->xyz + 3 * (size_t)T[i], c->plc->xyz + 3 * (size_t)T[(i + 1) % 3],
               c->plc->xyz + 3 * (size_t)T[(i + 2) % 3]) < RF_FLAT_COS)
      return 1;
  return 0;
}

int rf_flat_split_param(const rf_ctx *c, uint32_t g, const mpq_t lo, const mpq_t hi, mpq_t t)
{
  if (g >= c->nssfoot || isnan(c->ssfoot[g]))
    return 0;
  double l = mpq_get_d(lo), h = mpq_get_d(hi);
  if (!(h > l))
    return 0;
  /* the foot as a fraction of g in sixty-fourths, an eighth of g away from its ends:
   * exactly inside g, with a bounded denominator */
  double s = floor((c->ssfoot[g] - l) / (h - l) * 64 + 0.5);
  s = s < 8 ? 8 : s > 56 ? 56 : s;
  mpq_t w;
  mpq_init(w);
  mpq_sub(w, hi, lo);
  mpq_set_ui(t, (unsigned long)s, 64);
  mpq_canonicalize(t); /* 32/64: mpq_equal, which compares limbs, takes it for another value */
  mpq_mul(t, t, w);
  mpq_add(t, t, lo);
  mpq_clear(w);
  return 1;
}

tr_status rf_flat_scan(rf_ctx *c, int *pushed)
{
  *pushed = 0;
  free(c->ssfoot);
  c->nssfoot = 0;
  c->ssfoot = malloc((c->nss ? c->nss : 1) * sizeof *c->ssfoot);
  if (!c->ssfoot)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-segments", c->nss);
  c->nssfoot = c->nss;
  for (uint32_t g = 0; g < c->nss; g++)
    c->ssfoot[g] = NAN;
  for (uint32_t f = 0; f < c->nsf; f++) {
    if (c->sfdead[f])
      continue;
    const uint32_t *v = c->sfv + 3 * (size_t)f;
    for (int i = 0; i < 3; i++) {
      uint32_t p = v[(i + 1) % 3], q = v[(i + 2) % 3];
      const double *x = c->m->xyz + 3 * (size_t)v[i];
      if (!(rf_cos_angle(x, c->m->xyz + 3 * (size_t)p, c->m->xyz + 3 * (size_t)q) < RF_FLAT_COS))
        continue;
      /* a triangle has one angle over 90 degrees at most: f is done either way */
      uint32_t g = rf_subseg_of(c, p, q);
      if (g == TR_NONE || c->ssnosplit[g] || !isnan(c->ssfoot[g]) || input_flat(c, f))
        break;
      c->ssfoot[g] = foot_param(c, g, x);
      if (!isnan(c->ssfoot[g])) {
        TR_CHECK(tr_u32buf_push(&c->qseg, g));
        *pushed = 1;
      }
      break;
    }
  }
  return TR_OK;
}
