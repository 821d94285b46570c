/* Two interior Steiner points become one (issue 16).
 *
 * An interior Steiner point p whose star has no retriangulation without it (neither a
 * cone from a link vertex, nor the Delaunay fill of the star, nor flips at p) usually
 * has it because its link has a constraint face that a fill without an inner point
 * cannot keep: edge recovery put a point there because the surface needed one. Such
 * points often come in pairs and clusters (a long pipe split twice, neighbouring
 * pipes), and the region two of them fill together often needs only one: the union U of
 * the stars of p and of a neighbour q (an edge pq, q an interior Steiner point too) is
 * replaced by the cone from one point x over U's boundary, where x is q (p goes), p (q
 * goes), or a double point inside U's kernel that q moves to (as relocation moves a
 * boundary point, star.c). Repeated, a cluster of k such points goes down to one.
 *
 * U's boundary faces hold neither p nor q (a face on p has both its tets on p), and the
 * faces inside U are those on p or q and the link faces of p that q's tets share: none
 * may be a constraint (sub-face), and U's tets must all be real and of p's region, so
 * that x replaces two points of one region's interior and every constraint stays on the
 * boundary of U as it was. Every cone tet is checked exactly positive (and, with dbl,
 * at its vertices' doubles); tr_mesh_replace checks the cone has exactly U's boundary. */
#include <stdlib.h>
#include <string.h>

#include "suppress_int.h"

/* the margins find_q's projections try for x (star.c), the widest first: on cheese 2
 * leave 145 points, 4 leave 142 for 4% more time, 6 no fewer */
#define SUP_MERGE_RELAX 4

static int cmp_u32(const void *a, const void *b)
{
  uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
  return (x > y) - (x < y);
}

static int in_set(const tr_u32buf *s, uint32_t t)
{
  return bsearch(&t, s->a, s->n, sizeof t, cmp_u32) != NULL;
}

/* An interior Steiner point whose tets are real, of region `region`, with no constraint
 * face on it and no mesh boundary face on it. */
static tr_status inner_point(struct tr_mesh *m, const sup_ctx *c, uint32_t v, uint32_t region,
                             tr_u32buf *ball, tr_u32buf *tmp, int *ok)
{
  *ok = 0;
  if (!m->vq || !m->vq[v] || m->v2t[v] == TR_NONE)
    return TR_OK;
  TR_CHECK(sup_faces_of(c, v, tmp));
  if (tmp->n)
    return TR_OK;
  TR_CHECK(tr_ball(m, v, 1, ball));
  for (size_t i = 0; i < ball->n; i++) {
    uint32_t t = ball->a[i];
    if (!tr_tet_is_real(m, t) || (m->region && m->region[t] != region))
      return TR_OK;
    for (int k = 0; k < 4; k++)
      if (m->tv[4 * (size_t)t + k] != v && m->tn[4 * (size_t)t + k] == TR_NONE)
        return TR_OK;
  }
  *ok = ball->n >= 4;
  return TR_OK;
}

/* U = bp + bq (sorted, unique) and its boundary faces (right-hand normal pointing in),
 * *ok = 0 if a face inside U that is on neither p nor q is a constraint. */
static tr_status union_of(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t q,
                          const tr_u32buf *bp, const tr_u32buf *bq, tr_u32buf *u,
                          tr_u32buf *bf, tr_u32buf *tmp, int *ok)
{
  *ok = 1;
  u->n = bf->n = 0;
  for (size_t i = 0; i < bp->n; i++)
    TR_CHECK(tr_u32buf_push(u, bp->a[i]));
  for (size_t i = 0; i < bq->n; i++)
    TR_CHECK(tr_u32buf_push(u, bq->a[i]));
  qsort(u->a, u->n, sizeof *u->a, cmp_u32);
  size_t n = 0;
  for (size_t i = 0; i < u->n; i++)
    if (n == 0 || u->a[i] != u->a[n - 1])
      u->a[n++] = u->a[i];
  u->n = n;
  for (size_t i = 0; i < u->n && *ok; i++) {
    uint32_t t = u->a[i];
    for (int k = 0; k < 4 && *ok; k++) {
      uint32_t w[3], nb = TR_NEIG(m, t, k);
      for (int a = 0; a < 3; a++)
        w[a] = m->tv[4 * (size_t)t + tr_face_vtx[k][a]];
      int onpq = 0;
      for (int a = 0; a < 3; a++)
        onpq |= w[a] == p || w[a] == q;
      if (nb != TR_NONE && in_set(u, nb)) {
        int sub = 0;
        if (!onpq && t < nb) {
          TR_CHECK(sup_is_sub(c, w, tmp, &sub));
          *ok = !sub;
        }
        continue;
      }
      if (onpq) { /* cannot happen for interior p and q: refuse rather than guess */
        *ok = 0;
        break;
      }
      for (int a = 0; a < 3; a++)
        TR_CHECK(tr_u32buf_push(bf, w[a]));
    }
  }
  return TR_OK;
}

/* Replaces U by the cone from apex over bf; p and q lose their tets unless apex. */
static tr_status cone(struct tr_mesh *m, const tr_u32buf *u, const tr_u32buf *bf, uint32_t apex,
                      uint32_t region, int *done)
{
  size_t nf = bf->n / 3;
  uint32_t *nv = malloc(sizeof *nv * 4 * (nf ? nf : 1)), *ids = malloc(sizeof *ids * (nf ? nf : 1));
  tr_status st = TR_OK;
  if (!nv || !ids) {
    st = tr_error(TR_ERR_NOMEM, "out of memory merging two points");
    goto out;
  }
  for (size_t i = 0; i < nf; i++) {
    memcpy(nv + 4 * i, bf->a + 3 * i, 3 * sizeof *nv);
    nv[4 * i + 3] = apex;
  }
  st = tr_mesh_replace(m, u->a, (uint32_t)u->n, nv, (uint32_t)nf, ids);
  if (st == TR_ERR_INTERNAL) { /* not U's boundary: refused, mesh unchanged */
    st = TR_OK;
    goto out;
  }
  if (st != TR_OK)
    goto out;
  for (size_t i = 0; i < nf; i++) {
    if (m->region)
      m->region[ids[i]] = region;
    for (int k = 0; k < 4; k++)
      m->v2t[nv[4 * i + k]] = ids[i];
  }
  *done = 1;
out:
  free(nv);
  free(ids);
  return st;
}

static int cmp_tri(const void *pa, const void *pb)
{
  const uint32_t *a = pa, *b = pb;
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i])
      return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* h mixed with q and U's boundary faces, each rotated to its smallest vertex first,
 * sorted (bf is reordered: the cone does not depend on the order of its faces). */
static uint64_t mix(uint64_t h, uint32_t q, tr_u32buf *bf)
{
  for (size_t i = 0; i < bf->n; i += 3)
    tr_rotate_min3(bf->a + i);
  qsort(bf->a, bf->n / 3, 3 * sizeof *bf->a, cmp_tri);
  h = (h ^ q) * 0xBF58476D1CE4E5B9ull;
  for (size_t i = 0; i < bf->n; i++)
    h = (h ^ bf->a[i]) * 0x94D049BB133111EBull;
  return h ^ (h >> 29);
}

/* Merges p into q, with U = their stars and bf its boundary: *done = 1 if p is gone. */
static tr_status merge_pair(struct tr_mesh *m, uint32_t p, uint32_t q, const tr_u32buf *u,
                            const tr_u32buf *bf, uint32_t region, int dbl, int *done)
{
  size_t nf = bf->n / 3;
  tr_status st = TR_OK;
  /* q stays where it is, or p does (q goes), or q moves into U's kernel */
  if (sup_sees_all(m, bf->a, nf, q, NULL, dbl)) {
    if ((st = cone(m, u, bf, q, region, done)) == TR_OK && *done)
      m->v2t[p] = TR_NONE;
    return st;
  }
  if (sup_sees_all(m, bf->a, nf, p, NULL, dbl)) {
    if ((st = cone(m, u, bf, p, region, done)) == TR_OK && *done)
      m->v2t[q] = TR_NONE;
    return st;
  }
  double dir[4] = {0, 0, 0, 0}, x[3];
  int found = 0;
  TR_CHECK(sup_find_q(m, bf, u, m->xyz + 3 * (size_t)p, m->xyz + 3 * (size_t)q, dir, dbl,
                      SUP_MERGE_RELAX, x, &found));
  if (!found)
    return TR_OK;
  /* the cone is positive for x, so for q moved there (exactly, a double); which faces
   * the cone has does not depend on where q is */
  if ((st = cone(m, u, bf, q, region, done)) == TR_OK && *done) {
    tr_qpoint_set_d(m->vq[q], x);
    memcpy(m->xyz + 3 * (size_t)q, x, sizeof x);
    m->v2t[p] = TR_NONE;
  }
  return st;
}

tr_status sup_merge(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t region, int dbl,
                    int *done)
{
  *done = 0;
  tr_u32buf bp = {0}, bq = {0}, u = {0}, bf = {0}, tmp = {0}, nbr = {0};
  int ok = 0;
  tr_status st = inner_point(m, c, p, region, &bp, &tmp, &ok);
  /* the candidates q: p's link vertices that are Steiner points, in id order, each once */
  for (size_t i = 0; i < bp.n && st == TR_OK && ok; i++)
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      uint32_t v = m->tv[4 * (size_t)bp.a[i] + k];
      if (v != p && m->vq[v])
        st = tr_u32buf_push(&nbr, v);
    }
  if (st == TR_OK && ok && nbr.n) {
    qsort(nbr.a, nbr.n, sizeof *nbr.a, cmp_u32);
    size_t n = 0;
    for (size_t i = 0; i < nbr.n; i++)
      if (n == 0 || nbr.a[i] != nbr.a[n - 1])
        nbr.a[n++] = nbr.a[i];
    nbr.n = n;
  }
  /* pass 0 keys the candidate unions: the passes retry every point left while anything
   * changed, and the same unions with p and q where they were fail the same way */
  uint64_t key = 0x2545F4914F6CDD1Dull ^ (uint64_t)dbl;
  for (int pass = 0; pass < 2 && st == TR_OK && ok && !*done; pass++) {
    if (pass == 1 && c->mtried && c->mtried[p] == key)
      break;
    for (size_t i = 0; i < nbr.n && st == TR_OK && !*done; i++) {
      uint32_t q = nbr.a[i];
      int qok = 0, uok = 0;
      if ((st = inner_point(m, c, q, region, &bq, &tmp, &qok)) != TR_OK || !qok)
        continue;
      if ((st = union_of(m, c, p, q, &bp, &bq, &u, &bf, &tmp, &uok)) != TR_OK || !uok)
        continue;
      if (pass == 0)
        key = mix(key, q, &bf);
      else
        st = merge_pair(m, p, q, &u, &bf, region, dbl, done);
    }
  }
  if (st == TR_OK && ok && !*done && c->mtried)
    c->mtried[p] = key;
  tr_u32buf_free(&bp);
  tr_u32buf_free(&bq);
  tr_u32buf_free(&u);
  tr_u32buf_free(&bf);
  tr_u32buf_free(&tmp);
  tr_u32buf_free(&nbr);
  return st;
}
