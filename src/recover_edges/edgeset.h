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
 * It is the edge-keyed face of the shared vertex-tuple map (core/vtmap.h): the same
 * hashing and growth, under the names the recovery stages read best.
 */
#ifndef TR_RECOVER_EDGES_EDGESET_H
#define TR_RECOVER_EDGES_EDGESET_H

#include <stdint.h>

#include "core/status.h"
#include "core/vtmap.h"

typedef struct tr_edgeset {
  tr_vtmap m; /* arity 2, keys {min, max} */
} tr_edgeset;

#define TR_EDGESET_NONE TR_VTMAP_NONE

static inline void tr_edgeset_free(tr_edgeset *s) { tr_vtmap_free(&s->m); }
/* Inserts {u,v} -> val; an existing entry keeps its first value. */
static inline tr_status tr_edgeset_put(tr_edgeset *s, uint32_t u, uint32_t v, uint32_t val)
{
  uint32_t k[2];
  tr_vtkey_edge(u, v, k);
  return tr_vtmap_put(&s->m, 2, k, val, NULL);
}
/* The value of {u,v}, TR_EDGESET_NONE if absent. s may be NULL (empty). */
static inline uint32_t tr_edgeset_get(const tr_edgeset *s, uint32_t u, uint32_t v)
{
  uint32_t k[2];
  tr_vtkey_edge(u, v, k);
  return s ? tr_vtmap_get(&s->m, 2, k) : TR_EDGESET_NONE;
}

#endif
