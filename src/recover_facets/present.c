/* The presence test of a facet and its sub-faces (see facet.h for the argument). Areas
 * are compared in the projection that drops an axis along which F's normal has a
 * non-zero component: the projection scales every area in F's plane by the same
 * non-zero factor, so equal projected sums mean equal areas, and the sign of a projected
 * area says whether a face turns like F. */
#include "recover_facets/facet.h"

#include <stdlib.h>

#include "recover_facets/cluster.h"

/* out = doubled signed area of abc projected along axis drop (axes drop+1, drop+2 in
 * that cyclic order, as tr_orient2d_proj_p). */
static void proj_area(mpq_t out, const tr_point *a, const tr_point *b, const tr_point *c,
                      int drop, mpq_t *tmp)
{
  int i = (drop + 1) % 3, j = (drop + 2) % 3;
  mpq_t *ax = tmp, *ay = tmp + 1, *u = tmp + 2, *v = tmp + 3, *w = tmp + 4;
  tr_point_get_q(a, i, *ax);
  tr_point_get_q(a, j, *ay);
  tr_point_get_q(b, i, *u);
  mpq_sub(*u, *u, *ax);        /* bx - ax */
  tr_point_get_q(c, j, *v);
  mpq_sub(*v, *v, *ay);        /* cy - ay */
  mpq_mul(out, *u, *v);
  tr_point_get_q(b, j, *u);
  mpq_sub(*u, *u, *ay);        /* by - ay */
  tr_point_get_q(c, i, *v);
  mpq_sub(*v, *v, *ax);        /* cx - ax */
  mpq_mul(*w, *u, *v);
  mpq_sub(out, out, *w);
}

/* The projection axis for F, or -1 when F is degenerate. */
static int facet_axis(const struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g, int *sign)
{
  tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
  for (int d = 0; d < 3; d++) {
    int s = tr_orient2d_proj_p(&pe, &pf, &pg, d);
    if (s) {
      *sign = s;
      return d;
    }
  }
  return -1;
}

tr_status tr_facet_faces(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                         int *present, tr_u32buf *faces)
{
  *present = 0;
  int fsign = 0;
  if (facet_axis(m, e, f, g, &fsign) < 0)
    return tr_error(TR_ERR_UNSUPPORTED, "facet %u (%u %u %u) is degenerate", idx, e, f, g);
  tr_clusterel *cl = NULL;
  uint32_t ncl = 0;
  TR_CHECK(tr_cluster_collect(m, e, f, g, &cl, &ncl));
  tr_status st = tr_facet_faces_of_cluster(m, idx, e, f, g, cl, ncl, 1, present, faces);
  free(cl);
  return st;
}

tr_status tr_facet_faces_of_cluster(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f,
                                    uint32_t g, const tr_clusterel *cl, uint32_t ncl,
                                    int area_check, int *present, tr_u32buf *faces)
{
  *present = 0;
  int fsign = 0, drop = facet_axis(m, e, f, g, &fsign);
  if (drop < 0)
    return tr_error(TR_ERR_UNSUPPORTED, "facet %u (%u %u %u) is degenerate", idx, e, f, g);
  for (uint32_t i = 0; i < ncl; i++)
    if (cl[i].type != TR_CO_PLAN)
      return TR_OK; /* a tet crosses F: missing */
  /* The coplanar faces, each once (both tets around it are CO_PLAN clusterels). */
  uint32_t *tri = malloc(3 * (size_t)(ncl ? ncl : 1) * sizeof *tri);
  if (!tri)
    return tr_error(TR_ERR_NOMEM, "facet %u: out of memory", idx);
  uint32_t nt = 0;
  for (uint32_t i = 0; i < ncl; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)cl[i].iele;
    const uint8_t *fv = tr_face_vtx[(int)cl[i].face];
    uint32_t w[3] = {tv[fv[0]], tv[fv[1]], tv[fv[2]]}, t;
    if (w[0] > w[1]) { t = w[0]; w[0] = w[1]; w[1] = t; }
    if (w[1] > w[2]) { t = w[1]; w[1] = w[2]; w[2] = t; }
    if (w[0] > w[1]) { t = w[0]; w[0] = w[1]; w[1] = t; }
    for (int q = 0; q < 3; q++)
      tri[3 * nt + q] = w[q];
    nt++;
  }
  qsort(tri, nt, 3 * sizeof *tri, tr_cmp_face_key);
  uint32_t nu = 0;
  for (uint32_t i = 0; i < nt; i++)
    if (nu == 0 || tr_cmp_face_key(tri + 3 * i, tri + 3 * (nu - 1)) != 0) {
      for (int q = 0; q < 3; q++)
        tri[3 * nu + q] = tri[3 * i + q];
      nu++;
    }
  /* Exact area sum; orient each face like F on the way. */
  mpq_t sum, a, tmp[5];
  mpq_init(sum);
  mpq_init(a);
  for (int q = 0; q < 5; q++)
    mpq_init(tmp[q]);
  for (uint32_t i = 0; i < nu; i++) {
    uint32_t *w = tri + 3 * i;
    tr_point p0 = tr_mesh_point(m, w[0]), p1 = tr_mesh_point(m, w[1]),
             p2 = tr_mesh_point(m, w[2]);
    if (!area_check) {
      if (tr_orient2d_proj_p(&p0, &p1, &p2, drop) != fsign) {
        uint32_t t = w[1];
        w[1] = w[2];
        w[2] = t;
      }
      continue;
    }
    proj_area(a, &p0, &p1, &p2, drop, tmp);
    if (mpq_sgn(a) != fsign) { /* never 0: a mesh face is not flat */
      uint32_t t = w[1];
      w[1] = w[2];
      w[2] = t;
      mpq_neg(a, a);
    }
    mpq_add(sum, sum, a);
  }
  int equal = 1;
  if (area_check) {
    tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
    proj_area(a, &pe, &pf, &pg, drop, tmp);
    equal = mpq_equal(sum, a);
  }
  mpq_clear(sum);
  mpq_clear(a);
  for (int q = 0; q < 5; q++)
    mpq_clear(tmp[q]);
  tr_status st = TR_OK;
  if (!equal) {
    st = tr_error(TR_ERR_INTERNAL,
                  "facet %u (%u %u %u): no tet crosses it but its %u coplanar faces do not "
                  "cover it", idx, e, f, g, nu);
  } else {
    *present = 1;
    if (faces) {
      for (uint32_t i = 0; i < nu; i++)
        tr_rotate_min3(tri + 3 * i);
      qsort(tri, nu, 3 * sizeof *tri, tr_cmp_face_key);
      for (uint32_t i = 0; i < 3 * nu && st == TR_OK; i++)
        st = tr_u32buf_push(faces, tri[i]);
    }
  }
  free(tri);
  return st;
}
