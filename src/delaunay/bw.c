/* Incremental Bowyer-Watson on the flat tet store (conflict rule in delaunay.h).
 *
 * Per point: a visibility walk from the last created tet to the tet containing it (or
 * to a ghost whose hull face it sees), a breadth-first search of the conflict region
 * (the cavity), and the star re-triangulation: every cavity boundary face (t, k) gives
 * the new tet "t with vertex k replaced by p". That keeps the orientation (p is on the
 * same side of the face as the old vertex k) and keeps TR_GHOST in slot 3. The new tets
 * are glued to each other through the faces that contain p: such a face is (p, u, v) in
 * one tet and (p, v, u) in the other. The boundary vertices get small local ids while
 * the cavity is searched (lid), and the directed edge (u, v) is then a cell of a
 * LDIM x LDIM map (star_small: no hashing, no branches); a cavity with more boundary
 * vertices (rare: a point at the centre of many cospherical ones) takes a hash table of
 * directed edges instead (star_glue_tet). All buffers live in the context and are
 * reused, so an insertion allocates nothing unless the mesh grows.
 *
 * During the build, vertices are numbered in insertion order over a copy of the points
 * in that order: consecutive insertions then touch neighbouring memory (coordinates).
 * The perturbation still uses the input indices (dvtx.orig); ids are mapped back at the end.
 *
 * What the time goes to (random points): about 16500 instructions per point (valgrind
 * --tool=cachegrind on 10^5 points), run at a high rate: 10^5 points (whose mesh fits
 * in the last-level cache) take as long per point as 10^6, so instruction count and
 * mispredicted branches are what to cut, not memory traffic. The insphere determinant
 * a quarter, the cavity search (marks, local ids, boundary faces) a third, writing and
 * gluing the new tets a sixth, walk, sort and renumbering the rest. 48 insphere tests,
 * 6.6 walk steps, 21 cavity tets and 28 new tets per point (TR_DT_STATS). Tried and
 * measured slower: one 32-byte record per tet (vertices and neighbours in one line)
 * converted to tv/tn at the end (the pass and the larger lines cost more than the
 * misses saved); caching vertex - p differences per insertion.
 */
#include <stdlib.h>
#include <math.h>
#include <string.h>

#include "delaunay.h"
#include "det2.h"
#include "predicates.h"

/* The cavity mark is the top bit of vertex slot 0 of the tet itself: the conflict test
 * reads that slot anyway. Vertex ids stay below 2^31 (n is capped far lower); TR_GHOST
 * is only in slot 3. A cavity tet's slot is rewritten or freed: no mark outlives the
 * insertion. Tets not in conflict are not marked: the few reached twice (3 of 48 tests
 * per point) cost less to test again than marks, a list and a clearing pass. */
#define MARK 0x80000000u

/* A hint only: the BFS knows which tets it reads and writes next before it gets there. */
#if defined(__GNUC__) || defined(__clang__)
#define PREFETCH(p) __builtin_prefetch(p)
#else
#define PREFETCH(p) ((void)(p))
#endif

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

static tr_status grow_buf(void **p, uint32_t *cap, uint32_t need, size_t size)
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
static tr_status grow_bufs(dt *D, uint32_t n)
{
  TR_CHECK(grow_buf((void **)&D->cav, &D->capcav, n, sizeof *D->cav));
  return grow_buf((void **)&D->bf, &D->capbf, n, sizeof *D->bf);
}

/* -DTR_DT_STATS prints per-point averages (insphere tests, walk steps, cavity and
 * boundary sizes) after a build: the numbers to look at when tuning. */
#ifdef TR_DT_STATS
#include <stdio.h>
static unsigned long long st_ins, st_walk, st_cav, st_bf, st_pts, st_big;
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
static double static_is_bound(double ext)
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

static double static_o3_bound(double ext)
{
  if (!(ext >= 0x1p-100 && ext <= 0x1p100))
    return INFINITY;
  return 4.0 * TR_O3_FILTER * ext * ext * ext;
}

static int conflict(const dt *D, uint32_t t, const double *p, uint32_t pi)
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
static uint32_t locate(dt *D, uint32_t t, const double *p)
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
static tr_status star_begin(dt *D, uint32_t nnew)
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
static int star_small(uint32_t *restrict tv, uint32_t *restrict tn, uint32_t *restrict map,
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

static tr_status star_end(const dt *D, uint32_t nnew)
{
  if (2 * D->nglued != 3 * nnew)
    return tr_error(TR_ERR_INTERNAL,
                    "Delaunay: the cavity boundary is not a closed surface (%u of %u star faces "
                    "matched)",
                    2 * D->nglued, 3 * nnew);
  return TR_OK;
}

static tr_status alloc_slot(struct tr_mesh *m, uint32_t *s)
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

static tr_status insert(dt *D, uint32_t pi)
{
  struct tr_mesh *m = D->m;
  const double *p = X(D, pi);
  uint32_t t0 = locate(D, D->last, p);
  if (m->tv[4 * (size_t)t0 + 3] != TR_GHOST) {
    const uint32_t *v = m->tv + 4 * (size_t)t0;
    for (int k = 0; k < 4; k++) {
      const double *q = X(D, v[k]);
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
        return tr_error(TR_ERR_INTERNAL, "Delaunay: point %u equals vertex %u after "
                        "duplicate removal", D->orig[pi], D->orig[v[k]]);
    }
  }
  /* The located tet conflicts: p is strictly inside a real tet's closed ball unless it is
   * a vertex, and strictly beyond a ghost's hull face. */
  /* the counts and buffers in locals: stores into the tets could alias D's fields */
  uint32_t ncav = 0, nbf = 0;
  uint32_t *cav = D->cav;
  bface *bf = D->bf;
  /* both buffers have at least room entries */
  uint32_t room = D->capcav < D->capbf ? D->capcav : D->capbf;
  cav[ncav++] = 4 * t0; /* cav: codes 4 * tet + the face it was entered by */
  m->tv[4 * (size_t)t0] |= MARK;
  uint32_t nloc = 1;
  const uint32_t stb = D->stamp << 8;
  for (int k = 0; k < 4; k++)
    PREFETCH(m->tv + 4 * (size_t)(m->tn[4 * (size_t)t0 + k] >> 2));
  for (uint32_t i = 0; i < ncav; i++) {
    /* the face a tet was entered by leads back into the cavity: skip it (t0: none) */
    const uint32_t t = cav[i] >> 2;
    const uint8_t *faces = i ? OTHER[cav[i] & 3] : OTHER[4];
    const int nf = i ? 3 : 4;
    /* a tet's neighbours are read one after the other between conflict tests: start
     * their misses one cavity tet ahead (its neighbour codes were prefetched when it
     * joined the cavity), so that they overlap this tet's tests (t0's were started
     * above; the second cavity tet, found while t0 is searched, gets none) */
    if (i + 1 < ncav) {
      const uint32_t *tnn = m->tn + 4 * (size_t)(cav[i + 1] >> 2);
      for (int k = 0; k < 4; k++)
        PREFETCH(m->tv + 4 * (size_t)(tnn[k] >> 2));
    }
    /* every vertex of a cavity tet is on the cavity boundary: number them here, while
     * their points are still in cache from the conflict tests */
    const uint32_t *tvt = m->tv + 4 * (size_t)t;
    const uint32_t t3 = tvt[3];
    /* room for what this tet's faces can add (at most 4 entries) */
    if (ncav + nbf + 4 > room) {
      D->ncav = ncav;
      D->nbf = nbf;
      TR_CHECK(grow_bufs(D, ncav + nbf + 4));
      cav = D->cav;
      bf = D->bf;
      room = D->capcav < D->capbf ? D->capcav : D->capbf;
    }
    const uint32_t vt[4] = {tvt[0] & ~MARK, tvt[1], tvt[2], t3}; /* t unmarked */
    uint8_t lt[4];
    if (i == 0) {
      for (int k = 0; k < 4; k++)
        lt[k] = (uint8_t)(vt[k] == TR_GHOST ? 0 : lid(D->pv, stb, &nloc, vt[k]));
    } else {
      /* the entry face's vertices were numbered with the tet t was found from (searched
       * before t): their tags hold their ids; only the vertex across it can be new */
      const uint32_t e = cav[i] & 3;
      for (int k = 0; k < 3; k++)
        lt[k] = (uint8_t)D->pv[vt[k]].tag;
      lt[3] = (uint8_t)(t3 == TR_GHOST ? 0 : D->pv[t3].tag);
      if (vt[e] != TR_GHOST)
        lt[e] = (uint8_t)lid(D->pv, stb, &nloc, vt[e]);
    }
    for (int f = 0; f < nf; f++) {
      const int k = faces[f];
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k], u = c >> 2;
      uint32_t *w = m->tv + 4 * (size_t)u;
      if (w[0] & MARK)
        continue;
      /* u's neighbours if it joins the cavity, else the face glued to a new tet */
      PREFETCH(m->tn + 4 * (size_t)u);
      /* Both outcomes are written and the count keeps one: whether u conflicts
       * follows no pattern, and a mispredicted branch costs more than the stores. */
      const uint32_t cf = (uint32_t)conflict(D, u, p, pi);
      w[0] |= cf << 31;
      cav[ncav] = c;
      ncav += cf;
      /* the boundary face (t, k), kept unless u joined the cavity */
      bface *b = &bf[nbf];
      nbf += cf ^ 1;
      memcpy(b->v, vt, sizeof b->v);
      b->v[k] = pi;
      b->out = c;
      b->k = (uint32_t)k;
      memcpy(b->l, lt, sizeof lt);
    }
  }
  D->ncav = ncav;
  D->nbf = nbf;
  STAT((st_cav += D->ncav, st_bf += D->nbf, st_pts++));

  if (++D->stamp == 1u << 24) { /* wrapped: old tags could look current */
    for (uint32_t i = 0; i < D->n; i++)
      D->pv[i].tag = 0;
    D->stamp = 1;
  }

  /* Re-triangulate: reuse the cavity's slots first. */
  const int small = nloc <= LDIM;
  if (!small) {
    STAT(st_big++);
    TR_CHECK(star_begin(D, D->nbf));
  }
  /* The slot of each new tet: the cavity's, then free or new ones. All are taken before
   * the tets are written: m->tv and m->tn may move when the store grows. */
  if (D->nbf > D->capslot)
    TR_CHECK(grow_buf((void **)&D->slot, &D->capslot, D->nbf, sizeof *D->slot));
  if (3 * D->nbf > D->capsd)
    TR_CHECK(grow_buf((void **)&D->sd, &D->capsd, 3 * D->nbf, sizeof *D->sd));
  {
    uint32_t *slot = D->slot, i = 0;
    for (; i < D->nbf && i < D->ncav; i++)
      slot[i] = D->cav[i] >> 2;
    for (; i < D->nbf; i++)
      TR_CHECK(alloc_slot(m, &slot[i]));
  }
  uint32_t last = TR_NONE;
  int bad = 0;
  if (small) {
    bad = star_small(m->tv, m->tn, D->map, D->bf, D->slot, D->sd, D->nbf, &last);
  } else {
    for (uint32_t i = 0; i < D->nbf; i++) {
      const uint32_t s = D->slot[i];
      const bface *b = &D->bf[i];
      uint32_t *v = m->tv + 4 * (size_t)s;
      memcpy(v, b->v, sizeof b->v);
      m->tn[4 * (size_t)s + b->k] = b->out;
      m->tn[b->out] = 4 * s + b->k;
      if (v[3] != TR_GHOST)
        last = s;
      star_glue_tet(D, s, b->k);
    }
  }
  for (uint32_t i = D->nbf; i < D->ncav; i++)
    tr_tet_free(m, D->cav[i] >> 2);
  if (last == TR_NONE)
    return tr_error(TR_ERR_INTERNAL, "Delaunay: inserting point %u created no real tet",
                    D->orig[pi]);
  D->last = last;
  if (!small)
    return star_end(D, D->nbf);
  if (bad)
    return tr_error(TR_ERR_INTERNAL, "Delaunay: the cavity boundary of point %u is not a "
                    "closed surface", D->orig[pi]);
  return TR_OK;
}

/* Are a, b, c collinear? Exactly: all three coordinate projections are degenerate. */
static int collinear(const double *a, const double *b, const double *c)
{
  return tr_orient2d_proj(a, b, c, 0) == 0 && tr_orient2d_proj(a, b, c, 1) == 0 &&
         tr_orient2d_proj(a, b, c, 2) == 0;
}

/* Picks four affinely independent points among order[0..m) and moves them to the front.
 * The messages name input points so that the user can look at them. */
static tr_status first_simplex(const double *xyz, uint32_t n, uint32_t *order, uint32_t m)
{
  if (m < 4) {
    if (m == 1 && n > 1)
      return tr_error(TR_ERR_DEGENERATE, "all %u points are the same point", n);
    return tr_error(TR_ERR_DEGENERATE, "only %u distinct point(s) (of %u): a tetrahedralization "
                    "needs at least 4 points not in a plane", m, n);
  }
  const double *a = xyz + 3 * (size_t)order[0], *b = xyz + 3 * (size_t)order[1];
  uint32_t j = 2;
  while (j < m && collinear(a, b, xyz + 3 * (size_t)order[j]))
    j++;
  if (j == m)
    return tr_error(TR_ERR_DEGENERATE, "all %u points are collinear (line through points %u, %u)",
                    n, order[0], order[1]);
  uint32_t t = order[2];
  order[2] = order[j];
  order[j] = t;
  const double *c = xyz + 3 * (size_t)order[2];
  j = 3;
  while (j < m && tr_orient3d(a, b, c, xyz + 3 * (size_t)order[j]) == 0)
    j++;
  if (j == m)
    return tr_error(TR_ERR_DEGENERATE,
                    "all %u points are coplanar (plane through points %u, %u, %u)", n, order[0],
                    order[1], order[2]);
  t = order[3];
  order[3] = order[j];
  order[j] = t;
  if (tr_orient3d(a, b, c, xyz + 3 * (size_t)order[3]) < 0) {
    t = order[0];
    order[0] = order[1];
    order[1] = t;
  }
  return TR_OK;
}

/* Triangulates the D->n points of D->xyz (insertion ids 0..n-1; 0..3 span 3D). */
static tr_status build(dt *D)
{
  struct tr_mesh *mesh = D->m;
  uint32_t t0, g[4];
  for (int k = 0; k < 4; k++)
    for (int i = 0; i < 3; i++) {
      int j = SIDE[k][i][0];
      if (SIDE[k][i][1] != tr_face_rot[k][j][0] || SIDE[k][i][2] != tr_face_rot[k][j][1])
        return tr_error(TR_ERR_INTERNAL, "Delaunay: SIDE disagrees with tr_face_rot");
    }
  TR_CHECK(tr_tet_new(mesh, 0, 1, 2, 3, &t0));
  for (int k = 0; k < 4; k++) {
    const uint32_t *v = mesh->tv + 4 * (size_t)t0;
    const uint8_t *f = tr_face_vtx[k];
    /* reversed face: the ghost's face 3 looks out of the hull */
    TR_CHECK(tr_tet_new(mesh, v[f[0]], v[f[2]], v[f[1]], TR_GHOST, &g[k]));
    tr_glue(mesh, t0, k, g[k], 3);
  }
  /* the ghosts' faces through TR_GHOST: the star of the ghost vertex */
  TR_CHECK(star_begin(D, 4));
  for (int k = 0; k < 4; k++)
    star_glue_tet(D, g[k], 3);
  TR_CHECK(star_end(D, 4));
  D->last = t0;
  for (uint32_t i = 4; i < D->n; i++)
    TR_CHECK(insert(D, i));
#ifdef TR_DT_STATS
  fprintf(stderr, "points %llu (%llu by the hash) insphere %.2f walk %.2f cavity %.2f boundary "
          "%.2f per point\n", st_pts, st_big, (double)st_ins / st_pts,
          (double)st_walk / st_pts, (double)st_cav / st_pts, (double)st_bf / st_pts);
#endif
  return TR_OK;
}

/* Back from insertion ids to input indices: tets, then v2t. */
static tr_status renumber(struct tr_mesh *m, const uint32_t *order, uint32_t nu)
{
  memset(m->flags, 0, m->nt); /* the build never sets flags; new slots were not cleared */
  /* v2t is not needed while building (walks start from the last tet), so it is set
   * once here, in the same pass: the last tet in slot order that has the vertex */
  (void)nu;
  for (uint32_t i = 0; i < m->nv; i++)
    m->v2t[i] = TR_NONE;
  uint32_t *v2t = m->v2t;
  for (uint32_t t = 0; t < m->nt; t++) {
    uint32_t *v = m->tv + 4 * (size_t)t;
    if (v[0] == TR_NONE)
      continue;
    for (int k = 0; k < 3; k++) {
      v[k] = order[v[k]];
      v2t[v[k]] = t;
    }
    if (v[3] != TR_GHOST) {
      v[3] = order[v[3]];
      v2t[v[3]] = t;
    }
  }
  return TR_OK;
}

tr_status tr_delaunay_build(const double *xyz, uint32_t n, struct tr_mesh **out)
{
  *out = NULL;
  for (uint32_t i = 0; i < n; i++)
    for (int c = 0; c < 3; c++) {
      double x = xyz[3 * (size_t)i + (size_t)c];
      if (!(x - x == 0))
        return tr_error(TR_ERR_INPUT, "point %u has a non-finite coordinate (%g)", i, x);
    }
  if (n >= (TR_GHOST - 1) || n > (UINT32_MAX / 4 - 64) / 7)
    return tr_error(TR_ERR_NOMEM, "too many points (%u)", n);
  struct tr_mesh *m;
  /* ~6.7 tets per point for uniform random points; growth covers the rest. */
  TR_CHECK(tr_mesh_create(n, 7 * n + 64, &m));
  tr_status s = TR_OK;
  dt D;
  memset(&D, 0, sizeof D);
  D.m = m;
  D.rng = 0x2545F4914F6CDD1Dull;
  uint32_t *order = malloc((n ? n : 1) * sizeof *order);
  dvtx *P = NULL;
  m->dup_map = malloc((n ? n : 1) * sizeof *m->dup_map);
  if (!order || !m->dup_map) {
    s = tr_error(TR_ERR_NOMEM, "out of memory for %u points", n);
    goto done;
  }
  if (n)
    memcpy(m->xyz, xyz, 3 * (size_t)n * sizeof *xyz);
  m->nv = n;
  for (uint32_t i = 0; i < n; i++)
    m->v2t[i] = TR_NONE;
  uint32_t nu = 0;
  if ((s = tr_spatial_order(xyz, n, order, &nu, m->dup_map)) != TR_OK)
    goto done;
  m->ndup = n - nu;
  if ((s = first_simplex(xyz, n, order, nu)) != TR_OK)
    goto done;
  P = malloc((size_t)nu * sizeof *P);
  D.map = malloc(LDIM * LDIM * sizeof *D.map);
  if (!P || !D.map) {
    s = tr_error(TR_ERR_NOMEM, "out of memory for %u points", n);
    goto done;
  }
  for (uint32_t i = 0; i < LDIM * LDIM; i++)
    D.map[i] = TR_NONE;
  for (uint32_t i = 0; i < nu; i++) {
    memcpy(P[i].x, xyz + 3 * (size_t)order[i], sizeof P[i].x);
    P[i].orig = order[i];
    P[i].tag = 0;
  }
  D.pv = P;
  D.stamp = 1;
  {
    double lo[3], hi[3], ext = 0;
    for (int c = 0; c < 3; c++)
      lo[c] = hi[c] = P[0].x[c];
    for (uint32_t i = 1; i < nu; i++)
      for (int c = 0; c < 3; c++) {
        lo[c] = P[i].x[c] < lo[c] ? P[i].x[c] : lo[c];
        hi[c] = P[i].x[c] > hi[c] ? P[i].x[c] : hi[c];
      }
    for (int c = 0; c < 3; c++)
      ext = hi[c] - lo[c] > ext ? hi[c] - lo[c] : ext;
    D.is_bound = static_is_bound(ext);
    D.o3_bound = static_o3_bound(ext);
  }
  D.orig = order;
  D.n = nu;
  if ((s = grow_buf((void **)&D.cav, &D.capcav, 256, sizeof *D.cav)) != TR_OK ||
      (s = grow_buf((void **)&D.bf, &D.capbf, 256, sizeof *D.bf)) != TR_OK)
    goto done;
  if ((s = build(&D)) != TR_OK)
    goto done;
  /* on insertion ids: they follow the Hilbert curve, so the canonical order keeps the
   * locality of the build (input indices may be in any order), and they are a function
   * of the input alone, like the tetrahedralization */
  if ((s = tr_delaunay_canonical(m)) != TR_OK)
    goto done;
  s = renumber(m, order, nu);
done:
  free(order);
  free(P);
  free(D.cav);
  free(D.slot);
  free(D.sd);
  free(D.bf);
  free(D.ht);
  free(D.map);
  if (s != TR_OK) {
    tr_mesh_destroy(m);
    return s;
  }
  *out = m;
  return TR_OK;
}

tr_status tr_delaunay(const double *xyz, uint32_t npoints, tr_mesh **out)
{
  tr_error_clear();
  if (!out || (!xyz && npoints))
    return tr_error(TR_ERR_USAGE, "tr_delaunay: NULL argument");
  tr_status s = tr_delaunay_build(xyz, npoints, out);
  if (s == TR_OK && (s = tr_mesh_attach_dense_tets(*out)) != TR_OK) {
    /* the dense tet array of tr_mesh_tets (the store keeps its ghost tets) */
    tr_mesh_destroy(*out);
    *out = NULL;
  }
  return s;
}
