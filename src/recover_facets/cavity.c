/* Missing-facet recovery by cavity retriangulation (see cavity.h). */
#include "recover_facets/cavity.h"
#include "recover_facets/ldt.h"

#include <stdlib.h>
#include <string.h>

/* ---- the cavity ---- */

/* A boundary face of the old region: its vertices turning so that the region is on the
 * positive side (tr_face_vtx order in the region's tet), that tet and face code, and the
 * side of F's plane it lies on. */
typedef struct bface {
  uint32_t v[3];
  uint32_t t;
  int k, side;
} bface;

typedef struct cav {
  struct tr_mesh *m;
  tr_point pe, pf, pg;
  tr_flip_guard guard;
  void *ud;
  tr_u32buf reg;    /* the old tets, sorted */
  uint32_t *vid;    /* the region's vertices, sorted */
  int8_t *vside;    /* their side of F's plane (orient3d sign) */
  uint32_t nv;
  bface *bf;
  uint32_t nbf;
  tr_u32buf newv;   /* 4 global ids per new tet */
  tr_u32buf plane[2]; /* sorted keys of the faces in F's plane, upper / lower side */
  tr_u32buf missing;  /* indices into bf of boundary faces the Delaunay mesh lacks */
  tr_ldt D;
  tr_point *pts;
  uint32_t *gid;
  tr_ldt_face *ft;         /* faces of the real local tets, sorted */
  uint8_t *seen;
  uint32_t *queue;
} cav;

static int cmp_u32(const void *a, const void *b)
{
  uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
  return (x > y) - (x < y);
}

static int in_sorted(const uint32_t *a, size_t n, uint32_t x)
{
  return bsearch(&x, a, n, sizeof x, cmp_u32) != NULL;
}

static int vside(const cav *c, uint32_t v)
{
  if (c->nv == 0) /* the first round: no side known yet (bsearch wants an array) */
    return 2;
  const uint32_t *r = bsearch(&v, c->vid, c->nv, sizeof v, cmp_u32);
  return r ? c->vside[r - c->vid] : 2;
}

/* The region's vertices with their sides; sides known from an earlier round are kept. */
static tr_status collect_vertices(cav *c)
{
  size_t n = 4 * c->reg.n;
  uint32_t *v = malloc(n * sizeof *v);
  int8_t *s = malloc(n ? n : 1);
  if (!v || !s) {
    free(v);
    free(s);
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  }
  for (size_t i = 0; i < c->reg.n; i++)
    memcpy(v + 4 * i, c->m->tv + 4 * (size_t)c->reg.a[i], 4 * sizeof *v);
  qsort(v, n, sizeof *v, cmp_u32);
  size_t nu = 0;
  for (size_t i = 0; i < n; i++)
    if (nu == 0 || v[i] != v[nu - 1])
      v[nu++] = v[i];
  for (size_t i = 0; i < nu; i++) {
    int o = vside(c, v[i]);
    if (o == 2) {
      tr_point p = tr_mesh_point(c->m, v[i]);
      o = tr_orient3d_p(&c->pe, &c->pf, &c->pg, &p);
    }
    s[i] = (int8_t)o;
  }
  free(c->vid);
  free(c->vside);
  c->vid = v;
  c->vside = s;
  c->nv = (uint32_t)nu;
  return TR_OK;
}

/* The boundary faces of the region and their sides. *ok = 0 if one lies in F's plane or
 * crosses it (not the region cavity.h describes). */
static tr_status collect_boundary(cav *c, int *ok)
{
  const struct tr_mesh *m = c->m;
  *ok = 1;
  free(c->bf);
  c->bf = malloc(4 * c->reg.n * sizeof *c->bf);
  c->nbf = 0;
  if (!c->bf)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  for (size_t i = 0; i < c->reg.n; i++) {
    uint32_t t = c->reg.a[i];
    for (int k = 0; k < 4; k++) {
      uint32_t nb = TR_NEIG(m, t, k);
      if (nb != TR_NONE && in_sorted(c->reg.a, c->reg.n, nb))
        continue;
      bface *b = &c->bf[c->nbf++];
      tr_ldt_face_of(m->tv + 4 * (size_t)t, k, b->v);
      b->t = t;
      b->k = k;
      int up = 0, lo = 0;
      for (int j = 0; j < 3; j++) {
        int s = vside(c, b->v[j]);
        up |= s > 0;
        lo |= s < 0;
      }
      if (up == lo) {
        *ok = 0;
        return TR_OK;
      }
      b->side = up ? 1 : -1;
    }
  }
  return TR_OK;
}

/* The real tet of the local mesh with face (a, b, c) turning as given (so its fourth
 * vertex is on the positive side), or TR_NONE. */
static uint32_t find_turned(const cav *c, uint32_t nft, const uint32_t loc[3])
{
  return tr_ldt_find_turned(&c->D, c->ft, nft, loc);
}

/* The other real local tet across face `face` of tet j, TR_NONE on the hull. */
static uint32_t across(const cav *c, uint32_t nft, uint32_t j, uint32_t face)
{
  return tr_ldt_across(&c->D, c->ft, nft, j, face);
}

static uint32_t local_id(const cav *c, uint32_t n, uint32_t v)
{
  const uint32_t *r = bsearch(&v, c->gid, n, sizeof v, cmp_u32);
  return r ? (uint32_t)(r - c->gid) : TR_NONE;
}

enum { SIDE_OK = 0, SIDE_MISSING = 1, SIDE_FAIL = 2 };

/* Retriangulates the side s (+1 / -1) of the cavity: appends its tets to c->newv and its
 * faces in F's plane to c->plane, or lists the boundary faces its Delaunay mesh lacks in
 * c->missing. *res = SIDE_*. */
static tr_status one_side(cav *c, int s, int *res)
{
  *res = SIDE_FAIL;
  uint32_t n = 0;
  for (uint32_t i = 0; i < c->nv; i++)
    if (c->vside[i] * s >= 0) {
      if (n == TR_CAVITY_MAX_VERTICES)
        return TR_OK;
      c->gid[n] = c->vid[i];
      c->pts[n++] = tr_mesh_point(c->m, c->vid[i]);
    }
  int ok;
  TR_CHECK(tr_ldt_build(&c->D, c->pts, n, &ok));
  if (!ok)
    return TR_OK;
  tr_ldt *D = &c->D;
  uint32_t nft = 0;
  free(c->ft);
  c->ft = malloc(4 * (size_t)(D->n ? D->n : 1) * sizeof *c->ft);
  free(c->seen);
  c->seen = calloc(D->n ? D->n : 1, 1);
  free(c->queue);
  c->queue = malloc((D->n ? D->n : 1) * sizeof *c->queue);
  if (!c->ft || !c->seen || !c->queue)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  for (uint32_t j = 0; j < D->n; j++) {
    if (D->t[j][3] == TR_LDT_GHOST)
      continue;
    for (uint32_t k = 0; k < 4; k++) {
      tr_ldt_face_of(D->t[j], (int)k, c->ft[nft].k);
      tr_sort3(c->ft[nft].k);
      c->ft[nft].tet = j;
      c->ft[nft++].face = k;
    }
  }
  qsort(c->ft, nft, sizeof *c->ft, tr_ldt_cmp_face);
  /* every boundary face of this side, seen from the cavity, and the flood's seeds */
  uint32_t nq = 0;
  tr_ldt_face *wall = malloc((c->nbf ? c->nbf : 1) * sizeof *wall);
  if (!wall)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  uint32_t nw = 0;
  for (uint32_t i = 0; i < c->nbf; i++) {
    if (c->bf[i].side != s)
      continue;
    uint32_t loc[3];
    for (int j = 0; j < 3; j++)
      loc[j] = local_id(c, n, c->bf[i].v[j]);
    uint32_t j = find_turned(c, nft, loc);
    if (j == TR_NONE) {
      tr_status st = tr_u32buf_push(&c->missing, i);
      if (st != TR_OK) {
        free(wall);
        return st;
      }
      continue;
    }
    memcpy(wall[nw].k, loc, sizeof loc);
    tr_sort3(wall[nw].k);
    wall[nw].tet = wall[nw].face = 0;
    nw++;
    if (!c->seen[j]) {
      c->seen[j] = 1;
      c->queue[nq++] = j;
    }
  }
  if (c->missing.n) {
    free(wall);
    *res = SIDE_MISSING;
    return TR_OK;
  }
  qsort(wall, nw, sizeof *wall, tr_cmp_face_key);
  /* the flood: across every face that is neither a wall nor in F's plane */
  int leak = 0;
  for (uint32_t h = 0; h < nq && !leak; h++) {
    uint32_t j = c->queue[h];
    for (uint32_t k = 0; k < 4 && !leak; k++) {
      uint32_t f[3];
      tr_ldt_face_of(D->t[j], (int)k, f);
      int onplane = 1;
      for (int q = 0; q < 3; q++)
        onplane &= vside(c, c->gid[f[q]]) == 0;
      tr_sort3(f);
      if (onplane || bsearch(f, wall, nw, sizeof *wall, tr_cmp_face_key))
        continue;
      uint32_t o = across(c, nft, j, k);
      if (o == TR_NONE)
        leak = 1;
      else if (!c->seen[o]) {
        c->seen[o] = 1;
        c->queue[nq++] = o;
      }
    }
  }
  free(wall);
  if (leak)
    return TR_OK;
  /* no vertex may be lost, and every tet must be positive (exact) */
  uint8_t *used = calloc(n, 1);
  if (!used)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  for (uint32_t h = 0; h < nq; h++)
    for (int q = 0; q < 4; q++)
      used[D->t[c->queue[h]][q]] = 1;
  int all = 1;
  for (uint32_t i = 0; i < n; i++)
    all &= used[i];
  free(used);
  for (uint32_t h = 0; h < nq && all; h++) {
    const uint32_t *t = D->t[c->queue[h]];
    all = tr_orient3d_p(&c->pts[t[0]], &c->pts[t[1]], &c->pts[t[2]], &c->pts[t[3]]) > 0;
  }
  if (!all)
    return TR_OK;
  for (uint32_t h = 0; h < nq; h++) {
    const uint32_t *t = D->t[c->queue[h]];
    for (int q = 0; q < 4; q++)
      TR_CHECK(tr_u32buf_push(&c->newv, c->gid[t[q]]));
    for (int k = 0; k < 4; k++) {
      uint32_t f[3];
      tr_ldt_face_of(t, k, f);
      int onplane = 1;
      for (int q = 0; q < 3; q++) {
        f[q] = c->gid[f[q]];
        onplane &= vside(c, f[q]) == 0;
      }
      if (!onplane)
        continue;
      tr_sort3(f);
      for (int q = 0; q < 3; q++)
        TR_CHECK(tr_u32buf_push(&c->plane[s < 0], f[q]));
    }
  }
  *res = SIDE_OK;
  return TR_OK;
}

/* Si's expansion: the tet behind missing boundary face b joins the cavity, unless that
 * face is protected, the tet is a ghost, or its fourth vertex is not on b's side (or an
 * R corner already in the cavity). *ok = 0 then. */
static tr_status expand(cav *c, const bface *b, tr_u32buf *add, int *ok)
{
  const struct tr_mesh *m = c->m;
  *ok = 0;
  uint32_t code = m->tn[4 * (size_t)b->t + (size_t)b->k];
  if (code == TR_NONE || tr_tet_is_ghost(m, code >> 2))
    return TR_OK;
  if (c->guard && c->guard(c->ud, b->v, 3))
    return TR_OK;
  uint32_t w = m->tv[code], nb = code >> 2;
  int sw = vside(c, w);
  if (sw == 2) {
    tr_point p = tr_mesh_point(m, w);
    sw = tr_orient3d_p(&c->pe, &c->pf, &c->pg, &p);
    if (sw == 0)
      return TR_OK; /* a new vertex in the plane: maybe outside F */
  }
  if (sw * b->side < 0)
    return TR_OK;
  *ok = 1;
  return tr_u32buf_push(add, nb);
}

static int same_planes(cav *c)
{
  tr_u32buf *a = &c->plane[0], *b = &c->plane[1];
  if (a->n != b->n)
    return 0;
  if (a->n == 0)
    return 1;
  qsort(a->a, a->n / 3, 3 * sizeof *a->a, tr_cmp_face_key);
  qsort(b->a, b->n / 3, 3 * sizeof *b->a, tr_cmp_face_key);
  return memcmp(a->a, b->a, a->n * sizeof *a->a) == 0;
}

/* Every protected edge and face of the old tets is a simplex of the new ones. */
static tr_status keeps_constraints(cav *c, int *ok)
{
  *ok = 1;
  if (!c->guard)
    return TR_OK;
  tr_sxset se = {0}, sf = {0};
  tr_status st = TR_OK;
  for (size_t i = 0; i + 4 <= c->newv.n && st == TR_OK; i += 4) {
    const uint32_t *t = c->newv.a + i;
    for (int e = 0; e < 6 && st == TR_OK; e++) {
      uint32_t v[3] = {t[tr_edge_vtx[e][0]], t[tr_edge_vtx[e][1]], TR_NONE};
      if (tr_sxset_add(&se, v) < 0)
        st = TR_ERR_NOMEM;
    }
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      uint32_t v[3];
      tr_ldt_face_of(t, k, v);
      if (tr_sxset_add(&sf, v) < 0)
        st = TR_ERR_NOMEM;
    }
  }
  for (size_t i = 0; i < c->reg.n && st == TR_OK && *ok; i++) {
    const uint32_t *t = c->m->tv + 4 * (size_t)c->reg.a[i];
    for (int e = 0; e < 6 && *ok; e++) {
      uint32_t v[3] = {t[tr_edge_vtx[e][0]], t[tr_edge_vtx[e][1]], TR_NONE};
      if (c->guard(c->ud, v, 2) && !tr_sxset_has(&se, v))
        *ok = 0;
    }
    for (int k = 0; k < 4 && *ok; k++) {
      uint32_t v[3];
      tr_ldt_face_of(t, k, v);
      if (c->guard(c->ud, v, 3) && !tr_sxset_has(&sf, v))
        *ok = 0;
    }
  }
  tr_sxset_free(&se);
  tr_sxset_free(&sf);
  return st;
}

static void cav_free(cav *c)
{
  tr_u32buf_free(&c->reg);
  tr_u32buf_free(&c->newv);
  tr_u32buf_free(&c->plane[0]);
  tr_u32buf_free(&c->plane[1]);
  tr_u32buf_free(&c->missing);
  free(c->vid);
  free(c->vside);
  free(c->bf);
  tr_ldt_free(&c->D);
  free(c->pts);
  free(c->gid);
  free(c->ft);
  free(c->seen);
  free(c->queue);
}

/* The rounds of retriangulation and expansion; *why = 0 success, 1 a boundary face
 * stayed missing, 2 any other refusal. */
static tr_status retriangulate(cav *c, tr_cavity_stats *st, int *why)
{
  *why = 2;
  for (int round = 0;; round++) {
    int ok, r[2];
    TR_CHECK(collect_vertices(c));
    TR_CHECK(collect_boundary(c, &ok));
    if (!ok)
      return TR_OK;
    c->newv.n = c->plane[0].n = c->plane[1].n = c->missing.n = 0;
    TR_CHECK(one_side(c, 1, &r[0]));
    if (r[0] == SIDE_FAIL)
      return TR_OK;
    TR_CHECK(one_side(c, -1, &r[1]));
    if (r[1] == SIDE_FAIL)
      return TR_OK;
    if (r[0] == SIDE_OK && r[1] == SIDE_OK)
      break;
    *why = 1;
    if (round == TR_CAVITY_EXPAND)
      return TR_OK;
    tr_u32buf add = {0};
    tr_status s = TR_OK;
    for (size_t i = 0; i < c->missing.n && s == TR_OK; i++) {
      s = expand(c, &c->bf[c->missing.a[i]], &add, &ok);
      if (!ok)
        break;
    }
    /* two missing faces may lead to the same tet: add each once */
    if (add.n)
      qsort(add.a, add.n, sizeof *add.a, cmp_u32);
    for (size_t i = 0; i < add.n && s == TR_OK && ok; i++)
      if (i == 0 || add.a[i] != add.a[i - 1]) {
        s = tr_u32buf_push(&c->reg, add.a[i]);
        if (st)
          st->expanded++;
      }
    tr_u32buf_free(&add);
    TR_CHECK(s);
    if (!ok)
      return TR_OK;
    qsort(c->reg.a, c->reg.n, sizeof *c->reg.a, cmp_u32);
    *why = 2;
  }
  if (!same_planes(c))
    return TR_OK;
  int ok;
  TR_CHECK(keeps_constraints(c, &ok));
  if (ok)
    *why = 0;
  return TR_OK;
}

tr_status tr_facet_cavity(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                          const tr_clusterel *cl, uint32_t ncl, tr_flip_guard guard, void *ud,
                          tr_cavity_stats *st, int *done)
{
  (void)idx; /* the refusals are not errors: nothing to name it in */
  *done = 0;
  cav c;
  memset(&c, 0, sizeof c);
  c.m = m;
  c.pe = tr_mesh_point(m, e);
  c.pf = tr_mesh_point(m, f);
  c.pg = tr_mesh_point(m, g);
  c.guard = guard;
  c.ud = ud;
  tr_status s = TR_OK;
  for (uint32_t i = 0; i < ncl && s == TR_OK; i++)
    if (cl[i].type != TR_CO_PLAN)
      s = tr_u32buf_push(&c.reg, cl[i].iele);
  if (s != TR_OK || c.reg.n == 0) {
    cav_free(&c);
    return s;
  }
  if (st)
    st->tried++;
  qsort(c.reg.a, c.reg.n, sizeof *c.reg.a, cmp_u32);
  c.pts = malloc(TR_CAVITY_MAX_VERTICES * sizeof *c.pts);
  c.gid = malloc(TR_CAVITY_MAX_VERTICES * sizeof *c.gid);
  int why = 2;
  if (!c.pts || !c.gid)
    s = tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  if (s == TR_OK)
    s = retriangulate(&c, st, &why);
  if (s == TR_OK && why == 0) {
    s = tr_mesh_replace(m, c.reg.a, (uint32_t)c.reg.n, c.newv.a, (uint32_t)(c.newv.n / 4), NULL);
    if (s == TR_ERR_INTERNAL) { /* the new tets do not fill the old region: refused */
      s = TR_OK;
      why = 2;
    } else if (s == TR_OK) {
      *done = 1;
    }
  }
  if (st && s == TR_OK) {
    if (*done)
      st->recovered++;
    else if (why == 1)
      st->failed_boundary++;
    else
      st->failed_other++;
  }
  cav_free(&c);
  return s;
}
