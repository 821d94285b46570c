/* Edge collapses inside the envelope (tr_simp_try_collapse), and the classes of the input
 * points that say which may go where (tr_simp_classify).
 *
 * A collapse u -> v removes vertex u: its triangles that hold v go, the others get v in
 * place of u. It is made only when
 *  - u may move that way: u is on no feature edge, or on exactly two (a chain) and uv is
 *    one of them (so the chain stays a chain of edges); feature edges are sharp ones
 *    (normals more than TR_SIMP_SHARP_DEG apart), marker boundaries, open and
 *    non-manifold edges, and their ends and corners never move;
 *  - the topology stays: u's star is one disk, and the links of u and v share exactly
 *    the two vertices opposite uv (the link condition), no triangle is made twice;
 *  - no normal turns over: each new triangle's normal has a positive dot product with
 *    the one it replaces (exact sign);
 *  - the smallest angle of the triangles changed grows (a choice, in doubles);
 *  - the envelope holds both ways: every new triangle lies within d of the input
 *    surface, and every input point that was within d of u's old star is within d of
 *    the new triangles and their neighbours (input points farther than d from the old
 *    star were covered by triangles the collapse leaves alone). Both proven by
 *    tr_simp_cover; a piece budget run out counts as a refusal.
 * Self-intersections are left to the stage (stage.c), which checks the whole result
 * exactly and freezes what took part. */
#define _DEFAULT_SOURCE
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "edit.h"
#include "simplify.h"

#define MAXLINK 256

tr_status tr_simp_try_collapse(tr_simp_edit *c, uint32_t u, uint32_t v, int *done)
{
  *done = 0;
  if (c->cls[u] != TR_SIMP_FREE && c->cls[u] != TR_SIMP_CHAIN)
    return TR_OK;
  if (c->cls[u] == TR_SIMP_CHAIN && !tr_simp_is_feat(c, u, v))
    return TR_OK;
  uint32_t lu[MAXLINK], lv[MAXLINK];
  uint32_t nu = tr_simp_link(c, u, lu, MAXLINK), nv = tr_simp_link(c, v, lv, MAXLINK);
  if (nu >= MAXLINK || nv >= MAXLINK || c->ninc[u] != nu)
    return TR_OK;
  /* the two triangles on uv and their apexes */
  uint32_t apex[2], na = 0;
  for (uint32_t i = 0; i < c->ninc[u]; i++) {
    const uint32_t *t = c->tri + 3 * (size_t)c->inc[u][i];
    if (!tr_simp_has(t, v))
      continue;
    for (int k = 0; k < 3; k++)
      if (t[k] != u && t[k] != v && na < 2)
        apex[na++] = t[k];
      else if (t[k] != u && t[k] != v)
        na = 3;
  }
  if (na != 2)
    return TR_OK;
  uint32_t common = 0;
  for (uint32_t i = 0; i < nu; i++)
    for (uint32_t j = 0; j < nv; j++)
      if (lu[i] == lv[j] && lu[i] != u && lu[i] != v) {
        if (lu[i] != apex[0] && lu[i] != apex[1])
          return TR_OK;
        common++;
      }
  if (common != 2)
    return TR_OK;
  uint32_t w = UINT32_MAX;
  if (c->cls[u] == TR_SIMP_CHAIN) {
    for (uint32_t i = 0; i < nu; i++)
      if (lu[i] != v && tr_simp_is_feat(c, u, lu[i]))
        w = lu[i];
    if (w == UINT32_MAX || w == apex[0] || w == apex[1])
      return TR_OK;
  }
  /* the new triangles, in slots past the live ones */
  uint32_t nt0 = c->nt, nnew = 0;
  double old_min = 180, new_min = 180;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  tr_status st = TR_OK;
  int ok = 1;
  for (uint32_t i = 0; i < c->ninc[u] && ok && st == TR_OK; i++) {
    uint32_t t = c->inc[u][i];
    const uint32_t *tv = c->tri + 3 * (size_t)t;
    old_min = fmin(old_min, tr_simp_tri_angle(c, t));
    for (int k = 0; k < 3; k++)
      for (int j = 0; j < 3; j++)
        lo[j] = fmin(lo[j], tr_simp_at(c, tv[k])[j]), hi[j] = fmax(hi[j], tr_simp_at(c, tv[k])[j]);
    if (tr_simp_has(tv, v))
      continue;
    uint32_t nvx[3];
    for (int k = 0; k < 3; k++)
      nvx[k] = tv[k] == u ? v : tv[k];
    uint32_t id;
    st = tr_simp_new_slot(c, nvx, c->orig[t], &id);
    tv = c->tri + 3 * (size_t)t; /* the array may have moved */
    if (st != TR_OK)
      break;
    nnew++;
    if (tr_simp_normal_dot_sign(tr_simp_at(c, tv[0]), tr_simp_at(c, tv[1]), tr_simp_at(c, tv[2]),
                                tr_simp_at(c, nvx[0]), tr_simp_at(c, nvx[1]),
                                tr_simp_at(c, nvx[2])) <= 0)
      ok = 0;
    new_min = fmin(new_min, tr_simp_tri_angle(c, id));
  }
  if (ok && st == TR_OK && !(new_min > old_min))
    ok = 0;
  if (ok && st == TR_OK)
    st = tr_simp_envelope(c, c->inc[u], c->ninc[u], nt0, lu, nu, lo, hi, &ok);
  if (!ok || st != TR_OK) {
    c->nt = nt0;
    return st;
  }
  /* made: the old star goes, the new triangles come */
  uint32_t nold = c->ninc[u];
  uint32_t *old = malloc(sizeof *old * (nold ? nold : 1));
  if (!old)
    return tr_error(TR_ERR_NOMEM, "out of memory collapsing an edge");
  memcpy(old, c->inc[u], sizeof *old * nold);
  st = tr_simp_commit(c, old, nold, nt0);
  free(old);
  c->cls[u] = TR_SIMP_GONE;
  if (st == TR_OK && w != UINT32_MAX) {
    uint32_t k[2];
    tr_vtkey_edge(v, w, k);
    st = tr_vtmap_set(&c->feat, 2, k, 1);
  }
  if (st == TR_OK)
    c->into[u] = v;
  *done = st == TR_OK;
  (void)nnew;
  return st;
}

static void normal(const double *a, const double *b, const double *c, double n[3])
{
  double u[3], v[3];
  for (int k = 0; k < 3; k++)
    u[k] = b[k] - a[k], v[k] = c[k] - a[k];
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
}

/* Which edges are sharp is a choice (doubles); it only decides what may move, never
 * validity. */
tr_status tr_simp_classify(tr_simp_edit *c)
{
  const struct tr_plc *p = c->plc;
  tr_vtmap em = {0};
  uint32_t ne = 0, *cnt = malloc(sizeof *cnt * 3 * (size_t)(p->ntris ? p->ntris : 1));
  uint32_t *t0 = malloc(sizeof *t0 * 3 * (size_t)(p->ntris ? p->ntris : 1));
  uint32_t *t1 = malloc(sizeof *t1 * 3 * (size_t)(p->ntris ? p->ntris : 1));
  tr_status st = cnt && t0 && t1 ? tr_vtmap_reserve(&em, 2, 3 * p->ntris)
                                 : tr_error(TR_ERR_NOMEM, "out of memory for the edges");
  for (uint32_t t = 0; t < p->ntris && st == TR_OK; t++)
    for (int k = 0; k < 3 && st == TR_OK; k++) {
      uint32_t key[2], id;
      tr_vtkey_edge(p->tris[3 * (size_t)t + k], p->tris[3 * (size_t)t + (k + 1) % 3], key);
      st = tr_vtmap_put(&em, 2, key, ne, &id);
      if (st != TR_OK)
        break;
      if (id == ne)
        cnt[ne] = 0, t0[ne] = t, t1[ne] = UINT32_MAX, ne++;
      if (cnt[id]++ == 1)
        t1[id] = t;
    }
  const double cosmax = cos(TR_SIMP_SHARP_DEG * M_PI / 180);
  uint8_t *sharp = st == TR_OK ? calloc(ne ? ne : 1, 1) : NULL;
  if (st == TR_OK && !sharp)
    st = tr_error(TR_ERR_NOMEM, "out of memory for the edges");
  for (uint32_t e = 0; e < ne && st == TR_OK; e++) {
    if (cnt[e] != 2) {
      sharp[e] = 2; /* open or non-manifold: its vertices stay */
      continue;
    }
    const uint32_t *a = p->tris + 3 * (size_t)t0[e], *b = p->tris + 3 * (size_t)t1[e];
    int32_t ma = p->tri_marker ? p->tri_marker[t0[e]] : 0;
    int32_t mb = p->tri_marker ? p->tri_marker[t1[e]] : 0;
    double n1[3], n2[3];
    normal(tr_simp_at(c, a[0]), tr_simp_at(c, a[1]), tr_simp_at(c, a[2]), n1);
    normal(tr_simp_at(c, b[0]), tr_simp_at(c, b[1]), tr_simp_at(c, b[2]), n2);
    double dt = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    double l = sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
               sqrt(n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]);
    if (ma != mb || !(dt >= cosmax * l))
      sharp[e] = 1;
  }
  for (uint32_t t = 0; t < p->ntris && st == TR_OK; t++)
    for (int k = 0; k < 3 && st == TR_OK; k++) {
      uint32_t key[2];
      tr_vtkey_edge(p->tris[3 * (size_t)t + k], p->tris[3 * (size_t)t + (k + 1) % 3], key);
      uint32_t e = tr_vtmap_get(&em, 2, key);
      if (sharp[e] == 1)
        st = tr_vtmap_set(&c->feat, 2, key, 1);
    }
  for (uint32_t v = 0; v < p->npoints && st == TR_OK; v++) {
    uint8_t cl = tr_simp_is_frozen(c, v) ? TR_SIMP_FROZEN : TR_SIMP_FREE;
    uint32_t nf = 0;
    if (c->ninc[v] == 0)
      cl = TR_SIMP_FROZEN;
    for (uint32_t i = 0; i < c->ninc[v] && cl != TR_SIMP_FROZEN; i++) {
      const uint32_t *t = p->tris + 3 * (size_t)c->inc[v][i];
      for (int k = 0; k < 3; k++) {
        uint32_t a = t[k], b = t[(k + 1) % 3], key[2];
        if (a != v)
          continue; /* each edge at v once: as it leaves v in this triangle */
        for (int s = 0; s < 2; s++) {
          tr_vtkey_edge(v, s ? t[(k + 2) % 3] : b, key);
          uint32_t e = tr_vtmap_get(&em, 2, key);
          if (sharp[e] == 2)
            cl = TR_SIMP_FROZEN;
          else if (sharp[e] == 1 && s == 0)
            nf++;
        }
      }
    }
    /* one disk: walking across the edges around v comes back after all its triangles */
    if (cl != TR_SIMP_FROZEN) {
      uint32_t start = c->inc[v][0], cur = start, steps = 0;
      do {
        const uint32_t *t = p->tris + 3 * (size_t)cur;
        uint32_t nxt = t[0] == v ? t[2] : t[1] == v ? t[0] : t[1]; /* previous vertex */
        uint32_t found = UINT32_MAX;
        for (uint32_t i = 0; i < c->ninc[v]; i++) {
          const uint32_t *s = p->tris + 3 * (size_t)c->inc[v][i];
          if (c->inc[v][i] != cur && tr_simp_has(s, nxt))
            found = c->inc[v][i];
        }
        cur = found;
        steps++;
      } while (cur != UINT32_MAX && cur != start && steps <= c->ninc[v]);
      if (cur != start || steps != c->ninc[v])
        cl = TR_SIMP_FROZEN;
    }
    if (cl != TR_SIMP_FROZEN)
      cl = nf == 0 ? TR_SIMP_FREE : nf == 2 ? TR_SIMP_CHAIN : TR_SIMP_FROZEN;
    c->cls[v] = cl;
  }
  tr_vtmap_free(&em);
  free(cnt), free(t0), free(t1), free(sharp);
  return st;
}
