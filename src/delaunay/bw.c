/* Incremental Bowyer-Watson on the flat tet store (conflict rule in delaunay.h).
 *
 * Per point: a visibility walk from the last created tet to the tet containing it (or
 * to a ghost whose hull face it sees), a breadth-first search of the conflict region
 * (the cavity), and the star re-triangulation: every cavity boundary face (t, k) gives
 * the new tet "t with vertex k replaced by p". That keeps the orientation (p is on the
 * same side of the face as the old vertex k) and keeps TR_GHOST in slot 3. The new tets
 * are glued to each other through the faces that contain p: such a face is (p, u, v) in
 * one tet and (p, v, u) in the other. The boundary vertices get small local ids while
 * the cavity is searched (lid), and the directed edge (u, v) is then a cell of a
 * LDIM x LDIM map (star_small: no hashing, no branches); a cavity with more boundary
 * vertices (rare: a point at the centre of many cospherical ones) takes a hash table of
 * directed edges instead (star_glue_tet). All buffers live in the context and are
 * reused, so an insertion allocates nothing unless the mesh grows.
 *
 * During the build, vertices are numbered in insertion order over a copy of the points
 * in that order: consecutive insertions then touch neighbouring memory (coordinates).
 * The perturbation still uses the input indices (dvtx.orig); ids are mapped back at the end.
 *
 * What the time goes to (random points): about 16500 instructions per point (valgrind
 * --tool=cachegrind on 10^5 points), run at a high rate: 10^5 points (whose mesh fits
 * in the last-level cache) take as long per point as 10^6, so instruction count and
 * mispredicted branches are what to cut, not memory traffic. The insphere determinant
 * a quarter, the cavity search (marks, local ids, boundary faces) a third, writing and
 * gluing the new tets a sixth, walk, sort and renumbering the rest. 48 insphere tests,
 * 6.6 walk steps, 21 cavity tets and 28 new tets per point (TR_DT_STATS). Tried and
 * measured slower: one 32-byte record per tet (vertices and neighbours in one line)
 * converted to tv/tn at the end (the pass and the larger lines cost more than the
 * misses saved); caching vertex - p differences per insertion.
 */
#include <stdlib.h>
#include <math.h>
#include <string.h>

#include "bwkernel.h"
#include "core/hugepage.h"


static tr_status insert(dt *D, uint32_t pi)
{
  struct tr_mesh *m = D->m;
  const double *p = X(D, pi);
  uint32_t t0 = locate(D, D->last, p);
  if (m->tv[4 * (size_t)t0 + 3] != TR_GHOST) {
    const uint32_t *v = m->tv + 4 * (size_t)t0;
    for (int k = 0; k < 4; k++) {
      const double *q = X(D, v[k]);
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
        return tr_error(TR_ERR_INTERNAL, "Delaunay: point %u equals vertex %u after "
                        "duplicate removal", D->orig[pi], D->orig[v[k]]);
    }
  }
  /* The located tet conflicts: p is strictly inside a real tet's closed ball unless it is
   * a vertex, and strictly beyond a ghost's hull face. */
  /* the counts and buffers in locals: stores into the tets could alias D's fields */
  uint32_t ncav = 0, nbf = 0;
  uint32_t *cav = D->cav;
  bface *bf = D->bf;
  /* both buffers have at least room entries */
  uint32_t room = D->capcav < D->capbf ? D->capcav : D->capbf;
  cav[ncav++] = 4 * t0; /* cav: codes 4 * tet + the face it was entered by */
  m->tv[4 * (size_t)t0] |= MARK;
  uint32_t nloc = 1;
  const uint32_t stb = D->stamp << 8;
  for (int k = 0; k < 4; k++)
    TR_PREFETCH(m->tv + 4 * (size_t)(m->tn[4 * (size_t)t0 + k] >> 2));
  for (uint32_t i = 0; i < ncav; i++) {
    /* the face a tet was entered by leads back into the cavity: skip it (t0: none) */
    const uint32_t t = cav[i] >> 2;
    const uint8_t *faces = i ? OTHER[cav[i] & 3] : OTHER[4];
    const int nf = i ? 3 : 4;
    /* a tet's neighbours are read one after the other between conflict tests: start
     * their misses one cavity tet ahead (its neighbour codes were prefetched when it
     * joined the cavity), so that they overlap this tet's tests (t0's were started
     * above; the second cavity tet, found while t0 is searched, gets none) */
    if (i + 1 < ncav) {
      const uint32_t *tnn = m->tn + 4 * (size_t)(cav[i + 1] >> 2);
      for (int k = 0; k < 4; k++)
        TR_PREFETCH(m->tv + 4 * (size_t)(tnn[k] >> 2));
    }
    /* every vertex of a cavity tet is on the cavity boundary: number them here, while
     * their points are still in cache from the conflict tests */
    const uint32_t *tvt = m->tv + 4 * (size_t)t;
    const uint32_t t3 = tvt[3];
    /* room for what this tet's faces can add (at most 4 entries) */
    if (ncav + nbf + 4 > room) {
      D->ncav = ncav;
      D->nbf = nbf;
      TR_CHECK(grow_bufs(D, ncav + nbf + 4));
      cav = D->cav;
      bf = D->bf;
      room = D->capcav < D->capbf ? D->capcav : D->capbf;
    }
    const uint32_t vt[4] = {tvt[0] & ~MARK, tvt[1], tvt[2], t3}; /* t unmarked */
    uint8_t lt[4];
    if (i == 0) {
      for (int k = 0; k < 4; k++)
        lt[k] = (uint8_t)(vt[k] == TR_GHOST ? 0 : lid(D->pv, stb, &nloc, vt[k]));
    } else {
      /* the entry face's vertices were numbered with the tet t was found from (searched
       * before t): their tags hold their ids; only the vertex across it can be new */
      const uint32_t e = cav[i] & 3;
      for (int k = 0; k < 3; k++)
        lt[k] = (uint8_t)D->pv[vt[k]].tag;
      lt[3] = (uint8_t)(t3 == TR_GHOST ? 0 : D->pv[t3].tag);
      if (vt[e] != TR_GHOST)
        lt[e] = (uint8_t)lid(D->pv, stb, &nloc, vt[e]);
    }
    for (int f = 0; f < nf; f++) {
      const int k = faces[f];
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k], u = c >> 2;
      uint32_t *w = m->tv + 4 * (size_t)u;
      if (w[0] & MARK)
        continue;
      /* u's neighbours if it joins the cavity, else the face glued to a new tet */
      TR_PREFETCH(m->tn + 4 * (size_t)u);
      /* Both outcomes are written and the count keeps one: whether u conflicts
       * follows no pattern, and a mispredicted branch costs more than the stores. */
      const uint32_t cf = (uint32_t)conflict(D, u, p, pi);
      w[0] |= cf << 31;
      cav[ncav] = c;
      ncav += cf;
      /* the boundary face (t, k), kept unless u joined the cavity */
      bface *b = &bf[nbf];
      nbf += cf ^ 1;
      memcpy(b->v, vt, sizeof b->v);
      b->v[k] = pi;
      b->out = c;
      b->k = (uint32_t)k;
      memcpy(b->l, lt, sizeof lt);
    }
  }
  D->ncav = ncav;
  D->nbf = nbf;
  STAT((st_cav += D->ncav, st_bf += D->nbf, st_pts++));

  if (++D->stamp == 1u << 24) { /* wrapped: old tags could look current */
    for (uint32_t i = 0; i < D->n; i++)
      D->pv[i].tag = 0;
    D->stamp = 1;
  }

  /* Re-triangulate: reuse the cavity's slots first. */
  const int small = nloc <= LDIM;
  if (!small) {
    STAT(st_big++);
    TR_CHECK(star_begin(D, D->nbf));
  }
  /* The slot of each new tet: the cavity's, then free or new ones. All are taken before
   * the tets are written: m->tv and m->tn may move when the store grows. */
  if (D->nbf > D->capslot)
    TR_CHECK(grow_buf((void **)&D->slot, &D->capslot, D->nbf, sizeof *D->slot));
  if (3 * D->nbf > D->capsd)
    TR_CHECK(grow_buf((void **)&D->sd, &D->capsd, 3 * D->nbf, sizeof *D->sd));
  {
    uint32_t *slot = D->slot, i = 0;
    for (; i < D->nbf && i < D->ncav; i++)
      slot[i] = D->cav[i] >> 2;
    for (; i < D->nbf; i++)
      TR_CHECK(alloc_slot(m, &slot[i]));
  }
  uint32_t last = TR_NONE;
  int bad = 0;
  if (small) {
    bad = star_small(m->tv, m->tn, D->map, D->bf, D->slot, D->sd, D->nbf, &last);
  } else {
    for (uint32_t i = 0; i < D->nbf; i++) {
      const uint32_t s = D->slot[i];
      const bface *b = &D->bf[i];
      uint32_t *v = m->tv + 4 * (size_t)s;
      memcpy(v, b->v, sizeof b->v);
      m->tn[4 * (size_t)s + b->k] = b->out;
      m->tn[b->out] = 4 * s + b->k;
      if (v[3] != TR_GHOST)
        last = s;
      star_glue_tet(D, s, b->k);
    }
  }
  for (uint32_t i = D->nbf; i < D->ncav; i++)
    tr_tet_free(m, D->cav[i] >> 2);
  if (last == TR_NONE)
    return tr_error(TR_ERR_INTERNAL, "Delaunay: inserting point %u created no real tet",
                    D->orig[pi]);
  D->last = last;
  if (!small)
    return star_end(D, D->nbf);
  if (bad)
    return tr_error(TR_ERR_INTERNAL, "Delaunay: the cavity boundary of point %u is not a "
                    "closed surface", D->orig[pi]);
  return TR_OK;
}

/* Are a, b, c collinear? Exactly: all three coordinate projections are degenerate. */
static int collinear(const double *a, const double *b, const double *c)
{
  return tr_orient2d_proj(a, b, c, 0) == 0 && tr_orient2d_proj(a, b, c, 1) == 0 &&
         tr_orient2d_proj(a, b, c, 2) == 0;
}

/* Picks four affinely independent points among order[0..m) and moves them to the front.
 * The messages name input points so that the user can look at them. */
static tr_status first_simplex(const double *xyz, uint32_t n, uint32_t *order, uint32_t m)
{
  if (m < 4) {
    if (m == 1 && n > 1)
      return tr_error(TR_ERR_DEGENERATE, "all %u points are the same point", n);
    return tr_error(TR_ERR_DEGENERATE, "only %u distinct point(s) (of %u): a tetrahedralization "
                    "needs at least 4 points not in a plane", m, n);
  }
  const double *a = xyz + 3 * (size_t)order[0], *b = xyz + 3 * (size_t)order[1];
  uint32_t j = 2;
  while (j < m && collinear(a, b, xyz + 3 * (size_t)order[j]))
    j++;
  if (j == m)
    return tr_error(TR_ERR_DEGENERATE, "all %u points are collinear (line through points %u, %u)",
                    n, order[0], order[1]);
  uint32_t t = order[2];
  order[2] = order[j];
  order[j] = t;
  const double *c = xyz + 3 * (size_t)order[2];
  j = 3;
  while (j < m && tr_orient3d(a, b, c, xyz + 3 * (size_t)order[j]) == 0)
    j++;
  if (j == m)
    return tr_error(TR_ERR_DEGENERATE,
                    "all %u points are coplanar (plane through points %u, %u, %u)", n, order[0],
                    order[1], order[2]);
  t = order[3];
  order[3] = order[j];
  order[j] = t;
  if (tr_orient3d(a, b, c, xyz + 3 * (size_t)order[3]) < 0) {
    t = order[0];
    order[0] = order[1];
    order[1] = t;
  }
  return TR_OK;
}

tr_status tr_dt_insert_serial(dt *D, uint32_t pi)
{
  return insert(D, pi);
}

/* Triangulates the D->n points of D->xyz (insertion ids 0..n-1; 0..3 span 3D): serially,
 * or the first `prefix` points serially and the rest with nthreads threads (par.c). */
static tr_status build(dt *D, uint32_t nthreads, uint32_t prefix)
{
  struct tr_mesh *mesh = D->m;
  uint32_t t0, g[4];
  for (int k = 0; k < 4; k++)
    for (int i = 0; i < 3; i++) {
      int j = SIDE[k][i][0];
      if (SIDE[k][i][1] != tr_face_rot[k][j][0] || SIDE[k][i][2] != tr_face_rot[k][j][1])
        return tr_error(TR_ERR_INTERNAL, "Delaunay: SIDE disagrees with tr_face_rot");
    }
  TR_CHECK(tr_tet_new(mesh, 0, 1, 2, 3, &t0));
  for (int k = 0; k < 4; k++) {
    const uint32_t *v = mesh->tv + 4 * (size_t)t0;
    const uint8_t *f = tr_face_vtx[k];
    /* reversed face: the ghost's face 3 looks out of the hull */
    TR_CHECK(tr_tet_new(mesh, v[f[0]], v[f[2]], v[f[1]], TR_GHOST, &g[k]));
    tr_glue(mesh, t0, k, g[k], 3);
  }
  /* the ghosts' faces through TR_GHOST: the star of the ghost vertex */
  TR_CHECK(star_begin(D, 4));
  for (int k = 0; k < 4; k++)
    star_glue_tet(D, g[k], 3);
  TR_CHECK(star_end(D, 4));
  D->last = t0;
  const uint32_t ser = nthreads > 1 && prefix < D->n ? (prefix > 4 ? prefix : 4) : D->n;
  for (uint32_t i = 4; i < ser; i++)
    TR_CHECK(insert(D, i));
  if (ser < D->n)
    STAT_LAP("prefix");
  if (ser < D->n)
    TR_CHECK(tr_dt_insert_parallel(D, ser, nthreads));
#ifdef TR_DT_STATS
  fprintf(stderr, "points %llu (%llu by the hash) insphere %.2f walk %.2f cavity %.2f boundary "
          "%.2f per point\n", st_pts, st_big, (double)st_ins / st_pts,
          (double)st_walk / st_pts, (double)st_cav / st_pts, (double)st_bf / st_pts);
#endif
  return TR_OK;
}

tr_status tr_delaunay_build(const double *xyz, uint32_t n, struct tr_mesh **out)
{
  return tr_delaunay_build_ex(xyz, n, 1, 0, out);
}

tr_status tr_delaunay_build_threads(const double *xyz, uint32_t n, int threads,
                                    struct tr_mesh **out)
{
  const int nt = tr_delaunay_thread_count(threads);
  return tr_delaunay_build_ex(xyz, n, nt, TR_DT_SERIAL_PREFIX * (uint32_t)nt, out);
}

/* One thread's range [i0, i1) of the per-point passes around the sort: phase 0 checks
 * and copies the input points (bad: the first non-finite one, TR_NONE if none) and
 * clears v2t; phase 1 gathers the points in insertion order (P) and their bounding box. */
typedef struct pjob {
  const double *xyz;
  struct tr_mesh *m;
  const uint32_t *order;
  dvtx *P;
  uint32_t i0, i1, bad;
  int phase;
  double lo[3], hi[3];
} pjob;

static void *points_job(void *arg)
{
  pjob *J = arg;
  if (J->phase == 0) {
    J->bad = TR_NONE;
    for (uint32_t i = J->i0; i < J->i1 && J->bad == TR_NONE; i++)
      for (int c = 0; c < 3; c++) {
        const double x = J->xyz[3 * (size_t)i + (size_t)c];
        if (!(x - x == 0))
          J->bad = i;
      }
    memcpy(J->m->xyz + 3 * (size_t)J->i0, J->xyz + 3 * (size_t)J->i0,
           3 * (size_t)(J->i1 - J->i0) * sizeof *J->xyz);
    for (uint32_t i = J->i0; i < J->i1; i++)
      J->m->v2t[i] = TR_NONE;
    return NULL;
  }
  dvtx *P = J->P;
  for (int c = 0; c < 3; c++)
    J->lo[c] = J->hi[c] = J->xyz[3 * (size_t)J->order[J->i0] + (size_t)c];
  for (uint32_t i = J->i0; i < J->i1; i++) {
    memcpy(P[i].x, J->xyz + 3 * (size_t)J->order[i], sizeof P[i].x);
    P[i].orig = J->order[i];
    P[i].tag = 0;
    for (int c = 0; c < 3; c++) {
      J->lo[c] = P[i].x[c] < J->lo[c] ? P[i].x[c] : J->lo[c];
      J->hi[c] = P[i].x[c] > J->hi[c] ? P[i].x[c] : J->hi[c];
    }
  }
  return NULL;
}

/* Runs phase `phase` of the per-point passes on [0, n) with up to nthreads threads (one
 * per 2^16 points at most). */
static void points_pass(pjob *J, int nthreads, uint32_t n, int phase)
{
  int nth = nthreads < 1 ? 1 : nthreads > 64 ? 64 : nthreads;
  if (n >> 16 < (uint32_t)nth)
    nth = n >> 16 ? (int)(n >> 16) : 1;
  for (int j = 0; j < nth; j++) {
    J[j] = J[0];
    J[j].phase = phase;
    J[j].i0 = (uint32_t)((uint64_t)n * (uint32_t)j / (uint32_t)nth);
    J[j].i1 = (uint32_t)((uint64_t)n * (uint32_t)(j + 1) / (uint32_t)nth);
  }
  tr_dt_run_jobs(points_job, J, sizeof *J, nth);
  for (int j = 1; j < nth; j++) {
    J[0].bad = J[0].bad != TR_NONE ? J[0].bad : J[j].bad; /* the first one */
    for (int c = 0; c < 3; c++) {
      J[0].lo[c] = J[j].lo[c] < J[0].lo[c] ? J[j].lo[c] : J[0].lo[c];
      J[0].hi[c] = J[j].hi[c] > J[0].hi[c] ? J[j].hi[c] : J[0].hi[c];
    }
  }
}

tr_status tr_delaunay_build_ex(const double *xyz, uint32_t n, int nthreads, uint32_t prefix,
                               struct tr_mesh **out)
{
  *out = NULL;
  STAT_LAP(NULL);
  if (n >= (TR_GHOST - 1) || n > (UINT32_MAX / 4 - 64) / 7)
    return tr_error(TR_ERR_NOMEM, "too many points (%u)", n);
  struct tr_mesh *m;
  /* ~6.7 tets per point for uniform random points; growth covers the rest. With threads,
   * the room par.c reserves for its passes (12 slots per point of a pass: ~9.4 per point
   * of the whole set) from the start: growing the store later moves it (mremap) to an
   * address where its huge pages (core/hugepage.c) no longer line up, and the kernel splits them
   * all. Untouched room costs address space only. */
  uint64_t tcap = 7ull * n + 64;
  /* 2 * 4096 * 64: two of par.c's chunks for each of the most threads */
  if (nthreads > 1 && 10ull * n + 2ull * 4096 * 64 + 64 < UINT32_MAX / 4 - 64)
    tcap = 10ull * n + 2ull * 4096 * 64 + 64;
  TR_CHECK(tr_mesh_create(n, (uint32_t)tcap, &m));
  /* untouched yet: the arrays read at random take huge pages (core/hugepage.c) */
  tr_advise_hugepages(m->tv, 4 * (size_t)m->cap_t * sizeof *m->tv);
  tr_advise_hugepages(m->tn, 4 * (size_t)m->cap_t * sizeof *m->tn);
  tr_advise_hugepages(m->flags, (size_t)m->cap_t);
  tr_advise_hugepages(m->xyz, 3 * (size_t)m->cap_v * sizeof *m->xyz);
  tr_advise_hugepages(m->v2t, (size_t)m->cap_v * sizeof *m->v2t);
  pjob PJ[64];
  PJ[0] = (pjob){.xyz = xyz, .m = m};
  if (n)
    points_pass(PJ, nthreads, n, 0);
  if (n && PJ[0].bad != TR_NONE) {
    const uint32_t i = PJ[0].bad;
    const double *x = xyz + 3 * (size_t)i;
    tr_mesh_destroy(m);
    return tr_error(TR_ERR_INPUT, "point %u has a non-finite coordinate (%g)", i,
                    x[0] - x[0] != 0 ? x[0] : x[1] - x[1] != 0 ? x[1] : x[2]);
  }
  tr_status s = TR_OK;
  dt D;
  memset(&D, 0, sizeof D);
  D.m = m;
  D.rng = 0x2545F4914F6CDD1Dull;
  uint32_t *order = malloc((n ? n : 1) * sizeof *order);
  dvtx *P = NULL;
  m->dup_map = malloc((n ? n : 1) * sizeof *m->dup_map);
  tr_advise_hugepages(order, (size_t)n * sizeof *order);
  tr_advise_hugepages(m->dup_map, (size_t)n * sizeof *m->dup_map);
  if (!order || !m->dup_map) {
    s = tr_error(TR_ERR_NOMEM, "out of memory for %u points", n);
    goto done;
  }
  m->nv = n;
  uint32_t nu = 0;
  STAT_LAP("copy");
  /* from here on the mesh's copy of the points (the same bits) rather than the caller's
   * array: the copy has huge pages, for the gathers in Hilbert order below */
  if ((s = tr_spatial_order_threads(m->xyz, n, order, &nu, m->dup_map, nthreads)) != TR_OK)
    goto done;
  m->ndup = n - nu;
  STAT_LAP("sort");
  if ((s = first_simplex(m->xyz, n, order, nu)) != TR_OK)
    goto done;
  P = malloc((size_t)nu * sizeof *P);
  tr_advise_hugepages(P, (size_t)nu * sizeof *P);
  D.map = malloc(LDIM * LDIM * sizeof *D.map);
  if (!P || !D.map) {
    s = tr_error(TR_ERR_NOMEM, "out of memory for %u points", n);
    goto done;
  }
  for (uint32_t i = 0; i < LDIM * LDIM; i++)
    D.map[i] = TR_NONE;
  PJ[0] = (pjob){.xyz = m->xyz, .order = order, .P = P};
  points_pass(PJ, nthreads, nu, 1);
  D.pv = P;
  D.stamp = 1;
  {
    double ext = 0;
    for (int c = 0; c < 3; c++)
      ext = PJ[0].hi[c] - PJ[0].lo[c] > ext ? PJ[0].hi[c] - PJ[0].lo[c] : ext;
    D.is_bound = static_is_bound(ext);
    D.o3_bound = static_o3_bound(ext);
  }
  D.orig = order;
  D.n = nu;
  if ((s = grow_buf((void **)&D.cav, &D.capcav, 256, sizeof *D.cav)) != TR_OK ||
      (s = grow_buf((void **)&D.bf, &D.capbf, 256, sizeof *D.bf)) != TR_OK)
    goto done;
  STAT_LAP("points");
  if ((s = build(&D, nthreads > 1 ? (uint32_t)nthreads : 1, prefix)) != TR_OK)
    goto done;
  STAT_LAP("insert");
  /* on insertion ids: they follow the Hilbert curve, so the canonical order keeps the
   * locality of the build (input indices may be in any order), and they are a function
   * of the input alone, like the tetrahedralization; the tets are written back in input
   * indices (and v2t set) as they are sorted */
  s = tr_delaunay_canonical_map(m, nthreads, order);
  STAT_LAP("canonical");
done:
  free(order);
  free(P);
  free(D.cav);
  free(D.slot);
  free(D.sd);
  free(D.bf);
  free(D.ht);
  free(D.map);
  if (s != TR_OK) {
    tr_mesh_destroy(m);
    return s;
  }
  *out = m;
  return TR_OK;
}

tr_status tr_delaunay(const double *xyz, uint32_t npoints, tr_mesh **out)
{
  tr_error_clear();
  if (!out || (!xyz && npoints))
    return tr_error(TR_ERR_USAGE, "tr_delaunay: NULL argument");
  tr_status s = tr_delaunay_build(xyz, npoints, out);
  if (s == TR_OK && (s = tr_mesh_attach_dense_tets(*out)) != TR_OK) {
    /* the dense tet array of tr_mesh_tets (the store keeps its ghost tets) */
    tr_mesh_destroy(*out);
    *out = NULL;
  }
  return s;
}
