/* Unit tests of the suppression steps (src/suppress/suppress.h) on exact configurations
 * built here: the un-split of a fan (ear clipping in a triangle's plane), full removal
 * and relocation of a Steiner point on an input edge and inside an input triangle. Every
 * mesh goes through the mesh validator after the change and, compacted, through the
 * exact conformity validator against its PLC. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "suppress/suppress.h"

#include "../pipeline/texpect.h"
#include "keepcheck.h"

/* ---- the un-split: ear clipping ---- */

/* 2 * signed area of a polygon of small integer points in the z = 0 plane (exact). */
static double area2(const struct tr_mesh *m, const uint32_t *poly, uint32_t n)
{
  double s = 0;
  for (uint32_t i = 0; i < n; i++) {
    const double *a = m->xyz + 3 * (size_t)poly[i], *b = m->xyz + 3 * (size_t)poly[(i + 1) % n];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s;
}

static void ear_clipping(void)
{
  /* a star-shaped polygon with reflex vertices and three collinear vertices, in the
   * plane z = 0 of the input triangle (0,0,0) (1,0,0) (0,1,0) */
  static const double pts[][2] = {{0, 0}, {4, 0}, {8, 0}, {8, 8}, {4, 3}, {0, 8}, {2, 4}};
  struct tr_mesh *m = NULL;
  tr_status s = tr_mesh_create(8, 8, &m);
  EXPECT(s == TR_OK, "create");
  uint32_t poly[7], id;
  for (int i = 0; i < 7; i++) {
    double x[3] = {pts[i][0], pts[i][1], 0};
    tr_mesh_add_vertex(m, x, &id);
    poly[i] = id;
  }
  double tx[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  uint32_t tt[3] = {0, 1, 2};
  tr_plc *plc = NULL;
  tr_plc_create(&plc);
  tr_plc_set(plc, tx, 3, tt, 1, NULL);
  int drop = -1, sign = 0;
  s = tr_sup_plane(plc, 0, &drop, &sign);
  EXPECT(s == TR_OK && drop == 2 && sign != 0, "plane of z = 0: drop %d sign %d", drop, sign);
  uint32_t out[15];
  s = tr_sup_triangulate(m, drop, sign, poly, 7, out);
  EXPECT(s == TR_OK, "triangulate: %s", tr_last_error());
  double total = 0;
  for (int i = 0; i < 5 && s == TR_OK; i++) {
    double a = area2(m, out + 3 * i, 3);
    EXPECT(a > 0, "ear %d (%u %u %u) is not counter-clockwise", i, out[3 * i], out[3 * i + 1],
           out[3 * i + 2]);
    total += a;
  }
  EXPECT(total == area2(m, poly, 7), "ears cover %g, polygon %g", total, area2(m, poly, 7));
  /* a clockwise polygon has no ear */
  uint32_t cw[3] = {poly[0], poly[3], poly[1]};
  s = tr_sup_triangulate(m, drop, sign, cw, 3, out);
  EXPECT(s == TR_ERR_INTERNAL, "a clockwise triangle was accepted");
  tr_plc_destroy(plc);
  tr_mesh_destroy(m);
}

/* ---- a tet split by one Steiner point ---- */

/* The PLC of the tet a b c d = (0,0,0) (4,0,0) (0,4,0) (0,0,4), oriented by validation. */
static tr_plc *tet_plc(void)
{
  double x[12] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4};
  uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  tr_plc *p = NULL;
  tr_plc_create(&p);
  tr_plc_set(p, x, 4, t, 4, NULL);
  tr_status s = tr_plc_validate(p, NULL);
  EXPECT(s == TR_OK, "tet PLC: %s", tr_last_error());
  return p;
}

/* The mesh of the tet with Steiner point p (vertex 4) at the exact rational `at`, which
 * lies on edge {0,1} (edge = 1) or inside triangle {0,1,2} (edge = 0): the tet split into
 * the tets joining p to the faces not containing it, and the sub-faces of the input
 * triangles accordingly. */
static struct tr_mesh *split_tet(const tr_plc *plc, const char *at[3], int edge,
                                 tr_subfaces *sub)
{
  struct tr_mesh *m = NULL;
  tr_mesh_create(8, 8, &m);
  uint32_t id;
  for (int i = 0; i < 4; i++)
    tr_mesh_add_vertex(m, plc->xyz + 3 * i, &id);
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  for (int k = 0; k < 3; k++)
    mpq_set_str(q->c[k], at[k], 10);
  tr_qpoint_update(q);
  tr_mesh_add_steiner(m, q, &id);
  tr_mesh_enable_regions(m);
  /* positive order of the tet */
  uint32_t v[4] = {0, 1, 2, 3};
  tr_point P[4];
  for (int i = 0; i < 4; i++)
    P[i] = tr_mesh_point(m, v[i]);
  if (tr_orient3d_p(&P[0], &P[1], &P[2], &P[3]) < 0) {
    v[0] = 1;
    v[1] = 0;
  }
  /* p replaces, in turn, each vertex of the edge or triangle it lies on; the new tets
   * are glued where they share a face (tr_mesh_replace cannot split the tet's boundary
   * faces, so they are built here) */
  uint32_t ids[3], nn = 0;
  for (int i = 0; i < 4; i++) {
    uint32_t w = v[i], nv[4];
    if (w == 3 || (edge && w == 2))
      continue;
    memcpy(nv, v, sizeof v);
    nv[i] = 4;
    tr_tet_new(m, nv[0], nv[1], nv[2], nv[3], &ids[nn++]);
  }
  for (uint32_t i = 0; i < nn; i++)
    for (uint32_t j = i + 1; j < nn; j++)
      for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++) {
          uint32_t fa[3], fb[3];
          for (int k = 0; k < 3; k++) {
            fa[k] = m->tv[4 * ids[i] + tr_face_vtx[a][k]];
            fb[k] = m->tv[4 * ids[j] + tr_face_vtx[b][k]];
          }
          tr_sort3(fa);
          tr_sort3(fb);
          if (!memcmp(fa, fb, sizeof fa))
            tr_glue(m, ids[i], a, ids[j], b);
        }
  for (uint32_t t = 0; t < m->nt; t++)
    m->region[t] = 1;
  /* sub-faces: each input triangle with p on it is split the same way */
  sub->n = 0;
  sub->v = malloc(sizeof *sub->v * 3 * 8);
  sub->tri = malloc(sizeof *sub->tri * 8);
  uint32_t lim = edge ? 1 : 2; /* p lies on the vertices 0..lim's edge or triangle */
  for (uint32_t j = 0; j < plc->ntris; j++) {
    const uint32_t *f = plc->tris + 3 * j;
    int on = (f[0] <= lim) + (f[1] <= lim) + (f[2] <= lim) == (int)lim + 1;
    for (int i = 0; i < 3; i++) {
      if (on ? f[i] > lim : i > 0)
        continue;
      uint32_t *o = sub->v + 3 * sub->n;
      memcpy(o, f, 3 * sizeof *o);
      if (on)
        o[i] = 4;
      sub->tri[sub->n++] = j;
    }
  }
  return m;
}

/* The mesh validator and the exact conformity validator against the PLC (6 * volume of
 * the tet = 64) on m as it is; with final, also on the compacted mesh (which takes the
 * Steiner points out of m), and keep: its boundary faces must be the input triangles. */
static void validate(struct tr_mesh *m, const tr_plc *plc, int final, int keep, const char *what)
{
  tr_status s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", what, tr_last_error());
  mpq_t v;
  mpq_init(v);
  mpq_set_ui(v, 64, 1);
  s = tr_check_conformity(m, plc, v, 0);
  EXPECT(s == TR_OK, "%s: conformity: %s", what, tr_last_error());
  struct tr_mesh *o = NULL;
  if (final && (s = tr_pipeline_compact(m, NULL, &o)) == TR_OK) {
    s = tr_check_mesh(o, TR_CHK_TOPOLOGY, NULL);
    EXPECT(s == TR_OK, "%s: compacted mesh: %s", what, tr_last_error());
    s = tr_check_conformity(o, plc, v, 0);
    EXPECT(s == TR_OK, "%s: compacted conformity: %s", what, tr_last_error());
    char why[256];
    if (keep)
      EXPECT(keep_surface_holds(o, plc, why, sizeof why) == 0, "%s: surface: %s", what, why);
  }
  mpq_clear(v);
  tr_mesh_destroy(o);
}

static void run_split(const char *at[3], int edge, unsigned flags, int expect_done,
                      const char *what)
{
  tr_plc *plc = tet_plc();
  tr_subfaces sub;
  memset(&sub, 0, sizeof sub);
  struct tr_mesh *m = split_tet(plc, at, edge, &sub);
  validate(m, plc, 0, 0, "before");
  uint32_t nsub0 = sub.n;
  tr_suppress_stats st;
  tr_status s = tr_suppress_steiner(m, &sub, plc, flags, &st);
  EXPECT(s == TR_OK, "%s: %s", what, tr_last_error());
  uint64_t done = expect_done == 1 ? st.removed : st.relocated;
  EXPECT(done == 1 && st.removed + st.relocated == 1, "%s: removed %llu relocated %llu", what,
         (unsigned long long)st.removed, (unsigned long long)st.relocated);
  EXPECT(sub.n == 4, "%s: %u sub-faces left of %u, want the 4 input triangles", what, sub.n,
         nsub0);
  for (uint32_t j = 0; j < sub.n; j++) {
    EXPECT(sub.tri[j] == j, "%s: sub-face %u is on triangle %u", what, j, sub.tri[j]);
    uint32_t a[3], b[3];
    memcpy(a, sub.v + 3 * j, sizeof a);
    memcpy(b, plc->tris + 3 * sub.tri[j], sizeof b);
    tr_rotate_min3(a);
    tr_rotate_min3(b);
    EXPECT(!memcmp(a, b, sizeof a), "%s: sub-face %u is not its triangle, same turn", what, j);
  }
  EXPECT(st.on_edges == 0 && st.on_facets == 0 && st.interior == (expect_done == 2),
         "%s: counts %llu/%llu/%llu", what, (unsigned long long)st.on_edges,
         (unsigned long long)st.on_facets, (unsigned long long)st.interior);
  uint32_t nt = tr_mesh_count_real(m);
  if (expect_done == 1) {
    EXPECT(nt == 1, "%s: %u tets after full removal, want the tet itself", what, nt);
    EXPECT(m->v2t[4] == TR_NONE, "%s: p is still used", what);
  } else {
    /* p is a double strictly inside: four tets, its exact point equal to its double */
    EXPECT(nt == 4, "%s: %u tets after relocation, want the cone of 4", what, nt);
    mpq_t x;
    mpq_init(x);
    for (int k = 0; k < 3; k++) {
      mpq_set_d(x, m->xyz[12 + k]);
      EXPECT(mpq_equal(x, m->vq[4]->c[k]), "%s: coordinate %d is not its double", what, k);
      EXPECT(m->xyz[12 + k] > 0, "%s: coordinate %d = %g is not inside", what, k, m->xyz[12 + k]);
    }
    mpq_clear(x);
  }
  validate(m, plc, 1, 1, what);
  tr_pipeline_subfaces_free(&sub);
  tr_mesh_destroy(m);
  tr_plc_destroy(plc);
}

/* keepcheck.h itself: the meshes before suppression have a split edge or facet. */
static void check_split(const char *at[3], int edge)
{
  tr_plc *plc = tet_plc();
  tr_subfaces sub;
  memset(&sub, 0, sizeof sub);
  struct tr_mesh *m = split_tet(plc, at, edge, &sub), *o = NULL;
  validate(m, plc, 0, 0, "split");
  tr_status s = tr_pipeline_compact(m, NULL, &o);
  char why[256] = "";
  EXPECT(s == TR_OK && keep_surface_holds(o, plc, why, sizeof why) != 0,
         "the surface check passed a split %s", edge ? "edge" : "facet");
  EXPECT(strstr(why, "Steiner point 4"), "the check does not name the point: %s", why);
  tr_mesh_destroy(o);
  tr_pipeline_subfaces_free(&sub);
  tr_mesh_destroy(m);
  tr_plc_destroy(plc);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  /* on edge {0,1} at 4/3 (not a double's nearest-is-exact case), and inside {0,1,2} */
  const char *on_edge[3] = {"4/3", "0", "0"};
  const char *in_tri[3] = {"1/3", "5/7", "0"};
  if (!strcmp(c, "ears"))
    ear_clipping();
  else if (!strcmp(c, "remove_edge"))
    run_split(on_edge, 1, TR_SUP_REMOVE, 1, "removal on an edge");
  else if (!strcmp(c, "remove_facet"))
    run_split(in_tri, 0, TR_SUP_REMOVE, 1, "removal inside a facet");
  else if (!strcmp(c, "relocate_edge"))
    run_split(on_edge, 1, TR_SUP_RELOCATE, 2, "relocation from an edge");
  else if (!strcmp(c, "relocate_facet"))
    run_split(in_tri, 0, TR_SUP_RELOCATE, 2, "relocation from a facet");
  else if (!strcmp(c, "check_split")) {
    check_split(on_edge, 1);
    check_split(in_tri, 0);
  } else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
