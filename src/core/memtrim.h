/* Giving freed heap memory back to the system between stages. */
#ifndef TR_MEMTRIM_H
#define TR_MEMTRIM_H

/* Returns the whole free pages inside malloc's heap to the kernel (glibc malloc_trim;
 * elsewhere a no-op). Stages that free more than they keep (refinement's queues and
 * caches) otherwise leave those pages resident: the next stage's allocations land in
 * some of them, and the peak resident size counts all of them. Changes no allocation's
 * content or address, so outputs stay the same. */
void tr_release_free_memory(void);

#endif
