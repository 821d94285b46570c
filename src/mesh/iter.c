/* Ball(P) and Shell(E): the two neighbourhoods the recovery stages walk. */
#include "mesh.h"

#include <stdlib.h>
#include <string.h>

#include "core/vtmap.h"

/* The tet a search of Ball(p) starts from: v2t[p], checked. */
static tr_status ball_start(const struct tr_mesh *m, uint32_t p, uint32_t *t0)
{
  if (p >= m->nv)
    return tr_error(TR_ERR_INTERNAL, "Ball(%u): no such vertex (%u vertices)", p, m->nv);
  *t0 = m->v2t[p];
  if (*t0 == TR_NONE || *t0 >= m->nt || tr_ncode(m, *t0, p) < 0)
    return tr_error(TR_ERR_INVALID_MESH, "Ball(%u): v2t[%u] = %u does not contain the vertex",
                    p, p, *t0);
  return TR_OK;
}

tr_status tr_ball(struct tr_mesh *m, uint32_t p, int with_ghosts, tr_u32buf *out)
{
  out->n = 0;
  uint32_t t0 = TR_NONE;
  TR_CHECK(ball_start(m, p, &t0));
  /* The buffer doubles as the BFS queue. Ghosts are always traversed: a hull vertex's
   * real tets are connected through faces containing p anyway, but v2t may name a ghost. */
  TR_CHECK(tr_u32buf_push(out, t0));
  m->flags[t0] |= TR_TF_MARK;
  tr_status s = TR_OK;
  for (size_t i = 0; i < out->n && s == TR_OK; i++) {
    uint32_t t = out->a[i];
    for (int k = 0; k < 4; k++) {
      if (m->tv[4 * (size_t)t + (size_t)k] == p)
        continue;
      uint32_t u = TR_NEIG(m, t, k);
      if (u == TR_NONE || (m->flags[u] & TR_TF_MARK))
        continue;
      m->flags[u] |= TR_TF_MARK;
      if ((s = tr_u32buf_push(out, u)) != TR_OK)
        break;
    }
  }
  size_t j = 0;
  for (size_t i = 0; i < out->n; i++) {
    uint32_t t = out->a[i];
    m->flags[t] &= (uint8_t)~TR_TF_MARK;
    if (with_ghosts || !tr_tet_is_ghost(m, t))
      out->a[j++] = t;
  }
  out->n = j;
  return s;
}

static int tet_has(const uint32_t *tv, uint32_t x)
{
  return tv[0] == x || tv[1] == x || tv[2] == x || tv[3] == x;
}

tr_status tr_ball_find(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c, uint32_t *t)
{
  return tr_ball_find_ex(m, p, b, c, 0, t);
}

tr_status tr_ball_find_ex(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c,
                          int with_ghosts, uint32_t *t)
{
  *t = TR_NONE;
  uint32_t t0 = TR_NONE;
  TR_CHECK(ball_start(m, p, &t0));
  /* The queue lives on the stack until it outgrows it (a vertex of very high degree). */
  uint32_t local[256], *q = local, nq = 0, cap = 256;
  tr_status s = TR_OK;
  q[nq++] = t0;
  m->flags[t0] |= TR_TF_MARK;
  for (uint32_t i = 0; i < nq && *t == TR_NONE; i++) {
    const uint32_t *tv = m->tv + 4 * (size_t)q[i];
    if (tet_has(tv, b) && (c == TR_NONE || tet_has(tv, c))) {
      *t = q[i];
      if (with_ghosts || tr_tet_is_real(m, q[i]))
        break;
      *t = TR_NONE; /* a hull edge or face is also in the real tet across the hull */
    }
    for (int k = 0; k < 4; k++) {
      if (tv[k] == p)
        continue;
      uint32_t u = TR_NEIG(m, q[i], k);
      if (u == TR_NONE || (m->flags[u] & TR_TF_MARK))
        continue;
      if (nq == cap) {
        uint32_t nc = 2 * cap, *nqa = malloc(sizeof *nqa * nc);
        if (!nqa) {
          s = tr_error(TR_ERR_NOMEM, "out of memory for Ball(%u)", p);
          break;
        }
        memcpy(nqa, q, sizeof *q * nq);
        if (q != local)
          free(q);
        q = nqa;
        cap = nc;
      }
      m->flags[u] |= TR_TF_MARK;
      q[nq++] = u;
    }
    if (s != TR_OK)
      break;
  }
  for (uint32_t i = 0; i < nq; i++)
    m->flags[q[i]] &= (uint8_t)~TR_TF_MARK;
  if (q != local)
    free(q);
  return s;
}

tr_status tr_ball_find_domain(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c,
                              uint32_t *t)
{
  TR_CHECK(tr_ball_find(m, p, b, c, t));
  if (*t == TR_NONE)
    TR_CHECK(tr_ball_find(m, b, p, c, t));
  if (*t == TR_NONE && c != TR_NONE)
    TR_CHECK(tr_ball_find(m, c, p, b, t));
  /* every ball's v2t piece missed it: the rare non-manifold vertex, or no such edge */
  for (uint32_t u = 0; *t == TR_NONE && u < m->nt; u++) {
    if (!tr_tet_is_real(m, u))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)u;
    if (tet_has(tv, p) && tet_has(tv, b) && (c == TR_NONE || tet_has(tv, c)))
      *t = u;
  }
  return TR_OK;
}

tr_status tr_mesh_find_faces(const struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                             uint32_t *tet)
{
  /* The real tets of each vertex, in slot order (a CSR built in two passes over the
   * tets): a triangle's tet is the first in the list of its vertex with the fewest tets
   * that has the other two, so the first real tet in slot order with the face, as a
   * deterministic answer must be. A hash of the triangles probed for every face of every
   * tet cost twice as much (a sorted key and a hash per face, two faces per tet). */
  uint32_t nv = m->nv, *start = calloc((size_t)nv + 2, sizeof *start), *list = NULL;
  if (!start)
    return tr_error(TR_ERR_NOMEM, "out of memory for the tets of %u vertices", nv);
  size_t total = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int k = 0; k < 4; k++)
      start[tv[k] + 2]++;
    total += 4;
  }
  if (total >= UINT32_MAX || !(list = malloc(sizeof *list * (total ? total : 1)))) {
    free(start);
    return tr_error(TR_ERR_NOMEM, "out of memory for the %zu vertex-tet pairs of the mesh",
                    total);
  }
  /* counted at v + 2, summed: start[v + 1] is where v's entries begin; filling moves it
   * to where they end, so that v's range is [start[v], start[v + 1]) */
  for (uint32_t v = 2; v <= nv; v++)
    start[v] += start[v - 1];
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int k = 0; k < 4; k++)
      list[start[tv[k] + 1]++] = t;
  }
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t *T = tris + 3 * (size_t)i;
    tet[i] = TR_NONE;
    if (T[0] >= nv || T[1] >= nv || T[2] >= nv)
      continue; /* no tet has a vertex that is not in the mesh */
    int a = 0;
    for (int k = 1; k < 3; k++)
      if (start[T[k] + 1] - start[T[k]] < start[T[a] + 1] - start[T[a]])
        a = k;
    uint32_t b = T[(a + 1) % 3], c = T[(a + 2) % 3];
    if (b == c || b == T[a])
      continue; /* a degenerate triple is no face */
    for (uint32_t j = start[T[a]]; j < start[T[a] + 1]; j++) {
      const uint32_t *tv = m->tv + 4 * (size_t)list[j];
      if ((tv[0] == b || tv[1] == b || tv[2] == b || tv[3] == b) &&
          (tv[0] == c || tv[1] == c || tv[2] == c || tv[3] == c)) {
        tet[i] = list[j];
        break;
      }
    }
  }
  free(start);
  free(list);
  return TR_OK;
}

tr_status tr_mesh_find_edges(const struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                             uint8_t *present)
{
  for (uint32_t i = 0; i < n; i++) {
    uint32_t a = edges[2 * (size_t)i], b = edges[2 * (size_t)i + 1];
    if (a == b || a >= m->nv || b >= m->nv)
      return tr_error(TR_ERR_INTERNAL, "edge %u (%u-%u): not two vertices of the mesh (%u)",
                      i, a, b, m->nv);
  }
  /* up[start[u] .. start[u + 1]): the higher ends of u's edges, one entry per real tet
   * with the edge (a few repeats each, cheaper to scan than to remove) */
  size_t total = 0;
  uint32_t *start = calloc((size_t)m->nv + 2, sizeof *start), *up = NULL;
  if (!start)
    return tr_error(TR_ERR_NOMEM, "out of memory for the edges of %u vertices", m->nv);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int e = 0; e < 6; e++) {
      uint32_t u = tv[tr_edge_vtx[e][0]], w = tv[tr_edge_vtx[e][1]];
      start[(u < w ? u : w) + 2]++;
    }
    total += 6;
  }
  if (total >= UINT32_MAX || !(up = malloc(sizeof *up * (total ? total : 1)))) {
    free(start);
    return tr_error(TR_ERR_NOMEM, "out of memory for the %zu tet edges of the mesh", total);
  }
  /* counted at u + 2, summed: start[u + 1] is where u's entries begin; filling moves it
   * to where they end, so that u's range is [start[u], start[u + 1]) */
  for (uint32_t v = 2; v <= m->nv; v++)
    start[v] += start[v - 1];
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int e = 0; e < 6; e++) {
      uint32_t u = tv[tr_edge_vtx[e][0]], w = tv[tr_edge_vtx[e][1]];
      if (u < w)
        up[start[u + 1]++] = w;
      else
        up[start[w + 1]++] = u;
    }
  }
  for (uint32_t i = 0; i < n; i++) {
    uint32_t a = edges[2 * (size_t)i], b = edges[2 * (size_t)i + 1];
    if (a > b) {
      uint32_t x = a;
      a = b;
      b = x;
    }
    uint8_t yes = 0;
    for (uint32_t j = start[a]; j < start[a + 1] && !yes; j++)
      yes = up[j] == b;
    present[i] = yes;
  }
  free(start);
  free(up);
  return TR_OK;
}

/* For tet t containing a (slot i) and b (slot j): the slots c, d such that (a,b,c,d) is
 * an even permutation of the slots, i.e. a positively oriented listing of t. */
static void shell_cd(int i, int j, int *c, int *d)
{
  int x = -1, y = -1;
  for (int k = 0; k < 4; k++)
    if (k != i && k != j) {
      if (x < 0)
        x = k;
      else
        y = k;
    }
  int perm[4] = {i, j, x, y}, inv = 0;
  for (int p = 0; p < 4; p++)
    for (int q = p + 1; q < 4; q++)
      inv += perm[p] > perm[q];
  if (inv % 2 == 0) {
    *c = x;
    *d = y;
  } else {
    *c = y;
    *d = x;
  }
}

tr_status tr_shell(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0, tr_u32buf *out,
                   int *closed)
{
  out->n = 0;
  *closed = 0;
  if (t0 == TR_NONE) {
    tr_u32buf ball = {0};
    tr_status s = tr_ball(m, a, 1, &ball);
    if (s == TR_OK) {
      for (size_t i = 0; i < ball.n && t0 == TR_NONE; i++)
        if (tr_ncode(m, ball.a[i], b) >= 0)
          t0 = ball.a[i];
    }
    tr_u32buf_free(&ball);
    TR_CHECK(s);
    if (t0 == TR_NONE)
      return tr_error(TR_ERR_INTERNAL, "Shell(%u,%u): the edge is not in the mesh", a, b);
  }
  if (tr_tet_ecode(m, t0, a, b) < 0)
    return tr_error(TR_ERR_INTERNAL, "Shell(%u,%u): tet %u does not have this edge", a, b, t0);
  /* Forward: across the face opposite c (it holds a, b, d). */
  uint32_t t = t0, limit = m->nt + 1;
  for (;;) {
    TR_CHECK(tr_u32buf_push(out, t));
    int c, d;
    shell_cd(tr_ncode(m, t, a), tr_ncode(m, t, b), &c, &d);
    uint32_t u = TR_NEIG(m, t, c);
    if (u == t0) {
      *closed = 1;
      return TR_OK;
    }
    if (u == TR_NONE)
      break;
    if (tr_tet_ecode(m, u, a, b) < 0 || out->n > limit)
      return tr_error(TR_ERR_INVALID_MESH, "Shell(%u,%u): tet %u does not close around the edge",
                      a, b, u);
    t = u;
  }
  /* Open shell: walk backwards from t0 (across the face opposite d) and put those first. */
  size_t nfwd = out->n;
  t = t0;
  for (;;) {
    int c, d;
    shell_cd(tr_ncode(m, t, a), tr_ncode(m, t, b), &c, &d);
    uint32_t u = TR_NEIG(m, t, d);
    if (u == TR_NONE)
      break;
    if (tr_tet_ecode(m, u, a, b) < 0 || out->n > limit)
      return tr_error(TR_ERR_INVALID_MESH, "Shell(%u,%u): tet %u does not close around the edge",
                      a, b, u);
    TR_CHECK(tr_u32buf_push(out, u));
    t = u;
  }
  /* out = fwd[0..nfwd) back[nfwd..n): reorder to reverse(back) fwd. */
  size_t nb = out->n - nfwd;
  if (nb) {
    uint32_t *tmp = malloc(out->n * sizeof *tmp);
    if (!tmp)
      return tr_error(TR_ERR_NOMEM, "out of memory in Shell");
    for (size_t i = 0; i < nb; i++)
      tmp[i] = out->a[out->n - 1 - i];
    for (size_t i = 0; i < nfwd; i++)
      tmp[nb + i] = out->a[i];
    for (size_t i = 0; i < out->n; i++)
      out->a[i] = tmp[i];
    free(tmp);
  }
  return TR_OK;
}
