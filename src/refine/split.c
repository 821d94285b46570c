/* Splitting a constraint piece (refine.h): a queued sub-segment at its exact split point
 * on the input edge (encroach.c), a queued sub-face at a dyadic point near its
 * circumcentre in its input triangle. A point that would lie inside the diametral sphere
 * of a sub-segment has that sub-segment split first; a piece that cannot be split (past
 * the bit-size guard, no valid cavity, or protected near a small input angle) is marked
 * (ssnosplit, sfnosplit) and not tried again. */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_impl.h"

/* The split point *q, its cavity built, into the mesh (which then owns it: *q = NULL) and
 * inserted (*ok from rf_insert). Past the bit-size guard of tr_mesh_add_constructed
 * (TR_ERR_UNSUPPORTED) the cavity is released and *ok = 0: the piece is left as it is. */
static tr_status insert_split_point(rf_ctx *c, tr_qpoint **q, int kind, uint32_t *pid,
                                    int *ok)
{
  tr_status st = tr_mesh_add_constructed(c->m, *q, pid);
  if (st == TR_OK) {
    *q = NULL;
    /* its kind before its sub-faces and sub-segments exist (rf_subface_of's shortcut) */
    st = rf_vertex_room(c, *pid + 1);
    if (st != TR_OK) {
      rf_cavity_release(c);
      return st;
    }
    c->vkind[*pid] = (uint8_t)kind;
    return rf_insert(c, *pid, ok);
  }
  if (st == TR_ERR_UNSUPPORTED) {
    rf_cavity_release(c);
    *ok = 0;
    return TR_OK;
  }
  return st;
}

tr_status rf_split_segment(rf_ctx *c, uint32_t g)
{
  struct tr_mesh *m = c->m;
  uint32_t u = c->ssv[2 * (size_t)g], w = c->ssv[2 * (size_t)g + 1], t;
  TR_CHECK(tr_ball_find_domain(m, u, w, TR_NONE, &t));
  if (t == TR_NONE)
    return tr_error(TR_ERR_INTERNAL, "refinement: sub-segment %u-%u is not a mesh edge", u, w);
  tr_qpoint *q = NULL;
  TR_CHECK(rf_segment_split_point(c, g, &q));
  tr_point p = tr_pt_q(q);
  int ok = 0;
  c->split_seg = g;
  tr_status st = rf_cavity(c, t, &p, m->nv, 1, &ok);
  uint32_t pid = TR_NONE;
  if (st == TR_OK && ok)
    st = insert_split_point(c, &q, RF_SEG, &pid, &ok);
  c->split_seg = TR_NONE;
  if (q) {
    tr_qpoint_clear(q);
    free(q);
  }
  TR_CHECK(st);
  if (!ok) {
    c->ssnosplit[g] = 1;
    return TR_OK;
  }
  c->st->on_segments++;
  return rf_after_insert(c, pid, RF_SEG, g, INFINITY);
}

tr_status rf_split_facet(rf_ctx *c, uint32_t f)
{
  struct tr_mesh *m = c->m;
  tr_qpoint *q = NULL;
  uint32_t where, encseg, t;
  TR_CHECK(rf_facet_split_point(c, f, &q, &where, &encseg));
  if (q && encseg != TR_NONE) {
    /* the circumcentre lies beyond a sub-segment: split that one, unless it cannot be or
     * is protected near a small angle (or, for a sub-face split for its shape, unless
     * rf_subshape_may_split refuses it); then f is left as it is */
    tr_point p = tr_pt_q(q), a = tr_mesh_point(m, c->ssv[2 * (size_t)encseg]),
             b = tr_mesh_point(m, c->ssv[2 * (size_t)encseg + 1]);
    int split = !c->ssnosplit[encseg] &&
                ((rf_in_diametral(&a, &b, &p) &&
                  !rf_protected_at(c, 1, encseg, RF_FACET, c->sftri[f], q->near)) ||
                 (c->shape_on && rf_subface_shape_bad(c, f, c->shape_bound) &&
                  rf_subshape_may_split(c, f, encseg)));
    tr_qpoint_clear(q);
    free(q);
    if (split) {
      TR_CHECK(tr_u32buf_push(&c->qseg, encseg));
      return tr_u32buf_push(&c->qface, f);
    }
    c->sfnosplit[f] = 1;
    return TR_OK;
  }
  if (!q) {
    c->sfnosplit[f] = 1;
    return TR_OK;
  }
  const uint32_t *S = c->sfv + 3 * (size_t)where;
  tr_status st0 = tr_ball_find_domain(m, S[0], S[1], S[2], &t);
  if (st0 == TR_OK && t == TR_NONE)
    st0 = tr_error(TR_ERR_INTERNAL, "refinement: sub-face %u-%u-%u is not a mesh face", S[0],
                   S[1], S[2]);
  if (st0 != TR_OK) {
    tr_qpoint_clear(q);
    free(q);
    return st0;
  }
  tr_point p = tr_pt_q(q);
  int ok = 0;
  tr_status st = rf_cavity(c, t, &p, m->nv, 1, &ok);
  /* a split point inside a sub-segment's diametral sphere is not inserted: the
   * sub-segment is split first (the sub-face stays queued) */
  /* ... unless that sub-segment is protected (angles.c) or cannot be split: then the
   * sub-face is left as it is, else its pieces would be split towards the sub-segment
   * without end */
  int pushed = 0, blocked = 0;
  for (size_t i = 0; st == TR_OK && ok && i < c->cav.n && !blocked; i++) {
    const uint32_t *v = m->tv + 4 * (size_t)c->cav.a[i];
    for (int e = 0; e < 6 && st == TR_OK && !blocked; e++) {
      uint32_t g = rf_subseg_of(c, v[tr_edge_vtx[e][0]], v[tr_edge_vtx[e][1]]);
      if (g == TR_NONE)
        continue;
      tr_point a = tr_mesh_point(m, c->ssv[2 * (size_t)g]), b = tr_mesh_point(m, c->ssv[2 * (size_t)g + 1]);
      if (!rf_in_diametral(&a, &b, &p))
        continue;
      if (c->ssnosplit[g] || (rf_protected_at(c, 1, g, RF_FACET, c->sftri[f], p.d) &&
                              !(c->shape_on && rf_subshape_may_split(c, f, g))))
        blocked = 1;
      else {
        st = tr_u32buf_push(&c->qseg, g);
        pushed = 1;
      }
    }
  }
  uint32_t pid = TR_NONE;
  if (st == TR_OK && ok && blocked) {
    rf_cavity_release(c);
    ok = 0;
  } else if (st == TR_OK && ok && pushed) {
    rf_cavity_release(c);
    st = tr_u32buf_push(&c->qface, f);
    ok = -1;
  } else if (st == TR_OK && ok)
    st = insert_split_point(c, &q, RF_FACET, &pid, &ok);
  if (q) {
    tr_qpoint_clear(q);
    free(q);
  }
  TR_CHECK(st);
  if (ok == 0)
    c->sfnosplit[f] = 1;
  if (ok != 1)
    return TR_OK;
  c->st->on_facets++;
  return rf_after_insert(c, pid, RF_FACET, c->sftri[f], INFINITY);
}
