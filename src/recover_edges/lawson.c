/* Lawson flips around a new vertex (see lawson.h).
 *
 * The stack holds link faces by vertex ids with a tet hint: flips move tets to other
 * slots, but a flip never touches a tet outside the region it replaces, so an entry whose
 * hint slot no longer holds the tet (p, a, b, c) names a face some flip destroyed (its
 * replacements were pushed by that flip) and is dropped.
 */
#include "recover_edges/lawson.h"

#include <stdlib.h>
#include <string.h>

#include "mesh/orient_memo.h"

void tr_lawson_free(tr_lawson *L)
{
  free(L->st);
  tr_u32buf_free(&L->ball);
  memset(L, 0, sizeof *L);
}

static tr_status push(tr_lawson *L, uint32_t t, const uint32_t f[3])
{
  if (L->n == L->cap) {
    size_t nc = L->cap ? 2 * L->cap : 64;
    uint32_t *q = realloc(L->st, 4 * nc * sizeof *q);
    if (!q)
      return tr_error(TR_ERR_NOMEM, "out of memory for the Lawson stack");
    L->st = q;
    L->cap = nc;
  }
  uint32_t *e = L->st + 4 * L->n++;
  e[0] = t;
  memcpy(e + 1, f, 3 * sizeof *f);
  return TR_OK;
}

/* Pushes the link face of p in tet t if t is real and has p. */
static tr_status push_link(struct tr_mesh *m, tr_lawson *L, uint32_t t, uint32_t p)
{
  if (!tr_tet_is_real(m, t))
    return TR_OK;
  int k = tr_ncode(m, t, p);
  if (k < 0)
    return TR_OK;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
  return push(L, t, f);
}

/* The vertex of tet u opposite its face shared with t across face k, TR_NONE on the hull
 * (no neighbour or a ghost on the other side). */
static uint32_t apex_across(const struct tr_mesh *m, uint32_t t, int k, uint32_t *u)
{
  uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
  if (c == TR_NONE || !tr_tet_is_real(m, c >> 2))
    return TR_NONE;
  *u = c >> 2;
  return m->tv[4 * (size_t)(c >> 2) + (c & 3)];
}

static int inside(const struct tr_mesh *m, uint32_t t, uint32_t d)
{
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  tr_point q[5] = {tr_mesh_point(m, tv[0]), tr_mesh_point(m, tv[1]), tr_mesh_point(m, tv[2]),
                   tr_mesh_point(m, tv[3]), tr_mesh_point(m, d)};
  return tr_insphere_p(&q[0], &q[1], &q[2], &q[3], &q[4]) > 0;
}

int tr_lawson_face_ok(const struct tr_mesh *m, uint32_t t, int k)
{
  uint32_t u;
  if (!tr_tet_is_real(m, t))
    return 1;
  uint32_t d = apex_across(m, t, k, &u);
  return d == TR_NONE || !inside(m, t, d);
}

/* 1 iff live slot t holds p and the three face vertices f (any order). */
static int holds_face(const struct tr_mesh *m, uint32_t t, uint32_t p, const uint32_t f[3])
{
  if (t >= m->nt || !tr_tet_is_real(m, t) || tr_ncode(m, t, p) < 0)
    return 0;
  for (int i = 0; i < 3; i++)
    if (tr_ncode(m, t, f[i]) < 0)
      return 0;
  return 1;
}

/* The 4-4 flip of the degenerate case: p, d and the face edge xy (the face's vertices
 * other than z = tv[j]) coplanar, pd crossing xy at a point interior to both. The shell
 * of xy is then t = (p,x,y,z), u = (d,x,y,z), (p,x,y,w), (d,x,y,w); on each side of the
 * plane the two tets are a pyramid over the strictly convex quad pxdy, which the diagonal
 * pd cuts into the new tets (z or w, p, d, x or y). The crossing is tested exactly with
 * the off-plane apex z: x, y on opposite sides of plane pdz and p, d on opposite sides
 * of plane xyz. */
static tr_status flip44(struct tr_mesh *m, uint32_t t, int k, int j, uint32_t u, uint32_t d,
                        tr_flip_guard guard, void *ud, tr_flip_rec *rec, int *done)
{
  *done = 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  uint32_t p = tv[k], z = tv[j], e[2], ne = 0;
  for (int i = 0; i < 4; i++)
    if (i != j && i != k)
      e[ne++] = tv[i];
  if (tr_mesh_orient(m, p, d, e[0], e[1]) != 0)
    return TR_OK;
  int sx = tr_mesh_orient(m, p, d, z, e[0]), sy = tr_mesh_orient(m, p, d, z, e[1]);
  int sp = tr_mesh_orient(m, e[0], e[1], z, p), sd = tr_mesh_orient(m, e[0], e[1], z, d);
  if (!sx || sx != -sy || !sp || sp != -sd)
    return TR_OK;
  /* the other side: t's neighbour across (p,x,y) and u's across (d,x,y), same apex w */
  uint32_t c1 = m->tn[4 * (size_t)t + (size_t)j];
  int ju = tr_ncode(m, u, z);
  if (c1 == TR_NONE || ju < 0)
    return TR_OK;
  uint32_t c2 = m->tn[4 * (size_t)u + (size_t)ju];
  if (c2 == TR_NONE)
    return TR_OK;
  uint32_t t2 = c1 >> 2, u2 = c2 >> 2;
  if (!tr_tet_is_real(m, t2) || !tr_tet_is_real(m, u2))
    return TR_OK;
  uint32_t w = m->tv[4 * (size_t)t2 + (c1 & 3)];
  if (m->tv[4 * (size_t)u2 + (c2 & 3)] != w || tr_ncode(m, t2, d) >= 0)
    return TR_OK;
  uint32_t ex[2] = {e[0], e[1]};
  if (guard && guard(ud, ex, 2))
    return TR_OK;
  uint32_t fz[4][3] = {{e[0], e[1], z}, {e[0], e[1], w}, {e[0], e[1], p}, {e[0], e[1], d}};
  for (int i = 0; i < 4 && guard; i++)
    if (guard(ud, fz[i], 3))
      return TR_OK;
  uint32_t newv[16], nn = 0;
  const uint32_t apex[2] = {z, w};
  for (int a = 0; a < 2; a++)
    for (int b = 0; b < 2; b++) {
      uint32_t *q = newv + 4 * nn++;
      q[0] = apex[a];
      q[1] = p;
      q[2] = d;
      q[3] = e[b];
      int o = tr_mesh_orient(m, q[0], q[1], q[2], q[3]);
      if (o == 0)
        return TR_OK; /* cannot happen after the tests above; refuse rather than assume */
      if (o < 0) {
        q[2] = e[b];
        q[3] = d;
      }
    }
  uint32_t old[4] = {t, u, t2, u2}, oldv[16];
  for (int i = 0; i < 4; i++)
    memcpy(oldv + 4 * i, m->tv + 4 * (size_t)old[i], 4 * sizeof *oldv);
  TR_CHECK(tr_mesh_replace(m, old, 4, newv, 4, rec->newid));
  memcpy(rec->oldv, oldv, sizeof oldv);
  memcpy(rec->newv, newv, sizeof newv);
  rec->nold = rec->nnew = 4;
  rec->hull = 0;
  *done = 1;
  return TR_OK;
}

/* Flips link face k (opposite p) of t whose apex d (in u) is inside t's circumsphere: 2-3
 * if pd crosses the open face, else 3-2 of a face edge whose shell is {t, u, (p, d, edge)},
 * else 4-4 of a face edge coplanar with pd. *kind = 23, 32, 44, or 0 (left). */
static tr_status flip_face(struct tr_mesh *m, uint32_t t, int k, uint32_t u, uint32_t d,
                           tr_flip_guard guard, void *ud, tr_flip_rec *rec, int *kind)
{
  int done;
  *kind = 0;
  TR_CHECK(tr_flip23(m, t, k, guard, ud, rec, &done));
  if (done) {
    *kind = 23;
    return TR_OK;
  }
  for (int j = 0; j < 4; j++) {
    if (j == k)
      continue;
    /* edge = the face's vertices other than vertex j; its third shell tet is across the
     * face of t opposite j, and must have apex d */
    uint32_t w;
    if (apex_across(m, t, j, &w) != d)
      continue;
    uint32_t e[2], ne = 0;
    for (int i = 0; i < 4; i++)
      if (i != j && i != k)
        e[ne++] = m->tv[4 * (size_t)t + (size_t)i];
    TR_CHECK(tr_flip_remove_edge(m, e[0], e[1], t, guard, ud, rec, &done));
    if (done) {
      *kind = 32;
      return TR_OK;
    }
  }
  for (int j = 0; j < 4; j++) {
    if (j == k)
      continue;
    TR_CHECK(flip44(m, t, k, j, u, d, guard, ud, rec, &done));
    if (done) {
      *kind = 44;
      return TR_OK;
    }
  }
  return TR_OK;
}

tr_status tr_lawson_vertex(struct tr_mesh *m, uint32_t p, tr_flip_guard guard, void *ud,
                           tr_lawson *L, tr_lawson_stats *st)
{
  tr_lawson_stats dummy;
  if (!st) {
    memset(&dummy, 0, sizeof dummy);
    st = &dummy;
  }
  L->n = 0;
  TR_CHECK(tr_ball(m, p, 0, &L->ball));
  /* pushed in reverse so that the first ball tet is examined first */
  for (size_t i = L->ball.n; i-- > 0;)
    TR_CHECK(push_link(m, L, L->ball.a[i], p));
  uint64_t budget = (uint64_t)TR_LAWSON_BUDGET * L->n, flips = 0;
  tr_flip_rec rec;
  while (L->n > 0) {
    const uint32_t *e = L->st + 4 * --L->n;
    uint32_t t = e[0], f[3] = {e[1], e[2], e[3]};
    if (!holds_face(m, t, p, f))
      continue;
    int k = tr_ncode(m, t, p);
    uint32_t u, d = apex_across(m, t, k, &u);
    if (d == TR_NONE)
      continue;
    st->tested++;
    if (!inside(m, t, d))
      continue;
    if (flips >= budget) {
      st->capped++;
      break;
    }
    int kind;
    TR_CHECK(flip_face(m, t, k, u, d, guard, ud, &rec, &kind));
    if (!kind) {
      st->blocked++;
      continue;
    }
    flips++;
    if (kind == 23)
      st->flip23++;
    else if (kind == 32)
      st->flip32++;
    else
      st->flip44++;
    for (uint32_t i = rec.nnew; i-- > 0;)
      TR_CHECK(push_link(m, L, rec.newid[i], p));
  }
  L->n = 0;
  return TR_OK;
}
