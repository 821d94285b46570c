/* Triangle edges grouped by their undirected key, the first step of every adjacency
 * question the input stages ask (manifoldness, orientation, cells, smoothing). */
#ifndef TR_CORE_EDGESORT_H
#define TR_CORE_EDGESORT_H

#include <stdint.h>

#include "core/status.h"

/* slots[0..3*ntris) = the edge slots of the triangles (slot 3t+k is the directed edge
 * tris[3t+k] -> tris[3t+(k+1)%3]) ordered by (min, max) of the two vertex ids, equal keys
 * in increasing slot order: what a stable comparison sort of 0..3n-1 by that key gives,
 * by two stable counting passes in O(ntris + nv). Every id must be < nv. */
tr_status tr_edge_slots_sorted(const uint32_t *tris, uint32_t ntris, uint32_t nv,
                               uint32_t *slots);

#endif
