/* The flipnm recursion undoes a nested edge removal that fails (flip.c): on the fin glued
 * inside a grid box (tests/hard, fin_attached_inside), the fin's diagonal 7-100 is crossed
 * by the edge 12-98, whose removal needs 98-11 removed first, which needs 11-51 removed
 * first; a failed try on the other edge of a blocked ring face used to leave flips behind
 * that made the right sequence unreachable, and the edge got a Steiner point.
 *
 * Usage: test_nested_undo MODE, on the Delaunay mesh of the case's points and its input
 * edges:
 *   flips: the default recovery adds no Steiner point; every input edge is a mesh edge;
 *          validator (links, exact orientation, v2t, Euler, exact volume unchanged);
 *   paper: without the general flips (the paper's algorithm) the same edges need at
 *          least one Steiner point, so the case does depend on the flips; validator. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../hard/hard_cases.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/recover_edges.h"
#include "tedges.h"

/* The sorted unique edges of the triangles (a < b). */
static uint32_t input_edges(const hard_case *c, uint32_t *e)
{
  for (uint32_t t = 0; t < c->nt; t++)
    for (int k = 0; k < 3; k++) {
      e[6 * t + 2 * k] = c->tris[3 * t + k];
      e[6 * t + 2 * k + 1] = c->tris[3 * t + (k + 1) % 3];
    }
  return sort_edges(e, 3 * c->nt);
}

int main(int argc, char **argv)
{
  if (argc != 2 || (strcmp(argv[1], "flips") && strcmp(argv[1], "paper"))) {
    fprintf(stderr, "usage: %s flips|paper\n", argv[0]);
    return 2;
  }
  int paper = !strcmp(argv[1], "paper");
  int ci = -1;
  for (int i = 0; i < hard_case_count(); i++)
    if (!strcmp(hard_case_name(i), "fin_attached_inside"))
      ci = i;
  hard_case c;
  if (ci < 0 || hard_case_build(ci, &c) != 0) {
    fprintf(stderr, "FAIL: cannot build fin_attached_inside\n");
    return 1;
  }
  uint32_t *e = malloc(6 * (size_t)c.nt * sizeof *e);
  struct tr_mesh *m = NULL;
  mpq_t vol;
  mpq_init(vol);
  int bad = 1;
  tr_edge_chains ch;
  memset(&ch, 0, sizeof ch);
  tr_edge_recovery_stats st;
  tr_edge_recovery_opts opt = {paper, paper, paper, NULL, 0};
  tr_status s = e ? tr_delaunay_build(c.xyz, c.np, &m) : TR_ERR_NOMEM;
  uint32_t ne = e ? input_edges(&c, e) : 0;
  if (s == TR_OK)
    s = tr_mesh_volume6(m, vol);
  if (s == TR_OK)
    s = tr_recover_edges_ex(m, e, ne, &opt, &ch, &st);
  if (s == TR_OK)
    s = tr_check_mesh(m, TR_CHK_TOPOLOGY, vol);
  if (s != TR_OK) {
    fprintf(stderr, "FAIL: %s: %s\n", tr_status_name(s), tr_last_error());
  } else if (st.missing_edges == 0) {
    fprintf(stderr, "FAIL: no input edge is missing from the Delaunay mesh: nothing shown\n");
  } else if (paper && st.points_added == 0) {
    fprintf(stderr, "FAIL: the paper's recovery needs no point: the case shows nothing\n");
  } else if (!paper && st.points_added != 0) {
    fprintf(stderr, "FAIL: %llu Steiner points on edges, want 0 (%llu missing edges)\n",
            (unsigned long long)st.points_added, (unsigned long long)st.missing_edges);
  } else {
    bad = 0;
    for (uint32_t i = 0; i < ne && !paper && !bad; i++)
      if (ch.start[i + 1] - ch.start[i] != 2) {
        fprintf(stderr, "FAIL: input edge %u-%u is not one mesh edge\n", e[2 * i], e[2 * i + 1]);
        bad = 1;
      }
    if (!bad)
      printf("fin_attached_inside (%s): %llu missing edges, %llu Steiner points, mesh valid\n",
             argv[1], (unsigned long long)st.missing_edges,
             (unsigned long long)st.points_added);
  }
  tr_edge_chains_free(&ch);
  if (m)
    tr_mesh_destroy(m);
  mpq_clear(vol);
  free(e);
  hard_case_free(&c);
  return bad;
}
