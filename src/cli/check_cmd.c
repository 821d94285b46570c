/* `tetrec check IN MESH`: rebuild a mesh store from the tets of MESH (neighbours glued by
 * matching faces), run the validator of src/mesh/check.h on it and, when every vertex is
 * known exactly (no Steiner point, or an --exact .node whose num/den coordinates are read
 * as rationals), the exact conformity validator of src/mesh/conform.h and the exact
 * volume comparison with the volume enclosed by the surface IN. */
#include <gmp.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "mesh/mesh.h"
#include "output/deviation.h"
#include "refine/quality.h"
#include "refine/refine_stage.h"
#include "smooth/smooth.h"

typedef struct {
  const uint32_t *key; /* 3 sorted vertices per face */
} facectx;

static int cmp_face(const void *ctx, uint32_t a, uint32_t b)
{
  const uint32_t *k = ((const facectx *)ctx)->key;
  for (int i = 0; i < 3; i++)
    if (k[3 * (size_t)a + i] != k[3 * (size_t)b + i])
      return k[3 * (size_t)a + i] < k[3 * (size_t)b + i] ? -1 : 1;
  return 0;
}

static tr_status build(const struct tr_plc *vol, tr_qpoint **exact, struct tr_mesh **out)
{
  struct tr_mesh *m = NULL;
  uint32_t nf = 4 * vol->ntets;
  uint32_t *key = malloc(sizeof *key * 3 * (size_t)(nf ? nf : 1));
  uint32_t *ord = malloc(sizeof *ord * (nf ? nf : 1));
  tr_status st = key && ord ? TR_OK : tr_error(TR_ERR_NOMEM, "out of memory");
  if (st == TR_OK)
    st = tr_mesh_create(vol->npoints, vol->ntets, &m);
  for (uint32_t i = 0; st == TR_OK && i < vol->npoints; i++) {
    uint32_t idx;
    if (exact && exact[i]) {
      st = tr_mesh_add_steiner(m, exact[i], &idx);
      if (st == TR_OK)
        exact[i] = NULL;
    } else
      st = tr_mesh_add_vertex(m, vol->xyz + 3 * (size_t)i, &idx);
  }
  for (uint32_t t = 0; st == TR_OK && t < vol->ntets; t++) {
    const uint32_t *v = vol->tets + 4 * (size_t)t;
    uint32_t id;
    if (v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] ||
        v[2] == v[3])
      st = tr_error(TR_ERR_INVALID_MESH, "tet %u repeats a vertex", t);
    else
      st = tr_tet_new(m, v[0], v[1], v[2], v[3], &id);
  }
  for (uint32_t f = 0; st == TR_OK && f < nf; f++) {
    uint32_t s[3];
    for (int i = 0; i < 3; i++)
      s[i] = vol->tets[4 * (size_t)(f / 4) + tr_face_vtx[f % 4][i]];
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2 - i; j++)
        if (s[j] > s[j + 1]) {
          uint32_t x = s[j];
          s[j] = s[j + 1];
          s[j + 1] = x;
        }
    memcpy(key + 3 * (size_t)f, s, sizeof s);
    ord[f] = f;
  }
  facectx c = {key};
  if (st == TR_OK)
    st = tr_sort_ids(ord, nf, cmp_face, &c);
  for (uint32_t i = 0; st == TR_OK && i < nf;) {
    uint32_t j = i + 1;
    while (j < nf && cmp_face(&c, ord[i], ord[j]) == 0)
      j++;
    if (j - i > 2)
      st = tr_error(TR_ERR_INVALID_MESH, "face (%u, %u, %u) is shared by %u tets",
                    key[3 * (size_t)ord[i]], key[3 * (size_t)ord[i] + 1],
                    key[3 * (size_t)ord[i] + 2], j - i);
    else if (j - i == 2)
      tr_glue(m, ord[i] / 4, (int)(ord[i] % 4), ord[i + 1] / 4, (int)(ord[i + 1] % 4));
    i = j;
  }
  free(key);
  free(ord);
  if (st != TR_OK) {
    tr_mesh_destroy(m);
    return st;
  }
  *out = m;
  return TR_OK;
}

/* A copy of p's triangles and segments with the pipeline's diagonal swaps applied;
 * *nswaps = how many. */
static tr_status smoothed_copy(const struct tr_plc *p, struct tr_plc **out, uint64_t *nswaps)
{
  *nswaps = 0;
  TR_CHECK(tr_plc_create(out));
  struct tr_plc *c = *out;
  tr_status st = tr_plc_set(c, p->xyz, p->npoints, p->tris, p->ntris, p->tri_marker);
  if (st == TR_OK && p->nsegs) {
    c->segs = malloc(sizeof *c->segs * 2 * (size_t)p->nsegs);
    if (!c->segs)
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    else {
      memcpy(c->segs, p->segs, sizeof *c->segs * 2 * (size_t)p->nsegs);
      c->nsegs = p->nsegs;
    }
  }
  if (st == TR_OK)
    st = tr_smooth_surface(c, nswaps);
  if (st != TR_OK) {
    tr_plc_destroy(c);
    *out = NULL;
  }
  return st;
}

/* Exact conformity to the surface; `tetrec mesh` swaps coplanar diagonals of the surface
 * by default (src/smooth), so a mesh that does not conform to IN's own triangles is
 * checked again against IN with those swaps: the same point set, the same facets. */
static tr_status conformity(const struct tr_mesh *m, const struct tr_plc *surface,
                            mpq_srcptr v6, unsigned flags, int *smoothed)
{
  *smoothed = 0;
  tr_status st = tr_check_conformity(m, surface, v6, flags);
  /* no swaps on exact corners (the pipeline makes none there): a copy in doubles would
   * check a rounded surface */
  if (st != TR_ERR_INVALID_MESH || surface->xq)
    return st;
  char first[512];
  snprintf(first, sizeof first, "%s", tr_last_error());
  struct tr_plc *c = NULL;
  uint64_t nswaps = 0;
  tr_status st2 = smoothed_copy(surface, &c, &nswaps);
  if (st2 == TR_OK && nswaps == 0)
    st2 = tr_error(st, "%s", first);
  else if (st2 == TR_OK) {
    st2 = tr_check_conformity(m, c, v6, flags);
    if (st2 == TR_OK)
      *smoothed = 1;
    else if (st2 == TR_ERR_INVALID_MESH) {
      char second[512];
      snprintf(second, sizeof second, "%s", tr_last_error());
      st2 = tr_error(st2, "%s (and with the surface's coplanar diagonals swapped as "
                     "`tetrec mesh` does: %s)", first, second);
    }
  }
  tr_plc_destroy(c);
  return st2;
}

/* The distance of the rounded Steiner points from the surface, measured on those that lie
 * on a constraint only: the vertices of the mesh's boundary faces and of the faces the
 * mesh file lists (internal facets). A refined mesh has interior points near the surface,
 * whose distance from it says nothing about rounding. */
static tr_status constrained_distance(const struct tr_mesh *m, const struct tr_plc *surface,
                                      const struct tr_plc *vol, double *dev, uint32_t *far)
{
  uint8_t *on = calloc(vol->npoints ? vol->npoints : 1, 1);
  if (!on)
    return tr_error(TR_ERR_NOMEM, "out of memory");
  for (uint32_t t = 0; t < vol->ntets; t++)
    for (int k = 0; k < 4; k++)
      if (m->tn[4 * (size_t)t + k] == TR_NONE)
        for (int i = 0; i < 3; i++)
          on[vol->tets[4 * (size_t)t + tr_face_vtx[k][i]]] = 1;
  for (size_t i = 0; i < 3 * (size_t)vol->ntris; i++)
    if (vol->tris[i] < vol->npoints)
      on[vol->tris[i]] = 1;
  tr_status st = tr_plc_points_distance(surface, vol->xyz, surface->npoints, vol->npoints, on,
                                        dev, far);
  free(on);
  return st;
}

/* The tets of m over the radius-edge and volume bounds and under the dihedral target of
 * opt, one line (a benchmark compares tetrec's and a peer's meshes with it). */
static tr_status print_bounds(const struct tr_mesh *m, const tr_options *opt)
{
  tr_refine_over over = {0, 0, 0};
  if (opt->quality_ratio > 0 || opt->max_volume > 0)
    TR_CHECK(tr_refine_count_over(m, NULL, opt, &over));
  uint32_t n = tr_mesh_num_tets(m);
  fprintf(stderr, "tetrec: check: bounds: %u tets", n);
  if (opt->quality_ratio > 0)
    fprintf(stderr, ", %llu (%.2f%%) over radius-edge %g", (unsigned long long)over.ratio,
            n ? 100.0 * (double)over.ratio / n : 0.0, opt->quality_ratio);
  if (opt->max_volume > 0)
    fprintf(stderr, ", %llu (%.2f%%) over volume %g", (unsigned long long)over.volume,
            n ? 100.0 * (double)over.volume / n : 0.0, opt->max_volume);
  if (opt->quality_min_dihedral > 0) {
    uint64_t under = tr_quality_count_below(m, opt->quality_min_dihedral);
    fprintf(stderr, ", %llu (%.2f%%) with a dihedral angle under %g degrees",
            (unsigned long long)under, n ? 100.0 * (double)under / n : 0.0,
            opt->quality_min_dihedral);
  }
  fputc('\n', stderr);
  return TR_OK;
}

tr_status tr_cli_check(const struct tr_plc *surface, const struct tr_plc *vol, tr_qpoint **exact,
                       int exact_file, int allow_open, int verbose, const tr_options *bounds)
{
  struct tr_mesh *m = NULL;
  if (vol->ntets == 0)
    return tr_error(TR_ERR_INVALID_MESH, "the mesh file has no tetrahedra");
  TR_CHECK(build(vol, exact, &m));
  mpq_t v6;
  mpq_init(v6);
  /* Without --exact a mesh file holds its Steiner points as rounded doubles (moved where
   * needed to keep every tet positive): a point that was exactly on a facet is a hair off
   * it, so neither exact conformity nor the exact volume can be verified on them, and any
   * tolerance would hide real failures. Then links and orientation are checked exactly on
   * the doubles, and the output says what was skipped. With an open surface the mesh
   * fills its convex hull: the enclosed volume means nothing. */
  uint32_t nsteiner = vol->npoints > surface->npoints ? vol->npoints - surface->npoints : 0;
  int smoothed = 0;
  mpq_srcptr vol6 = allow_open ? NULL : v6;
  tr_status st = tr_input_domain_volume6(surface, v6); /* internal facets, cracks too */
  /* The full exact check first, also on doubles: Steiner points strictly inside the
   * domain (--keep-surface, suppressed surface points) are plain doubles, and then nothing
   * is left unverified. Only doubles that fail it are taken as rounded. */
  /* --surface-tolerance: the mesh bounds a surface near the input, not the input:
   * links and orientation, then the two-sided bound instead of conformity */
  double tol = bounds && bounds->size >= offsetof(tr_options, surface_tolerance) +
                                             sizeof(double) ? bounds->surface_tolerance : 0;
  if (st == TR_OK && tol > 0) {
    st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
    if (st == TR_OK && verbose)
      fprintf(stderr, "tetrec: check: %u tets, links and orientation are valid\n",
              vol->ntets);
    if (st == TR_OK)
      st = tr_cli_check_tolerance(m, surface, vol, tol, verbose);
  }
  if (st == TR_OK && tol <= 0)
    st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol6);
  if (st == TR_OK && tol <= 0)
    st = conformity(m, surface, vol6, allow_open ? TR_CONF_OPEN : 0, &smoothed);
  /* --resolve's rational corners are input vertices that a file of doubles rounds too */
  int rounded = st == TR_ERR_INVALID_MESH && (nsteiner || surface->nxq) && !exact_file &&
                tol <= 0;
  if (rounded)
    st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
  int with_volume = !rounded && !allow_open;
  if (st == TR_OK && rounded)
    fprintf(stderr, "tetrec: check: %u Steiner points%s read as rounded doubles: exact "
            "conformity and the exact volume cannot be verified on them (write the mesh with "
            "--exact for that); links and orientation checked exactly on the doubles\n",
            nsteiner, surface->nxq ? " and the surface's rational corners" : "");
  double dev = 0;
  uint32_t far = 0;
  if (st == TR_OK && rounded)
    st = constrained_distance(m, surface, vol, &dev, &far);
  if (st == TR_OK && rounded && verbose)
    fprintf(stderr, "tetrec: check: the rounded Steiner points on the surface lie at most %.3g of "
            "the bounding box diagonal from it%s\n", dev,
            dev > 0x1p-40 ? " (above 2^-40: write the mesh with --exact to have them exactly)"
                          : "");
  if (st == TR_OK && verbose && tol <= 0) {
    if (rounded)
      fprintf(stderr, "tetrec: check: %u tets, links and orientation are valid\n", vol->ntets);
    else
      fprintf(stderr, "tetrec: check: %u tets%s, links and orientation are valid, the mesh "
              "conforms exactly to the surface%s%s\n", vol->ntets,
              !nsteiner ? "" : exact_file ? " (Steiner points read exactly)"
                                          : " (Steiner points as written, exactly)",
              smoothed ? " with its coplanar diagonals swapped" : "",
              with_volume ? ", volume equals the enclosed volume" : "");
  }
  if (verbose) {
    /* the shape of the tets, on the file's doubles (the nearest ones for exact points);
     * also when a check failed, so that a benchmark can compare meshes tetrec rejects */
    tr_quality q;
    tr_quality_measure(m, &q);
    tr_quality_print(stderr, "tetrec: check: ", &q);
    if (bounds && (bounds->quality_ratio > 0 || bounds->max_volume > 0 ||
                   bounds->quality_min_dihedral > 0)) {
      tr_status sb = print_bounds(m, bounds);
      st = st == TR_OK ? sb : st;
    }
  }
  mpq_clear(v6);
  tr_mesh_destroy(m);
  return st;
}
