/* General flips without Steiner points: Swap23 on any interior face, and edge removal
 * (Shewchuk's "edge removal", the paper's Swap32 / Swap44 generalised to Swap n -> 2n-4),
 * including an edge on the convex hull whose two hull faces are coplanar (the 2-2 hull
 * flip, with the real tets of the open shell retriangulated).
 *
 * Edge removal of AB: the Shell of AB is the ring r0..r(n-1). A triangulation T of the
 * ring polygon replaces the shell by the tets (A,x,y,z) and (B,z,y,x) for every triangle
 * (x,y,z) of T; it is valid iff every one of them is strictly positive (exact
 * tr_orient3d_p): the new tets then have exactly the boundary of the old shell and no
 * negative tet, so they tile it. T is chosen by dynamic programming over sub-polygons
 * (O(n^3)) maximising the minimum of a cheap double quality of its tets; ties go to the
 * lowest split index, so the choice is deterministic (no pointer or hash order).
 *
 * Hull case: when AB is a hull edge, the ring holds TR_GHOST once (between the two ghost
 * tets). The only triangle allowed to use TR_GHOST is (C, GHOST, D) with C, D its ring
 * neighbours; it turns into the ghost tets of the new hull faces ACD and BDC. That needs
 * A, B, C, D coplanar with AB and CD crossing at a point interior to both (the quad ACBD
 * strictly convex), which is checked exactly; the real part of the ring (C..D) is
 * triangulated as above. The ghost tets keep TR_GHOST in slot 3 and face the outside.
 *
 * Every flip can be undone exactly (tr_flip_undo) from its record: the drivers use that
 * to keep only flips that strictly reduce a crossing count, which bounds the work.
 *
 * Protection: a flip that would delete a protected edge (edge removal deletes AB) or a
 * protected face (Swap23 deletes its face, edge removal the faces around AB) is refused
 * (*done = 0). The caller supplies the test.
 */
#ifndef TR_RECOVER_EDGES_FLIP_H
#define TR_RECOVER_EDGES_FLIP_H

#include "core/vtmap.h"
#include "mesh/mesh.h"

/* The largest shell edge removal handles. */
#define TR_FLIP_MAX_RING 14
/* The deepest recursion of tr_flip_remove_edge_nm whose edges the star rule sees (see
 * tr_flip_journal.stars); edge recovery goes to depth 7. */
#define TR_FLIP_STACK 16

/* What a flip replaced: enough to put the old tets back. */
typedef struct tr_flip_rec {
  uint32_t nold, nnew;
  int hull;                                 /* 1: a hull edge was removed (2-2 hull flip) */
  uint32_t oldv[4 * TR_FLIP_MAX_RING];      /* vertices of the old tets */
  uint32_t newid[2 * TR_FLIP_MAX_RING - 4]; /* slots of the new tets (a hint: undoing later
                                               flips may move them, see tr_flip_undo) */
  uint32_t newv[4 * (2 * TR_FLIP_MAX_RING - 4)]; /* vertices of the new tets */
} tr_flip_rec;

/* Protection test: returns 1 iff the simplex v[0..nv) (nv = 2 edge, 3 face, any vertex
 * order) must not be deleted. */
typedef int (*tr_flip_guard)(void *ud, const uint32_t *v, int nv);

/* Swap23 on face k of t (both tets real, the segment between the apexes must cross the
 * open face). rec may be NULL. */
tr_status tr_flip23(struct tr_mesh *m, uint32_t t, int k, tr_flip_guard guard, void *ud,
                    tr_flip_rec *rec, int *done);

/* Removes edge ab (3 <= shell size <= TR_FLIP_MAX_RING, see above). t0: a tet of the shell
 * or TR_NONE. On success the edge is gone and *done = 1; rec (may be NULL) records it. */
tr_status tr_flip_remove_edge(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                              tr_flip_guard guard, void *ud, tr_flip_rec *rec, int *done);

/* A tet with edge ab (possibly a ghost), TR_NONE if ab is not a mesh edge: the first
 * such tet of tr_ball(m, a, 1, .), found without listing the whole ball. */
tr_status tr_flip_edge_tet(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t *t);

/* Puts the old tets of a successful flip back (slots may differ). The new tets are found
 * by their vertex lists: at newid[i] if that slot still holds them (the usual case), else
 * through Ball of their first vertex, since undoing later flips may have put tets in
 * other slots. */
tr_status tr_flip_undo(struct tr_mesh *m, const tr_flip_rec *rec);

/* A sequence of flips that can be undone as a whole, with a running measure: after every
 * flip, delta += sum of measure(new tets) - sum of measure(old tets) (measure may be NULL;
 * it sees vertex lists, TR_GHOST in slot 3 for ghosts). Zero-initialise; free with
 * tr_flip_journal_free. */
typedef int (*tr_flip_measure)(void *ud, const struct tr_mesh *m, const uint32_t v[4]);
/* Per-flip admission, asked after each flip with its record: 0 takes the flip back at
 * once (it then counts as refused). Edge recovery by flips uses it for TetGen's rule
 * that no flip may create a face or an edge the segment crosses (flipfirst.c). */
typedef int (*tr_flip_accept)(void *ud, const struct tr_mesh *m, const tr_flip_rec *r);
typedef struct tr_flip_journal {
  tr_flip_rec *r;
  uint32_t n, cap;
  long delta;
  uint32_t flips[5]; /* kept in the journal by kind: 2-3, 3-2, 4-4, n >= 5, hull */
  tr_flip_measure measure;
  void *mud;
  tr_flip_accept accept; /* NULL: every valid flip is kept */
  void *aud;
  int pivot; /* 1: the recursion removes only the edges that block a Swap23 */
  /* 1: edge removal only where TetGen's flips reach (3-2, n -> 2n-4 on a flat ring, and
   * the 4-4 whose edge and two opposite ring vertices are coplanar), the recursion's 2-3
   * flips doing the rest */
  int tetgen_flips;
  /* Flip attempts (made or refused) allowed, 0 = no limit: the recursion of
   * tr_flip_remove_edge_nm grows exponentially with its depth, and the deep searches of
   * edge recovery stop when this many attempts were spent. `tries` counts them; the
   * caller resets it. */
  uint32_t budget, tries;
  tr_u32buf shell; /* scratch of the edge removals: Shell(ab) (freed with the journal) */
  /* 1: TetGen's star rule in the recursion (the star counters of its flipnm, Si 2015).
   * The edges being removed, outermost first, are on stack[]; a tet holding one of them
   * is in that edge's star. A nested removal is not tried on an edge whose shell holds a
   * tet of a star on the stack other than the two at the face it unblocks, and no ring
   * face one of whose tets lies in another star on the stack is tried: the recursion
   * never takes apart a shell an outer level is working on. */
  int stars;
  uint32_t stack[2 * TR_FLIP_STACK];
  int nstack;
  uint32_t pruned; /* branches the star rule cut (nested removals and ring faces) */
} tr_flip_journal;
void tr_flip_journal_free(tr_flip_journal *j);
/* Undoes the journal's flips back to its first `to` entries (newest first). */
tr_status tr_flip_journal_undo(struct tr_mesh *m, tr_flip_journal *j, uint32_t to);

/* Edge removal with bounded recursion (TetGen's flipnm idea): if ab cannot be removed as
 * it is, shrink its shell by Swap23 on the faces (a, b, r_i) and, with depth > 1, by
 * removing the edges a-r_i / b-r_i that block those Swap23s first, then retry. Every
 * flip made is appended to j (also when ab stays: the caller decides whether to keep
 * them, typically by j->delta). depth 1 = plain removal. Once j->budget attempts are
 * spent (j->budget > 0), no further flip is tried and *done stays 0. */
tr_status tr_flip_remove_edge_nm(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0,
                                 int depth, tr_flip_guard guard, void *ud, tr_flip_journal *j,
                                 int *done);
/* The edges of face k of t that keep the segment between the two apexes from crossing
 * the open face (the Swap23 is valid iff there is none): their number, the edges in
 * e[0..n). 0 also when a tet is a ghost. */
int tr_flip23_blockers(const struct tr_mesh *m, uint32_t t, int k, uint32_t e[3][2]);
/* Swap23 on face k of t, appended to j. */
tr_status tr_flip23_j(struct tr_mesh *m, uint32_t t, int k, tr_flip_guard guard, void *ud,
                      tr_flip_journal *j, int *done);
/* The same when tr_flip23_blockers just found nb blockers of that face (nb < 0: not
 * asked): with one or two, a side of the face has an orientation >= 0 and another one
 * < 0, so the Swap23 is refused without its three tests again; the try is counted all
 * the same. (Three cannot happen between two valid tets: the three signs sum, as a
 * volume, to one of fixed sign; it is passed on to the tests.) */
tr_status tr_flip23_jb(struct tr_mesh *m, uint32_t t, int k, int nb, tr_flip_guard guard,
                       void *ud, tr_flip_journal *j, int *done);

/* A set of edges / triangles by vertex ids (any order; an edge has v[2] = TR_NONE): the
 * flip drivers list each crossed simplex once, and comparing every new candidate with
 * all earlier ones was quadratic in the pipe / cluster size. The shared vertex-tuple map
 * (core/vtmap.h) on the sorted triple. Zero-initialise. */
typedef struct tr_sxset {
  tr_vtmap map;
} tr_sxset;
/* Empties the set (keeps its memory). */
void tr_sxset_clear(tr_sxset *s);
/* 1 if v was added, 0 if it was there already, -1 out of memory (TR_ERR_NOMEM reported). */
int tr_sxset_add(tr_sxset *s, const uint32_t v[3]);
/* 1 iff v is in the set. */
int tr_sxset_has(const tr_sxset *s, const uint32_t v[3]);
void tr_sxset_free(tr_sxset *s);

#endif
