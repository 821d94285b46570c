/* Exact insphere in fixed-width integers: the fast exact stage for near-cospherical
 * points (see intdet.c). Internal to predicates/. */
#ifndef TR_INTDET_H
#define TR_INTDET_H

/* Exact value of tr_insphere(a, b, c, d, e) when the twelve coordinate differences
 * p - e can be written exactly as 62-bit integers times one power of two: either the
 * rounded differences dv (ax, ay, az, bx, ..., dz, the order of insphere.c) when
 * exact_diffs says they are exact, or, failing that, the differences of the raw
 * coordinates once those are 61-bit integers times one power of two. Returns 1 and
 * sets *out (exact sign, approximate magnitude) on success; 0 when neither form
 * exists (or int128 is unavailable), for the expansion stages to decide. */
int tr_insphere_int(const double *const p[5], const double dv[12], int exact_diffs,
                    double *out);

#endif
