/* Tables 10, 11 and 12 of the seed paper, transcribed row by row, and one case the paper
 * lacks (FOU_EDG SZZS). Every row was checked against exact geometry by
 * tests/recover_facets/test_tables.c + verify.c (positive tets, exact volume, neighbour links,
 * faces on the right original face, the cut polygon a union of faces, the S/Z pattern).
 * The OCR'd rows needed no correction: each printed row agrees with the geometry.
 * The Steiner carriers are not printed (Figs.2, 5, 6 are lost); they are deduced from the
 * Phi columns (the face of t a sub-face lies on) and verified by the same tests.
 *
 * Placement of H (S3/Z0, S0/Z3 of Table 11, ZSZS of Table 12), and why every new tet is
 * positive. In those cases every new tet except the ones on the far side of the cut is
 * H joined to one boundary triangle of the region R = t ∩ (closed half-space on the
 * side of the cut plane that holds A and B). R is convex (an intersection of half-spaces)
 * and its vertices are the old vertices on that side plus the P_i. We put H at the mean of
 * those vertices: THR_EDG: R has vertices A, B, C, P1, P2, P3; FOU_EDG: A, B, P1..P4.
 * Claim: H lies strictly inside R, so for every boundary triangle T of R ordered with its
 * normal pointing into R, tr_orient3d(T, H) > 0.
 * Proof: R's facet planes are the planes of the faces of t that R meets (ABC, ABD, BCD,
 * CAD, as far as present) and the cut plane. For a facet plane with inward normal n and
 * offset, every vertex of R has signed distance >= 0, and at least one vertex of R is
 * strictly off it (R has non-empty interior since every P_i is interior to its edge, so
 * no facet plane contains all vertices). The mean of the vertices has distance equal to
 * the mean of the distances: > 0. Hence H is strictly on the inner side of every facet
 * plane of R, i.e. in R's interior. Every boundary triangle of R (as the tables list
 * them: sub-triangles of R's facets) spans the plane of that facet, so the cone over it
 * from H is a tet with positive volume, and the cones over a triangulation of the
 * boundary of a convex body from an interior point tile the body. The tests check this
 * on many random exact configurations besides. H is a rational point inside the
 * clusterel, not on the missing facet (the paper's choice of such a point is lost with
 * Figs.5c, 5d, 6d).
 */
#include "recover_facets/cluster_tables.h"

#define A TR_DV_A
#define B TR_DV_B
#define C TR_DV_C
#define D TR_DV_D
#define E TR_DV_E
#define P1 TR_DV_P1
#define P2 TR_DV_P2
#define P3 TR_DV_P3
#define P4 TR_DV_P4
#define H TR_DV_H
#define IN TR_DEC_IN
#define NG TR_DEC_NG
#define PHI TR_DEC_PHI
#define S TR_DTYPE_S
#define Z TR_DTYPE_Z
#define NO TR_DTYPE_NONE

/* ---- Table 10: Swap32, t1 = ACBE, t2 = ABCD, t3 = ABDE; the missing facet ECD is
 * pierced by edge AB. ---- */
static const tr_dtet t10_tets[] = {
  /* Table 10 row ACDE: BDCE NG(t3,ib3) NG(t1,ib1) NG(t2,ib2) */
  {{A, C, D, E}, {IN(1), NG(3, B), NG(1, B), NG(2, B)}},
  /* Table 10 row BDCE: ACDE NG(t1,ia1) NG(t3,ia3) NG(t2,ia2) */
  {{B, D, C, E}, {IN(0), NG(1, A), NG(3, A), NG(2, A)}},
};
const tr_dectable tr_table10_swap32 = {
  "Table 10 Swap32", 3, {{A, C, B, E}, {A, B, C, D}, {A, B, D, E}}, 0, {{0}}, 2, t10_tets};

#define T_ABCD {{A, B, C, D}}
#define THR_STEINER 3, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}, {P3, 2, {C, D, 0, 0}}}
#define THR_STEINER_H                                                                     \
  4, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}, {P3, 2, {C, D, 0, 0}},               \
      {H, 4, {A, B, C, D}}}
#define FOU_STEINER                                                                       \
  4, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}, {P3, 2, {B, C, 0, 0}},               \
      {P4, 2, {A, C, 0, 0}}}
#define FOU_STEINER_H                                                                     \
  5, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}, {P3, 2, {B, C, 0, 0}},               \
      {P4, 2, {A, C, 0, 0}}, {H, 4, {A, B, C, D}}}

/* The tet on the D side of the cut is the same in all four THR_EDG cases; only its link
 * across P1P2P3 changes. Table 11 rows P1P2P3D: phi(ia,P2P3D) phi(ib,P1DP3)
 * phi(ic,P1P2D) <k>. */
#define P1P2P3D_ROW(k)                                                                    \
  {{P1, P2, P3, D}, {PHI(A, P2, P3, D), PHI(B, P1, D, P3), PHI(C, P1, P2, D), IN(k)}}

/* ---- Table 11: THR_EDG, P1 on AD, P2 on BD, P3 on CD ---- */
static const tr_dtet t11_s2z1[] = {
  /* Table 11 S2/Z1 row ABCP1: P1BCP2 phi(ib,AP1C) phi(ic,ABP1) NG(t,id) */
  {{A, B, C, P1}, {IN(1), PHI(B, A, P1, C), PHI(C, A, B, P1), NG(1, D)}},
  /* Table 11 S2/Z1 row P1BCP2: phi(ia,BCP2) P1P2CP3 phi(ic,P1BP2) ABCP1 */
  {{P1, B, C, P2}, {PHI(A, B, C, P2), IN(2), PHI(C, P1, B, P2), IN(0)}},
  /* Table 11 S2/Z1 row P1P2CP3: phi(ia,P2CP3) phi(ib,CP1P3) P1P2P3D P1BCP2 */
  {{P1, P2, C, P3}, {PHI(A, P2, C, P3), PHI(B, C, P1, P3), IN(3), IN(1)}},
  /* Table 11 S2/Z1 row P1P2P3D: ... P1P2CP3 */
  P1P2P3D_ROW(2),
};
static const tr_dtet t11_s1z2[] = {
  /* Table 11 S1/Z2 row ABCP3: phi(ia,BCP3) phi(ib,AP3C) ABP3P2 NG(t,id) */
  {{A, B, C, P3}, {PHI(A, B, C, P3), PHI(B, A, P3, C), IN(1), NG(1, D)}},
  /* Table 11 S1/Z2 row ABP3P2: phi(ia,BP3P2) AP2P3P1 phi(ic,ABP2) ABCP3 */
  {{A, B, P3, P2}, {PHI(A, B, P3, P2), IN(2), PHI(C, A, B, P2), IN(0)}},
  /* Table 11 S1/Z2 row AP2P3P1: P1P2P3D phi(ib,AP1P3) phi(ic,AP2P1) ABP3P2 */
  {{A, P2, P3, P1}, {IN(3), PHI(B, A, P1, P3), PHI(C, A, P2, P1), IN(1)}},
  /* Table 11 S1/Z2 row P1P2P3D: ... AP2P3P1 */
  P1P2P3D_ROW(2),
};
static const tr_dtet t11_s3z0[] = {
  /* Table 11 S3/Z0 row AP1BH: P1P2BH ABCH AP3P1H phi(ic,ABP1) */
  {{A, P1, B, H}, {IN(1), IN(6), IN(5), PHI(C, A, B, P1)}},
  /* Table 11 S3/Z0 row P1P2BH: BP2CH AP1BH P1P3P2H phi(ic,P1BP2) */
  {{P1, P2, B, H}, {IN(2), IN(0), IN(7), PHI(C, P1, B, P2)}},
  /* Table 11 S3/Z0 row BP2CH: CP2P3H ABCH P1P2BH phi(ia,BCP2) */
  {{B, P2, C, H}, {IN(3), IN(6), IN(1), PHI(A, B, C, P2)}},
  /* Table 11 S3/Z0 row CP2P3H: P1P3P2H ACP3H BP2CH phi(ia,P2CP3) */
  {{C, P2, P3, H}, {IN(7), IN(4), IN(2), PHI(A, P2, C, P3)}},
  /* Table 11 S3/Z0 row ACP3H: CP2P3H AP3P1H ABCH phi(ib,AP3C) */
  {{A, C, P3, H}, {IN(3), IN(5), IN(6), PHI(B, A, P3, C)}},
  /* Table 11 S3/Z0 row AP3P1H: P1P3P2H AP1BH ACP3H phi(ib,AP1P3) */
  {{A, P3, P1, H}, {IN(7), IN(0), IN(4), PHI(B, A, P1, P3)}},
  /* Table 11 S3/Z0 row ABCH: BP2CH ACP3H AP1BH NG(t,id) */
  {{A, B, C, H}, {IN(2), IN(4), IN(0), NG(1, D)}},
  /* Table 11 S3/Z0 row P1P3P2H: CP2P3H P1P2BH AP3P1H P1P2P3D */
  {{P1, P3, P2, H}, {IN(3), IN(1), IN(5), IN(8)}},
  /* Table 11 S3/Z0 row P1P2P3D: ... P1P3P2H */
  P1P2P3D_ROW(7),
};
static const tr_dtet t11_s0z3[] = {
  /* Table 11 S0/Z3 row AP1P2H: P1P3P2H AP2BH ACP1H phi(ic,AP2P1) */
  {{A, P1, P2, H}, {IN(7), IN(1), IN(4), PHI(C, A, P2, P1)}},
  /* Table 11 S0/Z3 row AP2BH: BP2P3H ABCH AP1P2H phi(ic,ABP2) */
  {{A, P2, B, H}, {IN(2), IN(6), IN(0), PHI(C, A, B, P2)}},
  /* Table 11 S0/Z3 row BP2P3H: P1P3P2H CBP3H AP2BH phi(ia,BP3P2) */
  {{B, P2, P3, H}, {IN(7), IN(3), IN(1), PHI(A, B, P3, P2)}},
  /* Table 11 S0/Z3 row CBP3H: BP2P3H CP3P1H ABCH phi(ia,BCP3) */
  {{C, B, P3, H}, {IN(2), IN(5), IN(6), PHI(A, B, C, P3)}},
  /* Table 11 S0/Z3 row ACP1H: CP3P1H AP1P2H ABCH phi(ib,AP1C) */
  {{A, C, P1, H}, {IN(5), IN(0), IN(6), PHI(B, A, P1, C)}},
  /* Table 11 S0/Z3 row CP3P1H: P1P3P2H ACP1H CBP3H phi(ib,CP1P3) */
  {{C, P3, P1, H}, {IN(7), IN(4), IN(3), PHI(B, C, P1, P3)}},
  /* Table 11 S0/Z3 row ABCH: CBP3H ACP1H AP2BH NG(t,id) */
  {{A, B, C, H}, {IN(3), IN(4), IN(1), NG(1, D)}},
  /* Table 11 S0/Z3 row P1P3P2H: BP2P3H AP1P2H CP3P1H P1P2P3D */
  {{P1, P3, P2, H}, {IN(2), IN(0), IN(5), IN(8)}},
  /* Table 11 S0/Z3 row P1P2P3D: ... P1P3P2H */
  P1P2P3D_ROW(7),
};

static const tr_dectable t11_tables[4] = {
  {"Table 11 S2/Z1", 1, T_ABCD, THR_STEINER, 4, t11_s2z1},
  {"Table 11 S1/Z2", 1, T_ABCD, THR_STEINER, 4, t11_s1z2},
  {"Table 11 S3/Z0", 1, T_ABCD, THR_STEINER_H, 9, t11_s3z0},
  {"Table 11 S0/Z3", 1, T_ABCD, THR_STEINER_H, 9, t11_s0z3},
};

/* dtype[] is indexed by the vertex opposite the face: A (face BCD), B (ADC), C (ABD),
 * D (ABC). THR_EDG: ABC has no cut edge. */
const tr_cluster_case tr_thr_edg_cases[TR_NUM_THR_EDG] = {
  {"S2/Z1", &t11_tables[0], {S, Z, S, NO}, 0, {0}},
  {"S1/Z2", &t11_tables[1], {Z, S, Z, NO}, 0, {0}},
  {"S3/Z0", &t11_tables[2], {S, S, S, NO}, 6, {A, B, C, P1, P2, P3}},
  {"S0/Z3", &t11_tables[3], {Z, Z, Z, NO}, 6, {A, B, C, P1, P2, P3}},
};

/* ---- Table 12: FOU_EDG, P1 on AD, P2 on BD, P3 on BC, P4 on AC. The paper numbers the
 * faces ABD, BCD, ACB, ADC as 0..3 and names a subcase by their types in that order. ---- */
static const tr_dtet t12_ssss[] = {
  /* Table 12 SSSS row P1P2P3D: phi(ia,P2P3D) P1P3CD phi(ic,P1P2D) P1P3P2B */
  {{P1, P2, P3, D}, {PHI(A, P2, P3, D), IN(1), PHI(C, P1, P2, D), IN(3)}},
  /* Table 12 SSSS row P1P3CD: phi(ia,P3CD) phi(ib,P1DC) P1P2P3D P1P3P4C */
  {{P1, P3, C, D}, {PHI(A, P3, C, D), PHI(B, P1, D, C), IN(0), IN(2)}},
  /* Table 12 SSSS row P1P3P4C: phi(id,P3P4C) phi(ib,P1CP4) P1P3CD P1P4P3A */
  {{P1, P3, P4, C}, {PHI(D, P3, P4, C), PHI(B, P1, C, P4), IN(1), IN(4)}},
  /* Table 12 SSSS row P1P3P2B: phi(ia,P3P2B) phi(ic,P1BP2) ABP3P1 P1P2P3D */
  {{P1, P3, P2, B}, {PHI(A, P3, P2, B), PHI(C, P1, B, P2), IN(5), IN(0)}},
  /* Table 12 SSSS row P1P4P3A: phi(id,P4P3A) ABP3P1 phi(ib,AP1P4) P1P3P4C */
  {{P1, P4, P3, A}, {PHI(D, P4, P3, A), IN(5), PHI(B, A, P1, P4), IN(2)}},
  /* Table 12 SSSS row ABP3P1: P1P3P2B P1P4P3A phi(ic,ABP1) phi(id,AP3B) */
  {{A, B, P3, P1}, {IN(3), IN(4), PHI(C, A, B, P1), PHI(D, A, P3, B)}},
};
static const tr_dtet t12_zsss[] = {
  /* Table 12 ZSSS row P1P2P3D: phi(ia,P2P3D) P1P3CD phi(ic,P1P2D) P1P3P2A */
  {{P1, P2, P3, D}, {PHI(A, P2, P3, D), IN(1), PHI(C, P1, P2, D), IN(3)}},
  /* Table 12 ZSSS row P1P3CD: phi(ia,P3CD) phi(ib,P1DC) P1P2P3D P1P3P4C */
  {{P1, P3, C, D}, {PHI(A, P3, C, D), PHI(B, P1, D, C), IN(0), IN(2)}},
  /* Table 12 ZSSS row P1P3P4C: phi(id,P3P4C) phi(ib,P1CP4) P1P3CD P1P4P3A */
  {{P1, P3, P4, C}, {PHI(D, P3, P4, C), PHI(B, P1, C, P4), IN(1), IN(4)}},
  /* Table 12 ZSSS row P1P3P2A: ABP3P2 phi(ic,AP2P1) P1P4P3A P1P2P3D */
  {{P1, P3, P2, A}, {IN(5), PHI(C, A, P2, P1), IN(4), IN(0)}},
  /* Table 12 ZSSS row P1P4P3A: phi(id,P4P3A) P1P3P2A phi(ib,AP1P4) P1P3P4C */
  {{P1, P4, P3, A}, {PHI(D, P4, P3, A), IN(3), PHI(B, A, P1, P4), IN(2)}},
  /* Table 12 ZSSS row ABP3P2: phi(ia,P3P2B) P1P3P2A phi(ic,ABP2) phi(id,AP3B) */
  {{A, B, P3, P2}, {PHI(A, P3, P2, B), IN(3), PHI(C, A, B, P2), PHI(D, A, P3, B)}},
};
static const tr_dtet t12_zzss[] = {
  /* Table 12 ZZSS row P1P2CD: phi(ia,P2CD) phi(ib,P1DC) phi(ic,P1P2D) P1P2P3C */
  {{P1, P2, C, D}, {PHI(A, P2, C, D), PHI(B, P1, D, C), PHI(C, P1, P2, D), IN(1)}},
  /* Table 12 ZZSS row P1P2P3C: phi(ia,P2P3C) P1P3P4C P1P2CD P1P3P2A */
  {{P1, P2, P3, C}, {PHI(A, P2, P3, C), IN(2), IN(0), IN(3)}},
  /* Table 12 ZZSS row P1P3P4C: phi(id,P3P4C) phi(ib,P1CP4) P1P2P3C P1P4P3A */
  {{P1, P3, P4, C}, {PHI(D, P3, P4, C), PHI(B, P1, C, P4), IN(1), IN(4)}},
  /* Table 12 ZZSS row P1P3P2A: ABP3P2 phi(ic,AP2P1) P1P4P3A P1P2P3C */
  {{P1, P3, P2, A}, {IN(5), PHI(C, A, P2, P1), IN(4), IN(1)}},
  /* Table 12 ZZSS row P1P4P3A: phi(id,P4P3A) P1P3P2A phi(ib,AP1P4) P1P3P4C */
  {{P1, P4, P3, A}, {PHI(D, P4, P3, A), IN(3), PHI(B, A, P1, P4), IN(2)}},
  /* Table 12 ZZSS row ABP3P2: phi(ia,P3P2B) P1P3P2A phi(ic,ABP2) phi(id,AP3B) */
  {{A, B, P3, P2}, {PHI(A, P3, P2, B), IN(3), PHI(C, A, B, P2), PHI(D, A, P3, B)}},
};
/* Not in the paper. ZZSS mirrored by the odd relabeling A<->B (which maps P1<->P2 and
 * P3<->P4 and turns every S face into a Z face and back); each mirrored tet gets its
 * first two vertices swapped to be positive again, and its N1, N2 swapped with them.
 * Its faces ABD, BCD, ACB, ADC come out S, Z, Z, S: the pattern SZZS, whose orbit under
 * the even relabelings ({SZZS, ZSSZ}) none of the six printed subcases reaches (ZZSS's
 * orbit is {ZZSS, SSZZ}, ZSZS's is {ZSZS, SZSZ}). */
static const tr_dtet t12_zssz[] = {
  /* mirror of ZZSS row P1P2CD */
  {{P1, P2, C, D}, {PHI(A, P2, D, C), PHI(B, P1, C, D), PHI(C, P2, P1, D), IN(1)}},
  /* mirror of ZZSS row P1P2P3C */
  {{P1, P2, P4, C}, {IN(2), PHI(B, P1, P4, C), IN(0), IN(3)}},
  /* mirror of ZZSS row P1P3P4C */
  {{P4, P2, P3, C}, {PHI(A, P2, C, P3), PHI(D, P4, P3, C), IN(1), IN(4)}},
  /* mirror of ZZSS row P1P3P2A */
  {{P4, P2, P1, B}, {PHI(C, B, P1, P2), IN(5), IN(4), IN(1)}},
  /* mirror of ZZSS row P1P4P3A */
  {{P3, P2, P4, B}, {IN(3), PHI(D, P3, P4, B), PHI(A, B, P2, P3), IN(2)}},
  /* mirror of ZZSS row ABP3P2 */
  {{A, B, P4, P1}, {IN(3), PHI(B, P4, P1, A), PHI(C, B, A, P1), PHI(D, B, P4, A)}},
};
static const tr_dtet t12_zszs[] = {
  /* Table 12 ZSZS row P1P2P3D: phi(ia,P2P3D) P1P3CD phi(ic,P1P2D) P1P3P2H */
  {{P1, P2, P3, D}, {PHI(A, P2, P3, D), IN(1), PHI(C, P1, P2, D), IN(4)}},
  /* Table 12 ZSZS row P1P3CD: phi(ia,P3CD) phi(ib,P1DC) P1P2P3D P1P3P4C */
  {{P1, P3, C, D}, {PHI(A, P3, C, D), PHI(B, P1, D, C), IN(0), IN(2)}},
  /* Table 12 ZSZS row P1P3P4C: phi(id,P3P4C) phi(ib,P1CP4) P1P3CD P1P4P3H */
  {{P1, P3, P4, C}, {PHI(D, P3, P4, C), PHI(B, P1, C, P4), IN(1), IN(3)}},
  /* Table 12 ZSZS row P1P4P3H: BP3P4H P1P3P2H AP4P1H P1P3P4C */
  {{P1, P4, P3, H}, {IN(10), IN(4), IN(5), IN(2)}},
  /* Table 12 ZSZS row P1P3P2H: BP2P3H AP1P2H P1P4P3H P1P2P3D */
  {{P1, P3, P2, H}, {IN(6), IN(7), IN(3), IN(0)}},
  /* Table 12 ZSZS row AP4P1H: P1P4P3H AP1P2H ABP4H phi(ib,AP1P4) */
  {{A, P4, P1, H}, {IN(3), IN(7), IN(9), PHI(B, A, P1, P4)}},
  /* Table 12 ZSZS row BP2P3H: P1P3P2H BP3P4H AP2BH phi(ia,P3P2B) */
  {{B, P2, P3, H}, {IN(4), IN(10), IN(8), PHI(A, P3, P2, B)}},
  /* Table 12 ZSZS row AP1P2H: P1P3P2H AP2BH AP4P1H phi(ic,AP2P1) */
  {{A, P1, P2, H}, {IN(4), IN(8), IN(5), PHI(C, A, P2, P1)}},
  /* Table 12 ZSZS row AP2BH: BP2P3H ABP4H AP1P2H phi(ic,ABP2) */
  {{A, P2, B, H}, {IN(6), IN(9), IN(7), PHI(C, A, B, P2)}},
  /* Table 12 ZSZS row ABP4H: BP3P4H AP4P1H AP2BH phi(id,P4BA) */
  {{A, B, P4, H}, {IN(10), IN(5), IN(8), PHI(D, P4, B, A)}},
  /* Table 12 ZSZS row BP3P4H: P1P4P3H ABP4H BP2P3H phi(id,P4P3B) */
  {{B, P3, P4, H}, {IN(3), IN(9), IN(6), PHI(D, P4, P3, B)}},
};
static const tr_dtet t12_zzzs[] = {
  /* Table 12 ZZZS row P1P2CD: phi(ia,P2CD) phi(ib,P1DC) phi(ic,P1P2D) P1P2P4C */
  {{P1, P2, C, D}, {PHI(A, P2, C, D), PHI(B, P1, D, C), PHI(C, P1, P2, D), IN(1)}},
  /* Table 12 ZZZS row P1P2P4C: P2P3P4C phi(ib,P1CP4) P1P2CD P1P4P2A */
  {{P1, P2, P4, C}, {IN(2), PHI(B, P1, C, P4), IN(0), IN(3)}},
  /* Table 12 ZZZS row P2P3P4C: phi(id,P3P4C) P1P2P4C phi(ia,P2P3C) P2P4P3B */
  {{P2, P3, P4, C}, {PHI(D, P3, P4, C), IN(1), PHI(A, P2, P3, C), IN(4)}},
  /* Table 12 ZZZS row P1P4P2A: ABP4P2 phi(ic,AP2P1) phi(ib,AP1P4) P1P2P4C */
  {{P1, P4, P2, A}, {IN(5), PHI(C, A, P2, P1), PHI(B, A, P1, P4), IN(1)}},
  /* Table 12 ZZZS row P2P4P3B: phi(id,P4P3B) phi(ia,P3P2B) ABP4P2 P2P3P4C */
  {{P2, P4, P3, B}, {PHI(D, P4, P3, B), PHI(A, P3, P2, B), IN(5), IN(2)}},
  /* Table 12 ZZZS row ABP4P2: P2P4P3B P1P4P2A phi(ic,ABP2) phi(id,P4BA) */
  {{A, B, P4, P2}, {IN(4), IN(3), PHI(C, A, B, P2), PHI(D, P4, B, A)}},
};
static const tr_dtet t12_zzzz[] = {
  /* Table 12 ZZZZ row P1P2P4D: P2CP4D phi(ib,P1DP4) phi(ic,P1P2D) P1P4P2A */
  {{P1, P2, P4, D}, {IN(2), PHI(B, P1, D, P4), PHI(C, P1, P2, D), IN(3)}},
  /* Table 12 ZZZZ row P2P3P4C: phi(id,P3P4C) P2CP4D phi(ia,P2P3C) P2P4P3B */
  {{P2, P3, P4, C}, {PHI(D, P3, P4, C), IN(2), PHI(A, P2, P3, C), IN(4)}},
  /* Table 12 ZZZZ row P2CP4D: phi(ib,CP4D) P1P2P4D phi(ia,P2CD) P2P3P4C */
  {{P2, C, P4, D}, {PHI(B, C, P4, D), IN(0), PHI(A, P2, C, D), IN(1)}},
  /* Table 12 ZZZZ row P1P4P2A: ABP4P2 phi(ic,AP2P1) phi(ib,AP1P4) P1P2P4D */
  {{P1, P4, P2, A}, {IN(5), PHI(C, A, P2, P1), PHI(B, A, P1, P4), IN(0)}},
  /* Table 12 ZZZZ row P2P4P3B: phi(id,P4P3B) phi(ia,P3P2B) ABP4P2 P2P3P4C */
  {{P2, P4, P3, B}, {PHI(D, P4, P3, B), PHI(A, P3, P2, B), IN(5), IN(1)}},
  /* Table 12 ZZZZ row ABP4P2: P2P4P3B P1P4P2A phi(ic,ABP2) phi(id,P4BA) */
  {{A, B, P4, P2}, {IN(4), IN(3), PHI(C, A, B, P2), PHI(D, P4, B, A)}},
};

static const tr_dectable t12_tables[7] = {
  {"Table 12 SSSS", 1, T_ABCD, FOU_STEINER, 6, t12_ssss},
  {"Table 12 ZSSS", 1, T_ABCD, FOU_STEINER, 6, t12_zsss},
  {"Table 12 ZZSS", 1, T_ABCD, FOU_STEINER, 6, t12_zzss},
  {"SZZS (mirror of Table 12 ZZSS)", 1, T_ABCD, FOU_STEINER, 6, t12_zssz},
  {"Table 12 ZZZS", 1, T_ABCD, FOU_STEINER, 6, t12_zzzs},
  {"Table 12 ZZZZ", 1, T_ABCD, FOU_STEINER, 6, t12_zzzz},
  {"Table 12 ZSZS", 1, T_ABCD, FOU_STEINER_H, 11, t12_zszs},
};

/* The name XYZW gives the types of faces ABD, BCD, ACB, ADC, i.e. of the faces opposite
 * C, A, D, B; dtype[] below is indexed by the opposite vertex A, B, C, D = (Y, W, X, Z). */
const tr_cluster_case tr_fou_edg_cases[TR_NUM_FOU_EDG] = {
  {"SSSS", &t12_tables[0], {S, S, S, S}, 0, {0}},
  {"ZSSS", &t12_tables[1], {S, S, Z, S}, 0, {0}},
  {"ZZSS", &t12_tables[2], {Z, S, Z, S}, 0, {0}},
  {"SZZS", &t12_tables[3], {Z, S, S, Z}, 0, {0}},
  {"ZZZS", &t12_tables[4], {Z, S, Z, Z}, 0, {0}},
  {"ZZZZ", &t12_tables[5], {Z, Z, Z, Z}, 0, {0}},
  {"ZSZS", &t12_tables[6], {S, S, Z, Z}, 6, {A, B, P1, P2, P3, P4}},
};

tr_status tr_cluster_make_h(const tr_cluster_case *c, const tr_point *const pts[TR_DV_COUNT],
                            tr_qpoint *out)
{
  if (c->nh == 0)
    return tr_error(TR_ERR_INTERNAL, "cluster case %s has no point H", c->name);
  mpq_t x, n;
  mpq_init(x);
  mpq_init(n);
  mpq_set_ui(n, c->nh, 1);
  for (int i = 0; i < 3; i++) {
    mpq_set_ui(out->c[i], 0, 1);
    for (int k = 0; k < c->nh; k++) {
      const tr_point *p = pts[c->hsum[k]];
      if (!p) {
        mpq_clear(x);
        mpq_clear(n);
        return tr_error(TR_ERR_INTERNAL, "cluster case %s: point %s missing for H", c->name,
                        tr_dv_name(c->hsum[k]));
      }
      tr_point_get_q(p, i, x);
      mpq_add(out->c[i], out->c[i], x);
    }
    mpq_div(out->c[i], out->c[i], n);
  }
  mpq_clear(x);
  mpq_clear(n);
  tr_qpoint_update(out);
  return TR_OK;
}
