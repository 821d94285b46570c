/* Rounding Steiner points to doubles, and its repair (issue 7).
 *
 * Before it, tr_round_flip_flat (flatflip.h) flips away the tets whose shape, not their
 * rounding, makes them flat in doubles.
 *
 * Steiner points are exact rationals (vq) that lie exactly on their edge or facet; the
 * writers print m->xyz, which for a Steiner point starts as its nearest double. Nearest
 * rounding can make a thin incident tet flat or inverted in doubles. Refinement therefore
 * admits a split point only where its new tets are positive in doubles, at its nearest
 * double or at one next to it, which it then keeps in m->xyz: the points after it were
 * admitted against that double (refine/insert.c). The repair starts from m->xyz as the
 * stages before left it; a point off its nearest double first goes back to it where its
 * whole star stays strictly positive there (index order). This stage re-checks
 * every tet incident to a Steiner point with the exact orient3d on the doubles the writers
 * print, and moves the double (never the exact point) of each Steiner point whose star has
 * a tet that is not strictly positive to a nearby double point that makes its whole star
 * strictly positive.
 *
 * The repaired double is generally no longer exactly on its edge or facet (that is
 * impossible in doubles in general): exact conformity holds for the exact mesh (vq, the
 * --exact output, the validators); the double output guarantees strictly positive tets.
 *
 * Search: the candidates are the doubles at offsets (i, j, k) ulp steps from the nearest
 * double (each step one nextafter on its axis), |i|,|j|,|k| <= TR_ROUND_RADIUS, in
 * increasing i*i + j*j + k*k, ties in lexicographic (i, j, k) order; the first one that
 * makes every incident tet strictly positive wins. Steiner points are visited in index
 * order; a point whose search fails (a neighbouring Steiner point may be the culprit) is
 * retried in the next round after the others moved, until a round moves nothing. Then a
 * point still stuck gets min-conflicts moves along one axis over the Steiner points
 * around it (round.c, conflicts(): the layered slivers of a facet bumpy below double
 * resolution need a joint placement along its normal), kept only if they lower the number
 * of non-positive tets. If that fails, it is tried together with each Steiner neighbour
 * w in index order (a
 * sliver between two Steiner points needs w farther away to leave room): w's candidates
 * that keep w's other tets positive, each with a search for the stuck point, both among
 * the offsets of norm i*i + j*j + k*k <= TR_ROUND_PAIR_RADIUS2. If no pair helps, a stuck
 * point moves to the first candidate with the fewest non-positive tets in its star when
 * that is fewer than now (clusters of nearly degenerate Steiner points then free each
 * other one by one). After any such move, single moves again. Every kept move changes
 * only the tets of the moved points and strictly lowers how many of them are not
 * positive, so the rounds terminate, and the result depends only on the mesh and the
 * doubles it starts from. */
#ifndef TR_OUTPUT_ROUND_H
#define TR_OUTPUT_ROUND_H

#include <stdint.h>

#include "mesh/mesh.h"
#include "predicates.h"

#define TR_ROUND_RADIUS 16
#define TR_ROUND_PAIR_RADIUS2 16
/* At most this many star checks (one candidate position against a point's tets) per
 * mesh by default, a few seconds: past it the search stops and the stage fails as below,
 * rather than searching for minutes on clusters of nearly degenerate Steiner points.
 * The most any repaired mesh tried so far needed is 204,419 (a star polyhedron with
 * vertices moved by one ulp). Subnormal coordinates send orient3d to GMP (expansions
 * would underflow), so there a check costs 1-6 us and the budget up to ~10 s
 * (Chazelle's polyhedron moved by ulps, subnormal at 0, is repaired with ~216,000). */
#define TR_ROUND_BUDGET 2000000

/* Repairs m->xyz of the Steiner points of m's kept tets (real, not TR_TF_OUTER) as above,
 * starting from m->xyz, with at most `budget` star checks (0: TR_ROUND_BUDGET).
 * *repaired = number of Steiner points whose double ends off its nearest rounding.
 * When some tet stays flat or inverted, returns TR_ERR_INVALID_MESH naming the first such
 * Steiner point (index, coordinates) and tet; the moves made so far are kept, the exact
 * points are never changed. */
tr_status tr_round_steiner(struct tr_mesh *m, uint64_t budget, uint64_t *repaired);

/* Tet v[0..3] is not strictly positive on the doubles m->xyz (exact orient3d on doubles). */
static inline int tr_round_flat(const struct tr_mesh *m, const uint32_t *v)
{
  const double *x = m->xyz;
  return tr_orient3d(x + 3 * (size_t)v[0], x + 3 * (size_t)v[1], x + 3 * (size_t)v[2],
                     x + 3 * (size_t)v[3]) <= 0;
}

/* Number of kept tets of m that are not strictly positive on the doubles m->xyz (exact
 * orient3d on doubles); *first (may be NULL) = the first one, TR_NONE if none. */
uint64_t tr_round_count_nonpositive(const struct tr_mesh *m, uint32_t *first);

#endif
