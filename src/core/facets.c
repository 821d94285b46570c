/* Planar facets of the input (facets.h): union-find over the triangles, each pair tested
 * with exact predicates on the input doubles. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/ufind.h"
#include "core/edgesort.h"
#include "core/facets.h"
#include "predicates.h"
#include "qpoint.h"

#define NONE UINT32_MAX /* TR_NONE, which is mesh.h's */

int tr_plc_tri_axis(const struct tr_plc *plc, uint32_t t)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  if (plc->xq) {
    tr_point a = tr_plc_point(plc, T[0]), b = tr_plc_point(plc, T[1]),
             c = tr_plc_point(plc, T[2]);
    for (int k = 0; k < 3; k++)
      if (tr_orient2d_proj_p(&a, &b, &c, k) != 0)
        return k;
    return -1;
  }
  const double *x = plc->xyz;
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj(x + 3 * (size_t)T[0], x + 3 * (size_t)T[1], x + 3 * (size_t)T[2], k) !=
        0)
      return k;
  return -1;
}

int tr_plc_tri_holds(const struct tr_plc *plc, uint32_t t, int k, const tr_point *p)
{
  const uint32_t *T = plc->tris + 3 * (size_t)t;
  tr_point a = tr_plc_point(plc, T[0]), b = tr_plc_point(plc, T[1]), d = tr_plc_point(plc, T[2]);
  int s = tr_orient2d_proj_p(&a, &b, &d, k);
  return s * tr_orient2d_proj_p(&a, &b, p, k) >= 0 && s * tr_orient2d_proj_p(&b, &d, p, k) >= 0 &&
         s * tr_orient2d_proj_p(&d, &a, p, k) >= 0;
}

uint32_t tr_facets_triangle_of(const tr_facets *F, const struct tr_plc *plc, uint32_t g, int k,
                               const tr_point *p, uint32_t hint)
{
  if (hint != NONE && (F->group[hint] != g || !tr_plc_tri_holds(plc, hint, k, p)))
    hint = NONE;
  /* members are increasing, so the first that holds p is the smallest; the box test in
   * doubles only skips triangles that p's exact coordinates lie outside of */
  const double *lo = p->q ? p->q->lo : p->d, *hi = p->q ? p->q->hi : p->d;
  for (uint32_t i = F->start[g]; i < F->start[g + 1]; i++) {
    uint32_t t = F->member[i];
    if (hint != NONE && t >= hint)
      return hint;
    const uint32_t *U = plc->tris + 3 * (size_t)t;
    int out = 0;
    for (int j = 0; j < 3 && !out; j++) {
      double mn = INFINITY, mx = -INFINITY;
      for (int v = 0; v < 3; v++) {
        const tr_qpoint *q = plc->xq ? plc->xq[U[v]] : NULL;
        double x0 = q ? q->lo[j] : plc->xyz[3 * (size_t)U[v] + j];
        double x1 = q ? q->hi[j] : x0;
        mn = x0 < mn ? x0 : mn;
        mx = x1 > mx ? x1 : mx;
      }
      out = hi[j] < mn || lo[j] > mx;
    }
    if (!out && tr_plc_tri_holds(plc, t, k, p))
      return t;
  }
  return hint;
}

/* Triangles s and t on edge slots 3s+i and 3t+j (the same undirected edge) merge? */
static int mergeable(const struct tr_plc *plc, uint32_t s, int i, uint32_t t, int j)
{
  const uint32_t *S = plc->tris + 3 * (size_t)s, *T = plc->tris + 3 * (size_t)t;
  uint32_t a = S[i], b = S[(i + 1) % 3], c = S[(i + 2) % 3], d = T[(j + 2) % 3];
  if (T[j] != b || T[(j + 1) % 3] != a) /* same direction: inconsistent orientation */
    return 0;
  if (plc->tri_marker && plc->tri_marker[s] != plc->tri_marker[t])
    return 0;
  if (plc->xq) { /* exact corners: the same tests on tr_point */
    tr_point qa = tr_plc_point(plc, a), qb = tr_plc_point(plc, b), qc = tr_plc_point(plc, c),
             qd = tr_plc_point(plc, d);
    if (tr_orient3d_p(&qa, &qb, &qc, &qd) != 0)
      return 0;
    int ax = tr_plc_tri_axis(plc, s);
    if (ax < 0 || tr_plc_tri_axis(plc, t) < 0)
      return 0;
    int sc = tr_orient2d_proj_p(&qa, &qb, &qc, ax), sd = tr_orient2d_proj_p(&qa, &qb, &qd, ax);
    return sc * sd < 0;
  }
  const double *x = plc->xyz;
  const double *pa = x + 3 * (size_t)a, *pb = x + 3 * (size_t)b, *pc = x + 3 * (size_t)c,
               *pd = x + 3 * (size_t)d;
  if (tr_orient3d(pa, pb, pc, pd) != 0)
    return 0;
  int ax = tr_plc_tri_axis(plc, s);
  if (ax < 0 || tr_plc_tri_axis(plc, t) < 0)
    return 0;
  double sc = tr_orient2d_proj(pa, pb, pc, ax), sd = tr_orient2d_proj(pa, pb, pd, ax);
  return (sc > 0 && sd < 0) || (sc < 0 && sd > 0);
}

void tr_facets_free(tr_facets *f)
{
  free(f->group);
  free(f->inner);
  free(f->start);
  free(f->member);
  memset(f, 0, sizeof *f);
}

tr_status tr_facets_copy(tr_facets *dst, const tr_facets *src)
{
  size_t n = src->ntris ? src->ntris : 1;
  *dst = *src;
  dst->group = malloc(sizeof *dst->group * n);
  dst->inner = malloc(n);
  dst->start = malloc(sizeof *dst->start * ((size_t)src->ntris + 2));
  dst->member = malloc(sizeof *dst->member * n);
  if (!dst->group || !dst->inner || !dst->start || !dst->member) {
    tr_facets_free(dst);
    return tr_error(TR_ERR_NOMEM, "out of memory for a copy of %u facets' triangles",
                    src->ntris);
  }
  memcpy(dst->group, src->group, sizeof *dst->group * n);
  memcpy(dst->inner, src->inner, n);
  memcpy(dst->start, src->start, sizeof *dst->start * ((size_t)src->ntris + 2));
  memcpy(dst->member, src->member, sizeof *dst->member * n);
  return TR_OK;
}

tr_status tr_facets_build(const struct tr_plc *plc, int keep_edges, tr_facets *out)
{
  uint32_t n = plc->ntris;
  memset(out, 0, sizeof *out);
  out->ntris = n;
  out->group = malloc(sizeof *out->group * (n ? n : 1));
  out->inner = calloc(n ? n : 1, 1);
  out->start = calloc((size_t)n + 2, sizeof *out->start);
  out->member = malloc(sizeof *out->member * (n ? n : 1));
  uint32_t *slots = NULL;
  if (!out->group || !out->inner || !out->start || !out->member)
    goto nomem;
  for (uint32_t t = 0; t < n; t++)
    out->group[t] = t;
  if (!keep_edges && n > 1) {
    slots = malloc(sizeof *slots * 3 * (size_t)n);
    if (!slots)
      goto nomem;
    tr_status st = tr_edge_slots_sorted(plc->tris, n, plc->npoints, slots);
    if (st != TR_OK) {
      free(slots);
      tr_facets_free(out);
      return st;
    }
    uint32_t *par = out->group;
    size_t ns = 3 * (size_t)n;
    for (size_t i = 0; i < ns;) {
      const uint32_t *Ti = plc->tris + 3 * (size_t)(slots[i] / 3);
      int ki = (int)(slots[i] % 3);
      uint32_t a = Ti[ki], b = Ti[(ki + 1) % 3];
      size_t j = i + 1;
      while (j < ns) {
        const uint32_t *Tj = plc->tris + 3 * (size_t)(slots[j] / 3);
        int kj = (int)(slots[j] % 3);
        uint32_t u = Tj[kj], v = Tj[(kj + 1) % 3];
        if (!((u == a && v == b) || (u == b && v == a)))
          break;
        j++;
      }
      if (j - i == 2) {
        uint32_t s = slots[i] / 3, t = slots[i + 1] / 3;
        int si = (int)(slots[i] % 3), ti = (int)(slots[i + 1] % 3);
        if (s != t && mergeable(plc, s, si, t, ti)) {
          out->inner[s] |= (uint8_t)(1u << si);
          out->inner[t] |= (uint8_t)(1u << ti);
          out->ninner++;
          tr_uf_unite(par, s, t); /* a root is its group's smallest index */
        }
      }
      i = j;
    }
    free(slots);
    for (uint32_t t = 0; t < n; t++)
      par[t] = tr_uf_find(par, t);
  }
  for (uint32_t t = 0; t < n; t++)
    out->start[out->group[t] + 1]++;
  for (uint32_t g = 0; g < n; g++) {
    out->nmerged += out->start[g + 1] > 1;
    out->start[g + 1] += out->start[g];
  }
  out->start[n + 1] = out->start[n];
  {
    /* members in increasing order: fill through a moving cursor per group */
    uint32_t *cur = malloc(sizeof *cur * (n ? n : 1));
    if (!cur)
      goto nomem;
    for (uint32_t g = 0; g < n; g++)
      cur[g] = out->start[g];
    for (uint32_t t = 0; t < n; t++)
      out->member[cur[out->group[t]]++] = t;
    free(cur);
  }
  return TR_OK;
nomem:
  free(slots);
  tr_facets_free(out);
  return tr_error(TR_ERR_NOMEM, "out of memory for the facets of %u triangles", n);
}
