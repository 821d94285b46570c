/* Geometric verification of a decomposition table on an exact rational configuration.
 *
 * For a table and a configuration (exact points for every name), verify() checks:
 *  (a) every old tet (precondition) and every new tet is positively oriented;
 *  (b) the new tets' volumes sum exactly to the old tets';
 *  (c) every face of a new tet marked INTERNAL is shared by exactly two new tets whose
 *      apices lie on opposite sides of it (links reciprocal: tr_dectable_check); every
 *      other face belongs to exactly one new tet;
 *  (d) an NG / PHI face lies in the closed old face it names, and that old face is on
 *      the boundary of the old region;
 *  (e) the cut polygon (the missing facet's part in the clusterel) is exactly a union of
 *      faces of the new tets: the faces in its plane have P-vertices only, and their
 *      areas add up to the polygon's;
 *  (f) the S/Z type of each face of t, decided on the geometry, is the one the case
 *      claims, and the one tr_dtype_of_table() derives symbolically.
 * Why (a)-(c) plus (d) and (b) prove that the new tets tile the old region exactly:
 * the number of new tets covering a generic point does not change across an internal
 * face (one tet on each side), and the faces where it can change lie on the old
 * boundary. So it is a constant d inside the old region and 0 outside; the volume
 * identity (b) forces d = 1.
 */
#include "verify.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "recover_facets/dtype.h"

int verify_quiet;

#define ERR(...)                          \
  do {                                    \
    if (!verify_quiet) {                  \
      fprintf(stderr, "FAIL %s: ", what); \
      fprintf(stderr, __VA_ARGS__);       \
      fputc('\n', stderr);                \
    }                                     \
    return 1;                             \
  } while (0)

void config_init(config *cf)
{
  memset(cf, 0, sizeof *cf);
  for (int i = 0; i < TR_DV_COUNT; i++)
    qv_init(&cf->p[i]);
}
void config_clear(config *cf)
{
  for (int i = 0; i < TR_DV_COUNT; i++)
    qv_clear(&cf->p[i]);
}

/* 1 iff q lies in the closed triangle abc (exactly). */
static int in_closed_triangle(const qv *q, const qv *a, const qv *b, const qv *c)
{
  qv u, v, n, w, x;
  qv_init(&u), qv_init(&v), qv_init(&n), qv_init(&w), qv_init(&x);
  mpq_t s;
  mpq_init(s);
  qv_sub(&u, b, a);
  qv_sub(&v, c, a);
  qv_cross(&n, &u, &v);
  qv_sub(&w, q, a);
  qv_dot(s, &n, &w);
  int ok = mpq_sgn(s) == 0;
  const qv *t[3] = {a, b, c};
  for (int i = 0; i < 3 && ok; i++) {
    /* q must be on the inner side of edge t[i] t[i+1] within the plane. */
    qv_sub(&u, t[(i + 1) % 3], t[i]);
    qv_sub(&w, q, t[i]);
    qv_cross(&x, &u, &w);
    qv_dot(s, &x, &n);
    ok = mpq_sgn(s) >= 0;
  }
  mpq_clear(s);
  qv_clear(&u), qv_clear(&v), qv_clear(&n), qv_clear(&w), qv_clear(&x);
  return ok;
}

/* 1 iff q lies strictly inside segment ab. */
static int on_open_edge(const qv *q, const qv *a, const qv *b)
{
  qv u, w, x;
  qv_init(&u), qv_init(&w), qv_init(&x);
  mpq_t s, l;
  mpq_init(s), mpq_init(l);
  qv_sub(&u, b, a);
  qv_sub(&w, q, a);
  qv_cross(&x, &u, &w);
  int ok = !mpq_sgn(x.c[0]) && !mpq_sgn(x.c[1]) && !mpq_sgn(x.c[2]);
  qv_dot(s, &w, &u);
  qv_dot(l, &u, &u);
  ok = ok && mpq_sgn(s) > 0 && mpq_cmp(s, l) < 0;
  mpq_clear(s), mpq_clear(l);
  qv_clear(&u), qv_clear(&w), qv_clear(&x);
  return ok;
}

/* |((q-p) x (r-p)) . n|: twice the area of pqr scaled by |n| (n the plane normal). */
static void area_n(mpq_t out, const qv *p, const qv *q, const qv *r, const qv *n)
{
  qv u, v;
  qv_init(&u), qv_init(&v);
  qv_sub(&u, q, p);
  qv_sub(&v, r, p);
  qv_cross(&u, &u, &v);
  qv_dot(out, &u, n);
  mpq_abs(out, out);
  qv_clear(&u), qv_clear(&v);
}

static int same_set3(const uint8_t a[3], const uint8_t b[3])
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static void old_face_sorted(const tr_dectable *t, int j, int vi, uint8_t out[3])
{
  int m = 0;
  for (int i = 0; i < 4; i++)
    if (i != vi)
      out[m++] = t->old[j][i];
  for (int i = 0; i < 3; i++)
    for (int k = i + 1; k < 3; k++)
      if (out[k] < out[i]) {
        uint8_t x = out[i];
        out[i] = out[k];
        out[k] = x;
      }
}

/* The S/Z type of old[0]'s face opposite `opp`, decided on the geometry: which
 * diagonal the new tets' faces lying in that face use. -1: no two cut edges; -2: both or
 * neither diagonal. */
static int geometric_dtype(const tr_dectable *t, const config *cf, uint8_t opp)
{
  uint8_t f[3];
  int m = 0;
  for (int i = 0; i < 4; i++)
    if (t->old[0][i] != opp)
      f[m++] = t->old[0][i];
  const qv *P = cf->p;
  if (qv_orient(&P[f[0]], &P[f[1]], &P[f[2]], &P[opp]) > 0) {
    uint8_t x = f[1];
    f[1] = f[2];
    f[2] = x;
  }
  /* Which Steiner point (by geometry, not by the table's carriers) is on which edge. */
  uint8_t on[3] = {TR_DV_NONE, TR_DV_NONE, TR_DV_NONE}; /* on[i]: edge f[i] f[i+1] */
  for (int i = 0; i < 3; i++)
    for (uint8_t s = TR_DV_P1; s <= TR_DV_P4; s++)
      if (tr_dectable_steiner(t, s) && on_open_edge(&P[s], &P[f[i]], &P[f[(i + 1) % 3]]))
        on[i] = s;
  int apex = -1;
  for (int i = 0; i < 3; i++) /* apex f[i]: edges (i-1) and i cut, edge i+1 not */
    if (on[i] != TR_DV_NONE && on[(i + 2) % 3] != TR_DV_NONE && on[(i + 1) % 3] == TR_DV_NONE)
      apex = i;
  if (apex < 0)
    return -1;
  uint8_t u = f[(apex + 1) % 3], v = f[(apex + 2) % 3];
  uint8_t pu = on[apex], pv = on[(apex + 2) % 3];
  /* Which names lie in the face's plane (computed once per name). */
  int inpl[TR_DV_COUNT] = {0};
  for (int r = 0; r < t->nnew; r++)
    for (int i = 0; i < 4; i++)
      inpl[t->tets[r].v[i]] = 1;
  for (int x = 0; x < TR_DV_COUNT; x++)
    if (inpl[x])
      inpl[x] = qv_orient(&P[f[0]], &P[f[1]], &P[f[2]], &P[x]) == 0;
  int s = 0, z = 0;
  for (int r = 0; r < t->nnew; r++) {
    const tr_dtet *d = &t->tets[r];
    for (int k = 0; k < 4; k++) {
      const uint8_t *w = d->v;
      int in_plane = 1, hu = 0, hv = 0, hpu = 0, hpv = 0;
      for (int i = 0; i < 4; i++) {
        if (i == k)
          continue;
        in_plane &= inpl[w[i]];
        hu |= w[i] == u, hv |= w[i] == v, hpu |= w[i] == pu, hpv |= w[i] == pv;
      }
      if (!in_plane)
        continue;
      s |= hv && hpu;
      z |= hu && hpv;
    }
  }
  if (s == z)
    return -2;
  return s ? TR_DTYPE_S : TR_DTYPE_Z;
}

int verify(const tr_dectable *t, const config *cf, const int8_t *dtype, const char *what)
{
  const qv *P = cf->p;
  if (tr_dectable_check(t) != TR_OK)
    ERR("tr_dectable_check: %s", tr_last_error());
  mpq_t vold, vnew, x;
  mpq_init(vold), mpq_init(vnew), mpq_init(x);
  int bad = 0;
  /* (a) */
  for (int j = 0; j < t->nold && !bad; j++) {
    const uint8_t *o = t->old[j];
    qv_det(x, &P[o[0]], &P[o[1]], &P[o[2]], &P[o[3]]);
    if (mpq_sgn(x) <= 0)
      bad = 1;
    mpq_add(vold, vold, x);
  }
  for (int r = 0; r < t->nnew && bad == 0; r++) {
    const uint8_t *v = t->tets[r].v;
    qv_det(x, &P[v[0]], &P[v[1]], &P[v[2]], &P[v[3]]);
    if (mpq_sgn(x) <= 0)
      bad = 2 + r;
    mpq_add(vnew, vnew, x);
  }
  int same_vol = mpq_equal(vold, vnew);
  mpq_clear(vold), mpq_clear(vnew), mpq_clear(x);
  if (bad == 1)
    ERR("configuration: an old tet is not positive");
  if (bad)
    ERR("row %d %s%s%s%s is not positively oriented", bad - 1,
        tr_dv_name(t->tets[bad - 2].v[0]), tr_dv_name(t->tets[bad - 2].v[1]),
        tr_dv_name(t->tets[bad - 2].v[2]), tr_dv_name(t->tets[bad - 2].v[3]));
  /* (b) */
  if (!same_vol)
    ERR("volumes of the new tets do not add up to the old ones");
  /* (c), (d) */
  for (int r = 0; r < t->nnew; r++) {
    const tr_dtet *d = &t->tets[r];
    for (int k = 0; k < 4; k++) {
      uint8_t f[3], g[3];
      tr_dtet_face_sorted(d, k, f);
      int count = 0, other = -1, ok_other = 0;
      for (int r2 = 0; r2 < t->nnew; r2++)
        for (int k2 = 0; k2 < 4; k2++) {
          tr_dtet_face_sorted(&t->tets[r2], k2, g);
          if (same_set3(f, g)) {
            count++;
            if (r2 != r) {
              other = r2;
              ok_other = qv_orient(&P[f[0]], &P[f[1]], &P[f[2]], &P[d->v[k]]) *
                             qv_orient(&P[f[0]], &P[f[1]], &P[f[2]],
                                       &P[t->tets[r2].v[k2]]) <
                         0;
            }
          }
        }
      const tr_dnb *n = &d->n[k];
      if (n->kind == TR_DNB_INTERNAL) {
        if (count != 2 || other != n->tet || !ok_other)
          ERR("row %d N%d: internal face not shared by exactly row %d on the other side",
              r + 1, k + 1, n->tet + 1);
        continue;
      }
      if (count != 1)
        ERR("row %d N%d: boundary face belongs to %d new tets", r + 1, k + 1, count);
      int j = n->kind == TR_DNB_NG ? n->tet : 0;
      int vi = tr_dectable_old_index(t, j, n->vtx);
      if (vi < 0)
        ERR("row %d N%d: no such old face", r + 1, k + 1);
      uint8_t of[3], og[3];
      old_face_sorted(t, j, vi, of);
      for (int j2 = 0; j2 < t->nold; j2++)
        for (int v2 = 0; v2 < 4; v2++) {
          if (j2 == j)
            continue;
          old_face_sorted(t, j2, v2, og);
          if (same_set3(of, og))
            ERR("row %d N%d: names an old face inside the old region", r + 1, k + 1);
        }
      for (int i = 0; i < 3; i++)
        if (!in_closed_triangle(&P[f[i]], &P[of[0]], &P[of[1]], &P[of[2]]))
          ERR("row %d N%d: vertex %s is not on the old face opposite %s", r + 1, k + 1,
              tr_dv_name(f[i]), tr_dv_name(n->vtx));
    }
  }
  /* (e) */
  {
    qv n, u, v;
    qv_init(&n), qv_init(&u), qv_init(&v);
    const qv *p0 = &P[cf->poly[0]];
    qv_sub(&u, &P[cf->poly[1]], p0);
    qv_sub(&v, &P[cf->poly[2]], p0);
    qv_cross(&n, &u, &v);
    mpq_t want, got, a;
    mpq_init(want), mpq_init(got), mpq_init(a);
    for (int i = 1; i + 1 < cf->npoly; i++) {
      area_n(a, p0, &P[cf->poly[i]], &P[cf->poly[i + 1]], &n);
      mpq_add(want, want, a);
    }
    int err = 0;
    int cside[TR_DV_COUNT]; /* side of each name w.r.t. the cut plane */
    for (int x = 0; x < TR_DV_COUNT; x++)
      cside[x] = qv_orient(p0, &P[cf->poly[1]], &P[cf->poly[2]], &P[x]);
    /* Each face in the plane is counted once: from the tet on its positive side. */
    for (int r = 0; r < t->nnew && !err; r++)
      for (int k = 0; k < 4 && !err; k++) {
        const uint8_t *w = t->tets[r].v;
        int in_plane = 1, only_poly = 1;
        for (int i = 0; i < 4; i++) {
          if (i == k)
            continue;
          in_plane &= cside[w[i]] == 0;
          int inp = 0;
          for (int q = 0; q < cf->npoly; q++)
            inp |= cf->poly[q] == w[i];
          only_poly &= inp;
        }
        if (!in_plane)
          continue;
        if (!only_poly)
          err = 1;
        if (cside[w[k]] > 0) {
          uint8_t f[3];
          tr_dtet_face_sorted(&t->tets[r], k, f);
          area_n(a, &P[f[0]], &P[f[1]], &P[f[2]], &n);
          mpq_add(got, got, a);
        }
      }
    int same = mpq_equal(want, got);
    mpq_clear(want), mpq_clear(got), mpq_clear(a);
    qv_clear(&n), qv_clear(&u), qv_clear(&v);
    if (err)
      ERR("a face in the cut plane has a vertex that is not a corner of the cut polygon");
    if (!same)
      ERR("the faces in the cut plane do not add up to the cut polygon");
  }
  /* (f) */
  if (dtype) {
    for (uint8_t x = TR_DV_A; x <= TR_DV_D; x++) {
      int g = geometric_dtype(t, cf, x);
      int s = tr_dtype_of_table(t, x);
      int want = dtype[x];
      if (g == -2)
        ERR("face opposite %s: new faces show neither or both diagonals", tr_dv_name(x));
      if (g != want)
        ERR("face opposite %s: geometry says %d, case says %d", tr_dv_name(x), g, want);
      if (s != want)
        ERR("face opposite %s: tr_dtype_of_table says %d, case says %d", tr_dv_name(x), s,
            want);
    }
  }
  return 0;
}

/* H from the library's rule, copied into the configuration. */
int place_h(config *cf, const tr_cluster_case *c)
{
  if (c->nh == 0)
    return 0;
  tr_qpoint q[TR_DV_COUNT], h;
  const tr_point *pp[TR_DV_COUNT];
  tr_point pt[TR_DV_COUNT];
  for (int i = 0; i < TR_DV_COUNT; i++) {
    tr_qpoint_init(&q[i]);
    for (int k = 0; k < 3; k++)
      mpq_set(q[i].c[k], cf->p[i].c[k]);
    tr_qpoint_update(&q[i]);
    pt[i] = tr_pt_q(&q[i]);
    pp[i] = &pt[i];
  }
  tr_qpoint_init(&h);
  tr_status st = tr_cluster_make_h(c, pp, &h);
  for (int k = 0; k < 3; k++)
    mpq_set(cf->p[TR_DV_H].c[k], h.c[k]);
  tr_qpoint_clear(&h);
  for (int i = 0; i < TR_DV_COUNT; i++)
    tr_qpoint_clear(&q[i]);
  return st != TR_OK;
}
