/* The reference for tr_smooth_surface_rule's worklist (smooth.c): every pass sorts all
 * the edges again and scans them all, in sorted edge order. Kept for the tests, which
 * check that the worklist makes the same swaps in the same order. */
#include <stdlib.h>
#include <string.h>

#include "core/edgesort.h"
#include "predicates.h"
#include "quad.h"
#include "smooth.h"

typedef struct {
  uint32_t a, b; /* a < b */
  uint32_t slot; /* 3 * triangle + position of the directed edge */
} ekey;

static int has_edge(const ekey *e, uint32_t n, uint32_t a, uint32_t b)
{
  if (a > b) {
    uint32_t x = a;
    a = b;
    b = x;
  }
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (e[mid].a < a || (e[mid].a == a && e[mid].b < b))
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n && e[lo].a == a && e[lo].b == b;
}

tr_status tr_smooth_surface_rule_passes(struct tr_plc *plc, tr_swap_rule rule, void *user,
                                        uint64_t *nswaps)
{
  *nswaps = 0;
  uint32_t nt = plc->ntris, ne = 3 * nt, nv = plc->npoints;
  if (nt < 2)
    return TR_OK;
  ekey *e = malloc(sizeof *e * ne);
  uint32_t *slots = malloc(sizeof *slots * ne);
  uint8_t *vused = calloc(nv ? nv : 1, 1);
  /* rej[s] = 1 + pass of the rejection of the pair whose first slot is s, with partner
   * slot rejp[s]; changed[t] = 1 + last pass that rewrote triangle t. */
  uint32_t *rej = calloc(ne, sizeof *rej), *rejp = malloc(sizeof *rejp * ne);
  uint32_t *changed = calloc(nt, sizeof *changed);
  tr_status st = TR_OK;
  if (!e || !slots || !vused || !rej || !rejp || !changed) {
    st = tr_error(TR_ERR_NOMEM, "out of memory smoothing %u triangles", nt);
    goto done;
  }
  uint32_t *T = plc->tris;
  const double *X = plc->xyz;
  for (int pass = 0; pass < TR_SMOOTH_MAX_PASSES; pass++) {
    if ((st = tr_edge_slots_sorted(T, nt, nv, slots)) != TR_OK)
      goto done;
    for (uint32_t i = 0; i < ne; i++) {
      uint32_t s = slots[i], a = T[s], b = T[3 * (s / 3) + (s % 3 + 1) % 3];
      e[i].a = a < b ? a : b;
      e[i].b = a < b ? b : a;
      e[i].slot = s;
    }
    memset(vused, 0, nv ? nv : 1);
    uint64_t done = 0;
    for (uint32_t i = 0; i + 1 < ne; i++) {
      /* exactly two triangles on the edge */
      if (e[i].a != e[i + 1].a || e[i].b != e[i + 1].b)
        continue;
      if (i + 2 < ne && e[i + 2].a == e[i].a && e[i + 2].b == e[i].b) {
        while (i + 1 < ne && e[i + 1].a == e[i].a && e[i + 1].b == e[i].b)
          i++;
        continue;
      }
      if (i > 0 && e[i - 1].a == e[i].a && e[i - 1].b == e[i].b)
        continue;
      uint32_t s1 = e[i].slot, s2 = e[i + 1].slot, t1 = s1 / 3, t2 = s2 / 3;
      /* t1 = (A, C, B) with directed edge A->C; t2 must hold C->A, third vertex D. */
      uint32_t A = T[s1], C = T[3 * t1 + (s1 % 3 + 1) % 3], B = T[3 * t1 + (s1 % 3 + 2) % 3];
      uint32_t p = T[s2], q = T[3 * t2 + (s2 % 3 + 1) % 3], D = T[3 * t2 + (s2 % 3 + 2) % 3];
      if (p != C || q != A || B == D)
        continue; /* inconsistent orientation: leave it alone */
      if (vused[A] || vused[B] || vused[C] || vused[D])
        continue;
      if (plc->tri_marker && plc->tri_marker[t1] != plc->tri_marker[t2])
        continue;
      if (rej[s1] && rejp[s1] == s2 && changed[t1] < rej[s1] && changed[t2] < rej[s1])
        continue;
      const double *pa = X + 3 * (size_t)A, *pb = X + 3 * (size_t)B, *pc = X + 3 * (size_t)C,
                   *pd = X + 3 * (size_t)D;
      const double *const quad[4] = {pa, pb, pc, pd};
      if (!tr_smooth_flat_convex(pa, pb, pc, pd) || !rule(user, quad, A, B, C, D)) {
        rej[s1] = (uint32_t)pass + 1;
        rejp[s1] = s2;
        continue;
      }
      if (has_edge(e, ne, B, D))
        continue;
      /* Quad A, D, C, B counter-clockwise about the normal: new (B, A, D), (D, C, B). */
      T[3 * t1] = B;
      T[3 * t1 + 1] = A;
      T[3 * t1 + 2] = D;
      T[3 * t2] = D;
      T[3 * t2 + 1] = C;
      T[3 * t2 + 2] = B;
      vused[A] = vused[B] = vused[C] = vused[D] = 1;
      changed[t1] = changed[t2] = (uint32_t)pass + 1;
      done++;
      i++;
    }
    *nswaps += done;
    if (!done)
      break;
  }
done:
  free(slots);
  free(e);
  free(vused);
  free(rej);
  free(rejp);
  free(changed);
  return st;
}
