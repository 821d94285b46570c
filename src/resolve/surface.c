/* The surface the pipeline meshes under --resolve (tr_options.resolve; docs/resolve.md):
 * the boundary of the solid by winding number, as a PLC.
 *
 * An input whose solid is bounded by its own triangles as given (every valid closed
 * input) goes through unchanged, so its mesh is the one without --resolve. Otherwise the
 * kept pieces are the PLC; a vertex that is a rational point and no double carries its
 * exact point (tr_plc.xq) and comes after the doubles, and the pipeline inserts it into
 * the Delaunay mesh exactly (src/delaunay/qinsert.c): never a rounded surface. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "resolve/resolve_impl.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* 1 iff piece i is input triangle i as given: its only source, its three corners. */
static int piece_is_triangle(const struct tr_plc *in, const tr_arrangement *arr, uint32_t i)
{
  const tr_arr_piece *x = arr->pieces + i;
  if (x->nsrc != 1 || arr->src[x->src].tri != i || arr->src[x->src].sign != 1)
    return 0;
  for (int k = 0; k < 3; k++) {
    uint32_t v = arr->of_input[in->tris[3 * (size_t)i + k]];
    if (x->v[0] != v && x->v[1] != v && x->v[2] != v)
      return 0;
  }
  return 1;
}

static int on_boundary(int keep)
{
  return keep == TR_SOLID_KEEP || keep == TR_SOLID_FLIP || keep == TR_SOLID_INTERNAL;
}

static int is_rational(const tr_qpoint *q)
{
  return q && (q->err[0] != 0 || q->err[1] != 0 || q->err[2] != 0);
}

/* The kept pieces as a PLC; a vertex that is no double gets its exact point in xq. */
static tr_status build(const struct tr_plc *in, const tr_arrangement *arr, const tr_solid *sol,
                       const uint32_t *vid, uint32_t nv, uint32_t nt, uint32_t nrat,
                       struct tr_plc **out)
{
  double *xyz = malloc(sizeof *xyz * 3 * (size_t)(nv ? nv : 1));
  uint32_t *tris = malloc(sizeof *tris * 3 * (size_t)(nt ? nt : 1));
  int32_t *mk = malloc(sizeof *mk * (nt ? nt : 1));
  uint32_t *srcs = malloc(sizeof *srcs * (nt ? nt : 1));
  double *vs = in->vsize ? malloc(sizeof *vs * (nv ? nv : 1)) : NULL;
  tr_qpoint **xq = nrat ? calloc(nv, sizeof *xq) : NULL;
  uint8_t *inner = nrat ? calloc(nt ? nt : 1, 1) : NULL;
  struct tr_plc *p = NULL;
  tr_status st = TR_OK;
  if (!xyz || !tris || !mk || !srcs || (in->vsize && !vs) || (nrat && (!xq || !inner))) {
    st = tr_error(TR_ERR_NOMEM, "--resolve: out of memory for %u triangles", nt);
    goto done;
  }
  for (uint32_t v = 0; v < arr->nverts; v++) {
    if (vid[v] == TR_ARR_NONE)
      continue;
    const tr_arr_vertex *x = arr->verts + v;
    const double *d = x->q ? x->q->near : in->xyz + 3 * (size_t)x->input;
    memcpy(xyz + 3 * (size_t)vid[v], d, 3 * sizeof *d);
    if (vs) /* a new point has no size of its own: no bound there */
      vs[vid[v]] = x->q ? 0 : in->vsize[x->input];
    if (is_rational(x->q)) {
      tr_qpoint *q = malloc(sizeof *q);
      if (!q) {
        st = tr_error(TR_ERR_NOMEM, "--resolve: out of memory for %u exact points", nrat);
        goto done;
      }
      tr_qpoint_init(q);
      tr_point pq = tr_pt_q(x->q);
      tr_qpoint_set_point(q, &pq);
      xq[vid[v]] = q;
    }
  }
  uint32_t j = 0;
  for (uint32_t i = 0; i < arr->npieces; i++) {
    if (!on_boundary(sol->keep[i]))
      continue;
    const uint32_t *v = arr->pieces[i].v;
    int f = sol->keep[i] == TR_SOLID_FLIP;
    tris[3 * j] = vid[v[0]];
    tris[3 * j + 1] = vid[v[f ? 2 : 1]];
    tris[3 * j + 2] = vid[v[f ? 1 : 2]];
    mk[j] = arr->pieces[i].marker;
    if (inner)
      inner[j] = sol->keep[i] == TR_SOLID_INTERNAL;
    uint32_t t = arr->src[arr->pieces[i].src].tri;
    srcs[j++] = in->tri_source ? in->tri_source[t] : t;
  }
  if ((st = tr_plc_create(&p)) != TR_OK)
    goto done;
  if ((st = tr_plc_set(p, xyz, nv, tris, nt, mk)) == TR_OK)
    st = tr_plc_copy_points(p, in);
  if (st == TR_OK && in->source && !(p->source = strdup(in->source)))
    st = tr_error(TR_ERR_NOMEM, "--resolve: out of memory");
  if (st == TR_OK) {
    p->tri_source = srcs;
    srcs = NULL;
    p->vsize = vs;
    vs = NULL;
    p->xq = xq;
    p->nxq = nrat;
    xq = NULL;
    p->tri_inner = inner;
    inner = NULL;
    *out = p;
    p = NULL;
  }
done:
  tr_plc_destroy(p);
  free(xyz);
  free(tris);
  free(mk);
  free(srcs);
  free(vs);
  for (uint32_t i = 0; xq && i < nv; i++)
    if (xq[i]) {
      tr_qpoint_clear(xq[i]);
      free(xq[i]);
    }
  free(xq);
  free(inner);
  return st;
}

static tr_status check_mode(int mode)
{
  if (mode != 1 && mode != 2)
    return tr_error(TR_ERR_USAGE, "tr_options.resolve is %d: 0 (off), 1 (the union: pieces "
                    "inside the solid dropped) or 2 (kept as internal facets)", mode);
  return TR_OK;
}

tr_status tr_resolve_plc(const struct tr_plc *in, int mode, struct tr_plc **out,
                         tr_resolve_info *info)
{
  *out = NULL;
  memset(info, 0, sizeof *info);
  TR_CHECK(check_mode(mode));
  double c0 = now();
  tr_arrangement arr;
  tr_solid sol;
  memset(&sol, 0, sizeof sol);
  uint32_t *vid = NULL;
  tr_status st = tr_arrangement_build(in, &arr);
  if (st == TR_OK)
    st = tr_solid_classify(in, &arr, mode == 2, &sol);
  if (st != TR_OK)
    goto done;
  info->npairs = arr.npairs;
  info->npieces = arr.npieces;
  info->nkept = sol.nkept;
  info->ninternal = sol.ninternal;
  info->ncomponents = sol.ncomponents;
  if (sol.nkept == 0) {
    st = tr_error(TR_ERR_INPUT, "%s: --resolve: the solid (winding number >= 1) is empty: "
                  "is the surface inside out?", in->source ? in->source : "input");
    goto done;
  }
  /* the input as given bounds its solid: mesh it as it is */
  int same = arr.npieces == in->ntris;
  for (uint32_t i = 0; same && i < arr.npieces; i++)
    same = piece_is_triangle(in, &arr, i) &&
           (sol.keep[i] == TR_SOLID_KEEP || sol.keep[i] == TR_SOLID_INTERNAL);
  if (same) {
    info->identity = 1;
    goto done;
  }
  if (in->nsegs) {
    st = tr_error(TR_ERR_UNSUPPORTED, "%s: --resolve with input segments: not implemented "
                  "(the surface changes and the segments are not cut)",
                  in->source ? in->source : "input");
    goto done;
  }
  if (!(vid = malloc(sizeof *vid * (arr.nverts ? arr.nverts : 1)))) {
    st = tr_error(TR_ERR_NOMEM, "--resolve: out of memory for %u vertices", arr.nverts);
    goto done;
  }
  for (uint32_t v = 0; v < arr.nverts; v++)
    vid[v] = TR_ARR_NONE;
  uint32_t nt = 0, nv = 0, nrat = 0;
  for (uint32_t i = 0; i < arr.npieces; i++)
    if (on_boundary(sol.keep[i])) {
      nt++;
      for (int k = 0; k < 3; k++)
        vid[arr.pieces[i].v[k]] = 0;
    }
  /* vertices in arrangement order (input points in input order, then the new ones), the
   * rational ones last: the Delaunay stage triangulates the doubles first */
  for (int pass = 0; pass < 2; pass++)
    for (uint32_t v = 0; v < arr.nverts; v++) {
      if (vid[v] == TR_ARR_NONE || is_rational(arr.verts[v].q) != pass)
        continue;
      vid[v] = nv++;
      info->nnew += arr.verts[v].q != NULL;
      nrat += pass;
    }
  info->nexact = nrat;
  st = build(in, &arr, &sol, vid, nv, nt, nrat, out);
done:
  free(vid);
  tr_solid_free(&sol);
  tr_arrangement_free(&arr);
  info->seconds = now() - c0;
  return st;
}

tr_status tr_resolve_replace(struct tr_plc **p, const tr_options *opt, int report)
{
  /* An input that validation accepts (its repairs included: merged duplicates, triangles
   * turned to agree with their neighbours and to face outward) is meshed as validated:
   * the same mesh as without --resolve. The arrangement reads the orientation as given,
   * so on such an input turned inside out it would find an empty solid. */
  TR_CHECK(check_mode(opt->resolve));
  if (!(*p)->xq) {
    struct tr_plc *v = NULL;
    TR_CHECK(tr_plc_copy(*p, &v));
    tr_status st = tr_plc_validate(v, opt);
    if (st == TR_OK) {
      if (report)
        fprintf(stderr, "tetrec: resolve: the input is valid as given: meshed as "
                "validated\n");
      tr_plc_destroy(*p);
      *p = v;
      return TR_OK;
    }
    tr_plc_destroy(v);
    if (st == TR_ERR_NOMEM)
      return st;
    tr_error_clear();
  }
  struct tr_plc *r = NULL;
  tr_resolve_info ri;
  TR_CHECK(tr_resolve_plc(*p, opt->resolve, &r, &ri));
  if (report)
    fprintf(stderr, "tetrec: resolve: %llu improper pairs, %u pieces, %u on the boundary, %u "
            "internal, %u new vertices on it (%u exact rationals), %u connected parts%s, %.3f s\n",
            (unsigned long long)ri.npairs, ri.npieces, ri.nkept, ri.ninternal, ri.nnew,
            ri.nexact, ri.ncomponents, ri.identity ? ": the input as given" : "", ri.seconds);
  if (r) {
    tr_plc_destroy(*p);
    *p = r;
  }
  return TR_OK;
}
