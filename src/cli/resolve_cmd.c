/* `tetrec resolve IN -o OUT`: the solid of a self-intersecting or defective surface as a
 * clean surface in doubles (src/resolve/snap.c; docs/resolve.md). What people use to
 * clean an STL for other tools: the output passes `tetrec check-surface` (but for
 * non-manifold edges where parts of the solid touch along an edge, which are its true
 * boundary) or the command fails saying where it does not. */
#include <stdio.h>

#include "cli.h"
#include "io/format_name.h"
#include "io/io.h"
#include "io/write.h"
#include "resolve/snap.h"

tr_status tr_cli_resolve(const tr_cli_args *a)
{
  if (!a->out)
    return tr_error(TR_ERR_USAGE, "resolve needs -o OUT, the surface to write (.off .stl "
                    ".mesh .meshb .vtu .vtk .msh or a TetGen base name)");
  TR_CHECK(tr_io_check_out_name(a->out, 1));
  if (a->msh_version & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(a->out));
  tr_plc *in = NULL;
  TR_CHECK(tr_cli_read_input(a, 1, &in));
  tr_status st = tr_io_check_writable(a->out);
  tr_plc *out = NULL;
  tr_snap_info si;
  if (st == TR_OK)
    /* STL stores floats: the surface is rounded to them and tested as written */
    st = tr_resolve_snap(in, a->resolve == 2 ? 2 : 1, tr_io_out_format(a->out) == TR_OUT_STL,
                         a->rounds ? a->rounds : TR_SNAP_ROUNDS, &out, &si);
  /* a surface format has no place for them: said, not dropped in silence */
  if (st == TR_OK && (in->nholes || in->nregions) && !a->quiet)
    fprintf(stderr, "tetrec: warning: %s: %u hole and %u region points are not written "
            "(a surface format has no place for them)\n", a->in, in->nholes, in->nregions);
  if (st == TR_OK)
    st = tr_plc_write_ex(out, a->out, a->msh_version);
  if (st == TR_OK && !a->quiet) {
    fprintf(stderr, "tetrec: resolve: %s: %llu improper pairs, %u new vertices, %u pieces, "
            "%u connected parts\n", a->in, (unsigned long long)si.npairs, si.nnew,
            si.npieces, si.ncomponents);
    fprintf(stderr, "tetrec: resolve: %d round%s (improper pairs made by rounding: %llu); "
            "%u vertices rounded to %s, %u merged onto another's double, %u triangles "
            "collapsed and dropped; largest move %.3g, at most %.3g from the exact solid's "
            "corners\n", si.rounds, si.rounds > 1 ? "s" : "",
            (unsigned long long)si.npairs_later, si.nrounded,
            tr_io_out_format(a->out) == TR_OUT_STL ? "floats (STL)" : "doubles", si.nmerged, si.ncollapsed,
            si.max_move, si.move_bound);
    fprintf(stderr, "tetrec: %s: %u vertices, %u triangles", a->out, si.nverts, si.ntris);
    if (si.ninternal)
      fprintf(stderr, ", of which the last %u (triangles %u..%u) are internal facets",
              si.ninternal, si.ntris - si.ninternal, si.ntris - 1);
    fprintf(stderr, ": no self-intersection (%.3f s)\n", si.seconds);
    if (si.left.nonmanifold)
      fprintf(stderr, "tetrec: note: %s has %u edges of more than two triangles (%s): valid "
              "for `tetrec mesh`; `tetrec check-surface` lists them as non-manifold\n", a->out,
              si.left.nonmanifold, si.ninternal ? "internal facets, or parts of the solid "
              "touching along an edge" : "parts of the solid touching along an edge");
  }
  tr_plc_destroy(out);
  tr_plc_destroy(in);
  return st;
}
