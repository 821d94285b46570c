/* The suppression stage's driver: sub-face bookkeeping, the outer tets taken out, the
 * passes over the boundary Steiner points, the --keep-surface verdict and the counts. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/check.h"
#include "mesh/conform.h"
#include "suppress_int.h"

tr_status sup_add(sup_ctx *c, uint32_t a, uint32_t b, uint32_t cc, uint32_t tri)
{
  if (c->n == c->cap) {
    uint32_t nc = c->cap ? 2 * c->cap : 64;
    uint32_t *v = realloc(c->v, sizeof *v * 3 * (size_t)nc);
    if (v)
      c->v = v;
    uint32_t *t = realloc(c->tri, sizeof *t * nc);
    if (t)
      c->tri = t;
    if (!v || !t)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-faces", nc);
    c->cap = nc;
  }
  if (c->nl + 3 > c->capl) {
    uint32_t nc = c->capl ? 2 * c->capl : 192;
    uint32_t *x = realloc(c->lnext, sizeof *x * nc);
    if (x)
      c->lnext = x;
    uint32_t *y = realloc(c->lsub, sizeof *y * nc);
    if (y)
      c->lsub = y;
    if (!x || !y)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-face links", nc);
    c->capl = nc;
  }
  uint32_t s = c->n++, f[3] = {a, b, cc};
  memcpy(c->v + 3 * (size_t)s, f, sizeof f);
  c->tri[s] = tri;
  for (int k = 0; k < 3; k++)
    if (f[k] < c->nv) {
      c->lsub[c->nl] = s;
      c->lnext[c->nl] = c->head[f[k]];
      c->head[f[k]] = c->nl++;
    }
  return TR_OK;
}

tr_status sup_faces_of(const sup_ctx *c, uint32_t p, tr_u32buf *out)
{
  out->n = 0;
  if (p >= c->nv)
    return TR_OK;
  for (uint32_t l = c->head[p]; l != TR_NONE; l = c->lnext[l])
    if (c->tri[c->lsub[l]] != TR_NONE)
      TR_CHECK(tr_u32buf_push(out, c->lsub[l]));
  return TR_OK;
}

tr_status sup_is_sub(const sup_ctx *c, const uint32_t w0[3], tr_u32buf *tmp, int *yes)
{
  uint32_t w[3] = {w0[0], w0[1], w0[2]};
  tr_sort3(w);
  *yes = 0;
  TR_CHECK(sup_faces_of(c, w[0], tmp));
  for (size_t i = 0; i < tmp->n && !*yes; i++) {
    uint32_t f[3];
    memcpy(f, c->v + 3 * (size_t)tmp->a[i], sizeof f);
    tr_sort3(f);
    *yes = !memcmp(f, w, sizeof f);
  }
  return TR_OK;
}

/* Input points come first: an exact one (--resolve's rational corners) is no Steiner
 * point and stays. */
static int steiner(const struct tr_mesh *m, const tr_plc *plc, uint32_t v)
{
  return v >= plc->npoints && m->vq && m->vq[v];
}

static int kept(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER);
}

/* Frees the outer and ghost tets; the kept tets' faces towards them become boundary. */
static void detach_outer(struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t) || kept(m, t))
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t cde = m->tn[4 * (size_t)t + k];
      if (cde != TR_NONE && kept(m, cde >> 2))
        m->tn[cde] = TR_NONE;
    }
  }
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && !kept(m, t))
      tr_tet_free(m, t);
  for (uint32_t v = 0; v < m->nv; v++)
    m->v2t[v] = TR_NONE;
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t))
      for (int k = 0; k < 4; k++)
        m->v2t[m->tv[4 * (size_t)t + k]] = t;
}

/* Where p lies: 0 inside the domain, 1 on an input edge, 2 inside an input triangle. */
static int where(const sup_ctx *c, uint32_t p, const tr_u32buf *f)
{
  if (f->n == 0)
    return 0;
  uint32_t tri = c->tri[f->a[0]];
  for (size_t i = 1; i < f->n; i++)
    if (c->tri[f->a[i]] != tri)
      return 1;
  /* one triangle: inside it iff its fan around p is closed (every u is some w) */
  for (size_t i = 0; i < f->n; i++) {
    const uint32_t *a = c->v + 3 * (size_t)f->a[i];
    int ia = a[0] == p ? 0 : a[1] == p ? 1 : 2;
    uint32_t u = a[(ia + 1) % 3];
    int hit = 0;
    for (size_t j = 0; j < f->n && !hit; j++) {
      const uint32_t *b = c->v + 3 * (size_t)f->a[j];
      int ib = b[0] == p ? 0 : b[1] == p ? 1 : 2;
      hit = b[(ib + 2) % 3] == u;
    }
    if (!hit)
      return 1;
  }
  return 2;
}

/* The error of --keep-surface for a point that stays on the boundary. */
static tr_status refuse(const sup_ctx *c, uint32_t p, const tr_u32buf *f, int loc)
{
  const tr_plc *plc = c->plc;
  const double *x = c->m->xyz + 3 * (size_t)p;
  uint32_t t0 = c->tri[f->a[0]];
  const uint32_t *a = plc->tris + 3 * (size_t)t0;
  uint32_t src = plc->tri_source ? plc->tri_source[t0] : t0;
  if (loc == 2)
    return tr_error(TR_ERR_UNSUPPORTED,
                    "--keep-surface: Steiner point %u (%.17g, %.17g, %.17g) inside input "
                    "facet %u (vertices %u %u %u) cannot be taken off the surface: no "
                    "vertex or double point of its star sees the whole star, or the star "
                    "meets an internal facet, a crack or another region",
                    p, x[0], x[1], x[2], src, a[0], a[1], a[2]);
  /* the input edge: the vertices the triangles of p's fans share */
  uint32_t e[2] = {TR_NONE, TR_NONE};
  for (size_t i = 0; i < f->n && e[1] == TR_NONE; i++) {
    uint32_t t1 = c->tri[f->a[i]];
    if (t1 == t0)
      continue;
    const uint32_t *b = plc->tris + 3 * (size_t)t1;
    int n = 0;
    for (int j = 0; j < 3; j++)
      for (int k = 0; k < 3; k++)
        if (a[j] == b[k] && n < 2)
          e[n++] = a[j];
  }
  return tr_error(TR_ERR_UNSUPPORTED,
                  "--keep-surface: Steiner point %u (%.17g, %.17g, %.17g) on input edge "
                  "(%u, %u) of facet %u cannot be taken off the surface: no vertex or "
                  "double point of its star sees the whole star, or the star meets an "
                  "internal facet, a crack or another region",
                  p, x[0], x[1], x[2], e[0], e[1], src);
}

static int cmp_sub(const void *pa, const void *pb)
{
  const uint32_t *a = pa, *b = pb; /* tri, v0, v1, v2 */
  for (int i = 0; i < 4; i++)
    if (a[i] != b[i])
      return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* The live sub-faces back into sub, in its documented order. */
static tr_status write_back(sup_ctx *c, tr_subfaces *sub)
{
  uint32_t n = 0;
  for (uint32_t i = 0; i < c->n; i++)
    n += c->tri[i] != TR_NONE;
  uint32_t *rec = malloc(sizeof *rec * 4 * (size_t)(n ? n : 1));
  uint32_t *v = malloc(sizeof *v * 3 * (size_t)(n ? n : 1));
  uint32_t *tri = malloc(sizeof *tri * (n ? n : 1));
  if (!rec || !v || !tri) {
    free(rec);
    free(v);
    free(tri);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-faces", n);
  }
  uint32_t k = 0;
  for (uint32_t i = 0; i < c->n; i++)
    if (c->tri[i] != TR_NONE) {
      uint32_t *r = rec + 4 * (size_t)k++;
      r[0] = c->tri[i];
      memcpy(r + 1, c->v + 3 * (size_t)i, 3 * sizeof *r);
      tr_rotate_min3(r + 1);
    }
  qsort(rec, n, 4 * sizeof *rec, cmp_sub);
  for (uint32_t i = 0; i < n; i++) {
    tri[i] = rec[4 * (size_t)i];
    memcpy(v + 3 * (size_t)i, rec + 4 * (size_t)i + 1, 3 * sizeof *v);
  }
  free(rec);
  free(sub->v);
  free(sub->tri);
  sub->v = v;
  sub->tri = tri;
  sub->n = n;
  return TR_OK;
}

tr_status tr_suppress_steiner(struct tr_mesh *m, tr_subfaces *sub, const tr_plc *plc,
                              unsigned flags, tr_suppress_stats *out)
{
  tr_suppress_stats local;
  if (!out)
    out = &local;
  memset(out, 0, sizeof *out);
  sup_ctx c;
  memset(&c, 0, sizeof c);
  c.m = m;
  c.plc = plc;
  c.nv = m->nv;
  tr_u32buf f = {0};
  uint8_t *used = NULL;
  tr_status st = TR_OK;
  if (!(c.head = malloc(sizeof *c.head * (m->nv ? m->nv : 1))))
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", m->nv);
  for (uint32_t v = 0; v < m->nv; v++)
    c.head[v] = TR_NONE;
  c.tried = calloc(2 * (size_t)(m->nv ? m->nv : 1), sizeof *c.tried);
  c.mtried = calloc(m->nv ? m->nv : 1, sizeof *c.mtried);
  c.ftried = calloc(2 * (size_t)(m->nv ? m->nv : 1), sizeof *c.ftried);
  if (!c.tried || !c.mtried || !c.ftried) {
    free(c.head);
    free(c.tried);
    free(c.mtried);
    free(c.ftried);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", m->nv);
  }
  for (uint32_t i = 0; i < sub->n && st == TR_OK; i++)
    st = sup_add(&c, sub->v[3 * (size_t)i], sub->v[3 * (size_t)i + 1],
                 sub->v[3 * (size_t)i + 2], sub->tri[i]);
  int any = 0;
  for (uint32_t p = 0; p < m->nv && st == TR_OK && !any && m->vq; p++)
    if (steiner(m, plc, p) && (st = sup_faces_of(&c, p, &f)) == TR_OK)
      any = f.n > 0 || (flags & TR_SUP_INTERIOR);
  unsigned act = flags & (TR_SUP_REMOVE | TR_SUP_RELOCATE);
  /* the interior points are counted among those to look at only when asked */
  if (st == TR_OK && any && act) {
    detach_outer(m);
    /* removal first, to a fixed point (a removal can free a neighbour on the same edge);
     * then relocation of what is left; then removal again, of interior points too if
     * asked */
    unsigned last = TR_SUP_REMOVE | (flags & TR_SUP_INTERIOR);
    /* the interior removal changes the stars of the points still on the surface: a
     * second removal and relocation round, and then interior removal again, takes most
     * of them off (under --keep-surface, cheese, rotor, rotor_small and turbine of CGAL's
     * models failed with three rounds) */
    /* then merging, once one by one nothing more goes: a merge moves the point that
     * stays, which can block a removal one by one that would have come later (on
     * chazelle_g8 merging in the earlier rounds left 9 points where they leave none) */
    unsigned rounds[6] = {TR_SUP_REMOVE, act, last, act, last,
                          last | (flags & TR_SUP_MERGE)};
    int nr = (flags & TR_SUP_INTERIOR) ? ((flags & TR_SUP_MERGE) ? 6 : 5) : 3;
    for (int r = 0; r < nr && st == TR_OK; r++) {
      if (!(rounds[r] & act))
        continue;
      int changed = 1;
      for (int pass = 0; pass < 16 && changed && st == TR_OK; pass++) {
        changed = 0;
        for (uint32_t p = 0; p < m->nv && st == TR_OK; p++) {
          if (!steiner(m, plc, p) || m->v2t[p] == TR_NONE)
            continue;
          int done = 0;
          st = sup_point(&c, p, rounds[r] | (flags & TR_SUP_REQUIRE), &done);
          if (done == 1)
            out->removed++;
          else if (done == 2)
            out->relocated++;
          changed |= done != 0;
          if (st == TR_OK && done && (flags & TR_SUP_CHECK)) {
            st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
            if (st == TR_OK)
              st = tr_check_conformity(m, plc, NULL, 0);
            if (st != TR_OK) {
              char why[512]; /* tr_last_error's buffer is the one tr_error writes */
              snprintf(why, sizeof why, "%s", tr_last_error());
              st = tr_error(st, "after %s Steiner point %u: %s",
                            done == 1 ? "removing" : "relocating", p, why);
            }
          }
        }
        if (rounds[r] & TR_SUP_RELOCATE)
          break; /* a relocated point is off the boundary: one pass is enough; removals
                    free their neighbours, so those rounds go on while they remove */
      }
    }
  }
  /* the counts, over the vertices of the kept tets */
  if (st == TR_OK && !(used = calloc(m->nv ? m->nv : 1, 1)))
    st = tr_error(TR_ERR_NOMEM, "out of memory for %u vertices", m->nv);
  for (uint32_t t = 0; t < m->nt && st == TR_OK; t++)
    if (kept(m, t))
      for (int k = 0; k < 4; k++)
        used[m->tv[4 * (size_t)t + k]] = 1;
  for (uint32_t p = 0; p < m->nv && st == TR_OK; p++) {
    if (!used[p] || !steiner(m, plc, p))
      continue;
    if ((st = sup_faces_of(&c, p, &f)) != TR_OK)
      break;
    int loc = where(&c, p, &f);
    if (loc == 0)
      out->interior++;
    else if (loc == 1)
      out->on_edges++;
    else
      out->on_facets++;
    if (loc && (flags & TR_SUP_REQUIRE))
      st = refuse(&c, p, &f, loc);
  }
  if (st == TR_OK && any && act)
    st = write_back(&c, sub);
  free(used);
  tr_u32buf_free(&f);
  free(c.head);
  free(c.tried);
  free(c.mtried);
  free(c.ftried);
  free(c.v);
  free(c.tri);
  free(c.lnext);
  free(c.lsub);
  return st;
}
