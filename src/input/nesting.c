/* Nesting of closed shells: which shell lies inside which, and whether a nested shell is
 * a cavity (its inside is not in the domain; its normals are turned into it) or an
 * inclusion (its inside is a region of its own; it stays outward, an internal boundary).
 *
 * Rule (validate.h): a shell directly inside a shell whose inside is in the domain is a
 * cavity iff a hole point lies in it and in none of its own nested shells, or, with no
 * region point there either, it was given facing into itself (negative enclosed volume
 * by the majority of its triangles as read; a tie keeps the former rule, cavity);
 * otherwise an inclusion. A region point asks for its cell to be meshed: TetGen's .poly
 * facets carry no orientation, so an inner box given either way with a region point in
 * it is a region (it was a cavity, and the region point an error, "outside the domain").
 * A shell at top level or directly inside a cavity bounds a body of its own (outward).
 *
 * A shell lies inside another iff a point of it off the other does (shells may share
 * vertices but do not cross: validation checks that after orientation). Point in
 * shell: count the exact crossings of the segment from the point to a point above the
 * whole input with the shell's triangles (tr_classify_segment_triangle). A crossing must
 * be a clean pass through a triangle's interior; if the segment grazes an edge, a vertex
 * or lies in a triangle's plane, another far point is tried. The points tried are the
 * shell's vertices, then the exact centroids of its triangles: a vertex on the other
 * shell makes every segment from it start there, and all the vertices of a shell can be
 * on another (a cavity whose corners touch the outer shell: a voxel left empty among 18,
 * found by the pipeline fuzzer), the interiors of its triangles cannot. Every decision
 * is exact; only the choice of the far points is arbitrary.
 *
 * Cost: a point is tested only against the shells whose bounding box holds it (a
 * uniform grid of the shells' boxes finds them), and a ray only against the triangles
 * whose box meets the ray's box (a thin column for the first, vertical, ray). 1000
 * cavities in a sphere: each cavity tests one shell instead of 1000. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "validate.h"

typedef struct {
  const struct tr_plc *plc;
  const uint32_t *order, *start;
  double *tbox;   /* 6 per triangle (lo, hi), indexed by triangle */
  double *sbox;   /* 6 per shell */
  double glo[3], cell[3];
  int g;          /* grid cells per axis */
  uint32_t *gstart, *gids; /* CSR: the closed shells whose box meets each grid cell */
  uint32_t *stamp, epoch;  /* dedupe of candidates over several cells */
  double zfar, ext;
} nest;

static void pbox(const tr_point *P, double lo[3], double hi[3])
{
  for (int d = 0; d < 3; d++) {
    lo[d] = P->q ? P->q->lo[d] : P->d[d];
    hi[d] = P->q ? P->q->hi[d] : P->d[d];
  }
}

/* 1 inside, 0 outside, -1 undecided (every ray tried was degenerate). */
static int inside(const nest *N, const tr_point *P, uint32_t d)
{
  static const double off[8][2] = {{0, 0},       {0.31, 0.17}, {-0.23, 0.41}, {0.57, -0.29},
                                   {-0.61, -0.37}, {0.13, 0.71}, {0.83, 0.47}, {-0.47, 0.89}};
  const struct tr_plc *plc = N->plc;
  const uint32_t *tris = N->order + N->start[d];
  uint32_t n = N->start[d + 1] - N->start[d];
  double plo[3], phi[3];
  pbox(P, plo, phi);
  for (int k = 0; k < 8; k++) {
    double q[3] = {P->d[0] + off[k][0] * N->ext, P->d[1] + off[k][1] * N->ext, N->zfar};
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
      lo[a] = q[a] < plo[a] ? q[a] : plo[a];
      hi[a] = q[a] > phi[a] ? q[a] : phi[a];
    }
    tr_point Q = tr_pt_d(q);
    int count = 0, clean = 1;
    for (uint32_t i = 0; i < n && clean; i++) {
      const double *b = N->tbox + 6 * (size_t)tris[i];
      if (b[0] > hi[0] || b[1] > hi[1] || b[2] > hi[2] || b[3] < lo[0] || b[4] < lo[1] ||
          b[5] < lo[2])
        continue; /* disjoint boxes: the segment misses the triangle */
      const uint32_t *v = plc->tris + 3 * (size_t)tris[i];
      tr_point A = tr_pt_d(plc->xyz + 3 * (size_t)v[0]), B = tr_pt_d(plc->xyz + 3 * (size_t)v[1]),
               C = tr_pt_d(plc->xyz + 3 * (size_t)v[2]);
      tr_isect r = tr_classify_segment_triangle(P, &Q, &A, &B, &C);
      if (r.n == 0)
        continue;
      if (r.n == 1 && r.end[0].type == TR_FAC && r.end[0].on_seg == TR_SEG_IN)
        count++;
      else
        clean = 0;
    }
    if (clean)
      return count & 1;
  }
  return -1;
}

static int cell_of(const nest *N, double x, int a)
{
  double c = floor((x - N->glo[a]) / N->cell[a]);
  return c < 0 ? 0 : c >= N->g ? N->g - 1 : (int)c;
}

/* The closed shells other than `skip` that contain P: appended to *out (count *n), or
 * -1 if a ray test was undecided. */
static int containers(nest *N, const tr_point *P, uint32_t skip, uint32_t **out, uint32_t *n,
                      uint32_t *cap)
{
  double lo[3], hi[3];
  pbox(P, lo, hi);
  int c0[3], c1[3];
  for (int a = 0; a < 3; a++) {
    c0[a] = cell_of(N, lo[a], a);
    c1[a] = cell_of(N, hi[a], a);
  }
  N->epoch++;
  for (int x = c0[0]; x <= c1[0]; x++)
    for (int y = c0[1]; y <= c1[1]; y++)
      for (int z = c0[2]; z <= c1[2]; z++) {
        size_t cell = ((size_t)x * (size_t)N->g + (size_t)y) * (size_t)N->g + (size_t)z;
        for (uint32_t i = N->gstart[cell]; i < N->gstart[cell + 1]; i++) {
          uint32_t d = N->gids[i];
          if (d == skip || N->stamp[d] == N->epoch)
            continue;
          N->stamp[d] = N->epoch;
          const double *b = N->sbox + 6 * (size_t)d;
          if (b[0] > lo[0] || b[1] > lo[1] || b[2] > lo[2] || b[3] < hi[0] || b[4] < hi[1] ||
              b[5] < hi[2])
            continue; /* P is not in d's closed box: outside d */
          int r = inside(N, P, d);
          if (r < 0)
            return -1;
          if (!r)
            continue;
          if (*n == *cap) {
            uint32_t c = *cap ? 2 * *cap : 16;
            uint32_t *x2 = realloc(*out, sizeof *x2 * c);
            if (!x2)
              return -2;
            *out = x2;
            *cap = c;
          }
          (*out)[(*n)++] = d;
        }
      }
  return 0;
}

static tr_status build(nest *N, const char *closed, uint32_t ncomp)
{
  const struct tr_plc *plc = N->plc;
  uint32_t nt = plc->ntris;
  N->tbox = malloc(sizeof(double) * 6 * (nt ? nt : 1));
  N->sbox = malloc(sizeof(double) * 6 * (ncomp ? ncomp : 1));
  N->stamp = calloc(ncomp ? ncomp : 1, sizeof *N->stamp);
  if (!N->tbox || !N->sbox || !N->stamp)
    return tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
  for (uint32_t c = 0; c < ncomp; c++) {
    double *s = N->sbox + 6 * (size_t)c;
    for (int a = 0; a < 3; a++)
      s[a] = INFINITY, s[3 + a] = -INFINITY;
    for (uint32_t i = N->start[c]; i < N->start[c + 1]; i++) {
      uint32_t t = N->order[i];
      double *b = N->tbox + 6 * (size_t)t;
      for (int a = 0; a < 3; a++) {
        b[a] = INFINITY, b[3 + a] = -INFINITY;
        for (int k = 0; k < 3; k++) {
          double x = plc->xyz[3 * (size_t)plc->tris[3 * (size_t)t + k] + a];
          b[a] = x < b[a] ? x : b[a];
          b[3 + a] = x > b[3 + a] ? x : b[3 + a];
        }
        s[a] = b[a] < s[a] ? b[a] : s[a];
        s[3 + a] = b[3 + a] > s[3 + a] ? b[3 + a] : s[3 + a];
      }
    }
  }
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  uint32_t nclosed = 0;
  for (uint32_t c = 0; c < ncomp; c++) {
    if (!closed[c])
      continue;
    nclosed++;
    for (int a = 0; a < 3; a++) {
      lo[a] = N->sbox[6 * (size_t)c + a] < lo[a] ? N->sbox[6 * (size_t)c + a] : lo[a];
      hi[a] = N->sbox[6 * (size_t)c + 3 + a] > hi[a] ? N->sbox[6 * (size_t)c + 3 + a] : hi[a];
    }
  }
  /* about one shell per cell when they are spread out; a shell spanning many cells
   * (the outer one) is listed in each, which is what its many candidates cost anyway */
  N->g = 1;
  while (N->g < 64 && (uint64_t)N->g * N->g * N->g < nclosed)
    N->g++;
  for (int a = 0; a < 3; a++) {
    N->glo[a] = lo[a];
    N->cell[a] = (hi[a] - lo[a]) / N->g;
    if (!(N->cell[a] > 0) || !isfinite(N->cell[a]))
      N->cell[a] = 1;
  }
  size_t ncell = (size_t)N->g * (size_t)N->g * (size_t)N->g;
  N->gstart = calloc(ncell + 1, sizeof *N->gstart);
  if (!N->gstart)
    return tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
  for (int pass = 0; pass < 2; pass++) {
    for (uint32_t c = 0; c < ncomp; c++) {
      if (!closed[c])
        continue;
      const double *s = N->sbox + 6 * (size_t)c;
      int c0[3], c1[3];
      for (int a = 0; a < 3; a++) {
        c0[a] = cell_of(N, s[a], a);
        c1[a] = cell_of(N, s[3 + a], a);
      }
      for (int x = c0[0]; x <= c1[0]; x++)
        for (int y = c0[1]; y <= c1[1]; y++)
          for (int z = c0[2]; z <= c1[2]; z++) {
            size_t cell = ((size_t)x * (size_t)N->g + (size_t)y) * (size_t)N->g + (size_t)z;
            if (pass == 0)
              N->gstart[cell + 1]++;
            else
              N->gids[N->gstart[cell]++] = c;
          }
    }
    if (pass == 0) {
      for (size_t i = 0; i < ncell; i++)
        N->gstart[i + 1] += N->gstart[i];
      if (N->gstart[ncell] > UINT32_MAX / 2)
        return tr_error(TR_ERR_NOMEM, "too many shells to decide their nesting");
      N->gids = malloc(sizeof *N->gids * (N->gstart[ncell] ? N->gstart[ncell] : 1));
      if (!N->gids)
        return tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
    } else { /* the fill moved each start to the next cell's: shift back */
      for (size_t i = ncell; i > 0; i--)
        N->gstart[i] = N->gstart[i - 1];
      N->gstart[0] = 0;
    }
  }
  return TR_OK;
}

/* The innermost of the shells in list[0..n): the deepest one (they form a chain). */
static uint32_t innermost(const uint32_t *list, uint32_t n, const uint32_t *depth)
{
  uint32_t best = UINT32_MAX;
  for (uint32_t i = 0; i < n; i++)
    if (best == UINT32_MAX || depth[list[i]] > depth[best] ||
        (depth[list[i]] == depth[best] && list[i] < best))
      best = list[i];
  return best;
}

tr_status tr_input_shell_cavities(struct tr_plc *plc, const uint32_t *order,
                                  const uint32_t *start, const char *closed, uint32_t ncomp,
                                  const int8_t *given, const uint32_t *tnum, tr_report *rep,
                                  char *cavity, uint32_t *ncav, uint32_t *nincl)
{
  *ncav = *nincl = 0;
  uint32_t nclosed = 0;
  for (uint32_t c = 0; c < ncomp; c++) {
    cavity[c] = 0;
    nclosed += closed[c] != 0;
  }
  if (nclosed < 2)
    return TR_OK;
  if (plc->nholes && !plc->hole_cavity &&
      !(plc->hole_cavity = calloc(plc->nholes, 1)))
    return tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
  nest N;
  memset(&N, 0, sizeof N);
  N.plc = plc, N.order = order, N.start = start;
  double zmax = -INFINITY, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < plc->npoints; i++)
    for (int d = 0; d < 3; d++) {
      double x = plc->xyz[3 * i + d];
      lo[d] = x < lo[d] ? x : lo[d];
      hi[d] = x > hi[d] ? x : hi[d];
    }
  zmax = hi[2];
  /* Strictly above every vertex; ext only spreads the tries. */
  N.zfar = zmax + (fabs(zmax) + 1), N.ext = (hi[0] - lo[0]) + (hi[1] - lo[1]) + 1;
  if (!isfinite(N.zfar) || !isfinite(N.ext))
    return tr_error(TR_ERR_UNSUPPORTED, "coordinates too large to decide shell nesting");
  uint32_t *depth = calloc(ncomp, sizeof *depth), *parent = malloc(sizeof *parent * ncomp);
  uint32_t *cstart = calloc((size_t)ncomp + 1, sizeof *cstart), *list = NULL, nl = 0, cap = 0;
  uint32_t *byd = malloc(sizeof *byd * ncomp), *holed = calloc(ncomp, sizeof *holed);
  uint32_t *regioned = calloc(ncomp, sizeof *regioned);
  char *dom_in = calloc(ncomp, 1);
  uint32_t *hin = malloc(sizeof *hin * (plc->nholes ? plc->nholes : 1)); /* innermost shell */
  tr_status st = TR_OK;
  if (!depth || !parent || !cstart || !byd || !holed || !regioned || !dom_in || !hin) {
    st = tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
    goto done;
  }
  if ((st = build(&N, closed, ncomp)) != TR_OK)
    goto done;
  /* The containers of every closed shell, listed in list[cstart[c] .. cstart[c+1]). */
  for (uint32_t c = 0; c < ncomp; c++) {
    cstart[c] = nl;
    parent[c] = UINT32_MAX;
    if (!closed[c])
      continue;
    int r = -1;
    uint64_t n = start[c + 1] - start[c];
    /* vertices first (doubles, cheap), then the triangles' centroids */
    for (uint64_t i = 0; i < 4 * n && r == -1; i++) {
      uint32_t t = order[start[c] + i % n];
      nl = cstart[c];
      if (i < 3 * n) {
        tr_point P = tr_pt_d(plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)t + i / n]);
        r = containers(&N, &P, c, &list, &nl, &cap);
      } else {
        tr_qpoint q;
        tr_qpoint_init(&q);
        tr_input_tri_centroid(plc, t, &q);
        tr_point P = tr_pt_q(&q);
        r = containers(&N, &P, c, &list, &nl, &cap);
        tr_qpoint_clear(&q);
      }
    }
    if (r == -2) {
      st = tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
      goto done;
    }
    if (r < 0) {
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "cannot decide whether the shell containing triangle %u is nested in "
                    "another (every ray tried grazes an edge)", tnum[order[start[c]]]);
      goto done;
    }
    depth[c] = nl - cstart[c];
  }
  cstart[ncomp] = nl;
  for (uint32_t c = 0; c < ncomp; c++)
    if (closed[c] && depth[c])
      parent[c] = innermost(list + cstart[c], depth[c], depth);
  /* Hole points, then region points: the innermost shell around each (one on a shell
   * decides nothing here; the coloring stage rejects it). */
  {
    uint32_t *hl = NULL, hn = 0, hcap = 0;
    for (uint32_t h = 0; h < plc->nholes + plc->nregions; h++) {
      int hole = h < plc->nholes;
      uint32_t i = hole ? h : h - plc->nholes;
      tr_point P = tr_pt_d(hole ? plc->holes + 3 * (size_t)i : plc->region_xyz + 3 * (size_t)i);
      hn = 0;
      if (hole)
        hin[i] = UINT32_MAX;
      int r = containers(&N, &P, UINT32_MAX, &hl, &hn, &hcap);
      if (r == -2) {
        free(hl);
        st = tr_error(TR_ERR_NOMEM, "out of memory deciding shell nesting");
        goto done;
      }
      if (r == 0 && hn) {
        uint32_t c = innermost(hl, hn, depth);
        uint32_t *mark = hole ? holed : regioned;
        if (!mark[c])
          mark[c] = i + 1;
        if (hole)
          hin[i] = c;
      }
    }
    free(hl);
  }
  /* Outer shells first: a shell's kind depends on its parent's. */
  uint32_t maxd = 0, k = 0;
  for (uint32_t c = 0; c < ncomp; c++)
    if (closed[c] && depth[c] > maxd)
      maxd = depth[c];
  for (uint32_t d = 0; d <= maxd; d++) /* few levels in practice; linear per level */
    for (uint32_t c = 0; c < ncomp; c++)
      if (closed[c] && depth[c] == d)
        byd[k++] = c;
  for (uint32_t i = 0; i < k; i++) {
    uint32_t c = byd[i], p = parent[c];
    if (p == UINT32_MAX || !dom_in[p]) {
      dom_in[c] = 1; /* a body of its own: at top level, or an island in a cavity */
      continue;
    }
    uint32_t t0 = tnum[order[start[c]]], tp = tnum[order[start[p]]];
    if (holed[c] || (!regioned[c] && given[c] <= 0)) {
      cavity[c] = 1;
      (*ncav)++;
      if (holed[c])
        tr_report_add(rep, TR_REP_SHELL,
                      "shell of triangle %u (inside the shell of triangle %u) is a cavity: "
                      "hole point %u lies in it", t0, tp, holed[c] - 1);
      else if (given[c] < 0)
        tr_report_add(rep, TR_REP_SHELL,
                      "shell of triangle %u (inside the shell of triangle %u) is a cavity: "
                      "it faces into itself as given", t0, tp);
      else
        tr_report_add(rep, TR_REP_SHELL,
                      "shell of triangle %u (inside the shell of triangle %u) is a cavity: "
                      "as many of its triangles face in as out, so the nesting decides",
                      t0, tp);
    } else {
      dom_in[c] = 1;
      (*nincl)++;
      if (given[c] <= 0)
        tr_report_add(rep, TR_REP_SHELL,
                      "shell of triangle %u (inside the shell of triangle %u) is an inclusion, "
                      "a region of its own: region point %u lies in it (a hole point in it "
                      "would make it a cavity)", t0, tp, regioned[c] - 1);
      else
        tr_report_add(rep, TR_REP_SHELL,
                      "shell of triangle %u (inside the shell of triangle %u) is an inclusion, "
                      "a region of its own: it faces outward as given (reverse it, or put a "
                      "hole point in it, to make it a cavity)", t0, tp);
    }
  }
  /* Every hole point in a cavity, not only the one that named it, did what it asked
   * (the outer stage finds it in no tet and must not call it outside the domain); the
   * cavity is its doing unless the shell was given facing into itself anyway. */
  for (uint32_t h = 0; h < plc->nholes && plc->hole_cavity; h++)
    if (hin[h] != UINT32_MAX && cavity[hin[h]])
      plc->hole_cavity[h] = !regioned[hin[h]] && given[hin[h]] <= 0 ? TR_HOLE_IN_CAVITY
                                                                     : TR_HOLE_EMPTIED;
done:
  free(hin);
  free(N.tbox);
  free(N.sbox);
  free(N.stamp);
  free(N.gstart);
  free(N.gids);
  free(depth);
  free(parent);
  free(cstart);
  free(list);
  free(byd);
  free(holed);
  free(regioned);
  free(dom_in);
  return st;
}
