/* Rounds of parallel circumcentre insertion for the refinement loop (refine.c, run),
 * with deterministic reservations (Blelloch, Fineman, Gibbons, Shun 2012, "Internally
 * deterministic parallel algorithms can be fast").
 *
 * Off by default; with par.round_min (tr_options.refine_rounds, --refine-rounds N) used
 * while at least that many bad tets are queued and no encroached piece is, whatever the
 * thread count: the mesh is then the same for any number of threads (not the one made
 * without rounds). Off, because they cost more CPU than they save so far (elephant.off,
 * docs/refinement.md "Parallel refinement"). A round:
 *  1. (serial) the next bad tets of the queue, in queue order, up to RF_ROUND_K of them;
 *     a dead or changed tet is dropped as the loop drops it; a tet with a vertex within
 *     two faces of one taken before it in this round waits (at the queue's back): its
 *     cavity would most likely lose to that one's;
 *  2. (parallel, read only) each candidate's circumcentre, its cavity (cavity.c, with
 *     the thread's own scratch) and every test the loop makes before it inserts: a
 *     plain insertion (no piece encroached, no sub-face inside the cavity, the cone
 *     check, the rounding check, every new face paired) is kept with its cavity; a
 *     circumcentre the loop would refuse as too close is counted; anything else goes to
 *     the serial loop's refine_tet after the round;
 *  3. (serial) reservations in candidate order: a candidate wins when none of its cavity
 *     tets, nor the tets across its cavity's faces, is taken by an earlier winner; its
 *     vertex id and the slots of its new tets (its cavity's, then free, then fresh ones)
 *     follow from the winners before it, never from a thread;
 *  4. (parallel) the winners' cones, into disjoint cavities, and the bad-tet tests of
 *     their new tets;
 *  5. (serial, candidate order) the surplus cavity slots freed, v2t, the vertices'
 *     insertion radii and spacings, the new bad tets queued; then the candidates left to
 *     the serial loop; the losers and the waiting tets go to the queue's back.
 * A thread only reads what another thread may write in the same phase when that is its
 * own candidate's, so there is no lock; work is handed out in chunks by an atomic
 * counter, and what a candidate computes does not depend on the thread that runs it.
 *
 * Not in rounds: meshes refined against a size field (sizing.c keeps one walk hint), and
 * the sliver stage's hooks (tr_refine_open_pinned, tr_refine_split_piece). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "delaunay/delaunay.h"
#include "refine/quality.h"
#include "refine/refine_impl.h"

#define RF_ROUND_K 4096u     /* candidates a round takes at most */
#define RF_ROUND_SCAN 4096u  /* queue items a round looks at, at most (elephant.off -a 2e-7:
                                16384 looked at 2.3 times the waits, lost 2.4 times the
                                candidates and cost 9% more CPU; 65536 more still) */
#define RF_ROUND_CHUNK 16u   /* candidates a thread takes at a time */
#define RF_ROUND_RING 2      /* step 1 claims the vertices 1 or 2 faces away from a tet
                                (1: 5.6 times the losers on elephant.off) */

enum { RC_DROP = 0, RC_INSERT, RC_SERIAL, RC_CLOSE, RC_LOSE };

typedef struct rcand {
  uint32_t it[5];  /* the queue item: tet and its vertices */
  uint8_t kind, big;
  double cc[3], emin; /* circumcentre; shortest edge, squared */
  /* RC_INSERT: in the arena of worker `w`, from off: ncav cavity tets, then nbf coned
   * faces (4 * tet + face), then 3 * nbf partners (3 * coned face + side) */
  uint32_t w, ncav, nbf;
  size_t off;
  /* winners: vertex id, first entry in the round's slot list */
  uint32_t pid;
  size_t slot0;
  double r2; /* insertion radius, squared (phase 4) */
} rcand;

typedef struct rround rround;

/* One thread's scratch: its rf_ctx copy's cavity buffers survive between rounds. */
typedef struct rworker {
  rround *R;
  uint32_t id;
  rf_ctx w;
  tr_u32buf arena;
  tr_u32buf scratch; /* one candidate's pairing keys */
  uint32_t *rec;     /* 5 per coned face: a, b, d, outer code, region (phase 4) */
  size_t caprec;
  tr_status st;
  char msg[256]; /* the message of a failure on this thread (messages are per thread) */
  double cpu;    /* this phase's CPU seconds */
} rworker;

struct rround {
  rf_ctx *c;
  rcand *cand;
  uint32_t n, capn;
  uint32_t next; /* the next chunk of candidates (atomic) */
  int phase;
  int nth;
  rworker *wk;
  uint32_t *slots; /* the winners' new tets' slots */
  size_t nslots, capslots;
  uint8_t *bad; /* per slot entry: the new tet is bad */
  size_t capbad;
  tr_u32buf back, surplus;
  /* CPU seconds per step, for -v -v: taking candidates, cavities (parallel, every
   * thread's), reservations, cones and tests (parallel, every thread's), bookkeeping,
   * the serial loop's share */
  double secs[6];
  uint8_t *vmark; /* per vertex: claimed in step 1 (0 at rest) */
  uint32_t capvmark;
  uint64_t kinds[5], deferred; /* candidates by outcome (RC_*), tets that waited */
};

/* CPU seconds of the calling thread: on a loaded machine wall time says little */
static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- phase 2: one candidate, read only ---- */

/* The edges of the new faces through the point, paired: each coned face (a, b, d) gives
 * the faces (b, d, p), (a, d, p), (a, b, p) (faces 0, 1, 2 of the new tet (a, b, d, p));
 * each edge must be shared by exactly two of them, since no sub-face is split. Paired in
 * a small open-addressed table of the edges (3 words each: a, b, side), in the thread's
 * scratch: the serial insertion sorts them (insert.c), which is most of its own cost. */
static tr_status pair_faces(rworker *W, const uint32_t *bf, uint32_t nbf, uint32_t *partner,
                            int *good)
{
  const struct tr_mesh *m = W->w.m;
  static const int ev[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  size_t cap = 16;
  while (cap < 6 * (size_t)nbf)
    cap *= 2;
  tr_u32buf *s = &W->scratch;
  TR_CHECK(tr_u32buf_reserve(s, 3 * cap));
  uint32_t *h = s->a;
  for (size_t i = 0; i < cap; i++)
    h[3 * i] = TR_NONE;
  *good = 1;
  for (uint32_t i = 0; i < nbf && *good; i++) {
    uint32_t t = bf[i] >> 2;
    int k = (int)(bf[i] & 3);
    uint32_t v[3];
    for (int j = 0; j < 3; j++)
      v[j] = m->tv[4 * (size_t)t + tr_face_vtx[k][j]];
    for (int j = 0; j < 3 && *good; j++) {
      uint32_t x = v[ev[j][0]], y = v[ev[j][1]], lo = x < y ? x : y, hi = x < y ? y : x;
      size_t e = (size_t)((lo * 2654435761u) ^ (hi * 40503u)) & (cap - 1);
      while (h[3 * e] != TR_NONE && !(h[3 * e] == lo && h[3 * e + 1] == hi))
        e = (e + 1) & (cap - 1);
      uint32_t me = 3 * i + (uint32_t)j;
      if (h[3 * e] == TR_NONE) {
        h[3 * e] = lo;
        h[3 * e + 1] = hi;
        h[3 * e + 2] = me;
      } else if (h[3 * e + 2] == TR_NONE) {
        *good = 0; /* a third face on the edge */
      } else {
        partner[me] = h[3 * e + 2];
        partner[h[3 * e + 2]] = me;
        h[3 * e + 2] = TR_NONE; /* paired */
      }
    }
  }
  for (size_t e = 0; e < cap && *good; e++)
    if (h[3 * e] != TR_NONE && h[3 * e + 2] != TR_NONE)
      *good = 0; /* an edge of one face only */
  return TR_OK;
}

/* What refine_tet (refine.c) would do with candidate x, up to the insertion; the cavity
 * of a plain insertion is kept in W's arena. */
static tr_status evaluate(rworker *W, rcand *x)
{
  rf_ctx *w = &W->w;
  struct tr_mesh *m = w->m;
  uint32_t t = x->it[0];
  x->kind = RC_SERIAL;
  if (!rf_tet_bad(w, t)) {
    x->kind = RC_DROP;
    return TR_OK;
  }
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double ratio, vol, emin = INFINITY;
  for (int e = 0; e < 6; e++) {
    double d = rf_dist2(m->xyz + 3 * (size_t)v[tr_edge_vtx[e][0]], m->xyz + 3 * (size_t)v[tr_edge_vtx[e][1]]);
    emin = d < emin ? d : emin;
  }
  x->emin = emin;
  if (!tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1], m->xyz + 3 * (size_t)v[2],
                    m->xyz + 3 * (size_t)v[3], &ratio, &vol, NULL, x->cc))
    return TR_OK;
  x->big = (uint8_t)rf_too_big(w, t);
  if (!x->big && rf_forced_by_angle(w, t))
    return TR_OK;
  tr_point p = tr_pt_d(x->cc);
  uint32_t found, blocker;
  TR_CHECK(rf_locate(w, t, &p, &found, &blocker));
  if (found == TR_NONE)
    return TR_OK;
  double cap = rf_sizing_cap(w, t);
  if (!x->big && rf_too_close(w, &found, 1, x->cc, cap)) {
    int maybe = 0;
    if (w->close_splits)
      TR_CHECK(rf_longs_near(w, x->cc, emin, &maybe)); /* built before the round: read only */
    if (!maybe) {
      x->kind = RC_CLOSE;
      return TR_OK;
    }
  }
  int ok = 0;
  w->split_seg = TR_NONE;
  TR_CHECK(rf_cavity(w, found, &p, m->nv, 0, &ok));
  if (!ok)
    return TR_OK;
  int close = !x->big && rf_too_close(w, w->cav.a, w->cav.n, x->cc, cap);
  int plain = 1, any = 0;
  for (size_t i = 0; plain && i < w->cav.n; i++) {
    uint32_t u = w->cav.a[i];
    const uint32_t *q = m->tv + 4 * (size_t)u;
    for (int k = 0; k < 4 && plain; k++) {
      uint32_t f = rf_subface_of(w, q[tr_face_vtx[k][0]], q[tr_face_vtx[k][1]], q[tr_face_vtx[k][2]]);
      if (f == TR_NONE)
        continue;
      uint32_t n = TR_NEIG(m, u, k);
      if (n != TR_NONE && (w->tstate[n] & 1)) /* ST_IN (cavity.c): a split, not plain */
        plain = 0;
      else if (!close) {
        const uint32_t *S = w->sfv + 3 * (size_t)f;
        tr_point a = tr_mesh_point(m, S[0]), b = tr_mesh_point(m, S[1]), d = tr_mesh_point(m, S[2]);
        any = rf_in_equatorial(&a, &b, &d, &p);
        plain = !any;
      }
    }
    for (int e = 0; e < 6 && plain; e++) {
      uint32_t g = rf_subseg_of(w, q[tr_edge_vtx[e][0]], q[tr_edge_vtx[e][1]]);
      if (g == TR_NONE || (close && (!w->close_splits || !rf_close_split(w, g, emin))))
        continue;
      tr_point a = tr_mesh_point(m, w->ssv[2 * (size_t)g]), b = tr_mesh_point(m, w->ssv[2 * (size_t)g + 1]);
      any = rf_in_diametral(&a, &b, &p);
      plain = !any;
    }
  }
  if (plain && close) {
    rf_cavity_release(w);
    x->kind = RC_CLOSE;
    return TR_OK;
  }
  /* the cone check of refine_tet, and the doubles (insert.c) */
  for (size_t i = 0; plain && i < w->bfaces.n; i++) {
    uint32_t u = w->bfaces.a[i] >> 2;
    int k = (int)(w->bfaces.a[i] & 3);
    const double *y[3];
    for (int j = 0; j < 3; j++)
      y[j] = m->xyz + 3 * (size_t)m->tv[4 * (size_t)u + tr_face_vtx[k][j]];
    double r2, v2;
    tr_tet_shape(y[0], y[1], y[2], x->cc, &r2, &v2, NULL, NULL);
    plain = r2 <= 1000 && r2 <= 100 * ratio;
  }
  if (plain)
    plain = rf_cone_admits(m, w->bfaces.a, w->bfaces.n, x->cc);
  tr_status st = TR_OK;
  if (plain) {
    size_t nbf = w->bfaces.n, ncav = w->cav.n, need = ncav + 4 * nbf;
    st = tr_u32buf_reserve(&W->arena, W->arena.n + need);
    if (st == TR_OK) {
      uint32_t *a = W->arena.a + W->arena.n;
      memcpy(a, w->cav.a, ncav * sizeof *a);
      memcpy(a + ncav, w->bfaces.a, nbf * sizeof *a);
      int good = 0;
      st = pair_faces(W, w->bfaces.a, (uint32_t)nbf, a + ncav + nbf, &good);
      if (st == TR_OK && good) {
        x->kind = RC_INSERT;
        x->w = W->id;
        x->off = W->arena.n;
        x->ncav = (uint32_t)ncav;
        x->nbf = (uint32_t)nbf;
        W->arena.n += need;
      }
    }
  }
  rf_cavity_release(w);
  return st;
}

/* ---- phase 4: one winner's cone ---- */

static tr_status cone(rworker *W, rcand *x)
{
  rround *R = W->R;
  rf_ctx *c = R->c;
  struct tr_mesh *m = c->m;
  const uint32_t *bf = R->wk[x->w].arena.a + x->off + x->ncav, *partner = bf + x->nbf;
  const uint32_t *slot = R->slots + x->slot0;
  if (W->caprec < 5 * (size_t)x->nbf) {
    size_t cap = 5 * (size_t)x->nbf * 2;
    uint32_t *r = realloc(W->rec, cap * sizeof *r);
    if (!r)
      return tr_error(TR_ERR_NOMEM, "out of memory for a cone of %u faces", x->nbf);
    W->rec = r;
    W->caprec = cap;
  }
  /* read every coned face before a cavity slot is written over */
  for (uint32_t i = 0; i < x->nbf; i++) {
    uint32_t t = bf[i] >> 2;
    int k = (int)(bf[i] & 3);
    for (int j = 0; j < 3; j++)
      W->rec[5 * i + j] = m->tv[4 * (size_t)t + tr_face_vtx[k][j]];
    W->rec[5 * i + 3] = m->tn[4 * (size_t)t + k];
    W->rec[5 * i + 4] = m->region ? m->region[t] : 0;
  }
  double r2 = x->emin;
  const double *p = m->xyz + 3 * (size_t)x->pid;
  for (uint32_t i = 0; i < x->nbf; i++) {
    uint32_t s = slot[i];
    uint32_t *tv = m->tv + 4 * (size_t)s, *tn = m->tn + 4 * (size_t)s;
    tv[0] = W->rec[5 * i];
    tv[1] = W->rec[5 * i + 1];
    tv[2] = W->rec[5 * i + 2];
    tv[3] = x->pid;
    for (int j = 0; j < 3; j++) {
      uint32_t q = partner[3 * i + (uint32_t)j];
      tn[j] = 4 * slot[q / 3] + q % 3;
      double d = rf_dist2(p, m->xyz + 3 * (size_t)tv[j]);
      r2 = d < r2 ? d : r2;
    }
    uint32_t o = W->rec[5 * i + 3];
    tn[3] = o;
    if (o != TR_NONE)
      m->tn[o] = 4 * s + 3;
    m->flags[s] = 0;
    if (m->region)
      m->region[s] = W->rec[5 * i + 4];
  }
  x->r2 = r2;
  return TR_OK;
}

/* The bad-tet tests of a winner's new tets, right after its cone: a test reads the tet's
 * own vertices and region only, which its own cone wrote (one pass over the cone, while
 * it is in cache, instead of a second phase over every winner). */
static void bad_tests(rworker *W, const rcand *x)
{
  rround *R = W->R;
  for (uint32_t i = 0; i < x->nbf; i++)
    R->bad[x->slot0 + i] = (uint8_t)rf_tet_bad(&W->w, R->slots[x->slot0 + i]);
}

/* ---- threads ---- */

static void *job(void *arg)
{
  rworker *W = arg;
  rround *R = W->R;
  double t0 = now();
  for (;;) {
    uint32_t i0 = __atomic_fetch_add(&R->next, RF_ROUND_CHUNK, __ATOMIC_RELAXED);
    if (i0 >= R->n)
      break;
    uint32_t i1 = i0 + RF_ROUND_CHUNK < R->n ? i0 + RF_ROUND_CHUNK : R->n;
    for (uint32_t i = i0; i < i1 && W->st == TR_OK; i++) {
      rcand *x = R->cand + i;
      if (R->phase == 2)
        W->st = evaluate(W, x);
      else if (R->phase == 4 && x->kind == RC_INSERT) {
        W->st = cone(W, x);
        if (W->st == TR_OK)
          bad_tests(W, x);
      }
    }
  }
  if (W->st != TR_OK)
    snprintf(W->msg, sizeof W->msg, "%s", tr_last_error());
  W->cpu = now() - t0;
  return NULL;
}

/* The scratch fields of the worker's context: its own; everything else is c's. */
static void worker_enter(rworker *W, const rf_ctx *c)
{
  rf_ctx own = W->w;
  W->w = *c;
  W->w.cav = own.cav;
  W->w.init = own.init;
  W->w.bfaces = own.bfaces;
  W->w.stack = own.stack;
  W->w.tmp = own.tmp;
  W->w.newsf = own.newsf;
  W->w.newtets = own.newtets;
  W->w.cnext = own.cnext;
  W->w.tstate = own.tstate;
  W->w.captstate = own.captstate;
  W->w.vcone = own.vcone;
  W->w.vhead = own.vhead;
  W->w.capvcone = own.capvcone;
  W->w.cone_stamp = own.cone_stamp;
  W->w.split_seg = TR_NONE;
  W->w.st = NULL; /* no stats from a thread */
}

static tr_status run_phase(rround *R, int phase)
{
  R->phase = phase;
  R->next = 0;
  for (int j = 0; j < R->nth; j++) {
    worker_enter(&R->wk[j], R->c);
    R->wk[j].st = TR_OK;
  }
  tr_dt_run_jobs(job, R->wk, sizeof *R->wk, R->nth);
  for (int j = 0; j < R->nth; j++)
    R->secs[phase == 2 ? 1 : 3] += R->wk[j].cpu;
  for (int j = 0; j < R->nth; j++)
    if (R->wk[j].st != TR_OK)
      return tr_error(R->wk[j].st, "%s", R->wk[j].msg);
  return TR_OK;
}

void rf_rounds_free(rf_ctx *c)
{
  rround *R = c->rounds;
  if (!R)
    return;
  if (c->par.verbose >= 2)
    fprintf(stderr, "tetrec: refinement rounds, CPU: candidates %.3f s, cavities %.3f s "
            "(parallel), reservations %.3f s, cones %.3f s (parallel), bookkeeping %.3f s, "
            "serial loop %.3f s\n", R->secs[0], R->secs[1], R->secs[2], R->secs[3], R->secs[4],
            R->secs[5]);
  if (c->par.verbose >= 2)
    fprintf(stderr, "tetrec: refinement rounds, candidates: %llu dropped, %llu inserted, %llu "
            "to the serial loop, %llu too close, %llu lost; %llu waited\n",
            (unsigned long long)R->kinds[RC_DROP], (unsigned long long)R->kinds[RC_INSERT],
            (unsigned long long)R->kinds[RC_SERIAL], (unsigned long long)R->kinds[RC_CLOSE],
            (unsigned long long)R->kinds[RC_LOSE], (unsigned long long)R->deferred);
  for (int j = 0; j < R->nth; j++) {
    rworker *W = &R->wk[j];
    tr_u32buf *b[] = {&W->w.cav, &W->w.init, &W->w.bfaces, &W->w.stack, &W->w.tmp,
                      &W->w.newsf, &W->w.newtets, &W->w.cnext, &W->arena, &W->scratch};
    for (size_t i = 0; i < sizeof b / sizeof *b; i++)
      tr_u32buf_free(b[i]);
    free(W->w.tstate);
    free(W->w.vcone);
    free(W->w.vhead);
    free(W->rec);
  }
  free(R->wk);
  free(R->cand);
  free(R->slots);
  free(R->bad);
  free(R->vmark);
  tr_u32buf_free(&R->back);
  tr_u32buf_free(&R->surplus);
  free(R);
  c->rounds = NULL;
}

static tr_status rounds_init(rf_ctx *c)
{
  if (c->rounds)
    return TR_OK;
  rround *R = calloc(1, sizeof *R);
  if (!R)
    return tr_error(TR_ERR_NOMEM, "out of memory for refinement rounds");
  c->rounds = R;
  R->c = c;
  R->nth = c->par.threads > 1 ? (c->par.threads > 64 ? 64 : c->par.threads) : 1;
  R->wk = calloc((size_t)R->nth, sizeof *R->wk);
  R->cand = malloc(RF_ROUND_K * sizeof *R->cand);
  if (!R->wk || !R->cand)
    return tr_error(TR_ERR_NOMEM, "out of memory for refinement rounds");
  R->capn = RF_ROUND_K;
  for (int j = 0; j < R->nth; j++) {
    R->wk[j].R = R;
    R->wk[j].id = (uint32_t)j;
    R->wk[j].w.split_seg = TR_NONE;
  }
  return TR_OK;
}

int rf_round_wanted(const rf_ctx *c)
{
  return c->rounds_on && c->par.round_min && !c->par.sizing &&
         (c->qtet.n - c->htet) / 5 >= c->par.round_min;
}

/* Step 1's claim: the vertices of t and of the tets across its faces (flags in R->vmark),
 * unless one is claimed already. Two bad tets that close have overlapping cavities far
 * more often than not (elephant.off: 4.3 losers per winner when only t and its face
 * neighbours were claimed), and a loser's cavity is work thrown away. */
static int claim(rround *R, uint32_t t, tr_u32buf *marked, tr_status *st)
{
  const struct tr_mesh *m = R->c->m;
  uint32_t v[32];
  int n = 0;
  for (int k = 0; k < 4; k++)
    v[n++] = m->tv[4 * (size_t)t + k];
  for (int k = 0; k < 4; k++) {
    uint32_t o = m->tn[4 * (size_t)t + k];
    if (o == TR_NONE)
      continue;
    uint32_t u = o >> 2;
    v[n++] = m->tv[4 * (size_t)u + (o & 3)]; /* the vertex across face k */
    for (int j = 0; j < 4 && RF_ROUND_RING > 1; j++) { /* and across u's other faces */
      uint32_t q = m->tn[4 * (size_t)u + j];
      if (j != (int)(o & 3) && q != TR_NONE)
        v[n++] = m->tv[4 * (size_t)(q >> 2) + (q & 3)];
    }
  }
  for (int i = 0; i < n; i++)
    if (R->vmark[v[i]])
      return 0;
  for (int i = 0; i < n && *st == TR_OK; i++)
    if (!R->vmark[v[i]]) {
      R->vmark[v[i]] = 1;
      *st = tr_u32buf_push(marked, v[i]);
    }
  return 1;
}

static void unmark_vertices(rround *R, tr_u32buf *marked)
{
  for (size_t i = 0; i < marked->n; i++)
    R->vmark[marked->a[i]] = 0;
  marked->n = 0;
}

static void unmark(struct tr_mesh *m, tr_u32buf *marked)
{
  for (size_t i = 0; i < marked->n; i++)
    m->flags[marked->a[i]] &= (uint8_t)~TR_TF_MARK2;
  marked->n = 0;
}

/* Does winner x's cavity, or a tet across it, hold a tet an earlier winner took? If not,
 * x takes them. */
static int reserve(rround *R, const rcand *x, tr_u32buf *marked, tr_status *st)
{
  struct tr_mesh *m = R->c->m;
  const uint32_t *cav = R->wk[x->w].arena.a + x->off, *bf = cav + x->ncav;
  for (uint32_t i = 0; i < x->ncav; i++)
    if (m->flags[cav[i]] & TR_TF_MARK2)
      return 0;
  for (uint32_t i = 0; i < x->nbf; i++) {
    uint32_t o = m->tn[bf[i]];
    if (o != TR_NONE && (m->flags[o >> 2] & TR_TF_MARK2))
      return 0;
  }
  for (uint32_t i = 0; i < x->ncav && *st == TR_OK; i++) {
    m->flags[cav[i]] |= TR_TF_MARK2;
    *st = tr_u32buf_push(marked, cav[i]);
  }
  for (uint32_t i = 0; i < x->nbf && *st == TR_OK; i++) {
    uint32_t o = m->tn[bf[i]];
    if (o != TR_NONE && !(m->flags[o >> 2] & TR_TF_MARK2)) {
      m->flags[o >> 2] |= TR_TF_MARK2;
      *st = tr_u32buf_push(marked, o >> 2);
    }
  }
  return 1;
}

/* Room for n more slot entries. */
static tr_status slots_room(rround *R, size_t n)
{
  if (R->nslots + n <= R->capslots)
    return TR_OK;
  size_t cap = (R->nslots + n) * 2;
  uint32_t *s = realloc(R->slots, cap * sizeof *s);
  if (s)
    R->slots = s;
  uint8_t *b = realloc(R->bad, cap);
  if (b)
    R->bad = b;
  if (!s || !b)
    return tr_error(TR_ERR_NOMEM, "out of memory for %zu new tets", cap);
  R->capslots = cap;
  return TR_OK;
}

tr_status rf_round(rf_ctx *c, uint64_t room)
{
  TR_CHECK(rounds_init(c));
  rround *R = c->rounds;
  struct tr_mesh *m = c->m;
  if (c->close_splits && !c->longs.built) { /* a thread may only read the grid */
    int maybe;
    TR_CHECK(rf_longs_near(c, m->xyz, 0, &maybe));
  }
  double t0 = now(), t1;
  if (R->capvmark < m->nv) {
    uint32_t cap = m->cap_v > m->nv ? m->cap_v : m->nv;
    uint8_t *vm = realloc(R->vmark, cap);
    if (!vm)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex marks", cap);
    memset(vm + R->capvmark, 0, cap - R->capvmark);
    R->vmark = vm;
    R->capvmark = cap;
  }
  /* 1. candidates */
  uint32_t K = room < RF_ROUND_K ? (uint32_t)room : RF_ROUND_K;
  tr_u32buf *marked = &c->tmp;
  marked->n = 0;
  R->back.n = 0;
  R->n = 0;
  tr_status st = TR_OK;
  for (uint32_t scanned = 0; st == TR_OK && R->n < K && scanned < RF_ROUND_SCAN && c->htet < c->qtet.n;
       scanned++) {
    const uint32_t *it = c->qtet.a + c->htet;
    c->htet += 5;
    if (!(it[0] < m->nt && !tr_tet_is_free(m, it[0]) && !memcmp(m->tv + 4 * (size_t)it[0], it + 1, 4 * sizeof *it)))
      continue;
    if (!claim(R, it[0], marked, &st)) {
      R->deferred++;
      for (int j = 0; j < 5 && st == TR_OK; j++)
        st = tr_u32buf_push(&R->back, it[j]);
      continue;
    }
    rcand *x = R->cand + R->n++;
    memset(x, 0, sizeof *x);
    memcpy(x->it, it, sizeof x->it);
  }
  unmark_vertices(R, marked);
  TR_CHECK(st);
  /* 2. every candidate's cavity, read only */
  for (int j = 0; j < R->nth; j++)
    R->wk[j].arena.n = 0;
  R->secs[0] += now() - t0;
  TR_CHECK(run_phase(R, 2));
  t0 = now();
  /* 3. reservations, vertex ids and slots in candidate order */
  R->nslots = 0;
  R->surplus.n = 0;
  uint32_t nwin = 0;
  size_t extra = 0;
  for (uint32_t i = 0; i < R->n && st == TR_OK; i++) {
    rcand *x = R->cand + i;
    if (x->kind != RC_INSERT)
      continue;
    if (!reserve(R, x, marked, &st)) {
      x->kind = RC_LOSE;
      continue;
    }
    nwin++;
    if (x->nbf > x->ncav)
      extra += x->nbf - x->ncav;
  }
  unmark(m, marked);
  TR_CHECK(st);
  uint64_t fresh = extra > m->nfree ? extra - m->nfree : 0;
  if (m->nt + fresh > m->cap_t) {
    uint64_t cap = (uint64_t)m->cap_t + m->cap_t / 2;
    if (cap < m->nt + fresh)
      cap = m->nt + fresh;
    TR_CHECK(tr_mesh_reserve_tets(m, cap > UINT32_MAX / 4 - 1 ? UINT32_MAX / 4 - 1 : (uint32_t)cap));
  }
  TR_CHECK(tr_mesh_reserve_vertices(m, m->nv + nwin));
  TR_CHECK(rf_vertex_room(c, m->nv + nwin));
  for (uint32_t i = 0; i < R->n; i++) {
    rcand *x = R->cand + i;
    if (x->kind != RC_INSERT)
      continue;
    TR_CHECK(tr_mesh_add_vertex(m, x->cc, &x->pid));
    TR_CHECK(slots_room(R, x->nbf));
    x->slot0 = R->nslots;
    const uint32_t *cav = R->wk[x->w].arena.a + x->off;
    for (uint32_t j = 0; j < x->nbf; j++) {
      uint32_t s;
      if (j < x->ncav)
        s = cav[j];
      else if (m->free_head != TR_NONE) {
        s = m->free_head;
        m->free_head = m->tn[4 * (size_t)s];
        m->nfree--;
      } else
        s = m->nt++;
      R->slots[R->nslots++] = s;
    }
    for (uint32_t j = x->nbf; j < x->ncav; j++)
      TR_CHECK(tr_u32buf_push(&R->surplus, cav[j]));
  }
  /* 4. the cones and the bad-tet tests of their tets */
  R->secs[2] += now() - t0;
  if (nwin)
    TR_CHECK(run_phase(R, 4));
  t0 = now();
  /* 5. in candidate order: the bookkeeping of rf_after_insert, then the rest */
  for (size_t i = 0; i < R->surplus.n; i++)
    tr_tet_free(m, R->surplus.a[i]);
  for (uint32_t i = 0; i < R->n; i++) {
    rcand *x = R->cand + i;
    R->kinds[x->kind]++;
    if (x->kind == RC_CLOSE)
      c->st->skipped_close++;
    if (x->kind == RC_LOSE)
      for (int j = 0; j < 5; j++)
        TR_CHECK(tr_u32buf_push(&R->back, x->it[j]));
    if (x->kind != RC_INSERT)
      continue;
    uint32_t pid = x->pid;
    const double *p = m->xyz + 3 * (size_t)pid;
    c->vkind[pid] = RF_FREE;
    c->vown[pid] = TR_NONE;
    for (uint32_t j = 0; j < x->nbf; j++) {
      uint32_t s = R->slots[x->slot0 + j];
      const uint32_t *v = m->tv + 4 * (size_t)s;
      for (int k = 0; k < 4; k++)
        m->v2t[v[k]] = s;
      for (int k = 0; c->spacing_on && k < 3; k++)
        if (c->vrad[v[k]] > 0) {
          double d = rf_dist2(p, m->xyz + 3 * (size_t)v[k]), *sp = c->vspace + v[k];
          if (!(*sp > 0))
            *sp = c->vrad[v[k]];
          if (d < *sp * *sp)
            *sp = sqrt(d);
        }
    }
    c->vrad[pid] = isfinite(x->r2) ? sqrt(x->r2) : 0;
    if (c->spacing_on)
      c->vspace[pid] = c->vrad[pid];
    c->st->points++;
    c->st->inside++;
    for (uint32_t j = 0; j < x->nbf; j++)
      if (R->bad[x->slot0 + j]) {
        uint32_t s = R->slots[x->slot0 + j];
        TR_CHECK(tr_u32buf_push(&c->qtet, s));
        for (int k = 0; k < 4; k++)
          TR_CHECK(tr_u32buf_push(&c->qtet, m->tv[4 * (size_t)s + k]));
      }
    /* a tet over the volume bound its circumcentre left whole goes back (refine_tet) */
    uint32_t t = x->it[0];
    if (x->big && !tr_tet_is_free(m, t) && !memcmp(m->tv + 4 * (size_t)t, x->it + 1, 4 * sizeof *x->it))
      TR_CHECK(rf_push_tet(c, t));
  }
  c->st->round_points += nwin;
  c->st->rounds++;
  t1 = now();
  R->secs[4] += t1 - t0;
  for (uint32_t i = 0; i < R->n; i++) {
    rcand *x = R->cand + i;
    uint32_t t = x->it[0];
    if (x->kind == RC_SERIAL && !tr_tet_is_free(m, t) &&
        !memcmp(m->tv + 4 * (size_t)t, x->it + 1, 4 * sizeof *x->it) && rf_tet_bad(c, t)) {
      c->st->round_serial++;
      TR_CHECK(rf_refine_tet(c, t));
    }
  }
  R->secs[5] += now() - t1;
  /* the losers and the waiting tets go to the back of the queue: most of them are gone or
   * changed by the time they come up again, which costs a look; put back at the front,
   * they were looked at again round after round (elephant.off: 12 times per candidate) */
  for (size_t i = 0; i < R->back.n; i++)
    TR_CHECK(tr_u32buf_push(&c->qtet, R->back.a[i]));
  return TR_OK;
}
