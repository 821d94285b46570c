/* `tetrec check --surface-tolerance EPS IN MESH`: the two-sided bound between the surface
 * IN and the boundary of MESH, proven (src/simplify/bound.c) on the file's doubles. The
 * boundary is taken from the tets themselves (their faces without a neighbour) plus the
 * triangles the file lists (internal facets between regions): nothing the simplifier
 * reported is trusted. */
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "mesh/mesh.h"
#include "simplify/simplify.h"

tr_status tr_cli_check_tolerance(const struct tr_mesh *m, const struct tr_plc *surface,
                                 const struct tr_plc *vol, double eps, int verbose)
{
  size_t nf = 0;
  for (uint32_t t = 0; t < vol->ntets; t++)
    for (int k = 0; k < 4; k++)
      nf += m->tn[4 * (size_t)t + k] == TR_NONE;
  nf += vol->ntris;
  uint32_t *f = malloc(sizeof *f * 3 * (nf ? nf : 1));
  if (!f)
    return tr_error(TR_ERR_NOMEM, "out of memory for %zu boundary faces", nf);
  size_t n = 0;
  for (uint32_t t = 0; t < vol->ntets; t++)
    for (int k = 0; k < 4; k++)
      if (m->tn[4 * (size_t)t + k] == TR_NONE) {
        for (int i = 0; i < 3; i++)
          f[3 * n + i] = vol->tets[4 * (size_t)t + tr_face_vtx[k][i]];
        n++;
      }
  for (size_t i = 0; i < 3 * (size_t)vol->ntris; i++)
    f[3 * n + i] = vol->tris[i];
  n += vol->ntris;
  double diag = tr_simplify_diagonal(surface), d = eps * diag;
  tr_simp_bound_result r;
  tr_status st = tr_simplify_bound(surface->xyz, surface->tris, surface->ntris, vol->xyz, f,
                                   (uint32_t)n, d, &r);
  free(f);
  if (st != TR_OK)
    return st;
  if (!r.ok)
    return tr_error(TR_ERR_INVALID_MESH, "surface tolerance %g: %s %s triangle %u is %s "
                    "within %g (%g of the diagonal) of the %s", eps,
                    r.side ? "the mesh's boundary" : "the input surface's",
                    r.side ? "" : "", r.tri, r.undecided ? "not proven" : "not",
                    d, eps, r.side ? "input surface" : "mesh's boundary");
  if (verbose)
    fprintf(stderr, "tetrec: check: the mesh's boundary (%zu faces) and the input surface "
            "are within %.3g of the bounding box diagonal of each other, proven (at most "
            "%.3g measured)\n", n, eps, diag > 0 ? r.measured / diag : 0);
  return TR_OK;
}
