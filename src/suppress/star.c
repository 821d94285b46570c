/* The star of a boundary Steiner point after the un-split: full removal (a cone from a
 * boundary vertex) or relocation (a cone from a double point inside the kernel). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "suppress_int.h"

static int cmp_u32(const void *a, const void *b)
{
  uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
  return x < y ? -1 : x > y;
}

static void face_key(const uint32_t *tv, int k, uint32_t out[3])
{
  for (int i = 0; i < 3; i++)
    out[i] = tv[tr_face_vtx[k][i]];
  tr_sort3(out);
}

/* The candidates below are found in doubles, from normals and distances of degree 2 in the
 * coordinates: at coordinates near 1e200 those overflow (a NaN point reached GMP, which
 * aborts on it), near 1e-200 they underflow to nothing. They are computed on coordinates
 * times 2^-e, e = tr_frame_exp(tr_box_half_extent(box of the points involved)), which brings the
 * points' half extent into [1/2, 1): exact, so a star at any power-of-two scale gives the
 * candidates of the same star at unit size, bit for bit, and the exact checks decide as
 * they would there. */
/* the box of the points ids[0..n) of m and of x (if not NULL) */
static void box_of(const struct tr_mesh *m, const uint32_t *ids, size_t n, const double *x,
                   double lo[3], double hi[3])
{
  const double *first = x ? x : m->xyz + 3 * (size_t)ids[0];
  for (int k = 0; k < 3; k++)
    lo[k] = hi[k] = first[k];
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 3; k++) {
      double y = m->xyz[3 * (size_t)ids[i] + k];
      lo[k] = y < lo[k] ? y : lo[k];
      hi[k] = y > hi[k] ? y : hi[k];
    }
}

/* the normal of the triangle (a, b, c) of m in the frame 2^-e and its length */
static double normal(const struct tr_mesh *m, const uint32_t *abc, int e, double n[3])
{
  double x[3][3], u[3], w[3];
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++)
      x[i][k] = ldexp(m->xyz[3 * (size_t)abc[i] + k], -e);
  for (int k = 0; k < 3; k++) {
    u[k] = x[1][k] - x[0][k];
    w[k] = x[2][k] - x[0][k];
  }
  n[0] = u[1] * w[2] - u[2] * w[1];
  n[1] = u[2] * w[0] - u[0] * w[2];
  n[2] = u[0] * w[1] - u[1] * w[0];
  return sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* 1 iff every face (3 ids each) sees apex strictly positively, exactly and with every
 * point at its double (m->xyz); faces that contain apex are skipped, apex == TR_NONE:
 * the double point q. */
int sup_sees_all(const struct tr_mesh *m, const uint32_t *f, size_t nf, uint32_t apex,
                 const double *q, int dbl)
{
  /* a candidate that left the range of doubles is no point (GMP aborts on it) */
  if (apex == TR_NONE && !(isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2])))
    return 0;
  tr_point pq = apex == TR_NONE ? tr_pt_d(q) : tr_mesh_point(m, apex);
  for (size_t i = 0; i < nf; i++) {
    const uint32_t *g = f + 3 * i;
    if (g[0] == apex || g[1] == apex || g[2] == apex)
      continue;
    tr_point a = tr_mesh_point(m, g[0]), b = tr_mesh_point(m, g[1]), c = tr_mesh_point(m, g[2]);
    if (tr_orient3d_p(&a, &b, &c, &pq) <= 0)
      return 0;
  }
  /* Positive with the Steiner points at their nearest doubles too: the rounding stage
   * cannot repair a cone tet whose shape, not a vertex's rounding, makes it flat. Where
   * that is asked too much (dbl = 0, --keep-surface's last try), the rounding repair
   * gets its chance. */
  if (!dbl)
    return 1;
  tr_point dq = apex == TR_NONE ? tr_pt_d(q) : tr_pt_d(m->xyz + 3 * (size_t)apex);
  for (size_t i = 0; i < nf; i++) {
    const uint32_t *g = f + 3 * i;
    if (g[0] == apex || g[1] == apex || g[2] == apex)
      continue;
    tr_point a = tr_pt_d(m->xyz + 3 * (size_t)g[0]), b = tr_pt_d(m->xyz + 3 * (size_t)g[1]),
             c = tr_pt_d(m->xyz + 3 * (size_t)g[2]);
    if (tr_orient3d_p(&a, &b, &c, &dq) <= 0)
      return 0;
  }
  return 1;
}

/* Replaces the star by the tets newv[0..nnew) whose boundary is the link plus the merged
 * triangles. tr_mesh_replace matches the old and new boundaries face by face, and here
 * the sub-faces on p (old boundary) differ from the merged triangles (new boundary): a
 * temporary lid of ghost tets over each closes both into the same boundary, the lid's
 * open faces being the polygon edges. The lid is freed afterwards. */
static tr_status commit(sup_ctx *c, const tr_u32buf *star, const uint32_t *newv, uint32_t nnew,
                        const tr_u32buf *old, const tr_u32buf *merged, uint32_t region)
{
  struct tr_mesh *m = c->m;
  uint32_t nold = (uint32_t)old->n, nm = (uint32_t)(merged->n / 4);
  uint32_t nlist = (uint32_t)star->n + nold, nnv = nnew + nm;
  uint32_t *list = malloc(sizeof *list * nlist);
  uint32_t *nv = malloc(sizeof *nv * 4 * (size_t)nnv);
  uint32_t *ids = malloc(sizeof *ids * nnv);
  tr_status st = TR_OK;
  uint32_t nlid = 0;
  if (!list || !nv || !ids) {
    st = tr_error(TR_ERR_NOMEM, "out of memory suppressing a Steiner point");
    goto done;
  }
  memcpy(list, star->a, star->n * sizeof *list);
  for (uint32_t i = 0; i < nold && st == TR_OK; i++) {
    const uint32_t *f = c->v + 3 * (size_t)old->a[i];
    uint32_t key[3] = {f[0], f[1], f[2]}, g;
    tr_sort3(key);
    uint32_t t = TR_NONE;
    int kk = -1;
    for (size_t j = 0; j < star->n && t == TR_NONE; j++)
      for (int k = 0; k < 4; k++) {
        uint32_t w[3];
        face_key(m->tv + 4 * (size_t)star->a[j], k, w);
        if (!memcmp(w, key, sizeof w) && m->tn[4 * (size_t)star->a[j] + k] == TR_NONE) {
          t = star->a[j];
          kk = k;
          break;
        }
      }
    if (t == TR_NONE) {
      st = tr_error(TR_ERR_INTERNAL, "suppress: sub-face (%u,%u,%u) is not on the star",
                    f[0], f[1], f[2]);
      break;
    }
    if ((st = tr_tet_new(m, f[0], f[1], f[2], TR_GHOST, &g)) != TR_OK)
      break;
    tr_glue(m, g, 3, t, kk);
    list[star->n + nlid++] = g;
  }
  /* the lid tets share their faces through p */
  for (uint32_t i = 0; i < nlid && st == TR_OK; i++)
    for (uint32_t j = i + 1; j < nlid; j++)
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
          uint32_t gi = list[star->n + i], gj = list[star->n + j], wa[3], wb[3];
          face_key(m->tv + 4 * (size_t)gi, a, wa);
          face_key(m->tv + 4 * (size_t)gj, b, wb);
          if (!memcmp(wa, wb, sizeof wa))
            tr_glue(m, gi, a, gj, b);
        }
  if (st != TR_OK)
    goto undo;
  memcpy(nv, newv, 4 * (size_t)nnew * sizeof *nv);
  for (uint32_t i = 0; i < nm; i++) {
    const uint32_t *f = merged->a + 4 * (size_t)i;
    uint32_t *o = nv + 4 * (size_t)(nnew + i);
    o[0] = f[0];
    o[1] = f[1];
    o[2] = f[2];
    o[3] = TR_GHOST;
  }
  st = tr_mesh_replace(m, list, (uint32_t)star->n + nlid, nv, nnv, ids);
  if (st != TR_OK)
    goto undo;
  /* drop the new lid */
  for (uint32_t i = nnew; i < nnv; i++) {
    for (int k = 0; k < 4; k++) {
      uint32_t cde = m->tn[4 * (size_t)ids[i] + k];
      if (cde != TR_NONE)
        m->tn[cde] = TR_NONE;
    }
    tr_tet_free(m, ids[i]);
  }
  for (uint32_t i = 0; i < nnew; i++) {
    if (m->region)
      m->region[ids[i]] = region;
    for (int k = 0; k < 4; k++)
      m->v2t[m->tv[4 * (size_t)ids[i] + k]] = ids[i];
  }
  for (uint32_t i = 0; i < nold; i++)
    c->tri[old->a[i]] = TR_NONE;
  for (uint32_t i = 0; i < nm && st == TR_OK; i++) {
    const uint32_t *f = merged->a + 4 * (size_t)i;
    st = sup_add(c, f[0], f[1], f[2], f[3]);
  }
  goto done;
undo:
  for (uint32_t i = 0; i < nlid; i++) {
    uint32_t g = list[star->n + i];
    for (int k = 0; k < 4; k++) {
      uint32_t cde = m->tn[4 * (size_t)g + k];
      if (cde != TR_NONE)
        m->tn[cde] = TR_NONE;
    }
    tr_tet_free(m, g);
  }
done:
  free(list);
  free(nv);
  free(ids);
  return st;
}

/* The star of p, if p is a boundary point of one region whose only constraint faces
 * are the sub-faces on it (each a face of the star with nothing behind it). */
static tr_status star_of(sup_ctx *c, uint32_t p, const tr_u32buf *old, tr_u32buf *star,
                         uint32_t *region, int *ok)
{
  struct tr_mesh *m = c->m;
  *ok = 0;
  TR_CHECK(tr_ball(m, p, 1, star));
  uint32_t nb = 0;
  for (size_t i = 0; i < star->n; i++) {
    uint32_t t = star->a[i];
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      return TR_OK;
    uint32_t r = m->region ? m->region[t] : 0;
    if (i == 0)
      *region = r;
    else if (r != *region)
      return TR_OK;
    for (int k = 0; k < 4; k++) {
      if (m->tv[4 * (size_t)t + k] == p)
        continue;
      uint32_t w[3];
      face_key(m->tv + 4 * (size_t)t, k, w);
      int sub = 0;
      for (size_t j = 0; j < old->n && !sub; j++) {
        uint32_t f[3] = {c->v[3 * (size_t)old->a[j]], c->v[3 * (size_t)old->a[j] + 1],
                         c->v[3 * (size_t)old->a[j] + 2]};
        tr_sort3(f);
        sub = !memcmp(f, w, sizeof f);
      }
      int open = m->tn[4 * (size_t)t + k] == TR_NONE;
      if (sub != open)
        return TR_OK; /* a crack or internal facet through p, or a hole in the mesh */
      nb += (uint32_t)open;
    }
  }
  *ok = nb == old->n;
  return TR_OK;
}

/* The faces' planes in the frame 2^-e, for the projections below: computed once per
 * search, not once per step of every pass (400 steps times the faces, times the passes,
 * made the projections the costliest part of merging). */
static void planes_of(const struct tr_mesh *m, const uint32_t *f, size_t nf, int e,
                      sup_kplane *pl)
{
  for (size_t i = 0; i < nf; i++) {
    pl[i].len = normal(m, f + 3 * i, e, pl[i].n);
    for (int k = 0; k < 3; k++)
      pl[i].a[k] = ldexp(m->xyz[3 * (size_t)f[3 * i] + k], -e);
  }
}

/* A point inside the kernel of the faces by projections in doubles (Agmon-Motzkin): from
 * g, move onto the half-space d_i >= tau of the face the point violates most, until it
 * is at least tau inside every face or 400 steps are taken, for margins tau shrinking
 * from a fraction of the star's size. Only a candidate: the caller checks it exactly.
 * pl: the planes in the frame 2^-e, L the box's size in it. A step is a function of x
 * alone, so once x is back, bit for bit, where it was one or two steps before, the
 * remaining steps only alternate between the last two points: the point the 400 steps
 * end on is taken from them at once (where the kernel is empty or thinner than tau the
 * projections can settle into such a cycle early: 13% of suppression's instructions on
 * 77343.stl --keep-surface). */
void sup_relax(const sup_kplane *pl, size_t nf, int e, double L, const double g[3], double q[3],
               int pass)
{
  double x[3];
  double tau = L / (double)(8 << (3 * pass));
  for (int k = 0; k < 3; k++)
    x[k] = ldexp(g[k], -e);
  double x1[3], x2[3]; /* x one and two steps before */
  for (int it = 0; it < 400; it++) {
    double worst = 0, wn[3] = {0, 0, 0};
    int found = 0;
    for (size_t i = 0; i < nf; i++) {
      const double *n = pl[i].n, *a = pl[i].a, len = pl[i].len;
      if (!(len > 0))
        continue;
      double d = (n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2])) / len;
      if (!found || d < worst) {
        found = 1;
        worst = d;
        for (int k = 0; k < 3; k++)
          wn[k] = n[k] / len;
      }
    }
    if (!found || worst >= tau)
      break;
    if (it >= 1)
      memcpy(x2, x1, sizeof x2);
    memcpy(x1, x, sizeof x1);
    for (int k = 0; k < 3; k++)
      x[k] += (tau - worst) * wn[k];
    /* x is the point after step it, x1 after it - 1, x2 after it - 2 */
    if (!memcmp(x, x1, sizeof x))
      break; /* a fixed point: every later step leaves it */
    if (it >= 1 && !memcmp(x, x2, sizeof x)) {
      if ((399 - it) % 2)
        memcpy(x, x1, sizeof x); /* step 399 ends on the other point of the cycle */
      break;
    }
  }
  for (int k = 0; k < 3; k++)
    q[k] = ldexp(x[k], e);
}

/* A double point that sees every face of bf strictly (sees_all): from p's double p0
 * halfway towards g again and again, then projections into the kernel (relax), then the
 * centroids of the region's tets. */
tr_status sup_find_q(const struct tr_mesh *m, const tr_u32buf *bf, const tr_u32buf *star,
                     const double *p0, const double g[3], const double dir[4], int dbl,
                     int relaxes, double q[3], int *found)
{
  size_t nf = bf->n / 3;
  *found = 1;
  /* p moved off the surface along the sum of the merged triangles' inner unit normals:
   * for a small enough step this is inside the kernel (p sees every link face strictly,
   * and the sum points into the inner side of each surface plane through p), so the
   * steps go down to the resolution of p's coordinates */
  double step = dir[3];
  for (int j = 0; j < 80 && step > 0; j++, step *= 0.5) {
    for (int k = 0; k < 3; k++)
      q[k] = p0[k] + step * dir[k];
    if (sup_sees_all(m, bf->a, nf, TR_NONE, q, dbl))
      return TR_OK;
  }
  double s = 1.0;
  for (int j = 0; j < 40; j++, s *= 0.5) {
    for (int k = 0; k < 3; k++)
      q[k] = p0[k] + (g[k] - p0[k]) * s;
    if (sup_sees_all(m, bf->a, nf, TR_NONE, q, dbl))
      return TR_OK;
  }
  /* a relaxed point that has not reached its margin may still see every face */
  if (relaxes > 0 && nf > 0) {
    sup_kplane *pl = malloc(sizeof *pl * nf);
    if (!pl)
      return tr_error(TR_ERR_NOMEM, "out of memory for %zu planes", nf);
    double lo[3], hi[3];
    box_of(m, bf->a, 3 * nf, g, lo, hi);
    int e = tr_frame_exp(tr_box_half_extent(lo, hi));
    double L = ldexp(2 * tr_box_half_extent(lo, hi), -e);
    planes_of(m, bf->a, nf, e, pl);
    for (int pass = 0; pass < relaxes; pass++) {
      sup_relax(pl, nf, e, L, g, q, pass);
      if (sup_sees_all(m, bf->a, nf, TR_NONE, q, dbl)) {
        free(pl);
        return TR_OK;
      }
    }
    free(pl);
  }
  for (size_t i = 0; i < star->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)star->a[i];
    /* quarters first: exact, and the sum of four coordinates near 1e308 overflows */
    for (int k = 0; k < 3; k++)
      q[k] = 0.25 * m->xyz[3 * (size_t)tv[0] + k] + 0.25 * m->xyz[3 * (size_t)tv[1] + k] +
             0.25 * m->xyz[3 * (size_t)tv[2] + k] + 0.25 * m->xyz[3 * (size_t)tv[3] + k];
    if (sup_sees_all(m, bf->a, nf, TR_NONE, q, dbl))
      return TR_OK;
  }
  *found = 0;
  return TR_OK;
}

/* Full removal: the first boundary vertex (in id order) that sees every face not on it
 * becomes the apex of the cone that replaces the star. */
static tr_status try_remove(sup_ctx *c, uint32_t p, const tr_u32buf *star, const tr_u32buf *bf,
                            const tr_u32buf *old, const tr_u32buf *merged, uint32_t region,
                            int dbl, int *done)
{
  struct tr_mesh *m = c->m;
  size_t nf = bf->n / 3;
  tr_u32buf verts = {0}, nv = {0};
  tr_status st = TR_OK;
  for (size_t i = 0; i < bf->n && st == TR_OK; i++)
    st = tr_u32buf_push(&verts, bf->a[i]);
  if (st == TR_OK)
    qsort(verts.a, verts.n, sizeof *verts.a, cmp_u32);
  for (size_t i = 0; i < verts.n && st == TR_OK && !*done; i++) {
    uint32_t v = verts.a[i];
    if ((i && verts.a[i - 1] == v) || !sup_sees_all(m, bf->a, nf, v, NULL, dbl))
      continue;
    for (size_t j = 0; j < nf && st == TR_OK; j++) {
      const uint32_t *g = bf->a + 3 * j;
      if (g[0] == v || g[1] == v || g[2] == v)
        continue;
      for (int k = 0; k < 3 && st == TR_OK; k++)
        st = tr_u32buf_push(&nv, g[k]);
      if (st == TR_OK)
        st = tr_u32buf_push(&nv, v);
    }
    if (st == TR_OK)
      st = commit(c, star, nv.a, (uint32_t)(nv.n / 4), old, merged, region);
    if (st == TR_OK) {
      m->v2t[p] = TR_NONE;
      *done = 1;
    }
  }
  tr_u32buf_free(&verts);
  tr_u32buf_free(&nv);
  return st;
}

/* Relocation: a double point q inside the star's kernel (find_q) replaces p, which keeps
 * its id and becomes an interior point at q exactly. */
static tr_status try_relocate(sup_ctx *c, uint32_t p, const tr_u32buf *star,
                              const tr_u32buf *bf, const tr_u32buf *old,
                              const tr_u32buf *merged, uint32_t region, int dbl, int *done)
{
  struct tr_mesh *m = c->m;
  size_t nf = bf->n / 3;
  double g[3] = {0, 0, 0}, q[3], lo[3], hi[3];
  const double *p0 = m->xyz + 3 * (size_t)p;
  box_of(m, bf->a, 3 * nf, p0, lo, hi);
  int e = tr_frame_exp(tr_box_half_extent(lo, hi));
  /* g: the centroid of the link's vertices (the link faces come first in bf) */
  for (size_t i = 0; i < star->n * 3; i++)
    for (int k = 0; k < 3; k++)
      g[k] += ldexp(m->xyz[3 * (size_t)bf->a[i] + k], -e);
  for (int k = 0; k < 3; k++)
    g[k] = ldexp(g[k] / (double)(star->n * 3), e);
  /* the inner direction (dir[0..2]: the merged triangles' unit normals, which bf lists
   * pointing in) and the star's size (dir[3]) */
  double dir[4] = {0, 0, 0, 0};
  for (size_t i = star->n; i < nf; i++) {
    double n[3], len = normal(m, bf->a + 3 * i, e, n);
    for (int k = 0; k < 3 && len > 0; k++)
      dir[k] += n[k] / len;
  }
  for (size_t i = 0; i < 3 * nf; i++)
    for (int k = 0; k < 3; k++) {
      double d = fabs(ldexp(m->xyz[3 * (size_t)bf->a[i] + k], -e) - ldexp(p0[k], -e));
      dir[3] = d > dir[3] ? d : dir[3];
    }
  dir[3] = ldexp(dir[3], e);
  if (nf == star->n)
    dir[3] = 0; /* an interior point: no surface to step away from */
  int found = 0;
  TR_CHECK(sup_find_q(m, bf, star, p0, g, dir, dbl, SUP_RELAX_PASSES, q, &found));
  if (!found)
    return TR_OK;
  tr_u32buf nv = {0};
  tr_status st = TR_OK;
  for (size_t j = 0; j < nf && st == TR_OK; j++) {
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = tr_u32buf_push(&nv, bf->a[3 * j + k]);
    if (st == TR_OK)
      st = tr_u32buf_push(&nv, p);
  }
  if (st == TR_OK) {
    /* p's exact point becomes q: the cone is positive for q, so for p from now on */
    tr_qpoint_set_d(m->vq[p], q);
    memcpy(m->xyz + 3 * (size_t)p, q, sizeof q);
    st = commit(c, star, nv.a, (uint32_t)(nv.n / 4), old, merged, region);
    if (st == TR_OK)
      *done = 2;
  }
  tr_u32buf_free(&nv);
  return st;
}

static int cmp_face4(const void *pa, const void *pb)
{
  const uint32_t *a = pa, *b = pb;
  for (int i = 0; i < 4; i++)
    if (a[i] != b[i])
      return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* A key of p's star (ball: its tets) for its retriangulation (which p's position does
 * not matter to): the link faces as sorted triples, each with the vertex behind it (what
 * the first expansion adds), in sorted order, and the flags, mixed into 64 bits (never
 * 0). The expansion may look further than that: the chance a change there gives is
 * given up. */
uint64_t sup_star_key(const struct tr_mesh *m, uint32_t p, const tr_u32buf *ball,
                      unsigned flags)
{
  uint64_t h = 0x9E3779B97F4A7C15ull ^ flags;
  uint32_t *f = malloc(sizeof *f * 4 * (ball->n ? ball->n : 1));
  if (!f)
    return 0; /* no key: the point is tried */
  for (size_t i = 0; i < ball->n; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)ball->a[i];
    int k = tr_ncode(m, ball->a[i], p);
    for (int a = 0; a < 3; a++)
      f[4 * i + a] = k < 0 ? tv[a] : tv[tr_face_vtx[k][a]];
    tr_sort3(f + 4 * i);
    uint32_t nb = k < 0 ? TR_NONE : m->tn[4 * (size_t)ball->a[i] + (size_t)k];
    f[4 * i + 3] = nb == TR_NONE ? TR_NONE : m->tv[nb];
  }
  qsort(f, ball->n, 4 * sizeof *f, cmp_face4);
  for (size_t i = 0; i < 4 * ball->n; i++)
    h = (h ^ f[i]) * 0xBF58476D1CE4E5B9ull;
  free(f);
  h ^= h >> 31;
  return h ? h : 1;
}

tr_status sup_point(sup_ctx *c, uint32_t p, unsigned flags, int *done)
{
  struct tr_mesh *m = c->m;
  *done = 0;
  if (p >= m->nv || m->v2t[p] == TR_NONE)
    return TR_OK;
  tr_u32buf old = {0}, star = {0}, merged = {0}, bf = {0};
  tr_status st = sup_faces_of(c, p, &old);
  uint32_t region = 0;
  int ok = 0, edge = 0;
  /* an interior point (no sub-face on it) only with TR_SUP_INTERIOR, and not where it
   * could lie on an input segment */
  int inner = old.n == 0;
  if (st == TR_OK && (!inner || ((flags & TR_SUP_INTERIOR) && c->plc->nsegs == 0)))
    st = star_of(c, p, &old, &star, &region, &ok);
  if (st == TR_OK && ok && !inner)
    st = sup_unsplit(c, p, &old, &merged, &edge, &ok);
  if (st != TR_OK || !ok)
    goto done;
  /* the ball's boundary, each face listed so that its right-hand normal points in */
  for (size_t i = 0; i < star.n && st == TR_OK; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)star.a[i];
    int k = tr_ncode(m, star.a[i], p);
    for (int j = 0; j < 3 && st == TR_OK; j++)
      st = tr_u32buf_push(&bf, tv[tr_face_vtx[k][j]]);
  }
  for (size_t i = 0; i < merged.n / 4 && st == TR_OK; i++) {
    const uint32_t *f = merged.a + 4 * i;
    if ((st = tr_u32buf_push(&bf, f[0])) == TR_OK && (st = tr_u32buf_push(&bf, f[2])) == TR_OK)
      st = tr_u32buf_push(&bf, f[1]);
  }
  if (st != TR_OK)
    goto done;
  /* exact and in doubles first; under --keep-surface, exact only as a last try */
  for (int dbl = 1; dbl >= (flags & TR_SUP_REQUIRE ? 0 : 1) && !*done && st == TR_OK; dbl--) {
    if (flags & TR_SUP_REMOVE)
      st = try_remove(c, p, &star, &bf, &old, &merged, region, dbl, done);
    if (st == TR_OK && !*done && !inner && (flags & TR_SUP_RELOCATE))
      st = try_relocate(c, p, &star, &bf, &old, &merged, region, dbl, done);
  }
  /* the Delaunay retriangulation of the star, then the flips: last, since their undo may
   * move the star's tets to other slots */
  for (int dbl = 1; dbl >= (flags & TR_SUP_REQUIRE ? 0 : 1) && !*done && st == TR_OK; dbl--)
    if (inner && (flags & TR_SUP_REMOVE)) {
      /* the passes retry every point left while anything changed: a retriangulation
       * that failed on the same star (and the same tets behind it) would fail again */
      uint64_t key = c->tried ? sup_star_key(m, p, &star, (unsigned)dbl) : 0;
      if (!key || c->tried[2 * (size_t)p + (size_t)dbl] != key) {
        uint32_t t;
        int by_dbl = 0;
        st = sup_star_fill(m, c, p, region, dbl, SUP_FILL_EXPAND, &t, done, &by_dbl);
        if (st == TR_OK && !*done && key) {
          c->tried[2 * (size_t)p + (size_t)dbl] = key;
          /* refused whatever dbl: the dbl = 0 try (--keep-surface) would redo it */
          if (dbl && !by_dbl)
            c->tried[2 * (size_t)p] = sup_star_key(m, p, &star, 0);
        }
      }
      if (st == TR_OK && !*done)
        st = sup_flip_out(m, c, p, region, dbl, done);
      /* at doubles only: a merge's cone left to the rounding repair is one whole
       * union's worth of tets to repair, and the exact-only try doubles the time */
      if (st == TR_OK && !*done && (flags & TR_SUP_MERGE) && dbl)
        st = sup_merge(m, c, p, region, dbl, done);
    }
  /* The edge removals' positivity depends on where p is: a point relocated off the
   * surface sits just inside it, where its star is flat. Moved into its kernel (the
   * centroid of its link or a point towards it, kept as a double, find_q), it is often
   * removable; if not, it stays there (a valid interior point). The star changed. */
  if (st == TR_OK && !*done && inner && (flags & TR_SUP_REMOVE)) {
    st = star_of(c, p, &old, &star, &region, &ok);
    bf.n = 0;
    for (size_t i = 0; i < star.n && st == TR_OK && ok; i++) {
      const uint32_t *tv = m->tv + 4 * (size_t)star.a[i];
      int k = tr_ncode(m, star.a[i], p);
      for (int j = 0; j < 3 && st == TR_OK; j++)
        st = tr_u32buf_push(&bf, tv[tr_face_vtx[k][j]]);
    }
    int moved = 0;
    if (st == TR_OK && ok)
      st = try_relocate(c, p, &star, &bf, &old, &merged, region, 1, &moved);
    if (st == TR_OK && moved)
      st = sup_flip_out(m, c, p, region, 1, done);
  }
done:
  tr_u32buf_free(&old);
  tr_u32buf_free(&star);
  tr_u32buf_free(&merged);
  tr_u32buf_free(&bf);
  return st;
}
