/* Recovery of one missing facet: Swap32, general flips, cavity retriangulation, else
 * clusterel decomposition (see facet.h). */
#include "recover_facets/facet.h"

#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "construct.h"
#include "core/vtmap.h"
#include "mesh/orient_memo.h"
#include "recover_edges/decompose.h"
#include "recover_edges/edge_tables.h"
#include "recover_facets/cluster.h"
#include "recover_facets/dtype.h"
#include "recover_facets/flipfacet.h"

/* ---- crossed mesh edges and their Steiner points ---- */

typedef struct cut {
  uint32_t u, v; /* u < v */
  uint32_t p;    /* the Steiner vertex where uv crosses F */
} cut;

static int cmp_cut(const void *pa, const void *pb)
{
  const cut *a = pa, *b = pb;
  if (a->u != b->u)
    return a->u < b->u ? -1 : 1;
  return (a->v > b->v) - (a->v < b->v);
}

static uint32_t cut_point(const cut *c, uint32_t n, uint32_t a, uint32_t b)
{
  cut k = {a < b ? a : b, a < b ? b : a, 0};
  const cut *r = bsearch(&k, c, n, sizeof *c, cmp_cut);
  return r ? r->p : TR_NONE;
}

/* ---- the diagonal chosen on each face with two cut edges, by face vertex set ---- */

typedef struct dmap {
  tr_vtmap faces; /* sorted face vertices -> entry */
  uint32_t *ends; /* 2 per entry: the diagonal's ends, x < y */
  uint32_t n, cap;
} dmap;

/* ---- one facet's decomposition state ---- */

typedef struct ctx {
  struct tr_mesh *m;
  uint32_t idx;
  const tr_facet_opts *opt;
  tr_facet_detail *d;
  cut *cuts;
  uint32_t ncuts;
  dmap dm;
  tr_u32buf newv;  /* 4 ids per new tet */
  int forced;      /* force_first already used */
} ctx;

/* A face of the clusterel with two cut edges: X the apex, (X, U, V) the face in outward
 * order (dtype.h's definition of S and Z). Local codes. */
typedef struct quad {
  int on;
  int x, u, v;
} quad;

static int has_edge(const uint32_t *tets, int n, uint32_t a, uint32_t b)
{
  for (int i = 0; i < n; i++) {
    const uint32_t *t = tets + 4 * i;
    int ha = 0, hb = 0;
    for (int k = 0; k < 4; k++) {
      ha |= t[k] == a;
      hb |= t[k] == b;
    }
    if (ha && hb)
      return 1;
  }
  return 0;
}

/* The diagonal a candidate decomposition draws on quad face k: TR_DTYPE_S / _Z, or
 * TR_DTYPE_NONE when it draws neither or both (a broken table). */
static int drawn_type(const uint32_t *tv, uint32_t sp[4][4], const quad *q, const uint32_t *tets,
                      int n)
{
  int s = has_edge(tets, n, tv[q->v], sp[q->x][q->u]);
  int z = has_edge(tets, n, tv[q->u], sp[q->x][q->v]);
  if (s == z)
    return TR_DTYPE_NONE;
  return s ? TR_DTYPE_S : TR_DTYPE_Z;
}

/* Instantiates table t with ids into out (4 ids per tet). */
static int instantiate(const tr_dectable *t, const uint32_t ids[TR_DV_COUNT], uint32_t *out)
{
  for (int r = 0; r < t->nnew; r++)
    for (int i = 0; i < 4; i++)
      out[4 * r + i] = ids[t->tets[r].v[i]];
  return t->nnew;
}

#define MAX_NEW 16

/* Chooses and plans the decomposition of one crossing clusterel; appends its new tets to
 * cx->newv and records its diagonals. */
static tr_status plan_clusterel(ctx *cx, const tr_clusterel *c)
{
  struct tr_mesh *m = cx->m;
  uint32_t tv[4];
  memcpy(tv, m->tv + 4 * (size_t)c->iele, sizeof tv);
  int iscut[4][4];
  uint32_t sp[4][4];
  memset(iscut, 0, sizeof iscut);
  uint8_t ecodes[4], car[4][4], ncar[4];
  uint32_t sid[4];
  int ncut = 0;
  for (int i = 0; i < c->nnodes; i++) {
    if (c->ntypes[i] != TR_NOD_MID)
      continue;
    int s = tr_ecode_start(c->codes[i]), t = tr_ecode_end(c->codes[i]);
    uint32_t p = cut_point(cx->cuts, cx->ncuts, tv[s], tv[t]);
    if (p == TR_NONE)
      return tr_error(TR_ERR_INTERNAL, "facet %u: edge %u-%u has no Steiner point", cx->idx,
                      tv[s], tv[t]);
    iscut[s][t] = iscut[t][s] = 1;
    sp[s][t] = sp[t][s] = p;
    car[ncut][0] = (uint8_t)s;
    car[ncut][1] = (uint8_t)t;
    ncar[ncut] = 2;
    sid[ncut] = p;
    ecodes[ncut++] = c->codes[i];
  }
  /* Faces with two cut edges and what the decomposed neighbours imposed on them. */
  quad qd[4];
  int8_t want[4];
  int use_force = cx->opt && cx->opt->force_on && !cx->forced;
  for (int k = 0; k < 4; k++) {
    want[k] = TR_DTYPE_ANY;
    qd[k].on = 0;
    const uint8_t *fv = tr_face_vtx[k];
    int o[3] = {fv[0], fv[2], fv[1]}; /* outward order */
    for (int r = 0; r < 3; r++) {
      int x = o[r], u = o[(r + 1) % 3], v = o[(r + 2) % 3];
      if (iscut[x][u] && iscut[x][v] && !iscut[u][v]) {
        qd[k].on = 1;
        qd[k].x = x;
        qd[k].u = u;
        qd[k].v = v;
      }
    }
    if (!qd[k].on)
      continue;
    uint32_t f[3] = {tv[qd[k].x], tv[qd[k].u], tv[qd[k].v]};
    tr_sort3(f);
    uint32_t de = tr_vtmap_get(&cx->dm.faces, 3, f);
    if (de != TR_VTMAP_NONE) {
      const uint32_t *dg = cx->dm.ends + 2 * (size_t)de;
      uint32_t sa = tv[qd[k].v], sb = sp[qd[k].x][qd[k].u];
      uint32_t za = tv[qd[k].u], zb = sp[qd[k].x][qd[k].v];
      if (dg[0] == (sa < sb ? sa : sb) && dg[1] == (sa < sb ? sb : sa))
        want[k] = TR_DTYPE_S;
      else if (dg[0] == (za < zb ? za : zb) && dg[1] == (za < zb ? zb : za))
        want[k] = TR_DTYPE_Z;
      else
        return tr_error(TR_ERR_INTERNAL, "facet %u: tet %u: recorded diagonal %u-%u is not one "
                        "of its face's two", cx->idx, c->iele, dg[0], dg[1]);
    } else if (use_force) {
      want[k] = (cx->opt->force_first >> k) & 1 ? TR_DTYPE_Z : TR_DTYPE_S;
    }
  }
  if (use_force)
    cx->forced = 1;
  uint32_t ids[TR_DV_COUNT], tets[4 * MAX_NEW];
  int nnew = 0;
  for (int n = 0; n < TR_DV_COUNT; n++)
    ids[n] = TR_NONE;
  if (ncut == 1 || ncut == 2) {
    /* pipel Case 1 (Table 5) / Case 2 II (Table 6 S or Z) */
    const tr_dectable *cand[2] = {&tr_table5_case1, NULL};
    if (ncut == 2) {
      cand[0] = &tr_table6_case2_2s;
      cand[1] = &tr_table6_case2_2z;
    }
    int found = -1;
    for (int ci = 0; ci < 2 && found < 0 && cand[ci]; ci++) {
      if (!tr_dec_match(cand[ci], tv, ncut, (const uint8_t(*)[4])car, ncar, sid, -1, ids))
        continue;
      nnew = instantiate(cand[ci], ids, tets);
      int ok = 1;
      for (int k = 0; k < 4; k++)
        if (qd[k].on && want[k] != TR_DTYPE_ANY && drawn_type(tv, sp, &qd[k], tets, nnew) != want[k])
          ok = 0;
      if (ok)
        found = ci;
    }
    if (found < 0)
      return tr_error(TR_ERR_INTERNAL, "facet %u: no pipel table fits clusterel %u (%d cut "
                      "edges)", cx->idx, c->iele, ncut);
    if (cx->d && ncut == 2)
      found ? cx->d->two_z++ : cx->d->two_s++;
  } else if (ncut == 3 || ncut == 4) {
    const tr_cluster_case *cs;
    uint8_t perm[4];
    TR_CHECK(tr_cluster_match(ncut, ecodes, want, &cs, perm));
    for (int n = 0; n < 4; n++)
      ids[n] = tv[perm[n]];
    const tr_dectable *t = cs->table;
    for (int i = 0; i < t->nsteiner; i++) {
      const tr_dsteiner *s = &t->steiner[i];
      if (s->ncar == 2)
        ids[s->name] = sp[perm[s->car[0]]][perm[s->car[1]]];
    }
    if (cs->nh) {
      /* H is built from points read now; nothing is added to the mesh in between */
      tr_point store[TR_DV_COUNT];
      const tr_point *pts[TR_DV_COUNT] = {0};
      for (int i = 0; i < cs->nh; i++) {
        store[cs->hsum[i]] = tr_mesh_point(m, ids[cs->hsum[i]]);
        pts[cs->hsum[i]] = &store[cs->hsum[i]];
      }
      tr_qpoint *q = malloc(sizeof *q);
      if (!q)
        return tr_error(TR_ERR_NOMEM, "facet %u: out of memory", cx->idx);
      tr_qpoint_init(q);
      tr_status st = tr_cluster_make_h(cs, pts, q);
      if (st == TR_OK)
        st = tr_mesh_add_constructed(m, q, &ids[TR_DV_H]);
      if (st != TR_OK) {
        tr_qpoint_clear(q);
        free(q);
        return st;
      }
      if (cx->d)
        cx->d->h_points++;
    }
    if (t->nnew > MAX_NEW)
      return tr_error(TR_ERR_INTERNAL, "%s: too many tets", t->name);
    nnew = instantiate(t, ids, tets);
    if (cx->d) {
      ptrdiff_t ci = ncut == 3 ? cs - tr_thr_edg_cases : cs - tr_fou_edg_cases;
      (ncut == 3 ? cx->d->thr_case : cx->d->fou_case)[ci]++;
    }
  } else {
    return tr_error(TR_ERR_INTERNAL, "facet %u: clusterel %u with %d cut edges", cx->idx,
                    c->iele, ncut);
  }
  /* Every quad face must carry exactly one diagonal, the imposed one if any; record it. */
  for (int k = 0; k < 4; k++) {
    if (!qd[k].on)
      continue;
    int dt = drawn_type(tv, sp, &qd[k], tets, nnew);
    if (dt == TR_DTYPE_NONE || (want[k] != TR_DTYPE_ANY && dt != want[k]))
      return tr_error(TR_ERR_INTERNAL, "facet %u: clusterel %u face %d split against the "
                      "neighbour's choice", cx->idx, c->iele, k);
    uint32_t f[3] = {tv[qd[k].x], tv[qd[k].u], tv[qd[k].v]};
    tr_sort3(f);
    uint32_t de;
    dmap *dm = &cx->dm;
    TR_CHECK(tr_vtmap_put(&dm->faces, 3, f, dm->n, &de));
    if (de == dm->n) {
      if (dm->n == dm->cap)
        return tr_error(TR_ERR_INTERNAL, "facet %u: more quad faces than the cluster has",
                        cx->idx);
      uint32_t a = dt == TR_DTYPE_S ? tv[qd[k].v] : tv[qd[k].u];
      uint32_t b = dt == TR_DTYPE_S ? sp[qd[k].x][qd[k].u] : sp[qd[k].x][qd[k].v];
      dm->ends[2 * (size_t)de] = a < b ? a : b;
      dm->ends[2 * (size_t)de + 1] = a < b ? b : a;
      dm->n++;
    }
  }
  /* exact positivity before anything is committed */
  for (int r = 0; r < nnew; r++) {
    tr_point p[4];
    for (int i = 0; i < 4; i++)
      p[i] = tr_mesh_point(m, tets[4 * r + i]);
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) <= 0)
      return tr_error(TR_ERR_INTERNAL, "facet %u: new tet %d of clusterel %u is not positive",
                      cx->idx, r, c->iele);
  }
  for (int i = 0; i < 4 * nnew; i++)
    TR_CHECK(tr_u32buf_push(&cx->newv, tets[i]));
  if (cx->d)
    cx->d->by_type[ncut]++;
  return TR_OK;
}

/* The crossed edges of all clusterels, each with its exact point on F's plane. */
static tr_status make_cuts(ctx *cx, const tr_clusterel *cl, uint32_t ncl, uint32_t e, uint32_t f,
                           uint32_t g)
{
  struct tr_mesh *m = cx->m;
  uint32_t n = 0;
  for (uint32_t i = 0; i < ncl; i++)
    n += cl[i].type; /* type = number of MID nodes */
  cx->cuts = malloc((n ? n : 1) * sizeof *cx->cuts);
  if (!cx->cuts)
    return tr_error(TR_ERR_NOMEM, "facet %u: out of memory", cx->idx);
  n = 0;
  for (uint32_t i = 0; i < ncl; i++)
    for (int j = 0; j < cl[i].nnodes; j++)
      if (cl[i].ntypes[j] == TR_NOD_MID) {
        const uint32_t *tv = m->tv + 4 * (size_t)cl[i].iele;
        uint32_t a = tv[tr_ecode_start(cl[i].codes[j])], b = tv[tr_ecode_end(cl[i].codes[j])];
        cx->cuts[n].u = a < b ? a : b;
        cx->cuts[n].v = a < b ? b : a;
        n++;
      }
  qsort(cx->cuts, n, sizeof *cx->cuts, cmp_cut);
  uint32_t nu = 0;
  for (uint32_t i = 0; i < n; i++)
    if (nu == 0 || cmp_cut(&cx->cuts[i], &cx->cuts[nu - 1]) != 0)
      cx->cuts[nu++] = cx->cuts[i];
  cx->ncuts = nu;
  for (uint32_t i = 0; i < nu; i++) {
    tr_qpoint *q = malloc(sizeof *q);
    if (!q)
      return tr_error(TR_ERR_NOMEM, "facet %u: out of memory", cx->idx);
    tr_qpoint_init(q);
    /* read the points again each time: adding a vertex may move m->xyz */
    tr_point pu = tr_mesh_point(m, cx->cuts[i].u), pv = tr_mesh_point(m, cx->cuts[i].v);
    tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
    tr_status st = TR_OK;
    if (tr_construct_line_plane(&pu, &pv, &pe, &pf, &pg, q) != 0)
      st = tr_error(TR_ERR_INTERNAL, "facet %u: edge %u-%u parallel to its plane", cx->idx,
                    cx->cuts[i].u, cx->cuts[i].v);
    if (st == TR_OK)
      st = tr_mesh_add_constructed(m, q, &cx->cuts[i].p);
    if (st != TR_OK) {
      tr_qpoint_clear(q);
      free(q);
      return st;
    }
  }
  if (cx->d)
    cx->d->steiner += nu;
  return TR_OK;
}

static tr_status decompose_cluster(ctx *cx, const tr_clusterel *cl, uint32_t ncl, uint32_t e,
                                   uint32_t f, uint32_t g)
{
  TR_CHECK(make_cuts(cx, cl, ncl, e, f, g));
  /* each clusterel has at most four faces with two cut edges */
  cx->dm.cap = 4 * ncl;
  cx->dm.ends = malloc(2 * (size_t)(cx->dm.cap ? cx->dm.cap : 1) * sizeof *cx->dm.ends);
  if (!cx->dm.ends)
    return tr_error(TR_ERR_NOMEM, "facet %u: out of memory", cx->idx);
  TR_CHECK(tr_vtmap_reserve(&cx->dm.faces, 3, cx->dm.cap));
  tr_u32buf old = {0};
  tr_status st = TR_OK;
  /* Test hook: the first clusterel of the highest type goes first, so all its faces are
   * free and the imposed pattern alone picks its case. */
  uint32_t first = TR_NONE;
  if (cx->opt && cx->opt->force_on)
    for (uint32_t i = 0; i < ncl; i++)
      if (cl[i].type >= TR_THR_EDG && (first == TR_NONE || cl[i].type > cl[first].type))
        first = i;
  for (uint32_t j = 0; j <= ncl && st == TR_OK; j++) {
    uint32_t i = j == 0 ? first : j - 1;
    if (i == TR_NONE || (j > 0 && i == first) || cl[i].type == TR_CO_PLAN)
      continue;
    st = plan_clusterel(cx, &cl[i]);
    if (st == TR_OK)
      st = tr_u32buf_push(&old, cl[i].iele);
  }
  /* One replacement for the whole cluster: sub-faces are glued by vertex set. */
  if (st == TR_OK)
    st = tr_mesh_replace(cx->m, old.a, (uint32_t)old.n, cx->newv.a, (uint32_t)(cx->newv.n / 4),
                         NULL);
  tr_u32buf_free(&old);
  return st;
}

/* ---- Swap32 (Table 10) ---- */

/* The crossing tet of cl with vertex set {a,b,c,d}, or TR_NONE. */
static uint32_t find_tet(const struct tr_mesh *m, const uint32_t *cr, int n, uint32_t a,
                         uint32_t b, uint32_t c, uint32_t d)
{
  for (int i = 0; i < n; i++)
    if (tr_ncode(m, cr[i], a) >= 0 && tr_ncode(m, cr[i], b) >= 0 &&
        tr_ncode(m, cr[i], c) >= 0 && tr_ncode(m, cr[i], d) >= 0)
      return cr[i];
  return TR_NONE;
}

static tr_status try_swap32(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                            const tr_clusterel *cl, uint32_t ncl, int *done)
{
  *done = 0;
  uint32_t cr[3];
  int n = 0;
  uint32_t a = TR_NONE, b = TR_NONE;
  for (uint32_t i = 0; i < ncl; i++) {
    if (cl[i].type == TR_CO_PLAN)
      continue;
    if (cl[i].type != TR_ONE_EDG || n == 3)
      return TR_OK;
    const uint32_t *tv = m->tv + 4 * (size_t)cl[i].iele;
    for (int j = 0; j < cl[i].nnodes; j++) {
      if (cl[i].ntypes[j] == TR_NOD_MID) {
        uint32_t x = tv[tr_ecode_start(cl[i].codes[j])], y = tv[tr_ecode_end(cl[i].codes[j])];
        if (x > y) {
          uint32_t t = x;
          x = y;
          y = t;
        }
        if (a == TR_NONE) {
          a = x;
          b = y;
        } else if (a != x || b != y) {
          return TR_OK;
        }
      } else if (cl[i].nodes[j] != e && cl[i].nodes[j] != f && cl[i].nodes[j] != g) {
        return TR_OK;
      }
    }
    cr[n++] = cl[i].iele;
  }
  if (n != 3)
    return TR_OK;
  tr_u32buf sh = {0};
  int closed = 0;
  tr_status st = tr_shell(m, a, b, TR_NONE, &sh, &closed);
  size_t shn = sh.n;
  tr_u32buf_free(&sh);
  TR_CHECK(st);
  if (!closed || shn != 3)
    return TR_OK;
  /* Name the points as Table 10 does and check its old tets are positive. */
  const uint32_t ring[6][3] = {{e, f, g}, {f, g, e}, {g, e, f},
                               {e, g, f}, {g, f, e}, {f, e, g}};
  for (int s = 0; s < 2; s++)
    for (int r = 0; r < 6; r++) {
      uint32_t ids[TR_DV_COUNT];
      for (int i = 0; i < TR_DV_COUNT; i++)
        ids[i] = TR_NONE;
      ids[TR_DV_A] = s ? b : a;
      ids[TR_DV_B] = s ? a : b;
      ids[TR_DV_C] = ring[r][0];
      ids[TR_DV_D] = ring[r][1];
      ids[TR_DV_E] = ring[r][2];
      const tr_dectable *t = &tr_table10_swap32;
      uint32_t old[3];
      int ok = 1;
      for (int j = 0; j < 3 && ok; j++) {
        const uint8_t *o = t->old[j];
        ok = tr_mesh_orient(m, ids[o[0]], ids[o[1]], ids[o[2]], ids[o[3]]) > 0;
        old[j] = find_tet(m, cr, 3, ids[o[0]], ids[o[1]], ids[o[2]], ids[o[3]]);
        ok = ok && old[j] != TR_NONE;
      }
      if (!ok)
        continue;
      uint32_t out[2];
      TR_CHECK(tr_dec_apply(m, t, old, ids, NULL, 0, out));
      *done = 1;
      return TR_OK;
    }
  return TR_OK;
}

tr_status tr_recover_facet(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                           const tr_facet_opts *opt, tr_facet_detail *d, int *outcome,
                           tr_u32buf *faces)
{
  int present = 0;
  *outcome = TR_FACET_PRESENT;
  tr_clusterel *cl = NULL;
  uint32_t ncl = 0;
  /* the degenerate-facet test comes first: the cluster search relies on a plane */
  tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
  if (!tr_orient2d_proj_p(&pe, &pf, &pg, 0) && !tr_orient2d_proj_p(&pe, &pf, &pg, 1) &&
      !tr_orient2d_proj_p(&pe, &pf, &pg, 2))
    return tr_error(TR_ERR_UNSUPPORTED, "facet %u (%u %u %u) is degenerate", idx, e, f, g);
  /* Most facets are faces of the Delaunay mesh already: then the facet is that one face,
   * listed as the cluster path would list it (turning like efg, smallest id first). */
  uint32_t t = opt && opt->hint ? opt->hint[idx] : TR_NONE;
  if (t != TR_NONE && !(t < m->nt && tr_tet_is_real(m, t) && tr_fcode(m, t, e, f, g) >= 0))
    t = TR_NONE; /* stale: flips for an earlier facet replaced that tet */
  if (t == TR_NONE && !(opt && opt->hint && opt->hint[idx] == TR_NONE))
    TR_CHECK(tr_ball_find(m, e, f, g, &t));
  if (t != TR_NONE) {
    uint32_t w[3] = {e, f, g};
    tr_rotate_min3(w);
    for (int q = 0; q < 3 && faces; q++)
      TR_CHECK(tr_u32buf_push(faces, w[q]));
    return TR_OK;
  }
  TR_CHECK(tr_cluster_collect(m, e, f, g, &cl, &ncl));
  tr_status st = tr_facet_faces_of_cluster(m, idx, e, f, g, cl, ncl, 0, &present, faces);
  if (st != TR_OK || present) {
    free(cl);
    return st;
  }
  int done = 0, by_flips = 0;
  if (!(opt && opt->no_swap))
    st = try_swap32(m, e, f, g, cl, ncl, &done);
  if (st == TR_OK && !done && !(opt && (opt->no_swap || opt->no_flips))) {
    /* general flips before any Steiner point (flipfacet.h) */
    int changed = 0, clear = 0;
    st = tr_facet_try_flips(m, e, f, g, opt ? opt->guard : NULL, opt ? opt->guard_ud : NULL,
                            d ? &d->flips : NULL, &changed, &clear);
    if (st == TR_OK && changed) {
      free(cl);
      cl = NULL;
      ncl = 0;
      st = tr_cluster_collect(m, e, f, g, &cl, &ncl);
      done = by_flips = clear;
    }
  }
  int by_cavity = 0;
  if (st == TR_OK && !done && !(opt && (opt->no_swap || opt->no_cavity))) {
    st = tr_facet_cavity(m, idx, e, f, g, cl, ncl, opt ? opt->guard : NULL,
                         opt ? opt->guard_ud : NULL, d ? &d->cavity : NULL, &by_cavity);
    done = by_cavity;
  }
  if (st == TR_OK && done) {
    *outcome = by_cavity  ? TR_FACET_BY_CAVITY
               : by_flips ? TR_FACET_BY_FLIPS
                          : TR_FACET_BY_SWAP32;
    if (d && !by_cavity) /* the cavity's are counted in d->cavity.recovered */
      by_flips ? d->by_flips++ : d->swap32++;
  } else if (st == TR_OK) {
    ctx cx;
    memset(&cx, 0, sizeof cx);
    cx.m = m;
    cx.idx = idx;
    cx.opt = opt;
    cx.d = d;
    st = decompose_cluster(&cx, cl, ncl, e, f, g);
    free(cx.cuts);
    free(cx.dm.ends);
    tr_vtmap_free(&cx.dm.faces);
    tr_u32buf_free(&cx.newv);
    *outcome = TR_FACET_BY_CLUSTER;
  }
  free(cl);
  TR_CHECK(st);
  TR_CHECK(tr_facet_faces(m, idx, e, f, g, &present, faces));
  if (!present)
    return tr_error(TR_ERR_INTERNAL, "facet %u (%u %u %u) still missing after %s", idx, e, f, g,
                    *outcome == TR_FACET_BY_SWAP32  ? "Swap32"
                    : *outcome == TR_FACET_BY_FLIPS ? "flips"
                    : *outcome == TR_FACET_BY_CAVITY ? "cavity retriangulation"
                                                    : "clusterel decomposition");
  return TR_OK;
}
