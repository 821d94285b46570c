/* Internals shared by the files of the suppression stage (suppress.h). */
#ifndef TR_SUPPRESS_INT_H
#define TR_SUPPRESS_INT_H

#include "suppress.h"

/* The working copy of the sub-faces with, for each vertex, the list of sub-faces on it
 * (linked nodes, so merged triangles can be added as points go). A dead sub-face has
 * tri == TR_NONE. */
typedef struct sup_ctx {
  struct tr_mesh *m;
  const tr_plc *plc;
  uint32_t n, cap;
  uint32_t *v, *tri;           /* 3 * cap, cap */
  uint32_t nv;                 /* vertices covered by head */
  uint32_t *head;              /* nv: first node of the vertex's list, TR_NONE */
  uint32_t nl, capl;
  uint32_t *lnext, *lsub;      /* nodes: next node, sub-face */
  uint64_t *tried;             /* 2 * nv or NULL: per interior point p and dbl, at
                                  2 * p + dbl, the key of its star at its last failed
                                  retriangulation (star.c), 0 none. One slot per dbl:
                                  --keep-surface tries dbl = 1 then 0 on every pass, and
                                  with one slot each try overwrote the other's key, so
                                  no retry was ever skipped */
  uint64_t *mtried;            /* nv or NULL: the same for its last failed merge (merge.c;
                                  at dbl = 1 only) */
  uint64_t *ftried;            /* 2 * nv or NULL: as tried, for its last failed
                                  retriangulation of the star its flips got stuck on
                                  (flipout.c) */
} sup_ctx;

/* Appends sub-face (a,b,c) of input triangle tri and links it to its vertices. */
tr_status sup_add(sup_ctx *c, uint32_t a, uint32_t b, uint32_t cc, uint32_t tri);
/* The live sub-faces on vertex p (reset first). */
tr_status sup_faces_of(const sup_ctx *c, uint32_t p, tr_u32buf *out);
/* *yes = 1 iff (w[0], w[1], w[2]), in any order, is a live sub-face; tmp is scratch. */
tr_status sup_is_sub(const sup_ctx *c, const uint32_t w[3], tr_u32buf *tmp, int *yes);

/* The un-split of p: for each input triangle, its fan around p retriangulated without p.
 * old: the sub-faces on p (ids in c); merged: 4 per triangle (a,b,c,input triangle),
 * oriented like the input triangle; *edge = 1 if p lies on an input edge (some fan is
 * open), else p is inside one triangle. Returns 0 and leaves everything unchanged if p's
 * fans are not simple (several triangles with closed fans, a fan that is not one chain,
 * more than TR_SUP_MAX_POLY vertices): such points are left alone. */
tr_status sup_unsplit(sup_ctx *c, uint32_t p, const tr_u32buf *old, tr_u32buf *merged,
                      int *edge, int *ok);

/* Tries to take p off the boundary: full removal (TR_SUP_REMOVE), then relocation
 * (TR_SUP_RELOCATE). *done = 0 (p stays), 1 (removed) or 2 (relocated). */
tr_status sup_point(sup_ctx *c, uint32_t p, unsigned flags, int *done);

/* Removes interior point p (no constraint on its star, region: its tets' region) by flips
 * that bring it down to four tets, then a 4-1 flip, or, stuck above four, by the
 * retriangulation of the smaller star (sup_star_fill, no expansion; c as there)
 * (flipout.c). dbl: refuse a new tet that
 * is not positive with its vertices at their doubles too. *done = 1 if p is gone; else
 * the mesh is as it was. */
tr_status sup_flip_out(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t region,
                       int dbl, int *done);

/* Removes interior point p (as sup_flip_out) by the Delaunay retriangulation of its star
 * without it, the star expanded across missing non-constraint faces at most `rounds`
 * times (starfill.c). c: the sub-faces, the constraints an expansion must not cross
 * (NULL: none). *done = 1 if p is gone (*tnew: one of the new tets); else the mesh is
 * untouched. *by_dbl (if not NULL) = 1 iff it was refused by a new tet that is flat at
 * doubles only: with 0, a call with dbl = 0 does the same work for the same refusal
 * (dbl decides nothing else), so a dbl = 1 refusal may key the dbl = 0 slot too. */
#define SUP_FILL_EXPAND 3
tr_status sup_star_fill(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t region,
                        int dbl, int rounds, uint32_t *tnew, int *done, int *by_dbl);

/* 1 iff every face of f (nf triples, right-hand normal pointing in) not on apex sees
 * apex (a vertex; TR_NONE: the double point q) strictly positively, exactly and, with
 * dbl, with every point at its double too (star.c). */
int sup_sees_all(const struct tr_mesh *m, const uint32_t *f, size_t nf, uint32_t apex,
                 const double *q, int dbl);
/* A double point q that sees every face of bf (sup_sees_all): candidates from p0 along
 * dir (dir[3] the step, 0: none), between p0 and g, projections into the kernel (with
 * `relaxes` margins, the costly part), the centroids of the tets of star (star.c).
 * *found = 1 if found. */
#define SUP_RELAX_PASSES 6

/* A face's plane for sup_relax: normal n (length len; 0: a face of zero length, skipped)
 * and a point a on it, in the frame 2^-e. */
typedef struct sup_kplane {
  double n[3], a[3], len;
} sup_kplane;
/* find_q's projections into the kernel of the planes pl[0..nf) (star.c): from g (not in
 * the frame), at most 400 steps onto the half-space d >= tau of the most violated plane,
 * tau = L / 8^(pass + 1); the point reached into q (not in the frame). */
void sup_relax(const sup_kplane *pl, size_t nf, int e, double L, const double g[3], double q[3],
               int pass);
tr_status sup_find_q(const struct tr_mesh *m, const tr_u32buf *bf, const tr_u32buf *star,
                     const double *p0, const double g[3], const double dir[4], int dbl,
                     int relaxes, double q[3], int *found);

/* A key of p's star (ball: its tets) for its retriangulation, which p's position does
 * not matter to: its link faces, each with the vertex behind it, and flags; nonzero, or
 * 0 (no key) when out of memory (star.c). */
uint64_t sup_star_key(const struct tr_mesh *m, uint32_t p, const tr_u32buf *ball,
                      unsigned flags);

/* Two interior Steiner points become one (merge.c): for a neighbour q of interior point
 * p that is an interior Steiner point too, the union of their stars is replaced by the
 * cone from q, from p (then q is the one that goes), or from a double point in the
 * union's kernel, where q moves. *done = 1 if one of them is gone; else the mesh is
 * untouched. */
tr_status sup_merge(struct tr_mesh *m, const sup_ctx *c, uint32_t p, uint32_t region, int dbl,
                    int *done);

#endif
