/* The property --keep-surface promises, checked on an output mesh: every boundary face
 * (no tet behind, or a tet of another region) is an input triangle, none of their
 * vertices is a Steiner point, and no Steiner point lies on an input triangle (exact), so
 * with the exact conformity validator's covering no input triangle is split: a crack's
 * or an internal facet's triangles too, which have tets of one region on both sides.
 * Without internal facets or cracks the boundary faces are then exactly the input
 * triangles. Mesh vertices are
 * matched to the PLC's points by their coordinates (the output numbers only the points
 * some tet uses). */
#ifndef TR_TESTS_SUPPRESS_KEEPCHECK_H
#define TR_TESTS_SUPPRESS_KEEPCHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "mesh/mesh.h"

static int keep_cmp3(const void *a, const void *b)
{
  return tr_cmp_face_key(a, b);
}

static const double *keep_xyz; /* the points keep_cmp_pt orders */
static int keep_cmp_pt(const void *a, const void *b)
{
  const double *x = keep_xyz + 3 * (size_t)*(const uint32_t *)a,
               *y = keep_xyz + 3 * (size_t)*(const uint32_t *)b;
  for (int i = 0; i < 3; i++)
    if (x[i] != y[i])
      return x[i] < y[i] ? -1 : 1;
  return 0;
}

/* Sorts n keys of 3 and drops repeats; returns the new n. */
static size_t keep_unique3(uint32_t *k, size_t n)
{
  qsort(k, n, 3 * sizeof *k, keep_cmp3);
  size_t j = 0;
  for (size_t i = 0; i < n; i++)
    if (j == 0 || tr_cmp_face_key(k + 3 * (j - 1), k + 3 * i) != 0)
      memmove(k + 3 * j++, k + 3 * i, 3 * sizeof *k);
  return j;
}

/* 0 when the property holds, else -1 with the reason in why. */
static int keep_surface_holds(const struct tr_mesh *m, const struct tr_plc *plc, char *why,
                              size_t nwhy)
{
  uint32_t *bf = malloc(sizeof *bf * 12 * (size_t)(m->nt + 1));
  uint32_t *it = malloc(sizeof *it * 3 * (size_t)(plc->ntris + 1));
  uint32_t *ord = malloc(sizeof *ord * (size_t)(plc->npoints + 1));
  int ret = -1;
  size_t nb = 0;
  if (!bf || !it || !ord) {
    snprintf(why, nwhy, "out of memory");
    goto out;
  }
  for (uint32_t i = 0; i < plc->npoints; i++)
    ord[i] = i;
  keep_xyz = plc->xyz;
  qsort(ord, plc->npoints, sizeof *ord, keep_cmp_pt);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t c = m->tn[4 * (size_t)t + k], *f = bf + 3 * nb;
      int bnd = c == TR_NONE || (m->region && m->region[c >> 2] != m->region[t]);
      if (!bnd)
        continue;
      for (int j = 0; j < 3; j++) {
        uint32_t v = m->tv[4 * (size_t)t + tr_face_vtx[k][j]];
        if (m->vq && m->vq[v]) {
          snprintf(why, nwhy, "boundary face of tet %u has Steiner point %u", t, v);
          goto out;
        }
        /* the input point with these coordinates: a key in ord's order, then its id */
        uint32_t key = plc->npoints;
        size_t lo = 0, hi = plc->npoints;
        while (lo < hi) { /* binary search of m's point among plc's sorted points */
          size_t mid = (lo + hi) / 2;
          const double *x = plc->xyz + 3 * (size_t)ord[mid], *y = m->xyz + 3 * (size_t)v;
          int cmp = 0;
          for (int i = 0; i < 3 && !cmp; i++)
            cmp = x[i] < y[i] ? -1 : x[i] > y[i];
          if (cmp == 0) {
            key = ord[mid];
            break;
          }
          if (cmp < 0)
            lo = mid + 1;
          else
            hi = mid;
        }
        if (key == plc->npoints) {
          snprintf(why, nwhy, "mesh vertex %u is no input point", v);
          goto out;
        }
        f[j] = key;
      }
      tr_sort3(f);
      nb++;
    }
  }
  for (uint32_t i = 0; i < plc->ntris; i++) {
    memcpy(it + 3 * (size_t)i, plc->tris + 3 * (size_t)i, 3 * sizeof *it);
    tr_sort3(it + 3 * (size_t)i);
  }
  nb = keep_unique3(bf, nb);
  size_t ni = keep_unique3(it, plc->ntris);
  for (size_t i = 0; i < nb; i++)
    if (!bsearch(bf + 3 * i, it, ni, 3 * sizeof *it, keep_cmp3)) {
      snprintf(why, nwhy, "boundary face (%u,%u,%u) is not an input triangle", bf[3 * i],
               bf[3 * i + 1], bf[3 * i + 2]);
      goto out;
    }
  /* no Steiner point on an input triangle (closed), by exact orientation */
  for (uint32_t v = 0; v < m->nv; v++) {
    if (!m->vq || !m->vq[v] || m->v2t[v] == TR_NONE)
      continue;
    tr_point q = tr_mesh_point(m, v);
    for (uint32_t i = 0; i < plc->ntris; i++) {
      const uint32_t *t = plc->tris + 3 * (size_t)i;
      tr_point a = tr_pt_d(plc->xyz + 3 * (size_t)t[0]), b = tr_pt_d(plc->xyz + 3 * (size_t)t[1]),
               c = tr_pt_d(plc->xyz + 3 * (size_t)t[2]);
      if (tr_orient3d_p(&a, &b, &c, &q) != 0)
        continue;
      int drop = 0, sg = 0;
      for (drop = 0; drop < 3 && !(sg = tr_orient2d_proj_p(&a, &b, &c, drop)); drop++)
        ;
      if (sg * tr_orient2d_proj_p(&a, &b, &q, drop) >= 0 &&
          sg * tr_orient2d_proj_p(&b, &c, &q, drop) >= 0 &&
          sg * tr_orient2d_proj_p(&c, &a, &q, drop) >= 0) {
        snprintf(why, nwhy, "Steiner point %u lies on input triangle %u", v, i);
        goto out;
      }
    }
  }
  ret = 0;
out:
  free(bf);
  free(ord);
  free(it);
  return ret;
}

#endif
