/* Planar facets (src/core/facets.h) and the conformity validator on merged facets
 * (src/mesh/conform.h): which neighbours merge, and that a mesh whose faces cross an
 * exactly coplanar inner edge validates while one whose "facet" is off by one ulp fails
 * naming the edge. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/facets.h"
#include "core/plc.h"
#include "mesh/conform.h"
#include "mesh/mesh.h"
#include "tcommon.h"
#include "../pipeline/tplc.h"

/* A unit square (two triangles, diagonal 0-2) and a third triangle: in the plane beyond
 * edge 1-2 (merges), or folded back over the square (same side: does not). */
static int square_groups(void)
{
  double x[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0, 0.5, 0.25, 0};
  uint32_t t[] = {0, 1, 2, 0, 2, 3, 1, 4, 2};
  struct tr_plc p = tm_plc_view(x, 6, t, 3, NULL);
  tr_facets F;
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[0] == 0 && F.group[1] == 0 && F.group[2] == 0,
         "three coplanar neighbours: groups %u %u %u", F.group[0], F.group[1], F.group[2]);
  EXPECT(F.ninner == 2 && F.nmerged == 1, "inner %u merged %u", F.ninner, F.nmerged);
  EXPECT(F.inner[0] == ((1u << 1) | (1u << 2)) && F.inner[1] == 1u && F.inner[2] == (1u << 2),
         "inner bits %u %u %u", F.inner[0], F.inner[1], F.inner[2]);
  EXPECT(tr_facets_size(&F, 0) == 3 && F.member[F.start[0]] == 0 &&
             F.member[F.start[0] + 2] == 2,
         "members of facet 0");
  tr_facets_free(&F);
  EXPECT_OK(tr_facets_build(&p, 1, &F), "facets, keep_edges");
  EXPECT(F.group[1] == 1 && F.group[2] == 2 && F.ninner == 0, "keep_edges merged something");
  tr_facets_free(&F);
  /* the third triangle folded over the square: coplanar, same side of edge 0-2 */
  uint32_t t2[] = {0, 1, 2, 2, 0, 5};
  p = tm_plc_view(x, 6, t2, 2, NULL);
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 1 && F.ninner == 0, "folded triangles merged");
  tr_facets_free(&F);
  /* inconsistent orientation: edge 0->2 in both triangles */
  uint32_t t4[] = {0, 1, 2, 0, 3, 2};
  p = tm_plc_view(x, 6, t4, 2, NULL);
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 1, "triangles of opposite orientations merged");
  tr_facets_free(&F);
  return 0;
}

static int markers_differ_no_merge(void)
{
  double x[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  uint32_t t[] = {0, 1, 2, 0, 2, 3};
  int32_t mk[] = {1, 2};
  struct tr_plc p = tm_plc_view(x, 4, t, 2, mk);
  tr_facets F;
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 1 && F.ninner == 0, "triangles with markers 1 and 2 merged");
  tr_facets_free(&F);
  mk[1] = 1;
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 0 && F.ninner == 1, "same markers: not merged");
  tr_facets_free(&F);
  return 0;
}

/* Two coplanar triangles on opposite sides of edge 0-2 and a fin on it: three triangles
 * on the edge, no merge; also one ulp off the plane, no merge. */
static int non_manifold_or_off_plane_no_merge(void)
{
  double x[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1};
  uint32_t t[] = {0, 1, 2, 0, 2, 3, 0, 2, 4};
  struct tr_plc p = tm_plc_view(x, 5, t, 3, NULL);
  tr_facets F;
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[0] == 0 && F.group[1] == 1 && F.group[2] == 2 && F.ninner == 0,
         "non-manifold edge merged");
  tr_facets_free(&F);
  p.ntris = 2;
  x[11] = nextafter(0.0, 1.0);
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 1 && F.ninner == 0, "triangles one ulp off each other's plane merged");
  tr_facets_free(&F);
  x[11] = 0;
  EXPECT_OK(tr_facets_build(&p, 0, &F), "facets");
  EXPECT(F.group[1] == 0 && F.ninner == 1, "the coplanar pair did not merge");
  tr_facets_free(&F);
  return 0;
}

/* The square pyramid (base P Q R S at z = 1, apex T): its Delaunay mesh (two tets) takes
 * one base diagonal; the input surface takes the other. */
static int pyramid_validator(int ulp)
{
  double x[15] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 2};
  if (ulp)
    x[8] = nextafter(1.0, 0.0); /* R one ulp down: the base is no longer one plane */
  tr_mesh *m = NULL;
  EXPECT_OK(tr_delaunay(x, 5, &m), "delaunay");
  /* off the plane, Delaunay adds the flat tet P Q R S between the two pyramids: left out
   * (the validator skips outer tets), the mesh is a pyramid with a folded base */
  for (uint32_t t = 0; t < m->nt; t++) {
    int h4 = 0;
    for (int i = 0; i < 4; i++)
      h4 |= m->tv[4 * (size_t)t + i] == 4;
    if (tr_tet_is_real(m, t) && !h4)
      m->flags[t] |= TR_TF_OUTER;
  }
  uint32_t pr = 0; /* is P-R (0-2) a mesh edge? */
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    int h0 = 0, h2 = 0;
    for (int i = 0; i < 4; i++) {
      h0 |= m->tv[4 * (size_t)t + i] == 0;
      h2 |= m->tv[4 * (size_t)t + i] == 2;
    }
    pr |= h0 && h2;
  }
  /* base triangles with the diagonal the mesh lacks, oriented outward (down) */
  uint32_t t_pr[] = {0, 2, 1, 0, 3, 2, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  uint32_t t_qs[] = {1, 0, 3, 1, 3, 2, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  uint32_t *t = pr ? t_qs : t_pr;
  uint32_t a = pr ? 1 : 0, b = pr ? 3 : 2;
  struct tr_plc p = tm_plc_view(x, 5, t, 6, NULL);
  tr_status s = tr_check_conformity(m, &p, NULL, 0);
  if (!ulp) {
    EXPECT(s == TR_OK, "faces crossing an exactly coplanar inner edge rejected: %s",
           tr_last_error());
    s = tr_check_conformity(m, &p, NULL, TR_CONF_KEEP_EDGES);
    char want[64];
    snprintf(want, sizeof want, "input edge (%u, %u)", a, b);
    EXPECT(s == TR_ERR_INVALID_MESH && strstr(tr_last_error(), want),
           "TR_CONF_KEEP_EDGES accepted the crossed diagonal: %s", tr_last_error());
  } else {
    char want[64];
    snprintf(want, sizeof want, "input edge (%u, %u)", a, b);
    EXPECT(s == TR_ERR_INVALID_MESH && strstr(tr_last_error(), want),
           "a diagonal between triangles one ulp off coplanar was not reported: %s",
           tr_last_error());
  }
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "groups"))
    return square_groups();
  if (!strcmp(c, "markers"))
    return markers_differ_no_merge();
  if (!strcmp(c, "nonmanifold"))
    return non_manifold_or_off_plane_no_merge();
  if (!strcmp(c, "crossed"))
    return pyramid_validator(0);
  if (!strcmp(c, "ulp"))
    return pyramid_validator(1);
  fprintf(stderr, "unknown case '%s'\n", c);
  return 2;
}
