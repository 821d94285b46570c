/* Transparent huge pages for the Delaunay build's large arrays. Every 4 KB page of a
 * fresh allocation costs one page fault when first touched; in this VM a fault costs
 * ~8 us (kernel entry with page-table isolation, paravirtual interrupt toggling), and
 * the faults of the tet store, the points and the canonical order's arrays were a
 * quarter of the process CPU time on 10^6 points (sys 1.06 s of 3.95 s; 128k faults).
 * A 2 MB page takes one fault for 512 small ones. Kernels whose THP mode is "madvise"
 * (a common default) only give huge pages to ranges marked MADV_HUGEPAGE; "always"
 * gives them anyway, "never" ignores the advice. Only a hint: failure changes nothing,
 * and the memory's contents and the results never depend on it. */
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
