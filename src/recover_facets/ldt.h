/* A small exact Delaunay tetrahedralization of a few points (local ids), for the cavity
 * retriangulations: facet recovery's (cavity.h, Si & Gaertner 2005) and the removal of an
 * interior Steiner point by the retriangulation of its star (src/suppress/starfill.c).
 *
 * Bowyer-Watson by brute force (every tet tested for every point, quadratic: only for
 * cavities of a few hundred vertices at most), exact insphere; a cospherical point is not
 * in conflict, so the result is a Delaunay tetrahedralization, the one of the insertion
 * order (local ids ascending). Hull faces carry ghost tets whose fourth vertex is
 * TR_LDT_GHOST. */
#ifndef TR_RECOVER_FACETS_LDT_H
#define TR_RECOVER_FACETS_LDT_H

#include <stddef.h>
#include <stdint.h>

#include "core/status.h"
#include "mesh/mesh.h"

#define TR_LDT_GHOST (UINT32_MAX - 1)

/* A face of a tet by its sorted vertices, with the tet and the face's code in it. */
typedef struct tr_ldt_face {
  uint32_t k[3];
  uint32_t tet;
  uint32_t face;
} tr_ldt_face;

typedef struct tr_ldt {
  const tr_point *p;
  uint32_t (*t)[4];
  uint32_t n, cap;
  uint8_t *cf;      /* per tet: in conflict (scratch) */
  tr_ldt_face *fk;  /* scratch: faces */
  size_t capfk;
} tr_ldt;

/* Order of tr_ldt_face: key, then tet, then face code. */
int tr_ldt_cmp_face(const void *pa, const void *pb);
/* Face k of tet t in tr_face_vtx order (turning so that vertex k is on its positive side). */
void tr_ldt_face_of(const uint32_t *t, int k, uint32_t out[3]);
/* 1 iff (a0, a1, a2) is a rotation of (x0, x1, x2): the same face turning the same way. */
int tr_ldt_same_turn(const uint32_t a[3], const uint32_t x[3]);

/* The Delaunay mesh of p[0..n) (kept by pointer) inserted in index order. *ok = 0 when
 * the points span less than 3D or one repeats. */
tr_status tr_ldt_build(tr_ldt *D, const tr_point *p, uint32_t n, int *ok);
void tr_ldt_free(tr_ldt *D);

/* The faces of D's real tets, sorted (*ft reallocated, *nft of them). */
tr_status tr_ldt_faces(const tr_ldt *D, tr_ldt_face **ft, uint32_t *nft);
/* The real tet of D with face loc turning as given (its fourth vertex on the positive
 * side), or TR_NONE. */
uint32_t tr_ldt_find_turned(const tr_ldt *D, const tr_ldt_face *ft, uint32_t nft,
                            const uint32_t loc[3]);
/* The other real tet across face `face` of tet j, TR_NONE on the hull. */
uint32_t tr_ldt_across(const tr_ldt *D, const tr_ldt_face *ft, uint32_t nft, uint32_t j,
                       uint32_t face);

#endif
