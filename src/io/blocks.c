/* Block-parallel writing of a file section (blocks.h).
 *
 * Blocks are handed out in increasing order under one mutex, and a thread writes its
 * block only when the count of written blocks reaches it. A thread that waits has only
 * earlier blocks ahead of it, each held by a thread that is formatting or writing it, so
 * the order cannot deadlock, whatever threads started: the threads come from the Delaunay
 * stage's job runner (tr_dt_run_jobs), which runs a job whose thread could not start on
 * the calling thread after job 0 -- by then every block is handed out, and that job finds
 * nothing to do. The writing itself stays in order on one FILE: text is formatted much
 * slower than the kernel copies it, so formatting is what the threads share. */
#include <pthread.h>
#include <stdlib.h>

#include "blocks.h"
#include "write.h"
#include "delaunay/delaunay.h"

#define MAX_THREADS 64
#define SLACK 32 /* past the last record: tr_io_fmt_double's NUL */

typedef struct shared {
  FILE *f;
  uint64_t n, nblocks;
  tr_io_block_fn fn;
  const void *ctx;
  pthread_mutex_t mu;
  pthread_cond_t cv;
  uint64_t next;    /* the next block to hand out */
  uint64_t written; /* blocks written so far */
} shared;

typedef struct job {
  shared *S;
  char *buf;
} job;

static void *run(void *arg)
{
  job *J = arg;
  shared *S = J->S;
  for (;;) {
    pthread_mutex_lock(&S->mu);
    uint64_t b = S->next;
    if (b < S->nblocks)
      S->next++;
    pthread_mutex_unlock(&S->mu);
    if (b >= S->nblocks)
      return NULL;
    uint64_t i0 = b * TR_IO_BLOCK, i1 = i0 + TR_IO_BLOCK < S->n ? i0 + TR_IO_BLOCK : S->n;
    char *end = S->fn(S->ctx, i0, i1, J->buf);
    pthread_mutex_lock(&S->mu);
    while (S->written != b)
      pthread_cond_wait(&S->cv, &S->mu);
    pthread_mutex_unlock(&S->mu);
    /* alone on f until `written` moves on: the others wait above */
    fwrite(J->buf, 1, (size_t)(end - J->buf), S->f);
    pthread_mutex_lock(&S->mu);
    S->written++;
    pthread_cond_broadcast(&S->cv);
    pthread_mutex_unlock(&S->mu);
  }
}

int tr_io_thread_count(int threads) { return tr_delaunay_thread_count(threads < 0 ? 1 : threads); }

tr_status tr_io_write_blocks(FILE *f, uint64_t n, size_t max_bytes, tr_io_block_fn fn,
                             const void *ctx, int threads)
{
  if (n == 0)
    return TR_OK;
  uint64_t nblocks = (n + TR_IO_BLOCK - 1) / TR_IO_BLOCK;
  int nth = threads < 1 ? 1 : threads > MAX_THREADS ? MAX_THREADS : threads;
  if ((uint64_t)nth > nblocks)
    nth = (int)nblocks;
  size_t size = (size_t)(n < TR_IO_BLOCK ? n : TR_IO_BLOCK) * max_bytes + SLACK;
  job J[MAX_THREADS];
  for (int j = 0; j < nth; j++)
    if (!(J[j].buf = malloc(size))) {
      while (j--)
        free(J[j].buf);
      return tr_error(TR_ERR_NOMEM, "out of memory for %d output buffers of %zu bytes", nth,
                      size);
    }
  if (nth == 1) {
    for (uint64_t i0 = 0; i0 < n; i0 += TR_IO_BLOCK) {
      char *end = fn(ctx, i0, i0 + TR_IO_BLOCK < n ? i0 + TR_IO_BLOCK : n, J[0].buf);
      fwrite(J[0].buf, 1, (size_t)(end - J[0].buf), f);
    }
    free(J[0].buf);
    return TR_OK;
  }
  shared S = {f, n, nblocks, fn, ctx, PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0, 0};
  for (int j = 0; j < nth; j++)
    J[j].S = &S;
  tr_dt_run_jobs(run, J, sizeof *J, nth);
  pthread_mutex_destroy(&S.mu);
  pthread_cond_destroy(&S.cv);
  for (int j = 0; j < nth; j++)
    free(J[j].buf);
  return TR_OK;
}
