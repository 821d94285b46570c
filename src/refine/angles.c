/* Small input angles (refine.h, termination). Delaunay refinement ends when the input's
 * segments and facets meet at no less than 90 degrees (Shewchuk 1998); where two of them
 * meet at an input vertex V under a small angle, a point on one encroaches pieces of the
 * other near V, whose split points encroach the first again, one level closer to V each
 * time, without end. The rules here stop that descent: a piece near V is not split for a
 * vertex on a constraint that meets the piece's constraint at V under less than 60
 * degrees, and a bad tet whose shortest edge joins two such constraints is left as it is.
 *
 * Wedge grading relaxes both rules between two input edges meeting at V under an angle
 * of 3 degrees or more, for the bad tets that refinement leaves so (refine.c: exempt with
 * a dihedral angle under 10 degrees, or with a circumcentre it cannot use): a piece [x, y]
 * of one edge (x, y its ends' distances from V) that a vertex of the tet on the other
 * encroaches is split when it does not end at V and y - x > x / 4 (rf_wedge_split).
 * Both edges are then split at radii a step of at most about 1.25 apart where the tets
 * between them are bad, so the sub-faces spanning the
 * wedge there are no longer caps with their small corners at split points, which every
 * tet standing on them inherits (rotor_small.off: 0.63% of tets under 10 degrees -> 0.46%).
 * It cannot descend: the piece at V is never split by it, so its points lie beyond the
 * innermost point of their edge, each piece it makes is longer than x / 16 (the split
 * point is within a quarter of the middle), and an edge of length L whose innermost point
 * is at r gets at most about ln(L / r) / ln(1 + 1/16) of them.
 *
 * Angles are measured in doubles on the input's vertices: they choose which points are
 * inserted, never how the mesh is connected, so they need no exactness (and doubles are
 * deterministic). */
#include <math.h>

#include "predicates.h"

#include "refine/refine_impl.h"

#define RF_SMALL_COS 0.5 /* cos 60 degrees */
#define RF_SHARP_COS 0.8660254037844386 /* cos 30 degrees: a triangle's own corner */
/* wedge grading (rf_wedge_split): a piece is split across a wedge only while longer than
 * this fraction of its near end's distance from the wedge's vertex, and only where the
 * wedge is at least 3 degrees wide (under that, pieces of that length still span
 * needles, so the points would buy nothing: joint.off's 0.66-degree fan lost its
 * smallest-angle target to them) */
#define RF_WEDGE_STEP 0.25
#define RF_WEDGE_MIN_COS 0.9986295347545738 /* cos 3 degrees */

typedef struct {
  int kind;     /* RF_SEG or RF_FACET, 0: none */
  uint32_t v[3]; /* input vertex ids: 2 for a segment, 3 for a triangle */
  uint32_t tri; /* RF_FACET: the input triangle (of a merged facet: the one near the point
                   in question) */
  uint32_t cl;  /* its cap cluster (capcluster.c), TR_NONE: none; an input vertex (kind
                   0, v[0] the vertex) has one when it is a corner of a cap */
} element;

/* The triangle of facet g whose projection holds p (doubles: a choice of which corner
 * angles to measure, like every measure here), else g's first. */
static uint32_t facet_tri_at(const rf_ctx *c, uint32_t g, const double *p)
{
  const tr_facets *F = &c->fc;
  if (tr_facets_size(F, g) == 1 || !p)
    return g;
  const uint32_t *G = c->plc->tris + 3 * (size_t)g;
  const double *xyz = c->plc->xyz;
  int k = 0;
  for (; k < 3; k++)
    if (tr_orient2d_proj(xyz + 3 * (size_t)G[0], xyz + 3 * (size_t)G[1], xyz + 3 * (size_t)G[2], k) != 0)
      break;
  if (k == 3)
    return g;
  for (uint32_t i = F->start[g]; i < F->start[g + 1]; i++) {
    const uint32_t *T = c->plc->tris + 3 * (size_t)F->member[i];
    double s = tr_orient2d_proj(xyz + 3 * (size_t)T[0], xyz + 3 * (size_t)T[1], xyz + 3 * (size_t)T[2], k);
    int in = 1;
    for (int e = 0; e < 3 && in; e++)
      in = s * tr_orient2d_proj(xyz + 3 * (size_t)T[e], xyz + 3 * (size_t)T[(e + 1) % 3], p, k) >= 0;
    if (in)
      return F->member[i];
  }
  return g;
}

static element elem_of(const rf_ctx *c, int kind, uint32_t own, const double *at)
{
  element e = {0, {0, 0, 0}, TR_NONE, TR_NONE};
  if (kind == RF_SEG) {
    e.kind = RF_SEG;
    e.v[0] = c->ssab[2 * (size_t)own];
    e.v[1] = c->ssab[2 * (size_t)own + 1];
    e.cl = rf_caps_edge(&c->caps, e.v[0], e.v[1]);
  } else if (kind == RF_FACET) {
    e.kind = RF_FACET;
    e.tri = facet_tri_at(c, own, at);
    for (int i = 0; i < 3; i++)
      e.v[i] = c->plc->tris[3 * (size_t)e.tri + i];
    if (c->caps.n)
      e.cl = c->caps.tri[e.tri];
  } else if (kind == RF_INPUT && c->caps.n && own < c->plc->npoints) {
    e.v[0] = own;
    e.cl = c->caps.vert[own];
  }
  return e;
}

static element elem_of_vertex(const rf_ctx *c, uint32_t x)
{
  return elem_of(c, c->vkind[x], c->vown[x], c->m->xyz + 3 * (size_t)x);
}

static const double *X(const rf_ctx *c, uint32_t v)
{
  return c->plc->xyz + 3 * (size_t)v;
}

/* v scaled by 2^-e, each component the double ldexp gives: where 2^-e is a double (e >=
 * -1023), the product by it is rounded once, to nearest, only when subnormal, as ldexp
 * rounds; one ldexp per vector instead of three (the stats measure every input corner). */
static void scale_pow2(double v[3], int e)
{
  if (e >= -1023) {
    const double f = ldexp(1.0, -e);
    for (int i = 0; i < 3; i++)
      v[i] *= f;
  } else {
    for (int i = 0; i < 3; i++)
      v[i] = ldexp(v[i], -e);
  }
}

/* The differences are scaled by a power of two each (exact, so the cosine is the same
 * double wherever their squares neither overflow nor underflow): at an input scale of 1e200
 * or 1e-200 the squares did, and every angle came out 90 degrees or 0 (no cap, no small
 * angle found). */
double rf_cos_angle(const double *o, const double *p, const double *q)
{
  double a[3], b[3], ma = 0, mb = 0;
  for (int i = 0; i < 3; i++) {
    a[i] = p[i] - o[i];
    b[i] = q[i] - o[i];
    ma = fabs(a[i]) > ma ? fabs(a[i]) : ma;
    mb = fabs(b[i]) > mb ? fabs(b[i]) : mb;
  }
  int ea = 0, eb = 0;
  if (ma > 0 && isfinite(ma))
    frexp(ma, &ea);
  if (mb > 0 && isfinite(mb))
    frexp(mb, &eb);
  scale_pow2(a, ea);
  scale_pow2(b, eb);
  double n = sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  return n > 0 ? (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / n : 1;
}

void rf_tri_cos_angles(const double *x0, const double *x1, const double *x2, double c[3])
{
  /* d[k] = x[k+1] - x[k], scaled. Corner k's vectors are d[k] and x[k+2] - x[k] =
   * -d[k+2]: a subtraction of distinct doubles rounds the same either way round, and so
   * do the scaling, the squares and the products (negated), so the cosine is
   * -(d[k].d[k+2]) / n, with three differences, scalings and squared lengths instead of
   * six. Only a zero may differ, in its sign (x - x is +0 both ways round). */
  const double *x[3] = {x0, x1, x2};
  double d[3][3], dd[3];
  for (int k = 0; k < 3; k++) {
    double m = 0;
    for (int i = 0; i < 3; i++) {
      d[k][i] = x[(k + 1) % 3][i] - x[k][i];
      m = fabs(d[k][i]) > m ? fabs(d[k][i]) : m;
    }
    int e = 0;
    if (m > 0 && isfinite(m))
      frexp(m, &e);
    scale_pow2(d[k], e);
    dd[k] = d[k][0] * d[k][0] + d[k][1] * d[k][1] + d[k][2] * d[k][2];
  }
  for (int k = 0; k < 3; k++) {
    const double *a = d[k], *b = d[(k + 2) % 3];
    double n = sqrt(dd[k] * dd[(k + 2) % 3]);
    c[k] = n > 0 ? -(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / n : 1;
  }
}

static int nverts(const element *e)
{
  return e->kind == RF_SEG ? 2 : 3;
}

static int has(const element *e, uint32_t v)
{
  for (int i = 0; i < nverts(e); i++)
    if (e->v[i] == v)
      return 1;
  return 0;
}

/* Segment V-P against triangle T at its vertex V: small if P's direction is close to one
 * of T's edges at V other than VP itself, or (seen over T's corner) to T's plane. */
static int seg_facet_small(const rf_ctx *c, uint32_t V, uint32_t P, const element *t)
{
  uint32_t o[2];
  int k = 0;
  for (int i = 0; i < 3; i++)
    if (t->v[i] != V)
      o[k++] = t->v[i];
  if (P == o[0] || P == o[1]) /* an edge of T: T's own corner, where concentric shells
                                 * end the descent unless the corner is sharp */
    return rf_cos_angle(X(c, V), X(c, o[0]), X(c, o[1])) > RF_SHARP_COS;
  if (rf_cos_angle(X(c, V), X(c, P), X(c, o[0])) > RF_SMALL_COS ||
      rf_cos_angle(X(c, V), X(c, P), X(c, o[1])) > RF_SMALL_COS)
    return 1;
  /* elevation of VP over T's plane, when VP lies over T's corner */
  double u[3], w[3], p[3], n[3];
  for (int i = 0; i < 3; i++) {
    u[i] = X(c, o[0])[i] - X(c, V)[i];
    w[i] = X(c, o[1])[i] - X(c, V)[i];
    p[i] = X(c, P)[i] - X(c, V)[i];
  }
  for (int i = 0; i < 3; i++)
    n[i] = u[(i + 1) % 3] * w[(i + 2) % 3] - u[(i + 2) % 3] * w[(i + 1) % 3];
  double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double pp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  if (!(nn > 0 && pp > 0))
    return 0;
  double s = fabs(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / (nn * pp); /* sin elevation */
  /* the projection of P lies over the corner iff it is on the inner side of both edges */
  double q[3];
  for (int i = 0; i < 3; i++)
    q[i] = p[i] - n[i] * (n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / (nn * nn);
  double c1[3], c2[3];
  for (int i = 0; i < 3; i++) {
    c1[i] = u[(i + 1) % 3] * q[(i + 2) % 3] - u[(i + 2) % 3] * q[(i + 1) % 3];
    c2[i] = q[(i + 1) % 3] * w[(i + 2) % 3] - q[(i + 2) % 3] * w[(i + 1) % 3];
  }
  int over = c1[0] * n[0] + c1[1] * n[1] + c1[2] * n[2] > 0 && c2[0] * n[0] + c2[1] * n[1] + c2[2] * n[2] > 0;
  return over && s < 0.8660254037844386; /* elevation under 60 degrees */
}

/* Two triangles sharing edge V-W: the wedge between them (angle of their third vertices
 * seen along the edge). */
static int facet_facet_small(const rf_ctx *c, uint32_t V, uint32_t W, uint32_t A, uint32_t B)
{
  double e[3], a[3], b[3];
  for (int i = 0; i < 3; i++) {
    e[i] = X(c, W)[i] - X(c, V)[i];
    a[i] = X(c, A)[i] - X(c, V)[i];
    b[i] = X(c, B)[i] - X(c, V)[i];
  }
  double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  if (!(ee > 0))
    return 0;
  double ta = (a[0] * e[0] + a[1] * e[1] + a[2] * e[2]) / ee, tb = (b[0] * e[0] + b[1] * e[1] + b[2] * e[2]) / ee;
  double zero[3] = {0, 0, 0};
  for (int i = 0; i < 3; i++) {
    a[i] -= ta * e[i];
    b[i] -= tb * e[i];
  }
  return rf_cos_angle(zero, a, b) > RF_SMALL_COS;
}

/* Do the constraints of e and f meet at input vertex V under a small angle? */
static int small_at(const rf_ctx *c, uint32_t V, const element *e, const element *f)
{
  if (e->kind == RF_SEG && f->kind == RF_SEG) {
    uint32_t P = e->v[0] == V ? e->v[1] : e->v[0], Q = f->v[0] == V ? f->v[1] : f->v[0];
    /* two edges of one input triangle: its own corner (see seg_facet_small) */
    double lim = rf_face_get(&c->trimap, V, P, Q) != TR_NONE ? RF_SHARP_COS : RF_SMALL_COS;
    return P != Q && rf_cos_angle(X(c, V), X(c, P), X(c, Q)) > lim;
  }
  if (e->kind == RF_SEG || f->kind == RF_SEG) {
    const element *s = e->kind == RF_SEG ? e : f, *t = e->kind == RF_SEG ? f : e;
    uint32_t P = s->v[0] == V ? s->v[1] : s->v[0];
    return seg_facet_small(c, V, P, t);
  }
  /* two triangles */
  if (c->fc.group[e->tri] == c->fc.group[f->tri])
    return 0; /* one facet */
  int shared = 0;
  uint32_t W = TR_NONE;
  for (int i = 0; i < 3; i++)
    if (has(f, e->v[i])) {
      shared++;
      if (e->v[i] != V)
        W = e->v[i];
    }
  if (shared == 3)
    return 0; /* the same triangle */
  if (shared == 2 && W != TR_NONE) {
    uint32_t A = TR_NONE, B = TR_NONE;
    for (int i = 0; i < 3; i++) {
      if (!has(f, e->v[i]))
        A = e->v[i];
      if (!has(e, f->v[i]))
        B = f->v[i];
    }
    return facet_facet_small(c, V, W, A, B);
  }
  /* only V in common: small if an edge of one is close to the other */
  for (int i = 0; i < 3; i++)
    if (e->v[i] != V && seg_facet_small(c, V, e->v[i], f))
      return 1;
  return 0;
}

/* Two constraints of one cap cluster, neither holding the other (a vertex of a segment
 * or triangle, a segment of a triangle, or the same one: pieces of one constraint). */
static int one_cluster(const element *e, const element *f)
{
  if (e->cl == TR_NONE || e->cl != f->cl)
    return 0;
  const element *a = e->kind <= f->kind ? e : f, *b = e->kind <= f->kind ? f : e;
  if (!a->kind)
    return !b->kind ? a->v[0] != b->v[0] : !has(b, a->v[0]);
  if (a->kind == b->kind)
    return a->kind == RF_SEG ? !(has(b, a->v[0]) && has(b, a->v[1])) : a->tri != b->tri;
  return !(has(b, a->v[0]) && has(b, a->v[1])); /* a segment, b a triangle */
}

/* *at = the input vertex where e and f meet under a small angle, or TR_NONE when they
 * are two constraints of one cap cluster (no such vertex, and no distance from it). */
static int small_between(const rf_ctx *c, const element *e, const element *f, uint32_t *at)
{
  if (one_cluster(e, f)) {
    if (at)
      *at = TR_NONE;
    return 1;
  }
  if (!e->kind || !f->kind)
    return 0;
  for (int i = 0; i < nverts(e); i++)
    if (has(f, e->v[i]) && small_at(c, e->v[i], e, f)) {
      if (at)
        *at = e->v[i];
      return 1;
    }
  return 0;
}

int rf_small_angle_edge(const rf_ctx *c, uint32_t x, uint32_t y)
{
  element e = elem_of_vertex(c, x), f = elem_of_vertex(c, y);
  return small_between(c, &e, &f, NULL);
}

/* Is the piece (sub-segment when seg, else sub-face `id`) protected from a split caused
 * by vertex v? Its constraint and v's meet at an input vertex V under a small angle, and
 * the piece lies within twice v's distance from V. */
int rf_protected_at(const rf_ctx *c, int seg, uint32_t id, int kind, uint32_t own,
                    const double *pw)
{
  element f = elem_of(c, kind, own, pw), e;
  if (!f.kind && f.cl == TR_NONE)
    return 0;
  const uint32_t *pv;
  int np;
  if (seg) {
    e.kind = RF_SEG;
    e.v[0] = c->ssab[2 * (size_t)id];
    e.v[1] = c->ssab[2 * (size_t)id + 1];
    e.cl = rf_caps_edge(&c->caps, e.v[0], e.v[1]);
    pv = c->ssv + 2 * (size_t)id;
    np = 2;
  } else {
    pv = c->sfv + 3 * (size_t)id;
    double cen[3];
    for (int i = 0; i < 3; i++)
      cen[i] = (c->m->xyz[3 * (size_t)pv[0] + i] + c->m->xyz[3 * (size_t)pv[1] + i] +
                c->m->xyz[3 * (size_t)pv[2] + i]) / 3;
    e = elem_of(c, RF_FACET, c->sftri[id], cen);
    np = 3;
  }
  uint32_t V;
  if (!small_between(c, &e, &f, &V))
    return 0;
  if (V == TR_NONE)
    return 1; /* one cap cluster: the whole of it */
  double r = rf_dist2(pw, X(c, V));
  for (int k = 0; k < np; k++)
    if (rf_dist2(c->m->xyz + 3 * (size_t)pv[k], X(c, V)) > 4 * r)
      return 0;
  return 1;
}

int rf_wedge_split(const rf_ctx *c, uint32_t g, uint32_t v)
{
  if (c->vkind[v] != RF_SEG)
    return 0;
  element e = {RF_SEG, {c->ssab[2 * (size_t)g], c->ssab[2 * (size_t)g + 1], 0}, TR_NONE,
               rf_caps_edge(&c->caps, c->ssab[2 * (size_t)g], c->ssab[2 * (size_t)g + 1])};
  element f = elem_of_vertex(c, v);
  uint32_t V;
  if (!small_between(c, &e, &f, &V) || V == TR_NONE)
    return 0;
  const uint32_t *pv = c->ssv + 2 * (size_t)g;
  if (pv[0] == V || pv[1] == V)
    return 0;
  uint32_t P = e.v[0] == V ? e.v[1] : e.v[0], Q = f.v[0] == V ? f.v[1] : f.v[0];
  if (rf_cos_angle(X(c, V), X(c, P), X(c, Q)) > RF_WEDGE_MIN_COS)
    return 0;
  double d[2];
  for (int k = 0; k < 2; k++)
    d[k] = sqrt(rf_dist2(c->m->xyz + 3 * (size_t)pv[k], X(c, V)));
  double x = fmin(d[0], d[1]), y = fmax(d[0], d[1]);
  return y - x > RF_WEDGE_STEP * x;
}

int rf_protected(const rf_ctx *c, int seg, uint32_t id, uint32_t v)
{
  return rf_protected_at(c, seg, id, c->vkind[v], c->vown[v], c->m->xyz + 3 * (size_t)v);
}
