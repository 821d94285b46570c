/* The seed paper's edge-recovery tables (Tables 3-9) in the dectable.h format, each
 * verified geometrically by tests/recover_edges/test_tables.c. */
#ifndef TR_RECOVER_EDGES_EDGE_TABLES_H
#define TR_RECOVER_EDGES_EDGE_TABLES_H

#include "core/dectable.h"

extern const tr_dectable tr_table3_swap23;   /* t1=ACDE, t2=BDCE -> 3 tets around AB */
extern const tr_dectable tr_table4_swap44;   /* t1=ACDE, t2=ADCF, t3=BDCE, t4=BCDF */
extern const tr_dectable tr_table5_case1;    /* P on edge BD */
extern const tr_dectable tr_table6_case2_1;  /* P1 on AD, P2 on BC (opposite edges) */
extern const tr_dectable tr_table6_case2_2s; /* P1 on AD, P2 on BD, ABD S-type */
extern const tr_dectable tr_table6_case2_2z; /* P1 on AD, P2 on BD, ABD Z-type */
extern const tr_dectable tr_table7_case3;    /* P in face BCD */
extern const tr_dectable tr_table8_case4;    /* P1 on edge AD, P2 in face BCD */
extern const tr_dectable tr_table9_case5;    /* P1 in face ABD, P2 in face BCD */

/* All of the above, for loops in tests. */
extern const tr_dectable *const tr_edge_tables[];
extern const int tr_num_edge_tables;

#endif
