/* `tetrec resolve`: the boundary of the solid written in doubles, free of intersections
 * (issue 49 step 4; docs/resolve.md).
 *
 * The exact boundary has rational corners where the input's triangles cross. Rounding
 * them to the nearest doubles moves them by at most half an ulp per coordinate, which can
 * make pieces cross again (two cuts close together, a thin piece turned over) or
 * collapse. So the rounded surface goes through the self-intersection test; while it
 * finds anything, the rounded surface is resolved again (arrangement and solid by winding
 * number) and rounded again. A round only adds vertices where the previous rounding made
 * the surface cross itself, and those lie within a few ulps of rounded vertices, so the
 * iteration settles in a round or two on the models measured. When it does not within the
 * bound, the caller gets an error naming the first pair still crossing: never a surface
 * that still intersects itself without saying so.
 *
 * Internal facets (mode 2) are kept through the rounds by giving them to the next
 * arrangement twice, once in each orientation: their weight is 0, so they change no
 * winding number, and where both sides stay in the solid they come back as internal. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "input/defects.h"
#include "input/validate.h"
#include "resolve/resolve_impl.h"
#include "resolve/snap.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A rounded surface: vertices, triangles (the boundary's, then nint internal ones), the
 * marker and the user's input element of each. */
typedef struct {
  double *xyz;
  uint32_t nv, nt, nint;
  uint32_t *tris, *src;
  int32_t *mk;
} surf;

static void surf_free(surf *s)
{
  free(s->xyz);
  free(s->tris);
  free(s->src);
  free(s->mk);
  memset(s, 0, sizeof *s);
}

/* |p - x|, Euclidean, rounded up a little: the largest rounding move is a bound in the
 * report, so it must not come out low. */
static double displacement(const tr_point *p, const double x[3])
{
  mpq_t d, n;
  mpq_inits(d, n, NULL);
  double s = 0;
  for (int k = 0; k < 3; k++) {
    tr_point_get_q(p, k, d);
    mpq_set_d(n, x[k]);
    mpq_sub(d, d, n);
    double y = fabs(mpq_get_d(d));
    s += y * y;
  }
  mpq_clears(d, n, NULL);
  return sqrt(s) * (1 + 0x1p-50);
}

static int kept(int k)
{
  return k == TR_SOLID_KEEP || k == TR_SOLID_FLIP || k == TR_SOLID_INTERNAL;
}

/* out = the kept pieces of (arr, sol) with every vertex at its nearest double (or float,
 * to_float), vertices that round to one value merged (the first in the arrangement's
 * order names it), and triangles whose corners merged dropped. orig: the user's input
 * element of each triangle of plc. */
static tr_status round_surface(const struct tr_plc *plc, const uint32_t *orig,
                               const tr_arrangement *arr, const tr_solid *sol, int to_float,
                               surf *out, tr_snap_info *info)
{
  uint32_t n = arr->nverts;
  uint32_t *id = malloc(sizeof *id * (n ? n : 1)), *ord = malloc(sizeof *ord * (n ? n : 1));
  double *x = malloc(sizeof *x * 3 * (size_t)(n ? n : 1));
  uint32_t nt = sol->nkept + sol->ninternal;
  out->tris = malloc(sizeof *out->tris * 3 * (size_t)(nt ? nt : 1));
  out->src = malloc(sizeof *out->src * (nt ? nt : 1));
  out->mk = malloc(sizeof *out->mk * (nt ? nt : 1));
  tr_status st = TR_OK;
  if (!id || !ord || !x || !out->tris || !out->src || !out->mk) {
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory for %u vertices", n);
    goto done;
  }
  for (uint32_t v = 0; v < n; v++)
    id[v] = TR_ARR_NONE;
  for (uint32_t i = 0; i < arr->npieces; i++)
    if (kept(sol->keep[i]))
      for (int k = 0; k < 3; k++)
        id[arr->pieces[i].v[k]] = 0;
  uint32_t nused = 0;
  double most = 0;
  for (uint32_t v = 0; v < n; v++) {
    if (id[v] == TR_ARR_NONE)
      continue;
    tr_point p = tr_arr_point(arr, plc, v);
    double *d = x + 3 * (size_t)v;
    memcpy(d, p.d, 3 * sizeof *d);
    /* rational -> double -> float can miss the nearest float by a tie: harmless, the
     * rounded surface is tested exactly as it is */
    for (int k = 0; to_float && k < 3; k++)
      d[k] = (double)(float)d[k];
    if (!isfinite(d[0]) || !isfinite(d[1]) || !isfinite(d[2])) {
      st = tr_error(TR_ERR_INPUT, "%s: resolve: a vertex near %.17g %.17g %.17g is beyond "
                    "the range of %s", plc->source ? plc->source : "input", p.d[0], p.d[1],
                    p.d[2], to_float ? "floats (STL)" : "doubles");
      goto done;
    }
    int moved = p.q && (p.q->err[0] != 0 || p.q->err[1] != 0 || p.q->err[2] != 0);
    for (int k = 0; to_float && k < 3; k++)
      moved |= d[k] != p.d[k];
    if (moved) {
      info->nrounded++;
      double m = displacement(&p, d);
      most = m > most ? m : most;
    }
    ord[nused++] = v;
  }
  info->max_move = most > info->max_move ? most : info->max_move;
  info->move_bound += most;
  /* a stable sort: the first of a run of equal doubles is the least vertex */
  st = tr_sort_ids(ord, nused, tr_cmp_point, x);
  if (st != TR_OK)
    goto done;
  for (uint32_t i = 0; i < nused; i++) /* id = the representative, for now */
    id[ord[i]] = i && tr_cmp_point(x, ord[i - 1], ord[i]) == 0 ? id[ord[i - 1]] : ord[i];
  uint32_t nv = 0;
  for (uint32_t v = 0; v < n; v++) /* representatives numbered in arrangement order */
    if (id[v] == v)
      ord[v] = nv++;
  info->nmerged += nused - nv;
  if (!(out->xyz = malloc(sizeof *out->xyz * 3 * (size_t)(nv ? nv : 1)))) {
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory for %u vertices", nv);
    goto done;
  }
  for (uint32_t v = 0; v < n; v++)
    if (id[v] == v)
      memcpy(out->xyz + 3 * (size_t)ord[v], x + 3 * (size_t)v, 3 * sizeof *x);
  out->nv = nv;
  /* the boundary's pieces, outward, then the internal ones */
  uint32_t j = 0;
  for (int pass = 0; pass < 2; pass++)
    for (uint32_t i = 0; i < arr->npieces; i++) {
      int k = sol->keep[i];
      if (pass == 0 ? k != TR_SOLID_KEEP && k != TR_SOLID_FLIP : k != TR_SOLID_INTERNAL)
        continue;
      const uint32_t *pv = arr->pieces[i].v;
      int f = k == TR_SOLID_FLIP;
      uint32_t a = ord[id[pv[0]]], b = ord[id[pv[f ? 2 : 1]]], c = ord[id[pv[f ? 1 : 2]]];
      if (a == b || b == c || c == a) {
        info->ncollapsed++;
        continue;
      }
      out->tris[3 * j] = a;
      out->tris[3 * j + 1] = b;
      out->tris[3 * j + 2] = c;
      out->mk[j] = arr->pieces[i].marker;
      out->src[j] = orig[arr->src[arr->pieces[i].src].tri];
      j++;
      if (pass == 1)
        out->nint++;
    }
  out->nt = j;
done:
  free(id);
  free(ord);
  free(x);
  return st;
}

/* What `tetrec check-surface` would find in s (src/input/defects.c), but non-manifold
 * edges (the union of solids touching along an edge has them, and so do internal
 * facets): zero-area and duplicate triangles, open edges, then the improper pairs of the
 * others. The first pair goes to first[2] (UINT32_MAX if none). */
static tr_status defects(const surf *s, tr_snap_defects *d, uint32_t first[2])
{
  memset(d, 0, sizeof *d);
  first[0] = first[1] = UINT32_MAX;
  struct tr_plc w;
  memset(&w, 0, sizeof w);
  w.npoints = s->nv;
  w.xyz = s->xyz;
  w.ntris = s->nt;
  w.tris = s->tris;
  tr_surface_defects f;
  tr_status st = tr_surface_defects_find(&w, &f);
  if (st == TR_OK) {
    d->zero = f.nzero;
    d->duplicate = f.ndup;
    d->open = f.nopen;
    d->nonmanifold = f.nnonmanifold;
    d->pairs = f.npairs;
    if (f.npairs) {
      first[0] = f.pairs[0];
      first[1] = f.pairs[1];
    }
  }
  tr_surface_defects_free(&f);
  return st;
}

/* The soup the next round resolves: s, its internal triangles given twice (weight 0). */
static tr_status next_soup(const surf *s, const struct tr_plc *in, struct tr_plc **out,
                           uint32_t **orig)
{
  uint32_t nt = s->nt + s->nint;
  uint32_t *tris = malloc(sizeof *tris * 3 * (size_t)(nt ? nt : 1));
  int32_t *mk = malloc(sizeof *mk * (nt ? nt : 1));
  uint32_t *src = malloc(sizeof *src * (nt ? nt : 1));
  struct tr_plc *p = NULL;
  tr_status st = TR_OK;
  if (!tris || !mk || !src) {
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory for %u triangles", nt);
    goto done;
  }
  memcpy(tris, s->tris, sizeof *tris * 3 * (size_t)s->nt);
  memcpy(mk, s->mk, sizeof *mk * s->nt);
  memcpy(src, s->src, sizeof *src * s->nt);
  for (uint32_t i = 0; i < s->nint; i++) {
    uint32_t t = s->nt - s->nint + i, j = s->nt + i;
    tris[3 * (size_t)j] = s->tris[3 * (size_t)t];
    tris[3 * (size_t)j + 1] = s->tris[3 * (size_t)t + 2];
    tris[3 * (size_t)j + 2] = s->tris[3 * (size_t)t + 1];
    mk[j] = s->mk[t];
    src[j] = s->src[t];
  }
  if ((st = tr_plc_create(&p)) != TR_OK)
    goto done;
  if ((st = tr_plc_set(p, s->xyz, s->nv, tris, nt, mk)) != TR_OK)
    goto done;
  if (in->source && !(p->source = strdup(in->source))) {
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory");
    goto done;
  }
  /* messages of the next round name the user's input elements */
  p->tri_source = src;
  src = NULL;
  *orig = p->tri_source;
  *out = p;
  p = NULL;
done:
  tr_plc_destroy(p);
  free(tris);
  free(mk);
  free(src);
  return st;
}

/* The result as a PLC (hole and region points are the caller's business). */
static tr_status to_plc(const surf *s, const struct tr_plc *in, struct tr_plc **out)
{
  struct tr_plc *p = NULL;
  TR_CHECK(tr_plc_create(&p));
  tr_status st = tr_plc_set(p, s->xyz, s->nv, s->tris, s->nt, s->mk);
  uint32_t *src = st == TR_OK ? malloc(sizeof *src * (s->nt ? s->nt : 1)) : NULL;
  if (st == TR_OK && !src)
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory");
  if (st == TR_OK && in->source && !(p->source = strdup(in->source)))
    st = tr_error(TR_ERR_NOMEM, "resolve: out of memory");
  if (st != TR_OK) {
    free(src);
    tr_plc_destroy(p);
    return st;
  }
  memcpy(src, s->src, sizeof *src * s->nt);
  p->tri_source = src;
  *out = p;
  return TR_OK;
}

static tr_status not_converged(const struct tr_plc *in, const surf *s, const tr_snap_defects *d,
                               const uint32_t first[2], int rounds, int diverges)
{
  const char *name = in->source ? in->source : "input";
  const char *why = diverges ? " (it grows instead of settling: the next round would "
                               "resolve more than twice the first one's triangles)" : "";
  if (first[0] == UINT32_MAX)
    return tr_error(TR_ERR_SELF_INTERSECT, "%s: resolve: after %d rounds of rounding%s the "
                    "surface still has %u zero-area and %u duplicate triangles and "
                    "%u open edges (no crossing pair); nothing written", name, rounds, why, d->zero,
                    d->duplicate, d->open);
  const double *x = s->xyz;
  const uint32_t *a = s->tris + 3 * (size_t)first[0], *b = s->tris + 3 * (size_t)first[1];
  return tr_error(TR_ERR_SELF_INTERSECT, "%s: resolve: after %d rounds of rounding%s the "
                  "surface still intersects itself (%llu pairs); nothing written. The "
                  "first: triangles %u and %u (of input faces %u and %u), corners (%.17g %.17g "
                  "%.17g) (%.17g %.17g %.17g) (%.17g %.17g %.17g) and (%.17g %.17g %.17g) "
                  "(%.17g %.17g %.17g) (%.17g %.17g %.17g)", name, rounds, why,
                  (unsigned long long)d->pairs, first[0], first[1], s->src[first[0]],
                  s->src[first[1]], x[3 * a[0]], x[3 * a[0] + 1], x[3 * a[0] + 2], x[3 * a[1]],
                  x[3 * a[1] + 1], x[3 * a[1] + 2], x[3 * a[2]], x[3 * a[2] + 1],
                  x[3 * a[2] + 2], x[3 * b[0]], x[3 * b[0] + 1], x[3 * b[0] + 2], x[3 * b[1]],
                  x[3 * b[1] + 1], x[3 * b[1] + 2], x[3 * b[2]], x[3 * b[2] + 1],
                  x[3 * b[2] + 2]);
}

tr_status tr_resolve_snap(const struct tr_plc *in, int mode, int to_float, int max_rounds,
                          struct tr_plc **out, tr_snap_info *info)
{
  *out = NULL;
  memset(info, 0, sizeof *info);
  if (mode != 1 && mode != 2)
    return tr_error(TR_ERR_USAGE, "resolve: mode %d: 1 (the union) or 2 (with internal "
                    "facets)", mode);
  if (max_rounds < 1)
    return tr_error(TR_ERR_USAGE, "resolve: at least one round, not %d", max_rounds);
  if (in->nsegs)
    return tr_error(TR_ERR_UNSUPPORTED, "%s: resolve: the input has %u segments; the "
                    "arrangement cuts triangles only, and they would be lost",
                    in->source ? in->source : "input", in->nsegs);
  double t0 = now();
  const struct tr_plc *cur = in;
  struct tr_plc *own = NULL;
  uint32_t *orig0 = malloc(sizeof *orig0 * (in->ntris ? in->ntris : 1));
  if (!orig0)
    return tr_error(TR_ERR_NOMEM, "resolve: out of memory");
  for (uint32_t t = 0; t < in->ntris; t++)
    orig0[t] = in->tri_source ? in->tri_source[t] : t;
  const uint32_t *orig = orig0;
  surf s;
  memset(&s, 0, sizeof s);
  tr_status st = TR_OK;
  uint32_t first_size = 0; /* triangles of the first rounded soup */
  for (int round = 1;; round++) {
    tr_arrangement arr;
    tr_solid sol;
    memset(&sol, 0, sizeof sol);
    st = tr_arrangement_build(cur, &arr);
    if (st == TR_OK)
      st = tr_solid_classify(cur, &arr, mode == 2, &sol);
    if (st == TR_OK && round == 1) {
      info->npairs = arr.npairs;
      info->npieces = arr.npieces;
      info->ncomponents = sol.ncomponents;
      for (uint32_t v = 0; v < arr.nverts; v++)
        info->nnew += arr.verts[v].q != NULL;
    } else if (st == TR_OK)
      info->npairs_later += arr.npairs;
    if (st == TR_OK && sol.nkept == 0)
      st = tr_error(TR_ERR_INPUT, "%s: resolve: the solid (winding number >= 1) is empty: "
                    "is the surface inside out?", in->source ? in->source : "input");
    surf_free(&s);
    if (st == TR_OK)
      st = round_surface(cur, orig, &arr, &sol, to_float, &s, info);
    tr_solid_free(&sol);
    tr_arrangement_free(&arr);
    if (st != TR_OK)
      break;
    info->rounds = round;
    uint32_t first[2];
    if ((st = defects(&s, &info->left, first)) != TR_OK)
      break;
    const tr_snap_defects *d = &info->left;
    if (!d->pairs && !d->zero && !d->duplicate && !d->open) /* non-manifold edges are fine */
      break;
    /* A round resolves the previous one's rounded surface, which should stay about its
     * size: new pieces only where the rounding made crossings. Sheets that the rounding
     * leaves nearly coplanar (internal facets on a rotated coplanar contact) cross each
     * other along long cuts instead, and each round multiplies them; stop that before
     * its arrangement takes minutes. */
    uint32_t next = s.nt + s.nint;
    if (round == 1)
      first_size = next;
    int diverges = round > 1 && next > 2 * (uint64_t)first_size + 64;
    if (round >= max_rounds || diverges) {
      st = not_converged(in, &s, d, first, round, diverges);
      break;
    }
    struct tr_plc *nx = NULL;
    uint32_t *no = NULL;
    if ((st = next_soup(&s, in, &nx, &no)) != TR_OK)
      break;
    tr_plc_destroy(own);
    own = nx;
    cur = nx;
    orig = no;
  }
  if (st == TR_OK) {
    info->ntris = s.nt;
    info->ninternal = s.nint;
    info->nverts = s.nv;
    st = to_plc(&s, in, out);
  }
  surf_free(&s);
  tr_plc_destroy(own);
  free(orig0);
  info->seconds = now() - t0;
  return st;
}
