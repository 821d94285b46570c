/* Huge-page advice for large arrays of the Delaunay build (huge.c). */
#ifndef TR_DT_HUGE_H
#define TR_DT_HUGE_H

#include <stddef.h>

/* Asks the kernel to back the untouched pages of [p, p + bytes) by 2 MB pages (Linux
 * transparent huge pages; elsewhere, or below 4 MB, nothing). Call it before the first
 * touch: pages already faulted in stay small. */
void tr_dt_advise_huge(void *p, size_t bytes);

#endif
