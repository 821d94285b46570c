/* Transparent huge pages for the large arrays of the Delaunay build (tet store, points,
 * sort and canonical-order buffers). */
#ifndef TR_HUGEPAGE_H
#define TR_HUGEPAGE_H

#include <stddef.h>

/* Asks the kernel to back the whole 2 MB pages inside [p, p + bytes) with huge pages
 * when they are first touched (Linux madvise MADV_HUGEPAGE; elsewhere, or below 2 MB, a
 * no-op). A hint: nothing depends on whether it is taken, so outputs stay the same. */
void tr_advise_hugepages(void *p, size_t bytes);

#endif
