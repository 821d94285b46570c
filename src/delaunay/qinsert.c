/* Bowyer-Watson insertion of exact rational points into the Delaunay mesh of the double
 * points (--resolve's boundary vertices that are no doubles, docs/resolve.md).
 *
 * The builder (bw.c) is specialised for doubles (static filters, 32-byte points, local
 * ids); these points are few (hundreds on CGAL's models) and every predicate on them is
 * exact on tr_point, so this is the plain algorithm: a visibility walk to the tet that
 * contains p, the tets whose circumsphere holds p strictly (tr_insphere_p > 0), and the
 * star of p over the cavity's boundary faces.
 *
 * Why the result is a valid tetrahedralization without perturbing p: the mesh is
 * Delaunay for the unperturbed points in the weak sense (no point strictly inside a
 * circumsphere), and the tets whose sphere holds p strictly form a region star-shaped
 * from p. A boundary face between a cavity tet t and an outside tet u cannot have p in
 * its plane: the spheres of t and u meet that plane in the same circle, so p would be
 * strictly inside both or neither. The new tets are still checked exactly (orientation
 * > 0), so a wrong premise is an internal error, never a flat tet.
 *
 * Ghosts (the hull, delaunay.h), as in the builder: a ghost joins the cavity when p sees
 * its hull face strictly, or lies in its plane and the real tet behind conflicts. p may lie
 * outside the hull of the double points: a solid's extreme points are input points when
 * it is a union, but not when a part given inside out cuts a corner away (fuzz_resolve);
 * the walk then stops at a ghost that sees p. A ghost's hull face with p makes a real tet,
 * its other faces new ghosts (TR_GHOST stays in slot 3). */
#include <stdlib.h>
#include <string.h>

#include "delaunay.h"
#include "mesh/orient_memo.h"

typedef struct side {
  uint32_t a, b; /* the face's two vertices other than p, a < b */
  uint32_t code; /* 4 * tet + face */
} side;

static int cmp_side(const void *x, const void *y)
{
  const side *s = x, *t = y;
  if (s->a != t->a)
    return s->a < t->a ? -1 : 1;
  if (s->b != t->b)
    return s->b < t->b ? -1 : 1;
  return (s->code > t->code) - (s->code < t->code);
}

static int conflict_real(const struct tr_mesh *m, uint32_t t, const tr_point *p)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  tr_point a = tr_mesh_point(m, v[0]), b = tr_mesh_point(m, v[1]), c = tr_mesh_point(m, v[2]),
           d = tr_mesh_point(m, v[3]);
  return tr_insphere_p(&a, &b, &c, &d, p) > 0;
}

static int conflict(const struct tr_mesh *m, uint32_t t, const tr_point *p)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  if (v[3] != TR_GHOST)
    return conflict_real(m, t, p);
  tr_point a = tr_mesh_point(m, v[0]), b = tr_mesh_point(m, v[1]), c = tr_mesh_point(m, v[2]);
  int o = tr_orient3d_p(&a, &b, &c, p);
  if (o != 0)
    return o > 0;
  return conflict_real(m, m->tn[4 * (size_t)t + 3] >> 2, p);
}

/* Sign of p against face k of real tet t: > 0 on t's side. */
static int face_side(const struct tr_mesh *m, uint32_t t, int k, const tr_point *p)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  tr_point a = tr_mesh_point(m, v[tr_face_vtx[k][0]]), b = tr_mesh_point(m, v[tr_face_vtx[k][1]]),
           c = tr_mesh_point(m, v[tr_face_vtx[k][2]]);
  return tr_orient3d_p(&a, &b, &c, p);
}

/* A real tet whose closed inside holds p, or a ghost whose hull face p sees strictly: a
 * visibility walk from t0 (the face to leave by is tried from a rotating start, so the
 * walk cannot cycle on a fixed choice), and after too many steps a scan of every tet. */
static tr_status locate(const struct tr_mesh *m, uint32_t t0, const tr_point *p, uint32_t *out)
{
  uint32_t t = t0, rot = 0;
  uint64_t limit = 4 * (uint64_t)m->nt + 64;
  for (uint64_t step = 0; step < limit; step++) {
    int moved = 0;
    for (int j = 0; j < 4 && !moved; j++) {
      int k = (int)((j + rot) & 3);
      if (face_side(m, t, k, p) < 0) {
        uint32_t u = TR_NEIG(m, t, k);
        if (u != TR_NONE && tr_tet_is_ghost(m, u)) {
          /* p is strictly beyond this hull face: the ghost on it conflicts */
          *out = u;
          return TR_OK;
        }
        if (u == TR_NONE)
          break;
        t = u;
        moved = 1;
      }
    }
    rot++;
    if (!moved) {
      int in = 1;
      for (int k = 0; k < 4 && in; k++)
        in = face_side(m, t, k, p) >= 0;
      if (in) {
        *out = t;
        return TR_OK;
      }
      break;
    }
  }
  for (uint32_t u = 0; u < m->nt; u++) {
    if (!tr_tet_is_real(m, u))
      continue;
    int in = 1;
    for (int k = 0; k < 4 && in; k++)
      in = face_side(m, u, k, p) >= 0;
    if (in) {
      *out = u;
      return TR_OK;
    }
  }
  for (uint32_t u = 0; u < m->nt; u++) { /* outside the hull: a ghost that sees p */
    if (tr_tet_is_free(m, u) || !tr_tet_is_ghost(m, u))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)u;
    tr_point a = tr_mesh_point(m, v[0]), b = tr_mesh_point(m, v[1]), c = tr_mesh_point(m, v[2]);
    if (tr_orient3d_p(&a, &b, &c, p) > 0) {
      *out = u;
      return TR_OK;
    }
  }
  return tr_error(TR_ERR_INTERNAL, "exact point near (%.17g, %.17g, %.17g) lies in no tet of "
                  "the Delaunay mesh of the double points", p->d[0], p->d[1], p->d[2]);
}

/* Scratch shared by the insertions of one call. */
typedef struct qctx {
  tr_u32buf cav;   /* cavity tets; marked with TR_TF_MARK while listed */
  side *sd;        /* side faces of the new tets */
  size_t nsd, capsd;
  tr_u32buf bnd;   /* boundary faces: 4 * cavity tet + face */
} qctx;

static tr_status push_side(qctx *c, uint32_t a, uint32_t b, uint32_t code)
{
  if (c->nsd == c->capsd) {
    size_t n = c->capsd ? 2 * c->capsd : 64;
    side *s = realloc(c->sd, n * sizeof *s);
    if (!s)
      return tr_error(TR_ERR_NOMEM, "out of memory inserting an exact point");
    c->sd = s;
    c->capsd = n;
  }
  c->sd[c->nsd].a = a < b ? a : b;
  c->sd[c->nsd].b = a < b ? b : a;
  c->sd[c->nsd++].code = code;
  return TR_OK;
}

static tr_status insert_one(struct tr_mesh *m, qctx *c, uint32_t pid, uint32_t *hint)
{
  tr_point p = tr_mesh_point(m, pid);
  uint32_t t0 = TR_NONE;
  TR_CHECK(locate(m, *hint, &p, &t0));
  c->cav.n = c->bnd.n = 0;
  c->nsd = 0;
  TR_CHECK(tr_u32buf_push(&c->cav, t0));
  m->flags[t0] |= TR_TF_MARK;
  tr_status st = TR_OK;
  for (size_t i = 0; st == TR_OK && i < c->cav.n; i++) {
    uint32_t t = c->cav.a[i];
    for (int k = 0; st == TR_OK && k < 4; k++) {
      uint32_t u = TR_NEIG(m, t, k);
      if (u != TR_NONE && (m->flags[u] & TR_TF_MARK))
        continue;
      if (u != TR_NONE && conflict(m, u, &p)) {
        m->flags[u] |= TR_TF_MARK;
        st = tr_u32buf_push(&c->cav, u);
      } else {
        st = tr_u32buf_push(&c->bnd, 4 * t + (uint32_t)k);
      }
    }
  }
  /* a boundary face seen by a neighbour that joined the cavity later is no boundary */
  size_t nb = 0;
  for (size_t i = 0; i < c->bnd.n; i++) {
    uint32_t t = c->bnd.a[i] >> 2, u = TR_NEIG(m, t, (int)(c->bnd.a[i] & 3));
    if (u == TR_NONE || !(m->flags[u] & TR_TF_MARK))
      c->bnd.a[nb++] = c->bnd.a[i];
  }
  c->bnd.n = nb;
  /* every new real tet must be positive: checked before anything changes */
  for (size_t i = 0; st == TR_OK && i < c->bnd.n; i++) {
    uint32_t t = c->bnd.a[i] >> 2;
    int k = (int)(c->bnd.a[i] & 3);
    if (tr_tet_is_ghost(m, t) && k == 3) {
      /* p beyond the hull: the hull face and p make a real tet, positive iff p sees the
       * face strictly (a ghost that joined for p in its plane has its real tet in the
       * cavity too, so its face 3 is no boundary) */
      const uint32_t *v = m->tv + 4 * (size_t)t;
      tr_point a = tr_mesh_point(m, v[0]), b = tr_mesh_point(m, v[1]),
               cc = tr_mesh_point(m, v[2]);
      if (tr_orient3d_p(&a, &b, &cc, &p) <= 0)
        st = tr_error(TR_ERR_INTERNAL, "exact point %u near (%.17g, %.17g, %.17g): a flat tet "
                      "on the hull", pid, p.d[0], p.d[1], p.d[2]);
    } else if (!tr_tet_is_ghost(m, t) && face_side(m, t, k, &p) <= 0)
      st = tr_error(TR_ERR_INTERNAL, "exact point %u: its Bowyer-Watson cavity is not "
                    "star-shaped (face %u of tet %u)", pid, (unsigned)k, t);
  }
  if (st != TR_OK) {
    for (size_t i = 0; i < c->cav.n; i++)
      m->flags[c->cav.a[i]] &= (uint8_t)~TR_TF_MARK;
    return st;
  }
  /* new tets: cavity tet t with vertex k replaced by p, glued outside across face k */
  uint32_t *nv = malloc(sizeof *nv * 4 * (c->bnd.n ? c->bnd.n : 1));
  uint32_t *out = malloc(sizeof *out * (c->bnd.n ? c->bnd.n : 1));
  if (!nv || !out) {
    free(nv);
    free(out);
    for (size_t i = 0; i < c->cav.n; i++)
      m->flags[c->cav.a[i]] &= (uint8_t)~TR_TF_MARK;
    return tr_error(TR_ERR_NOMEM, "out of memory inserting an exact point");
  }
  for (size_t i = 0; i < c->bnd.n; i++) {
    uint32_t t = c->bnd.a[i] >> 2;
    int k = (int)(c->bnd.a[i] & 3);
    memcpy(nv + 4 * i, m->tv + 4 * (size_t)t, 4 * sizeof *nv);
    nv[4 * i + (size_t)k] = pid;
    out[i] = m->tn[4 * (size_t)t + (size_t)k];
  }
  for (size_t i = 0; i < c->cav.n; i++) {
    m->flags[c->cav.a[i]] = 0;
    tr_tet_free(m, c->cav.a[i]);
  }
  for (size_t i = 0; st == TR_OK && i < c->bnd.n; i++) {
    uint32_t t, k = c->bnd.a[i] & 3;
    const uint32_t *v = nv + 4 * i;
    st = tr_tet_new(m, v[0], v[1], v[2], v[3], &t);
    if (st != TR_OK)
      break;
    if (out[i] != TR_NONE)
      tr_glue(m, t, (int)k, out[i] >> 2, (int)(out[i] & 3));
    for (uint32_t j = 0; st == TR_OK && j < 4; j++) /* faces through p */
      if (j != k) {
        uint32_t a = v[tr_face_vtx[j][0]], b = v[tr_face_vtx[j][1]], d = v[tr_face_vtx[j][2]];
        uint32_t e0 = a == pid ? b : a, e1 = a == pid || b == pid ? d : b;
        st = push_side(c, e0, e1, 4 * t + j);
      }
    if (!tr_tet_is_ghost(m, t))
      *hint = t;
  }
  free(nv);
  free(out);
  if (st != TR_OK)
    return st;
  /* each side face is in exactly two new tets */
  qsort(c->sd, c->nsd, sizeof *c->sd, cmp_side);
  for (size_t i = 0; i < c->nsd; i += 2) {
    if (i + 1 >= c->nsd || c->sd[i].a != c->sd[i + 1].a || c->sd[i].b != c->sd[i + 1].b)
      return tr_error(TR_ERR_INTERNAL, "exact point %u: the star of its cavity does not close",
                      pid);
    tr_glue(m, c->sd[i].code >> 2, (int)(c->sd[i].code & 3), c->sd[i + 1].code >> 2,
            (int)(c->sd[i + 1].code & 3));
  }
  return TR_OK;
}

/* A copy of exact point i (q) as m's next vertex *id. */
static tr_status add_exact(struct tr_mesh *m, const tr_qpoint *q, uint32_t i, uint32_t *id)
{
  tr_qpoint *x = malloc(sizeof *x);
  if (!x)
    return tr_error(TR_ERR_NOMEM, "out of memory for exact point %u", i);
  tr_qpoint_init(x);
  tr_point src = tr_pt_q(q);
  tr_qpoint_set_point(x, &src);
  tr_status st = tr_mesh_add_steiner(m, x, id);
  if (st != TR_OK) {
    tr_qpoint_clear(x);
    free(x);
  }
  return st;
}

tr_status tr_delaunay_insert_exact(struct tr_mesh *m, tr_qpoint *const *q, uint32_t n)
{
  if (!n)
    return TR_OK;
  TR_CHECK(tr_mesh_reserve_vertices(m, m->nv + n));
  uint32_t hint = TR_NONE;
  for (uint32_t t = 0; t < m->nt && hint == TR_NONE; t++)
    if (tr_tet_is_real(m, t))
      hint = t;
  if (hint == TR_NONE)
    return tr_error(TR_ERR_DEGENERATE, "no tet to insert exact points into");
  qctx c;
  memset(&c, 0, sizeof c);
  tr_status st = TR_OK;
  for (uint32_t i = 0; st == TR_OK && i < n; i++) {
    uint32_t id;
    if ((st = add_exact(m, q[i], i, &id)) == TR_OK)
      st = insert_one(m, &c, id, &hint);
  }
  tr_u32buf_free(&c.cav);
  tr_u32buf_free(&c.bnd);
  free(c.sd);
  tr_mesh_orient_memo_forget(m); /* new vertex ids */
  return st == TR_OK ? tr_delaunay_canonical(m) : st;
}

/* Three points on one line: every coordinate projection of them is degenerate. */
static int collinear_p(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
  tr_point x = tr_mesh_point(m, a), y = tr_mesh_point(m, b), z = tr_mesh_point(m, c);
  return tr_orient2d_proj_p(&x, &y, &z, 0) == 0 && tr_orient2d_proj_p(&x, &y, &z, 1) == 0 &&
         tr_orient2d_proj_p(&x, &y, &z, 2) == 0;
}

/* s[0..3] = four of m's n vertices that span a positive tet, exactly, the first such in
 * vertex order (vertices are distinct: validation merged duplicates). */
static tr_status first_simplex_p(const struct tr_mesh *m, uint32_t n, uint32_t s[4])
{
  if (n < 4)
    return tr_error(TR_ERR_DEGENERATE, "only %u distinct point(s): a tetrahedralization needs "
                    "at least 4 points not in a plane", n);
  s[0] = 0, s[1] = 1, s[2] = 2;
  while (s[2] < n && collinear_p(m, s[0], s[1], s[2]))
    s[2]++;
  if (s[2] == n)
    return tr_error(TR_ERR_DEGENERATE, "all %u points are collinear", n);
  tr_point a = tr_mesh_point(m, s[0]), b = tr_mesh_point(m, s[1]), c = tr_mesh_point(m, s[2]);
  int o = 0;
  for (s[3] = 2; s[3] < n; s[3]++) {
    if (s[3] == s[2])
      continue;
    tr_point d = tr_mesh_point(m, s[3]);
    if ((o = tr_orient3d_p(&a, &b, &c, &d)) != 0)
      break;
  }
  if (s[3] == n)
    return tr_error(TR_ERR_DEGENERATE, "all %u points are coplanar", n);
  if (o < 0) {
    uint32_t t = s[0];
    s[0] = s[1], s[1] = t;
  }
  return TR_OK;
}

tr_status tr_delaunay_build_exact(const double *xyz, uint32_t nd, tr_qpoint *const *q,
                                  uint32_t n, struct tr_mesh **out)
{
  *out = NULL;
  if ((uint64_t)nd + n >= TR_GHOST - 1)
    return tr_error(TR_ERR_NOMEM, "too many points (%u and %u)", nd, n);
  struct tr_mesh *m;
  TR_CHECK(tr_mesh_create(nd + n, 64, &m));
  tr_status st = TR_OK;
  /* no duplicates (validation merged them): the identity, which vertex_slot keeps */
  m->dup_map = malloc(sizeof *m->dup_map * (m->cap_v ? m->cap_v : 1));
  if (!m->dup_map)
    st = tr_error(TR_ERR_NOMEM, "out of memory for %u points", nd);
  for (uint32_t i = 0; st == TR_OK && i < nd; i++) {
    uint32_t id;
    st = tr_mesh_add_vertex(m, xyz + 3 * (size_t)i, &id);
  }
  for (uint32_t i = 0; st == TR_OK && i < n; i++) {
    uint32_t id;
    st = add_exact(m, q[i], i, &id);
  }
  uint32_t sv[4] = {0, 0, 0, 0}, t0 = TR_NONE, g[4];
  if (st == TR_OK)
    st = first_simplex_p(m, nd + n, sv);
  if (st == TR_OK)
    st = tr_tet_new(m, sv[0], sv[1], sv[2], sv[3], &t0);
  for (int k = 0; st == TR_OK && k < 4; k++) {
    const uint32_t *v = m->tv + 4 * (size_t)t0;
    const uint8_t *f = tr_face_vtx[k];
    /* reversed face: the ghost's face 3 looks out of the hull (as bw.c's first simplex) */
    st = tr_tet_new(m, v[f[0]], v[f[2]], v[f[1]], TR_GHOST, &g[k]);
    if (st == TR_OK)
      tr_glue(m, t0, k, g[k], 3);
  }
  /* the ghosts meet two by two across the faces through TR_GHOST, one per hull edge */
  for (int k = 0; st == TR_OK && k < 4; k++)
    for (int j = 0; j < 3; j++) {
      const uint32_t *v = m->tv + 4 * (size_t)g[k];
      uint32_t a = v[(j + 1) % 3], b = v[(j + 2) % 3];
      for (int k2 = k + 1; k2 < 4; k2++)
        for (int j2 = 0; j2 < 3; j2++) {
          const uint32_t *w = m->tv + 4 * (size_t)g[k2];
          uint32_t c = w[(j2 + 1) % 3], d = w[(j2 + 2) % 3];
          if ((a == c && b == d) || (a == d && b == c))
            tr_glue(m, g[k], j, g[k2], j2);
        }
    }
  qctx c;
  memset(&c, 0, sizeof c);
  uint32_t hint = t0;
  for (uint32_t i = 0; st == TR_OK && i < nd + n; i++)
    if (i != sv[0] && i != sv[1] && i != sv[2] && i != sv[3])
      st = insert_one(m, &c, i, &hint);
  tr_u32buf_free(&c.cav);
  tr_u32buf_free(&c.bnd);
  free(c.sd);
  tr_mesh_orient_memo_forget(m);
  if (st == TR_OK)
    st = tr_delaunay_canonical(m);
  if (st != TR_OK) {
    tr_mesh_destroy(m);
    return st;
  }
  *out = m;
  return TR_OK;
}
