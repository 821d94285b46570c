/* Exact constructions: the results are rational points, never rounded. Each returns
 * 0 on success and -1 when the construction is undefined (segment parallel to the
 * plane, coplanar segments parallel); callers decide with the classifiers first. */
#ifndef TR_CONSTRUCT_H
#define TR_CONSTRUCT_H

#include "qpoint.h"

#ifdef __cplusplus
extern "C" {
#endif

/* out = the intersection of the line through a,b with the plane of p,q,r. */
int tr_construct_line_plane(const tr_point *a, const tr_point *b, const tr_point *p,
                            const tr_point *q, const tr_point *r, tr_qpoint *out);
/* out = the intersection of the lines ab and cd, which must be coplanar and not
 * parallel. */
int tr_construct_line_line(const tr_point *a, const tr_point *b, const tr_point *c,
                           const tr_point *d, tr_qpoint *out);

#ifdef __cplusplus
}
#endif

#endif
