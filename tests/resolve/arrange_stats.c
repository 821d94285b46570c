/* Measures the arrangement of a surface file (not a test): counts and CPU seconds, and
 * with --check the whole validator of tcheck.h (slow: exact, every piece pair whose
 * boxes meet), then the solid by winding number: its boundary, rays, CPU. Usage: arrange_stats FILE [--check] */
#include <stdio.h>
#include <stdlib.h>
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
  /* the solid by winding number (src/resolve/winding.c) */
  c0 = clock();
  tr_solid so;
  st = tr_solid_classify(p, &a, 0, &so);
  sec = (double)(clock() - c0) / CLOCKS_PER_SEC;
  if (st != TR_OK)
    printf("solid: %s: %s\n", tr_status_name(st), tr_last_error());
  else {
    uint32_t vq = 0, vnd = 0; /* new vertices on the boundary, of which not doubles */
    uint8_t *on = calloc(a.nverts ? a.nverts : 1, 1);
    for (uint32_t i = 0; on && i < a.npieces; i++)
      if (so.keep[i] == TR_SOLID_KEEP || so.keep[i] == TR_SOLID_FLIP)
        for (int k = 0; k < 3; k++)
          on[a.pieces[i].v[k]] = 1;
    for (uint32_t v = 0; on && v < a.nverts; v++)
      if (on[v] && a.verts[v].q) {
        vq++;
        vnd += a.verts[v].q->err[0] != 0 || a.verts[v].q->err[1] != 0 ||
               a.verts[v].q->err[2] != 0;
      }
    free(on);
    /* the exact volume sums rationals of growing denominators (minutes on 300k pieces
     * with rational corners): with --check only; else the nearest doubles' volume */
    mpq_t v6;
    mpq_init(v6);
    if (argc > 2 && !strcmp(argv[2], "--check"))
      tr_solid_volume6(p, &a, &so, v6);
    else {
      double s6 = 0;
      for (uint32_t i = 0; i < a.npieces; i++) {
        if (so.keep[i] != TR_SOLID_KEEP && so.keep[i] != TR_SOLID_FLIP)
          continue;
        tr_point P[3];
        for (int k = 0; k < 3; k++)
          P[k] = tr_arr_point(&a, p, a.pieces[i].v[k]);
        const double *x = P[0].d, *y = P[1].d, *z = P[2].d;
        double d = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
                   x[2] * (y[0] * z[1] - y[1] * z[0]);
        s6 += so.keep[i] == TR_SOLID_FLIP ? -d : d;
      }
      mpq_set_d(v6, s6);
    }
    printf("solid: boundary %u of %u pieces\tparts %u\trays %u\tnew_on_boundary %u\tnot_doubles "
           "%u\tvolume %.17g\tcpu %.3f\n", so.nkept, so.npieces, so.ncomponents, so.nrays, vq,
           vnd, mpq_get_d(v6) / 6, sec);
    mpq_clear(v6);
  }
  tr_solid_free(&so);
  int bad = 0;
  if (argc > 2 && !strcmp(argv[2], "--check")) {
    bad = tc_check(argv[1], p, &a);
    printf("check: %s\n", bad ? "FAILED" : "ok");
  }
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
  return bad != 0;
}
