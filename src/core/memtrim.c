/* Why: glibc's malloc keeps freed chunks in its heap (brk) and returns only the top of it
 * to the kernel on its own. Blocks up to its dynamic mmap threshold (up to 32 MB once a
 * large block was freed) live there, so refinement, which allocates and frees hundreds of
 * megabytes of queues and scratch over the run, ended with 120 MB of free but resident
 * heap on CGAL's elephant at 2.1 million tets (272 MB resident, 152 MB in use), and the
 * sliver stage's peak came on top of it. malloc_trim(0) also releases the free pages in
 * the middle of the heap (madvise), not only its top. */
#include "memtrim.h"

#include <stdlib.h> /* features.h: __GLIBC__ */

#if defined(__GLIBC__)
#include <malloc.h>
#endif

void tr_release_free_memory(void)
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}
