/* The paper's two edge-recovering swaps (Fig.2, Tables 3 and 4), driven by the verified
 * tables: no Steiner point, the missing edge AB becomes a mesh edge. Both check every new
 * tet for strict positivity with exact predicates before touching the mesh, and report
 * through *done whether the swap was possible (a non-convex configuration is not an
 * error: the caller falls back to pipel decomposition). */
#ifndef TR_RECOVER_EDGES_SWAP_H
#define TR_RECOVER_EDGES_SWAP_H

#include "mesh/mesh.h"

/* Swap23 on tet t1 and its neighbour across face k1 (Table 3): A = vertex k1 of t1,
 * B = the neighbour's vertex opposite the shared face CDE. On success (*done = 1) out[3]
 * holds the tets ACBE, ABCD, ABDE. */
tr_status tr_swap23(struct tr_mesh *m, uint32_t t1, int k1, uint32_t out[3], int *done);

/* Swap44 around edge cd (Table 4): the shell of cd must be exactly 4 real tets whose
 * ring contains a and b opposite each other, with a, b, c, d coplanar and ab crossing cd.
 * On success out[4] holds ABDE, ACBE, ADBF, ABCF. */
tr_status tr_swap44(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                    uint32_t out[4], int *done);

#endif
