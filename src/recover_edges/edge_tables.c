/* Tables 3-9 of the seed paper, transcribed row by row. The OCR'd text of these tables
 * was checked entry by entry against the geometry (tests/recover_edges/test_tables.c:
 * orientation, exact volumes, face pairing, NG/Phi faces, boundary tiling, recovered
 * segment): no entry needed a correction. The same checks reject every single-entry
 * corruption of these tables and every relabeling that is not a symmetry, so a wrong
 * entry could not have passed. The Steiner carriers are not printed in the paper (its
 * Fig.3 is lost); they are deduced from the new tets, and the tests show each is the
 * only edge / face of the tet for which the table is valid. */
#include "recover_edges/edge_tables.h"

#define A TR_DV_A
#define B TR_DV_B
#define C TR_DV_C
#define D TR_DV_D
#define E TR_DV_E
#define F TR_DV_F
#define P TR_DV_P1 /* Tables 5 and 7 call their single Steiner point P */
#define P1 TR_DV_P1
#define P2 TR_DV_P2
#define IN TR_DEC_IN
#define NG TR_DEC_NG
#define PHI TR_DEC_PHI

/* ---- Table 3: Swap23, t1 = ACDE, t2 = BDCE (AB pierces CDE) ---- */
static const tr_dtet t3_tets[] = {
  /* Table 3 row ACBE: NG(t2,id2) ABDE NG(t1,id1) ABCD */
  {{A, C, B, E}, {NG(2, D), IN(2), NG(1, D), IN(1)}},
  /* Table 3 row ABCD: NG(t2,ie2) NG(t1,ie1) ABDE ACBE */
  {{A, B, C, D}, {NG(2, E), NG(1, E), IN(2), IN(0)}},
  /* Table 3 row ABDE: NG(t2,ic2) NG(t1,ic1) ACBE ABCD */
  {{A, B, D, E}, {NG(2, C), NG(1, C), IN(0), IN(1)}},
};
const tr_dectable tr_table3_swap23 = {
  "Table 3 Swap23", 2, {{A, C, D, E}, {B, D, C, E}}, 0, {{0}}, 3, t3_tets};

/* ---- Table 4: Swap44, t1 = ACDE, t2 = ADCF, t3 = BDCE, t4 = BCDF (ABCD coplanar) ---- */
static const tr_dtet t4_tets[] = {
  /* Table 4 row ABDE: NG(t3,ic3) NG(t1,ic1) ACBE ADBF */
  {{A, B, D, E}, {NG(3, C), NG(1, C), IN(1), IN(2)}},
  /* Table 4 row ACBE: NG(t3,id3) ABDE NG(t1,id1) ABCF */
  {{A, C, B, E}, {NG(3, D), IN(0), NG(1, D), IN(3)}},
  /* Table 4 row ADBF: NG(t4,ic4) ABCF NG(t2,ic2) ABDE */
  {{A, D, B, F}, {NG(4, C), IN(3), NG(2, C), IN(0)}},
  /* Table 4 row ABCF: NG(t4,id4) NG(t2,id2) ADBF ACBE */
  {{A, B, C, F}, {NG(4, D), NG(2, D), IN(2), IN(1)}},
};
const tr_dectable tr_table4_swap44 = {
  "Table 4 Swap44", 4, {{A, C, D, E}, {A, D, C, F}, {B, D, C, E}, {B, C, D, F}},
  0, {{0}}, 4, t4_tets};

#define T_ABCD {{A, B, C, D}}

/* ---- Table 5: Case 1 (NOD_EDG / EDG_NOD / EDG_DEG), P on edge BD ---- */
static const tr_dtet t5_tets[] = {
  /* Table 5 row ABCP: phi(ia,BCP) APCD phi(ic,ABP) NG(t,id) */
  {{A, B, C, P}, {PHI(A, B, C, P), IN(1), PHI(C, A, B, P), NG(1, D)}},
  /* Table 5 row APCD: phi(ia,PCD) NG(t,ib) phi(ic,APD) ABCP */
  {{A, P, C, D}, {PHI(A, P, C, D), NG(1, B), PHI(C, A, P, D), IN(0)}},
};
const tr_dectable tr_table5_case1 = {
  "Table 5 Case 1", 1, T_ABCD, 1, {{P, 2, {B, D, 0, 0}}}, 2, t5_tets};

/* ---- Table 6: Case 2 (EDG_EDG) ---- */
/* Subcase I: opposite edges, P1 on AD, P2 on BC. */
static const tr_dtet t6_1_tets[] = {
  /* Table 6 I row ABP2P1: P1BP2D AP2CP1 phi(ic,ABP1) phi(id,BAP2) */
  {{A, B, P2, P1}, {IN(2), IN(1), PHI(C, A, B, P1), PHI(D, B, A, P2)}},
  /* Table 6 I row AP2CP1: P1P2CD phi(ib,AP1C) ABP2P1 phi(id,ACP2) */
  {{A, P2, C, P1}, {IN(3), PHI(B, A, P1, C), IN(0), PHI(D, A, C, P2)}},
  /* Table 6 I row P1BP2D: phi(ia,BP2D) P1P2CD phi(ic,P1BD) ABP2P1 */
  {{P1, B, P2, D}, {PHI(A, B, P2, D), IN(3), PHI(C, P1, B, D), IN(0)}},
  /* Table 6 I row P1P2CD: phi(ia,P2CD) phi(ib,P1DC) P1BP2D AP2CP1 */
  {{P1, P2, C, D}, {PHI(A, P2, C, D), PHI(B, P1, D, C), IN(2), IN(1)}},
};
const tr_dectable tr_table6_case2_1 = {
  "Table 6 Case 2 I", 1, T_ABCD, 2, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, C, 0, 0}}},
  4, t6_1_tets};

/* Subcase II, S-type for ABD: P1 on AD, P2 on BD, diagonal B-P1 (see dtype.h). */
static const tr_dtet t6_2s_tets[] = {
  /* Table 6 II-S row ABCP1: P1BCP2 phi(ib,AP1C) phi(ic,ABP1) NG(t,id) */
  {{A, B, C, P1}, {IN(1), PHI(B, A, P1, C), PHI(C, A, B, P1), NG(1, D)}},
  /* Table 6 II-S row P1BCP2: phi(ia,BCP2) P1P2CD phi(ic,P1BP2) ABCP1 */
  {{P1, B, C, P2}, {PHI(A, B, C, P2), IN(2), PHI(C, P1, B, P2), IN(0)}},
  /* Table 6 II-S row P1P2CD: phi(ia,P2CD) phi(ib,P1DC) phi(ic,P1P2D) P1BCP2 */
  {{P1, P2, C, D}, {PHI(A, P2, C, D), PHI(B, P1, D, C), PHI(C, P1, P2, D), IN(1)}},
};
const tr_dectable tr_table6_case2_2s = {
  "Table 6 Case 2 II-S", 1, T_ABCD, 2, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}},
  3, t6_2s_tets};

/* Subcase II, Z-type for ABD: P1 on AD, P2 on BD, diagonal A-P2. */
static const tr_dtet t6_2z_tets[] = {
  /* Table 6 II-Z row ABCP2: phi(ia,BCP2) AP2CP1 phi(ic,ABP2) NG(t,id) */
  {{A, B, C, P2}, {PHI(A, B, C, P2), IN(1), PHI(C, A, B, P2), NG(1, D)}},
  /* Table 6 II-Z row AP2CP1: P1P2CD phi(ib,AP1C) phi(ic,AP2P1) ABCP2 */
  {{A, P2, C, P1}, {IN(2), PHI(B, A, P1, C), PHI(C, A, P2, P1), IN(0)}},
  /* Table 6 II-Z row P1P2CD: phi(ia,P2CD) phi(ib,P1DC) phi(ic,P1P2D) AP2CP1 */
  {{P1, P2, C, D}, {PHI(A, P2, C, D), PHI(B, P1, D, C), PHI(C, P1, P2, D), IN(1)}},
};
const tr_dectable tr_table6_case2_2z = {
  "Table 6 Case 2 II-Z", 1, T_ABCD, 2, {{P1, 2, {A, D, 0, 0}}, {P2, 2, {B, D, 0, 0}}},
  3, t6_2z_tets};

/* ---- Table 7: Case 3 (NOD_FAC / FAC_NOD), P in face BCD, the edge through A ---- */
static const tr_dtet t7_tets[] = {
  /* Table 7 row ABCP: phi(ia,BCP) APCD ABPD NG(t,id) */
  {{A, B, C, P}, {PHI(A, B, C, P), IN(1), IN(2), NG(1, D)}},
  /* Table 7 row APCD: phi(ia,CDP) NG(t,ib) ABPD ABCP */
  {{A, P, C, D}, {PHI(A, C, D, P), NG(1, B), IN(2), IN(0)}},
  /* Table 7 row ABPD: phi(ia,DBP) APCD NG(t,ic) ABCP */
  {{A, B, P, D}, {PHI(A, D, B, P), IN(1), NG(1, C), IN(0)}},
};
const tr_dectable tr_table7_case3 = {
  "Table 7 Case 3", 1, T_ABCD, 1, {{P, 3, {B, C, D, 0}}}, 3, t7_tets};

/* ---- Table 8: Case 4 (EDG_FAC / FAC_EDG), P1 on edge AD, P2 in face BCD ---- */
static const tr_dtet t8_tets[] = {
  /* Table 8 row ABCP1: P1BCP2 phi(ib,AP1C) phi(ic,ABP1) NG(t,id) */
  {{A, B, C, P1}, {IN(2), PHI(B, A, P1, C), PHI(C, A, B, P1), NG(1, D)}},
  /* Table 8 row P1BP2D: phi(ia,DBP2) P1P2CD phi(ic,P1BD) P1BCP2 */
  {{P1, B, P2, D}, {PHI(A, D, B, P2), IN(3), PHI(C, P1, B, D), IN(2)}},
  /* Table 8 row P1BCP2: phi(ia,BCP2) P1P2CD P1BP2D ABCP1 */
  {{P1, B, C, P2}, {PHI(A, B, C, P2), IN(3), IN(1), IN(0)}},
  /* Table 8 row P1P2CD: phi(ia,CDP2) phi(ib,CP1D) P1BP2D P1BCP2 */
  {{P1, P2, C, D}, {PHI(A, C, D, P2), PHI(B, C, P1, D), IN(1), IN(2)}},
};
const tr_dectable tr_table8_case4 = {
  "Table 8 Case 4", 1, T_ABCD, 2, {{P1, 2, {A, D, 0, 0}}, {P2, 3, {B, C, D, 0}}},
  4, t8_tets};

/* ---- Table 9: Case 5 (FAC_FAC), Scheme 1, P1 in face ABD, P2 in face BCD ---- */
static const tr_dtet t9_tets[] = {
  /* Table 9 row ABCP1: P1BCP2 AP1CD phi(ic,ABP1) NG(t,id) */
  {{A, B, C, P1}, {IN(1), IN(4), PHI(C, A, B, P1), NG(1, D)}},
  /* Table 9 row P1BCP2: phi(ia,BCP2) P1P2CD P1BP2D ABCP1 */
  {{P1, B, C, P2}, {PHI(A, B, C, P2), IN(2), IN(3), IN(0)}},
  /* Table 9 row P1P2CD: phi(ia,CDP2) AP1CD P1BP2D P1BCP2 */
  {{P1, P2, C, D}, {PHI(A, C, D, P2), IN(4), IN(3), IN(1)}},
  /* Table 9 row P1BP2D: phi(ia,DBP2) P1P2CD phi(ic,BDP1) P1BCP2 */
  {{P1, B, P2, D}, {PHI(A, D, B, P2), IN(2), PHI(C, B, D, P1), IN(1)}},
  /* Table 9 row AP1CD: P1P2CD NG(t,ib) phi(ic,DAP1) ABCP1 */
  {{A, P1, C, D}, {IN(2), NG(1, B), PHI(C, D, A, P1), IN(0)}},
};
const tr_dectable tr_table9_case5 = {
  "Table 9 Case 5 Scheme 1", 1, T_ABCD, 2, {{P1, 3, {A, B, D, 0}}, {P2, 3, {B, C, D, 0}}},
  5, t9_tets};

const tr_dectable *const tr_edge_tables[] = {
  &tr_table3_swap23, &tr_table4_swap44, &tr_table5_case1, &tr_table6_case2_1,
  &tr_table6_case2_2s, &tr_table6_case2_2z, &tr_table7_case3, &tr_table8_case4,
  &tr_table9_case5,
};
const int tr_num_edge_tables = (int)(sizeof tr_edge_tables / sizeof tr_edge_tables[0]);
