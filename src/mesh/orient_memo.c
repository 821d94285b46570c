/* The orientation memo (orient_memo.h). */
#include "orient_memo.h"

#include <stdlib.h>

#include "mesh.h"
#include "predicates.h"

static int orient_direct(const struct tr_mesh *m, const uint32_t v[4])
{
  tr_point p[4] = {tr_mesh_point(m, v[0]), tr_mesh_point(m, v[1]), tr_mesh_point(m, v[2]),
                   tr_mesh_point(m, v[3])};
  return tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
}

int tr_mesh_orient(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  uint32_t v[4] = {a, b, c, d};
  tr_orient_memo *o = m->omemo;
  if (!o)
    return orient_direct(m, v);
  /* Most tests on input points pass the static filter in a few nanoseconds, less than a
   * probe of a table that has left the cache: only the rest is remembered. */
  if (a >= m->nv || b >= m->nv || c >= m->nv || d >= m->nv)
    return orient_direct(m, v); /* not four vertices: no key */
  double det;
  if ((!m->vq || !(m->vq[a] || m->vq[b] || m->vq[c] || m->vq[d])) &&
      tr_orient3d_filter(m->xyz + 3 * (size_t)a, m->xyz + 3 * (size_t)b,
                         m->xyz + 3 * (size_t)c, m->xyz + 3 * (size_t)d, &det))
    return det > 0 ? 1 : -1;
  /* sort by a network of five exchanges; each one flips the orientation */
  static const int net[5][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}, {1, 2}};
  int parity = 1;
  for (int i = 0; i < 5; i++) {
    uint32_t *x = &v[net[i][0]], *y = &v[net[i][1]];
    if (*x > *y) {
      uint32_t t = *x;
      *x = *y;
      *y = t;
      parity = -parity;
    }
  }
  if (v[0] == v[1] || v[1] == v[2] || v[2] == v[3])
    return 0; /* a repeated vertex */
  o->asked++;
  uint32_t *slot = o->map.cap ? tr_vtmap_find_(&o->map, 4, v) : NULL;
  if (slot && slot[0] != TR_VTMAP_NONE) {
    o->found++;
    return parity * ((int)slot[4] - 1);
  }
  int s = orient_direct(m, v);
  if (o->map.n >= o->room) {
    /* grow while small models stay small; at the bound, or when memory is short, start
     * over (a failed reservation's message is not an error of the run: nothing failed) */
    if (o->room >= TR_ORIENT_MEMO_KEYS || tr_vtmap_reserve(&o->map, 4, 2 * o->room) != TR_OK)
      tr_vtmap_clear(&o->map);
    else
      o->room *= 2;
  }
  /* the map has room for o->room keys, so the put does not allocate and cannot fail */
  (void)tr_vtmap_put(&o->map, 4, v, (uint32_t)(s + 1), NULL);
  return parity * s;
}

tr_status tr_mesh_orient_memo_on(struct tr_mesh *m)
{
  tr_mesh_orient_memo_off(m);
  tr_orient_memo *o = calloc(1, sizeof *o);
  if (!o)
    return tr_error(TR_ERR_NOMEM, "out of memory for the orientation memo");
  o->room = 1u << 12;
  tr_status s = tr_vtmap_reserve(&o->map, 4, o->room);
  if (s != TR_OK) {
    free(o);
    return s;
  }
  m->omemo = o;
  return TR_OK;
}

void tr_mesh_orient_memo_off(struct tr_mesh *m)
{
  if (!m->omemo)
    return;
  tr_vtmap_free(&m->omemo->map);
  free(m->omemo);
  m->omemo = NULL;
}

void tr_mesh_orient_memo_forget(struct tr_mesh *m)
{
  if (m->omemo)
    tr_vtmap_clear(&m->omemo->map);
}
