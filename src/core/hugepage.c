/* Why: the Delaunay build reads its tets, neighbours and points at random over hundreds
 * of megabytes (the walk, the cavity search, the canonical order's scatter). With 4 KB
 * pages nearly every such access also misses the TLB, and each page costs a fault when it
 * is first written. Most Linux systems enable transparent huge pages only for regions
 * that ask (the "madvise" mode), so the builder asks, for its large arrays: on 10^6
 * uniform points the 1-thread build's process CPU time fell by 25-30% (bench/delaunay). The
 * memory must not have been touched yet for a page to be taken huge at its first fault
 * (khugepaged may still collapse touched ones later); the allocations here are fresh
 * mappings of malloc's, so only their first page holds malloc's header. */
#define _DEFAULT_SOURCE /* madvise */
#include "hugepage.h"

#include <stdint.h>
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

void tr_advise_hugepages(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const uintptr_t huge = (uintptr_t)1 << 21;
  if (!p || bytes < huge)
    return;
  /* the whole pages of the block, not only its 2 MB-aligned middle: a large block is a
   * mapping of its own, and advising part of it splits it in two, after which realloc
   * cannot move it with mremap and copies it instead (faulting in every page of the
   * copy: 60k faults when par.c grew the store on 10^6 points). The kernel gives huge
   * pages to the aligned part anyway. */
  const long pg = sysconf(_SC_PAGESIZE);
  if (pg <= 0)
    return;
  const uintptr_t mask = (uintptr_t)pg - 1;
  const uintptr_t a = (uintptr_t)p & ~mask, e = ((uintptr_t)p + bytes + mask) & ~mask;
  (void)madvise((void *)a, e - a, MADV_HUGEPAGE); /* a hint: failure changes nothing */
#else
  (void)p;
  (void)bytes;
#endif
}
