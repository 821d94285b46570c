/* Instantiating a decomposition table (core/dectable.h) on mesh tets, and the pipel
 * record of the paper ("Definition of a pipel").
 *
 * A table addresses its old tets only through vertex NAMES, so the slot order of a mesh
 * tet never matters: the caller binds names to mesh vertex ids (ids[]) and the table's
 * NG(t_j, X) is read as the link of old tet j across the face opposite vertex ids[X].
 *
 * Phi links (faces split by Steiner points): the neighbour across a split face is a
 * pipel of the same pipe (a Steiner point lies on the missing edge, so every tet around
 * its edge or face is cut by the edge). When that pipel is already decomposed, the new
 * tet is glued to the one of its dectets that has the sub-face; otherwise the face is
 * left open (TR_NONE) and glued when that neighbour is decomposed. The old tet's link
 * across a split face is never rewritten by the neighbour, so it still names the
 * neighbour's old id, which is the pipel's iEle.
 */
#ifndef TR_RECOVER_EDGES_DECOMPOSE_H
#define TR_RECOVER_EDGES_DECOMPOSE_H

#include <stdint.h>

#include "core/dectable.h"
#include "mesh/mesh.h"

/* The paper's MAX_DEC_TETS (the largest edge-recovery table, Table 9, has 5). */
#define TR_MAX_DEC_TETS 8

/* Pipel types: type = (second << 2) | first with TR_DEG/TR_NOD/TR_EDG/TR_FAC of
 * predicates/classify.h; bits 4..7: bit 4+k set iff face k (local code) has Z-type. */
#define TR_PIPEL_TYPE(first, second) ((uint8_t)(((second) << 2) | (first)))

typedef struct tr_pipel {
  uint32_t iEle;     /* the tet (its id before decomposition) */
  uint8_t type;      /* see TR_PIPEL_TYPE, plus DType bits */
  uint8_t iCod1, iCod2; /* NCode / ECode / FCode of the entity each point lies on */
  uint32_t iNod1, iNod2; /* mesh vertex ids of the two intersection points (TR_NONE) */
  uint32_t dectets[TR_MAX_DEC_TETS];
  uint8_t nTets;     /* 0 until decomposed */
  uint8_t ghost;     /* 1: a ghost tet whose hull face the edge splits (pipe.c) */
} tr_pipel;

/* The pipel whose iEle is e, or NULL. */
const tr_pipel *tr_pipe_find(const tr_pipel *pipe, uint32_t npipe, uint32_t e);

/* Instantiates table t. old[j] = the mesh tet playing t->old[j]; ids[n] = the mesh
 * vertex of every name n the table uses (the Steiner points already added to the mesh).
 * pipe/npipe: the pipels for Phi links (NULL/0 when the table has none).
 * Every new tet is checked strictly positive with exact predicates BEFORE the mesh is
 * touched: on failure (TR_ERR_INTERNAL) the mesh is unchanged. On success the old tets are
 * freed, out[0..t->nnew) receives the new tets and all NG / INTERNAL / available Phi
 * links are glued. */
tr_status tr_dec_apply(struct tr_mesh *m, const tr_dectable *t, const uint32_t *old,
                       const uint32_t ids[TR_DV_COUNT], const tr_pipel *pipe, uint32_t npipe,
                       uint32_t *out);

/* Relabeling of one mesh tet for a one-tet table: finds an even permutation of the tet's
 * vertices (tv = its 4 vertex ids) to A..D and an assignment of the given Steiner
 * points to the table's Steiner names such that point i lies on the open simplex the
 * table expects. car[i] = the local codes (0..3, any order) of the simplex holding point
 * i, ncar[i] their number, sid[i] its mesh vertex id. If prefer >= 0, labelings where
 * local code `prefer` is A come first. Fixed search order (deterministic). Returns 1 and
 * fills ids[] (A..D and the Steiner names) on success, 0 if the table does not fit. */
int tr_dec_match(const tr_dectable *t, const uint32_t tv[4], int nst, const uint8_t car[][4],
                 const uint8_t *ncar, const uint32_t *sid, int prefer,
                 uint32_t ids[TR_DV_COUNT]);

#endif
