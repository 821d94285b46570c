/* Canonical storage order of a Delaunay mesh.
 *
 * The perturbed Delaunay tetrahedralization is unique, but the slots its tets land in,
 * and which of a tet's 12 positive vertex orders is stored, depend on the insertion
 * order (and, with several threads, on scheduling). Every later stage walks tets in slot
 * order, so this pass makes the store a function of the tetrahedralization alone: each
 * tet rotated (an even permutation: orientation kept) so that its smallest vertex comes
 * first and the smallest of the other three second, ghosts rotated among their first
 * three slots (TR_GHOST stays in slot 3); real tets first, sorted by vertex tuple, then
 * the ghosts sorted by their hull face; free slots dropped, neighbours renumbered.
 * tr_delaunay_build calls it on insertion ids (Hilbert order, a function of the input),
 * with the map back to input indices, applied as the sorted tets are written.
 *
 * Cost: one counting sort on the first vertex (a bucket holds ~6.7 tets on random points;
 * a bucket of a vertex with a huge star falls back to qsort), a pass to write the
 * neighbours. Linear in the number of tets. No new tet arrays: a sorted bucket record
 * (three vertices and the old slot, 16 bytes) is overwritten in place by the tet's
 * vertices, so the records become the new tv, and the new tn goes where the old tv
 * was (read for the last time by the scatter). Fresh pages cost about 1 us each to
 * fault in, a quarter of this pass before. With several threads every pass is cut into
 * one range per thread (tets for the counting and the writing, buckets for the sorting;
 * each thread counts into its own array, so a bucket holds thread 0's tets first): the
 * records of a bucket end up sorted the same way whatever the cut, so the store is the
 * same byte for byte. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay.h"
#include "core/hugepage.h"
#include "core/prefetch.h"
#include "dtstat.h"

#define CANON_MAX_THREADS 64
/* records or tets ahead whose random accesses are started early (a hint) */
#define AHEAD 16
#define NR_NONE UINT64_MAX


/* PERM[r]: new slot j takes old slot PERM[r][j]. 0..11: real tets, r = 3k + s where k is
 * the old slot of the smallest vertex and s the rotation of the other three, listed from
 * OTH[k] (an order that makes (k, OTH[k]) even); 12..14: ghosts, rotations of slots
 * 0..2. All twelve are the even permutations (orientation kept). INV: the inverses. */
static const uint8_t OTH[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
static const uint8_t PERM[15][4] = {
    {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2}, {1, 3, 2, 0},
    {1, 2, 0, 3}, {2, 0, 1, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {3, 0, 2, 1},
    {3, 2, 1, 0}, {3, 1, 0, 2}, {0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}};
static const uint8_t INV[15][4] = {
    {0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 0, 3, 2}, {3, 0, 2, 1},
    {2, 0, 1, 3}, {1, 2, 0, 3}, {3, 1, 0, 2}, {2, 3, 0, 1}, {1, 3, 2, 0},
    {3, 2, 1, 0}, {2, 1, 3, 0}, {0, 1, 2, 3}, {2, 0, 1, 3}, {1, 2, 0, 3}};

/* The rotation of tet v (see PERM). */
static uint8_t rotation_slow(const uint32_t *v)
{
  if (v[3] == TR_GHOST) {
    const int s = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    return (uint8_t)(12 + s);
  }
  int k = 0;
  for (int j = 1; j < 4; j++)
    k = v[j] < v[k] ? j : k;
  const uint8_t *o = OTH[k];
  const int s = v[o[0]] < v[o[1]] ? (v[o[0]] < v[o[2]] ? 0 : 2) : (v[o[1]] < v[o[2]] ? 1 : 2);
  return (uint8_t)(3 * k + s);
}

/* rotation_slow as a lookup on the pairwise comparisons (bit i: the i-th of v0<v1,
 * v0<v2, v0<v3, v1<v2, v1<v3, v2<v3; ghosts: v0<v1, v0<v2, v1<v2), computed from it for
 * the 24 orders of four distinct vertices (255: no order, some vertices equal): which
 * vertex is smallest follows no pattern, and the branches of rotation_slow mispredicted
 * about twice per tet. */
static const uint8_t ROT_REAL[64] = {
    10,  10,  255, 9,   255, 255, 255, 2,   11,  255, 11,  9,   255, 255, 255, 2,
    255, 255, 255, 255, 255, 255, 255, 255, 4,   255, 4,   255, 255, 255, 3,   0,
    8,   8,   255, 255, 255, 6,   255, 1,   255, 255, 255, 255, 255, 255, 255, 255,
    7,   255, 255, 255, 7,   6,   255, 1,   5,   255, 255, 255, 5,   255, 3,   0};
static const uint8_t ROT_GHOST[8] = {14, 14, 255, 12, 13, 255, 13, 12};

static inline uint8_t rotation(const uint32_t *v)
{
  uint8_t r;
  if (v[3] == TR_GHOST) {
    r = ROT_GHOST[(v[0] < v[1]) | (v[0] < v[2]) << 1 | (v[1] < v[2]) << 2];
  } else {
    r = ROT_REAL[(v[0] < v[1]) | (v[0] < v[2]) << 1 | (v[0] < v[3]) << 2 | (v[1] < v[2]) << 3 |
                 (v[1] < v[3]) << 4 | (v[2] < v[3]) << 5];
  }
  return r != 255 ? r : rotation_slow(v);
}

/* A tet in the sort: its canonical slots 1..3 (slot 0 is the bucket) and old slot. The
 * records of a bucket are contiguous, so its sort touches one short run of memory. */
typedef struct skey {
  uint32_t v[3];
  uint32_t t;
} skey;

static int skey_cmp(const void *a, const void *b)
{
  const skey *x = a, *y = b;
  for (int j = 0; j < 3; j++)
    if (x->v[j] != y->v[j])
      return x->v[j] < y->v[j] ? -1 : 1;
  return 0;
}

/* skey_cmp(x, y) < 0 with the first two vertices in one comparison */
static inline int skey_less(const skey *x, const skey *y)
{
  const uint64_t a = (uint64_t)x->v[0] << 32 | x->v[1], b = (uint64_t)y->v[0] << 32 | y->v[1];
  return a < b || (a == b && x->v[2] < y->v[2]);
}

/* One thread's share of each phase: a range of old slots (phases A, B, D) and a range of
 * buckets (phase C). cnt: its count of each bucket (A), then where its next record of
 * each bucket goes (B). */
typedef struct cjob {
  struct tr_mesh *m;
  uint64_t *nr; /* per old slot: (bucket, then new slot) << 8 | rotation; NR_NONE: free */
  uint32_t *end, *cnt, *tn;
  const uint32_t *order; /* vertex id map (NULL: none) */
  uint32_t *v2t;         /* C: the last new slot of each vertex in this job's range */
  skey *sk;
  uint32_t nv, t0, t1;
  uint32_t v0, v1; /* A: the range of m->v2t it clears (its own v2t, if not that, whole) */
  size_t f0, f1;   /* D: the range of flags it clears */
  size_t b0, b1;
  int phase;
} cjob;

/* A: the rotation and bucket of each live tet (in nr, for now), counted. */
static void phase_count(cjob *J)
{
  const struct tr_mesh *m = J->m;
  /* the clearing of the v2t arrays for C, here to spread it (and the first touch of
   * a thread's own array) over the threads */
  for (uint32_t i = J->v0; i < J->v1; i++)
    m->v2t[i] = TR_NONE;
  if (J->v2t != m->v2t)
    for (uint32_t i = 0; i < J->nv; i++)
      J->v2t[i] = TR_NONE;
  for (uint32_t t = J->t0; t < J->t1; t++) {
    const uint32_t *v = m->tv + 4 * (size_t)t;
    if (v[0] == TR_NONE) {
      J->nr[t] = NR_NONE;
      continue;
    }
    const uint8_t r = rotation(v);
    const uint32_t b = (r < 12 ? 0 : J->nv) + v[PERM[r][0]];
    J->nr[t] = (uint64_t)b << 8 | r;
    J->cnt[b]++;
  }
}

/* B: each live tet's record into its bucket. */
static void phase_scatter(cjob *J)
{
  const struct tr_mesh *m = J->m;
  for (uint32_t t = J->t0; t < J->t1; t++) {
    /* the bucket counter and the record's place are random: start the counter's miss
     * two distances ahead, the record's (where it would go if nothing came between)
     * one distance ahead, once the counter is in cache */
    if (t + 2 * AHEAD < J->t1 && J->nr[t + 2 * AHEAD] != NR_NONE)
      TR_PREFETCH(&J->cnt[J->nr[t + 2 * AHEAD] >> 8]);
    if (t + AHEAD < J->t1 && J->nr[t + AHEAD] != NR_NONE)
      TR_PREFETCH_W(&J->sk[J->cnt[J->nr[t + AHEAD] >> 8]]);
    if (J->nr[t] != NR_NONE) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      const uint8_t *p = PERM[J->nr[t] & 255];
      skey *k = &J->sk[J->cnt[J->nr[t] >> 8]++];
      k->v[0] = v[p[1]];
      k->v[1] = v[p[2]];
      k->v[2] = v[p[3]];
      k->t = t;
    }
  }
}

/* C: each bucket sorted by the other three vertices (J->end[b]: the end of bucket b);
 * then each record, in order, becomes its tet's new slot: the new slot goes to nr,
 * the four (mapped) vertices over the record. */
static void phase_sort(cjob *J)
{
  skey *sk = J->sk;
  const uint32_t *order = J->order;
  uint32_t *v2t = J->v2t;
  uint64_t *nr = J->nr;
  const uint32_t nv = J->nv, rend = J->b1 > J->b0 ? J->end[J->b1 - 1] : 0;
  uint32_t lo = J->b0 ? J->end[J->b0 - 1] : 0;
  for (size_t b = J->b0; b < J->b1; b++) {
    const uint32_t hi = J->end[b];
    if (hi - lo > 32) {
      qsort(sk + lo, hi - lo, sizeof *sk, skey_cmp);
    } else {
      for (uint32_t i = lo + 1; i < hi; i++) {
        const skey x = sk[i];
        uint32_t j = i;
        while (j > lo && skey_less(&x, &sk[j - 1])) {
          sk[j] = sk[j - 1];
          j--;
        }
        sk[j] = x;
      }
    }
    if (hi == lo)
      continue; /* also the last bucket, nv + nv, whose vertex does not exist */
    const int ghost = b >= nv;
    const uint32_t v0 = (uint32_t)(ghost ? b - nv : b);
    const uint32_t w0 = order ? order[v0] : v0;
    for (uint32_t i = lo; i < hi; i++) {
      const skey k = sk[i];
      /* nr[k.t] is a random read-modify-write (the old slots of a bucket are scattered):
       * start the miss of a later record's entry (in a later bucket of this job's range:
       * not sorted yet, but its old slot all the same; past the range, none) */
      if (i + AHEAD < rend) {
        const skey *a = &sk[i + AHEAD];
        TR_PREFETCH_W(&nr[a->t]);
        /* and the v2t entries it will set (input indices: random on a random input) */
        if (order)
          for (int j = 0; j < 3; j++)
            TR_PREFETCH_W(&v2t[order[a->v[j] < nv ? a->v[j] : 0]]);
      }
      nr[k.t] = (uint64_t)i << 8 | (nr[k.t] & 255);
      skey w = {{w0, k.v[0], k.v[1]}, k.v[2]};
      if (order) {
        w.v[1] = order[w.v[1]];
        w.v[2] = order[w.v[2]];
        w.t = ghost ? TR_GHOST : order[w.t];
      }
      sk[i] = w;
      v2t[w.v[0]] = v2t[w.v[1]] = v2t[w.v[2]] = i;
      if (!ghost)
        v2t[w.t] = i;
    }
    lo = hi;
  }
}

/* D: the neighbours of each tet written to its new slot, in old slot order (the reads
 * stream, the writes go to one line per tet). */
static void phase_write(cjob *J)
{
  const uint32_t *otn = J->m->tn;
  const uint64_t *nr = J->nr;
  uint32_t *tn = J->tn;
  if (J->f1 > J->f0) /* the flags cleared here, spread over the threads */
    memset(J->m->flags + J->f0, 0, J->f1 - J->f0);
  for (uint32_t t = J->t0; t < J->t1; t++) {
    /* the four neighbour entries of nr are random reads: start those of a later live
     * tet (the old tn streams; a free slot's tn is not a neighbour list) */
    if (t + AHEAD < J->t1 && nr[t + AHEAD] != NR_NONE) {
      const uint32_t *ta = otn + 4 * (size_t)(t + AHEAD);
      for (int j = 0; j < 4; j++)
        TR_PREFETCH(&nr[ta[j] >> 2]);
      TR_PREFETCH_W(&tn[4 * (size_t)(nr[t + AHEAD] >> 8)]); /* its new slot: random too */
    }
    const uint64_t x = nr[t];
    if (x == NR_NONE)
      continue;
    const uint32_t o = (uint32_t)(x >> 8);
    const uint8_t *p = PERM[x & 255];
    for (int j = 0; j < 4; j++) {
      const uint32_t c = otn[4 * (size_t)t + p[j]];
      const uint64_t y = nr[c >> 2]; /* slot and rotation in one load: one miss */
      tn[4 * (size_t)o + j] = 4 * (uint32_t)(y >> 8) + INV[y & 255][c & 3];
    }
  }
}

static void *phase_run(void *arg)
{
  cjob *J = arg;
  switch (J->phase) {
  case 0: phase_count(J); break;
  case 1: phase_scatter(J); break;
  case 2: phase_sort(J); break;
  default: phase_write(J); break;
  }
  return NULL;
}

/* Runs phase `phase` of every job, job 0 on the calling thread; a job whose thread
 * cannot start runs here too, after the others (the phases' results do not depend on
 * which thread ran a job). */
static void run_phase(cjob *J, int nth, int phase)
{
  pthread_t th[CANON_MAX_THREADS];
  int started[CANON_MAX_THREADS] = {0};
  for (int j = 0; j < nth; j++)
    J[j].phase = phase;
  for (int j = 1; j < nth; j++)
    started[j] = pthread_create(&th[j], NULL, phase_run, &J[j]) == 0;
  phase_run(&J[0]);
  for (int j = 1; j < nth; j++) {
    if (started[j])
      pthread_join(th[j], NULL);
    else
      phase_run(&J[j]);
  }
}

tr_status tr_delaunay_canonical(struct tr_mesh *m)
{
  return tr_delaunay_canonical_map(m, 1, NULL);
}

tr_status tr_delaunay_canonical_threads(struct tr_mesh *m, int nthreads)
{
  return tr_delaunay_canonical_map(m, nthreads, NULL);
}

tr_status tr_delaunay_canonical_map(struct tr_mesh *m, int nthreads, const uint32_t *order)
{
  const uint32_t nt = m->nt, nv = m->nv;
  const size_t nb = 2 * (size_t)nv + 1; /* buckets: real by first vertex, then ghosts */
  /* a thread's counts and v2t cost 12 bytes per vertex: not worth it for a small mesh */
  int nth = nthreads < 1 ? 1 : nthreads > CANON_MAX_THREADS ? CANON_MAX_THREADS : nthreads;
  if (nt / 65536u < (uint32_t)nth)
    nth = nt / 65536u ? (int)(nt / 65536u) : 1;
  uint64_t *nr = malloc((nt ? nt : 1) * sizeof *nr);
  uint32_t *end = malloc(nb * sizeof *end);
  uint32_t *cnt = calloc(nb * (size_t)nth, sizeof *cnt);
  uint32_t *loc = nth > 1 ? malloc((size_t)(nth - 1) * (nv ? nv : 1) * sizeof *loc) : NULL;
  /* the records, then the new tv: room for cap_t tets */
  skey *sk = malloc((m->cap_t ? m->cap_t : 1) * sizeof *sk);
  tr_status s = TR_OK;
  if (!nr || !end || !cnt || !sk || (nth > 1 && !loc)) {
    s = tr_error(TR_ERR_NOMEM, "out of memory ordering %u tets", nt);
    goto done;
  }
  /* untouched yet (calloc's fresh mapping too): huge pages for the random accesses */
  tr_advise_hugepages(nr, (size_t)nt * sizeof *nr);
  tr_advise_hugepages(sk, (size_t)m->cap_t * sizeof *sk);
  tr_advise_hugepages(cnt, nb * (size_t)nth * sizeof *cnt);
  tr_advise_hugepages(end, nb * sizeof *end);
  if (loc)
    tr_advise_hugepages(loc, (size_t)(nth - 1) * nv * sizeof *loc);
  _Static_assert(sizeof(skey) == 4 * sizeof(uint32_t), "a record is a tv entry");
  cjob J[CANON_MAX_THREADS];
  for (int j = 0; j < nth; j++)
    J[j] = (cjob){.m = m, .nr = nr, .end = end,
                  .cnt = cnt + nb * (size_t)j, .order = order, .sk = sk, .nv = nv,
                  .v2t = j ? loc + (size_t)(j - 1) * nv : m->v2t,
                  .t0 = (uint32_t)((uint64_t)nt * (uint32_t)j / (uint32_t)nth),
                  .t1 = (uint32_t)((uint64_t)nt * (uint32_t)(j + 1) / (uint32_t)nth),
                  .v0 = (uint32_t)((uint64_t)nv * (uint32_t)j / (uint32_t)nth),
                  .v1 = (uint32_t)((uint64_t)nv * (uint32_t)(j + 1) / (uint32_t)nth),
                  .f0 = (size_t)m->cap_t * (size_t)j / (size_t)nth,
                  .f1 = (size_t)m->cap_t * (size_t)(j + 1) / (size_t)nth};
  STAT_LAP(NULL);
  run_phase(J, nth, 0);
  STAT_LAP("canon count");
  /* bucket b holds the records of thread 0, then 1, ...: cnt becomes where each
   * thread's next record of b goes, end[b] the end of b */
  uint32_t run = 0;
  for (size_t b = 0; b < nb; b++) {
    for (int j = 0; j < nth; j++) {
      const uint32_t c = J[j].cnt[b];
      J[j].cnt[b] = run;
      run += c;
    }
    end[b] = run;
  }
  const uint32_t nlive = run;
  run_phase(J, nth, 1);
  STAT_LAP("canon scatter");
  /* the buckets cut into runs of about nlive / nth records */
  size_t b = 0;
  for (int j = 0; j < nth; j++) {
    J[j].b0 = b;
    const uint64_t want = (uint64_t)nlive * (uint32_t)(j + 1) / (uint32_t)nth;
    while (b < nb && (j == nth - 1 || end[b] <= want))
      b++;
    J[j].b1 = b;
  }
  run_phase(J, nth, 2);
  STAT_LAP("canon sort");
  /* the old tv was last read by the scatter: the new tn goes there */
  for (int j = 0; j < nth; j++)
    J[j].tn = m->tv;
  run_phase(J, nth, 3);
  STAT_LAP("canon write");
  free(m->tn);
  m->tn = m->tv;
  m->tv = (uint32_t *)sk;
  sk = NULL;
  m->nt = nlive;
  m->free_head = TR_NONE;
  m->nfree = 0;
  /* v2t: the last slot of each vertex; a later range's record is a later slot */
  for (int j = 1; j < nth; j++)
    for (uint32_t i = 0; i < nv; i++)
      if (J[j].v2t[i] != TR_NONE)
        m->v2t[i] = J[j].v2t[i];
done:
  free(nr);
  free(end);
  free(cnt);
  free(loc);
  free(sk);
  return s;
}
