/* Parallel Bowyer-Watson (the scheme of Marot, Pellerin, Remacle, "One machine, one
 * minute, three billion tetrahedra", 2019): the points after a serial prefix go in blocks
 * (each about the size of the mesh so far, so a block stays within a BRIO round or two);
 * a block is cut into one contiguous Hilbert range per thread, and each thread inserts
 * its range with the serial kernel (bwkernel.h), owning every tet it reads or writes:
 * a tet is taken with an atomic compare-and-swap on own[t] (0 free, else the thread
 * number; a slot of the thread's fresh chunk, which no other thread can reach, by a
 * plain store: 4.1 instead of 10.9 locked instructions per point) and stays the
 * thread's until it holds HOLD_MAX tets, then all are given back (between two
 * insertions): later reads by the same thread cost one load, and only the
 * first touch of a tet per window costs a locked instruction (taking and giving back
 * around every insertion cost ~70 of them per point, +45% CPU over the serial build on
 * 10^6 points), while what a thread holds stays near the points it inserts now (holding
 * everything until the range is done deferred 6% of uniform points and 25% of sphere
 * points in a block's first pass; with the window, under 0.1%). A thread takes each tet its
 * walk steps on, each cavity tet, each neighbour it tests and the real tet behind a
 * ghost it tests. A tet held by another thread is a conflict: the insertion is undone
 * (the cavity marks cleared; nothing else was written yet) and the point waits for the
 * next pass, in which the deferred points are cut at shifted places. When a pass defers
 * nearly as many points as it was given, the rest go in serially. Each thread starts
 * from the tet at its range's first point (located serially): a start shared by the
 * threads would be held by the first one for the whole pass.
 *
 * Which thread inserts which point, and in which order, changes the slots, never the
 * tetrahedralization (unique under the symbolic perturbation); tr_delaunay_canonical then
 * gives the same store for any number of threads.
 *
 * Per thread: its own cavity buffers and star tables (a dt of its own), its own local-id
 * tags (a vertex can be on two threads' cavity boundaries at once), its own free slots
 * and a chunk of fresh slots. The store is reserved before each pass and never moves
 * while threads run; a thread that runs out of room defers its points. */
#include <pthread.h>
#include <unistd.h>

#include "bwkernel.h"
#include "core/hugepage.h"

#define CHUNK 4096u /* fresh slots a thread takes at a time */
#define HOLD_MAX 8192u /* tets a thread holds before it gives them all back */

typedef struct shared {
  uint8_t *own;        /* per tet slot: owning thread + 1, 0 when free (a byte: a
                        * quarter of the cache lines and fresh pages of a word) */
  uint32_t nown;       /* entries of own */
  uint32_t next_fresh; /* first slot no thread has taken (atomic) */
  uint32_t cap;        /* slots usable in this pass */
} shared;

typedef struct worker {
  /* a worker starts a cache line of its own: its fields written at every insertion
   * (D.rng, D.stamp, held.n, fresh, hist) must not share a line with the next worker's */
  _Alignas(64) dt D; /* own buffers; m, pv, orig, n and the filter bounds shared */
  shared *S;
  uint8_t *own;    /* S->own for this pass (one load less per take) */
  uint32_t id;     /* 1 + thread number (at most 64: fits the owner byte) */
  uint32_t *tag;   /* D.n: stamp << 8 | local id (lid, per thread) */
  tr_u32buf held;  /* tets the thread owns (took in this pass) */
  tr_u32buf freed; /* slots this thread freed, for its next new tets */
  tr_u32buf defer; /* points of this pass given up on a conflict */
  uint32_t fresh, fresh_end; /* the thread's chunk of fresh slots */
  uint32_t hist[4];          /* recent real tets made: walk starts */
  const uint32_t *pts;
  uint32_t npts;
  int full;        /* no room left in this pass: the rest is deferred */
#ifdef TR_DT_STATS
  unsigned long long ntake, ncas; /* takes, and those that took a compare-and-swap */
#endif
  tr_status st;
} worker;

static inline int take(worker *W, uint32_t t)
{
  uint8_t *o = &W->own[t];
  uint8_t cur = __atomic_load_n(o, __ATOMIC_RELAXED);
  STAT(W->ntake++);
  if (cur == W->id)
    return 1;
  if (cur != 0)
    return 0;
  STAT(W->ncas++);
  if (!__atomic_compare_exchange_n(o, &cur, (uint8_t)W->id, 0, __ATOMIC_ACQUIRE,
                                   __ATOMIC_RELAXED))
    return 0;
  if (tr_u32buf_push(&W->held, t) != TR_OK) {
    __atomic_store_n(o, 0, __ATOMIC_RELEASE);
    W->st = TR_ERR_NOMEM;
    return 0;
  }
  return 1;
}

/* Gives back every tet the thread took in this pass: the release stores pair with the
 * acquiring compare-and-swap of a thread that takes one next (one still running, or
 * any thread of a later pass). */
static void give_back(worker *W)
{
  for (size_t i = 0; i < W->held.n; i++)
    __atomic_store_n(&W->own[W->held.a[i]], 0, __ATOMIC_RELEASE);
  W->held.n = 0;
}

/* lid of bw.c on the thread's own tags */
static inline uint32_t lid_w(uint32_t *tag, uint32_t stb, uint32_t *nloc, uint32_t v)
{
  const uint32_t d = tag[v] - stb;
  const uint32_t hit = d < 256;
  const uint32_t l = hit ? d : (*nloc & 255);
  tag[v] = stb | l;
  *nloc += !hit;
  return l;
}

static void next_stamp(worker *W)
{
  if (++W->D.stamp == 1u << 24) {
    memset(W->tag, 0, (size_t)W->D.n * sizeof *W->tag);
    W->D.stamp = 1;
  }
}

/* The walk of locate (bwkernel.h), holding the tet it stands on. 0 on a conflict. */
static int walk(worker *W, uint32_t t, const double *p, uint32_t *out)
{
  dt *D = &W->D;
  const struct tr_mesh *m = D->m;
  uint32_t prev = TR_NONE, r = 0;
  int bits = 0;
  for (;;) {
    if (bits < 2) {
      r = rnd(D);
      bits = 32;
    }
    const int s = (int)(r & 3);
    r >>= 2;
    bits -= 2;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    int moved = 0;
    for (int i = 0; i < 4; i++) {
      const int k = (s + i) & 3;
      const uint32_t u = m->tn[4 * (size_t)t + (size_t)k] >> 2;
      if (u == prev)
        continue;
      const uint8_t *f = tr_face_vtx[k];
      if (orient_neg(D, X(D, v[f[0]]), X(D, v[f[1]]), X(D, v[f[2]]), p)) {
        if (!take(W, u))
          return 0;
        prev = t;
        t = u;
        moved = 1;
        break;
      }
    }
    if (!moved || m->tv[4 * (size_t)t + 3] == TR_GHOST) {
      *out = t;
      return 1;
    }
  }
}

/* A slot for a new tet, owned: the thread's freed ones, then its chunk. 0: none. */
static int new_slot(worker *W, uint32_t *s)
{
  if (W->freed.n) {
    /* the thread's own frees are its already; a slot of the store's free list dealt to
     * it is reachable by no walk (starts are live tets), so the take cannot fail there */
    const uint32_t t = W->freed.a[W->freed.n - 1];
    if (!take(W, t))
      return 0;
    W->freed.n--;
    *s = t;
    return 1;
  }
  if (W->fresh == W->fresh_end) {
    const uint32_t lo = __atomic_fetch_add(&W->S->next_fresh, CHUNK, __ATOMIC_RELAXED);
    if (lo >= W->S->cap || W->S->cap - lo < CHUNK) {
      W->full = 1;
      return 0;
    }
    /* slots of a chunk that end up unused (given up across a chunk change in an undo)
     * must read as free; clearing them here, in the thread, also spreads the first
     * touch of the store's new pages over the threads */
    for (uint32_t t = lo; t < lo + CHUNK; t++)
      W->D.m->tv[4 * (size_t)t] = TR_NONE;
    W->fresh = lo;
    W->fresh_end = lo + CHUNK;
  }
  /* a fresh slot is reachable by no other thread (no tet links to it until this one
   * writes its tets, which it holds): owned by a plain store, no compare-and-swap (a
   * locked instruction also waits for every load in flight: ~7 per point) */
  const uint32_t t = W->fresh;
  if (tr_u32buf_push(&W->held, t) != TR_OK) {
    W->st = TR_ERR_NOMEM;
    return 0;
  }
  __atomic_store_n(&W->own[t], (uint8_t)W->id, __ATOMIC_RELAXED);
  *s = W->fresh++;
  return 1;
}

/* Inserts point pi: 1 done, 0 deferred (nothing changed), -1 error in W->st. */
static int pinsert(worker *W, uint32_t pi)
{
  dt *D = &W->D;
  struct tr_mesh *m = D->m;
  const double *p = X(D, pi);
  uint32_t t0 = TR_NONE;
  for (int h = 0; h < 4 && t0 == TR_NONE; h++) {
    const uint32_t s = W->hist[h];
    if (s == TR_NONE || !take(W, s))
      continue;
    if (m->tv[4 * (size_t)s] != TR_NONE && m->tv[4 * (size_t)s + 3] != TR_GHOST)
      t0 = s; /* a live real tet (freed or turned into a ghost since: try the next) */
  }
  if (t0 == TR_NONE || !walk(W, t0, p, &t0))
    return W->st == TR_OK ? 0 : -1;
  if (m->tv[4 * (size_t)t0 + 3] != TR_GHOST) {
    const uint32_t *v = m->tv + 4 * (size_t)t0;
    for (int k = 0; k < 4; k++) {
      const double *q = X(D, v[k]);
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) {
        W->st = tr_error(TR_ERR_INTERNAL, "Delaunay: point %u equals vertex %u after "
                         "duplicate removal", D->orig[pi], D->orig[v[k]]);
        return -1;
      }
    }
  }
  uint32_t ncav = 0, nbf = 0, nloc = 1;
  const uint32_t stb = D->stamp << 8;
  D->cav[ncav++] = 4 * t0;
  m->tv[4 * (size_t)t0] |= MARK;
  int ok = 1;
  uint32_t *cav = D->cav, *tag = W->tag;
  const uint8_t *own = W->own;
  bface *bf = D->bf;
  uint32_t room = D->capcav < D->capbf ? D->capcav : D->capbf;
  for (int k = 0; k < 4; k++)
    TR_PREFETCH(m->tv + 4 * (size_t)(m->tn[4 * (size_t)t0 + k] >> 2));
  /* the serial kernel's search (bw.c insert: prefetches one cavity tet ahead, local ids
   * of the vertex across the entry face only, both outcomes of a test written), plus a
   * take of every tet read */
  for (uint32_t i = 0; i < ncav; i++) {
    const uint32_t t = cav[i] >> 2;
    const uint8_t *faces = i ? OTHER[cav[i] & 3] : OTHER[4];
    const int nf = i ? 3 : 4;
    if (i + 1 < ncav) {
      const uint32_t *tnn = m->tn + 4 * (size_t)(cav[i + 1] >> 2);
      for (int k = 0; k < 4; k++) {
        TR_PREFETCH(m->tv + 4 * (size_t)(tnn[k] >> 2));
        TR_PREFETCH(own + (tnn[k] >> 2));
      }
    }
    if (ncav + nbf + 4 > room) {
      if ((W->st = grow_bufs(D, ncav + nbf + 4)) != TR_OK) {
        ok = 0;
        break;
      }
      cav = D->cav;
      bf = D->bf;
      room = D->capcav < D->capbf ? D->capcav : D->capbf;
    }
    const uint32_t *tvt = m->tv + 4 * (size_t)t;
    const uint32_t t3 = tvt[3];
    const uint32_t vt[4] = {tvt[0] & ~MARK, tvt[1], tvt[2], t3};
    uint8_t lt[4];
    if (i == 0) {
      for (int k = 0; k < 4; k++)
        lt[k] = (uint8_t)(vt[k] == TR_GHOST ? 0 : lid_w(tag, stb, &nloc, vt[k]));
    } else {
      const uint32_t e = cav[i] & 3;
      for (int k = 0; k < 3; k++)
        lt[k] = (uint8_t)tag[vt[k]];
      lt[3] = (uint8_t)(t3 == TR_GHOST ? 0 : tag[t3]);
      if (vt[e] != TR_GHOST)
        lt[e] = (uint8_t)lid_w(tag, stb, &nloc, vt[e]);
    }
    for (int f = 0; f < nf; f++) {
      const int k = faces[f];
      const uint32_t c = m->tn[4 * (size_t)t + (size_t)k], u = c >> 2;
      if (!take(W, u)) {
        ok = 0;
        break;
      }
      uint32_t *w = m->tv + 4 * (size_t)u;
      if (w[0] & MARK)
        continue;
      TR_PREFETCH(m->tn + 4 * (size_t)u);
      /* conflict() reads the real tet behind a ghost */
      if (w[3] == TR_GHOST && !take(W, m->tn[4 * (size_t)u + 3] >> 2)) {
        ok = 0;
        break;
      }
      const uint32_t cf = (uint32_t)conflict(D, u, p, pi);
      w[0] |= cf << 31;
      cav[ncav] = c;
      ncav += cf;
      bface *b = &bf[nbf];
      nbf += cf ^ 1;
      memcpy(b->v, vt, sizeof b->v);
      b->v[k] = pi;
      b->out = c;
      b->k = (uint32_t)k;
      memcpy(b->l, lt, sizeof lt);
    }
    if (!ok)
      break;
  }
  next_stamp(W);
  /* the slots of the new tets: the cavity's, then the thread's own */
  if (ok && nbf > D->capslot &&
      (W->st = grow_buf((void **)&D->slot, &D->capslot, nbf, sizeof *D->slot)) != TR_OK)
    ok = 0;
  if (ok && 3 * nbf > D->capsd &&
      (W->st = grow_buf((void **)&D->sd, &D->capsd, 3 * nbf, sizeof *D->sd)) != TR_OK)
    ok = 0;
  uint32_t i = 0;
  for (; ok && i < nbf && i < ncav; i++)
    D->slot[i] = D->cav[i] >> 2;
  const uint32_t fresh0 = W->fresh, end0 = W->fresh_end, nfreed0 = (uint32_t)W->freed.n;
  for (; ok && i < nbf; i++)
    ok = new_slot(W, &D->slot[i]);
  if (!ok) {
    /* undo: marks off, the slots taken back (they were not written: a chunk's unused
     * slots read as free, see new_slot); the tets stay the thread's for the pass */
    for (uint32_t j = 0; j < ncav; j++)
      m->tv[4 * (size_t)(D->cav[j] >> 2)] &= ~MARK;
    W->fresh = W->fresh_end == end0 ? fresh0 : W->fresh_end - CHUNK;
    W->freed.n = nfreed0;
    return W->st == TR_OK ? 0 : -1;
  }
  uint32_t last = TR_NONE;
  int bad = 0;
  D->ncav = ncav;
  D->nbf = nbf;
  if (nloc <= LDIM) {
    bad = star_small(m->tv, m->tn, D->map, D->bf, D->slot, D->sd, nbf, &last);
  } else {
    if ((W->st = star_begin(D, nbf)) != TR_OK)
      return -1;
    for (uint32_t j = 0; j < nbf; j++) {
      const uint32_t s = D->slot[j];
      const bface *b = &D->bf[j];
      memcpy(m->tv + 4 * (size_t)s, b->v, sizeof b->v);
      m->tn[4 * (size_t)s + b->k] = b->out;
      m->tn[b->out] = 4 * s + b->k;
      if (b->v[3] != TR_GHOST)
        last = s;
      star_glue_tet(D, s, b->k);
    }
    if ((W->st = star_end(D, nbf)) != TR_OK)
      bad = 1;
  }
  for (uint32_t j = nbf; j < ncav; j++) {
    const uint32_t s = D->cav[j] >> 2;
    m->tv[4 * (size_t)s] = TR_NONE;
    if (tr_u32buf_push(&W->freed, s) != TR_OK)
      W->st = TR_ERR_NOMEM;
  }
  if (bad || last == TR_NONE || W->st != TR_OK) {
    if (W->st == TR_OK)
      W->st = tr_error(TR_ERR_INTERNAL, "Delaunay: the cavity of point %u is not a ball",
                       D->orig[pi]);
    return -1;
  }
  memmove(W->hist + 1, W->hist, 3 * sizeof *W->hist);
  W->hist[0] = last;
  return 1;
}

static void *run(void *arg)
{
  worker *W = arg;
  for (uint32_t i = 0; i < W->npts && W->st == TR_OK; i++) {
    const uint32_t pi = W->pts[i];
    const int r = W->full ? 0 : pinsert(W, pi);
    if (r == 0 && tr_u32buf_push(&W->defer, pi) != TR_OK)
      W->st = TR_ERR_NOMEM;
    if (W->held.n >= HOLD_MAX)
      give_back(W);
  }
  give_back(W);
  return NULL;
}

/* Threads to use for the option value (0: every online core). */
int tr_delaunay_thread_count(int threads)
{
  if (threads > 0)
    return threads > 64 ? 64 : threads;
  const long c = sysconf(_SC_NPROCESSORS_ONLN);
  return c < 1 ? 1 : c > 64 ? 64 : (int)c;
}

static int real_live(const struct tr_mesh *m, uint32_t t)
{
  return m->tv[4 * (size_t)t] != TR_NONE && m->tv[4 * (size_t)t + 3] != TR_GHOST;
}

static tr_status reserve(dt *D, shared *S, uint32_t npts, uint32_t nthreads)
{
  struct tr_mesh *m = D->m;
  const uint64_t want = (uint64_t)m->nt + 12ull * npts + 2ull * CHUNK * nthreads + 64;
  if (want > UINT32_MAX / 4 - 64)
    return tr_error(TR_ERR_NOMEM, "too many tets for the parallel Delaunay build");
  if (want > m->cap_t) {
    TR_CHECK(tr_mesh_reserve_tets(m, (uint32_t)want));
    tr_advise_hugepages(m->tv, (size_t)m->cap_t * 4 * sizeof *m->tv);
    tr_advise_hugepages(m->tn, (size_t)m->cap_t * 4 * sizeof *m->tn);
  }
  if (m->cap_t > S->nown) {
    /* every owner word is 0 between passes: a fresh zeroed array, whose pages the
     * threads fault in as they touch them (a realloc and memset here would zero
     * hundreds of MB in serial on 10^7 points) */
    free(S->own);
    S->own = calloc(m->cap_t, sizeof *S->own);
    S->nown = S->own ? m->cap_t : 0;
    tr_advise_hugepages(S->own, (size_t)S->nown * sizeof *S->own);
    if (!S->own)
      return tr_error(TR_ERR_NOMEM, "out of memory for the tet owners");
  }
  S->next_fresh = m->nt;
  S->cap = m->cap_t;
  return TR_OK;
}

/* One pass: pts[0..k) cut into nthreads ranges starting at shift, deferred points
 * appended to *left. */
static tr_status pass(dt *D, shared *S, worker *W, uint32_t nthreads, const uint32_t *pts,
                      uint32_t k, uint32_t shift, tr_u32buf *left)
{
  TR_CHECK(reserve(D, S, k, nthreads));
  struct tr_mesh *m = D->m;
  const uint32_t nt0 = m->nt;
  /* the store's free slots are dealt to the threads, so the store grows only by what
   * they do not cover */
  for (uint32_t j = 0; m->free_head != TR_NONE; j = (j + 1) % nthreads) {
    const uint32_t t = m->free_head;
    m->free_head = m->tn[4 * (size_t)t];
    m->nfree--;
    TR_CHECK(tr_u32buf_push(&W[j].freed, t));
  }
  if (!real_live(m, D->last)) /* the serial inserts' start: any live real tet */
    for (uint32_t t = 0; t < m->nt; t++)
      if (real_live(m, t)) {
        D->last = t;
        break;
      }
  /* shifted ranges wrap around the end of pts: cut them from a rotated copy */
  uint32_t *rot = NULL;
  if (shift) {
    rot = malloc((size_t)k * sizeof *rot);
    if (!rot)
      return tr_error(TR_ERR_NOMEM, "out of memory for the deferred points");
    for (uint32_t i = 0; i < k; i++)
      rot[i] = pts[(i + shift) % k];
  }
  for (uint32_t j = 0; j < nthreads; j++) {
    const uint32_t a = (uint32_t)((uint64_t)k * j / nthreads);
    const uint32_t b = (uint32_t)((uint64_t)k * (j + 1) / nthreads);
    worker *w = &W[j];
    w->own = S->own;
    w->pts = (rot ? rot : pts) + a;
    w->npts = b - a;
    w->defer.n = 0;
    w->fresh = w->fresh_end = 0;
    w->full = 0;
    w->st = TR_OK;
    /* a start of its own near its range (a shared start would be owned by the first
     * thread that walks from it, for the whole pass): the real tet at its first point */
    for (int h = 0; h < 4; h++)
      w->hist[h] = TR_NONE;
    if (w->npts) {
      uint32_t t = locate(D, D->last, X(D, w->pts[0]));
      if (m->tv[4 * (size_t)t + 3] == TR_GHOST)
        t = m->tn[4 * (size_t)t + 3] >> 2;
      w->hist[0] = t;
    }
  }
  pthread_t th[64];
  uint32_t started = 1;
  for (uint32_t j = 1; j < nthreads; j++, started++)
    if (pthread_create(&th[j], NULL, run, &W[j]) != 0)
      break;
  run(&W[0]);
  for (uint32_t j = 1; j < started; j++)
    pthread_join(th[j], NULL);
  /* threads that could not start: their ranges wait like deferred points */
  for (uint32_t j = started; j < nthreads; j++)
    for (uint32_t i = 0; i < W[j].npts; i++)
      TR_CHECK(tr_u32buf_push(&W[j].defer, W[j].pts[i]));
  free(rot);
  /* the slots taken: the used ones are tets, the rest of each chunk and the freed
   * ones go to the store's free list for the serial inserts; a chunk that did not fit
   * below cap was not given (nor cleared) */
  m->nt = S->next_fresh <= S->cap ? S->next_fresh
                                  : nt0 + (S->cap - nt0) / CHUNK * CHUNK;
  tr_status st = TR_OK;
  for (uint32_t j = 0; j < nthreads; j++) {
    worker *w = &W[j];
    if (st == TR_OK && w->st != TR_OK)
      st = w->st;
    for (uint32_t s = w->fresh; s < w->fresh_end && s < m->nt; s++)
      tr_tet_free(m, s);
    for (size_t i = 0; i < w->freed.n; i++)
      tr_tet_free(m, w->freed.a[i]);
    w->freed.n = 0;
    for (size_t i = 0; i < w->defer.n && st == TR_OK; i++)
      st = tr_u32buf_push(left, w->defer.a[i]);
  }
  /* the serial inserts and the next pass start from a live real tet */
  for (uint32_t j = 0; j < nthreads; j++)
    for (int h = 0; h < 4; h++) {
      const uint32_t s = W[j].hist[h];
      if (s != TR_NONE && s < m->nt && real_live(m, s)) {
        D->last = s;
        j = nthreads;
        break;
      }
    }
  /* a chunk taken past the end (a thread that found the store full) left nothing */
  return st;
}

tr_status tr_dt_insert_parallel(dt *D, uint32_t from, uint32_t nthreads)
{
  shared S = {0};
  worker W[64];
  memset(W, 0, sizeof W);
  tr_u32buf cur = {0}, left = {0};
  tr_status st = TR_OK;
  for (uint32_t j = 0; j < nthreads && st == TR_OK; j++) {
    worker *w = &W[j];
    w->S = &S;
    w->id = j + 1;
    w->D = *D; /* shared fields; the buffers below are the thread's own */
    w->D.cav = NULL;
    w->D.bf = NULL;
    w->D.slot = NULL;
    w->D.sd = NULL;
    w->D.ht = NULL;
    w->D.capcav = w->D.capbf = w->D.capslot = w->D.capsd = w->D.capht = 0;
    w->D.rng = D->rng + 0x9E3779B97F4A7C15ull * (j + 1);
    w->D.stamp = 1;
    w->D.map = malloc(LDIM * LDIM * sizeof *w->D.map);
    w->tag = calloc(D->n ? D->n : 1, sizeof *w->tag);
    tr_advise_hugepages(w->tag, (size_t)D->n * sizeof *w->tag); /* random access: TLB */
    for (int h = 0; h < 4; h++)
      w->hist[h] = TR_NONE;
    if (!w->D.map || !w->tag) {
      st = tr_error(TR_ERR_NOMEM, "out of memory for the Delaunay threads");
      break;
    }
    for (uint32_t i = 0; i < LDIM * LDIM; i++)
      w->D.map[i] = TR_NONE;
    if ((st = grow_buf((void **)&w->D.cav, &w->D.capcav, 256, sizeof *w->D.cav)) != TR_OK ||
        (st = grow_buf((void **)&w->D.bf, &w->D.capbf, 256, sizeof *w->D.bf)) != TR_OK)
      break;
  }
  STAT_LAP(NULL);
  /* blocks about the size of the mesh so far */
  uint32_t done = from;
  while (st == TR_OK && done < D->n) {
    uint32_t k = done < D->n - done ? done : D->n - done;
    cur.n = 0;
    for (uint32_t i = 0; i < k && st == TR_OK; i++)
      st = tr_u32buf_push(&cur, done + i);
    done += k;
    for (uint32_t shift = 0; st == TR_OK && cur.n; shift++) {
      left.n = 0;
      const uint32_t kk = (uint32_t)cur.n;
      st = pass(D, &S, W, nthreads, cur.a, kk, shift ? kk / (2 * nthreads) : 0, &left);
#ifdef TR_DT_STATS
      fprintf(stderr, "pass: %u points from %u, %u deferred\n", kk, done - k, (uint32_t)left.n);
#endif
      STAT_LAP("pass");
      const tr_u32buf t = cur;
      cur = left;
      left = t;
      /* few points left, or little progress: the rest serially */
      if (st == TR_OK && cur.n && (cur.n < 64 * nthreads || 10 * cur.n > 9 * kk)) {
        for (size_t i = 0; i < cur.n && st == TR_OK; i++)
          st = tr_dt_insert_serial(D, cur.a[i]);
        cur.n = 0;
        STAT_LAP("serial rest");
      }
    }
  }
  for (uint32_t j = 0; j < nthreads; j++) {
    worker *w = &W[j];
    free(w->D.cav);
    free(w->D.bf);
    free(w->D.slot);
    free(w->D.sd);
    free(w->D.ht);
    free(w->D.map);
    free(w->tag);
    tr_u32buf_free(&w->held);
    tr_u32buf_free(&w->freed);
    tr_u32buf_free(&w->defer);
  }
  tr_u32buf_free(&cur);
  tr_u32buf_free(&left);
#ifdef TR_DT_STATS
  unsigned long long ntake = 0, ncas = 0;
  for (uint32_t j = 0; j < nthreads; j++)
    ntake += W[j].ntake, ncas += W[j].ncas;
  fprintf(stderr, "parallel points %u: takes %.2f, compare-and-swaps %.2f per point\n",
          D->n - from, (double)ntake / (D->n - from), (double)ncas / (D->n - from));
#endif
  free(S.own);
  return st;
}
