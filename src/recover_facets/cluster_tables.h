/* The seed paper's facet-recovery tables in the core/dectable.h format:
 *   Table 10  Swap32 (three tets around edge AB -> two tets sharing the facet CDE);
 *   Table 11  clusterel THR_EDG: the missing facet cuts edges AD, BD, CD (P1, P2, P3);
 *   Table 12  clusterel FOU_EDG: the missing facet cuts edges AD, BD, BC, AC (P1..P4),
 *             i.e. it separates {A,B} from {C,D}; AB and CD are the uncut edges.
 * Each table is verified geometrically by tests/recover_facets/test_tables.c.
 *
 * Each clusterel decomposition comes with its DType pattern (S/Z type of every face of
 * t = ABCD that has two cut edges, see dtype.h) and, where the paper needs it, the rule
 * that places the extra point H. tr_cluster_match() (dtype.h) picks the case and the
 * relabeling for a concrete clusterel.
 */
#ifndef TR_RECOVER_FACETS_CLUSTER_TABLES_H
#define TR_RECOVER_FACETS_CLUSTER_TABLES_H

#include "core/dectable.h"
#include "qpoint.h"

extern const tr_dectable tr_table10_swap32; /* t1=ACBE, t2=ABCD, t3=ABDE -> ACDE, BDCE */

/* Extension of dectable.h for clusterels: the decomposition, the DType the decomposition
 * imposes on each face of t = ABCD (indexed by the name A..D of the vertex opposite the
 * face; TR_DTYPE_NONE for a face with fewer than two cut edges), and the placement of H:
 * H = (1/nh) * sum of the points named in hsum[0..nh-1] (nh == 0: no H). Why that
 * placement makes every new tet positive is proved in cluster_tables.c. */
typedef struct tr_cluster_case {
  const char *name;         /* the paper's subcase name, e.g. "S2/Z1", "ZZSS" */
  const tr_dectable *table;
  int8_t dtype[4];          /* by opposite vertex A, B, C, D */
  uint8_t nh;
  uint8_t hsum[6];
} tr_cluster_case;

/* Table 11, in the order S2/Z1, S1/Z2, S3/Z0, S0/Z3 (preference order of
 * tr_cluster_match: cases without H first). */
#define TR_NUM_THR_EDG 4
extern const tr_cluster_case tr_thr_edg_cases[TR_NUM_THR_EDG];

/* Table 12 plus one case the paper lacks, in preference order: SSSS, ZSSS, ZZSS, SZZS,
 * ZZZS, ZZZZ, ZSZS. SZZS is the mirror image of ZZSS (see cluster_tables.c): the six
 * printed subcases cover only 14 of the 16 S/Z patterns under orientation-preserving
 * relabelings; SZZS and ZSSZ are the two left over. */
#define TR_NUM_FOU_EDG 7
extern const tr_cluster_case tr_fou_edg_cases[TR_NUM_FOU_EDG];

/* Exact position of H for case c: pts[name] are the points named A..D, P1..P4 (only the
 * names used by c->hsum are read). Returns TR_ERR_INTERNAL if c has no H. */
tr_status tr_cluster_make_h(const tr_cluster_case *c, const tr_point *const pts[TR_DV_COUNT],
                            tr_qpoint *out);

#endif
