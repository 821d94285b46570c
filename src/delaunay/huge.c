/* Transparent huge pages for the Delaunay build's large arrays. Two costs of 4 KB pages:
 * every page of a fresh allocation faults when first touched (in this VM ~8 us a fault:
 * kernel entry with page-table isolation, paravirtual interrupt toggling; 128k faults
 * on 10^6 points, a quarter of the process CPU time), and the build's random accesses
 * to the tet store, the points and the tags take a TLB miss on most tets. A 2 MB page
 * takes one fault for 512 small ones and one TLB entry for them. On 10^6 uniform points
 * (interleaved runs, loaded machine) the process CPU time went 4.5-4.9 -> 3.1-3.9 s with
 * one thread and 4.7-6.0 -> 3.8-4.2 s with two; faults 128k -> 15k, and the user time
 * fell by a third as well as the system time (fewer TLB misses, maybe fewer faults of
 * the host behind the guest's: this VM has no hardware counters to tell). Kernels whose THP
 * mode is "madvise" (a common default) only give huge pages to ranges marked
 * MADV_HUGEPAGE; "always" gives them anyway, "never" ignores the advice. Only a hint:
 * failure changes nothing, and the contents and results never depend on it. */
#if defined(__linux__)
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE */
#include <sys/mman.h>
#include <unistd.h>
#endif
#include <stdint.h>

#include "huge.h"

void tr_dt_advise_huge(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (!p || bytes < ((size_t)4 << 20))
    return;
  /* the whole pages of the block, not only its 2 MB-aligned part: a large block is a
   * mapping of its own, and advising part of it splits it in two, after which realloc
   * cannot move it with mremap and copies it instead (faulting in every page of the
   * copy: 60k faults when par.c grew the store on 10^6 points). The kernel gives huge
   * pages to the aligned part anyway. */
  const long pg = sysconf(_SC_PAGESIZE);
  if (pg <= 0)
    return;
  const uintptr_t mask = (uintptr_t)pg - 1;
  const uintptr_t a = (uintptr_t)p & ~mask, b = ((uintptr_t)p + bytes + mask) & ~mask;
  (void)madvise((void *)a, b - a, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}
