/* Orientation and openness of a surface that is not a union of closed 2-manifolds: edges
 * shared by three or more triangles (internal facets between regions, shells touching
 * along an edge) or by one (cracks, open surfaces). tr_plc_validate runs this only for
 * such inputs and only after the self-intersection check: the triangles meet in shared
 * vertices and edges only, which every step below assumes.
 *
 * Cells. The triangles cut space into cells. Each triangle has two sides (+: where its
 * right-hand normal points, -). Around an edge, the triangles sorted by angle leave
 * wedges between consecutive ones; the two sides facing a wedge bound the same cell
 * (exact orient3d sorting; one triangle alone: its two sides meet around the free edge).
 * The connected classes of sides are the boundary components of cells. A cell with
 * several components (a shell inside another) is found by a ray: from a point inside a
 * triangle, on the component's side, the first triangle the ray crosses is seen from
 * the same cell; a ray that crosses nothing reaches infinity. Every decision is exact:
 * the start point is the triangle's centroid (rational), the crossings are classified
 * with tr_classify_segment_triangle and ordered along the ray with orient3d on the
 * constructed crossing points; a ray that grazes an edge, a vertex or a plane is
 * replaced by another direction.
 *
 * Domain. The unbounded cell has depth 0; a cell's depth is the fewest triangles
 * crossed to reach it from infinity. Depth 1 is inside the domain. A deeper cell is
 * inside iff most of the triangles between it and shallower cells face out of it as
 * given (an inclusion, a region of its own, or a body inside a cavity) and outside iff
 * most face into it (a cavity), as tr_input_shell_cavities decides for closed shells; on
 * a tie, odd depth is inside and even depth outside (a cavity is at depth 2). The cell of
 * a hole point (located by a ray: the side of the first triangle crossed) is outside. A
 * triangle between an inside and an outside cell is turned to face the outside cell, one
 * between a nested cell and a shallower cell of the same kind to face out of the nested
 * cell if it is inside and into it if not; any other triangle with the domain (or the
 * outside) on both sides, an internal facet or a crack, keeps its orientation. A
 * triangle with a free edge whose cell is outside the domain is an open surface: an
 * error unless allow_open. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/ufind.h"
#include "classify.h"
#include "construct.h"
#include "core/box.h"
#include "core/edgesort.h"
#include "predicates.h"
#include "validate.h"

#define PRE(plc) (plc)->source ? (plc)->source : "", (plc)->source ? ": " : ""

static const double *P(const struct tr_plc *plc, uint32_t v) { return plc->xyz + 3 * (size_t)v; }

static void edge_of(const uint32_t *t, uint32_t id, uint32_t *lo, uint32_t *hi)
{
  uint32_t a = t[id], b = t[3 * (id / 3) + (id % 3 + 1) % 3];
  *lo = a < b ? a : b;
  *hi = a < b ? b : a;
}

static int cmp_edge(const void *ctx, uint32_t x, uint32_t y)
{
  uint32_t p0, p1, q0, q1;
  edge_of(ctx, x, &p0, &p1);
  edge_of(ctx, y, &q0, &q1);
  if (p0 != q0)
    return p0 < q0 ? -1 : 1;
  return (p1 > q1) - (p1 < q1);
}

static uint32_t third(const uint32_t *v, uint32_t a, uint32_t b)
{
  return v[0] != a && v[0] != b ? v[0] : v[1] != a && v[1] != b ? v[1] : v[2];
}

static int goes(const uint32_t *v, uint32_t a, uint32_t b)
{
  return (v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b);
}

/* Angular order around the axis a->b (right hand), starting at the half-plane of c0:
 * half 0 is [0, pi), half 1 is [pi, 2 pi). */
typedef struct {
  const struct tr_plc *plc;
  uint32_t a, b, c0;
  int drop; /* an axis where the normal of (a, b, c0) is nonzero */
} around;

static int half(const around *r, uint32_t c)
{
  const double *A = P(r->plc, r->a), *B = P(r->plc, r->b);
  int s = tr_sign(tr_orient3d(A, B, P(r->plc, r->c0), P(r->plc, c)));
  if (s)
    return s > 0 ? 0 : 1;
  /* coplanar: same side of the line ab as c0 (angle 0) or the other side (pi) */
  int s0 = tr_sign(tr_orient2d_proj(A, B, P(r->plc, r->c0), r->drop));
  int s1 = tr_sign(tr_orient2d_proj(A, B, P(r->plc, c), r->drop));
  return s0 == s1 ? 0 : 1;
}

/* -1 if c comes before d around the axis. */
static int before(const around *r, uint32_t c, int hc, uint32_t d, int hd)
{
  if (hc != hd)
    return hc < hd ? -1 : 1;
  if (c == d)
    return 0;
  int s = tr_sign(tr_orient3d(P(r->plc, r->a), P(r->plc, r->b), P(r->plc, c), P(r->plc, d)));
  return -s; /* det > 0: d is less than pi further on */
}

/* Unites the sides facing each wedge around one edge; ids[0..k) are edge ids 3t+j. */
static void wedges(const struct tr_plc *plc, const uint32_t *ids, uint32_t k, uint32_t *uf,
                   uint32_t *ord, int *hv)
{
  uint32_t a, b;
  edge_of(plc->tris, ids[0], &a, &b);
  around r = {plc, a, b, third(plc->tris + 3 * (size_t)(ids[0] / 3), a, b), 0};
  while (r.drop < 2 && tr_orient2d_proj(P(plc, a), P(plc, b), P(plc, r.c0), r.drop) == 0)
    r.drop++;
  for (uint32_t i = 0; i < k; i++) {
    ord[i] = ids[i] / 3;
    hv[i] = half(&r, third(plc->tris + 3 * (size_t)ord[i], a, b));
  }
  for (uint32_t i = 1; i < k; i++) { /* insertion sort: k is small */
    uint32_t t = ord[i];
    int h = hv[i];
    uint32_t c = third(plc->tris + 3 * (size_t)t, a, b), j = i;
    while (j > 0 && before(&r, c, h, third(plc->tris + 3 * (size_t)ord[j - 1], a, b), hv[j - 1]) < 0) {
      ord[j] = ord[j - 1];
      hv[j] = hv[j - 1];
      j--;
    }
    ord[j] = t;
    hv[j] = h;
  }
  for (uint32_t i = 0; i < k; i++) {
    uint32_t t = ord[i], u = ord[(i + 1) % k];
    /* a triangle that runs a->b has its normal towards increasing angle */
    uint32_t up = 2 * t + (goes(plc->tris + 3 * (size_t)t, a, b) ? 0 : 1);
    uint32_t down = 2 * u + (goes(plc->tris + 3 * (size_t)u, a, b) ? 1 : 0);
    tr_uf_unite(uf, up, down);
  }
}

enum { NDIR = 11 };
static const double dir[NDIR][3] = {{0, 0, 1},        {1, 0, 0},         {0, 1, 0},
                                    {0.31, 0.17, 1},  {1, -0.23, 0.41},  {0.57, 1, -0.29},
                                    {-0.61, -0.37, 1}, {1, 0.13, 0.71},  {0.83, 1, 0.47},
                                    {-0.47, 0.89, 1}, {1, 1, -0.53}};

typedef struct {
  const struct tr_plc *plc;
  double lo[3], hi[3], len;
  double *box; /* 6 per triangle: lo, hi */
  tr_qpoint q, x;
  /* the crossings of the current ray: triangle, side facing the start, position */
  uint32_t *hu, nh, cap;
  uint8_t *hs;
  mpq_t *key;
  /* The triangles by the xy cells of a uniform grid that their boxes meet: a vertical
   * ray (the first direction tried) classifies only those of its column's cells, so
   * the rays of all side classes cost near-linear time instead of classes x triangles. */
  int gx, gy;
  double gcell[2];
  uint32_t *gstart, *gids, *stamp, epoch;
} caster;

static int gcell_of(const caster *c, double x, int a)
{
  double k = floor((x - c->lo[a]) / c->gcell[a]);
  int n = a ? c->gy : c->gx;
  return k < 0 ? 0 : k >= n ? n - 1 : (int)k;
}

static tr_status build_grid(caster *c)
{
  uint32_t nt = c->plc->ntris;
  int g = 1;
  while (g < 4096 && (uint64_t)g * (uint64_t)g < nt)
    g++;
  c->gx = c->gy = g;
  for (int a = 0; a < 2; a++) {
    c->gcell[a] = (c->hi[a] - c->lo[a]) / g;
    if (!(c->gcell[a] > 0) || !isfinite(c->gcell[a]))
      c->gcell[a] = 1;
  }
  size_t ncell = (size_t)g * (size_t)g;
  c->gstart = calloc(ncell + 1, sizeof *c->gstart);
  c->stamp = calloc(nt ? nt : 1, sizeof *c->stamp);
  if (!c->gstart || !c->stamp)
    return tr_error(TR_ERR_NOMEM, "out of memory indexing the triangles");
  for (int pass = 0; pass < 2; pass++) {
    for (uint32_t t = 0; t < nt; t++) {
      const double *b = c->box + 6 * (size_t)t;
      int x0 = gcell_of(c, b[0], 0), x1 = gcell_of(c, b[3], 0);
      int y0 = gcell_of(c, b[1], 1), y1 = gcell_of(c, b[4], 1);
      for (int x = x0; x <= x1; x++)
        for (int y = y0; y <= y1; y++) {
          size_t k = (size_t)x * (size_t)g + (size_t)y;
          if (pass == 0)
            c->gstart[k + 1]++;
          else
            c->gids[c->gstart[k]++] = t;
        }
    }
    if (pass == 0) {
      for (size_t i = 0; i < ncell; i++)
        c->gstart[i + 1] += c->gstart[i];
      if (c->gstart[ncell] > UINT32_MAX / 2)
        return tr_error(TR_ERR_NOMEM, "too many triangles to index");
      if (!(c->gids = malloc(sizeof *c->gids * (c->gstart[ncell] ? c->gstart[ncell] : 1))))
        return tr_error(TR_ERR_NOMEM, "out of memory indexing the triangles");
    } else {
      for (size_t i = ncell; i > 0; i--)
        c->gstart[i] = c->gstart[i - 1];
      c->gstart[0] = 0;
    }
  }
  return TR_OK;
}

/* The triangles a ray with box [slo, shi] may cross: for a vertical ray (column) those
 * of the grid cells of its column, each once; else all. The set of triangles classified,
 * and so every result, is the same either way. */
typedef struct {
  int column, x0, x1, y0, y1, x, y;
  uint32_t i, iend;
} cand_iter;

static void cand_begin(caster *c, cand_iter *it, int column, const double slo[3],
                       const double shi[3])
{
  memset(it, 0, sizeof *it);
  it->column = column;
  it->iend = c->plc->ntris;
  if (!column)
    return;
  it->x0 = it->x = gcell_of(c, slo[0], 0), it->x1 = gcell_of(c, shi[0], 0);
  it->y0 = it->y = gcell_of(c, slo[1], 1), it->y1 = gcell_of(c, shi[1], 1);
  size_t k = (size_t)it->x * (size_t)c->gy + (size_t)it->y;
  it->i = c->gstart[k];
  it->iend = c->gstart[k + 1];
  c->epoch++;
}

static int cand_next(caster *c, cand_iter *it, uint32_t *u)
{
  for (;;) {
    if (it->i == it->iend) {
      if (!it->column || (it->x == it->x1 && it->y == it->y1))
        return 0;
      if (it->y < it->y1)
        it->y++;
      else
        it->y = it->y0, it->x++;
      size_t k = (size_t)it->x * (size_t)c->gy + (size_t)it->y;
      it->i = c->gstart[k];
      it->iend = c->gstart[k + 1];
      continue;
    }
    if (!it->column) {
      *u = it->i++;
      return 1;
    }
    uint32_t x = c->gids[it->i++];
    if (c->stamp[x] != c->epoch) {
      c->stamp[x] = c->epoch;
      *u = x;
      return 1;
    }
  }
}

static int add_hit(caster *c, uint32_t u, int side, const mpq_t key)
{
  if (c->nh == c->cap) {
    uint32_t cap = c->cap ? 2 * c->cap : 64;
    uint32_t *hu = realloc(c->hu, sizeof *hu * cap);
    if (hu)
      c->hu = hu;
    uint8_t *hs = realloc(c->hs, sizeof *hs * cap);
    if (hs)
      c->hs = hs;
    mpq_t *k = realloc(c->key, sizeof *k * cap);
    if (k)
      c->key = k;
    if (!hu || !hs || !k)
      return -1;
    for (uint32_t i = c->cap; i < cap; i++)
      mpq_init(c->key[i]);
    c->cap = cap;
  }
  c->hu[c->nh] = u;
  c->hs[c->nh] = (uint8_t)side;
  mpq_set(c->key[c->nh], key);
  c->nh++;
  return 0;
}

/* Casts a ray from the centroid of t on side s (0 = +) to beyond the bounding box and
 * unites the sides that face each stretch of it between two crossings (the last
 * stretch with uf[inf], the outside). 1 on success, 0 if the direction grazes, -1 out
 * of memory. */
static int cast_dir(caster *c, uint32_t t, int s, int d, uint32_t *uf, uint32_t inf)
{
  /* Axis rays first: their bounding box is a thin column, so few triangles are
   * classified; generic directions when they graze (an axis ray from a triangle in an
   * axis plane is parallel to it, from a grid cell it may run along a diagonal). */
  const struct tr_plc *plc = c->plc;
  const uint32_t *v = plc->tris + 3 * (size_t)t;
  tr_point Q = tr_pt_q(&c->q), T[3] = {tr_pt_d(P(plc, v[0])), tr_pt_d(P(plc, v[1])),
                                        tr_pt_d(P(plc, v[2]))};
  double far[3];
  int ax = 0; /* the axis along which the ray moves fastest: positions compare on it */
  for (int i = 0; i < 3; i++) {
    far[i] = c->q.near[i] + c->len * dir[d][i];
    if (dir[d][i] * dir[d][i] > dir[d][ax] * dir[d][ax])
      ax = i;
  }
  tr_point F = tr_pt_d(far);
  int side = tr_orient3d_p(&T[0], &T[1], &T[2], &F), sign = dir[d][ax] > 0 ? 1 : -1;
  if (side == 0)
    return 0;
  if ((side > 0) != (s == 0)) {
    for (int i = 0; i < 3; i++)
      far[i] = c->q.near[i] - c->len * dir[d][i];
    sign = -sign;
    if (tr_orient3d_p(&T[0], &T[1], &T[2], &F) != (s == 0 ? 1 : -1))
      return 0;
  }
  double slo[3], shi[3];
  for (int i = 0; i < 3; i++) {
    slo[i] = c->q.lo[i] < far[i] ? c->q.lo[i] : far[i];
    shi[i] = c->q.hi[i] > far[i] ? c->q.hi[i] : far[i];
  }
  c->nh = 0;
  cand_iter it;
  cand_begin(c, &it, dir[d][0] == 0 && dir[d][1] == 0, slo, shi);
  for (uint32_t u; cand_next(c, &it, &u);) {
    const double *bx = c->box + 6 * (size_t)u;
    if (u == t || bx[0] > shi[0] || bx[1] > shi[1] || bx[2] > shi[2] || bx[3] < slo[0] ||
        bx[4] < slo[1] || bx[5] < slo[2])
      continue;
    const uint32_t *w = plc->tris + 3 * (size_t)u;
    tr_point U[3] = {tr_pt_d(P(plc, w[0])), tr_pt_d(P(plc, w[1])), tr_pt_d(P(plc, w[2]))};
    tr_isect r = tr_classify_segment_triangle(&Q, &F, &U[0], &U[1], &U[2]);
    if (r.n == 0)
      continue;
    if (r.n != 1 || r.end[0].type != TR_FAC || r.end[0].on_seg != TR_SEG_IN)
      return 0;
    int qs = tr_orient3d_p(&U[0], &U[1], &U[2], &Q); /* nonzero: a proper crossing */
    if (tr_construct_line_plane(&Q, &F, &U[0], &U[1], &U[2], &c->x) != 0)
      return 0;
    if (sign < 0)
      mpq_neg(c->x.c[ax], c->x.c[ax]);
    if (add_hit(c, u, qs > 0 ? 0 : 1, c->x.c[ax]) != 0)
      return -1;
  }
  /* order along the ray; two crossings at one position share a point: grazing */
  for (uint32_t i = 1; i < c->nh; i++)
    for (uint32_t j = i; j > 0; j--) {
      int cmp = mpq_cmp(c->key[j], c->key[j - 1]);
      if (cmp == 0)
        return 0;
      if (cmp > 0)
        break;
      mpq_swap(c->key[j], c->key[j - 1]);
      uint32_t x = c->hu[j];
      c->hu[j] = c->hu[j - 1];
      c->hu[j - 1] = x;
      uint8_t y = c->hs[j];
      c->hs[j] = c->hs[j - 1];
      c->hs[j - 1] = y;
    }
  uint32_t prev = 2 * t + (uint32_t)s;
  for (uint32_t i = 0; i < c->nh; i++) {
    tr_uf_unite(uf, prev, 2 * c->hu[i] + c->hs[i]);
    prev = 2 * c->hu[i] + 1 - c->hs[i];
  }
  tr_uf_unite(uf, prev, inf);
  return 1;
}

void tr_input_tri_centroid(const struct tr_plc *plc, uint32_t t, tr_qpoint *q)
{
  const uint32_t *v = plc->tris + 3 * (size_t)t;
  mpq_t x;
  mpq_init(x);
  for (int i = 0; i < 3; i++) {
    mpq_set_d(q->c[i], P(plc, v[0])[i]);
    for (int k = 1; k < 3; k++) {
      mpq_set_d(x, P(plc, v[k])[i]);
      mpq_add(q->c[i], q->c[i], x);
    }
    mpq_set_ui(x, 3, 1);
    mpq_div(q->c[i], q->c[i], x);
  }
  mpq_clear(x);
  tr_qpoint_update(q);
}

/* The cell (a class of sides, as a uf root) holding point p, which lies on no triangle:
 * the side facing p of the first triangle a ray from p crosses, or the outside (inf).
 * 1 done, 0 every direction grazes. */
static int locate(caster *c, const double *p, uint32_t *uf, uint32_t inf, uint32_t *cell)
{
  const struct tr_plc *plc = c->plc;
  tr_point S = tr_pt_d(p);
  mpq_t best;
  mpq_init(best);
  int done = 0;
  for (int d = 0; d < NDIR && !done; d++) {
    double far[3], slo[3], shi[3];
    int ax = 0;
    for (int i = 0; i < 3; i++) {
      far[i] = p[i] + c->len * dir[d][i];
      slo[i] = p[i] < far[i] ? p[i] : far[i];
      shi[i] = p[i] > far[i] ? p[i] : far[i];
      if (dir[d][i] * dir[d][i] > dir[d][ax] * dir[d][ax])
        ax = i;
    }
    tr_point F = tr_pt_d(far);
    uint32_t first = inf;
    int clean = 1;
    cand_iter it;
    cand_begin(c, &it, dir[d][0] == 0 && dir[d][1] == 0, slo, shi);
    for (uint32_t u; clean && cand_next(c, &it, &u);) {
      const double *bx = c->box + 6 * (size_t)u;
      if (bx[0] > shi[0] || bx[1] > shi[1] || bx[2] > shi[2] || bx[3] < slo[0] ||
          bx[4] < slo[1] || bx[5] < slo[2])
        continue;
      const uint32_t *w = plc->tris + 3 * (size_t)u;
      tr_point U[3] = {tr_pt_d(P(plc, w[0])), tr_pt_d(P(plc, w[1])), tr_pt_d(P(plc, w[2]))};
      tr_isect r = tr_classify_segment_triangle(&S, &F, &U[0], &U[1], &U[2]);
      if (r.n == 0)
        continue;
      if (r.n != 1 || r.end[0].type != TR_FAC || r.end[0].on_seg != TR_SEG_IN ||
          tr_construct_line_plane(&S, &F, &U[0], &U[1], &U[2], &c->x) != 0) {
        clean = 0;
        break;
      }
      if (dir[d][ax] < 0)
        mpq_neg(c->x.c[ax], c->x.c[ax]);
      int cmp = first == inf ? -1 : mpq_cmp(c->x.c[ax], best);
      if (cmp == 0)
        clean = 0; /* two crossings at one point: an edge or a vertex */
      else if (cmp < 0) {
        mpq_set(best, c->x.c[ax]);
        first = 2 * u + (tr_orient3d_p(&U[0], &U[1], &U[2], &S) > 0 ? 0 : 1);
      }
    }
    if (clean) {
      *cell = tr_uf_find(uf, first);
      done = 1;
    }
  }
  mpq_clear(best);
  return done;
}

/* A ray from side s of triangle t: 1 done, 0 every direction grazes, -1 out of memory. */
static int cast(caster *c, uint32_t t, int s, uint32_t *uf, uint32_t inf)
{
  tr_input_tri_centroid(c->plc, t, &c->q);
  for (int d = 0; d < NDIR; d++) {
    int r = cast_dir(c, t, s, d, uf, inf);
    if (r != 0)
      return r;
  }
  return 0;
}

/* The analysis; sides (may be NULL) receives per triangle, after orientation, bit 0 =
 * the + side is in the domain, bit 1 = the - side is; tnum / orig may be NULL;
 * hole_used (may be NULL) receives per hole point TR_HOLE_EMPTIED if its cell would be
 * in the domain without it, TR_HOLE_IN_CAVITY if its cell is a cavity anyway, 0 if it
 * lies outside every shell. */
static tr_status cells(struct tr_plc *plc, const uint32_t *tnum, const uint32_t *orig,
                       int allow_open, char *flipped, uint8_t *sides, uint8_t *hole_used)
{
  uint32_t nt = plc->ntris, ne = 3 * nt;
  uint32_t *e = malloc(sizeof *e * (ne ? ne : 1)), *uf = malloc(sizeof *uf * (2 * (size_t)nt + 1));
  uint32_t *ord = malloc(sizeof *ord * (nt ? nt : 1)), *depth = NULL, *roots = NULL;
  int32_t *vote = NULL; /* per cell: triangles saying it is in the domain minus out */
  int *hv = malloc(sizeof *hv * (nt ? nt : 1));
  char *free_edge = calloc(nt ? nt : 1, 1);
  caster c;
  memset(&c, 0, sizeof c);
  c.plc = plc;
  c.box = malloc(sizeof(double) * 6 * (nt ? nt : 1));
  tr_qpoint_init(&c.q);
  tr_qpoint_init(&c.x);
  tr_status st = TR_OK;
  if (!e || !uf || !ord || !hv || !free_edge || !c.box) {
    st = tr_error(TR_ERR_NOMEM, "out of memory orienting the surface");
    goto done;
  }
  for (uint32_t i = 0; i < ne; i++)
    e[i] = i;
  for (uint32_t i = 0; i < 2 * nt; i++)
    uf[i] = i;
  if ((st = tr_edge_slots_sorted(plc->tris, nt, plc->npoints, e)) != TR_OK)
    goto done;
  for (uint32_t i = 0; i < ne;) {
    uint32_t j = i + 1;
    while (j < ne && cmp_edge(plc->tris, e[i], e[j]) == 0)
      j++;
    if (j - i == 1)
      free_edge[e[i] / 3] = 1;
    wedges(plc, e + i, j - i, uf, ord, hv);
    i = j;
  }
  /* The bounding box of everything, and a ray length that leaves it from anywhere. */
  for (int d = 0; d < 3; d++) {
    c.lo[d] = nt ? P(plc, plc->tris[0])[d] : 0;
    c.hi[d] = c.lo[d];
  }
  for (uint32_t t = 0; t < nt; t++) {
    double *lo = c.box + 6 * (size_t)t, *hi = lo + 3;
    tr_box_of(plc->xyz, plc->tris + 3 * (size_t)t, 3, lo, hi);
    for (int d = 0; d < 3; d++) {
      c.lo[d] = lo[d] < c.lo[d] ? lo[d] : c.lo[d];
      c.hi[d] = hi[d] > c.hi[d] ? hi[d] : c.hi[d];
    }
  }
  c.len = 2 * ((c.hi[0] - c.lo[0]) + (c.hi[1] - c.lo[1]) + (c.hi[2] - c.lo[2])) + 1;
  for (int d = 0; d < 3; d++)
    if (!(c.len + c.hi[d] - c.lo[d] < 1e300) || c.hi[d] > 1e300 || c.lo[d] < -1e300) {
      st = tr_error(TR_ERR_UNSUPPORTED, "coordinates too large to orient a non-manifold surface");
      goto done;
    }
  if ((st = build_grid(&c)) != TR_OK)
    goto done;
  /* One ray per side class, from the classes as the wedges left them (uf[2nt] is the
   * outside); a class whose triangles all graze tries up to 16 of them. */
  uf[2 * nt] = 2 * nt;
  uint32_t nroot = 0;
  roots = malloc(sizeof *roots * (2 * (size_t)nt + 1));
  depth = malloc(sizeof *depth * (2 * (size_t)nt + 1)); /* first: each side's class */
  if (!roots || !depth) {
    st = tr_error(TR_ERR_NOMEM, "out of memory orienting the surface");
    goto done;
  }
  for (uint32_t x = 0; x < 2 * nt; x++) {
    depth[x] = tr_uf_find(uf, x);
    if (depth[x] == x)
      roots[nroot++] = x;
  }
  for (uint32_t i = 0; i < nroot; i++) {
    uint32_t s = roots[i];
    int r = 0;
    for (uint32_t x = s, tries = 0; x < 2 * nt && r == 0 && tries < 16; x++)
      if (depth[x] == s) {
        r = cast(&c, x / 2, (int)(x % 2), uf, 2 * nt);
        tries++;
      }
    if (r < 0) {
      st = tr_error(TR_ERR_NOMEM, "out of memory orienting the surface");
      goto done;
    }
    if (r == 0) {
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "%s%scannot decide which cell triangle %u faces (every ray tried grazes "
                    "an edge)", PRE(plc), tnum ? tnum[s / 2] : s / 2);
      goto done;
    }
  }
  /* Depth of each cell: relaxation over the triangles joining two cells, one linear pass
   * per level of nesting. */
  for (uint32_t i = 0; i <= 2 * nt; i++)
    depth[i] = UINT32_MAX;
  uint32_t inf = tr_uf_find(uf, 2 * nt);
  depth[inf] = 0;
  for (int changed = 1; changed;) {
    changed = 0;
    for (uint32_t t = 0; t < nt; t++) {
      uint32_t p = tr_uf_find(uf, 2 * t), m = tr_uf_find(uf, 2 * t + 1);
      if (depth[p] != UINT32_MAX && depth[p] + 1 < depth[m])
        depth[m] = depth[p] + 1, changed = 1;
      if (depth[m] != UINT32_MAX && depth[m] + 1 < depth[p])
        depth[p] = depth[m] + 1, changed = 1;
    }
  }
  /* Nested cells (depth 2 and more) by the orientation of the triangles between them and
   * the cell around them, as nesting.c decides for closed shells: facing out of the cell
   * (an inclusion, or a body in a cavity) votes it in, facing into it (a cavity) votes
   * it out; a tie keeps parity. On a surface oriented by parity this is parity. */
  if (!(vote = calloc(2 * (size_t)nt + 1, sizeof *vote))) {
    st = tr_error(TR_ERR_NOMEM, "out of memory orienting the surface");
    goto done;
  }
  for (uint32_t t = 0; t < nt; t++) {
    uint32_t p = tr_uf_find(uf, 2 * t), m = tr_uf_find(uf, 2 * t + 1);
    if (depth[p] == UINT32_MAX || depth[m] == UINT32_MAX) {
      st = tr_error(TR_ERR_INTERNAL, "%s%striangle %u bounds a cell not reached from outside",
                    PRE(plc), tnum ? tnum[t] : t);
      goto done;
    }
    /* The orientation as given votes, as in nesting.c: the consistency repair turned a
     * whole shell to agree with its first triangle, which says nothing of the shell's
     * kind (a .poly box with one facet listed inward is still an inclusion). */
    int as_given = flipped && flipped[t] ? -1 : 1;
    if (depth[p] == depth[m] + 1 && depth[p] >= 2)
      vote[p] -= as_given; /* the normal points into p, the inner cell */
    else if (depth[m] == depth[p] + 1 && depth[m] >= 2)
      vote[m] += as_given;
  }
  /* A hole point's cell is outside the domain (vote INT32_MIN marks it). */
  for (uint32_t h = 0; h < plc->nholes; h++) {
    const double *hp = plc->holes + 3 * (size_t)h;
    tr_point H = tr_pt_d(hp);
    for (uint32_t t = 0; t < nt; t++) {
      const double *bx = c.box + 6 * (size_t)t;
      if (hp[0] < bx[0] || hp[1] < bx[1] || hp[2] < bx[2] || hp[0] > bx[3] || hp[1] > bx[4] ||
          hp[2] > bx[5])
        continue;
      const uint32_t *v = plc->tris + 3 * (size_t)t;
      tr_point A = tr_pt_d(P(plc, v[0])), B = tr_pt_d(P(plc, v[1])), C = tr_pt_d(P(plc, v[2]));
      if (tr_classify_segment_triangle(&H, &H, &A, &B, &C).n) {
        st = tr_error(TR_ERR_INPUT,
                      "%s%shole point %u (%.17g, %.17g, %.17g) lies on triangle %u: it must "
                      "lie strictly inside a cell", PRE(plc), h, hp[0], hp[1], hp[2],
                      tnum ? tnum[t] : t);
        goto done;
      }
    }
    uint32_t cell;
    if (!locate(&c, hp, uf, 2 * nt, &cell)) {
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "cannot decide which cell hole point %u lies in (every ray tried grazes "
                    "an edge)", h);
      goto done;
    }
    /* a second hole point in an emptied cell counts as used too; one in a cell already
     * outside is either in a cavity (the surface leaves it empty: asked and done) or
     * outside every shell (it removes nothing) */
    if (hole_used)
      hole_used[h] = vote[cell] == INT32_MIN ||
                             (vote[cell] ? vote[cell] > 0 : (int)(depth[cell] & 1))
                         ? TR_HOLE_EMPTIED
                     : depth[cell] ? TR_HOLE_IN_CAVITY
                                   : 0;
    vote[cell] = INT32_MIN;
  }
  for (uint32_t t = 0; t < nt; t++) {
    uint32_t p = tr_uf_find(uf, 2 * t), m = tr_uf_find(uf, 2 * t + 1);
    int in_p = vote[p] == INT32_MIN ? 0 : vote[p] ? vote[p] > 0 : (int)(depth[p] & 1);
    int in_m = vote[m] == INT32_MIN ? 0 : vote[m] ? vote[m] > 0 : (int)(depth[m] & 1);
    if (free_edge[t] && !in_p && !allow_open) {
      const uint32_t *v = plc->tris + 3 * (size_t)t;
      uint32_t a = 0, b = 0;
      for (int k = 0; k < 3; k++) { /* the free edge */
        uint32_t x = v[k], y = v[(k + 1) % 3], n = 0;
        for (uint32_t i = 0; i < nt && n < 2; i++) {
          const uint32_t *w = plc->tris + 3 * (size_t)i;
          n += (w[0] == x || w[1] == x || w[2] == x) && (w[0] == y || w[1] == y || w[2] == y);
        }
        if (n == 1) {
          a = x < y ? x : y;
          b = x < y ? y : x;
          break;
        }
      }
      st = tr_error(TR_ERR_OPEN,
                    "%s%sopen surface: edge (%u, %u) belongs to 1 triangle (triangle %u) and "
                    "does not lie inside a closed region; use --allow-open to mesh it anyway",
                    PRE(plc), orig ? orig[a] : a, orig ? orig[b] : b, tnum ? tnum[t] : t);
      goto done;
    }
    if (sides) /* after the turn below, when there is one: outside on the + side */
      sides[t] = (uint8_t)(in_p && !in_m ? 2 : in_p | in_m << 1);
    /* Between a nested cell and a shallower one the triangle faces the way its vote
     * went (out of an inner cell, into an outer one), so that the analysis of the
     * validated surface (tr_input_side_domains, as given = as it is) decides alike;
     * elsewhere only a normal pointing into the domain from outside is turned. */
    int turn = in_p && !in_m;
    if (in_p == in_m && depth[p] == depth[m] + 1 && depth[p] >= 2)
      turn = in_p;
    else if (in_p == in_m && depth[m] == depth[p] + 1 && depth[m] >= 2)
      turn = !in_m;
    if (turn) {
      uint32_t *v = plc->tris + 3 * (size_t)t, x = v[1];
      v[1] = v[2];
      v[2] = x;
      if (flipped)
        flipped[t] ^= 1;
    }
  }
done:
  tr_qpoint_clear(&c.q);
  tr_qpoint_clear(&c.x);
  for (uint32_t i = 0; i < c.cap; i++)
    mpq_clear(c.key[i]);
  free(c.key);
  free(c.hu);
  free(c.hs);
  free(c.box);
  free(c.gstart);
  free(c.gids);
  free(c.stamp);
  free(e);
  free(uf);
  free(ord);
  free(hv);
  free(free_edge);
  free(depth);
  free(roots);
  free(vote);
  return st;
}

tr_status tr_input_orient_cells(struct tr_plc *plc, const uint32_t *tnum, const uint32_t *orig,
                                int allow_open, char *flipped)
{
  if (plc->nholes && !plc->hole_cavity && !(plc->hole_cavity = calloc(plc->nholes, 1)))
    return tr_error(TR_ERR_NOMEM, "out of memory orienting the surface");
  return cells(plc, tnum, orig, allow_open, flipped, NULL, plc->hole_cavity);
}

tr_status tr_input_side_domains(const struct tr_plc *plc, uint8_t *sides)
{
  if (plc->xq) { /* a resolved surface: its sides are known exactly (tri_inner) */
    for (uint32_t t = 0; t < plc->ntris; t++)
      sides[t] = plc->tri_inner && plc->tri_inner[t] ? 3 : 2;
    return TR_OK;
  }
  struct tr_plc copy = *plc; /* the analysis may turn triangles: on a copy of them */
  uint32_t n = plc->ntris;
  copy.tris = malloc(sizeof *copy.tris * 3 * (size_t)(n ? n : 1));
  if (!copy.tris)
    return tr_error(TR_ERR_NOMEM, "out of memory classifying the triangles' sides");
  memcpy(copy.tris, plc->tris, sizeof *copy.tris * 3 * (size_t)n);
  tr_status st = cells(&copy, NULL, NULL, 1, NULL, sides, NULL);
  /* report the sides of the caller's orientation */
  for (uint32_t t = 0; st == TR_OK && t < n; t++)
    if (copy.tris[3 * (size_t)t + 1] != plc->tris[3 * (size_t)t + 1])
      sides[t] = (uint8_t)((sides[t] & 1) << 1 | (sides[t] >> 1));
  free(copy.tris);
  return st;
}

tr_status tr_input_domain_volume6(const struct tr_plc *plc, mpq_t out)
{
  uint32_t n = plc->ntris;
  uint8_t *sides = malloc(n ? n : 1);
  uint32_t *ids = malloc(sizeof *ids * (n ? n : 1));
  struct tr_plc copy = *plc;
  copy.tris = malloc(sizeof *copy.tris * 3 * (size_t)(n ? n : 1));
  tr_status st = TR_OK;
  if (!sides || !ids || !copy.tris)
    st = tr_error(TR_ERR_NOMEM, "out of memory measuring the domain");
  if (st == TR_OK)
    st = tr_input_side_domains(plc, sides);
  if (st == TR_OK) {
    uint32_t m = 0;
    for (uint32_t t = 0; t < n; t++) {
      const uint32_t *v = plc->tris + 3 * (size_t)t;
      uint32_t *w = copy.tris + 3 * (size_t)t;
      w[0] = v[0]; /* the domain on the - side: outward as it is */
      w[1] = sides[t] == 1 ? v[2] : v[1];
      w[2] = sides[t] == 1 ? v[1] : v[2];
      if (sides[t] == 1 || sides[t] == 2)
        ids[m++] = t;
    }
    st = tr_input_volume6_of(&copy, ids, m, out);
  }
  free(copy.tris);
  free(sides);
  free(ids);
  return st;
}
