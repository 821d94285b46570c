/* The long sub-segments near a point (refine_impl.h, rf_longs_near): a grid of the
 * diametral balls of the pieces that are at least half their input edge, the only ones a
 * close circumcentre may still split (refine.c, close splits).
 *
 * Why: most circumcentres refinement tries lie too close to a new vertex (cheese.off:
 * 102,780 of 115,516), and such a point only splits the long pieces it encroaches in its
 * cavity. Building that cavity to find none was a sixth of cheese's CPU. When the point is
 * too close to a vertex of the tet that holds it (a tet every cavity of the point keeps)
 * and no long piece has it in or near its diametral ball, the cavity can hold no piece to
 * split, and refine_tet skips it.
 *
 * The grid is built on the first query of a context, from the live pieces then long; a
 * piece split later is dead and its entries are skipped; a new piece that is long (a half
 * of an input edge split once) is added by rf_subseg_add. Pieces whose ball spans many
 * cells are kept in one list that every query scans. The ball test is in doubles with a
 * margin far above the rounding of the pieces' end points (constraint points may be
 * rationals, m->xyz their nearest doubles or one next to it, insert.c), so it never
 * misses a piece the exact test (rf_in_diametral) would find: it only decides which
 * cavities are built. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "refine/refine_impl.h"

#define RF_LONGS_SPAN 4     /* cells per axis a ball may span before it goes to the list */
#define RF_LONGS_MAXC (1u << 20) /* cell coordinates are clamped to [0, RF_LONGS_MAXC) */

/* The squared distance between vertices a and b (on the doubles). */
static double len2(const rf_ctx *c, uint32_t a, uint32_t b)
{
  const double *u = c->m->xyz + 3 * (size_t)a, *v = c->m->xyz + 3 * (size_t)b;
  double l2 = 0;
  for (int j = 0; j < 3; j++)
    l2 += (v[j] - u[j]) * (v[j] - u[j]);
  return l2;
}

/* Whether piece g, of squared length l2, is at least half its input edge. */
static int long_at(const rf_ctx *c, uint32_t g, double l2)
{
  return 4 * l2 >= len2(c, c->ssab[2 * (size_t)g], c->ssab[2 * (size_t)g + 1]);
}

int rf_piece_long(const rf_ctx *c, uint32_t g)
{
  return long_at(c, g, len2(c, c->ssv[2 * (size_t)g], c->ssv[2 * (size_t)g + 1]));
}

int rf_close_split(const rf_ctx *c, uint32_t g, double emin)
{
  double l2 = len2(c, c->ssv[2 * (size_t)g], c->ssv[2 * (size_t)g + 1]);
  return l2 >= 4 * emin && long_at(c, g, l2);
}

/* Piece g's ball: centre, radius with the margin. */
static void ball_of(const rf_ctx *c, uint32_t g, double o[3], double *r)
{
  const double *x = c->m->xyz;
  const double *u = x + 3 * (size_t)c->ssv[2 * (size_t)g], *v = x + 3 * (size_t)c->ssv[2 * (size_t)g + 1];
  double l2 = 0, s = 0;
  for (int j = 0; j < 3; j++) {
    o[j] = 0.5 * (u[j] + v[j]);
    l2 += (v[j] - u[j]) * (v[j] - u[j]);
    s = fmax(s, fmax(fabs(u[j]), fabs(v[j])));
  }
  *r = 0.5 * sqrt(l2) * (1 + 1e-9) + 1e-12 * s;
}

static uint32_t cell_of(const rf_longs *L, double x, int j)
{
  double q = floor((x - L->o[j]) / L->h);
  if (!(q >= 0)) /* NaN too */
    return 0;
  return q >= RF_LONGS_MAXC - 1 ? RF_LONGS_MAXC - 1 : (uint32_t)q;
}

static tr_status add(rf_ctx *c, uint32_t g)
{
  rf_longs *L = &c->longs;
  double o[3], r;
  ball_of(c, g, o, &r);
  uint32_t lo[3], hi[3];
  int wide = !isfinite(r);
  for (int j = 0; j < 3 && !wide; j++) {
    lo[j] = cell_of(L, o[j] - r, j);
    hi[j] = cell_of(L, o[j] + r, j);
    wide = hi[j] - lo[j] >= RF_LONGS_SPAN;
  }
  if (wide)
    return tr_u32buf_push(&L->wide, g);
  for (uint32_t i = lo[0]; i <= hi[0]; i++)
    for (uint32_t j = lo[1]; j <= hi[1]; j++)
      for (uint32_t k = lo[2]; k <= hi[2]; k++) {
        uint32_t key[3] = {i, j, k}, head = tr_vtmap_get(&L->cells, 3, key);
        uint32_t e = (uint32_t)(L->ent.n / 2);
        TR_CHECK(tr_u32buf_push(&L->ent, g));
        TR_CHECK(tr_u32buf_push(&L->ent, head)); /* TR_VTMAP_NONE ends a list */
        TR_CHECK(tr_vtmap_set(&L->cells, 3, key, e));
      }
  return TR_OK;
}

static int by_value(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static tr_status build(rf_ctx *c)
{
  rf_longs *L = &c->longs;
  const struct tr_mesh *m = c->m;
  L->built = 1;
  /* the cell: twice the median length of the long pieces */
  size_t n = 0;
  for (uint32_t g = 0; g < c->nss; g++)
    n += !c->ssdead[g] && rf_piece_long(c, g);
  if (!n)
    return TR_OK;
  double *rad = malloc(sizeof *rad * n);
  if (!rad)
    return tr_error(TR_ERR_NOMEM, "out of memory for %zu long sub-segments", n);
  size_t k = 0;
  for (uint32_t g = 0; g < c->nss; g++)
    if (!c->ssdead[g] && rf_piece_long(c, g)) {
      double o[3], r;
      ball_of(c, g, o, &r);
      rad[k++] = r;
    }
  qsort(rad, n, sizeof *rad, by_value);
  L->h = 4 * rad[n / 2]; /* the radius is half the length */
  free(rad);
  for (int j = 0; j < 3; j++)
    L->o[j] = INFINITY;
  for (uint32_t v = 0; v < m->nv; v++)
    for (int j = 0; j < 3; j++)
      L->o[j] = fmin(L->o[j], m->xyz[3 * (size_t)v + j]);
  if (!(L->h > 0) || !isfinite(L->h) || !isfinite(L->o[0] + L->o[1] + L->o[2])) {
    L->h = INFINITY; /* every piece in the list */
    L->o[0] = L->o[1] = L->o[2] = 0;
  }
  TR_CHECK(tr_vtmap_reserve(&L->cells, 3, (uint32_t)(n < UINT32_MAX / 8 ? 2 * n : n)));
  for (uint32_t g = 0; g < c->nss; g++)
    if (!c->ssdead[g] && rf_piece_long(c, g))
      TR_CHECK(add(c, g));
  return TR_OK;
}

tr_status rf_longs_added(rf_ctx *c, uint32_t g)
{
  if (!c->longs.built || !rf_piece_long(c, g))
    return TR_OK;
  return add(c, g);
}

static int near(const rf_ctx *c, uint32_t g, const double p[3], double emin)
{
  if (c->ssdead[g] || !rf_close_split(c, g, emin))
    return 0;
  double o[3], r;
  ball_of(c, g, o, &r);
  double d2 = (p[0] - o[0]) * (p[0] - o[0]) + (p[1] - o[1]) * (p[1] - o[1]) +
              (p[2] - o[2]) * (p[2] - o[2]);
  return !(sqrt(d2) > r); /* NaN: near */
}

tr_status rf_longs_near(rf_ctx *c, const double p[3], double emin, int *maybe)
{
  rf_longs *L = &c->longs;
  *maybe = 0;
  if (!L->built)
    TR_CHECK(build(c));
  for (size_t i = 0; i < L->wide.n; i++)
    if (near(c, L->wide.a[i], p, emin)) {
      *maybe = 1;
      return TR_OK;
    }
  if (!L->cells.n)
    return TR_OK;
  uint32_t key[3] = {cell_of(L, p[0], 0), cell_of(L, p[1], 1), cell_of(L, p[2], 2)};
  for (uint32_t e = tr_vtmap_get(&L->cells, 3, key); e != TR_VTMAP_NONE; e = L->ent.a[2 * (size_t)e + 1])
    if (near(c, L->ent.a[2 * (size_t)e], p, emin)) {
      *maybe = 1;
      return TR_OK;
    }
  return TR_OK;
}

void rf_longs_free(rf_longs *L)
{
  tr_vtmap_free(&L->cells);
  tr_u32buf_free(&L->ent);
  tr_u32buf_free(&L->wide);
  memset(L, 0, sizeof *L);
}
