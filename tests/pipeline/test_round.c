/* Rounding of Steiner points to doubles and its repair (src/output/round.h), and the
 * exact --exact round trip. Hand-built stores put a rational Steiner point where nearest
 * rounding crosses a plane; every store, before and after, goes through tr_check_mesh
 * (exact, with the exact volume) and tr_check_conformity, and the doubles that would be
 * written are re-checked as a plain double mesh. */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "core/plc.h"
#include "io/io.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "output/round.h"
#include "pipeline/pipeline.h"

#include "texpect.h"

static const char *outdir = ".";

/* ---- hand-built stores ---- */
/* The corner points of plane x + y + z = 1 and the doubles next to 1/3. */
static const double A[3] = {1, 0, 0}, B[3] = {0, 1, 0}, C[3] = {0, 0, 1};
static double third(int ulps)
{
  double x = 1.0 / 3.0;
  for (; ulps > 0; ulps--)
    x = nextafter(x, 2);
  for (; ulps < 0; ulps++)
    x = nextafter(x, 0);
  return x;
}

/* A new Steiner point with exact coordinates num[i] / den[i] (strings, base 10). */
static tr_qpoint *qpoint(const char *num[3], const char *den[3])
{
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  for (int k = 0; k < 3; k++) {
    mpz_set_str(mpq_numref(q->c[k]), num[k], 10);
    mpz_set_str(mpq_denref(q->c[k]), den[k], 10);
    mpq_canonicalize(q->c[k]);
  }
  tr_qpoint_update(q);
  return q;
}

/* q = (a + b + c + d) / 4 exactly, a..d plain doubles or exact points. */
static tr_qpoint *centroid(const tr_point *p[4])
{
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  mpq_t x;
  mpq_init(x);
  for (int k = 0; k < 3; k++) {
    mpq_set_ui(q->c[k], 0, 1);
    for (int i = 0; i < 4; i++) {
      tr_point_get_q(p[i], k, x);
      mpq_add(q->c[k], q->c[k], x);
    }
    mpq_set_ui(x, 1, 4);
    mpq_mul(q->c[k], q->c[k], x);
  }
  mpq_clear(x);
  tr_qpoint_update(q);
  return q;
}

/* The slot of the tet with vertices v[0..3] (in that order), TR_NONE if none. */
static uint32_t find_tet(const struct tr_mesh *m, const uint32_t v[4])
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && !memcmp(m->tv + 4 * (size_t)t, v, 4 * sizeof *v))
      return t;
  return TR_NONE;
}

/* Splits tet t at the new vertex p (inside it): the four tets with p in each slot. */
static void split(struct tr_mesh *m, uint32_t t, uint32_t p)
{
  uint32_t nv[16];
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 4; k++)
      nv[4 * i + k] = k == i ? p : m->tv[4 * (size_t)t + k];
  tr_status s = tr_mesh_replace(m, &t, 1, nv, 4, NULL);
  EXPECT(s == TR_OK, "split: %s", tr_last_error());
}

/* The tet ABCD (positive: d above x + y + z = 1) as a store and as its surface. */
static struct tr_mesh *tet_store(const double d[3], tr_plc **surface)
{
  struct tr_mesh *m = NULL;
  uint32_t id, t;
  tr_mesh_create(8, 16, &m);
  const double *p[4] = {A, B, C, d};
  for (int i = 0; i < 4; i++)
    tr_mesh_add_vertex(m, p[i], &id);
  tr_tet_new(m, 0, 1, 2, 3, &t);
  double xyz[12];
  for (int i = 0; i < 4; i++)
    memcpy(xyz + 3 * i, p[i], sizeof xyz[0] * 3);
  /* faces as seen from outside: the reverse of tr_face_vtx order */
  uint32_t tris[12];
  for (int k = 0; k < 4; k++) {
    tris[3 * k] = tr_face_vtx[k][0];
    tris[3 * k + 1] = tr_face_vtx[k][2];
    tris[3 * k + 2] = tr_face_vtx[k][1];
  }
  tr_plc_create(surface);
  tr_plc_set(*surface, xyz, 4, tris, 4, NULL);
  return m;
}

/* The doubles of m (what the writers print) as a plain double store: every Steiner point
 * replaced by its xyz. */
static struct tr_mesh *double_copy(const struct tr_mesh *m)
{
  struct tr_mesh *o = NULL;
  uint32_t id;
  EXPECT(m->nfree == 0, "double_copy: the store has free slots");
  tr_mesh_create(m->nv, m->nt, &o);
  for (uint32_t v = 0; v < m->nv; v++)
    tr_mesh_add_vertex(o, m->xyz + 3 * (size_t)v, &id);
  for (uint32_t t = 0; t < m->nt; t++) {
    const uint32_t *v = m->tv + 4 * (size_t)t;
    tr_tet_new(o, v[0], v[1], v[2], v[3], &id);
    memcpy(o->tn + 4 * (size_t)id, m->tn + 4 * (size_t)t, 4 * sizeof *o->tn);
  }
  return o;
}

/* Both validators on the exact store (exact volume = the surface's), then the validator
 * on its doubles; want_doubles_ok: whether the doubles must be valid too. */
static void validate(const char *name, struct tr_mesh *m, const tr_plc *surface,
                     int want_doubles_ok)
{
  tr_status s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
  EXPECT(s == TR_OK, "%s: exact mesh invalid: %s", name, tr_last_error());
  s = tr_check_conformity(m, surface, NULL, 0);
  EXPECT(s == TR_OK, "%s: exact mesh does not conform: %s", name, tr_last_error());
  struct tr_mesh *d = double_copy(m);
  s = tr_check_mesh(d, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
  if (want_doubles_ok)
    EXPECT(s == TR_OK, "%s: double mesh invalid: %s", name, tr_last_error());
  else
    EXPECT(s == TR_ERR_INVALID_MESH, "%s: double mesh unexpectedly valid", name);
  tr_mesh_destroy(d);
}

static int same_exact(const tr_qpoint *a, const tr_qpoint *b)
{
  for (int k = 0; k < 3; k++)
    if (!mpq_equal(a->c[k], b->c[k]))
      return 0;
  return 1;
}

/* P = the centroid of ABC lifted by 2^-80 along (1,1,1): inside ABCD, but its nearest
 * double (1/3 rounded down on every axis) is below the plane, so ABCP inverts. The first
 * candidate in search order above the plane is (0, +1, +1) ulp: x + y + z = 1 + ulp/3
 * (the offsets of norm 1 give sums <= 1, and the norm-2 offsets before it in
 * lexicographic order have i + j + k <= 0). */
static void t_inverting(void)
{
  const double D[3] = {1, 1, 1};
  tr_plc *surf = NULL;
  struct tr_mesh *m = tet_store(D, &surf);
  const char *num[3] = {"1208925819614629174706179", "1208925819614629174706179",
                        "1208925819614629174706179"};
  const char *den[3] = {"3626777458843887524118528", "3626777458843887524118528",
                        "3626777458843887524118528"};
  /* (2^80 + 3) / (3 * 2^80) = 1/3 + 2^-80 */
  tr_qpoint *q = qpoint(num, den);
  uint32_t p;
  tr_mesh_add_steiner(m, q, &p);
  split(m, 0, p);
  EXPECT(m->xyz[3 * p] == third(0) && m->xyz[3 * p + 2] == third(0),
         "inverting: nearest double of 1/3 + 2^-80 is not 1/3 rounded");
  validate("inverting (nearest)", m, surf, 0);
  uint32_t first;
  EXPECT(tr_round_count_nonpositive(m, &first) == 1, "inverting: expected 1 bad tet");
  uint64_t rep = 0;
  tr_status s = tr_round_steiner(m, 0, &rep);
  EXPECT(s == TR_OK, "inverting: %s", tr_last_error());
  EXPECT(rep == 1, "inverting: %llu repairs, expected 1", (unsigned long long)rep);
  EXPECT(tr_round_count_nonpositive(m, NULL) == 0, "inverting: tets still non-positive");
  const double *x = m->xyz + 3 * (size_t)p;
  EXPECT(x[0] == third(0) && x[1] == third(1) && x[2] == third(1),
         "inverting: repaired to (%.17g, %.17g, %.17g), expected 1/3 + (0, 1, 1) ulp", x[0],
         x[1], x[2]);
  EXPECT(m->vq[p] == q && mpq_cmp_si(q->c[0], 1, 3) > 0, "inverting: exact point changed");
  validate("inverting (repaired)", m, surf, 1);
  tr_mesh_destroy(m);
  tr_plc_destroy(surf);
}

/* A Steiner point well inside a fat tet: nothing to repair, its double stays the nearest. */
static void t_no_repair(void)
{
  const double D[3] = {1, 1, 1};
  tr_plc *surf = NULL;
  struct tr_mesh *m = tet_store(D, &surf);
  const char *num[3] = {"3", "5", "4"}, *den[3] = {"7", "11", "9"};
  tr_qpoint *q = qpoint(num, den);
  uint32_t p;
  tr_mesh_add_steiner(m, q, &p);
  split(m, 0, p);
  double before[3];
  memcpy(before, m->xyz + 3 * (size_t)p, sizeof before);
  uint64_t rep = 7;
  tr_status s = tr_round_steiner(m, 0, &rep);
  EXPECT(s == TR_OK, "no_repair: %s", tr_last_error());
  EXPECT(rep == 0, "no_repair: %llu repairs", (unsigned long long)rep);
  EXPECT(!memcmp(before, m->xyz + 3 * (size_t)p, sizeof before) &&
             !memcmp(before, q->near, sizeof before),
         "no_repair: the double moved off the nearest");
  validate("no_repair", m, surf, 1);
  tr_mesh_destroy(m);
  tr_plc_destroy(surf);
}

/* Two adjacent Steiner points that both round below the plane: P as in t_inverting, Q the
 * centroid of the sliver ABCP. Their stars share three tets. The result: every tet positive,
 * at most the two points moved, the same doubles on a second run. */
static void t_interacting(void)
{
  const double D[3] = {1, 1, 1};
  double got[2][6];
  for (int run = 0; run < 2; run++) {
    tr_plc *surf = NULL;
    struct tr_mesh *m = tet_store(D, &surf);
    const char *num[3] = {"1208925819614629174706179", "1208925819614629174706179",
                          "1208925819614629174706179"};
    const char *den[3] = {"3626777458843887524118528", "3626777458843887524118528",
                          "3626777458843887524118528"};
    uint32_t p, q;
    tr_mesh_add_steiner(m, qpoint(num, den), &p);
    split(m, 0, p);
    uint32_t abcp[4] = {0, 1, 2, p};
    uint32_t t = find_tet(m, abcp);
    tr_point a = tr_pt_d(A), b = tr_pt_d(B), c = tr_pt_d(C), pp = tr_mesh_point(m, p);
    const tr_point *four[4] = {&a, &b, &c, &pp};
    tr_mesh_add_steiner(m, centroid(four), &q);
    EXPECT(t != TR_NONE, "interacting: no tet ABCP");
    if (t == TR_NONE)
      return;
    split(m, t, q);
    validate("interacting (nearest)", m, surf, 0);
    uint64_t rep = 0;
    tr_status s = tr_round_steiner(m, 0, &rep);
    EXPECT(s == TR_OK, "interacting: %s", tr_last_error());
    EXPECT(rep >= 1 && rep <= 2, "interacting: %llu repairs", (unsigned long long)rep);
    EXPECT(tr_round_count_nonpositive(m, NULL) == 0, "interacting: tets still non-positive");
    validate("interacting (repaired)", m, surf, 1);
    memcpy(got[run], m->xyz + 3 * (size_t)p, 3 * sizeof(double));
    memcpy(got[run] + 3, m->xyz + 3 * (size_t)q, 3 * sizeof(double));
    tr_mesh_destroy(m);
    tr_plc_destroy(surf);
  }
  EXPECT(!memcmp(got[0], got[1], sizeof got[0]), "interacting: two runs differ");
}

/* ABCD so thin that no double lies strictly inside it near P: D is 2 ulps above the
 * centroid of ABC on the double grid, so x + y + z of D is 1 + 2^-54 while every double
 * point near (1/3,1/3,1/3) has x + y + z = 1 + k 2^-54 (k integer): none strictly between
 * the planes, so no position of P makes all four of its tets positive. */
static void t_unrepairable(void)
{
  const double D[3] = {third(1), third(1), third(0)};
  tr_plc *surf = NULL;
  struct tr_mesh *m = tet_store(D, &surf);
  tr_point a = tr_pt_d(A), b = tr_pt_d(B), c = tr_pt_d(C), d = tr_pt_d(D);
  const tr_point *four[4] = {&a, &b, &c, &d};
  uint32_t p;
  tr_mesh_add_steiner(m, centroid(four), &p);
  split(m, 0, p);
  uint64_t rep = 0;
  tr_status s = tr_round_steiner(m, 0, &rep);
  EXPECT(s == TR_ERR_INVALID_MESH, "unrepairable: status %s", tr_status_name(s));
  char want[64];
  snprintf(want, sizeof want, "Steiner point %u near (", p);
  EXPECT(strstr(tr_last_error(), want) && strstr(tr_last_error(), "--exact"),
         "unrepairable: message does not name the point: %s", tr_last_error());
  EXPECT(rep <= 1 && tr_round_count_nonpositive(m, NULL) >= 1,
         "unrepairable: %llu repairs and every tet positive", (unsigned long long)rep);
  validate("unrepairable (exact mesh kept)", m, surf, 0);
  tr_mesh_destroy(m);
  tr_plc_destroy(surf);
}

/* ---- end to end ---- */
/* A twisted n-gonal prism of height h (the top turned by tw of a sector: Schoenhardt's
 * prism for n = 3, tw = 1/4), each side split along the diagonal that makes it reflex, so
 * it needs Steiner points; then rotated by a1 about y and a2 about x so that no facet is
 * axis-aligned and Steiner points round in every direction. Thin ones make thin tets. */
static tr_plc *twisted(int n, double h, double tw, double a1, double a2)
{
  double x[36];
  uint32_t t[72];
  int nt = 0;
  const double pi = 3.14159265358979;
  for (int i = 0; i < n; i++) {
    double a = 2 * pi * i / n, b = a + tw * 2 * pi / n;
    double p[2][3] = {{cos(a), sin(a), 0}, {cos(b), sin(b), h}};
    for (int s = 0; s < 2; s++) {
      double X = p[s][0], Y = p[s][1], Z = p[s][2];
      double X1 = X * cos(a1) - Z * sin(a1), Z1 = X * sin(a1) + Z * cos(a1);
      double *q = x + 3 * (s * n + i);
      q[0] = X1;
      q[1] = Y * cos(a2) - Z1 * sin(a2);
      q[2] = Y * sin(a2) + Z1 * cos(a2);
    }
  }
  for (int i = 1; i + 1 < n; i++) {
    uint32_t f[6] = {0, (uint32_t)i + 1, (uint32_t)i, (uint32_t)n, (uint32_t)(n + i),
                     (uint32_t)(n + i + 1)};
    memcpy(t + nt, f, sizeof f);
    nt += 6;
  }
  for (int i = 0; i < n; i++) {
    uint32_t j = (uint32_t)(i + 1) % (uint32_t)n, u = (uint32_t)i, N = (uint32_t)n;
    uint32_t f[6] = {u, j, N + j, u, N + j, N + u};
    memcpy(t + nt, f, sizeof f);
    nt += 6;
  }
  tr_plc *p = NULL;
  tr_plc_create(&p);
  tr_plc_set(p, x, 2 * (uint32_t)n, t, (uint32_t)nt / 3, NULL);
  return p;
}

/* Meshes plc: the exact output conforms, its doubles are a valid mesh, the repairs are
 * counted as the Steiner points whose double is not the nearest; then the --exact .node
 * is read back exactly. Returns the number of Steiner points. */
static uint64_t end_to_end(const char *name, tr_plc *plc, uint64_t *repairs)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  tr_status s = tr_mesh_plc_ex(plc, &opt, &m, &st, &used);
  EXPECT(s == TR_OK, "%s: tr_mesh_plc: %s", name, tr_last_error());
  if (s != TR_OK)
    return 0;
  validate(name, m, used, 1);
  uint64_t moved = 0, nst = 0;
  for (uint32_t v = 0; v < m->nv; v++)
    if (m->vq && m->vq[v]) {
      nst++;
      moved += memcmp(m->xyz + 3 * (size_t)v, m->vq[v]->near, 3 * sizeof(double)) != 0;
    }
  EXPECT(moved == st.rounding_repairs, "%s: %llu doubles moved, stats say %llu", name,
         (unsigned long long)moved, (unsigned long long)st.rounding_repairs);
  *repairs = st.rounding_repairs;
  char base[1024];
  snprintf(base, sizeof base, "%s/%s", outdir, name);
  s = tr_mesh_write(m, base, 1);
  EXPECT(s == TR_OK, "%s: write: %s", name, tr_last_error());
  char path[1100], *buf = NULL;
  size_t len = 0;
  snprintf(path, sizeof path, "%s.node", base);
  tr_qpoint **q = NULL;
  uint32_t n = 0;
  int exact_file = 0;
  if (s == TR_OK && tr_io_load(path, &buf, &len) == TR_OK)
    s = tr_read_node_exact_buf(buf, len, path, &q, &n, &exact_file);
  EXPECT(s == TR_OK && n == m->nv, "%s: exact read: %s", name, tr_last_error());
  EXPECT(!nst || exact_file, "%s: the .node does not say it is exact", name);
  tr_plc *back = NULL;
  s = tr_plc_read(path, &back);
  EXPECT(s == TR_OK && back->npoints == m->nv, "%s: double read: %s", name, tr_last_error());
  for (uint32_t v = 0; q && s == TR_OK && v < n && v < m->nv; v++) {
    const tr_qpoint *e = m->vq ? m->vq[v] : NULL;
    /* exact points come back exact, the others as the same doubles; the plain reader
     * rounds an exact point to its nearest double */
    const double *d = back->xyz + 3 * (size_t)v;
    /* a Steiner point that is exactly a double (an edge midpoint often is) comes back
     * as that plain double */
    int isd = e && !memcmp(e->lo, e->hi, 3 * sizeof *d);
    int same = e && !isd ? q[v] && same_exact(q[v], e) && !memcmp(d, e->near, 3 * sizeof *d)
             : e ? (q[v] ? same_exact(q[v], e) : 1) && !memcmp(d, e->near, 3 * sizeof *d)
                 : !q[v] && !memcmp(d, m->xyz + 3 * (size_t)v, 3 * sizeof *d);
    EXPECT(same, "%s: vertex %u not read back exactly", name, v);
  }
  for (uint32_t v = 0; q && v < n; v++)
    if (q[v]) {
      tr_qpoint_clear(q[v]);
      free(q[v]);
    }
  tr_plc_destroy(back);
  free(q);
  free(buf);
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  return nst;
}

static void t_end_to_end(void)
{
  uint64_t total = 0, steiner = 0;
  int cases = 0;
  tr_plc *p = twisted(3, 1, 0.25, 0, 0);
  uint64_t rep = 0;
  steiner += end_to_end("schoenhardt", p, &rep);
  total += rep;
  tr_plc_destroy(p);
  /* rotated twisted prisms, thick to 1e-12 thin: many of them need repairs */
  static const double hs[] = {1, 1e-3, 1e-6, 1e-9, 1e-12}, tws[] = {0.55, 0.7},
                      a1s[] = {0, 1.4};
  for (int n = 4; n <= 6; n++)
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++) {
          char name[64];
          snprintf(name, sizeof name, "twisted_%d_%d_%d_%d", n, i, j, k);
          p = twisted(n, hs[i], tws[j], a1s[k], 0.4);
          uint64_t ns = end_to_end(name, p, &rep);
          EXPECT(ns >= 1, "%s: no Steiner point", name);
          steiner += ns;
          total += rep;
          cases++;
          tr_plc_destroy(p);
        }
  printf("end to end: %d meshes, %llu Steiner points, %llu repaired\n", cases + 1,
         (unsigned long long)steiner, (unsigned long long)total);
}

int main(int argc, char **argv)
{
  const char *w = argc > 1 ? argv[1] : "all";
  if (argc > 2)
    outdir = argv[2];
  int all = !strcmp(w, "all");
  if (all || !strcmp(w, "inverting"))
    t_inverting();
  if (all || !strcmp(w, "no_repair"))
    t_no_repair();
  if (all || !strcmp(w, "interacting"))
    t_interacting();
  if (all || !strcmp(w, "unrepairable"))
    t_unrepairable();
  if (all || !strcmp(w, "end_to_end"))
    t_end_to_end();
  if (failures)
    fprintf(stderr, "%d failures\n", failures);
  return failures ? 1 : 0;
}
