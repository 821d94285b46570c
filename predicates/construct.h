/* Exact constructions: the results are rational points, never rounded. Each returns
 * 0 on success and -1 when the construction is undefined (segment parallel to the
 * plane, coplanar segments parallel); callers decide with the classifiers first. */
#ifndef TR_CONSTRUCT_H
#define TR_CONSTRUCT_H

#include "qpoint.h"

#ifdef __cplusplus
extern "C" {
#endif

/* out = the intersection of the line through a,b with the plane of p,q,r. -1 when ab is
 * parallel to the plane or lies in it, a == b, or p,q,r are collinear. out may be the
 * qpoint behind one of the inputs. */
int tr_construct_line_plane(const tr_point *a, const tr_point *b, const tr_point *p,
                            const tr_point *q, const tr_point *r, tr_qpoint *out);
/* out = the intersection of the lines ab and cd. -1 when they are not coplanar
 * (checked exactly), parallel (collinear included) or a == b or c == d. */
int tr_construct_line_line(const tr_point *a, const tr_point *b, const tr_point *c,
                           const tr_point *d, tr_qpoint *out);
/* Frees the calling thread's construction temporaries (tr_exact_scratch_free calls it too). */
void tr_construct_scratch_free(void);

#ifdef __cplusplus
}
#endif

#endif
