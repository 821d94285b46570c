/* Swap23 and edge removal with exact validity tests (see flip.h). Both build the new
 * tets' vertex lists, test every real one strictly positive, and leave the relinking to
 * tr_mesh_replace, which also refuses (mesh unchanged) a set that does not have the old
 * region's boundary. */
#include "recover_edges/flip.h"

#include "mesh/orient_memo.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Through the orientation memo when the stage has it on (mesh/orient_memo.h): the
 * searches below ask the same tuples many times over. */
static int positive(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  return tr_mesh_orient(m, a, b, c, d) > 0;
}

/* A cheap shape measure in doubles (only ranks valid triangulations, never decides
 * validity): 6 * volume / (sum of squared edge lengths)^(3/2), scale free. */
static double quality(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  const double *p[4] = {m->xyz + 3 * (size_t)a, m->xyz + 3 * (size_t)b, m->xyz + 3 * (size_t)c,
                        m->xyz + 3 * (size_t)d};
  double u[3], v[3], w[3], s = 0;
  for (int i = 0; i < 3; i++) {
    u[i] = p[1][i] - p[0][i];
    v[i] = p[2][i] - p[0][i];
    w[i] = p[3][i] - p[0][i];
  }
  double vol = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]);
  for (int i = 0; i < 4; i++)
    for (int j = i + 1; j < 4; j++)
      for (int k = 0; k < 3; k++) {
        double e = p[i][k] - p[j][k];
        s += e * e;
      }
  return s > 0 ? fabs(vol) / (s * sqrt(s)) : 0;
}

static void record(tr_flip_rec *rec, const uint32_t *newv, const uint32_t *ids, uint32_t nold,
                   uint32_t nnew)
{
  if (!rec)
    return;
  rec->nold = nold;
  rec->nnew = nnew;
  memcpy(rec->newid, ids, nnew * sizeof *ids);
  memcpy(rec->newv, newv, 4 * (size_t)nnew * sizeof *newv);
}

tr_status tr_flip23(struct tr_mesh *m, uint32_t t, int k, tr_flip_guard guard, void *ud,
                    tr_flip_rec *rec, int *done)
{
  *done = 0;
  assert(k >= 0 && k < 4);
  uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
  if (c == TR_NONE || !tr_tet_is_real(m, t) || !tr_tet_is_real(m, c >> 2))
    return TR_OK;
  uint32_t u = c >> 2;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  uint32_t a = tv[k], b = m->tv[4 * (size_t)u + (c & 3)];
  uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
  if (guard && guard(ud, f, 3))
    return TR_OK;
  /* stop at the first failing side: a zero is often a rational point on a plane, which
   * only the exact stage decides */
  int sg[3];
  for (int i = 0; i < 3; i++) {
    sg[i] = tr_mesh_orient(m, a, b, f[i], f[(i + 1) % 3]);
    if (sg[i] == 0 || sg[i] != sg[0])
      return TR_OK;
  }
  if (sg[0] < 0) {
    uint32_t x = a;
    a = b;
    b = x;
  }
  uint32_t newv[12], old[2] = {t, u}, ids[3];
  for (int i = 0; i < 3; i++) {
    newv[4 * i] = a;
    newv[4 * i + 1] = b;
    newv[4 * i + 2] = f[i];
    newv[4 * i + 3] = f[(i + 1) % 3];
  }
  uint32_t oldv[8];
  memcpy(oldv, m->tv + 4 * (size_t)t, 4 * sizeof *oldv);
  memcpy(oldv + 4, m->tv + 4 * (size_t)u, 4 * sizeof *oldv);
  TR_CHECK(tr_mesh_replace(m, old, 2, newv, 3, ids));
  if (rec) {
    memcpy(rec->oldv, oldv, sizeof oldv);
    rec->hull = 0;
  }
  record(rec, newv, ids, 2, 3);
  *done = 1;
  return TR_OK;
}

int tr_flip23_blockers(const struct tr_mesh *m, uint32_t t, int k, uint32_t e[3][2])
{
  uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
  if (c == TR_NONE || !tr_tet_is_real(m, t) || !tr_tet_is_real(m, c >> 2))
    return 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  uint32_t a = tv[k], b = m->tv[4 * (size_t)(c >> 2) + (c & 3)];
  uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
  int n = 0;
  /* orient(a, b, f[i], f[i+1]) sums, as a volume, to a multiple of (b - a) . N with N
   * the face's normal, negative for a on the face's positive side: ab meets the open
   * face iff all three are negative, and an edge with a sign >= 0 is one ab passes
   * beside (or through) */
  for (int i = 0; i < 3; i++)
    if (tr_mesh_orient(m, a, b, f[i], f[(i + 1) % 3]) >= 0) {
      e[n][0] = f[i];
      e[n][1] = f[(i + 1) % 3];
      n++;
    }
  return n;
}

/* The vertex of tet t that is none of a, b and is shared with tet u. */
static uint32_t shared_third(const struct tr_mesh *m, uint32_t t, uint32_t u, uint32_t a,
                             uint32_t b)
{
  for (int i = 0; i < 4; i++) {
    uint32_t v = m->tv[4 * (size_t)t + (size_t)i];
    if (v != a && v != b && tr_ncode(m, u, v) >= 0)
      return v;
  }
  return TR_NONE;
}

typedef struct ering {
  const struct tr_mesh *m;
  uint32_t A, B;
  uint32_t r[TR_FLIP_MAX_RING];
  int n;        /* vertices of the polygon to triangulate (real ones) */
  double val[TR_FLIP_MAX_RING][TR_FLIP_MAX_RING];
  int8_t cut[TR_FLIP_MAX_RING][TR_FLIP_MAX_RING];
} ering;

/* Best triangulation of sub-polygon i..j (j - i >= 2): val = min quality, -1 impossible. */
static void ring_dp(ering *R)
{
  int n = R->n;
  for (int i = 0; i + 1 < n; i++)
    R->val[i][i + 1] = INFINITY;
  for (int len = 2; len < n; len++)
    for (int i = 0; i + len < n; i++) {
      int j = i + len;
      double best = -1;
      int bk = -1;
      for (int k = i + 1; k < j; k++) {
        double l = R->val[i][k], r = R->val[k][j];
        if (l < 0 || r < 0)
          continue;
        double q = l < r ? l : r;
        if (q <= best)
          continue; /* cannot improve: skip the exact tests */
        uint32_t x = R->r[i], y = R->r[k], z = R->r[j];
        if (!positive(R->m, R->A, x, y, z) || !positive(R->m, R->B, z, y, x))
          continue;
        double qa = quality(R->m, R->A, x, y, z), qb = quality(R->m, R->B, z, y, x);
        double qt = qa < qb ? qa : qb;
        if (qt < q)
          q = qt;
        if (q > best) {
          best = q;
          bk = k;
        }
      }
      R->val[i][j] = bk < 0 ? -1 : best;
      R->cut[i][j] = (int8_t)bk;
    }
}

/* Emits the tets of the chosen triangulation of i..j. */
static void ring_emit(const ering *R, int i, int j, uint32_t *newv, uint32_t *nnew)
{
  if (j - i < 2)
    return;
  int k = R->cut[i][j];
  uint32_t x = R->r[i], y = R->r[k], z = R->r[j];
  uint32_t *p = newv + 4 * (size_t)*nnew;
  p[0] = R->A; p[1] = x; p[2] = y; p[3] = z;
  p[4] = R->B; p[5] = z; p[6] = y; p[7] = x;
  *nnew += 2;
  ring_emit(R, i, k, newv, nnew);
  ring_emit(R, k, j, newv, nnew);
}

/* Ball(a) in tr_ball's order (ghosts included), stopped at the first tet that has b.
 * The same tet as the first of tr_ball(a, 1) with vertex b, without listing the rest of
 * the ball: these look-ups were a tenth of the flip drivers' time. */
tr_status tr_flip_edge_tet(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t *t)
{
  return tr_ball_find_ex(m, a, b, TR_NONE, 1, t);
}

static tr_status remove_edge(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                             tr_flip_guard guard, void *ud, const tr_flip_journal *j,
                             int star, tr_u32buf *sh, tr_flip_rec *rec, int *done, int *found);

tr_status tr_flip_remove_edge(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                              tr_flip_guard guard, void *ud, tr_flip_rec *rec, int *done)
{
  tr_u32buf sh = {0};
  int found;
  tr_status s = remove_edge(m, a, b, t0, guard, ud, NULL, 0, &sh, rec, done, &found);
  tr_u32buf_free(&sh);
  return s;
}

/* How many (tet, star) pairs tet v forms with the stars on j's stack below `top`. */
static int in_stars(const tr_flip_journal *j, const uint32_t *v, int top)
{
  int n = 0;
  for (int k = 0; k < top && k < TR_FLIP_STACK; k++) {
    uint32_t x = j->stack[2 * k], y = j->stack[2 * k + 1];
    int hx = 0, hy = 0;
    for (int q = 0; q < 4; q++) {
      hx |= v[q] == x;
      hy |= v[q] == y;
    }
    n += hx && hy;
  }
  return n;
}

/* sh: scratch for Shell(ab), whose memory the caller keeps across calls (the journal's
 * for the searches, which remove edges by the thousand). *found = 1 when ab is still
 * there and sh holds its closed shell from the tet tr_flip_edge_tet finds, as
 * tr_flip_remove_edge_nm takes it next (the mesh is then unchanged: *done = 0 and no
 * flip was made and undone). star: ab is a nested removal under the star rule; *found
 * = -1 when its shell breaks the rule (nothing is tried). */
static tr_status remove_edge(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                             tr_flip_guard guard, void *ud, const tr_flip_journal *j,
                             int star, tr_u32buf *sh, tr_flip_rec *rec, int *done, int *found)
{
  *done = 0;
  *found = 0;
  uint32_t e2[2] = {a, b};
  if (a == TR_GHOST || b == TR_GHOST || (guard && guard(ud, e2, 2)))
    return TR_OK;
  int looked = 0;
  if (t0 == TR_NONE || tr_tet_is_free(m, t0) || tr_tet_ecode(m, t0, a, b) < 0) {
    TR_CHECK(tr_flip_edge_tet(m, a, b, &t0));
    if (t0 == TR_NONE)
      return TR_OK;
    looked = 1;
  }
  int closed = 0;
  tr_status s = tr_shell(m, a, b, t0, sh, &closed);
  if (s == TR_OK && star) {
    /* the two tets at the face this removal unblocks are in the star above it */
    int n = 0;
    for (size_t i = 0; i < sh->n && n <= 2; i++)
      n += in_stars(j, m->tv + 4 * (size_t)sh->a[i], j->nstack);
    if (n > 2) {
      *found = -1;
      return TR_OK;
    }
  }
  *found = s == TR_OK && closed && looked;
  if (s != TR_OK || !closed || sh->n < 3 || sh->n > TR_FLIP_MAX_RING)
    return s;
  int n = (int)sh->n, g = -1, sign = 0, ok = 1;
  uint32_t ring[TR_FLIP_MAX_RING], old[TR_FLIP_MAX_RING];
  memcpy(old, sh->a, sh->n * sizeof *old);
  for (int i = 0; i < n && ok; i++) {
    ring[i] = shared_third(m, old[i], old[(i + 1) % n], a, b);
    ok = ring[i] != TR_NONE;
    if (ring[i] == TR_GHOST) {
      ok = g < 0;
      g = i;
    }
  }
  if (ok && j && j->tetgen_flips && n >= 4 && g < 0) {
    /* TetGen's flips reach a flat ring, and the 4-4 flip: four tets whose edge ab and
     * two opposite ring vertices are coplanar. The Swap23 that starts a 4-4 in TetGen
     * (flipnm) makes a flat tet, which tetrec's Swap23 refuses, so the 4-4 is taken here
     * in one step. Without it, the 2D diagonal swaps inside planar CAD faces were left
     * to the last level: turbine.off --keep-surface, on TetGen's own Delaunay mesh and in
     * its segment order, left 823 edges after level 4 where TetGen's first level leaves
     * 312; 373 with it (docs/recovery.md). */
    int flat = 1;
    for (int q = 3; q < n && flat; q++)
      flat = tr_mesh_orient(m, ring[0], ring[1], ring[2], ring[q]) == 0;
    if (!flat && n == 4)
      flat = tr_mesh_orient(m, a, b, ring[0], ring[2]) == 0 ||
             tr_mesh_orient(m, a, b, ring[1], ring[3]) == 0;
    if (!flat)
      return TR_OK;
  }
  /* tet i = {a, b, ring[i-1], ring[i]}: one parity for all real tets of the shell */
  for (int i = 0; i < n && ok; i++) {
    uint32_t p[4] = {a, b, ring[(i + n - 1) % n], ring[i]};
    if (p[2] == TR_GHOST || p[3] == TR_GHOST)
      continue;
    int e = tr_tet_even_order(m, old[i], p);
    if (e < 0 || (sign && (e ? 1 : -1) != sign))
      ok = 0;
    sign = e ? 1 : -1;
  }
  if (!ok || !sign)
    return TR_OK;
  for (int i = 0; i < n && guard; i++) {
    uint32_t f[3] = {a, b, ring[i]};
    if (ring[i] != TR_GHOST && guard(ud, f, 3))
      return TR_OK;
  }
  ering R;
  R.m = m;
  R.A = sign > 0 ? a : b; /* now (A, B, ring[i-1], ring[i]) is positive */
  R.B = sign > 0 ? b : a;
  /* the ghost, if any, goes last: the real polygon is ring[0..n-2] closed by C-D */
  R.n = g < 0 ? n : n - 1;
  for (int i = 0; i < R.n; i++)
    R.r[i] = ring[(g + 1 + i) % n];
  if (R.n < 3)
    return TR_OK;
  if (g >= 0) {
    uint32_t C = R.r[0], D = R.r[R.n - 1], X = R.r[1];
    /* hull faces ABC, BAD coplanar, AB and CD crossing inside both: the new hull faces
     * ACD, BDC cover the same quad (X is off the plane: tet A B C X is a real shell tet) */
    if (tr_mesh_orient(m, R.A, R.B, C, D) != 0)
      return TR_OK;
    int s1 = tr_mesh_orient(m, R.A, R.B, C, X), s2 = tr_mesh_orient(m, R.A, R.B, D, X);
    int s3 = tr_mesh_orient(m, C, D, R.A, X), s4 = tr_mesh_orient(m, C, D, R.B, X);
    if (!s1 || !s2 || !s3 || !s4 || s1 == s2 || s3 == s4)
      return TR_OK;
  }
  ring_dp(&R);
  if (R.val[0][R.n - 1] < 0)
    return TR_OK;
  uint32_t newv[4 * (2 * TR_FLIP_MAX_RING - 4)], nnew = 0, ids[2 * TR_FLIP_MAX_RING - 4];
  ring_emit(&R, 0, R.n - 1, newv, &nnew);
  if (g >= 0) {
    /* ghosts of ACD and BDC, TR_GHOST in slot 3 (even permutations of (A,C,D,G) and
     * (B,G,D,C), the orientation the ring order gives them) */
    uint32_t C = R.r[0], D = R.r[R.n - 1], *p = newv + 4 * (size_t)nnew;
    p[0] = R.A; p[1] = C; p[2] = D; p[3] = TR_GHOST;
    p[4] = C; p[5] = R.B; p[6] = D; p[7] = TR_GHOST;
    nnew += 2;
  }
  uint32_t oldv[4 * TR_FLIP_MAX_RING];
  for (int i = 0; i < n; i++)
    memcpy(oldv + 4 * i, m->tv + 4 * (size_t)old[i], 4 * sizeof *oldv);
  *found = 0; /* the shell goes now, also if the flip is taken back */
  TR_CHECK(tr_mesh_replace(m, old, (uint32_t)n, newv, nnew, ids));
  if (rec) {
    memcpy(rec->oldv, oldv, 4 * (size_t)n * sizeof *oldv);
    rec->hull = g >= 0;
  }
  record(rec, newv, ids, (uint32_t)n, nnew);
  *done = 1;
  return TR_OK;
}

/* 1 iff live tet t has exactly the vertices v[0..3] (same slots). */
static int holds(const struct tr_mesh *m, uint32_t t, const uint32_t v[4])
{
  return t < m->nt && !tr_tet_is_free(m, t) && memcmp(m->tv + 4 * (size_t)t, v, 4 * sizeof *v) == 0;
}

tr_status tr_flip_undo(struct tr_mesh *m, const tr_flip_rec *rec)
{
  uint32_t ids[2 * TR_FLIP_MAX_RING - 4];
  tr_u32buf ball = {0};
  tr_status s = TR_OK;
  for (uint32_t i = 0; i < rec->nnew && s == TR_OK; i++) {
    const uint32_t *v = rec->newv + 4 * (size_t)i;
    ids[i] = rec->newid[i];
    if (holds(m, ids[i], v))
      continue;
    ids[i] = TR_NONE;
    if ((s = tr_ball(m, v[0], 1, &ball)) != TR_OK)
      break;
    for (size_t k = 0; k < ball.n && ids[i] == TR_NONE; k++)
      if (holds(m, ball.a[k], v))
        ids[i] = ball.a[k];
    if (ids[i] == TR_NONE)
      s = tr_error(TR_ERR_INTERNAL, "flip undo: tet (%u %u %u %u) is gone", v[0], v[1], v[2],
                   v[3]);
  }
  tr_u32buf_free(&ball);
  TR_CHECK(s);
  return tr_mesh_replace(m, ids, rec->nnew, rec->oldv, rec->nold, NULL);
}

/* ---- journals and flipnm ---- */

void tr_flip_journal_free(tr_flip_journal *j)
{
  tr_u32buf_free(&j->shell);
  free(j->r);
  j->r = NULL;
  j->n = j->cap = 0;
}

/* Room for one more record: r[n] is then the slot to fill. */
static tr_status journal_room(tr_flip_journal *j)
{
  if (j->n < j->cap)
    return TR_OK;
  uint32_t nc = j->cap ? 2 * j->cap : 16;
  tr_flip_rec *q = realloc(j->r, nc * sizeof *q);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory for a flip journal");
  j->r = q;
  j->cap = nc;
  return TR_OK;
}

static void journal_commit(struct tr_mesh *m, tr_flip_journal *j)
{
  const tr_flip_rec *r = &j->r[j->n++];
  int kind = r->hull ? 4 : r->nold == 2 ? 0 : r->nold == 3 ? 1 : r->nold == 4 ? 2 : 3;
  j->flips[kind]++;
  if (!j->measure)
    return;
  for (uint32_t i = 0; i < r->nold; i++)
    j->delta -= j->measure(j->mud, m, r->oldv + 4 * (size_t)i);
  for (uint32_t i = 0; i < r->nnew; i++)
    j->delta += j->measure(j->mud, m, r->newv + 4 * (size_t)i);
}

tr_status tr_flip_journal_undo(struct tr_mesh *m, tr_flip_journal *j, uint32_t to)
{
  while (j->n > to) {
    const tr_flip_rec *r = &j->r[j->n - 1];
    int kind = r->hull ? 4 : r->nold == 2 ? 0 : r->nold == 3 ? 1 : r->nold == 4 ? 2 : 3;
    j->flips[kind]--;
    if (j->measure) {
      for (uint32_t i = 0; i < r->nnew; i++)
        j->delta -= j->measure(j->mud, m, r->newv + 4 * (size_t)i);
      for (uint32_t i = 0; i < r->nold; i++)
        j->delta += j->measure(j->mud, m, r->oldv + 4 * (size_t)i);
    }
    TR_CHECK(tr_flip_undo(m, r));
    j->n--;
  }
  return TR_OK;
}

/* Keeps the flip just made in r[n] if the journal's admission rule allows it. */
static tr_status admit(struct tr_mesh *m, tr_flip_journal *j, int *done)
{
  if (!*done)
    return TR_OK;
  if (j->accept && !j->accept(j->aud, m, &j->r[j->n])) {
    *done = 0;
    return tr_flip_undo(m, &j->r[j->n]);
  }
  journal_commit(m, j);
  return TR_OK;
}

static int spent(const tr_flip_journal *j)
{
  return j->budget && j->tries >= j->budget;
}

tr_status tr_flip23_j(struct tr_mesh *m, uint32_t t, int k, tr_flip_guard guard, void *ud,
                      tr_flip_journal *j, int *done)
{
  *done = 0;
  if (spent(j))
    return TR_OK;
  j->tries++;
  TR_CHECK(journal_room(j));
  TR_CHECK(tr_flip23(m, t, k, guard, ud, &j->r[j->n], done));
  return admit(m, j, done);
}

tr_status tr_flip23_jb(struct tr_mesh *m, uint32_t t, int k, int nb, tr_flip_guard guard,
                       void *ud, tr_flip_journal *j, int *done)
{
  if (nb != 1 && nb != 2)
    return tr_flip23_j(m, t, k, guard, ud, j, done);
  /* one side's sign is >= 0 and another's < 0: tr_flip23 would refuse; the try counts
   * (the budget sees the same tries either way) */
  *done = 0;
  if (!spent(j))
    j->tries++;
  return TR_OK;
}

/* *found: as remove_edge's (0 when nothing was tried) */
static tr_status remove_j(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                          tr_flip_guard guard, void *ud, tr_flip_journal *j, int star,
                          int *done, int *found)
{
  *done = 0;
  *found = 0;
  if (spent(j))
    return TR_OK;
  j->tries++;
  TR_CHECK(journal_room(j));
  TR_CHECK(remove_edge(m, a, b, t0, guard, ud, j, star, &j->shell, &j->r[j->n], done, found));
  return admit(m, j, done);
}

/* The shell tet holding face (a, b, r) and its code of that face, found from Shell(ab). */
static int shell_face(struct tr_mesh *m, const tr_u32buf *sh, uint32_t a, uint32_t b, uint32_t r,
                      uint32_t *t, int *k)
{
  for (size_t i = 0; i < sh->n; i++) {
    int c = tr_fcode(m, sh->a[i], a, b, r);
    if (c >= 0) {
      *t = sh->a[i];
      *k = c;
      return 1;
    }
  }
  return 0;
}

static tr_status remove_nm(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0, int depth,
                           tr_flip_guard guard, void *ud, tr_flip_journal *j, int nested,
                           int *done);

tr_status tr_flip_remove_edge_nm(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                                 int depth, tr_flip_guard guard, void *ud, tr_flip_journal *j,
                                 int *done)
{
  return remove_nm(m, a, b, t0, depth, guard, ud, j, 0, done);
}

/* nested: ab is removed to unblock a Swap23 of an outer level (the star rule applies) */
static tr_status remove_nm(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0, int depth,
                           tr_flip_guard guard, void *ud, tr_flip_journal *j, int nested,
                           int *done)
{
  int found;
  TR_CHECK(remove_j(m, a, b, t0, guard, ud, j, nested && j->stars, done, &found));
  j->pruned += found < 0;
  if (*done || found < 0 || depth <= 1 || spent(j))
    return TR_OK;
  uint32_t e2[2] = {a, b};
  if (guard && guard(ud, e2, 2))
    return TR_OK;
  tr_u32buf sh = {0};
  tr_status s = TR_OK;
  if (j->nstack < TR_FLIP_STACK) {
    j->stack[2 * j->nstack] = a;
    j->stack[2 * j->nstack + 1] = b;
  }
  j->nstack++;
  /* every pass either shrinks the shell by one (Swap23 on a ring face) or stops; the
   * sub-removals are bounded by depth, and the passes by the first shell size */
  for (int pass = 0, limit = -1; s == TR_OK && !*done; pass++) {
    int closed;
    uint32_t t1;
    if (found) {
      /* the failed removal just took this very shell and changed nothing: a copy (taking
       * every shell twice was 4% of the instructions of 65395.stl --keep-surface) */
      sh.n = 0;
      closed = 1;
      for (size_t i = 0; i < j->shell.n && s == TR_OK; i++)
        s = tr_u32buf_push(&sh, j->shell.a[i]);
      if (s != TR_OK)
        break;
    } else {
      if ((s = tr_flip_edge_tet(m, a, b, &t1)) != TR_OK)
        break;
      if (t1 == TR_NONE) {
        *done = 1; /* a nested removal took ab away */
        break;
      }
      if ((s = tr_shell(m, a, b, t1, &sh, &closed)) != TR_OK || !closed)
        break;
    }
    if (limit < 0)
      limit = (int)sh.n;
    if (pass > limit || sh.n < 3)
      break;
    int progress = 0;
    /* ring vertices in shell order (deterministic) */
    /* any flip (even a partial nested one) makes the shell stale: re-take it */
    uint32_t n0 = j->n;
    /* Each ring vertex r once, with the first shell tet holding face (a, b, r): a failed
     * try changes nothing (progress is any flip), so trying the same r again when the
     * next shell tet lists it would repeat the same work for the same answer. */
    uint32_t seen[64], nseen = 0;
    for (;;) {
      /* an undone nested removal leaves the same tets, not the same slots: the shell and
       * the tet copied from it are stale then, so the scan starts again on a fresh shell
       * (seen keeps the ring vertices already tried, and a scan meets a stale slot only
       * after a nested try of a new one, so it ends). A slot still holding the tet or
       * another one with face (a, b, r) is used as it is. */
      int stale = 0;
      for (size_t i = 0; i < sh.n && !progress && !stale && s == TR_OK && !spent(j); i++) {
        uint32_t tv[4];
        memcpy(tv, m->tv + 4 * (size_t)sh.a[i], sizeof tv); /* flips may move m->tv */
        for (int q = 0; q < 4 && !progress && !stale && s == TR_OK; q++) {
          uint32_t r = tv[q], t;
          int k, ok = 0, dup = 0;
          if (r == a || r == b || r == TR_GHOST)
            continue;
          for (uint32_t x = 0; x < nseen && !dup; x++)
            dup = seen[x] == r;
          if (dup)
            continue;
          if (nseen < 64) {
            /* first sight of r in shell order: this tet is the first with face (a, b, r) */
            t = sh.a[i];
            k = tr_fcode(m, t, a, b, r);
            if (k < 0) {
              /* a nested removal that undid its own flips leaves j->n as it was but may
               * free or refill this slot (fuzz_pipeline: a freed one, k = -1): the shell
               * is stale; r is tried on the fresh one */
              stale = 1;
              break;
            }
            seen[nseen++] = r;
          } else if (!shell_face(m, &sh, a, b, r, &t, &k))
            continue;
          /* with j->pivot, only the edges that block the Swap23 (TetGen's reflex link
           * edges): removing the others rarely helps and doubles the search per level */
          int try_ar = 1, try_br = 1, nb = -1;
          if (j->pivot) {
            uint32_t be[3][2];
            nb = tr_flip23_blockers(m, t, k, be);
            try_ar = try_br = 0;
            for (int x = 0; x < nb; x++) {
              try_ar |= (be[x][0] == a && be[x][1] == r) || (be[x][0] == r && be[x][1] == a);
              try_br |= (be[x][0] == b && be[x][1] == r) || (be[x][0] == r && be[x][1] == b);
            }
          }
          if (j->stars && j->nstack > 1) {
            /* a face whose tets are in another star on the stack is not flipped */
            uint32_t u = m->tn[4 * (size_t)t + (size_t)k];
            if (in_stars(j, m->tv + 4 * (size_t)t, j->nstack - 1) ||
                (u != TR_NONE && in_stars(j, m->tv + 4 * (size_t)(u >> 2), j->nstack - 1))) {
              j->pruned++;
              continue;
            }
          }
          s = tr_flip23_jb(m, t, k, nb, guard, ud, j, &ok);
          if (s == TR_OK && !ok && depth > 2 && !spent(j)) {
            /* the Swap23 is blocked by edge a-r or b-r: try removing one of them; a
             * removal that fails is undone before the other is tried */
            if (try_ar)
              s = remove_nm(m, a, r, TR_NONE, depth - 1, guard, ud, j, 1, &ok);
            if (s == TR_OK && !ok) {
              stale |= j->n != n0;
              s = tr_flip_journal_undo(m, j, n0);
            }
            if (s == TR_OK && !ok && try_br)
              s = remove_nm(m, b, r, TR_NONE, depth - 1, guard, ud, j, 1, &ok);
            if (s == TR_OK && !ok) {
              stale |= j->n != n0;
              s = tr_flip_journal_undo(m, j, n0);
            }
          }
          progress = ok || j->n != n0;
        }
      }
      if (s != TR_OK || progress || !stale || nseen >= 64 || spent(j))
        break;
      if ((s = tr_flip_edge_tet(m, a, b, &t1)) != TR_OK || t1 == TR_NONE)
        break;
      if ((s = tr_shell(m, a, b, t1, &sh, &closed)) != TR_OK || !closed)
        break;
    }
    if (s != TR_OK || !progress)
      break;
    s = remove_j(m, a, b, TR_NONE, guard, ud, j, 0, done, &found);
  }
  tr_u32buf_free(&sh);
  j->nstack--;
  return s;
}

/* ---- sets of simplices ---- */

void tr_sxset_clear(tr_sxset *s)
{
  tr_vtmap_clear(&s->map);
}

void tr_sxset_free(tr_sxset *s)
{
  tr_vtmap_free(&s->map);
}

/* Keys are sorted, so TR_NONE (an edge's v[2]) comes last and never starts a key. */
int tr_sxset_has(const tr_sxset *s, const uint32_t v[3])
{
  uint32_t o[3] = {v[0], v[1], v[2]};
  tr_sort3(o);
  return tr_vtmap_get(&s->map, 3, o) != TR_VTMAP_NONE;
}

int tr_sxset_add(tr_sxset *s, const uint32_t v[3])
{
  uint32_t o[3] = {v[0], v[1], v[2]}, n = s->map.n;
  tr_sort3(o);
  if (tr_vtmap_put(&s->map, 3, o, 1, NULL) != TR_OK)
    return -1;
  return s->map.n > n;
}
