/* `tetrec check IN MESH`: rebuild a mesh store from the tets of MESH (neighbours glued by
 * matching faces), run the validator of src/mesh/check.h on it, and compare its exact
 * volume with the volume enclosed by the surface IN. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/mesh.h"

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

static tr_status build(const struct tr_plc *vol, struct tr_mesh **out)
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

tr_status tr_cli_check(const struct tr_plc *surface, const struct tr_plc *vol, int verbose)
{
  struct tr_mesh *m = NULL;
  if (vol->ntets == 0)
    return tr_error(TR_ERR_INVALID_MESH, "the mesh file has no tetrahedra");
  TR_CHECK(build(vol, &m));
  mpq_t v6;
  mpq_init(v6);
  /* A mesh file holds its Steiner points as rounded doubles: a point that was exactly on
   * a facet may now be a hair off it, so the exact volume of the file's mesh need not
   * equal the enclosed volume even when the mesh tetrec built does. Comparing would
   * report a false failure, and any tolerance would hide real ones; so with Steiner points
   * the volume is not compared, and the output says so. */
  int steiner = vol->npoints > surface->npoints;
  tr_status st = tr_input_volume6(surface, v6);
  if (st == TR_OK)
    st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, steiner ? NULL : v6);
  if (st == TR_OK && steiner)
    fprintf(stderr, "tetrec: check: %u Steiner points read as rounded doubles: the exact "
            "volume comparison is skipped (links and orientation checked on the rounded "
            "coordinates)\n", vol->npoints - surface->npoints);
  if (st == TR_OK && verbose)
    fprintf(stderr, "tetrec: check: %u tets, links and orientation are valid%s\n",
            vol->ntets, steiner ? "" : ", volume equals the enclosed volume");
  mpq_clear(v6);
  tr_mesh_destroy(m);
  return st;
}
