#define _DEFAULT_SOURCE /* sbrk, madvise */
/* The command's heap policy (cli.h: tr_cli_heap_setup).
 *
 * Why: on CGAL's sample models a fifth of the command's CPU time was the kernel's, nearly
 * all of it page faults (refined_elephant: 19k minor faults for a 41 MB peak). glibc's
 * default policy serves big blocks by mmap and gives freed memory back (munmap, heap
 * trimming), so every stage's arrays fault their pages in again; and each fault maps one
 * 4 KiB page. A one-shot batch process keeps what it freed for the next stage, and its
 * heap asks for transparent huge pages where the kernel leaves that to the program
 * (/sys/kernel/mm/transparent_hugepage/enabled = madvise): 19k faults -> under 1k, the
 * CPU of the big models down by a fifth (the same as GLIBC_TUNABLES=glibc.malloc.hugetlb=1
 * with MALLOC_MMAP_THRESHOLD_ and MALLOC_TRIM_THRESHOLD_, which a program cannot set for
 * itself). The library never does this: it is the host program's choice.
 *
 * Nothing here changes what is computed: allocation addresses never reach an output (the
 * outputs are byte-identical with and without it). Elsewhere than glibc on Linux it does
 * nothing. */
#include "cli.h"

#if defined(__linux__) && defined(__GLIBC__)
#include <limits.h>
#include <malloc.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

/* Blocks under this come from the heap (glibc's largest allowed value, 64-bit). */
#define TR_HEAP_MMAP_THRESHOLD (32 << 20)
/* Room the first heap extension reserves (virtual: a page costs only once touched); the
 * huge-page advice covers it. Beyond it the heap grows with ordinary pages. */
#define TR_HEAP_RESERVE (256u << 20)
#define TR_HEAP_HUGE_PAGE ((uintptr_t)2 << 20)

void tr_cli_heap_setup(void)
{
  /* any of these also turns glibc's dynamic threshold off: all three are set */
  if (!mallopt(M_MMAP_THRESHOLD, TR_HEAP_MMAP_THRESHOLD) || !mallopt(M_TRIM_THRESHOLD, INT_MAX))
    return;
  uintptr_t b0 = (uintptr_t)sbrk(0);
  if (b0 == (uintptr_t)-1 || !mallopt(M_TOP_PAD, (int)TR_HEAP_RESERVE))
    return;
  /* a block larger than what is left at the heap's top makes malloc extend the heap by
   * the block and the pad at once: the heap's address range is then known */
  void *p = malloc(TR_HEAP_HUGE_PAGE);
  uintptr_t b1 = (uintptr_t)sbrk(0);
  free(p);
  /* later extensions pad by glibc's default again, not by the reserve */
  mallopt(M_TOP_PAD, 128 << 10);
#ifdef MADV_HUGEPAGE
  uintptr_t lo = (b0 + TR_HEAP_HUGE_PAGE - 1) & ~(TR_HEAP_HUGE_PAGE - 1);
  uintptr_t hi = b1 & ~(TR_HEAP_HUGE_PAGE - 1);
  if (p && b1 != (uintptr_t)-1 && hi > lo)
    (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE); /* advice: failure changes nothing */
#endif
}
#else
void tr_cli_heap_setup(void)
{
}
#endif
