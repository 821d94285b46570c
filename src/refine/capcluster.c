/* Cap clusters (refine_impl.h, rf_caps): input triangles with a corner over 179 degrees,
 * joined across their shared edges: two caps or more, or one flat cap (is_flat_cap).
 *
 * A cap's third vertex lies within a sliver of its length of its long edge, and two caps
 * that share an edge put their outer edges as close to each other with no input vertex in
 * common (32770.stl: edges 18905-18942 and 18910-18911, 0.34 and 0.22 long, about 1e-5
 * apart along 0.2). The small-angle rules of angles.c see no wedge between such edges, so
 * refinement split each for the points on the other down to pieces about their distance
 * apart: 3,300 pieces on four edges and 27k of the model's 164k vertices, with 83% of the
 * refinement CPU spent on the needle tets between them. Those tets cannot be made good
 * short of that: every boundary face inside a cap is as thin as the cap. So the
 * constraints of one cluster are treated as meeting at a small angle (angles.c): a piece
 * of one is not split for a point on another, and a bad tet whose shortest edge joins two
 * of them is left, as in any small-angle wedge.
 *
 * Angles are measured in doubles on the input's vertices, like those of angles.c: they
 * choose which points are inserted, never how the mesh is connected. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/ufind.h"
#include "refine/refine_impl.h"

#define RF_CAP_COS (-0.9998476951563913) /* cos 179 degrees */

/* A lone cap whose apex lies within RF_CAP_FLAT of its long edge's length from that edge
 * counts as a cluster of its own. Refinement separates the apex from the edge by splitting
 * the edge down to pieces about the apex's height: log2(1 / RF_CAP_FLAT) levels and more,
 * each with its ring of points, for sub-faces that stay as thin as the cap whatever is
 * split. The caps of 93703.stl (two) are 2e-15 and 1e-14 of their edge off it, flat but
 * for the last bits of the doubles: 93703 took 3.6 s and 31,535 tets (5.6% under 10
 * degrees) with them split down, 1.2 s and 17,250 (3.0%) as clusters. anchor_dense.off's
 * cap is 1e-5 off its edge, about 17 levels: those splits pay (its smallest angle is 1.6
 * degrees with them, 0.07 as a cluster). */
#define RF_CAP_FLAT 0x1p-32

/* The corner of triangle t over 179 degrees (0..2), or -1: t is no cap. */
static int cap_corner(const struct tr_plc *plc, uint32_t t)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  for (int k = 0; k < 3; k++)
    if (rf_cos_angle(plc->xyz + 3 * (size_t)T[k], plc->xyz + 3 * (size_t)T[(k + 1) % 3],
                     plc->xyz + 3 * (size_t)T[(k + 2) % 3]) < RF_CAP_COS)
      return k;
  return -1;
}

static int is_cap(const struct tr_plc *plc, uint32_t t)
{
  return cap_corner(plc, t) >= 0;
}

/* The apex of cap t within RF_CAP_FLAT of its long edge's length from it: |u x w| < FLAT
 * |u|^2 for u the edge and w the apex from its first end, both scaled by one power of two
 * (exact) so that no square overflows or underflows at the input's scale. */
static int is_flat_cap(const struct tr_plc *plc, uint32_t t)
{
  int k = cap_corner(plc, t);
  if (k < 0)
    return 0;
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  const double *o = plc->xyz + 3 * (size_t)T[k], *a = plc->xyz + 3 * (size_t)T[(k + 1) % 3],
               *b = plc->xyz + 3 * (size_t)T[(k + 2) % 3];
  double u[3], w[3], big = 0;
  for (int i = 0; i < 3; i++) {
    u[i] = b[i] - a[i];
    w[i] = o[i] - a[i];
    big = fmax(big, fmax(fabs(u[i]), fabs(w[i])));
  }
  if (!(big > 0) || !isfinite(big))
    return 0;
  int e;
  frexp(big, &e);
  for (int i = 0; i < 3; i++) {
    u[i] = ldexp(u[i], -e);
    w[i] = ldexp(w[i], -e);
  }
  double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) < RF_CAP_FLAT * uu;
}

void rf_caps_free(rf_caps *k)
{
  tr_vtmap_free(&k->edge);
  free(k->vert);
  free(k->tri);
  memset(k, 0, sizeof *k);
}

tr_status rf_caps_build(rf_caps *k, const struct tr_plc *plc)
{
  rf_caps_free(k);
  uint32_t ncap = 0;
  for (uint32_t t = 0; t < plc->ntris; t++)
    ncap += (uint32_t)is_cap(plc, t);
  if (!ncap)
    return TR_OK;
  /* union-find over the triangles, only caps joined; a cluster is named by its smallest
   * cap (the root is kept the smaller of the two) */
  uint32_t *up = malloc(sizeof *up * (size_t)plc->ntris);
  k->tri = malloc(sizeof *k->tri * (size_t)plc->ntris);
  k->vert = malloc(sizeof *k->vert * (size_t)(plc->npoints ? plc->npoints : 1));
  tr_vtmap owner = {0}; /* cap edge -> a cap on it */
  tr_status s = up && k->tri && k->vert ? TR_OK
                                        : tr_error(TR_ERR_NOMEM, "out of memory for cap clusters");
  for (uint32_t t = 0; s == TR_OK && t < plc->ntris; t++) {
    up[t] = t;
    k->tri[t] = is_cap(plc, t) ? t : TR_NONE;
  }
  for (uint32_t t = 0; s == TR_OK && t < plc->ntris; t++) {
    if (k->tri[t] == TR_NONE)
      continue;
    const uint32_t *T = plc->tris + 3 * (size_t)t;
    for (int e = 0; e < 3 && s == TR_OK; e++) {
      uint32_t key[2];
      tr_vtkey_edge(T[e], T[(e + 1) % 3], key);
      uint32_t o = tr_vtmap_get(&owner, 2, key);
      if (o == TR_VTMAP_NONE) {
        s = tr_vtmap_set(&owner, 2, key, t);
        continue;
      }
      tr_uf_unite(up, o, t);
    }
  }
  if (s == TR_OK)
    memset(k->vert, 0xff, sizeof *k->vert * (size_t)plc->npoints);
  /* a cap alone is no cluster unless flat (is_flat_cap): its edges meet at its two sharp
   * corners, where the rules of angles.c already stop the descent, and the points its apex
   * makes on its long edge are a few levels of splits (anchor_dense.off's one cap:
   * smallest angle 1.6 degrees with them, 0.07 when it counted as a cluster) */
  uint32_t *size = s == TR_OK ? calloc(plc->ntris, sizeof *size) : NULL;
  if (s == TR_OK && !size)
    s = tr_error(TR_ERR_NOMEM, "out of memory for cap clusters");
  for (uint32_t t = 0; s == TR_OK && t < plc->ntris; t++)
    if (k->tri[t] != TR_NONE)
      size[tr_uf_find(up, t)]++;
  ncap = 0;
  for (uint32_t t = 0; s == TR_OK && t < plc->ntris; t++) {
    if (k->tri[t] == TR_NONE)
      continue;
    uint32_t cl = tr_uf_find(up, t);
    if (size[cl] < 2 && !is_flat_cap(plc, t)) {
      k->tri[t] = TR_NONE;
      continue;
    }
    ncap++;
    k->tri[t] = cl;
    const uint32_t *T = plc->tris + 3 * (size_t)t;
    for (int e = 0; e < 3 && s == TR_OK; e++) {
      uint32_t key[2];
      tr_vtkey_edge(T[e], T[(e + 1) % 3], key);
      s = tr_vtmap_set(&k->edge, 2, key, cl);
      if (k->vert[T[e]] == TR_NONE || cl < k->vert[T[e]])
        k->vert[T[e]] = cl;
    }
  }
  k->n = ncap;
  free(up);
  free(size);
  tr_vtmap_free(&owner);
  if (s != TR_OK || !ncap)
    rf_caps_free(k);
  return s;
}

tr_status rf_caps_copy(rf_caps *dst, const rf_caps *src, const struct tr_plc *plc)
{
  rf_caps_free(dst);
  if (!src->n)
    return TR_OK;
  dst->tri = malloc(sizeof *dst->tri * (size_t)plc->ntris);
  dst->vert = malloc(sizeof *dst->vert * (size_t)plc->npoints);
  if (!dst->tri || !dst->vert) {
    rf_caps_free(dst);
    return tr_error(TR_ERR_NOMEM, "out of memory for cap clusters");
  }
  memcpy(dst->tri, src->tri, sizeof *dst->tri * (size_t)plc->ntris);
  memcpy(dst->vert, src->vert, sizeof *dst->vert * (size_t)plc->npoints);
  dst->n = src->n;
  tr_status s = tr_vtmap_copy(&dst->edge, &src->edge);
  if (s != TR_OK)
    rf_caps_free(dst);
  return s;
}

uint32_t rf_caps_edge(const rf_caps *k, uint32_t a, uint32_t b)
{
  if (!k->n)
    return TR_NONE;
  uint32_t key[2];
  tr_vtkey_edge(a, b, key);
  uint32_t cl = tr_vtmap_get(&k->edge, 2, key);
  return cl == TR_VTMAP_NONE ? TR_NONE : cl;
}
