/* The cone of a cavity (cavity.c) from the new vertex, and the constraint bookkeeping that
 * goes with it: the sub-faces inside the cavity (the ones the point splits) are replaced
 * by the fan from the point over the boundary edges of their region in each input
 * triangle, and a split sub-segment by its two halves. Everything is checked before the
 * mesh is touched: each new face through the point must be shared by exactly two new
 * tets, or by one when it is a new sub-face on the domain boundary. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "output/round.h"
#include "predicates/predicates.h"
#include "refine/refine_impl.h"

typedef struct {
  uint32_t a, b; /* edge key, a < b */
  uint32_t tet;  /* index into the new tets */
  int slot;      /* face of the new tet */
} prec;

static int cmp_prec(const void *pa, const void *pb)
{
  const prec *x = pa, *y = pb;
  if (x->a != y->a)
    return x->a < y->a ? -1 : 1;
  if (x->b != y->b)
    return x->b < y->b ? -1 : 1;
  return x->tet < y->tet ? -1 : x->tet > y->tet;
}

/* cmp_prec's order, inline */
static int prec_before(const prec *x, const prec *y)
{
  return x->a != y->a ? x->a < y->a : x->b != y->b ? x->b < y->b : x->tet < y->tet;
}

/* Sorts pr[0..n) in cmp_prec's order: Shell's sort with Ciura's gaps, inline, for the
 * cones of ordinary cavities (qsort's calls through its comparator, once per inserted
 * point, were 3% of 37384.stl's instructions under --quality 1.414); a huge cone goes to
 * qsort. No two records compare equal (a new tet's three faces through the point hold
 * three different edges), so both give the same order. */
static void sort_prec(prec *pr, size_t n)
{
  if (n > 4096) {
    qsort(pr, n, sizeof *pr, cmp_prec);
    return;
  }
  static const size_t gaps[] = {701, 301, 132, 57, 23, 10, 4, 1};
  for (size_t g = 0; g < sizeof gaps / sizeof *gaps; g++)
    for (size_t i = gaps[g]; i < n; i++) {
      prec x = pr[i];
      size_t j = i;
      for (; j >= gaps[g] && prec_before(&x, &pr[j - gaps[g]]); j -= gaps[g])
        pr[j] = pr[j - gaps[g]];
      pr[j] = x;
    }
}

static int same_edge(uint32_t a, uint32_t b, uint32_t u, uint32_t v)
{
  return (a == u && b == v) || (a == v && b == u);
}

/* Is {a,b} the edge of one of the new sub-faces (4 entries each in ns: a, b, p, tri)? */
static int new_sub_edge(const tr_u32buf *ns, uint32_t a, uint32_t b)
{
  for (size_t i = 0; i < ns->n; i += 4)
    if (same_edge(a, b, ns->a[i], ns->a[i + 1]))
      return 1;
  return 0;
}

/* Does the new sub-face (a, b, p) turn like the removed sub-face f, whose boundary edge ab
 * it cones (exact, in the projection of f's facet)? When every new sub-face of a facet
 * does, the fan from p covers each point of the removed region once and nothing else.
 * The 3D cavity is star-shaped from p, but its cut by the facet's plane can hold ground
 * outside the facet: a merged facet need not be convex, and a notch between two of its
 * strips may lie inside the domain. A sub-face beyond the notch is then removed with
 * edges whose fan from p would cross the notch; this test refuses that insertion. */
static int fans_into(const rf_ctx *c, uint32_t f, uint32_t a, uint32_t b, uint32_t p)
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = c->sfv + 3 * (size_t)f;
  int axis = tr_plc_tri_axis(c->plc, c->sftri[f]);
  tr_point x[3], pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b), pp = tr_mesh_point(m, p);
  for (int i = 0; i < 3; i++)
    x[i] = tr_mesh_point(m, v[i]);
  int s = tr_orient2d_proj_p(&x[0], &x[1], &x[2], axis);
  return s != 0 && tr_orient2d_proj_p(&pa, &pb, &pp, axis) == s;
}

/* Refinement's points against the doubles they are written as (issue 50, item 4). The
 * cone is positive exactly (cavity.c), but on a surface bumpy below double resolution
 * (stlcutters 77343.stl and 93703.stl: nearly planar bottoms off their planes by a few
 * ulps) split points land closer to a vertex than the doubles separate, or with new tets
 * thinner than an ulp; rounded, those tets are flat or inverted, and a cascade of them
 * exhausts the final repair (output/round.c), which may move a point by only
 * TR_ROUND_RADIUS ulps per axis. Such a point is refused: the element it was for is given
 * up like any refused insertion. Both tests below are exact and scale-free, and a tet
 * that passed them keeps passing: no vertex's double changes during refinement, not even
 * the double a Steiner point was admitted at (below), which it keeps in m->xyz. */

/* The double vertex v is written as before any repair: m->xyz, which for a Steiner point
 * is its nearest double or the double next to it that rounding_allows admitted it at (the
 * repair starts from there, round.h). */
static const double *rounded(const struct tr_mesh *m, uint32_t v)
{
  return m->xyz + 3 * (size_t)v;
}

/* Do the doubles x and y lie within RF_ROUND_APART ulps (of the larger magnitude of the
 * two) of each other on every axis? Then the repair may not separate them: in particular
 * two distinct exact points with the same nearest double. Exact: the difference of two
 * doubles that close is exact (Sterbenz), and the bound is a power of two times an ulp;
 * a farther pair's rounded difference still exceeds it. */
#define RF_ROUND_APART TR_ROUND_RADIUS
static int inseparable(const double *x, const double *y)
{
  for (int i = 0; i < 3; i++) {
    double a = fmax(fabs(x[i]), fabs(y[i]));
    if (!(fabs(x[i] - y[i]) <= RF_ROUND_APART * (nextafter(a, INFINITY) - a)))
      return 0;
  }
  return 1;
}

/* Is every new tet (a, b, d, p), a b d = the first three entries of each 6-entry record
 * of nv, strictly positive (exact orient3d) with p at the double y? */
static int cone_positive_at(const struct tr_mesh *m, const uint32_t *nv, size_t nnew,
                            const double *y)
{
  for (size_t i = 0; i < nnew; i++)
    if (tr_orient3d(rounded(m, nv[6 * i]), rounded(m, nv[6 * i + 1]),
                    rounded(m, nv[6 * i + 2]), y) <= 0)
      return 0;
  return 1;
}

/* May point pid, its cone in nv, go in for its doubles? No vertex of the cone within
 * RF_ROUND_APART ulps of it, and every new tet strictly positive with pid at its nearest
 * double or, for a Steiner point (which the repair moves), at a double one ulp away on
 * some axes: a sliver thinner than an ulp is let in (refusing it cost
 * star_steiner_cluster_s3_1477.off most of its -O 3 gain: 1.10 -> 0.14 degrees; pinion
 * admits 289 points so). *at = the double it goes in at, which it keeps (rf_insert): the
 * points after it are checked against it there. Checked against its nearest double
 * instead, each point let in so assumed its neighbours at theirs, and the moves they
 * needed at the end conflicted: stlcutters 1452677.stl left 161 tets flat after the
 * repair's budget (exit 9), a box with an edge chamfered 1e-9 wide
 * (tests/data/chamfer_ribbon_rounding.off) one. */
static int rounding_allows(const struct tr_mesh *m, const uint32_t *nv, size_t nnew,
                           uint32_t pid, double at[3])
{
  const double *x = rounded(m, pid);
  memcpy(at, x, 3 * sizeof(double));
  for (size_t i = 0; i < nnew; i++)
    for (int j = 0; j < 3; j++)
      if (nv[6 * i + j] != TR_GHOST && inseparable(rounded(m, nv[6 * i + j]), x))
        return 0;
  for (size_t i = 0; i < nnew; i++)
    for (int j = 0; j < 3; j++)
      if (nv[6 * i + j] == TR_GHOST)
        return 1; /* no double to test; never in a cavity of inner tets */
  if (cone_positive_at(m, nv, nnew, x))
    return 1;
  if (!(m->vq && m->vq[pid]))
    return 0;
  for (int o = 1; o < 27; o++) {
    double y[3];
    for (int i = 0, k = o; i < 3; i++, k /= 3)
      y[i] = k % 3 == 0 ? x[i] : nextafter(x[i], k % 3 == 1 ? INFINITY : -INFINITY);
    if (cone_positive_at(m, nv, nnew, y)) {
      memcpy(at, y, sizeof y);
      return 1;
    }
  }
  return 0;
}

int rf_cone_admits(const struct tr_mesh *m, const uint32_t *bf, size_t nbf, const double x[3])
{
  for (size_t i = 0; i < nbf; i++) {
    const uint32_t *v = m->tv + 4 * (size_t)(bf[i] >> 2);
    int k = (int)(bf[i] & 3);
    for (int j = 0; j < 3; j++)
      if (v[tr_face_vtx[k][j]] == TR_GHOST || inseparable(rounded(m, v[tr_face_vtx[k][j]]), x))
        return 0;
  }
  for (size_t i = 0; i < nbf; i++) {
    const uint32_t *v = m->tv + 4 * (size_t)(bf[i] >> 2);
    int k = (int)(bf[i] & 3);
    if (tr_orient3d(rounded(m, v[tr_face_vtx[k][0]]), rounded(m, v[tr_face_vtx[k][1]]),
                    rounded(m, v[tr_face_vtx[k][2]]), x) <= 0)
      return 0;
  }
  return 1;
}

tr_status rf_insert(rf_ctx *c, uint32_t pid, int *ok)
{
  struct tr_mesh *m = c->m;
  *ok = 0;
  tr_u32buf *rem = &c->tmp, *ns = &c->newsf;
  rem->n = ns->n = 0;
  /* 1. the sub-faces the cavity removes: faces of its tets that are not coned */
  for (size_t i = 0; i < c->bfaces.n; i++)
    c->tstate[c->bfaces.a[i] >> 2] |= (uint8_t)(0x10u << (c->bfaces.a[i] & 3));
  tr_status st = TR_OK;
  for (size_t i = 0; i < c->cav.n && st == TR_OK; i++) {
    uint32_t t = c->cav.a[i];
    const uint32_t *v = m->tv + 4 * (size_t)t;
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      if (c->tstate[t] & (0x10u << k))
        continue;
      uint32_t sf = rf_subface_of(c, v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]],
                                  v[tr_face_vtx[k][2]]);
      if (sf == TR_NONE || c->sfdead[sf])
        continue;
      c->sfdead[sf] = 2; /* listed; undone below if the insertion is refused */
      st = tr_u32buf_push(rem, sf);
    }
  }
  /* 2. the new sub-faces: the point and each boundary edge of the removed region of each
   * input triangle, oriented like the removed sub-face it bounded */
  int good = 1;
  for (size_t i = 0; i < rem->n && st == TR_OK && good; i++) {
    uint32_t f = rem->a[i];
    const uint32_t *v = c->sfv + 3 * (size_t)f;
    for (int e = 0; e < 3 && st == TR_OK; e++) {
      uint32_t a = v[e], b = v[(e + 1) % 3];
      if (c->split_seg != TR_NONE &&
          same_edge(a, b, c->ssv[2 * (size_t)c->split_seg], c->ssv[2 * (size_t)c->split_seg + 1]))
        continue;
      int inner = 0;
      for (size_t j = 0; j < rem->n && !inner; j++) {
        uint32_t g = rem->a[j];
        if (g == f || c->sftri[g] != c->sftri[f])
          continue;
        const uint32_t *w = c->sfv + 3 * (size_t)g;
        for (int d = 0; d < 3; d++)
          inner |= same_edge(a, b, w[d], w[(d + 1) % 3]);
      }
      if (inner)
        continue;
      if (!fans_into(c, f, a, b, pid)) {
        good = 0;
        break;
      }
      uint32_t rec[4] = {a, b, pid, c->sftri[f]};
      for (int d = 0; d < 4 && st == TR_OK; d++)
        st = tr_u32buf_push(ns, rec[d]);
    }
  }
  /* 3. the new tets (a, b, d, p) over each coned face (a, b, d), and their faces through
   * p paired by edge */
  size_t nnew = c->bfaces.n;
  prec *pr = st == TR_OK ? malloc(sizeof *pr * 3 * (nnew ? nnew : 1)) : NULL;
  uint32_t *nv = st == TR_OK ? malloc(sizeof *nv * 6 * (nnew ? nnew : 1)) : NULL;
  if (st == TR_OK && (!pr || !nv))
    st = tr_error(TR_ERR_NOMEM, "out of memory for a cavity of %zu faces", nnew);
  good = good && st == TR_OK;
  for (size_t i = 0; good && i < nnew; i++) {
    uint32_t t = c->bfaces.a[i] >> 2;
    int k = (int)(c->bfaces.a[i] & 3);
    for (int j = 0; j < 3; j++)
      nv[6 * i + j] = m->tv[4 * (size_t)t + tr_face_vtx[k][j]];
    nv[6 * i + 3] = m->tn[4 * (size_t)t + k];
    nv[6 * i + 4] = m->region ? m->region[t] : 0;
    /* faces 0, 1, 2 of (a, b, d, p) hold p and the edges bd, ad, ab */
    static const int ev[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    for (int j = 0; j < 3; j++) {
      uint32_t x = nv[6 * i + ev[j][0]], y = nv[6 * i + ev[j][1]];
      pr[3 * i + j] = (prec){x < y ? x : y, x < y ? y : x, (uint32_t)i, j};
    }
  }
  double at[3];
  memcpy(at, rounded(m, pid), sizeof at);
  if (good)
    good = rounding_allows(m, nv, nnew, pid, at);
  if (good)
    sort_prec(pr, 3 * nnew);
  size_t npr = good ? 3 * nnew : 0;
  for (size_t i = 0; good && i < npr;) {
    size_t j = i + 1;
    while (j < npr && pr[j].a == pr[i].a && pr[j].b == pr[i].b)
      j++;
    if (j - i > 2 || (j - i == 1 && !new_sub_edge(ns, pr[i].a, pr[i].b)))
      good = 0;
    i = j;
  }
  for (size_t i = 0; good && i < ns->n; i += 4) {
    prec key = {ns->a[i] < ns->a[i + 1] ? ns->a[i] : ns->a[i + 1],
                ns->a[i] < ns->a[i + 1] ? ns->a[i + 1] : ns->a[i], 0, 0};
    size_t lo = 0, hi = npr;
    while (lo < hi) {
      size_t mid = (lo + hi) / 2;
      if (pr[mid].a < key.a || (pr[mid].a == key.a && pr[mid].b < key.b))
        lo = mid + 1;
      else
        hi = mid;
    }
    if (lo == npr || pr[lo].a != key.a || pr[lo].b != key.b)
      good = 0;
  }
  if (!good || st != TR_OK) {
    for (size_t i = 0; i < rem->n; i++)
      c->sfdead[rem->a[i]] = 0;
    rf_cavity_release(c);
    free(pr);
    free(nv);
    /* the refused point was the last one added: it goes, or it would stay a vertex of no
     * tet, which the stages after refinement (Ball walks) do not expect */
    if (pid == m->nv - 1 && m->v2t[pid] == TR_NONE) {
      if (pid < c->capv)
        c->vkind[pid] = RF_FREE; /* the slot's next point sets its own */
      tr_mesh_pop_vertex(m);
    }
    return st;
  }
  /* 4. the mesh: free the cavity, build and glue the cone; pid at the double its cone
   * was admitted for */
  memcpy(m->xyz + 3 * (size_t)pid, at, sizeof at);
  rf_cavity_release(c);
  for (size_t i = 0; i < c->cav.n; i++)
    tr_tet_free(m, c->cav.a[i]);
  c->newtets.n = 0;
  for (size_t i = 0; i < nnew && st == TR_OK; i++) {
    uint32_t id;
    st = tr_tet_new(m, nv[6 * i], nv[6 * i + 1], nv[6 * i + 2], pid, &id);
    if (st != TR_OK)
      break;
    st = tr_u32buf_push(&c->newtets, id);
    if (nv[6 * i + 3] != TR_NONE)
      tr_glue(m, id, 3, nv[6 * i + 3] >> 2, (int)(nv[6 * i + 3] & 3));
    if (m->region)
      m->region[id] = nv[6 * i + 4];
  }
  for (size_t i = 0; i + 1 < npr && st == TR_OK; i++)
    if (pr[i].a == pr[i + 1].a && pr[i].b == pr[i + 1].b) {
      tr_glue(m, c->newtets.a[pr[i].tet], pr[i].slot, c->newtets.a[pr[i + 1].tet], pr[i + 1].slot);
      i++;
    }
  free(pr);
  free(nv);
  TR_CHECK(st);
  /* 5. the constraints */
  for (size_t i = 0; i < rem->n; i++)
    c->sfdead[rem->a[i]] = 1;
  for (size_t i = 0; i < ns->n; i += 4)
    TR_CHECK(rf_subface_add(c, ns->a[i], ns->a[i + 1], ns->a[i + 2], ns->a[i + 3], NULL));
  if (c->split_seg != TR_NONE) {
    uint32_t g = c->split_seg;
    uint32_t u = c->ssv[2 * (size_t)g], v = c->ssv[2 * (size_t)g + 1];
    uint32_t A = c->ssab[2 * (size_t)g], B = c->ssab[2 * (size_t)g + 1];
    c->ssdead[g] = 1;
    TR_CHECK(rf_subseg_add(c, u, pid, A, B, NULL));
    TR_CHECK(rf_subseg_add(c, pid, v, A, B, NULL));
  }
  *ok = 1;
  return TR_OK;
}
