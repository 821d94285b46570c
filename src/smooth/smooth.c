/* Surface diagonal swaps: see smooth.h for the conditions and the exact incircle.
 *
 * Worklist passes. A pass visits the edges in sorted (min, max) order, as a pass over all
 * edges does (smooth_passes.c, the reference), but only the edges of the triangles around
 * a vertex that the previous pass's swaps used. Any other edge AC, with its triangles
 * ACB and CAD, has none of A, B, C, D used in the previous pass: no triangle holding AC
 * or BD was rewritten then, so its two triangles, its count of triangles and whether BD
 * is an edge are what they were at that pass's start, and that pass examined it (nothing
 * blocked it) and did not swap it; the rule depends on the four points only, so it would
 * not swap now either, and skipping it blocks no other edge. The same swaps happen in the
 * same order and the passes stop at the same one.
 *
 * What the pass needs is kept up to date swap by swap instead of sorted again: the twin
 * of each edge slot (the other slot of an edge with exactly two triangles), the corners
 * around each vertex (doubly linked) and their number. A swap only changes edges with a
 * used vertex, which the pass skips from then on, so live answers equal those of the
 * sorted snapshot the reference takes at the start of the pass. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/edgesort.h"
#include "predicates.h"
#include "quad.h"
#include "smooth.h"

/* An axis along which the normal of abc has a non-zero component, -1 if abc is flat. */
static int normal_axis(const double *a, const double *b, const double *c)
{
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj(a, b, c, k) != 0)
      return k;
  return -1;
}

int tr_coplanar_incircle(const double a[3], const double b[3], const double c[3],
                         const double d[3])
{
  int ax = normal_axis(a, b, c);
  if (ax < 0)
    return 0;
  double x[3] = {a[0], a[1], a[2]};
  /* Any change of coordinate ax alone leaves the plane (the normal has a non-zero
   * component there); stay finite for huge coordinates. */
  x[ax] = a[ax] + (fabs(a[ax]) + 1.0);
  if (!isfinite(x[ax]) || x[ax] == a[ax])
    x[ax] = a[ax] - (fabs(a[ax]) + 1.0);
  if (!isfinite(x[ax]) || x[ax] == a[ax])
    x[ax] = nextafter(a[ax], 0.0);
  int o = tr_sign(tr_orient3d(a, b, c, x));
  int s = tr_sign(tr_insphere(a, b, c, x, d));
  return o * s > 0;
}

/* Strictly convex quadrilateral with diagonals AC and BD: each diagonal separates the
 * other two points strictly, decided in a projection where the quad is not flat. */
static int convex_quad(const double *A, const double *B, const double *C, const double *D)
{
  int ax = normal_axis(A, C, B);
  if (ax < 0)
    return 0;
  int s1 = tr_sign(tr_orient2d_proj(A, C, B, ax)), s2 = tr_sign(tr_orient2d_proj(A, C, D, ax));
  int s3 = tr_sign(tr_orient2d_proj(B, D, A, ax)), s4 = tr_sign(tr_orient2d_proj(B, D, C, ax));
  return s1 * s2 < 0 && s3 * s4 < 0;
}

static inline int flat_convex(const double *A, const double *B, const double *C,
                              const double *D)
{
  return tr_orient3d(A, B, C, D) == 0 && convex_quad(A, B, C, D);
}

int tr_smooth_flat_convex(const double *A, const double *B, const double *C, const double *D)
{
  return flat_convex(A, B, C, D);
}

static int incircle_rule(void *user, const double *const q[4], uint32_t A, uint32_t B,
                         uint32_t C, uint32_t D)
{
  (void)user, (void)A, (void)B, (void)C, (void)D;
  return tr_coplanar_incircle(q[0], q[2], q[1], q[3]);
}

tr_status tr_smooth_surface(struct tr_plc *plc, uint64_t *nswaps)
{
  return tr_smooth_surface_rule(plc, incircle_rule, NULL, nswaps);
}

#define SM_NONE UINT32_MAX

/* An edge to examine: key = (min << 32) | max of its vertices, s = one of its slots. */
typedef struct {
  uint64_t key;
  uint32_t s;
} cand;

typedef struct {
  uint32_t *T;
  const double *X;
  const int32_t *marker;
  tr_swap_rule rule;
  void *user;
  uint32_t *twin;                /* per slot, SM_NONE unless the edge has two triangles */
  uint32_t *head, *next, *prev;  /* corners (= slots) around each vertex, once corners */
  uint32_t *deg;                 /* corners per vertex */
  int corners;                   /* built: at the first swap that passes the predicates */
  uint32_t nv;
  uint8_t *vused;                /* used by a swap of this pass */
  uint32_t *used, nused;         /* those vertices */
  uint32_t *rej, *rejp, *changed; /* as in the reference (smooth_passes.c) */
  uint32_t *stamp, *tl;          /* triangles listed for the next pass */
  uint32_t nt;
  cand *c, *ctmp;
  uint32_t nc;
} sm;

static uint32_t nx(uint32_t s) { return s % 3 == 2 ? s - 2 : s + 1; }
static uint32_t pv(uint32_t s) { return s % 3 == 0 ? s + 2 : s - 1; }

static void link_corner(sm *S, uint32_t c, uint32_t v)
{
  S->next[c] = S->head[v];
  S->prev[c] = SM_NONE;
  if (S->head[v] != SM_NONE)
    S->prev[S->head[v]] = c;
  S->head[v] = c;
  S->deg[v]++;
}

static void unlink_corner(sm *S, uint32_t c, uint32_t v)
{
  if (S->prev[c] != SM_NONE)
    S->next[S->prev[c]] = S->next[c];
  else
    S->head[v] = S->next[c];
  if (S->next[c] != SM_NONE)
    S->prev[S->next[c]] = S->prev[c];
  S->deg[v]--;
}

/* The corner lists, built on first need: a pass that swaps nothing (most surfaces' only
 * pass) never needs them. */
static void build_corners(sm *S, uint32_t ne)
{
  if (S->corners)
    return;
  for (uint32_t v = 0; v < S->nv; v++) {
    S->head[v] = SM_NONE;
    S->deg[v] = 0;
  }
  for (uint32_t c = ne; c-- > 0;)
    link_corner(S, c, S->T[c]);
  S->corners = 1;
}

/* BD is an edge iff a triangle around the vertex of fewer corners holds the other. */
static int has_edge(const sm *S, uint32_t B, uint32_t D)
{
  uint32_t v = S->deg[B] <= S->deg[D] ? B : D, w = v == B ? D : B;
  for (uint32_t c = S->head[v]; c != SM_NONE; c = S->next[c]) {
    const uint32_t *t = S->T + 3 * (size_t)(c / 3);
    if (t[0] == w || t[1] == w || t[2] == w)
      return 1;
  }
  return 0;
}

/* The swap of the reference, with twins and corners brought up to date. s1 = A->C in
 * t1 = (A, C, B), s2 = C->A in t2 = (C, A, D). */
static void swap(sm *S, uint32_t s1, uint32_t s2, uint32_t pass)
{
  uint32_t *T = S->T, t1 = s1 / 3, t2 = s2 / 3;
  uint32_t A = T[s1], C = T[nx(s1)], B = T[pv(s1)], D = T[pv(s2)];
  /* the four sides: their slots before and after (new t1 = (B, A, D), t2 = (D, C, B)) */
  uint32_t was[4] = {pv(s1), nx(s1), nx(s2), pv(s2)}; /* B->A, C->B, A->D, D->C */
  uint32_t now[4] = {3 * t1, 3 * t2 + 1, 3 * t1 + 1, 3 * t2};
  uint32_t tw[4];
  for (int i = 0; i < 4; i++)
    tw[i] = S->twin[was[i]]; /* never in t1 or t2: the quad's four vertices are distinct */
  const uint32_t nv1[3] = {B, A, D}, nv2[3] = {D, C, B};
  for (int k = 0; k < 3; k++) {
    uint32_t c = 3 * t1 + (uint32_t)k;
    unlink_corner(S, c, T[c]);
    link_corner(S, c, T[c] = nv1[k]);
    c = 3 * t2 + (uint32_t)k;
    unlink_corner(S, c, T[c]);
    link_corner(S, c, T[c] = nv2[k]);
  }
  for (int i = 0; i < 4; i++) {
    S->twin[now[i]] = tw[i];
    if (tw[i] != SM_NONE)
      S->twin[tw[i]] = now[i];
  }
  S->twin[3 * t1 + 2] = 3 * t2 + 2; /* D->B and B->D */
  S->twin[3 * t2 + 2] = 3 * t1 + 2;
  S->vused[A] = S->vused[B] = S->vused[C] = S->vused[D] = 1;
  S->used[S->nused++] = A;
  S->used[S->nused++] = B;
  S->used[S->nused++] = C;
  S->used[S->nused++] = D;
  S->changed[t1] = S->changed[t2] = pass + 1;
}

/* The quad of an edge with exactly two triangles (s: one of its slots), if it passes the
 * reference's checks that need no predicate and no vertex mark: t1 = (A, C, B) holds
 * s1 = A->C, t2 = (C, A, D) holds s2 = C->A, one marker, and no remembered refusal. */
typedef struct {
  uint32_t s1, s2, A, B, C, D;
} quad;

static inline int open_quad(const sm *S, uint32_t s, quad *Q)
{
  const uint32_t *T = S->T;
  uint32_t o = S->twin[s];
  if (o == SM_NONE)
    return 0; /* rewritten by this pass: the reference finds a used vertex */
  uint32_t s1 = s < o ? s : o, s2 = s < o ? o : s, t1 = s1 / 3, t2 = s2 / 3;
  uint32_t A = T[s1], C = T[nx(s1)], B = T[pv(s1)];
  uint32_t p = T[s2], q = T[nx(s2)], D = T[pv(s2)];
  if (p != C || q != A || B == D)
    return 0; /* inconsistent orientation: leave it alone */
  if (S->marker && S->marker[t1] != S->marker[t2])
    return 0;
  const uint32_t *rej = S->rej, *changed = S->changed;
  if (rej[s1] && S->rejp[s1] == s2 && changed[t1] < rej[s1] && changed[t2] < rej[s1])
    return 0;
  *Q = (quad){s1, s2, A, B, C, D};
  return 1;
}

/* The reference's examination of one edge; 1 if it swapped. */
static int examine(sm *S, uint32_t s, uint32_t pass)
{
  quad Q;
  if (!open_quad(S, s, &Q))
    return 0;
  uint32_t A = Q.A, B = Q.B, C = Q.C, D = Q.D;
  if (S->vused[A] || S->vused[B] || S->vused[C] || S->vused[D])
    return 0;
  const double *X = S->X, *pa = X + 3 * (size_t)A, *pb = X + 3 * (size_t)B,
               *pc = X + 3 * (size_t)C, *pd = X + 3 * (size_t)D;
  const double *const q4[4] = {pa, pb, pc, pd};
  if (!flat_convex(pa, pb, pc, pd) || !S->rule(S->user, q4, A, B, C, D)) {
    S->rej[Q.s1] = pass + 1;
    S->rejp[Q.s1] = Q.s2;
    return 0;
  }
  build_corners(S, 3 * S->nt);
  if (has_edge(S, B, D))
    return 0;
  swap(S, Q.s1, Q.s2, pass);
  return 1;
}

/* Candidates in key order (keys are distinct): insertion sort of short runs, then
 * bottom-up merges. */
static void sort_cands(cand *c, cand *tmp, uint32_t n)
{
  const uint32_t run = 16;
  for (uint32_t lo = 0; lo < n; lo += run) {
    uint32_t hi = lo + run < n ? lo + run : n;
    for (uint32_t i = lo + 1; i < hi; i++) {
      cand x = c[i];
      uint32_t j = i;
      for (; j > lo && c[j - 1].key > x.key; j--)
        c[j] = c[j - 1];
      c[j] = x;
    }
  }
  cand *src = c, *dst = tmp;
  for (uint32_t w = run; w < n; w *= 2) {
    for (uint32_t lo = 0; lo < n; lo += 2 * w) {
      uint32_t mid = lo + w < n ? lo + w : n, hi = lo + 2 * w < n ? lo + 2 * w : n;
      uint32_t i = lo, j = mid, k = lo;
      while (i < mid && j < hi)
        dst[k++] = src[i].key < src[j].key ? src[i++] : src[j++];
      while (i < mid)
        dst[k++] = src[i++];
      while (j < hi)
        dst[k++] = src[j++];
    }
    cand *x = src;
    src = dst;
    dst = x;
  }
  if (src != c)
    memcpy(c, src, sizeof *c * n);
}

static cand mkcand(const uint32_t *T, uint32_t s)
{
  uint32_t a = T[s], b = T[nx(s)];
  cand x = {a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a, s};
  return x;
}

/* The next pass's edges: those of the triangles around the vertices this pass used,
 * each edge once, less those open_quad turns down (it would turn them down during the
 * pass too: a triangle rewritten before their turn gives them a used vertex); clears the
 * marks of those vertices. */
static void next_cands(sm *S, uint32_t pass)
{
  uint32_t ntl = 0, mark = pass + 1;
  for (uint32_t i = 0; i < S->nused; i++) {
    uint32_t u = S->used[i];
    S->vused[u] = 0;
    for (uint32_t c = S->head[u]; c != SM_NONE; c = S->next[c])
      if (S->stamp[c / 3] != mark) {
        S->stamp[c / 3] = mark;
        S->tl[ntl++] = c / 3;
      }
  }
  S->nused = 0;
  S->nc = 0;
  for (uint32_t i = 0; i < ntl; i++)
    for (uint32_t s = 3 * S->tl[i]; s < 3 * S->tl[i] + 3; s++) {
      uint32_t o = S->twin[s];
      quad Q;
      if (o != SM_NONE && !(o < s && S->stamp[o / 3] == mark) && open_quad(S, s, &Q))
        S->c[S->nc++] = mkcand(S->T, s);
    }
  sort_cands(S->c, S->ctmp, S->nc);
}

tr_status tr_smooth_surface_rule(struct tr_plc *plc, tr_swap_rule rule, void *user,
                                 uint64_t *nswaps)
{
  *nswaps = 0;
  uint32_t nt = plc->ntris, ne = 3 * nt, nv = plc->npoints;
  if (nt < 2)
    return TR_OK;
  sm S = {.T = plc->tris, .X = plc->xyz, .marker = plc->tri_marker, .rule = rule, .user = user,
          .nv = nv, .nt = nt};
  size_t nv1 = nv ? nv : 1;
  uint32_t *slots = malloc(sizeof *slots * ne);
  S.twin = malloc(sizeof *S.twin * ne);
  S.head = malloc(sizeof *S.head * nv1);
  S.next = malloc(sizeof *S.next * ne);
  S.prev = malloc(sizeof *S.prev * ne);
  S.deg = malloc(sizeof *S.deg * nv1);
  S.vused = calloc(nv1, 1);
  S.used = malloc(sizeof *S.used * nv1);
  S.rej = calloc(ne, sizeof *S.rej);
  S.rejp = malloc(sizeof *S.rejp * ne);
  S.changed = calloc(nt, sizeof *S.changed);
  S.stamp = calloc(nt, sizeof *S.stamp);
  S.tl = malloc(sizeof *S.tl * nt);
  /* an edge with two triangles has two slots: at most ne / 2 candidates */
  S.c = malloc(sizeof *S.c * (ne / 2 + 1));
  S.ctmp = malloc(sizeof *S.ctmp * (ne / 2 + 1));
  tr_status st = TR_OK;
  if (!slots || !S.twin || !S.head || !S.next || !S.prev || !S.deg || !S.vused || !S.used ||
      !S.rej || !S.rejp || !S.changed || !S.stamp || !S.tl || !S.c || !S.ctmp) {
    st = tr_error(TR_ERR_NOMEM, "out of memory smoothing %u triangles", nt);
    goto done;
  }
  /* the first pass examines every edge with two triangles, in the sorted order */
  if ((st = tr_edge_slots_sorted(S.T, nt, nv, slots)) != TR_OK)
    goto done;
  for (uint32_t i = 0; i < ne; i++)
    S.twin[i] = SM_NONE;
  cand x = mkcand(S.T, slots[0]);
  for (uint32_t i = 0; i < ne;) {
    cand y = x;
    uint32_t j = i + 1;
    while (j < ne && (y = mkcand(S.T, slots[j])).key == x.key)
      j++;
    if (j - i == 2) {
      S.twin[slots[i]] = slots[i + 1];
      S.twin[slots[i + 1]] = slots[i];
      S.c[S.nc++] = x;
    }
    x = y;
    i = j;
  }
  free(slots);
  slots = NULL;
  for (uint32_t pass = 0; pass < TR_SMOOTH_MAX_PASSES; pass++) {
    if (pass > 0)
      next_cands(&S, pass);
    uint64_t done = 0;
    for (uint32_t i = 0; i < S.nc; i++)
      done += (uint64_t)examine(&S, S.c[i].s, pass);
    *nswaps += done;
    if (!done)
      break;
  }
done:
  free(slots);
  free(S.twin);
  free(S.head);
  free(S.next);
  free(S.prev);
  free(S.deg);
  free(S.vused);
  free(S.used);
  free(S.rej);
  free(S.rejp);
  free(S.changed);
  free(S.stamp);
  free(S.tl);
  free(S.c);
  free(S.ctmp);
  return st;
}
