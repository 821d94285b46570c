/* Sliver removal by a new interior point (sliver.h): a sliver's four points lie near a
 * small sphere, so flips and smoothing often cannot open it; a point at its circumcentre
 * can (Shewchuk 1998; Si 2015: TetGen's -O adds points for the worst slivers). The point
 * is the circumcentre computed in doubles, inserted as that exact double, by a
 * Bowyer-Watson cavity that never crosses a sub-face, shrunk until every face it is coned
 * from is strictly visible from the point. The cavity then is star-shaped about the point,
 * which lies strictly inside it, so the point is on no constraint and every new tet is
 * exactly positive. The insertion is kept only when the smallest dihedral angle of the new
 * tets beats that of the cavity and the refinement's bounds hold, so the mesh's smallest
 * angle never drops. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/prefetch.h"
#include "predicates/predicates.h"
#include "refine/quality.h"
#include "sliver/sliver.h"

/* Tets in a cavity: a sliver's is small, a bigger one is skipped. A point above a flat
 * cap's sub-face has a bigger one: the cap's sphere is huge, and so are those of the caps
 * beside it on a nearly flat stretch of surface. With 64, pinion.off kept 68 tets under 1
 * degree (smallest 0.000; 18 of them caps with two sub-faces), with 256 none (smallest
 * 1.02), for about the same CPU; 1024 found worse cavities and cost 50% more. Only 64 for
 * the circumcentre candidates and 256 for the others left pinion at 0.000 again. */
#define SL_MAX_CAVITY 256
/* Candidates farther from the tet's centroid than SL_FAR times its longest edge are not
 * tried: on pinion, rotor_small, joint and cheese no winner lies beyond 3.7 of them, and
 * of the CGAL models under 400 KB only mpi_triang's mesh changes (29.40% -> 29.13% of
 * tets under 10 degrees), while the flat tets of a slab 1e-6 thick put a sixth of their
 * candidates 100 edges away or more, each with a cavity of near-degenerate spheres
 * (tests/data/thin_boxes_1e-6.off: 1.51 -> 0.73 s, the same mesh). */
#define SL_FAR 20.0
/* a prime step through the slots of an insertion pass (visit_step) */
#define SL_VISIT_STEP 1000003u

/* Membership of a cavity's tets and of its cone's vertices: every face of every cavity tet
 * asks whether its neighbour is in, and the shrink loop asks again after each removal, so
 * a linear search made the candidate screening cubic in the cavity's size (the profile of
 * a thin slab: 40% of the stage in that search). A fixed table with deletion (a removed
 * tet leaves a tombstone); at most 4 * SL_MAX_CAVITY distinct ids go in (the cone's
 * vertices), so it never fills past half. Clearing resets the slots used only: most
 * cavities are a few tets, and a memset of the whole table per candidate would not be. */
#define SL_SET 2048u
#define SL_SET_EMPTY UINT32_MAX
#define SL_SET_GONE (UINT32_MAX - 1u)
typedef struct {
  uint32_t k[SL_SET];
  uint32_t used[SL_SET], nused; /* the slots taken since the last clear */
} idset;

static void set_init(idset *s)
{
  memset(s->k, 0xff, sizeof s->k);
  s->nused = 0;
}

static void set_clear(idset *s)
{
  for (uint32_t i = 0; i < s->nused; i++)
    s->k[s->used[i]] = SL_SET_EMPTY;
  s->nused = 0;
}

/* the slot holding x, or the empty slot where x would go */
static uint32_t set_slot(const idset *s, uint32_t x)
{
  uint32_t i = (uint32_t)((x + 1ull) * 0x9e3779b97f4a7c15ull >> 53); /* 11 bits */
  while (s->k[i] != x && s->k[i] != SL_SET_EMPTY)
    i = (i + 1) & (SL_SET - 1);
  return i;
}

static int set_has(const idset *s, uint32_t x)
{
  return s->k[set_slot(s, x)] == x;
}

static void set_add(idset *s, uint32_t x)
{
  uint32_t i = set_slot(s, x);
  if (s->k[i] == SL_SET_EMPTY)
    s->used[s->nused++] = i; /* a slot is empty once per clear: nused <= SL_SET */
  s->k[i] = x;
}

static void set_del(idset *s, uint32_t x)
{
  uint32_t i = set_slot(s, x);
  if (s->k[i] == x)
    s->k[i] = SL_SET_GONE;
}

/* p strictly inside the circumsphere of tet t: exact, or (screen) on the vertices'
 * doubles, which only ranks the candidates. */
static int conflicts(const struct tr_mesh *m, uint32_t t, const tr_point *p, int screen)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  if (screen) {
    const double *x = m->xyz;
    return tr_insphere(x + 3 * (size_t)v[0], x + 3 * (size_t)v[1], x + 3 * (size_t)v[2],
                       x + 3 * (size_t)v[3], p->d) > 0;
  }
  tr_point q[4];
  for (int i = 0; i < 4; i++)
    q[i] = tr_mesh_point(m, v[i]);
  return tr_insphere_p(&q[0], &q[1], &q[2], &q[3], p) > 0;
}

/* Face k of t with the point x in place of vertex k is strictly positive (exact, or on
 * the doubles: screen). */
static int sees(const struct tr_mesh *m, uint32_t t, int k, const tr_point *x, int screen)
{
  if (screen) {
    const double *y[4];
    for (int i = 0; i < 4; i++)
      y[i] = i == k ? x->d : m->xyz + 3 * (size_t)m->tv[4 * (size_t)t + (size_t)i];
    return tr_orient3d(y[0], y[1], y[2], y[3]) > 0;
  }
  tr_point q[4];
  for (int i = 0; i < 4; i++)
    q[i] = i == k ? *x : tr_mesh_point(m, m->tv[4 * (size_t)t + (size_t)i]);
  return tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0;
}

/* A face of the cavity's boundary: face k of cavity tet t is coned when the tet behind
 * it is not in the cavity. */
static int boundary(const struct tr_mesh *m, const idset *in, uint32_t t, int k)
{
  uint32_t nb = TR_NEIG(m, t, k);
  return nb == TR_NONE || !set_has(in, nb);
}

/* Takes cav[i] out of the cavity, the last tet (and its face answers, seen) in its place. */
static void take_out(idset *in, uint32_t *cav, uint32_t *n, uint8_t *vis, uint32_t i)
{
  set_del(in, cav[i]);
  cav[i] = cav[--*n];
  vis[i] = vis[*n];
}

/* Takes out of the cavity every tet at a vertex it swallowed (one on no coned face: the
 * mesh is not Delaunay, so the conflict tets of a point above a flat cap, whose sphere is
 * huge, may surround a vertex); the vertex is then on the boundary again, and the shrink
 * that follows restores visibility. Returns 0 when t itself has such a vertex. onb:
 * scratch for the vertices of the coned faces. */
static int carve(const struct tr_mesh *m, uint32_t t, uint32_t *cav, uint32_t *n, idset *in,
                 idset *onb, uint8_t *vis)
{
  set_clear(onb);
  for (uint32_t i = 0; i < *n; i++)
    for (int k = 0; k < 4; k++)
      if (boundary(m, in, cav[i], k))
        for (int j = 0; j < 3; j++)
          set_add(onb, m->tv[4 * (size_t)cav[i] + (size_t)tr_face_vtx[k][j]]);
  for (uint32_t i = 0; i < *n;) {
    const uint32_t *tv = m->tv + 4 * (size_t)cav[i];
    int swallows = 0;
    for (int k = 0; k < 4; k++)
      swallows |= !set_has(onb, tv[k]);
    if (!swallows) {
      i++;
      continue;
    }
    if (cav[i] == t)
      return 0;
    take_out(in, cav, n, vis, i);
  }
  return 1;
}

/* Is face k of cav[i] strictly seen from x? vis[i]: bits 0-3 whether face k is known,
 * bits 4-7 the answer; each face is tested once (the shrink below asked again after every
 * removal: a third of the stage's time on joint.off). */
static int seen(const struct tr_mesh *m, const uint32_t *cav, uint32_t i, int k,
                const tr_point *x, int screen, uint8_t *vis)
{
  if (!(vis[i] >> k & 1))
    vis[i] |= (uint8_t)(1u << k | (unsigned)sees(m, cav[i], k, x, screen) << (k + 4));
  return vis[i] >> (k + 4) & 1;
}

/* Takes out of the cavity the first tet (in cav's order) with a coned face x does not
 * strictly see, the last one in its place, until none is left; 0 when t would have to go.
 * The order of the tets taken out decides the order of the new tets, and with it what
 * the rounds after do; the scan is cheap once the faces' answers are cached. */
static int shrink(const struct tr_mesh *m, uint32_t t, const tr_point *x, int screen,
                  uint32_t *cav, uint32_t *n, idset *in, uint8_t *vis)
{
  for (int changed = 1; changed && *n;) {
    changed = 0;
    for (uint32_t i = 0; i < *n && !changed; i++)
      for (int k = 0; k < 4; k++)
        if (boundary(m, in, cav[i], k) && !seen(m, cav, i, k, x, screen, vis)) {
          if (cav[i] == t)
            return 0;
          take_out(in, cav, n, vis, i);
          changed = 1;
          break;
        }
  }
  return 1;
}

/* The flood's time is in memory: each tet it reaches costs a miss for its neighbour
 * links, one for its neighbours' vertices and one for the vertex they do not share (65395.stl:
 * half of try_cavity's samples on those loads). The links of a tet in the cavity are asked
 * for next, so its neighbours' slots are fetched ahead while its faces are tested. */
static inline void prefetch_neighbours(const struct tr_mesh *m, uint32_t t)
{
  const uint32_t *tn = m->tn + 4 * (size_t)t;
  for (int k = 0; k < 4; k++)
    if (tn[k] != TR_NONE) {
      TR_PREFETCH(m->tv + 4 * (size_t)(tn[k] >> 2));
      TR_PREFETCH(m->tn + 4 * (size_t)(tn[k] >> 2));
    }
}

/* The cavity of x from sliver t: t, grown through faces that are not sub-faces to real tets
 * whose circumsphere strictly holds x and to those behind a face x does not strictly see,
 * carved off the vertices it swallowed when onb is given (carve), then shrunk (a tet with
 * a coned face x does not strictly see leaves) until stable. *n = 0 when t itself would
 * have to leave or the cavity grows too big. out: scratch (onb may be the same set). */
static void cavity(const tr_sliver_ctx *c, uint32_t t, const tr_point *x, int screen,
                   uint32_t *cav, uint32_t *n, idset *in, idset *out, idset *onb)
{
  const struct tr_mesh *m = c->m;
  uint8_t vis[SL_MAX_CAVITY]; /* the faces' visibility, as far as known (seen) */
  *n = 0;
  set_clear(in);
  set_clear(out); /* the tets found out of conflict: each is tested once */
  cav[(*n)++] = t; /* the sliver goes whether or not its sphere holds x */
  set_add(in, t);
  for (uint32_t i = 0; i < *n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)cav[i];
    prefetch_neighbours(m, cav[i]);
    for (int k = 0; k < 4; k++) {
      uint32_t nb = TR_NEIG(m, cav[i], k);
      if (nb == TR_NONE || set_has(in, nb) || set_has(out, nb) || !tr_tet_is_real(m, nb))
        continue; /* the sets first: they are in cache, nb's vertices may not be */
      uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
      if (tr_sliver_protected(c, f, 3))
        continue;
      if (!conflicts(m, nb, x, screen)) {
        set_add(out, nb);
        continue;
      }
      if (*n == SL_MAX_CAVITY) {
        *n = 0;
        return;
      }
      cav[(*n)++] = nb;
      set_add(in, nb);
    }
  }
  /* a face x does not see, with a tet behind it that the cavity may take, grows the
   * cavity: a point off the sliver (above a sub-face) lies in a tet next to it */
  for (uint32_t i = 0; i < *n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)cav[i];
    prefetch_neighbours(m, cav[i]);
    vis[i] = 0;
    for (int k = 0; k < 4; k++) {
      uint32_t nb = TR_NEIG(m, cav[i], k);
      if (nb == TR_NONE || set_has(in, nb) || !tr_tet_is_real(m, nb) ||
          seen(m, cav, i, k, x, screen, vis))
        continue;
      uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
      if (tr_sliver_protected(c, f, 3))
        continue;
      if (*n == SL_MAX_CAVITY) {
        *n = 0;
        return;
      }
      cav[(*n)++] = nb;
      set_add(in, nb);
    }
  }
  if (onb && !carve(m, t, cav, n, in, onb, vis)) {
    *n = 0;
    return;
  }
  /* then the faces it still does not see take their tet out */
  if (!shrink(m, t, x, screen, cav, n, in, vis))
    *n = 0;
}

/* Sorts e[0..n) ascending: Shell's sort with Ciura's gaps, inline (a cone has a few
 * hundred edges at most, and qsort's calls through its comparator were 2% of pinion.off) */
static void sort_u64(uint64_t *e, uint32_t n)
{
  static const uint32_t gaps[] = {701, 301, 132, 57, 23, 10, 4, 1};
  for (size_t g = 0; g < sizeof gaps / sizeof *gaps; g++)
    for (uint32_t i = gaps[g]; i < n; i++) {
      uint64_t x = e[i];
      uint32_t j = i;
      for (; j >= gaps[g] && e[j - gaps[g]] > x; j -= gaps[g])
        e[j] = e[j - gaps[g]];
      e[j] = x;
    }
}

/* Every edge of the coned faces (vertex k of each new tet is the new vertex) in exactly
 * two of them: the boundary is a closed manifold surface, so the cone glues
 * (tr_mesh_replace would refuse anything else, after the vertex was added). */
static int manifold(const uint32_t *newv, const uint8_t *apex, uint32_t nf)
{
  uint64_t e[3 * 4 * SL_MAX_CAVITY];
  uint32_t ne = 0;
  for (uint32_t i = 0; i < nf; i++)
    for (int j = 0; j < 3; j++) {
      uint64_t a = newv[4 * i + tr_face_vtx[apex[i]][j]],
               b = newv[4 * i + tr_face_vtx[apex[i]][(j + 1) % 3]];
      e[ne++] = a < b ? a << 32 | b : b << 32 | a;
    }
  sort_u64(e, ne);
  for (uint32_t i = 0; i < ne; i += 2)
    if (i + 1 >= ne || e[i] != e[i + 1] || (i + 2 < ne && e[i + 2] == e[i]))
      return 0;
  return 1;
}

static tr_status grow_movable(tr_sliver_ctx *c, uint32_t nv)
{
  uint8_t *mv = realloc(c->movable, nv);
  if (!mv)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex flags", nv);
  c->movable = mv;
  return TR_OK;
}

/* A point under consideration: its cavity and cone (new vertex pid at x). */
struct trial {
  double x[3];
  uint32_t cav[SL_MAX_CAVITY], n, nf;
  uint32_t newv[4 * 4 * SL_MAX_CAVITY];
  double newmin;
  int carve; /* the cavity is carved (see carve) */
  int swallow; /* the cavity may swallow movable vertices (see insert_at) */
  idset in, cone; /* the tets of cav; the vertices of newv */
};
typedef struct trial trial;

/* Every vertex of the cavity's tets on a coned face: the cavity swallows no vertex (the
 * mesh is not Delaunay, and growth past the conflict tets may surround one). */
static int keeps_vertices(const tr_sliver_ctx *c, trial *z)
{
  const struct tr_mesh *m = c->m;
  set_clear(&z->cone);
  for (uint32_t i = 0; i < 4 * z->nf; i++)
    set_add(&z->cone, z->newv[i]);
  for (uint32_t i = 0; i < z->n; i++)
    for (int k = 0; k < 4; k++) {
      uint32_t v = m->tv[4 * (size_t)z->cav[i] + (size_t)k];
      if (!set_has(&z->cone, v) && !(z->swallow && c->movable[v]))
        return 0;
    }
  return 1;
}


/* No sub-face between two tets of the cavity: growth never crosses one, but may reach
 * the tet behind an inner sub-face (a region's facet) by another face, and the cone would
 * then delete it (a point off a cap's plane, next to such a facet, did). */
static int keeps_subfaces(const tr_sliver_ctx *c, const trial *z)
{
  const struct tr_mesh *m = c->m;
  for (uint32_t i = 0; i < z->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)z->cav[i];
    for (int k = 0; k < 4; k++) {
      uint32_t nb = TR_NEIG(m, z->cav[i], k);
      if (nb == TR_NONE || !set_has(&z->in, nb))
        continue;
      uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
      if (tr_sliver_protected(c, f, 3))
        return 0;
    }
  }
  return 1;
}

/* The faces of sliver t that no cavity crosses (a sub-face, or one without a real tet
 * behind it) are on the boundary of every cavity that keeps t (else the tet behind one is
 * inside, which keeps_subfaces refuses), so x must strictly see each (else shrink takes t
 * out), and its new tet there must beat `floor`. Where this fails, try_point would too,
 * after building the cavity: a sixth of the candidates on cheese.off fail here (points
 * off a cap's plane on the far side). */
static int fixed_faces_pass(const tr_sliver_ctx *c, uint32_t t, const double x[3],
                            const tr_point *px, int screen, double floor)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++) {
    uint32_t nb = TR_NEIG(m, t, k);
    uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
    if (nb != TR_NONE && tr_tet_is_real(m, nb) && !tr_sliver_protected(c, f, 3))
      continue;
    if (!sees(m, t, k, px, screen))
      return 0;
    if (floor >= 0) { /* the new tet as try_point builds it (angles are at least 0) */
      uint32_t p[4];
      memcpy(p, tv, sizeof p);
      p[k] = m->nv;
      if (!(tr_sliver_min_dihedral_at(m, p, m->nv, x, NULL) > floor))
        return 0;
    }
  }
  return 1;
}

/* try_point after fixed_faces_pass */
static int try_cavity(const tr_sliver_ctx *c, uint32_t t, const double x[3], int screen,
                      double floor, trial *z)
{
  const struct tr_mesh *m = c->m;
  memcpy(z->x, x, sizeof z->x);
  tr_point px = tr_pt_d(x);
  /* the cone's set is scratch until keeps_vertices fills it */
  cavity(c, t, &px, screen, z->cav, &z->n, &z->in, &z->cone, z->carve ? &z->cone : NULL);
  if (!z->n)
    return 0;
  uint32_t pid = m->nv; /* tr_mesh_add_vertex appends */
  uint8_t apex[4 * SL_MAX_CAVITY];
  double oldmin = INFINITY, was = 0;
  z->nf = 0;
  tr_sliver_tet_min_prefetch(c, z->cav, z->n);
  for (uint32_t i = 0; i < z->n; i++) {
    double rr;
    const uint32_t *tv = m->tv + 4 * (size_t)z->cav[i];
    oldmin = fmin(oldmin, tr_sliver_tet_min(c, z->cav[i], &rr));
    was = fmax(was, rr);
    for (int k = 0; k < 4; k++)
      if (boundary(m, &z->in, z->cav[i], k)) {
        uint32_t *p = z->newv + 4 * (size_t)z->nf;
        memcpy(p, tv, 4 * sizeof *p);
        p[k] = pid;
        apex[z->nf++] = (uint8_t)k;
      }
  }
  /* every new tet must beat thr: screened on its smallest cosine, and only the cones
   * that pass every test below get their angles (acos was 6.5% of pinion_small.off's CPU when
   * every new tet of every candidate took one; most candidates fail this screen) */
  double dih[4 * SL_MAX_CAVITY], rat[4 * SL_MAX_CAVITY], lo[4 * SL_MAX_CAVITY];
  uint8_t flat[4 * SL_MAX_CAVITY];
  const double thr = fmax(oldmin, floor), below = tr_dihedral_cos_below(thr);
  for (uint32_t i = 0; i < z->nf; i++) {
    int fl;
    lo[i] = tr_sliver_min_cos_at(m, z->newv + 4 * (size_t)i, pid, x, &fl);
    flat[i] = (uint8_t)fl;
    if (tr_sliver_cos_loses(lo[i], fl, below, thr))
      return 0; /* its angle is at most thr */
  }
  if (!manifold(z->newv, apex, z->nf) || !keeps_vertices(c, z) || !keeps_subfaces(c, z))
    return 0;
  z->newmin = INFINITY;
  for (uint32_t i = 0; i < z->nf; i++) {
    dih[i] = tr_sliver_angle_of_cos(lo[i], flat[i]);
    z->newmin = fmin(z->newmin, dih[i]);
  }
  if (!(z->newmin > thr))
    return 0;
  /* the ratios only where the bound looks at them (the circumsphere costs) */
  for (uint32_t i = 0; i < z->nf; i++) {
    rat[i] = 0;
    if (c->keep.ratio > 0 && !(dih[i] >= c->bound))
      rat[i] = tr_sliver_ratio_at(m, z->newv + 4 * (size_t)i, pid, x);
  }
  uint32_t region = m->region ? m->region[t] : 0; /* no sub-face inside the cavity */
  for (uint32_t i = 0; i < z->nf; i++)
    if (screen ? c->keep.ratio > 0 && rat[i] > tr_sliver_ratio_allowed(c, was) &&
                     !(dih[i] >= c->bound)
               : !tr_sliver_keeps_bounds(c, z->newv + 4 * (size_t)i, pid, x, region, rat[i],
                                         dih[i], was))
      return 0; /* the screen: the ratio part only (the volume part is exact) */
  return 1;
}

/* The cavity and cone of x for sliver t; 1 when the new tets' smallest angle beats the
 * cavity's and `floor` (the best screened candidate so far) and they keep the bounds. */
static int try_point(const tr_sliver_ctx *c, uint32_t t, const double x[3], int screen,
                     double floor, trial *z)
{
  tr_point px = tr_pt_d(x);
  if (fixed_faces_pass(c, t, x, &px, screen, floor) &&
      !(screen && tr_sliver_segment_blocked(c, t, x)))
    return try_cavity(c, t, x, screen, floor, z);
#ifndef NDEBUG
  int full = try_cavity(c, t, x, screen, floor, z); /* the same answer the long way */
  assert(!full);
  (void)full;
#endif
  return 0;
}

/* |b - a| */
static double dist3(const double *a, const double *b)
{
  return sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
              (b[2] - a[2]) * (b[2] - a[2]));
}

/* The normal (b - a) x (e - a) of triangle abe into n; returns its length. */
static double face_normal(const double *a, const double *b, const double *e, double n[3])
{
  double u[3], v[3];
  for (int j = 0; j < 3; j++) {
    u[j] = b[j] - a[j];
    v[j] = e[j] - a[j];
  }
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  return sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* Heights over a face of the points tried there, in units of the face's mean edge: a
 * good tet on it (0.8) down to a point just off a nearly flat ridge (0.1), where a higher
 * one would leave the domain or see a neighbouring sub-face edge-on. */
#define SL_HEIGHTS 4
#define SL_OFF_PLANE_ABOVE 5.0
static const double sl_height[SL_HEIGHTS] = {0.8, 0.5, 0.25, 0.1};

/* Three or four vertices of t on constraints: a flat tet there is a cap pinned between
 * them (no move reaches it), whose circumcentre lies far off and often beyond a sub-face. */
static int pinned(const tr_sliver_ctx *c, const uint32_t *tv)
{
  int fixed = 0;
  for (int i = 0; i < 4; i++)
    fixed += !c->movable[tv[i]];
  return fixed >= 3;
}

/* Points off the plane of a flat tet's largest face on both sides of its centroid g, at
 * the heights sl_height (a cap over a nearly flat input edge, with one sub-face or none,
 * opens from the side the domain lies on; the cavity's exact tests reject the other
 * side). Returns the number written (2 * SL_HEIGHTS, or 0 for a face flat in doubles). */
static int off_plane(const double *q[4], const double g[3], double out[][3])
{
  int best = -1;
  double area = 0, nrm[3] = {0, 0, 0}, len = 0;
  for (int k = 0; k < 4; k++) {
    double n[3];
    double nn = face_normal(q[tr_face_vtx[k][0]], q[tr_face_vtx[k][1]], q[tr_face_vtx[k][2]], n);
    if (nn > area) {
      area = nn;
      best = k;
      memcpy(nrm, n, sizeof nrm);
    }
  }
  if (best < 0 || !isfinite(area))
    return 0;
  for (int e = 0; e < 6; e++)
    len += dist3(q[tr_edge_vtx[e][0]], q[tr_edge_vtx[e][1]]) / 6;
  int n = 0;
  for (int h = 0; h < SL_HEIGHTS; h++)
    for (int sg = -1; sg <= 1; sg += 2, n++)
      for (int j = 0; j < 3; j++)
        out[n][j] = g[j] + sg * sl_height[h] * len * nrm[j] / area;
  return n;
}

/* Screens candidates [from, to) of t on the doubles: the one whose new tets' smallest
 * angle beats *top (and its cavity) becomes *have. */
static void rank(const tr_sliver_ctx *c, uint32_t t, const double (*cand)[3], int from, int to,
                 trial *z, double *top, int *have)
{
  for (int f = from; f < to; f++)
    if (try_point(c, t, cand[f], 1, *top, z) && z->newmin > *top)
      *top = z->newmin, *have = f;
}

/* Tries the circumcentre of sliver t and points between it and the centroid (when the
 * circumcentre lies beyond a constraint or its cone is worse); the best one that beats
 * its cavity goes in (*done = 1). */
static tr_status insert_at(tr_sliver_ctx *c, uint32_t t, int last, trial *best, trial *z,
                           int *done, uint32_t *gone)
{
  struct tr_mesh *m = c->m;
  *done = 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  const double *q[4];
  for (int i = 0; i < 4; i++)
    q[i] = m->xyz + 3 * (size_t)tv[i];
  double r, w, d[6], cc[3], g[3];
  /* a tet flat in doubles has no circumcentre there, but the points above its sub-faces
   * and off its plane still open it (pinion: a cap over a crease 1e-16 off flat, left at
   * 0 degrees when this returned) */
  const int has_cc = tr_tet_shape(q[0], q[1], q[2], q[3], &r, &w, d, cc);
  for (int j = 0; j < 3; j++)
    g[j] = 0.25 * (q[0][j] + q[1][j] + q[2][j] + q[3][j]);
  /* the candidates: the circumcentre and points between it and the centroid; above each
   * sub-face of t, points at the height of a good tet on that face (a tet with a sub-face
   * whose circumcentre lies outside the domain, e.g. a flat cap over a nearly flat input
   * edge with two sub-faces, is opened from inside) */
  double cand[4 + 4 * SL_HEIGHTS + 2 * SL_HEIGHTS][3];
  int nc = 0;
  static const double frac[] = {1, 0.75, 0.5, 0.25};
  double emax = 0;
  for (int e = 0; e < 6; e++)
    emax = fmax(emax, dist3(q[tr_edge_vtx[e][0]], q[tr_edge_vtx[e][1]]));
  for (int f = 0; f < 4 && has_cc; f++) {
    for (int j = 0; j < 3; j++)
      cand[nc][j] = g[j] + frac[f] * (cc[j] - g[j]);
    /* a point far off a flat tet (its circumcentre, out of a thin slab): SL_FAR */
    double reach = dist3(cand[nc], g);
    nc += reach <= SL_FAR * emax;
  }
  for (int k = 0; k < 4; k++) {
    uint32_t fv[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
    if (!tr_sliver_protected(c, fv, 3))
      continue;
    const double *a = m->xyz + 3 * (size_t)fv[0], *b = m->xyz + 3 * (size_t)fv[1],
                 *e = m->xyz + 3 * (size_t)fv[2];
    double nrm[3], fc[3];
    for (int j = 0; j < 3; j++)
      fc[j] = (a[j] + b[j] + e[j]) / 3;
    const double nn = face_normal(a, b, e, nrm);
    const double len = (dist3(a, b) + dist3(a, e) + dist3(b, e)) / 3;
    if (!(nn > 0) || !isfinite(nn))
      continue;
    /* the side of vertex k (inside the domain) */
    const double *o = m->xyz + 3 * (size_t)tv[k];
    double side = nrm[0] * (o[0] - a[0]) + nrm[1] * (o[1] - a[1]) + nrm[2] * (o[2] - a[2]);
    double sg = side > 0 ? 1 : -1;
    for (int h = 0; h < SL_HEIGHTS; h++, nc++)
      for (int j = 0; j < 3; j++)
        cand[nc][j] = fc[j] + sg * sl_height[h] * len * nrm[j] / nn;
  }
  /* ranked on the doubles, then the best one decided exactly; the points off the plane
   * of a pinned tet only when none of the others opens it or leaves it over
   * SL_OFF_PLANE_ABOVE degrees (each costs a cavity; always: 40% more CPU on joint and
   * pinion; only when none opens it: rotor_small's minimum fell from 1.46 to 0.02) */
  int have = -1;
  double top = -1;
  if (!last)
    rank(c, t, cand, 0, nc, z, &top, &have);
  if ((have < 0 || top < SL_OFF_PLANE_ABOVE) && pinned(c, tv)) {
    int first = nc;
    nc += off_plane(q, g, cand + nc);
    if (!last)
      rank(c, t, cand, first, nc, z, &top, &have);
  }
  /* the last resort (tr_sliver_insert_last): the same candidates with carved cavities,
   * then with cavities that may swallow interior points on no constraint, which leave the
   * mesh (for every tet, carving changed which candidate won elsewhere: pinion's smallest
   * angle fell from 1.02 to 0.000) */
  int carved = 0, swallow = 0;
  if (last) {
    z->carve = carved = 1;
    rank(c, t, cand, 0, nc, z, &top, &have);
    z->carve = 0;
    if (have < 0) {
      carved = 0;
      z->swallow = swallow = 1;
      rank(c, t, cand, 0, nc, z, &top, &have);
      z->swallow = 0;
    }
  }
  best->carve = carved;
  best->swallow = swallow;
  int ok = have >= 0 && try_point(c, t, cand[have], 0, -INFINITY, best);
  best->carve = best->swallow = 0;
  if (!ok)
    return TR_OK;
  if (swallow) { /* the vertices swallowed leave the mesh: nothing moves them again, and
                    the validator expects them in no tet (dup_map); best->cone still holds
                    the cone's vertices (keeps_vertices) */
    for (uint32_t i = 0; i < best->n; i++)
      for (int k = 0; k < 4; k++) {
        uint32_t x = m->tv[4 * (size_t)best->cav[i] + (size_t)k];
        if (!set_has(&best->cone, x)) {
          *gone += c->movable[x]; /* once per vertex: movable until swallowed */
          c->movable[x] = 0;
          if (m->dup_map)
            m->dup_map[x] = TR_NONE;
        }
      }
  }
  uint32_t v, ids[4 * SL_MAX_CAVITY];
  uint32_t region = m->region ? m->region[t] : 0;
  TR_CHECK(tr_mesh_add_vertex(m, best->x, &v));
  TR_CHECK(grow_movable(c, m->nv));
  c->movable[v] = 1; /* strictly inside a cavity no sub-face crosses: on no constraint */
  TR_CHECK(tr_mesh_replace(m, best->cav, best->n, best->newv, best->nf, ids));
  for (uint32_t i = 0; m->region && i < best->nf; i++)
    m->region[ids[i]] = region;
  /* the cone's vertices: every vertex of the cavity's tets but the swallowed ones, which
   * are in no tet now */
  TR_CHECK(tr_sliver_touch(c, best->newv, 4 * (size_t)best->nf));
  *done = 1;
  return TR_OK;
}

tr_status tr_sliver_insert_tet(tr_sliver_ctx *c, uint32_t t, void *scratch, int *done)
{
  trial *z = scratch;
  uint32_t key[4];
  *done = 0;
  memcpy(key, c->m->tv + 4 * (size_t)t, sizeof key);
  for (int i = 1; i < 4; i++) /* sorted: the tet whatever its rotation */
    for (int j = i; j > 0 && key[j - 1] > key[j]; j--) {
      uint32_t x = key[j];
      key[j] = key[j - 1];
      key[j - 1] = x;
    }
  if (tr_vtmap_get(&c->failed, 4, key) != TR_VTMAP_NONE)
    return TR_OK;
  uint32_t gone = 0;
  TR_CHECK(insert_at(c, t, 0, &z[0], &z[1], done, &gone));
  return *done ? TR_OK : tr_vtmap_set(&c->failed, 4, key, 0);
}

tr_status tr_sliver_insert_last(tr_sliver_ctx *c, uint32_t t, void *scratch, int *done,
                                 uint32_t *gone)
{
  trial *z = scratch;
  *done = 0;
  *gone = 0;
  if (!pinned(c, c->m->tv + 4 * (size_t)t))
    return TR_OK;
  return insert_at(c, t, 1, &z[0], &z[1], done, gone);
}

void *tr_sliver_insert_scratch(void)
{
  trial *z = malloc(2 * sizeof *z);
  for (int i = 0; z && i < 2; i++) {
    set_init(&z[i].in);
    set_init(&z[i].cone);
    z[i].carve = z[i].swallow = 0;
  }
  return z;
}

static uint64_t gcd(uint64_t a, uint64_t b)
{
  while (b) {
    uint64_t r = a % b;
    a = b;
    b = r;
  }
  return a;
}

/* The pass visits slot i * step mod n at its i-th step: every slot once (step and n
 * coprime), far from the last one. The store is in Hilbert order (order.c), and slivers
 * worked on one after the other in it, each next to the last one's new point, ended worse
 * than in the order refinement made them: on the quality bench 1.19% of tets under 10
 * degrees in store order against 1.11% before the sort (rotor_small 1.65% against 1.28%);
 * 1.13% in this order. The cache gain of the sort is in the cavities' walks, which this
 * order keeps. */
static uint64_t visit_step(uint32_t n)
{
  uint64_t step = SL_VISIT_STEP;
  while (n > 1 && gcd(step, n) != 1)
    step += 2;
  return step;
}

tr_status tr_sliver_insert_pass(tr_sliver_ctx *c, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  tr_status s = TR_OK;
  void *z = tr_sliver_insert_scratch();
  if (!z)
    return tr_error(TR_ERR_NOMEM, "out of memory for the sliver insertion");
  uint32_t nt = m->nt; /* new tets in slots past nt wait for the next pass (freed slots
                          below it are reused and visited when their turn is still to
                          come: deterministic) */
  const uint64_t step = visit_step(nt);
  for (uint32_t i = 0; i < nt && s == TR_OK && st->points < c->point_budget; i++) {
    const uint32_t t = (uint32_t)((uint64_t)i * step % nt);
    if (!tr_tet_is_real(m, t) || !(tr_sliver_tet_min(c, t, NULL) < c->insert_bound))
      continue;
    int done;
    s = tr_sliver_insert_tet(c, t, z, &done);
    st->points += (uint64_t)done;
  }
  free(z);
  return s;
}
