/* Pipe(E) collection and per-edge recovery (see pipe.h). */
#include "recover_edges/pipe.h"

#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "construct.h"
#include "mesh/orient_memo.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/swap.h"

void tr_pipe_free(tr_pipe *p)
{
  free(p->pl);
  memset(p, 0, sizeof *p);
}

static tr_status pipe_push(tr_pipe *p, const tr_pipel *x)
{
  if (p->n == p->cap) {
    uint32_t nc = p->cap ? 2 * p->cap : 16;
    tr_pipel *q = realloc(p->pl, nc * sizeof *q);
    if (!q)
      return tr_error(TR_ERR_NOMEM, "out of memory for a pipe of %u pipels", p->n);
    p->pl = q;
    p->cap = nc;
  }
  p->pl[p->n++] = *x;
  return TR_OK;
}

tr_status tr_mesh_has_edge(struct tr_mesh *m, uint32_t a, uint32_t b, int *yes)
{
  uint32_t t;
  tr_status s = tr_ball_find(m, a, b, TR_NONE, &t);
  *yes = s == TR_OK && t != TR_NONE;
  return s;
}

/* Classifies ab against real tet t; fills pl (iNod of EDG/FAC ends left TR_NONE). Returns
 * 1 if t is a pipel; sets *via to a vertex of t strictly inside ab, if any. */
static int classify(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t, tr_pipel *pl,
                    uint32_t *via, tr_segmemo *memo)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  tr_isect x;
  if (memo)
    x = tr_segmemo_classify(memo, m, v);
  else
    x = tr_segmemo_classify_ids(m, a, b, v);
  int cut = 0;
  uint8_t ty[2] = {TR_DEG, TR_DEG}, code[2] = {0, 0};
  uint32_t nod[2] = {TR_NONE, TR_NONE};
  for (int e = 0; e < x.n; e++) {
    ty[e] = x.end[e].type;
    code[e] = x.end[e].code;
    if (ty[e] == TR_NOD) {
      nod[e] = v[code[e]];
      if (nod[e] != a && nod[e] != b)
        *via = nod[e];
    } else {
      cut = 1;
    }
  }
  memset(pl, 0, sizeof *pl);
  pl->iEle = t;
  pl->type = TR_PIPEL_TYPE(ty[0], ty[1]);
  pl->iCod1 = code[0];
  pl->iCod2 = code[1];
  pl->iNod1 = nod[0];
  pl->iNod2 = nod[1];
  return cut;
}

/* 1 iff ab meets the hull face of ghost g at a point that is not a vertex of it: the
 * face gets split, so g must be replaced by one ghost per sub-face. */
static int tr_pipe_find_ghost(const tr_pipe *p, uint32_t t)
{
  for (uint32_t i = 0; i < p->n; i++)
    if (p->pl[i].ghost && p->pl[i].iEle == t)
      return 1;
  return 0;
}

/* 1 iff ab meets the hull face k of pipel pl's tet at a point that is not a vertex of it
 * (the face then gets split, so the ghost beyond it must be replaced by one ghost per
 * sub-face). Read off the classification against the tet, exactly: the face is part of
 * the tet, so ab meets it only in points of the clipped part of ab; if ab crosses its
 * plane that is an end of the part (the tet lies on one side), and if ab lies in the
 * plane the whole part lies in the face. An end on face k is a vertex, an edge or the
 * interior of the face as it is one of the tet (NOD other than k, EDG on an edge without
 * vertex k, FAC k). Classifying ab against the face itself instead mostly met ab lying
 * in a flat hull's plane, where every orientation is an exact zero: on 65395.stl
 * --keep-surface a twentieth of the run. */
static int ghost_is_cut(const tr_pipel *pl, int k)
{
  for (int e = 0; e < 2; e++) {
    int ty = e ? (pl->type >> 2) & 3 : pl->type & 3, code = e ? pl->iCod2 : pl->iCod1;
    if ((ty == TR_EDG && tr_ecode_start(code) != k && tr_ecode_end(code) != k) ||
        (ty == TR_FAC && code == k))
      return 1;
  }
  return 0;
}

tr_status tr_pipe_collect(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                          uint32_t *via)
{
  return tr_pipe_collect_memo(m, a, b, pipe, via, NULL);
}

/* The tets of a's star that ab enters, found by a walk in the star instead of
 * classifying all of it: those whose closed cone at a holds the direction of b (no
 * other tet of the star meets ab beyond a). Returns their number: 1 (the direction
 * inside a cone), 2 (inside the sector of a facet: the tets on both sides), or -1 when
 * the walk does not settle it: the direction along an edge of the star (a vertex on
 * ab), a step onto the hull, or a walk longer than the star (a walk in a triangulated
 * sphere of directions may cycle). */
static int star_entry(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_u32buf *ball,
                      uint32_t in[2])
{
  if (!ball->n)
    return -1;
  uint32_t t = ball->a[0];
  for (size_t step = 0; step <= ball->n; step++) {
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    int ia = -1, neg = -1, zero = -1, nzero = 0;
    for (int k = 0; k < 4; k++)
      if (tv[k] == a)
        ia = k;
    if (ia < 0)
      return -1;
    for (int k = 0; k < 4 && neg < 0; k++) {
      if (k == ia)
        continue;
      uint32_t p[4] = {tv[0], tv[1], tv[2], tv[3]};
      p[k] = b; /* g_k(b) of the classifier: >= 0 on tet's side of the facet through a */
      int g = tr_mesh_orient(m, p[0], p[1], p[2], p[3]);
      if (g < 0)
        neg = k;
      else if (g == 0)
        zero = k, nzero++;
    }
    if (neg < 0) {
      if (nzero > 1)
        return -1;
      in[0] = t;
      if (!nzero)
        return 1;
      uint32_t u = TR_NEIG(m, t, zero);
      if (u == TR_NONE || !tr_tet_is_real(m, u))
        return -1;
      in[1] = u;
      return 2;
    }
    uint32_t u = TR_NEIG(m, t, neg);
    if (u == TR_NONE || !tr_tet_is_real(m, u))
      return -1;
    t = u;
  }
  return -1;
}

tr_status tr_pipe_collect_memo(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                               uint32_t *via, tr_segmemo *memo)
{
  pipe->n = 0;
  *via = TR_NONE;
  tr_u32buf seen = {0}, ball = {0};
  tr_status s = tr_ball(m, a, 0, &ball);
  /* seen doubles as the BFS queue; TR_TF_MARK flags are cleared before returning */
  for (size_t i = 0; s == TR_OK && i < ball.n; i++) {
    m->flags[ball.a[i]] |= TR_TF_MARK;
    s = tr_u32buf_push(&seen, ball.a[i]);
  }
  /* Only the one or two tets of a's star that ab enters are pipels there; the others
   * need no classification (most of a collection's tests were on them). They are still
   * listed and marked, so the walk below and the pipe's order are as before. */
  uint32_t in[2] = {TR_NONE, TR_NONE};
  int nin = s == TR_OK ? star_entry(m, a, b, &ball, in) : -1;
#ifndef NDEBUG
  /* debug builds classify the whole star and check the walk's answer */
  for (size_t i = 0; s == TR_OK && nin > 0 && i < ball.n; i++) {
    uint32_t t = ball.a[i], dv = TR_NONE;
    tr_pipel tp;
    int cut = tr_tet_is_real(m, t) && classify(m, a, b, t, &tp, &dv, NULL);
    if (cut != (t == in[0] || t == in[1]))
      s = tr_error(TR_ERR_INTERNAL, "pipe %u-%u: tet %u of the star is %s by the walk", a, b,
                   t, cut ? "entered but missed" : "taken but not entered");
  }
#endif
  for (size_t i = 0; s == TR_OK && i < seen.n && *via == TR_NONE; i++) {
    uint32_t t = seen.a[i];
    tr_pipel pl, tp;
    if (nin > 0 && i < ball.n && t != in[0] && t != in[1])
      continue;
    if (!tr_tet_is_real(m, t) || !classify(m, a, b, t, &tp, via, memo))
      continue;
    if ((s = pipe_push(pipe, &tp)) != TR_OK)
      break;
    for (int k = 0; k < 4 && s == TR_OK; k++) {
      uint32_t u = TR_NEIG(m, t, k);
      if (u == TR_NONE || (m->flags[u] & TR_TF_MARK))
        continue;
      m->flags[u] |= TR_TF_MARK;
      s = tr_u32buf_push(&seen, u);
      if (s == TR_OK && !tr_tet_is_free(m, u) && tr_tet_is_ghost(m, u) &&
          ghost_is_cut(&tp, k)) {
        memset(&pl, 0, sizeof pl);
        pl.iEle = u;
        pl.ghost = 1;
        pl.iNod1 = pl.iNod2 = TR_NONE;
        s = pipe_push(pipe, &pl);
      }
    }
  }
  for (size_t i = 0; i < seen.n; i++)
    m->flags[seen.a[i]] &= (uint8_t)~TR_TF_MARK;
  tr_u32buf_free(&seen);
  tr_u32buf_free(&ball);
  if (s == TR_OK && *via != TR_NONE)
    pipe->n = 0;
  return s;
}

/* Entity key of an EDG / FAC end: its mesh vertices, sorted, TR_NONE-padded. */
static void end_key(const struct tr_mesh *m, uint32_t t, int ty, int code, uint32_t k[3])
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  if (ty == TR_EDG) {
    k[0] = v[tr_ecode_start(code)];
    k[1] = v[tr_ecode_end(code)];
    k[2] = TR_NONE;
  } else {
    for (int i = 0, q = 0; i < 4; i++)
      if (i != code)
        k[q++] = v[i];
  }
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++)
      if (k[j] < k[i]) {
        uint32_t x = k[i];
        k[i] = k[j];
        k[j] = x;
      }
}

typedef struct skey {
  uint32_t k[3], v;
} skey;

tr_status tr_pipe_add_steiner(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                              uint32_t *nadded)
{
  *nadded = 0;
  skey *keys = malloc((2 * (size_t)pipe->n + 1) * sizeof *keys);
  if (!keys)
    return tr_error(TR_ERR_NOMEM, "out of memory for Steiner keys");
  uint32_t nk = 0;
  tr_status s = TR_OK;
  /* Pipels in collection order, ends in segment order: the Steiner ids are deterministic */
  for (uint32_t i = 0; i < pipe->n && s == TR_OK; i++) {
    tr_pipel *pl = &pipe->pl[i];
    if (pl->ghost)
      continue;
    for (int e = 0; e < 2 && s == TR_OK; e++) {
      int ty = e ? (pl->type >> 2) & 3 : pl->type & 3;
      if (ty != TR_EDG && ty != TR_FAC)
        continue;
      uint32_t key[3];
      end_key(m, pl->iEle, ty, e ? pl->iCod2 : pl->iCod1, key);
      uint32_t id = TR_NONE;
      for (uint32_t j = 0; j < nk && id == TR_NONE; j++)
        if (!memcmp(keys[j].k, key, sizeof key))
          id = keys[j].v;
      if (id == TR_NONE) {
        tr_qpoint *q = malloc(sizeof *q);
        if (!q) {
          s = tr_error(TR_ERR_NOMEM, "out of memory for a Steiner point");
          break;
        }
        tr_qpoint_init(q);
        /* fetched here: adding a vertex may move m->xyz */
        tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
        tr_point p0 = tr_mesh_point(m, key[0]), p1 = tr_mesh_point(m, key[1]);
        int rc;
        if (ty == TR_EDG) {
          rc = tr_construct_line_line(&pa, &pb, &p0, &p1, q);
        } else {
          tr_point p2 = tr_mesh_point(m, key[2]);
          rc = tr_construct_line_plane(&pa, &pb, &p0, &p1, &p2, q);
        }
        if (rc != 0) {
          tr_qpoint_clear(q);
          free(q);
          s = tr_error(TR_ERR_INTERNAL, "edge %u-%u: Steiner point on %s %u-%u-%u undefined",
                       a, b, ty == TR_EDG ? "edge" : "face", key[0], key[1], key[2]);
          break;
        }
        if ((s = tr_mesh_add_constructed(m, q, &id)) != TR_OK) {
          tr_qpoint_clear(q);
          free(q);
          break;
        }
        keys[nk].k[0] = key[0];
        keys[nk].k[1] = key[1];
        keys[nk].k[2] = key[2];
        keys[nk++].v = id;
        ++*nadded;
      }
      if (e)
        pl->iNod2 = id;
      else
        pl->iNod1 = id;
    }
  }
  free(keys);
  return s;
}

/* One side face of a ghost tet: {u, v, GHOST} with u < v the hull edge. */
typedef struct side {
  uint32_t u, v, t;
  int k, used;
} side;

static void side_of(const struct tr_mesh *m, uint32_t t, int k, side *s)
{
  uint32_t w[2];
  for (int i = 0, q = 0; i < 3; i++)
    if (i != k)
      w[q++] = m->tv[4 * (size_t)t + (size_t)i];
  s->u = w[0] < w[1] ? w[0] : w[1];
  s->v = w[0] < w[1] ? w[1] : w[0];
  s->t = t;
  s->k = k;
  s->used = 0;
}

/* Replaces every ghost pipel by one ghost per sub-face of its hull face. The real pipels
 * are decomposed first; the faces they left open are exactly the sub-faces of split hull
 * faces. Side faces (hull edge + GHOST) are glued by matching hull edges, to each other
 * and to the untouched ghosts around. */
static tr_status split_ghosts(struct tr_mesh *m, tr_pipe *p)
{
  uint32_t ng = 0, nreal = 0;
  for (uint32_t i = 0; i < p->n; i++) {
    ng += p->pl[i].ghost;
    nreal += p->pl[i].ghost ? 0 : p->pl[i].nTets;
  }
  if (ng == 0)
    return TR_OK;
  /* open faces of the new real tets, at most 4 per tet; sides: 3 per new ghost + 3 per
   * old ghost */
  size_t nopen = 0, nside = 0;
  uint32_t *open = malloc(4 * (size_t)nreal * 2 * sizeof *open);
  int32_t *owner = malloc(4 * (size_t)nreal * sizeof *owner);
  side *sd = malloc((4 * (size_t)nreal + 3 * (size_t)ng) * 3 * sizeof *sd);
  uint32_t *hull = malloc(3 * (size_t)ng * sizeof *hull);
  tr_status s = TR_OK;
  if (!open || !owner || !sd || !hull) {
    s = tr_error(TR_ERR_NOMEM, "out of memory splitting hull faces");
    goto done;
  }
  for (uint32_t i = 0; i < p->n; i++) {
    const tr_pipel *pl = &p->pl[i];
    for (int j = 0; !pl->ghost && j < pl->nTets; j++)
      for (int k = 0; k < 4; k++)
        if (m->tn[4 * (size_t)pl->dectets[j] + (size_t)k] == TR_NONE) {
          open[2 * nopen] = pl->dectets[j];
          open[2 * nopen + 1] = (uint32_t)k;
          owner[nopen++] = -1;
        }
  }
  /* assign open faces to ghosts; record the sides towards ghosts that stay */
  uint32_t gi = 0;
  for (uint32_t i = 0; i < p->n; i++) {
    const tr_pipel *pl = &p->pl[i];
    if (!pl->ghost)
      continue;
    uint32_t g = pl->iEle;
    tr_point h[3];
    for (int k = 0; k < 3; k++) {
      hull[3 * gi + k] = m->tv[4 * (size_t)g + (size_t)k];
      uint32_t c = m->tn[4 * (size_t)g + (size_t)k];
      if (c != TR_NONE && !tr_pipe_find_ghost(p, c >> 2))
        side_of(m, c >> 2, (int)(c & 3), &sd[nside++]);
    }
    for (size_t f = 0; f < nopen; f++) {
      if (owner[f] >= 0)
        continue;
      int in = 1;
      for (int k = 0; k < 3; k++)
        h[k] = tr_mesh_point(m, hull[3 * gi + k]);
      for (int q = 0; q < 4 && in; q++) {
        if (q == (int)open[2 * f + 1])
          continue;
        tr_point x = tr_mesh_point(m, m->tv[4 * (size_t)open[2 * f] + (size_t)q]);
        in = tr_classify_point_triangle(&x, &h[0], &h[1], &h[2]).type != TR_DEG;
      }
      if (in)
        owner[f] = (int32_t)gi;
    }
    gi++;
  }
  for (size_t f = 0; f < nopen; f++)
    if (owner[f] < 0) {
      s = tr_error(TR_ERR_INTERNAL, "face %u of new tet %u is open but on no split hull face",
                   open[2 * f + 1], open[2 * f]);
      goto done;
    }
  for (uint32_t i = 0; i < p->n; i++)
    if (p->pl[i].ghost)
      tr_tet_free(m, p->pl[i].iEle);
  for (size_t f = 0; f < nopen; f++) {
    uint32_t r = open[2 * f], t;
    int k = (int)open[2 * f + 1];
    const uint8_t *fv = tr_face_vtx[k];
    const uint32_t *v = m->tv + 4 * (size_t)r;
    /* the real tet sees (a,b,c) with its inward normal; the ghost wants the outward one */
    if ((s = tr_tet_new(m, v[fv[0]], v[fv[2]], v[fv[1]], TR_GHOST, &t)) != TR_OK)
      goto done;
    tr_glue(m, t, 3, r, k);
    for (int q = 0; q < 3; q++)
      side_of(m, t, q, &sd[nside++]);
  }
  for (size_t i = 0; i < nside; i++) {
    if (sd[i].used)
      continue;
    size_t j = i + 1;
    while (j < nside && (sd[j].used || sd[j].u != sd[i].u || sd[j].v != sd[i].v))
      j++;
    if (j == nside) {
      s = tr_error(TR_ERR_INTERNAL, "hull edge %u-%u: ghost side face without a partner",
                   sd[i].u, sd[i].v);
      goto done;
    }
    sd[i].used = sd[j].used = 1;
    tr_glue(m, sd[i].t, sd[i].k, sd[j].t, sd[j].k);
  }
done:
  free(open);
  free(owner);
  free(sd);
  free(hull);
  return s;
}

tr_status tr_pipe_try_swaps(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                            const struct tr_edgeset *cons, tr_edge_stats *st, int *done)
{
  *done = 0;
  for (uint32_t i = 0; i < p->n; i++)
    if (p->pl[i].ghost)
      return TR_OK;
  if (p->n == 2) {
    for (uint32_t i = 0; i < 2; i++) {
      const tr_pipel *pl = &p->pl[i];
      if (pl->type == TR_PIPEL_TYPE(TR_NOD, TR_FAC) && pl->iNod1 == a) {
        uint32_t out[3];
        TR_CHECK(tr_swap23(m, pl->iEle, pl->iCod2, out, done));
        if (*done)
          st->by_swap23++;
        return TR_OK;
      }
    }
  }
  if (p->n == 4) {
    uint32_t c = TR_NONE, d = TR_NONE;
    for (uint32_t i = 0; i < 4; i++) {
      const tr_pipel *pl = &p->pl[i];
      int ty1 = pl->type & 3, ty2 = (pl->type >> 2) & 3, ec;
      if (ty1 == TR_NOD && ty2 == TR_EDG)
        ec = pl->iCod2;
      else if (ty1 == TR_EDG && ty2 == TR_NOD)
        ec = pl->iCod1;
      else
        return TR_OK;
      uint32_t u = m->tv[4 * (size_t)pl->iEle + (size_t)tr_ecode_start(ec)],
               w = m->tv[4 * (size_t)pl->iEle + (size_t)tr_ecode_end(ec)];
      if (c == TR_NONE) {
        c = u;
        d = w;
      } else if (!((c == u && d == w) || (c == w && d == u))) {
        return TR_OK;
      }
    }
    if (tr_edgeset_get(cons, c, d) != TR_EDGESET_NONE)
      return TR_OK;
    uint32_t out[4];
    TR_CHECK(tr_swap44(m, a, b, c, d, out, done));
    if (*done)
      st->by_swap44++;
  }
  return TR_OK;
}

/* Which table a decomposed pipel went through (its raw type, cut edges and DType). */
static int pipel_kind(const tr_pipel *pl)
{
  switch (tr_pipel_case(pl->type & 15)) {
  case 1: return TR_PK_CASE1;
  case 2: {
    int s0 = tr_ecode_start(pl->iCod1), e0 = tr_ecode_end(pl->iCod1);
    int s1 = tr_ecode_start(pl->iCod2), e1 = tr_ecode_end(pl->iCod2);
    if (!(s0 == s1 || s0 == e1 || e0 == s1 || e0 == e1))
      return TR_PK_CASE2_I;
    return (pl->type & 0xF0) ? TR_PK_CASE2_Z : TR_PK_CASE2_S;
  }
  case 3: return TR_PK_CASE3;
  case 4: return TR_PK_CASE4;
  default: return TR_PK_CASE5;
  }
}

tr_status tr_pipe_decompose(struct tr_mesh *m, tr_pipe *p, tr_edge_stats *st)
{
  for (uint32_t i = 0; i < p->n; i++) {
    tr_pipel *pl = &p->pl[i];
    if (pl->ghost) {
      st->ghosts_split++;
      continue;
    }
    TR_CHECK(tr_pipel_decompose(m, p->pl, p->n, pl));
    st->pipels[pipel_kind(pl)]++;
    st->raw[pl->type & 15]++;
  }
  return split_ghosts(m, p);
}

tr_status tr_recover_edge(struct tr_mesh *m, uint32_t a, uint32_t b, tr_edge_stats *st)
{
  /* explicit stack of sub-segments still to recover: splitting at existing vertices */
  tr_u32buf stack = {0};
  tr_pipe pipe = {0};
  tr_status s = tr_u32buf_push(&stack, a);
  if (s == TR_OK)
    s = tr_u32buf_push(&stack, b);
  while (stack.n > 0 && s == TR_OK) {
    uint32_t v1 = stack.a[stack.n - 1], v0 = stack.a[stack.n - 2];
    stack.n -= 2;
    int yes;
    if ((s = tr_mesh_has_edge(m, v0, v1, &yes)) != TR_OK)
      break;
    if (yes) {
      st->already++;
      continue;
    }
    uint32_t via;
    if ((s = tr_pipe_collect(m, v0, v1, &pipe, &via)) != TR_OK)
      break;
    if (via != TR_NONE) {
      st->split_at_vertex++;
      uint32_t four[4] = {via, v1, v0, via};
      for (int i = 0; i < 4 && s == TR_OK; i++)
        s = tr_u32buf_push(&stack, four[i]);
      continue;
    }
    if (pipe.n == 0) {
      s = tr_error(TR_ERR_INTERNAL, "edge %u-%u: empty pipe for a missing edge", v0, v1);
      break;
    }
    int done;
    if ((s = tr_pipe_try_swaps(m, v0, v1, &pipe, NULL, st, &done)) != TR_OK || done)
      continue;
    uint32_t nadd;
    if ((s = tr_pipe_add_steiner(m, v0, v1, &pipe, &nadd)) != TR_OK)
      break;
    st->steiner_points += nadd;
    if ((s = tr_pipe_decompose(m, &pipe, st)) == TR_OK)
      st->by_pipels++;
  }
  tr_u32buf_free(&stack);
  tr_pipe_free(&pipe);
  return s;
}

/* 1 when pipel pl starts at the end vertex (a if at_a, else b) and leaves its star
 * through a face or an edge: that crossing's type and code in pl's tet. */
static int end_crossing(const struct tr_mesh *m, const tr_pipel *pl, uint32_t a, uint32_t b,
                        int at_a, int *type, int *code)
{
  const uint32_t *tv = m->tv + 4 * (size_t)pl->iEle;
  int t1 = pl->type & 3, t2 = (pl->type >> 2) & 3;
  int ty = at_a ? t2 : t1;
  if ((at_a ? t1 : t2) != TR_NOD || tv[at_a ? pl->iCod1 : pl->iCod2] != (at_a ? a : b))
    return 0;
  if (ty != TR_EDG && ty != TR_FAC)
    return 0;
  *type = ty;
  *code = at_a ? pl->iCod2 : pl->iCod1;
  return 1;
}

int tr_pipe_end(const struct tr_mesh *m, const tr_pipe *p, uint32_t a, uint32_t b, int at_a,
                int *type, int *code)
{
  for (uint32_t i = 0; i < p->n; i++)
    if (!p->pl[i].ghost && end_crossing(m, &p->pl[i], a, b, at_a, type, code))
      return (int)i;
  return -1;
}

tr_status tr_pipe_end_star(struct tr_mesh *m, uint32_t a, uint32_t b, int at_a,
                           tr_segmemo *memo, tr_u32buf *ball, uint32_t *t, int *type,
                           int *code, int *found)
{
  *found = 0;
  uint32_t end = at_a ? a : b;
  if (end >= m->nv || m->v2t[end] == TR_NONE) {
    *found = -1; /* not a vertex of the mesh (tests ask for such segments): collect */
    return TR_OK;
  }
  TR_CHECK(tr_ball(m, end, 0, ball));
  uint32_t in[2] = {TR_NONE, TR_NONE}; /* as in the collection: the rest are not pipels */
  int nin = star_entry(m, end, at_a ? b : a, ball, in);
  for (size_t i = 0; i < ball->n; i++) {
    uint32_t u = ball->a[i], via = TR_NONE;
    tr_pipel pl;
    if (!tr_tet_is_real(m, u) || (nin > 0 && u != in[0] && u != in[1]))
      continue;
    int cut = classify(m, a, b, u, &pl, &via, memo);
    if (via != TR_NONE) {
      *found = -1; /* the collection stops there: let it */
      return TR_OK;
    }
    int ty, co;
    if (!cut || !end_crossing(m, &pl, a, b, at_a, &ty, &co))
      continue;
    if (*found) {
      /* at a, the collection lists a's star first, in this order: the first one is its
       * choice too; b's star comes in the order of the walk from a */
      if (!at_a)
        *found = -1;
      return TR_OK;
    }
    *found = 1;
    *t = u;
    *type = ty;
    *code = co;
  }
  return TR_OK;
}
