/* Shared body of the reader fuzzers: parse from memory, then (when the input parsed)
 * validate it, so the triangulation and validation paths are fuzzed too. Any crash,
 * leak or sanitizer report is a finding; every error status is a fine answer. */
#ifndef TR_FUZZ_IO_COMMON_H
#define TR_FUZZ_IO_COMMON_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "io/io.h"
#include "tetrec.h"

typedef tr_status (*tr_fuzz_reader)(const char *, size_t, const char *, struct tr_plc *);

static inline int tr_fuzz_run(tr_fuzz_reader rd, const uint8_t *data, size_t size)
{
  /* Validation is superlinear in the worst case: keep the inputs small enough that a
   * slow unit is a real finding, not the size of the input. */
  if (size > 1 << 16)
    return 0;
  struct tr_plc plc;
  memset(&plc, 0, sizeof plc);
  if (rd((const char *)data, size, "fuzz", &plc) == TR_OK) {
    tr_options o;
    tr_options_default(&o);
    o.allow_open = size & 1; /* both the strict and the open census */
    tr_status v = tr_plc_validate(&plc, &o);
    /* Differential check of the self-intersection broad phases on what validation left
     * (duplicates merged, indices in range): the grid and the sweep must name the same
     * pair. A disagreement is a finding (abort). */
    if (v == TR_OK || v == TR_ERR_SELF_INTERSECT) {
      char a[512];
      tr_status g = tr_input_self_intersections_by(&plc, NULL, TR_SELFINT_GRID);
      snprintf(a, sizeof a, "%s", g == TR_OK ? "" : tr_last_error());
      tr_status w = tr_input_self_intersections_by(&plc, NULL, TR_SELFINT_SWEEP);
      if (g != w || (w != TR_OK && strcmp(a, tr_last_error()) != 0))
        abort();
      /* and the narrow phase's shortcuts (axis planes, straddling pairs, coplanar fans,
       * cached planes) against the general path: the same list of improper pairs (the
       * reference tests every pair whose boxes meet: small inputs only) */
      if (plc.ntris <= 1500) {
        uint32_t *pr = NULL, *pg = NULL;
        size_t nr = 0, ng = 0;
        tr_status r1 = tr_input_self_intersection_pairs(&plc, TR_SELFINT_REFERENCE, &pr, &nr);
        tr_status r2 = tr_input_self_intersection_pairs(&plc, TR_SELFINT_GRID, &pg, &ng);
        if (r1 == TR_OK && r2 == TR_OK && (nr != ng || (nr && memcmp(pr, pg, 2 * nr * sizeof *pr))))
          abort();
        free(pr);
        free(pg);
      }
    }
  }
  tr_plc_clear(&plc);
  return 0;
}

#endif
