/* Splitting a missing sub-segment at one exact point (tr_pipe_split_mid, pipe.h).
 *
 * The midpoint M of ab lies in the closure of some pipels of Pipe(ab) (inside one tet, on
 * a face, or on an edge; on a hull face also in the ghost tet of that face): every tet
 * whose closure holds M is a pipel, because ab meets it at M, which is not a vertex. Those
 * tets are replaced by the cone from M over their faces that do not contain M (the tet
 * with vertex k replaced by M, for each face k not through M): strictly positive by
 * construction, and tr_mesh_replace checks that they fill the same region. Ghost tets
 * keep TR_GHOST in slot 3 (their hull face always holds M, so slot 3 is never replaced).
 *
 * The split point M is the midpoint of ab unless that lies in an end piece of the pipe
 * (the part of ab inside the pipels at a, or at b): then it is the point of the middle
 * part (between where ab leaves the pipels at a and enters those at b) that repeated
 * midpoint splits would reach first, a + t (b - a) with the dyadic t of smallest
 * denominator there. A split in an end piece removes none of the pipels in between;
 * when the middle part is tiny (ab grazing a sliver of nearly coplanar vertices, common
 * on ulp-perturbed grids) the midpoint splits converged on it from both sides, dozens of
 * Steiner points within 1e-14 of each other that no rounding to doubles can separate.
 * Splitting in the middle part at once also saves most of the points on the way (corpus
 * 7,737 -> 4,848 Steiner points).
 *
 * The middle part can be too thin for any short dyadic t when ab winds around a hub: an
 * edge every pipel has, that ab passes by without crossing it (skew by a subnormal
 * distance on Chazelle's polyhedron moved by ulps: a diagonal of the bumpy front face and
 * an edge lying in that face and in a groove's plane). Each split next to the hub leaves
 * it in place and the next sub-segment winds around it again, so splits converged on it
 * until the budget was gone and the pipels left points that no double rounding could
 * tell apart. There M is the point where ab crosses the hub's face as it leaves a's star
 * instead; M then lies in the hub's ring, and removing the hub (edge removal, flip.h)
 * can take the fan from M, which makes a-M and M-b mesh edges: M takes the hub's place as
 * if the hub had been split at its near-crossing with ab.
 */
#include <stdlib.h>

#include "classify.h"
#include "construct.h"
#include "recover_edges/pipe.h"

/* Bit k set iff face k of real tet tv holds p; -1 if p is outside the tet. */
static int faces_through(const struct tr_mesh *m, const uint32_t *tv, const tr_point *p)
{
  int mask = 0;
  for (int k = 0; k < 4; k++) {
    const uint8_t *f = tr_face_vtx[k];
    tr_point a = tr_mesh_point(m, tv[f[0]]), b = tr_mesh_point(m, tv[f[1]]),
             c = tr_mesh_point(m, tv[f[2]]);
    int o = tr_orient3d_p(&a, &b, &c, p);
    if (o < 0)
      return -1;
    if (o == 0)
      mask |= 1 << k;
  }
  return mask;
}

/* The point where ab crosses the face or edge of tr_pipe_end: the first (last) point
 * where ab leaves an end's star. 0 on success, -1 if there is none. */
static int end_crossing(const struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                        int at_a, tr_qpoint *out, uint32_t fv[3])
{
  int ty, code, i = tr_pipe_end(m, p, a, b, at_a, &ty, &code);
  if (i < 0)
    return -1;
  const uint32_t *tv = m->tv + 4 * (size_t)p->pl[i].iEle;
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  if (ty == TR_EDG) {
    fv[0] = tv[tr_ecode_start(code)];
    fv[1] = tv[tr_ecode_end(code)];
    fv[2] = TR_NONE;
    tr_point u = tr_mesh_point(m, fv[0]), w = tr_mesh_point(m, fv[1]);
    return tr_construct_line_line(&pa, &pb, &u, &w, out);
  }
  for (int j = 0; j < 3; j++)
    fv[j] = tv[tr_face_vtx[code][j]];
  tr_point u = tr_mesh_point(m, fv[0]), v = tr_mesh_point(m, fv[1]),
           w = tr_mesh_point(m, fv[2]);
  return tr_construct_line_plane(&pa, &pb, &u, &v, &w, out);
}

/* The hub of a pipe: an edge that every real pipel has (0 if there is none or the pipe
 * has fewer than three real pipels). */
static int pipe_hub(const struct tr_mesh *m, const tr_pipe *p, uint32_t hub[2])
{
  const uint32_t *t0 = NULL;
  uint32_t nreal = 0;
  for (uint32_t i = 0; i < p->n; i++)
    if (!p->pl[i].ghost && nreal++ == 0)
      t0 = m->tv + 4 * (size_t)p->pl[i].iEle;
  for (int e = 0; e < 6 && nreal >= 3; e++) {
    hub[0] = t0[tr_edge_vtx[e][0]];
    hub[1] = t0[tr_edge_vtx[e][1]];
    int all = 1;
    for (uint32_t i = 0; i < p->n && all; i++)
      all = p->pl[i].ghost || tr_tet_ecode(m, p->pl[i].iEle, hub[0], hub[1]) >= 0;
    if (all)
      return 1;
  }
  return 0;
}

/* Moves q (the midpoint of ab) into the middle part of Pipe(ab) when it lies strictly
 * inside an end piece (see the header). A dyadic t keeps the coordinates as short as
 * those of nested midpoints (the midpoint of the two crossing points, built on Steiner
 * points, passed the Steiner size guard within a few levels on a star). If the middle
 * part is a single point (ab crosses one edge), q becomes that crossing. If it is
 * shorter than 2^-TR_MIDDLE_BITS of ab and the pipe has a hub whose face ab crosses
 * where it leaves a's star, q becomes that crossing and 1 is returned (see
 * tr_pipe_split_mid); else q stays the midpoint. */
#define TR_MIDDLE_BITS 96
static int middle_point(const struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                        tr_qpoint *q, uint32_t hub[2])
{
  int at_hub = 0;
  tr_qpoint xa, xb;
  tr_qpoint_init(&xa);
  tr_qpoint_init(&xb);
  uint32_t fa[3], fb[3];
  if (end_crossing(m, a, b, p, 1, &xa, fa) != 0 || end_crossing(m, a, b, p, 0, &xb, fb) != 0)
    goto done;
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  int axis = tr_pipe_long_axis(&pa, &pb);
  if (axis < 0)
    goto done;
  mpq_t ca, cb, len, ta, tb, t, step;
  mpq_inits(ca, cb, len, ta, tb, t, step, NULL);
  /* parameters along ab, exact: the coordinate on the axis is monotone along ab, and it
   * differs at a and b (tr_pipe_long_axis), so len != 0 */
  tr_point_get_q(&pa, axis, ca);
  tr_point_get_q(&pb, axis, cb);
  mpq_sub(len, cb, ca);
  mpq_sub(ta, xa.c[axis], ca);
  mpq_div(ta, ta, len);
  mpq_sub(tb, xb.c[axis], ca);
  mpq_div(tb, tb, len);
  mpq_set_ui(t, 1, 2);
  mpq_set_ui(step, 1, 4);
  int found = 0;
  for (int bits = 0; bits < TR_MIDDLE_BITS && !found; bits++) {
    if (mpq_cmp(t, ta) < 0)
      mpq_add(t, t, step);
    else if (mpq_cmp(t, tb) > 0)
      mpq_sub(t, t, step);
    else
      found = 1;
    mpq_div_2exp(step, step, 1);
  }
  if (found && mpq_cmp_ui(t, 1, 2) != 0) {
    for (int i = 0; i < 3; i++) {
      tr_point_get_q(&pa, i, ca);
      tr_point_get_q(&pb, i, cb);
      mpq_sub(cb, cb, ca);
      mpq_mul(cb, cb, t);
      mpq_add(q->c[i], ca, cb);
    }
    tr_qpoint_update(q);
  } else if (!found) {
    tr_point px = tr_pt_q(&xa), py = tr_pt_q(&xb);
    if (tr_equal_p(&px, &py)) {
      tr_qpoint_set_point(q, &px);
    } else if (fa[2] != TR_NONE && pipe_hub(m, p, hub)) {
      int has = 0;
      for (int j = 0; j < 3; j++)
        has += fa[j] == hub[0] || fa[j] == hub[1];
      if (has == 2) {
        tr_qpoint_set_point(q, &px);
        at_hub = 1;
      }
    }
  }
  mpq_clears(ca, cb, len, ta, tb, t, step, NULL);
done:
  tr_qpoint_clear(&xa);
  tr_qpoint_clear(&xb);
  return at_hub;
}

tr_status tr_pipe_split_mid(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                            tr_flip_guard guard, void *ud, uint32_t *mid, int *done)
{
  *done = 0;
  *mid = TR_NONE;
  tr_qpoint *q = malloc(sizeof *q);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory for a midpoint");
  tr_qpoint_init(q);
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  mpq_t x, y;
  mpq_init(x);
  mpq_init(y);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(&pa, i, x);
    tr_point_get_q(&pb, i, y);
    mpq_add(x, x, y);
    mpq_div_2exp(q->c[i], x, 1);
  }
  mpq_clear(x);
  mpq_clear(y);
  tr_qpoint_update(q);
  uint32_t hub[2] = {TR_NONE, TR_NONE};
  int at_hub = middle_point(m, a, b, p, q, hub);
  tr_point pm = tr_pt_q(q);
  uint32_t id = m->nv; /* the id M gets if the split goes ahead */
  tr_u32buf old = {0}, newv = {0};
  tr_status s = TR_OK;
  for (uint32_t i = 0; i < p->n && s == TR_OK; i++) {
    uint32_t t = p->pl[i].iEle;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    int skip[4] = {0, 0, 0, 0};
    if (p->pl[i].ghost) {
      tr_point h0 = tr_mesh_point(m, tv[0]), h1 = tr_mesh_point(m, tv[1]),
               h2 = tr_mesh_point(m, tv[2]);
      if (tr_orient3d_p(&h0, &h1, &h2, &pm) != 0 ||
          tr_classify_point_triangle(&pm, &h0, &h1, &h2).type == TR_DEG)
        continue;
      skip[3] = 1;
      /* face k < 3 is (hull edge opposite k, GHOST): it holds M iff M is on that edge */
      for (int k = 0; k < 3; k++) {
        tr_point u = tr_mesh_point(m, tv[(k + 1) % 3]), w = tr_mesh_point(m, tv[(k + 2) % 3]);
        skip[k] = tr_classify_point_segment(&pm, &u, &w).type == TR_EDG;
      }
    } else {
      int mask = faces_through(m, tv, &pm);
      if (mask < 0)
        continue;
      for (int k = 0; k < 4; k++)
        skip[k] = (mask >> k) & 1;
    }
    s = tr_u32buf_push(&old, t);
    for (int k = 0; k < 4 && s == TR_OK; k++) {
      if (skip[k])
        continue;
      for (int j = 0; j < 4 && s == TR_OK; j++)
        s = tr_u32buf_push(&newv, j == k ? id : tv[j]);
    }
  }
  if (s == TR_OK && old.n > 0) {
    if ((s = tr_mesh_add_constructed(m, q, &id)) == TR_OK) {
      q = NULL;
      s = tr_mesh_replace(m, old.a, (uint32_t)old.n, newv.a, (uint32_t)(newv.n / 4), NULL);
      if (s == TR_OK) {
        *done = 1;
        *mid = id;
        int gone = 0;
        if (at_hub)
          s = tr_flip_remove_edge(m, hub[0], hub[1], TR_NONE, guard, ud, NULL, &gone);
        if (gone)
          *done = 2;
      } else {
        /* unused: take the vertex back so the store has no orphan */
        tr_mesh_pop_vertex(m);
        s = TR_OK;
      }
    }
  }
  if (q) {
    tr_qpoint_clear(q);
    free(q);
  }
  tr_u32buf_free(&old);
  tr_u32buf_free(&newv);
  return s;
}
