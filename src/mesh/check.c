/* The mesh validator (see check.h). Works in O(T log) with flat arrays so it can run on
 * the 10^6-point benchmark meshes, not only on test-sized ones. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "predicates.h"

static int has_exact(const struct tr_mesh *m, const uint32_t *v, int n)
{
  if (!m->vq)
    return 0;
  for (int i = 0; i < n; i++)
    if (v[i] != TR_GHOST && m->vq[v[i]])
      return 1;
  return 0;
}

static int orient_v(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  uint32_t v[4] = {a, b, c, d};
  if (has_exact(m, v, 4)) {
    tr_point p[4];
    for (int i = 0; i < 4; i++)
      p[i] = tr_mesh_point(m, v[i]);
    return tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
  }
  const double *x = m->xyz;
  return tr_sign(tr_orient3d(x + 3 * (size_t)a, x + 3 * (size_t)b, x + 3 * (size_t)c,
                             x + 3 * (size_t)d));
}

static void face_of(const uint32_t *tv, int k, uint32_t f[3])
{
  for (int i = 0; i < 3; i++)
    f[i] = tv[tr_face_vtx[k][i]];
}

/* (a,b,c) is a cyclic rotation of (x,z,y), i.e. the same face with opposite orientation. */
static int opposite_face(const uint32_t f[3], const uint32_t g[3])
{
  for (int r = 0; r < 3; r++)
    if (f[0] == g[r] && f[1] == g[(r + 2) % 3] && f[2] == g[(r + 1) % 3])
      return 1;
  return 0;
}

static tr_status check_links(const struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    for (int k = 0; k < 4; k++) {
      if (tv[k] != TR_GHOST && tv[k] >= m->nv)
        return tr_error(TR_ERR_INVALID_MESH, "tet %u: vertex %d is %u, out of range (%u vertices)",
                        t, k, tv[k], m->nv);
      for (int j = 0; j < k; j++)
        if (tv[j] == tv[k])
          return tr_error(TR_ERR_INVALID_MESH, "tet %u: vertex %u repeated", t, tv[k]);
    }
    for (int k = 0; k < 4; k++) {
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
      if (c == TR_NONE)
        continue;
      uint32_t u = c >> 2;
      if (u >= m->nt || tr_tet_is_free(m, u) || u == t)
        return tr_error(TR_ERR_INVALID_MESH, "tet %u face %d: neighbour %u is %s", t, k, u,
                        u == t ? "itself" : "not a live tet");
      if (m->tn[c] != 4 * t + (uint32_t)k)
        return tr_error(TR_ERR_INVALID_MESH,
                        "tet %u face %d: neighbour %u face %u does not link back (links to %u)", t,
                        k, u, c & 3, m->tn[c]);
      uint32_t f[3], g[3];
      face_of(tv, k, f);
      face_of(m->tv + 4 * (size_t)u, (int)(c & 3), g);
      if (!opposite_face(f, g))
        return tr_error(TR_ERR_INVALID_MESH,
                        "tet %u face %d (%u %u %u) and tet %u face %u (%u %u %u) are linked but "
                        "are not the same face with opposite orientations",
                        t, k, f[0], f[1], f[2], u, c & 3, g[0], g[1], g[2]);
    }
  }
  return TR_OK;
}

/* GMP's mpq functions assume canonical operands: mpq_equal compares limbs, so 16/32 and
 * 1/2 differ for it. A Steiner point built from a hand-set fraction must canonicalize it. */
static tr_status check_canonical(const struct tr_mesh *m)
{
  tr_status st = TR_OK;
  mpz_t g;
  mpz_init(g);
  for (uint32_t v = 0; m->vq && v < m->nv && st == TR_OK; v++)
    for (int k = 0; m->vq[v] && k < 3 && st == TR_OK; k++) {
      mpq_srcptr c = m->vq[v]->c[k];
      mpz_gcd(g, mpq_numref(c), mpq_denref(c));
      if (mpz_cmp_ui(g, 1) != 0 || mpz_sgn(mpq_denref(c)) <= 0)
        st = tr_error(TR_ERR_INVALID_MESH,
                      "Steiner point %u: coordinate %d (%.17g) is not a canonical rational "
                      "(a common factor or a denominator <= 0)",
                      v, k, mpq_get_d(c));
    }
  mpz_clear(g);
  return st;
}

static tr_status check_orient(const struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    if (v[0] == TR_GHOST || v[1] == TR_GHOST || v[2] == TR_GHOST)
      return tr_error(TR_ERR_INVALID_MESH, "tet %u: the ghost vertex is not in slot 3", t);
    if (v[3] == TR_GHOST)
      continue;
    int o = orient_v(m, v[0], v[1], v[2], v[3]);
    if (o <= 0)
      return tr_error(TR_ERR_INVALID_MESH, "tet %u (%u %u %u %u) is %s", t, v[0], v[1], v[2],
                      v[3], o == 0 ? "flat (orient3d = 0)" : "inverted (orient3d < 0)");
  }
  return TR_OK;
}

static int cmp_u64(const void *a, const void *b)
{
  uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
  return (x > y) - (x < y);
}

/* Vertex -> tets incidence (CSR), then per vertex: its distinct edges and faces to
 * higher vertices (counted once each, from their lowest vertex), face multiplicities. */
static tr_status check_incidence(const struct tr_mesh *m, unsigned what)
{
  uint32_t nv = m->nv;
  uint32_t *off = calloc((size_t)nv + 2, sizeof *off);
  uint32_t nlive = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t)) {
      nlive++;
      for (int k = 0; k < 4; k++) {
        uint32_t v = m->tv[4 * (size_t)t + (size_t)k];
        if (v != TR_GHOST && off)
          off[v + 2]++;
      }
    }
  uint32_t *inc = malloc(4 * (size_t)(nlive ? nlive : 1) * sizeof *inc);
  uint64_t *keys = NULL;
  size_t capkeys = 0;
  tr_status s = TR_OK;
  if (!off || !inc) {
    s = tr_error(TR_ERR_NOMEM, "validator: out of memory");
    goto done;
  }
  for (uint32_t v = 0; v < nv; v++)
    off[v + 2] += off[v + 1];
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t))
      for (int k = 0; k < 4; k++) {
        uint32_t v = m->tv[4 * (size_t)t + (size_t)k];
        if (v != TR_GHOST)
          inc[off[v + 1]++] = t;
      }
  /* now inc[off[v] .. off[v+1]) are the tets of v */
  uint64_t V = 0, E = 0, F = 0, T = tr_mesh_count_real(m);
  for (uint32_t v = 0; v < nv && s == TR_OK; v++) {
    uint32_t b = off[v], e = off[v + 1], nreal = 0;
    int has_v2t = 0;
    for (uint32_t i = b; i < e; i++) {
      nreal += (uint32_t)tr_tet_is_real(m, inc[i]);
      has_v2t |= inc[i] == m->v2t[v];
    }
    if ((what & TR_CHK_V2T) && e == b && m->v2t[v] != TR_NONE) {
      s = tr_error(TR_ERR_INVALID_MESH, "vertex %u: in no tet but v2t = %u", v, m->v2t[v]);
      break;
    }
    if ((what & TR_CHK_V2T) && e > b && !has_v2t) {
      s = tr_error(TR_ERR_INVALID_MESH, "vertex %u: v2t = %u is not one of its %u tets", v,
                   m->v2t[v], e - b);
      break;
    }
    /* input points only: a Steiner point removed after recovery (src/suppress) is in no
     * tet and keeps its slot */
    if ((what & TR_CHK_V2T) && m->dup_map && !(m->vq && m->vq[v])) {
      int kept = m->dup_map[v] == v;
      if (kept != (e > b)) {
        s = tr_error(TR_ERR_INVALID_MESH,
                     kept ? "vertex %u: an input point that is in no tet"
                     : m->dup_map[v] == TR_NONE ? "vertex %u: a removed point that is used by a tet"
                                                : "vertex %u: a dropped duplicate that is used by a tet",
                     v);
        break;
      }
    }
    V += nreal > 0;
    /* Edges (w) and faces (w1,w2) through v whose other vertices are all above v, so
     * each is counted once, from its lowest vertex. fa: faces of all live tets (for the
     * multiplicity check), fr: faces of real tets (for F). */
    size_t need = 3 * (size_t)(e - b);
    if (3 * need > capkeys) {
      uint64_t *k2 = realloc(keys, 3 * need * 2 * sizeof *keys);
      if (!k2) {
        s = tr_error(TR_ERR_NOMEM, "validator: out of memory");
        break;
      }
      keys = k2;
      capkeys = 3 * need * 2;
    }
    uint64_t *ek = keys, *fa = keys + need, *fr = keys + 2 * need;
    size_t ne = 0, nfa = 0, nfr = 0;
    for (uint32_t i = b; i < e; i++) {
      uint32_t t = inc[i];
      const uint32_t *tv = m->tv + 4 * (size_t)t;
      int real = tv[3] != TR_GHOST;
      int kv = tr_ncode(m, t, v);
      for (int j = 0; j < 4; j++)
        if (real && tv[j] > v)
          ek[ne++] = tv[j];
      for (int k = 0; k < 4; k++) {
        if (k == kv)
          continue;
        uint32_t w[2], nw = 0;
        int ok = 1;
        for (int j = 0; j < 4; j++)
          if (j != k && j != kv) {
            if (tv[j] < v)
              ok = 0;
            w[nw++] = tv[j];
          }
        if (!ok)
          continue;
        uint64_t lo = w[0] < w[1] ? w[0] : w[1], hi = w[0] < w[1] ? w[1] : w[0];
        fa[nfa++] = lo << 32 | hi;
        if (real)
          fr[nfr++] = lo << 32 | hi;
      }
    }
    qsort(ek, ne, sizeof *ek, cmp_u64);
    for (size_t i = 0; i < ne; i++)
      E += i == 0 || ek[i] != ek[i - 1];
    qsort(fr, nfr, sizeof *fr, cmp_u64);
    for (size_t i = 0; i < nfr; i++)
      F += i == 0 || fr[i] != fr[i - 1];
    qsort(fa, nfa, sizeof *fa, cmp_u64);
    for (size_t i = 0; i + 2 < nfa; i++)
      if ((what & TR_CHK_V2T) && fa[i] == fa[i + 2]) {
        s = tr_error(TR_ERR_INVALID_MESH, "face (%u %u %u) lies in more than two tets", v,
                     (unsigned)(fa[i] >> 32), (unsigned)(fa[i] & 0xffffffffu));
        break;
      }
  }
  if (s == TR_OK && (what & TR_CHK_EULER)) {
    int64_t chi = (int64_t)V - (int64_t)E + (int64_t)F - (int64_t)T;
    if (chi != 1)
      s = tr_error(TR_ERR_INVALID_MESH,
                   "Euler characteristic V - E + F - T = %llu - %llu + %llu - %llu = %lld, "
                   "expected 1 for a triangulated ball",
                   (unsigned long long)V, (unsigned long long)E, (unsigned long long)F,
                   (unsigned long long)T, (long long)chi);
  }
done:
  free(off);
  free(inc);
  free(keys);
  return s;
}

static tr_status check_delaunay(const struct tr_mesh *m)
{
  const double *x = m->xyz;
#define P(v) (x + 3 * (size_t)(v))
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    for (int k = 0; k < 4; k++) {
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
      if (c == TR_NONE || (c >> 2) < t)
        continue;
      uint32_t u = c >> 2;
      const uint32_t *w = m->tv + 4 * (size_t)u;
      uint32_t e = w[c & 3];
      if (v[3] != TR_GHOST && w[3] != TR_GHOST) {
        int r;
        if (has_exact(m, v, 4) || has_exact(m, &e, 1)) {
          tr_point p[5];
          for (int i = 0; i < 4; i++)
            p[i] = tr_mesh_point(m, v[i]);
          p[4] = tr_mesh_point(m, e);
          r = tr_insphere_p(&p[0], &p[1], &p[2], &p[3], &p[4]);
        } else {
          r = tr_insphere_sos(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(e), v[0], v[1], v[2], v[3],
                              e);
        }
        if (r > 0)
          return tr_error(TR_ERR_INVALID_MESH,
                          "not Delaunay: vertex %u of tet %u is inside the circumsphere of tet %u "
                          "(%u %u %u %u)",
                          e, u, t, v[0], v[1], v[2], v[3]);
      } else if (v[3] == TR_GHOST && w[3] == TR_GHOST && k != 3) {
        if (orient_v(m, v[0], v[1], v[2], e) > 0)
          return tr_error(TR_ERR_INVALID_MESH,
                          "hull not convex: vertex %u is beyond hull face (%u %u %u)", e, v[0],
                          v[1], v[2]);
      }
    }
  }
#undef P
  return TR_OK;
}

/* The sum runs as a balanced binary tree (a binary counter of partial sums: level k holds
 * the sum of 2^k tets) rather than left to right. Every Steiner point brings its own
 * denominator, so a running total's denominator grows to the lcm of all of them and a
 * left-to-right sum costs O(n) additions of that size: quadratic, minutes on a model
 * with 10^4 Steiner points. The tree adds numbers of similar size, O(n log n) in total. */
#define TR_VOL_LEVELS 40
tr_status tr_mesh_volume6(const struct tr_mesh *m, mpq_t out)
{
  mpq_t d[3][3], a[3], t1, t2, lev[TR_VOL_LEVELS];
  uint64_t used = 0; /* bit k: lev[k] holds a partial sum */
  for (int i = 0; i < 3; i++) {
    mpq_init(a[i]);
    for (int j = 0; j < 3; j++)
      mpq_init(d[i][j]);
  }
  for (int k = 0; k < TR_VOL_LEVELS; k++)
    mpq_init(lev[k]);
  mpq_init(t1);
  mpq_init(t2);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    tr_point p0 = tr_mesh_point(m, v[0]);
    for (int c = 0; c < 3; c++)
      tr_point_get_q(&p0, c, a[c]);
    for (int i = 0; i < 3; i++) {
      tr_point p = tr_mesh_point(m, v[i + 1]);
      for (int c = 0; c < 3; c++) {
        tr_point_get_q(&p, c, d[i][c]);
        mpq_sub(d[i][c], d[i][c], a[c]);
      }
    }
    /* det = d0 . (d1 x d2), into t2 */
    mpq_set_ui(t2, 0, 1);
    for (int c = 0; c < 3; c++) {
      int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      mpq_mul(t1, d[1][c1], d[2][c2]);
      mpq_mul(a[0], d[1][c2], d[2][c1]); /* a[] is free again: reuse as scratch */
      mpq_sub(t1, t1, a[0]);
      mpq_mul(t1, t1, d[0][c]);
      mpq_add(t2, t2, t1);
    }
    /* carry t2 up the counter */
    int k = 0;
    while (k < TR_VOL_LEVELS - 1 && (used >> k & 1)) {
      mpq_add(t2, t2, lev[k]);
      used &= ~((uint64_t)1 << k);
      k++;
    }
    if (used >> k & 1)
      mpq_add(lev[k], lev[k], t2); /* only past 2^39 tets */
    else
      mpq_swap(lev[k], t2);
    used |= (uint64_t)1 << k;
  }
  mpq_set_ui(out, 0, 1);
  for (int k = 0; k < TR_VOL_LEVELS; k++)
    if (used >> k & 1)
      mpq_add(out, out, lev[k]);
  for (int i = 0; i < 3; i++) {
    mpq_clear(a[i]);
    for (int j = 0; j < 3; j++)
      mpq_clear(d[i][j]);
  }
  for (int k = 0; k < TR_VOL_LEVELS; k++)
    mpq_clear(lev[k]);
  mpq_clear(t1);
  mpq_clear(t2);
  return TR_OK;
}

tr_status tr_check_mesh(const struct tr_mesh *m, unsigned what, mpq_srcptr volume6)
{
  if (what & (TR_CHK_LINKS | TR_CHK_V2T | TR_CHK_EULER | TR_CHK_DELAUNAY))
    TR_CHECK(check_links(m));
  if (what & TR_CHK_ORIENT) {
    TR_CHECK(check_canonical(m));
    TR_CHECK(check_orient(m));
  }
  if (what & (TR_CHK_V2T | TR_CHK_EULER))
    TR_CHECK(check_incidence(m, what));
  if (what & TR_CHK_DELAUNAY)
    TR_CHECK(check_delaunay(m));
  if (volume6) {
    mpq_t vol;
    mpq_init(vol);
    tr_mesh_volume6(m, vol);
    int eq = mpq_equal(vol, volume6);
    double got = mpq_get_d(vol), want = mpq_get_d(volume6);
    mpq_clear(vol);
    if (!eq)
      return tr_error(TR_ERR_INVALID_MESH,
                      "total volume differs: sum of 6*volume = %.17g, expected %.17g (exact "
                      "rationals differ)",
                      got, want);
  }
  return TR_OK;
}
