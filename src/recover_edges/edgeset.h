/* A hash map from undirected mesh edges {u,v} to a uint32 value, used by the edge
 * recovery stage as the set of constraint edges: every mesh edge that is (a piece of) an
 * input edge, mapped to that input edge's index.
 *
 * Why it exists: Swap44 deletes the edge CD it swaps away, and a Steiner point on a cut
 * edge splits it. Neither may happen to a recovered input edge. In a valid PLC no input
 * edge crosses another, so this never triggers; the set turns an invalid input (crossing
 * edges) into a refused swap and a TR_ERR_SELF_INTERSECT naming both edges instead of a
 * silently destroyed constraint.
 *
 * Open addressing with linear probing and a fixed multiplicative hash: no seed, so runs
 * are reproducible. Entries are never removed (a stale entry only makes a check more
 * conservative).
 */
#ifndef TR_RECOVER_EDGES_EDGESET_H
#define TR_RECOVER_EDGES_EDGESET_H

#include <stdint.h>

#include "core/status.h"

typedef struct tr_edgeset {
  uint64_t *key; /* (min << 32 | max) + 1; 0 = empty slot */
  uint32_t *val;
  uint32_t n, cap; /* cap is a power of two or 0 */
} tr_edgeset;

void tr_edgeset_free(tr_edgeset *s);
/* Inserts {u,v} -> val; an existing entry keeps its first value. */
tr_status tr_edgeset_put(tr_edgeset *s, uint32_t u, uint32_t v, uint32_t val);
/* The value of {u,v}, TR_EDGESET_NONE if absent. s may be NULL (empty). */
#define TR_EDGESET_NONE UINT32_MAX
uint32_t tr_edgeset_get(const tr_edgeset *s, uint32_t u, uint32_t v);

#endif
