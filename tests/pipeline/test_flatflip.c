/* Flips that take away tets flat in doubles (src/output/flatflip.h). Hand-built stores:
 * a Steiner point whose exact position makes a sliver strictly positive while its nearest
 * double makes it flat. Every store, before and after, goes through tr_check_mesh (exact
 * links, orientation, v2t); a flip must keep the exact volume and the oriented boundary,
 * and the doubles are counted with tr_round_count_nonpositive. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "mesh/check.h"
#include "output/flatflip.h"
#include "output/round.h"

#include "texpect.h"

/* a, b, c span the plane z = 0; e is below it. */
static const double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0};

/* The exact point x + 2^-k along axis (a Steiner point). */
static tr_qpoint *lifted(const double x[3], int axis, int k)
{
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  mpq_t eps;
  mpq_init(eps);
  mpq_set_ui(eps, 1, 1);
  mpq_div_2exp(eps, eps, (unsigned long)k);
  for (int i = 0; i < 3; i++) {
    mpq_set_d(q->c[i], x[i]);
    if (i == axis)
      mpq_add(q->c[i], q->c[i], eps);
  }
  mpq_clear(eps);
  tr_qpoint_update(q);
  return q;
}

/* Store with a, b, c, e (doubles, ids 0..3) and d (Steiner, id 4): tets abcd and acbe
 * glued along abc, regions r1 and r2. */
static struct tr_mesh *bipyramid(const double e[3], tr_qpoint *d, uint32_t r1, uint32_t r2)
{
  struct tr_mesh *m = NULL;
  uint32_t id, t1, t2;
  tr_mesh_create(8, 8, &m);
  const double *p[4] = {A, B, C, e};
  for (int i = 0; i < 4; i++)
    tr_mesh_add_vertex(m, p[i], &id);
  tr_mesh_add_steiner(m, d, &id);
  tr_tet_new(m, 0, 1, 2, 4, &t1);
  tr_tet_new(m, 0, 2, 1, 3, &t2);
  tr_glue(m, t1, 3, t2, 3);
  tr_mesh_enable_regions(m);
  m->region[t1] = r1;
  m->region[t2] = r2;
  return m;
}

/* The boundary faces as oriented triples (each rotated to begin with its smallest id),
 * sorted: equal lists <=> same oriented boundary. */
static size_t boundary(const struct tr_mesh *m, uint32_t out[][3], size_t cap)
{
  size_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    for (int k = 0; k < 4 && !tr_tet_is_free(m, t); k++)
      if (m->tn[4 * (size_t)t + (size_t)k] == TR_NONE && n < cap) {
        for (int i = 0; i < 3; i++)
          out[n][i] = m->tv[4 * (size_t)t + tr_face_vtx[k][i]];
        tr_rotate_min3(out[n]);
        n++;
      }
  qsort(out, n, sizeof out[0], tr_cmp_face_key);
  return n;
}

typedef struct {
  mpq_t vol;
  uint32_t bd[32][3];
  size_t nbd;
} snapshot;

static void take(snapshot *s, const struct tr_mesh *m)
{
  mpq_init(s->vol);
  tr_mesh_volume6(m, s->vol);
  s->nbd = boundary(m, s->bd, 32);
}

/* The store is exactly valid, with the snapshot's volume and oriented boundary. */
static void same_region(const char *name, const struct tr_mesh *m, snapshot *s)
{
  tr_status st = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, s->vol);
  EXPECT(st == TR_OK, "%s: exact mesh invalid: %s", name, tr_last_error());
  uint32_t bd[32][3];
  size_t n = boundary(m, bd, 32);
  EXPECT(n == s->nbd && !memcmp(bd, s->bd, n * sizeof bd[0]),
         "%s: the oriented boundary changed", name);
  mpq_clear(s->vol);
}

static uint64_t run(struct tr_mesh *m, const tr_subfaces *sub)
{
  tr_plc *none = NULL;
  tr_plc_create(&none);
  uint64_t nflips = 99;
  tr_status st = tr_round_flip_flat(m, sub, none, 0, 1, &nflips);
  EXPECT(st == TR_OK, "tr_round_flip_flat: %s", tr_last_error());
  tr_plc_destroy(none);
  return nflips;
}

/* d = (1/4, 1/4, 2^-1100): above abc, but its nearest double (z = 0, below the smallest
 * subnormal) is on it, so abcd is flat in doubles; e = (1/4, 1/4, -1). Regions 1 and r2. */
static struct tr_mesh *sliver_on_abc(uint32_t r2)
{
  const double e[3] = {0.25, 0.25, -1}, d0[3] = {0.25, 0.25, 0};
  return bipyramid(e, lifted(d0, 2, 1100), 1, r2);
}

/* Swap23 across abc gives three tets around de, fat in doubles. */
static void t_swap23(void)
{
  struct tr_mesh *m = sliver_on_abc(1);
  snapshot s;
  take(&s, m);
  EXPECT(m->xyz[3 * 4 + 2] == 0, "swap23: the nearest double of d is not on abc");
  EXPECT(tr_round_count_nonpositive(m, NULL) == 1, "swap23: expected one flat tet");
  uint64_t n = run(m, &(tr_subfaces){0});
  EXPECT(n == 1, "swap23: %llu flips, want 1", (unsigned long long)n);
  EXPECT(tr_round_count_nonpositive(m, NULL) == 0, "swap23: a tet is still flat");
  EXPECT(tr_mesh_count_real(m) == 3, "swap23: %u tets, want 3", tr_mesh_count_real(m));
  same_region("swap23", m, &s);
  tr_mesh_destroy(m);
}

/* The same with abc a sub-face: it is a constraint, nothing may flip it away. */
static void t_subface_kept(void)
{
  struct tr_mesh *m = sliver_on_abc(1);
  snapshot s;
  take(&s, m);
  uint32_t abc[3] = {0, 1, 2}, tri = 0;
  tr_subfaces sub = {.n = 1, .v = abc, .tri = &tri};
  uint64_t n = run(m, &sub);
  EXPECT(n == 0, "subface_kept: %llu flips across a sub-face", (unsigned long long)n);
  EXPECT(tr_round_count_nonpositive(m, NULL) == 1, "subface_kept: the flat tet is gone");
  same_region("subface_kept", m, &s);
  tr_mesh_destroy(m);
}

/* The same with the two tets in different regions: abc separates them. */
static void t_regions_kept(void)
{
  struct tr_mesh *m = sliver_on_abc(2);
  snapshot s;
  take(&s, m);
  uint64_t n = run(m, &(tr_subfaces){0});
  EXPECT(n == 0, "regions_kept: %llu flips between two regions", (unsigned long long)n);
  same_region("regions_kept", m, &s);
  tr_mesh_destroy(m);
}

/* d = (1/4, -1/4 + 2^-80, 1), e = (1/4, 1/4, -1): de crosses abc at (1/4, 2^-81, 0), just
 * inside edge ab. Around edge de the three tets deab, debc, deca; deab is positive by
 * 2^-80-ish but flat in doubles (the nearest d lies on plane abe). Swap32 on de gives
 * abcd and acbe back, both fat. */
static void t_swap32(void)
{
  const double e[3] = {0.25, 0.25, -1}, d0[3] = {0.25, -0.25, 1};
  struct tr_mesh *m = bipyramid(e, lifted(d0, 1, 80), 1, 1);
  /* first the three tets around de: a valid Swap23 of the bipyramid */
  uint32_t old[2] = {0, 1}, nv[12], ring[3] = {0, 1, 2};
  for (int i = 0; i < 3; i++) {
    uint32_t *t = nv + 4 * i, u = ring[i], w = ring[(i + 1) % 3];
    t[0] = 4, t[1] = 3, t[2] = u, t[3] = w;
    tr_point p[4];
    for (int k = 0; k < 4; k++)
      p[k] = tr_mesh_point(m, t[k]);
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) < 0)
      t[2] = w, t[3] = u;
  }
  tr_status st = tr_mesh_replace(m, old, 2, nv, 3, NULL);
  EXPECT(st == TR_OK, "swap32: setup: %s", tr_last_error());
  for (uint32_t t = 0; t < m->nt; t++)
    m->region[t] = 1;
  snapshot s;
  take(&s, m);
  EXPECT(tr_round_count_nonpositive(m, NULL) == 1, "swap32: expected one flat tet, got %llu",
         (unsigned long long)tr_round_count_nonpositive(m, NULL));
  uint64_t n = run(m, &(tr_subfaces){0});
  EXPECT(n == 1, "swap32: %llu flips, want 1", (unsigned long long)n);
  EXPECT(tr_round_count_nonpositive(m, NULL) == 0, "swap32: a tet is still flat");
  EXPECT(tr_mesh_count_real(m) == 2, "swap32: %u tets, want 2", tr_mesh_count_real(m));
  same_region("swap32", m, &s);
  tr_mesh_destroy(m);
}

/* The insertion after a failed repair (tr_round_insert_flat) never crosses the mesh's
 * boundary: in the bipyramid abcd + acbe of t_swap23 (called without the flips), the
 * centroid of the flat abcd lies on abc in doubles, so the cavity grows across abc into
 * acbe and then meets abd, bcd, cad, boundary faces in the plane of abc in doubles that
 * the centroid does not see: refused, nothing changes (2 tets, 5 vertices, abcd still
 * the one flat tet, exactly valid with the same volume and boundary). */
static void t_insert_refused(void)
{
  struct tr_mesh *m = sliver_on_abc(1);
  snapshot s;
  take(&s, m);
  tr_plc *none = NULL;
  tr_plc_create(&none);
  uint64_t n = 99;
  tr_status st = tr_round_insert_flat(m, &(tr_subfaces){0}, none, &n);
  EXPECT(st == TR_OK, "insert_refused: %s", tr_last_error());
  EXPECT(n == 0, "insert_refused: %llu points inserted, want 0", (unsigned long long)n);
  EXPECT(m->nv == 5, "insert_refused: %u vertices, want 5", m->nv);
  EXPECT(tr_mesh_count_real(m) == 2, "insert_refused: %u tets, want 2", tr_mesh_count_real(m));
  EXPECT(tr_round_count_nonpositive(m, NULL) == 1, "insert_refused: want abcd still flat");
  same_region("insert_refused", m, &s);
  tr_plc_destroy(none);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *w = argc > 1 ? argv[1] : "all";
  int all = !strcmp(w, "all");
  if (all || !strcmp(w, "swap23"))
    t_swap23();
  if (all || !strcmp(w, "subface_kept"))
    t_subface_kept();
  if (all || !strcmp(w, "regions_kept"))
    t_regions_kept();
  if (all || !strcmp(w, "swap32"))
    t_swap32();
  if (all || !strcmp(w, "insert_refused"))
    t_insert_refused();
  if (failures)
    fprintf(stderr, "%d failures\n", failures);
  return failures ? 1 : 0;
}
