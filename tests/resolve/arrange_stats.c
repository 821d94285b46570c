/* Measures the arrangement of a surface file (not a test): counts and CPU seconds, and
 * with --check the whole validator of tcheck.h (slow: exact, every piece pair whose
 * boxes meet). Usage: arrange_stats FILE [--check] */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "tetrec.h"
#include "tcheck.h"

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  tr_plc *p;
  if (tr_plc_read(argv[1], &p) != TR_OK) {
    fprintf(stderr, "%s\n", tr_last_error());
    return 1;
  }
  clock_t c0 = clock();
  tr_arrangement a;
  tr_status st = tr_arrangement_build(p, &a);
  double sec = (double)(clock() - c0) / CLOCKS_PER_SEC;
  if (st != TR_OK) {
    fprintf(stderr, "%s\n", tr_last_error());
    return 1;
  }
  uint32_t nnew = 0, multi = 0;
  for (uint32_t v = 0; v < a.nverts; v++)
    nnew += a.verts[v].q != NULL;
  for (uint32_t i = 0; i < a.npieces; i++)
    multi += a.pieces[i].nsrc > 1;
  printf("%s\ttris %u\tpairs %llu\tcoplanar %llu\tnew_vertices %u\tcrossings %llu\tpieces %u"
         "\tmulti %u\tdropped %llu\tcpu %.3f\n",
         argv[1], p->ntris, (unsigned long long)a.npairs, (unsigned long long)a.ncoplanar, nnew,
         (unsigned long long)a.ncrossings, a.npieces, multi, (unsigned long long)a.ndropped, sec);
  int bad = 0;
  if (argc > 2 && !strcmp(argv[2], "--check")) {
    bad = tc_check(argv[1], p, &a);
    printf("check: %s\n", bad ? "FAILED" : "ok");
  }
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
  return bad != 0;
}
