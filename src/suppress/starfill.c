/* Removal of an interior Steiner point by the retriangulation of its star (issue 16).
 *
 * The star of an interior point p (every tet on p; no constraint face contains p, its
 * tets are of one region) is a polyhedron bounded by p's link, a triangulated sphere.
 * Without p it is retriangulated as the Delaunay tetrahedralization of its vertices
 * (recover_facets/ldt.h, facet recovery's) restricted to it: each boundary face must be a
 * face of that Delaunay mesh with a tet on its inner side, and the new tets are those
 * reached from the boundary faces without crossing one. Where a boundary face is missing,
 * the tet behind it joins the cavity and its vertices the Delaunay mesh (Si's cavity
 * expansion, as in facet recovery), unless that face is a constraint (the domain's
 * boundary, a face between regions, a sub-face): then p stays. A vertex the expansion
 * takes inside the cavity must be kept by the new tets. Unlike the cone from a link
 * vertex (star.c) this needs no vertex that sees the whole link, and unlike the flips
 * (flipout.c) no sequence of edge removals at p.
 *
 * What it cannot do: a star whose link has no tetrahedralization without Steiner points
 * (a Schoenhardt-like link, or a lattice hexahedron with twisted face diagonals on the
 * surface, as in CGAL's cube-meshed and cross_quad) stays, since the surface faces of
 * the link are never expanded across.
 *
 * Every new tet is checked exactly positive (and, with dbl, positive at its vertices'
 * doubles: rounding cannot repair a flat shape); tr_mesh_replace checks that the new tets
 * have exactly the boundary of the cavity, so every constraint on it stays as it was. A
 * refusal leaves the mesh untouched. */
#include <stdlib.h>
#include <string.h>

#include "recover_facets/ldt.h"
#include "suppress_int.h"

/* the most vertices a cavity may have (the local Delaunay is quadratic in them) */
#define SUP_FILL_MAX_LINK 160

static int cmp_u32(const void *a, const void *b)
{
  uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
  return (x > y) - (x < y);
}

/* Sorts b and drops its repeats (the region and the vertex list are sets, kept sorted
 * for bsearch). */
static void sort_unique(tr_u32buf *b)
{
  qsort(b->a, b->n, sizeof *b->a, cmp_u32);
  size_t n = 0;
  for (size_t i = 0; i < b->n; i++)
    if (n == 0 || b->a[i] != b->a[n - 1])
      b->a[n++] = b->a[i];
  b->n = n;
}

static uint32_t local_id(const uint32_t *gid, uint32_t n, uint32_t v)
{
  const uint32_t *r = bsearch(&v, gid, n, sizeof v, cmp_u32);
  return r ? (uint32_t)(r - gid) : TR_NONE;
}

static int dbl_positive(const struct tr_mesh *m, const uint32_t v[4])
{
  tr_point q[4];
  for (int k = 0; k < 4; k++)
    q[k] = tr_pt_d(m->xyz + 3 * (size_t)v[k]);
  return tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0;
}

enum { FILL_OK, FILL_MISSING, FILL_FAIL };

/* The cavity: its tets (sorted), its boundary faces (t, k) with the vertices in
 * tr_face_vtx order (the cavity on their positive side), its vertices but p (sorted). */
typedef struct fillcav {
  tr_u32buf reg, bt, bv, gid, missing; /* missing: indices into bt of faces not found */
  int by_dbl; /* the last fill was refused by a new tet flat at doubles only */
} fillcav;

static int in_reg(const fillcav *c, uint32_t t)
{
  return bsearch(&t, c->reg.a, c->reg.n, sizeof t, cmp_u32) != NULL;
}

static tr_status collect(const struct tr_mesh *m, uint32_t p, fillcav *c)
{
  c->bt.n = c->bv.n = c->gid.n = 0;
  for (size_t i = 0; i < c->reg.n; i++) {
    uint32_t t = c->reg.a[i];
    for (int k = 0; k < 4; k++) {
      uint32_t v = m->tv[4 * (size_t)t + k], nb = TR_NEIG(m, t, k);
      if (v != p)
        TR_CHECK(tr_u32buf_push(&c->gid, v));
      if (nb != TR_NONE && in_reg(c, nb))
        continue;
      TR_CHECK(tr_u32buf_push(&c->bt, 4 * t + (uint32_t)k));
      for (int a = 0; a < 3; a++)
        TR_CHECK(tr_u32buf_push(&c->bv, m->tv[4 * (size_t)t + tr_face_vtx[k][a]]));
    }
  }
  sort_unique(&c->gid);
  return TR_OK;
}

/* The cavity's retriangulation without p (global ids, 4 each) into out: *res = FILL_OK;
 * FILL_MISSING with c->missing listing the boundary faces the Delaunay mesh lacks;
 * FILL_FAIL for any other refusal. */
static tr_status fill(struct tr_mesh *m, uint32_t p, fillcav *c, int dbl, tr_u32buf *out,
                      int *res)
{
  *res = FILL_FAIL;
  c->by_dbl = 0;
  TR_CHECK(collect(m, p, c));
  uint32_t n = (uint32_t)c->gid.n, nb = (uint32_t)(c->bt.n);
  if (n > SUP_FILL_MAX_LINK || n < 4)
    return TR_OK;
  const uint32_t *gid = c->gid.a; /* local id -> vertex, ascending */
  uint32_t *link = malloc(sizeof *link * 3 * (nb ? nb : 1));
  tr_ldt_face *wall = malloc(sizeof *wall * (nb ? nb : 1));
  tr_point *pts = malloc(sizeof *pts * n);
  uint8_t *used = calloc(n, 1);
  tr_ldt D;
  memset(&D, 0, sizeof D);
  tr_ldt_face *ft = NULL;
  uint32_t nft = 0, *queue = NULL;
  uint8_t *seen = NULL;
  tr_status st = TR_OK;
  if (!link || !wall || !pts || !used) {
    st = tr_error(TR_ERR_NOMEM, "out of memory removing a point");
    goto done;
  }
  for (uint32_t i = 0; i < n; i++)
    pts[i] = tr_mesh_point(m, gid[i]);
  for (size_t i = 0; i < 3 * (size_t)nb; i++)
    link[i] = local_id(gid, n, c->bv.a[i]);
  int built = 0;
  if ((st = tr_ldt_build(&D, pts, n, &built)) != TR_OK || !built)
    goto done;
  if ((st = tr_ldt_faces(&D, &ft, &nft)) != TR_OK)
    goto done;
  queue = malloc(sizeof *queue * (D.n ? D.n : 1));
  seen = calloc(D.n ? D.n : 1, 1);
  if (!queue || !seen) {
    st = tr_error(TR_ERR_NOMEM, "out of memory removing a point");
    goto done;
  }
  /* each boundary face must hold a Delaunay tet on its inner side: the flood's seeds */
  uint32_t nq = 0;
  c->missing.n = 0;
  for (uint32_t i = 0; i < nb && st == TR_OK; i++) {
    uint32_t j = tr_ldt_find_turned(&D, ft, nft, link + 3 * (size_t)i);
    if (j == TR_NONE) {
      st = tr_u32buf_push(&c->missing, i);
      continue;
    }
    memcpy(wall[i].k, link + 3 * (size_t)i, sizeof wall[i].k);
    tr_sort3(wall[i].k);
    wall[i].tet = wall[i].face = 0;
    if (!seen[j]) {
      seen[j] = 1;
      queue[nq++] = j;
    }
  }
  if (st != TR_OK)
    goto done;
  if (c->missing.n) {
    *res = FILL_MISSING;
    goto done;
  }
  qsort(wall, nb, sizeof *wall, tr_cmp_face_key);
  for (uint32_t h = 0; h < nq; h++) {
    uint32_t j = queue[h];
    for (uint32_t k = 0; k < 4; k++) {
      uint32_t f[3];
      tr_ldt_face_of(D.t[j], (int)k, f);
      tr_sort3(f);
      if (bsearch(f, wall, nb, sizeof *wall, tr_cmp_face_key))
        continue;
      uint32_t o = tr_ldt_across(&D, ft, nft, j, k);
      if (o == TR_NONE)
        goto done; /* leaked onto the hull: the boundary faces do not close the region */
      if (!seen[o]) {
        seen[o] = 1;
        queue[nq++] = o;
      }
    }
  }
  out->n = 0;
  for (uint32_t h = 0; h < nq; h++) {
    const uint32_t *t = D.t[queue[h]];
    if (tr_orient3d_p(&pts[t[0]], &pts[t[1]], &pts[t[2]], &pts[t[3]]) <= 0)
      goto done;
    uint32_t v[4] = {gid[t[0]], gid[t[1]], gid[t[2]], gid[t[3]]};
    if (dbl && !dbl_positive(m, v)) {
      c->by_dbl = 1;
      goto done;
    }
    for (int q = 0; q < 4 && st == TR_OK; q++) {
      used[t[q]] = 1;
      st = tr_u32buf_push(out, v[q]);
    }
    if (st != TR_OK)
      goto done;
  }
  /* a vertex the expansion took inside must not be lost */
  for (uint32_t i = 0; i < n; i++)
    if (!used[i])
      goto done;
  *res = FILL_OK;
done:
  free(link);
  free(wall);
  free(pts);
  free(used);
  free(ft);
  free(queue);
  free(seen);
  tr_ldt_free(&D);
  return st;
}

/* 1 iff face (t, k) is a sub-face of the working sub-faces. */
static tr_status is_subface(const sup_ctx *c, const struct tr_mesh *m, uint32_t t, int k,
                            tr_u32buf *tmp, int *yes)
{
  uint32_t w[3];
  for (int a = 0; a < 3; a++)
    w[a] = m->tv[4 * (size_t)t + tr_face_vtx[k][a]];
  return sup_is_sub(c, w, tmp, yes);
}

/* Si's expansion: the tet behind each missing boundary face joins the cavity, unless
 * the face is a constraint (the domain's boundary, another region's, a sub-face):
 * *ok = 0 then. */
static tr_status expand(struct tr_mesh *m, const sup_ctx *sc, fillcav *c, uint32_t region,
                        int *ok)
{
  tr_u32buf tmp = {0};
  tr_status st = TR_OK;
  *ok = 1;
  size_t n0 = c->reg.n;
  for (size_t i = 0; i < c->missing.n && *ok && st == TR_OK; i++) {
    uint32_t code = c->bt.a[c->missing.a[i]], t = code >> 2, nb = TR_NEIG(m, t, (int)(code & 3));
    int sub = 0;
    if (nb == TR_NONE || !tr_tet_is_real(m, nb) || (m->region && m->region[nb] != region)) {
      *ok = 0;
      break;
    }
    if (sc && ((st = is_subface(sc, m, t, (int)(code & 3), &tmp, &sub)) != TR_OK || sub)) {
      *ok = 0;
      break;
    }
    st = tr_u32buf_push(&c->reg, nb);
  }
  tr_u32buf_free(&tmp);
  if (st != TR_OK || !*ok)
    return st;
  sort_unique(&c->reg);
  *ok = c->reg.n > n0;
  return TR_OK;
}

tr_status sup_star_fill(struct tr_mesh *m, const sup_ctx *sc, uint32_t p, uint32_t region,
                        int dbl, int rounds, uint32_t *tnew, int *done, int *by_dbl)
{
  *done = 0;
  if (by_dbl)
    *by_dbl = 0;
  *tnew = TR_NONE;
  fillcav c;
  memset(&c, 0, sizeof c);
  tr_u32buf nv = {0};
  uint32_t *ids = NULL;
  tr_status st = tr_ball(m, p, 1, &c.reg);
  int ok = c.reg.n >= 4, res = FILL_FAIL;
  for (size_t i = 0; i < c.reg.n && ok; i++)
    ok = tr_tet_is_real(m, c.reg.a[i]);
  if (st == TR_OK && ok)
    qsort(c.reg.a, c.reg.n, sizeof *c.reg.a, cmp_u32);
  for (int round = 0; st == TR_OK && ok; round++) {
    if ((st = fill(m, p, &c, dbl, &nv, &res)) != TR_OK || res != FILL_MISSING)
      break;
    if (round >= rounds)
      break;
    st = expand(m, sc, &c, region, &ok);
  }
  ok = st == TR_OK && res == FILL_OK;
  if (by_dbl)
    *by_dbl = c.by_dbl;
  uint32_t nnew = (uint32_t)(nv.n / 4);
  if (ok && !(ids = malloc(sizeof *ids * (nnew ? nnew : 1))))
    st = tr_error(TR_ERR_NOMEM, "out of memory removing a point");
  if (st == TR_OK && ok) {
    st = tr_mesh_replace(m, c.reg.a, (uint32_t)c.reg.n, nv.a, nnew, ids);
    if (st == TR_ERR_INTERNAL) { /* not the cavity's boundary: refused, mesh unchanged */
      st = TR_OK;
      ok = 0;
    }
  }
  if (st == TR_OK && ok) {
    for (uint32_t i = 0; i < nnew && m->region; i++)
      m->region[ids[i]] = region;
    m->v2t[p] = TR_NONE;
    *tnew = nnew ? ids[0] : TR_NONE;
    *done = nnew > 0;
  }
  free(ids);
  tr_u32buf_free(&c.reg);
  tr_u32buf_free(&c.bt);
  tr_u32buf_free(&c.bv);
  tr_u32buf_free(&c.gid);
  tr_u32buf_free(&c.missing);
  tr_u32buf_free(&nv);
  return st;
}
