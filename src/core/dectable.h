/* Decomposition tables: the seed paper's Tables 3-12 as const data.
 *
 * FORMAT (stable; shared by recover_edges/ (Tables 3-9) and recover_facets/ (10-12)):
 *
 *  - Symbolic vertex names (tr_dv): A B C D are the vertices of the original tet
 *    t = ABCD (for a swap: the names the paper uses in its figure), E F the extra apexes
 *    of swap tets, P1..P4 the Steiner points, H the paper's extra point.
 *  - A table lists its OLD tets (old[j] = t_{j+1} in the paper, 4 names each; a pipel or
 *    clusterel decomposition has exactly one old tet, ABCD) and its NEW tets.
 *  - A new tet (tr_dtet) = 4 vertex names v[0..3] in the paper's order, positively
 *    oriented with the library convention (tr_orient3d(v0,v1,v2,v3) > 0, which is the
 *    paper's hypothesis 2), and n[k] = the neighbour across the face opposite v[k]
 *    (the paper's column N{k+1}). A neighbour spec (tr_dnb) is one of
 *      TR_DNB_INTERNAL  tet   = index (0-based) of another new tet of the same table;
 *      TR_DNB_NG        tet   = j (0-based index into old[]), vtx = a name of old[j]:
 *                       the paper's NG(t_{j+1}, i<vtx>_{j+1}) = the neighbour OLD tet
 *                       of old[j] across old[j]'s face opposite vtx (that face is, as
 *                       a vertex set, exactly this new tet's face);
 *      TR_DNB_PHI       vtx = a name of old[0], fac = 3 names as the paper writes them:
 *                       the paper's Phi(t, i<vtx>, fac): the new tet of the already
 *                       decomposed neighbour across old[0]'s face opposite vtx that has
 *                       face fac (fac is a sub-face of that original face; its vertex
 *                       set equals this new tet's face).
 *  - steiner[]: for each Steiner name used (P1..P4, H), the carrier: the names of the old
 *    vertices spanning the open simplex the point lies in (2 = interior of an edge,
 *    3 = interior of a face, 4 = interior of the tet). Deduced from and verified by the
 *    geometry (tests/recover_edges/test_tables.c), not stated in the paper.
 *  - Every entry carries a comment citing its table and row; every correction of an
 *    OCR slip is recorded next to the entry it fixes.
 *
 * Neighbour links here are symbolic; recover_edges/decompose.c instantiates a table on
 * mesh tets with concrete vertex ids.
 */
#ifndef TR_CORE_DECTABLE_H
#define TR_CORE_DECTABLE_H

#include <stdint.h>

#include "status.h"

/* Symbolic vertex names. */
enum tr_dv {
  TR_DV_A = 0, TR_DV_B, TR_DV_C, TR_DV_D, TR_DV_E, TR_DV_F,
  TR_DV_P1, TR_DV_P2, TR_DV_P3, TR_DV_P4, TR_DV_H,
  TR_DV_COUNT,
  TR_DV_NONE = 0xff
};

enum tr_dnb_kind { TR_DNB_NONE = 0, TR_DNB_INTERNAL, TR_DNB_NG, TR_DNB_PHI };

typedef struct tr_dnb {
  uint8_t kind;   /* enum tr_dnb_kind */
  uint8_t tet;    /* INTERNAL: new tet index; NG: old tet index j */
  uint8_t vtx;    /* NG, PHI: vertex name */
  uint8_t fac[3]; /* PHI: sub-face names (paper's order) */
} tr_dnb;

typedef struct tr_dtet {
  uint8_t v[4];   /* vertex names */
  tr_dnb n[4];    /* n[k]: across the face opposite v[k] */
} tr_dtet;

typedef struct tr_dsteiner {
  uint8_t name;   /* TR_DV_P1..TR_DV_H */
  uint8_t ncar;   /* 2 edge, 3 face, 4 tet interior */
  uint8_t car[4]; /* carrier vertex names (old vertices) */
} tr_dsteiner;

#define TR_DEC_MAX_OLD 4
#define TR_DEC_MAX_STEINER 5

typedef struct tr_dectable {
  const char *name;                 /* e.g. "Table 6 Case 2 II-S" */
  uint8_t nold;
  uint8_t old[TR_DEC_MAX_OLD][4];   /* old tets t_1..t_nold */
  uint8_t nsteiner;
  tr_dsteiner steiner[TR_DEC_MAX_STEINER];
  uint8_t nnew;
  const tr_dtet *tets;              /* nnew entries */
} tr_dectable;

/* Initializer helpers for the data files: INTERNAL(k), NG(t_j, X) with j 1-based as in
 * the paper, PHI(X, fac). */
#define TR_DEC_IN(k) {TR_DNB_INTERNAL, (k), TR_DV_NONE, {0, 0, 0}}
#define TR_DEC_NG(j1, x) {TR_DNB_NG, (uint8_t)((j1) - 1), (x), {0, 0, 0}}
#define TR_DEC_PHI(x, a, b, c) {TR_DNB_PHI, 0, (x), {(a), (b), (c)}}

/* "A", "P1", ... ("?" for an unknown code). */
const char *tr_dv_name(uint8_t v);

/* Combinatorial self-consistency of a table (no geometry): vertex names valid and
 * distinct per tet; INTERNAL links reciprocal and the two tets share exactly the face;
 * NG faces equal the named face of old[j]; PHI fac equals the face as a set and lies in
 * old[0]'s face opposite vtx (each of its names is a vertex of that face or a Steiner
 * point whose carrier lies in it). Returns TR_ERR_INTERNAL with a message naming table,
 * row and column on the first violation. */
tr_status tr_dectable_check(const tr_dectable *t);

/* The names of new tet `row`'s face opposite v[k], sorted ascending. */
void tr_dtet_face_sorted(const tr_dtet *d, int k, uint8_t out[3]);

/* Index in old[j] of name x, or -1. */
int tr_dectable_old_index(const tr_dectable *t, int j, uint8_t x);

/* The Steiner record of name x in t, or NULL. */
const tr_dsteiner *tr_dectable_steiner(const tr_dectable *t, uint8_t x);

/* DType of a triangular face split by Steiner points on two of its edges (Fig.1 of the
 * paper; the precise definition is in recover_edges/dtype.h). The paper stores it in
 * bits 5-8 of a pipel's type. Shared by pipels and clusterels. */
enum { TR_DTYPE_NONE = -1, TR_DTYPE_S = 0, TR_DTYPE_Z = 1 };

#endif
