/* The tets renumbered along a Hilbert curve of their centroids before the sliver stage.
 *
 * Refinement makes tets in the order of its queues, so after it neighbouring tets sit
 * far apart in the store and every walk across a face misses the cache (the sliver
 * stage's cavities spent about a fifth of their time loading a neighbour's vertices).
 * Sorted, the tets around a point share cache lines. The flip and smoothing passes visit
 * tets in this order, the insertion passes in a scattered one (insert.c, visit_step). It
 * is a function of the coordinates and, among equal keys, of the old slots (same input,
 * same mesh). The renumbering is done in place: no second copy of the tet store. */
#include "sliver.h"
#include "delaunay/delaunay.h"

#include <math.h>
#include <stdlib.h>

#define ORDER_BITS 16 /* per axis */

/* x in [lo, lo + span] on the grid of ORDER_BITS bits */
static uint32_t grid(double x, double lo, double span)
{
  const double top = (double)((1u << ORDER_BITS) - 1);
  double g = span > 0 ? (x - lo) / span * top : 0;
  return g > 0 ? (uint32_t)fmin(g, top) : 0;
}

/* Slot t's content (tets, neighbours, flags, region) to slot newid[t], in place: newid
 * is a permutation of [0, m->nt), which this turns into the identity. Each swap puts one
 * slot's content where it belongs, so at most nt swaps in all. The swaps cost time: on
 * elephant -a 4e-8 (2.2 million slots) the sort took 0.82 s, against 0.52 s with a
 * second store; a copy of one array at a time (freed and trimmed before the next) was
 * as fast but left the peak at 301 MB, against 294 MB in place. */
static void permute_in_place(struct tr_mesh *m, uint32_t *newid)
{
  for (uint32_t t = 0; t < m->nt; t++)
    while (newid[t] != t) {
      const uint32_t d = newid[t];
      uint32_t *a = m->tv + 4 * (size_t)t, *b = m->tv + 4 * (size_t)d;
      uint32_t *p = m->tn + 4 * (size_t)t, *q = m->tn + 4 * (size_t)d;
      for (int k = 0; k < 4; k++) {
        uint32_t x = a[k];
        a[k] = b[k], b[k] = x;
        x = p[k];
        p[k] = q[k], q[k] = x;
      }
      uint8_t f = m->flags[t];
      m->flags[t] = m->flags[d], m->flags[d] = f;
      if (m->region) {
        uint32_t r = m->region[t];
        m->region[t] = m->region[d], m->region[d] = r;
      }
      newid[t] = newid[d];
      newid[d] = d;
    }
}

tr_status tr_sliver_sort_tets(struct tr_mesh *m)
{
  uint32_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    n += !tr_tet_is_free(m, t);
  if (n < 2)
    return TR_OK;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (uint32_t v = 0; v < m->nv; v++)
    for (int j = 0; j < 3; j++) {
      lo[j] = fmin(lo[j], m->xyz[3 * (size_t)v + j]);
      hi[j] = fmax(hi[j], m->xyz[3 * (size_t)v + j]);
    }
  /* one span for the three axes: the cells stay cubes */
  const double span = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
  /* keyed in slot order, so the stable sort breaks ties by the old slot */
  tr_kv *k = malloc(sizeof *k * n), *tmp = malloc(sizeof *tmp * n);
  uint32_t *newid = malloc(sizeof *newid * (size_t)m->nt);
  if (!k || !tmp || !newid) {
    free(k), free(tmp), free(newid);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u tets", n);
  }
  uint32_t i = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    double c[3] = {0, 0, 0};
    int nc = 0;
    for (int a = 0; a < 4; a++)
      if (v[a] != TR_GHOST) {
        for (int j = 0; j < 3; j++)
          c[j] += m->xyz[3 * (size_t)v[a] + j];
        nc++;
      }
    uint32_t q[3];
    for (int j = 0; j < 3; j++)
      q[j] = grid(c[j] / nc, lo[j], span);
    k[i].key = tr_hilbert_key(q[0], q[1], q[2], ORDER_BITS);
    k[i++].idx = t;
  }
  _Static_assert(3 * ORDER_BITS < 56, "the key fits tr_radix_sort_kv");
  tr_radix_sort_kv(k, tmp, n);
  free(tmp);
  /* renumbered in place (a second set of arrays was 37 bytes a slot at the stage's
   * peak): the links and the vertices' tets first, while newid names the free slots
   * TR_NONE */
  for (uint32_t t = 0; t < m->nt; t++)
    newid[t] = TR_NONE;
  for (i = 0; i < n; i++)
    newid[k[i].idx] = i;
  free(k);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (newid[t] == TR_NONE)
      continue;
    uint32_t *tn = m->tn + 4 * (size_t)t;
    for (int a = 0; a < 4; a++)
      tn[a] = tn[a] == TR_NONE ? TR_NONE : 4 * newid[tn[a] >> 2] + (tn[a] & 3);
  }
  for (uint32_t v = 0; v < m->nv; v++)
    if (m->v2t[v] != TR_NONE)
      m->v2t[v] = m->v2t[v] < m->nt ? newid[m->v2t[v]] : TR_NONE;
  for (uint32_t t = 0, next = n; t < m->nt; t++) /* the free slots go past the tets */
    if (newid[t] == TR_NONE)
      newid[t] = next++;
  permute_in_place(m, newid);
  free(newid);
  m->nt = n;
  m->free_head = TR_NONE;
  m->nfree = 0;
  return TR_OK;
}
