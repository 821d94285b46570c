/* The exact constrained Delaunay triangulation of the points and cuts on one triangle.
 *
 * Why Delaunay and not any triangulation: two coplanar input triangles that overlap carry
 * the same points and cuts in their common region, bounded by cuts on both, and must
 * triangulate it into identical pieces (which then merge). The constrained Delaunay
 * triangulation of a region depends only on the region's points and constraints; with
 * cocircular points broken by a symbolic lift in a global order (prio), it is unique.
 * So both triangles produce it, whatever else each carries outside the region.
 *
 * Steps: points inserted one by one into the triangle (1-to-3 or edge 2-to-4 splits)
 * with Lawson flips, each constraint then forced in by flips of the edges that cross it
 * (Sloan 1993: a crossing edge whose quadrilateral is convex is flipped; the others wait
 * their turn, which terminates), and Lawson flips of the unconstrained edges to the
 * constrained Delaunay triangulation. Every test is exact: orient2d in the frame and the
 * perturbed incircle. The sizes are those of one triangle's cuts: scans over all its
 * triangles stand in for point location and edge lookup. */
#include <stdlib.h>
#include <string.h>

#include "predicates.h"
#include "resolve/resolve_impl.h"

#define NONE UINT32_MAX

typedef struct {
  uint32_t v[3];  /* counterclockwise in the frame */
  uint32_t nb[3]; /* across the edge opposite v[i] (v[i+1], v[i+2]); NONE: the hull */
  uint8_t con;    /* bit i: the edge opposite v[i] is a constraint */
} ctri;

struct rs_cdt {
  ctri *t;
  size_t nt, ct;
  const tr_point *pts;
  const uint32_t *prio;
  int drop, sgn;
  uint32_t *q; /* the queue of edges crossing a constraint, 2 vertices each */
  size_t cq;
  uint32_t *out;
  size_t cout;
  uint32_t *st; /* the stack of the Lawson flips after an insertion */
  size_t cst;
  uint32_t *lw; /* the stack of the final Lawson flips: edges, 2 points each */
  size_t clw;
  uint32_t *vt; /* a triangle holding each point, kept by set_tri */
  size_t cvt;
  uint32_t last; /* where the last point location ended */
};

tr_status rs_cdt_create(rs_cdt **c)
{
  if (!(*c = calloc(1, sizeof **c)))
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory");
  return TR_OK;
}

void rs_cdt_destroy(rs_cdt *c)
{
  if (!c)
    return;
  free(c->t);
  free(c->q);
  free(c->out);
  free(c->st);
  free(c->vt);
  free(c->lw);
  free(c);
}

static int o2(const rs_cdt *c, uint32_t a, uint32_t b, uint32_t d)
{
  return c->sgn * tr_orient2d_proj_p(c->pts + a, c->pts + b, c->pts + d, c->drop);
}

/* Exact sign of incircle(a, b, c, d) in the frame (> 0: d inside the circle of the
 * counterclockwise a, b, c), before perturbation. */
static int incircle_exact(const rs_cdt *c, uint32_t a, uint32_t b, uint32_t cc, uint32_t d)
{
  return c->sgn * tr_incircle_proj_p(c->pts + a, c->pts + b, c->pts + cc, c->pts + d, c->drop);
}

/* incircle with the lift of point i raised by eps^(rank of i), the least prio first:
 * the derivative of the determinant by the lift of a is orient2d(d, b, c), of b
 * orient2d(d, c, a), of c orient2d(d, a, b), of d -orient2d(a, b, c) (nonzero), so the
 * first nonzero of those in prio order is the sign. */
static int incircle(rs_cdt *c, uint32_t a, uint32_t b, uint32_t cc, uint32_t d)
{
  int s = incircle_exact(c, a, b, cc, d);
  if (s)
    return s;
  uint32_t w[4] = {a, b, cc, d};
  int done[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; k++) {
    int i = -1;
    for (int j = 0; j < 4; j++)
      if (!done[j] && (i < 0 || c->prio[w[j]] < c->prio[w[i]]))
        i = j;
    done[i] = 1;
    switch (i) {
    case 0: s = o2(c, d, b, cc); break;
    case 1: s = o2(c, d, cc, a); break;
    case 2: s = o2(c, d, a, b); break;
    default: s = -o2(c, a, b, cc); break;
    }
    if (s)
      return s;
  }
  return 0;
}

/* The index of the edge (a, b) (either way) in triangle t, or -1. */
static int edge_in(const ctri *t, uint32_t a, uint32_t b)
{
  for (int i = 0; i < 3; i++) {
    uint32_t x = t->v[(i + 1) % 3], y = t->v[(i + 2) % 3];
    if ((x == a && y == b) || (x == b && y == a))
      return i;
  }
  return -1;
}

/* t's edge i faces triangle n (NONE: the hull); n's matching edge faces t back. */
static void link(rs_cdt *c, uint32_t t, int i, uint32_t n)
{
  c->t[t].nb[i] = n;
  if (n != NONE) {
    int j = edge_in(c->t + n, c->t[t].v[(i + 1) % 3], c->t[t].v[(i + 2) % 3]);
    c->t[n].nb[j] = t;
  }
}

static void set_tri(rs_cdt *c, uint32_t t, uint32_t a, uint32_t b, uint32_t d, uint8_t con)
{
  c->t[t].v[0] = a;
  c->t[t].v[1] = b;
  c->t[t].v[2] = d;
  c->t[t].con = con;
  c->vt[a] = c->vt[b] = c->vt[d] = t;
}

static tr_status new_tri(rs_cdt *c, uint32_t *id)
{
  TR_CHECK(rs_grow((void **)&c->t, sizeof *c->t, c->nt + 1, &c->ct));
  *id = (uint32_t)c->nt++;
  memset(c->t + *id, 0xff, sizeof c->t[*id]);
  c->t[*id].con = 0;
  return TR_OK;
}

/* The bit of t's edge i. */
static uint8_t cbit(const ctri *t, int i) { return (uint8_t)(t->con >> i & 1); }

/* Rotates t so that v[0] is its vertex at index i. */
static void rotate(ctri *t, int i)
{
  ctri r = *t;
  r.con = 0;
  for (int k = 0; k < 3; k++) {
    r.v[k] = t->v[(k + i) % 3];
    r.nb[k] = t->nb[(k + i) % 3];
    r.con |= (uint8_t)(cbit(t, (k + i) % 3) << k);
  }
  *t = r;
}

/* Flips the edge opposite v[i] of t: t = (p, u, v), n = (q, v, u) become (p, u, q) and
 * (q, v, p). The quadrilateral must be strictly convex. */
static void flip(rs_cdt *c, uint32_t t, int i)
{
  rotate(c->t + t, i);
  uint32_t n = c->t[t].nb[0];
  rotate(c->t + n, edge_in(c->t + n, c->t[t].v[1], c->t[t].v[2]));
  ctri T = c->t[t], N = c->t[n];
  uint32_t p = T.v[0], u = T.v[1], v = T.v[2], q = N.v[0];
  /* outer edges: T's (v, p) at index 1 and (p, u) at 2; N's (u, q) at 1, (q, v) at 2 */
  set_tri(c, t, p, u, q, (uint8_t)(cbit(&N, 1) << 0 | cbit(&T, 2) << 2));
  set_tri(c, n, q, v, p, (uint8_t)(cbit(&T, 1) << 0 | cbit(&N, 2) << 2));
  link(c, t, 0, N.nb[1]);
  link(c, t, 2, T.nb[2]);
  link(c, n, 0, T.nb[1]);
  link(c, n, 2, N.nb[2]);
  link(c, t, 1, n);
}

/* Lawson flips after inserting p: stack of triangles whose edge opposite p is checked. */
static tr_status legalize(rs_cdt *c, uint32_t p, size_t ns)
{
  while (ns) {
    uint32_t t = c->st[--ns];
    int i = c->t[t].v[0] == p ? 0 : c->t[t].v[1] == p ? 1 : 2;
    uint32_t n = c->t[t].nb[i];
    if (n == NONE || cbit(c->t + t, i))
      continue;
    const ctri *T = c->t + t, *N = c->t + n;
    uint32_t q = N->v[edge_in(N, T->v[(i + 1) % 3], T->v[(i + 2) % 3])];
    if (incircle(c, T->v[0], T->v[1], T->v[2], q) <= 0)
      continue;
    flip(c, t, i); /* t = (p, u, q), n = (q, v, p): their edges opposite p */
    TR_CHECK(rs_grow((void **)&c->st, sizeof *c->st, ns + 2, &c->cst));
    c->st[ns++] = t;
    c->st[ns++] = n;
  }
  return TR_OK;
}

/* Triangle k holds p (closed): 1, with *zero = the edge p lies on or -1; 0 if not, with
 * *out = an edge p lies strictly beyond. -1: p is a corner of k. */
static int holds(const rs_cdt *c, uint32_t k, uint32_t p, int *zero, int *out)
{
  const ctri *T = c->t + k;
  int nz = 0;
  *zero = *out = -1;
  for (int i = 0; i < 3; i++) {
    int s = o2(c, T->v[(i + 1) % 3], T->v[(i + 2) % 3], p);
    if (s < 0) {
      *out = i;
      return 0;
    }
    if (!s)
      nz++, *zero = i;
  }
  return nz >= 2 ? -1 : 1;
}

static tr_status insert(rs_cdt *c, uint32_t p)
{
  uint32_t t = NONE;
  int zero = -1, out, h = 0;
  /* a visibility walk from the last triangle found (it ends in a Delaunay triangulation);
   * a scan of every triangle if it takes too long */
  uint32_t k = c->last < c->nt ? c->last : 0;
  for (size_t steps = 0; steps < 4 * c->nt + 16 && k != NONE; steps++) {
    if ((h = holds(c, k, p, &zero, &out)) != 0) {
      t = k;
      break;
    }
    k = c->t[k].nb[out];
  }
  for (size_t j = 0; j < c->nt && t == NONE; j++)
    if ((h = holds(c, (uint32_t)j, p, &zero, &out)) != 0)
      t = (uint32_t)j;
  if (h < 0)
    return tr_error(TR_ERR_INTERNAL, "arrangement: a point repeated in a triangulation");
  c->last = t;
  if (t == NONE)
    return tr_error(TR_ERR_INTERNAL, "arrangement: a point outside its triangle");
  size_t ns = 0;
  TR_CHECK(rs_grow((void **)&c->st, sizeof *c->st, 4, &c->cst));
  if (zero < 0) { /* 1 -> 3 */
    uint32_t t1, t2;
    TR_CHECK(new_tri(c, &t1));
    TR_CHECK(new_tri(c, &t2));
    ctri T = c->t[t];
    uint32_t a = T.v[0], b = T.v[1], d = T.v[2];
    set_tri(c, t, p, b, d, cbit(&T, 0));
    set_tri(c, t1, a, p, d, (uint8_t)(cbit(&T, 1) << 1));
    set_tri(c, t2, a, b, p, (uint8_t)(cbit(&T, 2) << 2));
    link(c, t, 0, T.nb[0]);
    link(c, t1, 1, T.nb[1]);
    link(c, t2, 2, T.nb[2]);
    link(c, t, 1, t1);
    link(c, t, 2, t2);
    link(c, t1, 2, t2);
    c->st[ns++] = t;
    c->st[ns++] = t1;
    c->st[ns++] = t2;
    return legalize(c, p, ns);
  }
  /* on the edge (b, d) of t = (a, b, d); n = (e, d, b) across it, if any */
  rotate(c->t + t, zero);
  ctri T = c->t[t];
  uint32_t a = T.v[0], b = T.v[1], d = T.v[2], n = T.nb[0], t1, n1 = NONE;
  TR_CHECK(new_tri(c, &t1));
  if (n != NONE)
    TR_CHECK(new_tri(c, &n1));
  uint8_t cb = cbit(&T, 0);
  set_tri(c, t, a, b, p, (uint8_t)(cbit(&T, 2) << 2 | cb << 0));
  set_tri(c, t1, a, p, d, (uint8_t)(cbit(&T, 1) << 1 | cb << 0));
  link(c, t, 2, T.nb[2]);
  link(c, t1, 1, T.nb[1]);
  link(c, t, 1, t1);
  c->st[ns++] = t;
  c->st[ns++] = t1;
  if (n == NONE) {
    c->t[t].nb[0] = c->t[t1].nb[0] = NONE;
    return legalize(c, p, ns);
  }
  rotate(c->t + n, edge_in(c->t + n, b, d));
  ctri N = c->t[n];
  uint32_t e = N.v[0];
  set_tri(c, n, e, d, p, (uint8_t)(cbit(&N, 2) << 2 | cb << 0));
  set_tri(c, n1, e, p, b, (uint8_t)(cbit(&N, 1) << 1 | cb << 0));
  link(c, n, 2, N.nb[2]);
  link(c, n1, 1, N.nb[1]);
  link(c, n, 1, n1);
  link(c, t, 0, n1);
  link(c, t1, 0, n);
  c->st[ns++] = n;
  c->st[ns++] = n1;
  return legalize(c, p, ns);
}

/* The open segments ab and uv cross at a point inside both. */
static int crosses(const rs_cdt *c, uint32_t a, uint32_t b, uint32_t u, uint32_t v)
{
  if (u == a || u == b || v == a || v == b)
    return 0;
  return o2(c, a, b, u) * o2(c, a, b, v) < 0 && o2(c, u, v, a) * o2(c, u, v, b) < 0;
}

/* The triangle holding edge (u, v) and the edge's index, or NONE: a turn around u. */
static uint32_t find_edge(const rs_cdt *c, uint32_t u, uint32_t v, int *e)
{
  uint32_t t0 = c->vt[u];
  for (int dir = 0; dir < 2; dir++) {
    uint32_t t = t0;
    do {
      const ctri *T = c->t + t;
      if ((*e = edge_in(T, u, v)) >= 0)
        return t;
      int i = T->v[0] == u ? 0 : T->v[1] == u ? 1 : 2;
      t = T->nb[dir ? (i + 1) % 3 : (i + 2) % 3];
    } while (t != NONE && t != t0);
    if (t == t0)
      break; /* a full turn: u is inside */
  }
  return NONE;
}

/* Queues the edges crossing the open segment ab, walking from a to b (no point lies
 * inside ab and no constraint crosses it). *tail = their number. */
static tr_status crossing_edges(rs_cdt *c, uint32_t a, uint32_t b, size_t *tail, size_t *cap)
{
  /* the triangle (a, x, y) of a's star whose wedge holds b */
  uint32_t t0 = c->vt[a], t = NONE, l = NONE, r = NONE;
  for (int dir = 0; dir < 2 && t == NONE; dir++) {
    uint32_t k = t0;
    do {
      const ctri *T = c->t + k;
      int i = T->v[0] == a ? 0 : T->v[1] == a ? 1 : 2;
      uint32_t x = T->v[(i + 1) % 3], y = T->v[(i + 2) % 3];
      if (o2(c, a, x, b) > 0 && o2(c, a, y, b) < 0) {
        t = k, r = x, l = y;
        break;
      }
      k = T->nb[dir ? (i + 1) % 3 : (i + 2) % 3];
    } while (k != NONE && k != t0);
    if (k == t0)
      break;
  }
  if (t == NONE)
    return tr_error(TR_ERR_INTERNAL, "arrangement: a constraint leaves its triangle");
  *tail = 0;
  for (;;) {
    TR_CHECK(rs_grow((void **)&c->q, 2 * sizeof *c->q, *tail + 1, cap));
    c->q[2 * *tail] = l;
    c->q[2 * (*tail)++ + 1] = r;
    const ctri *T = c->t + t;
    uint32_t n = T->nb[edge_in(T, l, r)];
    if (n == NONE)
      return tr_error(TR_ERR_INTERNAL, "arrangement: a constraint leaves its triangle");
    const ctri *N = c->t + n;
    uint32_t z = N->v[edge_in(N, l, r)];
    if (z == b)
      return TR_OK;
    int s = o2(c, a, b, z);
    if (!s)
      return tr_error(TR_ERR_INTERNAL, "arrangement: a point inside a constraint");
    if (s > 0)
      l = z;
    else
      r = z;
    t = n;
  }
}

static tr_status constrain(rs_cdt *c, uint32_t a, uint32_t b)
{
  size_t head = 0, tail = 0, cap = c->cq / 2, steps = 0;
  int e0;
  if (find_edge(c, a, b, &e0) == NONE)
    TR_CHECK(crossing_edges(c, a, b, &tail, &cap));
  c->cq = 2 * cap;
  /* a queue in the array: taken at head, put back at tail; compacted when full */
  size_t limit = 64 + 16 * c->nt * c->nt;
  while (head < tail) {
    if (++steps > limit)
      return tr_error(TR_ERR_INTERNAL, "arrangement: constraint insertion does not end");
    uint32_t u = c->q[2 * head], v = c->q[2 * head + 1];
    head++;
    int i;
    uint32_t t = find_edge(c, u, v, &i);
    if (t == NONE)
      return tr_error(TR_ERR_INTERNAL, "arrangement: a crossing edge vanished");
    const ctri *T = c->t + t, *N = c->t + T->nb[i];
    uint32_t p = T->v[i], q = N->v[edge_in(N, u, v)];
    int su = o2(c, p, q, u), sv = o2(c, p, q, v);
    if (su * sv < 0) {
      flip(c, t, i);
      if (crosses(c, a, b, p, q))
        u = p, v = q;
      else
        continue;
    }
    if (tail * 2 + 2 > c->cq) { /* compact */
      memmove(c->q, c->q + 2 * head, 2 * (tail - head) * sizeof *c->q);
      tail -= head;
      head = 0;
      cap = c->cq / 2;
      TR_CHECK(rs_grow((void **)&c->q, 2 * sizeof *c->q, tail + 1, &cap));
      c->cq = 2 * cap;
    }
    c->q[2 * tail] = u;
    c->q[2 * tail++ + 1] = v;
  }
  int i;
  uint32_t t = find_edge(c, a, b, &i);
  if (t == NONE)
    return tr_error(TR_ERR_INTERNAL, "arrangement: a constraint missing after its flips");
  c->t[t].con |= (uint8_t)(1u << i);
  uint32_t n = c->t[t].nb[i];
  if (n != NONE)
    c->t[n].con |= (uint8_t)(1u << edge_in(c->t + n, a, b));
  return TR_OK;
}

/* Lawson flips of unconstrained edges until every one is locally Delaunay: every edge
 * checked once, and the four outer edges of each flip again (the stack holds edges by
 * their points, looked up when taken: flips move edges between triangles). */
static tr_status lawson(rs_cdt *c)
{
  size_t ns = 0, limit = 64 + 16 * c->nt * c->nt, steps = 0;
  for (size_t k = 0; k < c->nt; k++)
    for (int i = 0; i < 3; i++) {
      const ctri *T = c->t + k;
      if (T->nb[i] == NONE || T->nb[i] < k || cbit(T, i))
        continue;
      TR_CHECK(rs_grow((void **)&c->lw, 2 * sizeof *c->lw, ns + 1, &c->clw));
      c->lw[2 * ns] = T->v[(i + 1) % 3];
      c->lw[2 * ns++ + 1] = T->v[(i + 2) % 3];
    }
  while (ns) {
    ns--;
    uint32_t u = c->lw[2 * ns], v = c->lw[2 * ns + 1];
    int i;
    uint32_t k = find_edge(c, u, v, &i);
    if (k == NONE)
      continue; /* flipped away */
    const ctri *T = c->t + k;
    uint32_t n = T->nb[i];
    if (n == NONE || cbit(T, i))
      continue;
    const ctri *N = c->t + n;
    uint32_t p = T->v[i], q = N->v[edge_in(N, u, v)];
    if (incircle(c, T->v[0], T->v[1], T->v[2], q) <= 0)
      continue;
    if (++steps > limit)
      return tr_error(TR_ERR_INTERNAL, "arrangement: Lawson flips do not end");
    flip(c, k, i);
    TR_CHECK(rs_grow((void **)&c->lw, 2 * sizeof *c->lw, ns + 4, &c->clw));
    uint32_t w[4][2] = {{u, q}, {p, u}, {v, p}, {q, v}};
    for (int j = 0; j < 4; j++) {
      c->lw[2 * ns] = w[j][0];
      c->lw[2 * ns++ + 1] = w[j][1];
    }
  }
  return TR_OK;
}

tr_status rs_cdt_run(rs_cdt *c, const tr_point *pts, const uint32_t *prio, uint32_t n,
                     int drop, int sgn, const uint32_t *segs, uint32_t nsegs,
                     const uint32_t **tris, uint32_t *ntris)
{
  c->pts = pts;
  c->prio = prio;
  c->drop = drop;
  c->sgn = sgn;
  c->nt = 0;
  c->last = 0;
  TR_CHECK(rs_grow((void **)&c->vt, sizeof *c->vt, n, &c->cvt));
  uint32_t t0;
  TR_CHECK(new_tri(c, &t0));
  set_tri(c, t0, 0, 1, 2, 0);
  for (uint32_t p = 3; p < n; p++)
    TR_CHECK(insert(c, p));
  for (uint32_t k = 0; k < nsegs; k++)
    TR_CHECK(constrain(c, segs[2 * k], segs[2 * k + 1]));
  TR_CHECK(lawson(c));
  TR_CHECK(rs_grow((void **)&c->out, 3 * sizeof *c->out, c->nt, &c->cout));
  for (size_t k = 0; k < c->nt; k++)
    memcpy(c->out + 3 * k, c->t[k].v, 3 * sizeof *c->out);
  *tris = c->out;
  *ntris = (uint32_t)c->nt;
  return TR_OK;
}
