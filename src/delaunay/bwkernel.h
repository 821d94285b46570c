/* The Bowyer-Watson kernel shared by the serial builder (bw.c) and the parallel one
 * (par.c): the builder context, the conflict tests with their static filters, the walk,
 * and the star re-triangulation. See bw.c for how it works and what it costs. Static
 * inline: each builder gets its own inlined copy, as when this was one file. */
#ifndef TR_BWKERNEL_H
#define TR_BWKERNEL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/prefetch.h"
#include "delaunay.h"
#include "det2.h"
#include "dtstat.h"
#include "predicates.h"

/* The cavity mark is the top bit of vertex slot 0 of the tet itself: the conflict test
 * reads that slot anyway. Vertex ids stay below 2^31 (n is capped far lower); TR_GHOST
 * is only in slot 3. A cavity tet's slot is rewritten or freed: no mark outlives the
 * insertion. Tets not in conflict are not marked: the few reached twice (3 of 48 tests
 * per point) cost less to test again than marks, a list and a clearing pass. */
#define MARK 0x80000000u


typedef struct bface {
  uint32_t v[4]; /* vertices of the new tet (p already in slot k) */
  uint32_t out;  /* neighbour code outside the cavity */
  uint32_t k;    /* slot of p */
  uint8_t l[4];  /* l[s]: local id (see lid) of v[s], s != k */
} bface;

/* A point during the build, 32 bytes so that no point straddles two cache lines, with
 * the two per-vertex fields the kernel needs next to the coordinates it loads anyway. */
typedef struct dvtx {
  double x[3];
  uint32_t orig; /* input index: the perturbation order */
  uint32_t tag;  /* stamp << 8 | local id on the current cavity boundary (lid) */
} dvtx;

/* The star is glued through a LDIM x LDIM map of directed boundary edges between local
 * vertex ids (id 0 is TR_GHOST); a cavity with more boundary vertices takes the hash. */
#define LDIM 64

/* Entry of the star's edge table: the side face (p, a, b) of a new tet, code 4*t+j. Its
 * partner is the face (p, b, a). Live iff gen equals the context's current generation,
 * so the table is never cleared between insertions. */
typedef struct hent {
  uint32_t a, b, code, gen;
} hent;

typedef struct dt {
  struct tr_mesh *m;
  dvtx *pv;             /* points in insertion order */
  const uint32_t *orig; /* insertion id -> input index (the perturbation order) */
  uint32_t stamp;       /* lid: the current insertion's stamp */
  uint32_t *map;        /* LDIM * LDIM side codes, TR_NONE between insertions */
  uint32_t n;
  uint64_t rng;
  uint32_t last; /* a real tet created by the last insertion: start of the next walk */
  uint32_t *cav, ncav, capcav;
  uint32_t *slot, capslot; /* slot of each new tet (insert) */
  struct side *sd;          /* side faces of the new tets (star_small) */
  uint32_t capsd;
  bface *bf;
  uint32_t nbf, capbf;
  double is_bound; /* static insphere filter bound (conflict_real) */
  double o3_bound; /* static orient3d filter bound (orient_neg) */
  hent *ht;        /* the edge table, capht entries (a power of two) */
  uint32_t capht, htbits, gen, nglued;
} dt;

static inline const double *X(const dt *D, uint32_t v) { return D->pv[v].x; }

/* Local id of boundary vertex v in the current insertion: 1, 2, ... in order of first
 * sight, kept in v's tag with the insertion's stamp (branch-free: whether v was seen is
 * data the predictor cannot guess). Ids past 255 wrap, but then nloc > LDIM and the ids
 * are not used. */
static inline uint32_t lid(dvtx *pv, uint32_t stb, uint32_t *nloc, uint32_t v)
{
  dvtx *q = &pv[v];
  const uint32_t d = q->tag - stb; /* stb = stamp << 8: d < 256 iff seen in this insertion */
  const uint32_t hit = d < 256;
  const uint32_t l = hit ? d : (*nloc & 255);
  q->tag = stb | l;
  *nloc += !hit;
  return l;
}

static inline uint32_t rnd(dt *D)
{
  uint64_t x = D->rng;
  x ^= x << 13;
  x ^= x >> 7;
  x ^= x << 17;
  D->rng = x;
  return (uint32_t)(x >> 32);
}

static inline tr_status grow_buf(void **p, uint32_t *cap, uint32_t need, size_t size)
{
  if (need <= *cap)
    return TR_OK;
  uint32_t nc = *cap ? *cap : 64;
  while (nc < need)
    nc *= 2;
  void *q = realloc(*p, (size_t)nc * size);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory in the Delaunay cavity buffers");
  *p = q;
  *cap = nc;
  return TR_OK;
}

/* Room for n entries in both cavity buffers (insert asks for the sum of their counts
 * plus the four entries the faces of one cavity tet can add: one bound for both). */
static inline tr_status grow_bufs(dt *D, uint32_t n)
{
  TR_CHECK(grow_buf((void **)&D->cav, &D->capcav, n, sizeof *D->cav));
  return grow_buf((void **)&D->bf, &D->capbf, n, sizeof *D->bf);
}

/* -DTR_DT_STATS prints per-point averages (insphere tests, walk steps, cavity and
 * boundary sizes) after a build: the numbers to look at when tuning; and the phase
 * timers (dtstat.h). */
#ifdef TR_DT_STATS
__attribute__((unused)) static unsigned long long st_ins, st_walk, st_cav, st_bf, st_pts, st_big;
#define STAT(x) (x)
#else
#define STAT(x) ((void)0)
#endif

/* Real tet t: does p lie strictly inside its (perturbed) circumsphere?
 *
 * A static filter first: the determinant of tr_insphere, bit for bit (det2.h computes
 * tr_insphere_det_'s very operations two at a time) and one comparison against
 * D->is_bound, a bound on its rounding
 * error valid for every five points of the input's bounding box. insphere.c bounds that
 * error by 385 eps mx my mz (mx^2 + my^2 + mz^2), with mx the largest rounded |x
 * difference|; that bound grows with mx, my, mz, and a rounded difference of two
 * coordinates in [lo, hi] is at most the rounded hi - lo (rounding is monotone), so
 * mx, my, mz <= ext (the largest rounded extent) gives 3 * 385 eps ext^5; is_bound is
 * 8 * 385 eps ext^5, which also covers its own roundings and the absolute underflow
 * errors (at most ~2^-1075 per product, times factors below 2^310 while 2^-100 <= ext
 * <= 2^100, against is_bound >= 2^-550). Outside that range is_bound is infinite and
 * every test takes the full path. An uncertain sign goes to tr_insphere_sos (its own
 * per-tet filter, then exact arithmetic, then the perturbation); calling tr_insphere
 * (whose fallback is already exact) first would evaluate every exactly cospherical case
 * (all of a grid's cubes) twice. */
static inline int conflict_real(const dt *D, uint32_t t, const double *e, uint32_t pi)
{
  STAT(st_ins++);
  const uint32_t *v = D->m->tv + 4 * (size_t)t;
  const double *a = X(D, v[0]), *b = X(D, v[1]), *c = X(D, v[2]), *d = X(D, v[3]);
  const double det = tr_dt_insphere_det(a, b, c, d, e);
  /* one branch, taken almost always; the sign itself goes out as data (see insert) */
  if (fabs(det) > D->is_bound)
    return det > 0;
  const dvtx *o = D->pv;
  return tr_insphere_sos(a, b, c, d, e, o[v[0]].orig, o[v[1]].orig, o[v[2]].orig, o[v[3]].orig,
                         o[pi].orig) > 0;
}

/* The static filter's bound for points whose coordinate extents are at most ext (see
 * conflict_real); infinite (filter off) outside the range its proof covers. */
static inline double static_is_bound(double ext)
{
  if (!(ext >= 0x1p-100 && ext <= 0x1p100))
    return INFINITY;
  return 8.0 * TR_IS_FILTER * ext * ext * ext * ext * ext;
}

/* tr_orient3d(a, b, c, d) < 0, with the same static filter idea as conflict_real: the
 * determinant of tr_orient3d (predicates.h, same evaluation order) against D->o3_bound =
 * 4 * 49 eps ext^3, at least twice orient.c's bound 49 eps mx my mz (which grows with
 * mx, my, mz <= ext) and far above any underflow error for 2^-100 <= ext <= 2^100
 * (infinite otherwise). An uncertain sign is decided by tr_orient3d. */
static inline int orient_neg(const dt *D, const double *a, const double *b, const double *c,
                             const double *d)
{
  const double det = tr_orient3d_det_(a, b, c, d);
  if (det > D->o3_bound)
    return 0;
  if (-det > D->o3_bound)
    return 1;
  return tr_orient3d(a, b, c, d) < 0;
}

static inline double static_o3_bound(double ext)
{
  if (!(ext >= 0x1p-100 && ext <= 0x1p100))
    return INFINITY;
  return 4.0 * TR_O3_FILTER * ext * ext * ext;
}

static inline int conflict(const dt *D, uint32_t t, const double *p, uint32_t pi)
{
  const struct tr_mesh *m = D->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  if (v[3] != TR_GHOST)
    return conflict_real(D, t, p, pi);
  double o = tr_orient3d(X(D, v[0]), X(D, v[1]), X(D, v[2]), p);
  if (o != 0)
    return o > 0;
  uint32_t r = m->tn[4 * (size_t)t + 3] >> 2;
  if (m->tv[4 * (size_t)r] & MARK)
    return 1;
  return conflict_real(D, r, p, pi);
}

/* Visibility walk from a real tet: leave through a face that has p strictly on its other
 * side, trying the faces from a pseudo-random first one so the walk cannot cycle.
 * Returns the real tet containing p (closed) or a ghost whose hull face p sees. */
static inline uint32_t locate(dt *D, uint32_t t, const double *p)
{
  const struct tr_mesh *m = D->m;
  uint32_t prev = TR_NONE;
  uint32_t r = 0;
  int bits = 0;
  for (;;) {
    if (bits < 2) {
      r = rnd(D);
      bits = 32;
    }
    int s = (int)(r & 3);
    r >>= 2;
    bits -= 2;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    int moved = 0;
    for (int i = 0; i < 4; i++) {
      int k = (s + i) & 3;
      uint32_t u = m->tn[4 * (size_t)t + (size_t)k] >> 2;
      if (u == prev)
        continue;
      const uint8_t *f = tr_face_vtx[k];
      if (orient_neg(D, X(D, v[f[0]]), X(D, v[f[1]]), X(D, v[f[2]]), p)) {
        prev = t;
        t = u;
        moved = 1;
        break;
      }
    }
    STAT(st_walk++);
    if (!moved || m->tv[4 * (size_t)t + 3] == TR_GHOST)
      return t;
  }
}

/* Gluing the star of a large cavity (the map of star_small has room for LDIM - 1 boundary
 * vertices): every side face (p, a, b) of a new tet meets the face (p, b, a) of
 * another, i.e. a directed edge of the cavity boundary meets its reverse. A small open
 * addressing table keyed on the edge, with a hash symmetric in a and b, finds the partner
 * at the first probe position the partner itself would use: one probe sequence per side
 * face, no per-vertex arrays, nothing to clear afterwards (generation stamps).
 * star_begin sizes the table for nnew new tets (at most 3 * nnew entries, load <= 3/4,
 * so a probe always ends). */
static inline tr_status star_begin(dt *D, uint32_t nnew)
{
  uint32_t bits = 6;
  while ((1u << bits) < 4 * nnew)
    bits++;
  if ((1u << bits) > D->capht) {
    free(D->ht);
    D->ht = calloc((size_t)1 << bits, sizeof *D->ht);
    if (!D->ht)
      return tr_error(TR_ERR_NOMEM, "out of memory in the Delaunay cavity buffers");
    D->capht = 1u << bits;
    D->gen = 0;
  }
  D->htbits = bits;
  if (++D->gen == 0) { /* wrapped: stale stamps could look live */
    memset(D->ht, 0, (size_t)D->capht * sizeof *D->ht);
    D->gen = 1;
  }
  D->nglued = 0;
  return TR_OK;
}

/* The side faces of new tet t, whose slot k holds p: SIDE[k][i] = {j, u, w}, face j
 * (j != k) listed from p as (p, v[u], v[w]); the rows are tr_face_rot[k][j] (mesh.h),
 * spelled out so the compiler sees constants (build() checks that they agree). */
static const uint8_t SIDE[4][3][3] = {
    {{1, 2, 3}, {2, 3, 1}, {3, 1, 2}},
    {{0, 3, 2}, {2, 0, 3}, {3, 2, 0}},
    {{0, 1, 3}, {1, 3, 0}, {3, 0, 1}},
    {{0, 2, 1}, {1, 0, 2}, {2, 1, 0}},
};

/* Glues side face j = (p, a, b) of new tet t (h, sh, mask, g: the table, in locals that
 * the stores into tn cannot be suspected to change). */
static inline uint32_t star_glue(hent *h, uint32_t sh, uint32_t mask, uint32_t g, uint32_t *tn,
                                 uint32_t t, uint32_t j, uint32_t a, uint32_t b)
{
  for (uint32_t i = ((a + b) * 0x9E3779B1u) >> sh;; i = (i + 1) & mask) {
    hent *e = &h[i];
    if (e->gen != g) {
      e->a = a;
      e->b = b;
      e->code = 4 * t + j;
      e->gen = g;
      return 0;
    }
    if (e->a == b && e->b == a) {
      tn[4 * (size_t)t + j] = e->code;
      tn[e->code] = 4 * t + j;
      e->a = e->b = TR_NONE; /* an edge is glued once; a third use would be an error */
      return 1;
    }
  }
}

/* Glues the three side faces of new tet t, whose slot k holds p (one case per k so that
 * the slots are constants). */
static inline void star_glue_tet(dt *D, uint32_t t, uint32_t k)
{
  uint32_t *tn = D->m->tn;
  const uint32_t *v = D->m->tv + 4 * (size_t)t;
  hent *h = D->ht;
  const uint32_t sh = 32 - D->htbits, mask = (1u << D->htbits) - 1, g = D->gen;
  uint32_t ng = 0;
#define SIDE1(k, i) \
  star_glue(h, sh, mask, g, tn, t, SIDE[k][i][0], v[SIDE[k][i][1]], v[SIDE[k][i][2]])
#define SIDES(k) ng += SIDE1(k, 0); ng += SIDE1(k, 1); ng += SIDE1(k, 2)
  switch (k) {
  case 0: SIDES(0); break;
  case 1: SIDES(1); break;
  case 2: SIDES(2); break;
  default: SIDES(3); break;
  }
#undef SIDES
#undef SIDE1
  D->nglued += ng;
}

/* A side face of a new tet waiting for its partner: its code and the map cell of its
 * partner (star_small). */
typedef struct side {
  uint32_t code, cell;
} side;

/* Writes the new tets of a small cavity, bf[i] into slot[i], glues them to their outer
 * neighbours, and glues their side faces to each other through the map: side (p, a, b)
 * is written to cell (a, b) first, then every side takes the cell of its reverse edge
 * (b, a) and empties it. Every cell is empty between insertions and a cell taken is
 * emptied, so if no side finds its cell empty, the S sides took S distinct cells written
 * in this insertion: no two sides share a directed edge, every edge has its reverse, the
 * boundary is a closed surface, each side is glued to the one whose cell it took and
 * back, and the map is empty again. Returns 0 if so, else 1. *last: a real new tet. */
static inline int star_small(uint32_t *restrict tv, uint32_t *restrict tn, uint32_t *restrict map,
                      const bface *restrict bf, const uint32_t *restrict slot,
                      side *restrict sd, uint32_t nbf, uint32_t *last)
{
  uint32_t l = TR_NONE;
  for (uint32_t i = 0; i < nbf; i++) {
    const uint32_t s = slot[i];
    const bface *b = &bf[i];
    const uint32_t k = b->k, out = b->out;
    memcpy(tv + 4 * (size_t)s, b->v, sizeof b->v);
    tn[4 * (size_t)s + k] = out;
    tn[out] = 4 * s + k;
    l = b->v[3] != TR_GHOST ? s : l;
    /* table lookups, not a switch on k: k follows no pattern */
    const uint8_t(*sk)[3] = SIDE[k];
    for (int i3 = 0; i3 < 3; i3++) {
      const uint32_t la = b->l[sk[i3][1]], lb = b->l[sk[i3][2]], code = 4 * s + sk[i3][0];
      map[la * LDIM + lb] = code;
      sd[3 * i + (uint32_t)i3] = (side){code, lb * LDIM + la};
    }
  }
  uint32_t mx = 0; /* an empty cell shows as TR_NONE, above every side code */
  for (uint32_t i = 0; i < 3 * nbf; i++) {
    const uint32_t o = map[sd[i].cell];
    map[sd[i].cell] = TR_NONE;
    tn[sd[i].code] = o;
    mx = o > mx ? o : mx;
  }
  *last = l;
  return mx == TR_NONE;
}

static inline tr_status star_end(const dt *D, uint32_t nnew)
{
  if (2 * D->nglued != 3 * nnew)
    return tr_error(TR_ERR_INTERNAL,
                    "Delaunay: the cavity boundary is not a closed surface (%u of %u star faces "
                    "matched)",
                    2 * D->nglued, 3 * nnew);
  return TR_OK;
}

static inline tr_status alloc_slot(struct tr_mesh *m, uint32_t *s)
{
  if (m->free_head != TR_NONE) {
    *s = m->free_head;
    m->free_head = m->tn[4 * (size_t)*s];
    m->nfree--;
    return TR_OK;
  }
  if (m->nt == m->cap_t) {
    uint32_t nc = m->cap_t + m->cap_t / 2 + 64;
    TR_CHECK(tr_mesh_reserve_tets(m, nc));
  }
  *s = m->nt++;
  return TR_OK;
}

/* OTHER[f]: the faces other than f; OTHER[4]: all four. */
static const uint8_t OTHER[5][4] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}, {0, 1, 2, 3}};

/* The serial insertion of bw.c, for par.c's leftovers; par.c's parallel insertion of the
 * points from..D->n-1 (insertion ids) with nthreads threads (at most 64). */
tr_status tr_dt_insert_serial(dt *D, uint32_t pi);
tr_status tr_dt_insert_parallel(dt *D, uint32_t from, uint32_t nthreads);

#endif
