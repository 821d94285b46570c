/* Gmsh .msh output, format 4.1 (default) or 2.2, ASCII (default) or binary, all read by
 * Gmsh and meshio (the ASCII forms also by dolfinx's gmshio and Elmer's ElmerGrid).
 *
 * Physical tags: each distinct region value becomes one volume entity, each distinct
 * triangle marker one surface entity and each distinct edge marker (check-surface's open
 * edges) one curve entity, numbered 1, 2, ... in increasing value, whose
 * physical tag is the value (none for 0, the value of "no marker"); tets without regions
 * (a Delaunay mesh) are region 1, so that readers which want every entity tagged once any
 * is (meshio, dolfinx) take them. Format 2.2 writes the
 * same two tags per element (physical, entity). All nodes form one block of the first
 * volume entity (or surface or curve entity when there are no tets); node and element
 * tags are 1-based and contiguous, edges first, then triangles. Doubles in %.17g read back bitwise.
 * The nodes and elements are formatted in blocks on m->threads threads, the binary ones on
 * one (blocks.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "blocks.h"
#include "put_number.h"
#include "write.h"

/* Elements grouped by value: vals[0..nval) the distinct values in increasing order,
 * first[e] the start of entity e in the elements sorted by (entity, index), order[] that
 * sorted list, or NULL when it is the identity (the values already non-decreasing in
 * index order: one entity, as for every Delaunay mesh, or regions numbered in tet
 * order), so that the common case costs no array per element. */
struct groups {
  uint32_t nval;
  int32_t *vals;
  uint32_t *order, *first;
};

/* The element at position j of the sorted order. */
static inline uint32_t elem_at(const struct groups *g, uint32_t j)
{
  return g->order ? g->order[j] : j;
}

static int cmp_i32(const void *a, const void *b)
{
  int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
  return (x > y) - (x < y);
}

static uint32_t entity_of(const struct groups *g, int32_t v)
{
  uint32_t lo = 0, hi = g->nval;
  while (hi - lo > 1) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (g->vals[mid] <= v)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

static void groups_free(struct groups *g)
{
  free(g->vals);
  free(g->order);
  free(g->first);
}

static tr_status group(const int32_t *val, uint32_t n, int32_t dflt, struct groups *g)
{
  memset(g, 0, sizeof *g);
  if (!val) { /* one entity, dflt, unless there are no elements */
    g->vals = malloc(sizeof *g->vals);
    g->first = calloc(3, sizeof *g->first);
    if (!g->vals || !g->first) {
      groups_free(g);
      return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
    }
    g->vals[0] = dflt;
    g->nval = n ? 1 : 0;
    g->first[1] = n;
    return TR_OK;
  }
  /* the distinct values: the first of each run of equal values, sorted, made unique;
   * a mesh's regions come in long runs, so this is far shorter than the elements */
  size_t cap = 64, nrun = 0;
  int sorted = 1;
  g->vals = malloc(sizeof *g->vals * cap);
  if (!g->vals)
    return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
  for (uint32_t i = 0; i < n; i++) {
    int32_t v = val[i];
    if (i && v == g->vals[nrun - 1])
      continue;
    if (i && v < g->vals[nrun - 1])
      sorted = 0;
    if (nrun == cap) {
      int32_t *w = realloc(g->vals, sizeof *w * (cap *= 2));
      if (!w) {
        groups_free(g);
        return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
      }
      g->vals = w;
    }
    g->vals[nrun++] = v;
  }
  if (!sorted)
    qsort(g->vals, nrun, sizeof *g->vals, cmp_i32);
  for (size_t i = 0; i < nrun; i++)
    if (i == 0 || g->vals[i] != g->vals[g->nval - 1])
      g->vals[g->nval++] = g->vals[i];
  g->first = calloc((size_t)g->nval + 2, sizeof *g->first);
  if (!g->first) {
    groups_free(g);
    return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
  }
  /* counting sort by entity keeps index order inside each entity; the entity is looked
   * up once per run */
  uint32_t e = 0;
  for (uint32_t i = 0; i < n; i++) {
    int32_t v = val[i];
    if (i == 0 || v != val[i - 1])
      e = entity_of(g, v);
    g->first[e + 1]++;
  }
  for (uint32_t k = 0; k < g->nval; k++)
    g->first[k + 1] += g->first[k];
  if (sorted)
    return TR_OK;
  uint32_t *at = malloc(sizeof *at * (g->nval ? g->nval : 1));
  g->order = malloc(sizeof *g->order * (n ? n : 1));
  if (!at || !g->order) {
    free(at);
    groups_free(g);
    return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
  }
  memcpy(at, g->first, sizeof *at * g->nval);
  for (uint32_t i = 0; i < n; i++) {
    int32_t v = val[i];
    if (i == 0 || v != val[i - 1])
      e = entity_of(g, v);
    g->order[at[e]++] = i;
  }
  free(at);
  return TR_OK;
}

/* Gmsh element types of the simplices of dimension 1, 2, 3: line, triangle, tetrahedron. */
static const int type_of[4] = {15, 1, 2, 4};

/* ---- the bulk sections, formatted in blocks (blocks.h) ---- */

/* Node records: 4.1 writes the tags, then the coordinates; 2.2 both on one line. Text or
 * little-endian binary (4.1: 8-byte tags; 2.2: 4-byte tags). */
static char *node_tags41(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  (void)ctx;
  for (uint64_t i = i0; i < i1; i++) {
    int64_t t = (int64_t)i + 1;
    p = tr_io_fmt_ints(p, &t, 1);
  }
  return p;
}

static char *node_xyz41(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, -1, m->xyz + 3 * (size_t)i, "\n");
  return p;
}

static char *node_rows22(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  for (uint64_t i = i0; i < i1; i++)
    p = tr_io_fmt_xyz(p, (int64_t)i + 1, m->xyz + 3 * (size_t)i, "\n");
  return p;
}

static char *node_tags41b(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  (void)ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = i0; i < i1; i++)
    q = tr_le64(q, i + 1);
  return (char *)q;
}

static char *node_xyz41b(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = 3 * i0; i < 3 * i1; i++)
    q = tr_le_f64(q, m->xyz[i]);
  return (char *)q;
}

static char *node_rows22b(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  const struct tr_mesh_view *m = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t i = i0; i < i1; i++) {
    q = tr_le32(q, (uint32_t)i + 1);
    for (int k = 0; k < 3; k++)
      q = tr_le_f64(q, m->xyz[3 * (size_t)i + k]);
  }
  return (char *)q;
}

/* The elements of one entity: record j is the element at first[e] + j of the sorted
 * order, with tag tag0 + j. */
struct entity {
  const struct groups *g;
  uint32_t e;
  int dim, per;
  const uint32_t *cv; /* per vertices an element */
  uint64_t tag0;
};

static char *elems41(const void *ctx, uint64_t j0, uint64_t j1, char *p)
{
  const struct entity *E = ctx;
  for (uint64_t j = j0; j < j1; j++) {
    const uint32_t *v = E->cv + (size_t)E->per * elem_at(E->g, E->g->first[E->e] + (uint32_t)j);
    int64_t row[5] = {(int64_t)(E->tag0 + j)};
    for (int k = 0; k < E->per; k++)
      row[k + 1] = (int64_t)v[k] + 1;
    p = tr_io_fmt_ints(p, row, E->per + 1);
  }
  return p;
}

static char *elems22(const void *ctx, uint64_t j0, uint64_t j1, char *p)
{
  const struct entity *E = ctx;
  for (uint64_t j = j0; j < j1; j++) {
    const uint32_t *v = E->cv + (size_t)E->per * elem_at(E->g, E->g->first[E->e] + (uint32_t)j);
    /* tag, type, 2 tags: physical (the value), elementary (the entity) */
    int64_t row[9] = {(int64_t)(E->tag0 + j), type_of[E->dim], 2, E->g->vals[E->e],
                      (int64_t)E->e + 1};
    for (int k = 0; k < E->per; k++)
      row[k + 5] = (int64_t)v[k] + 1;
    p = tr_io_fmt_ints(p, row, E->per + 5);
  }
  return p;
}

static char *elems41b(const void *ctx, uint64_t j0, uint64_t j1, char *p)
{
  const struct entity *E = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t j = j0; j < j1; j++) {
    const uint32_t *v = E->cv + (size_t)E->per * elem_at(E->g, E->g->first[E->e] + (uint32_t)j);
    q = tr_le64(q, E->tag0 + j);
    for (int k = 0; k < E->per; k++)
      q = tr_le64(q, (uint64_t)v[k] + 1);
  }
  return (char *)q;
}

static char *elems22b(const void *ctx, uint64_t j0, uint64_t j1, char *p)
{
  const struct entity *E = ctx;
  unsigned char *q = (unsigned char *)p;
  for (uint64_t j = j0; j < j1; j++) {
    const uint32_t *v = E->cv + (size_t)E->per * elem_at(E->g, E->g->first[E->e] + (uint32_t)j);
    q = tr_le32(q, (uint32_t)(E->tag0 + j));
    q = tr_le32(q, (uint32_t)E->g->vals[E->e]);
    q = tr_le32(q, E->e + 1);
    for (int k = 0; k < E->per; k++)
      q = tr_le32(q, v[k] + 1);
  }
  return (char *)q;
}

/* Every entity's elements, edges first: before each entity its header (41: text line or
 * binary record; 22 binary: the element header; 22 text: none). */
static tr_status write_elements(FILE *f, const struct tr_mesh_view *m,
                                const struct tr_edge_view *ev, const struct groups *g3,
                                int version, int binary, int threads)
{
  tr_io_block_fn fn = version == 41 ? (binary ? elems41b : elems41)
                                    : (binary ? elems22b : elems22);
  uint64_t tag = 1;
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    struct entity E = {g, 0, dim, dim + 1, dim == 1 ? ev->edges : dim == 2 ? m->tris : m->tets,
                       0};
    /* bytes of one record: text ints, or the binary fields */
    size_t max = binary ? (version == 41 ? 8 * (size_t)(E.per + 1) : 4 * (size_t)(E.per + 3))
                        : (size_t)(E.per + 5) * TR_IO_INT_MAX;
    for (uint32_t e = 0; e < g->nval; e++) {
      uint32_t count = g->first[e + 1] - g->first[e];
      unsigned char b[32], *p;
      if (version == 41 && !binary)
        fprintf(f, "%d %u %d %u\n", dim, e + 1, type_of[dim], count);
      else if (version == 41) {
        p = tr_le32(b, (uint32_t)dim);
        p = tr_le32(p, e + 1);
        p = tr_le32(p, (uint32_t)type_of[dim]);
        p = tr_le64(p, count);
        fwrite(b, 1, (size_t)(p - b), f);
      } else if (binary) {
        /* one header per entity: type, elements following, tags per element (physical,
         * elementary) */
        p = tr_le32(b, (uint32_t)type_of[dim]);
        p = tr_le32(p, count);
        p = tr_le32(p, 2);
        fwrite(b, 1, (size_t)(p - b), f);
      }
      E.e = e;
      E.tag0 = tag;
      TR_CHECK(tr_io_write_blocks(f, count, max, fn, &E, threads));
      tag += count;
    }
  }
  return TR_OK;
}

/* The bounding box of the nodes, lo[0..3) then hi[0..3). */
static void bounding_box(const struct tr_mesh_view *m, double box[6])
{
  for (int k = 0; k < 6; k++)
    box[k] = 0;
  for (uint32_t i = 0; i < m->nverts; i++)
    for (int k = 0; k < 3; k++) {
      double x = m->xyz[3 * (size_t)i + k];
      if (i == 0 || x < box[k])
        box[k] = x;
      if (i == 0 || x > box[3 + k])
        box[3 + k] = x;
    }
}

static tr_status write41(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                         const struct groups *g3, int threads)
{
  double box[6], *lo = box, *hi = box + 3;
  bounding_box(m, box);
  /* nodes must belong to an entity: a point entity when there is no other */
  int lone = !g3[0].nval && !g3[1].nval && !g3[2].nval;
  fprintf(f, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n%d %u %u %u\n", lone,
          g3[0].nval, g3[1].nval, g3[2].nval);
  if (lone)
    fprintf(f, "1 %.17g %.17g %.17g 0\n", lo[0], lo[1], lo[2]);
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    for (uint32_t e = 0; e < g->nval; e++) {
      fprintf(f, "%u %.17g %.17g %.17g %.17g %.17g %.17g ", e + 1, lo[0], lo[1], lo[2], hi[0],
              hi[1], hi[2]);
      if (g->vals[e])
        fprintf(f, "1 %d 0\n", (int)g->vals[e]);
      else
        fprintf(f, "0 0\n");
    }
  }
  fprintf(f, "$EndEntities\n$Nodes\n");
  if (m->nverts) {
    int dim = g3[2].nval ? 3 : g3[1].nval ? 2 : g3[0].nval ? 1 : 0;
    fprintf(f, "1 %u 1 %u\n%d 1 0 %u\n", m->nverts, m->nverts, dim, m->nverts);
    TR_CHECK(tr_io_write_blocks(f, m->nverts, TR_IO_INT_MAX, node_tags41, m, threads));
    TR_CHECK(tr_io_write_blocks(f, m->nverts, TR_IO_XYZ_MAX, node_xyz41, m, threads));
  } else
    fprintf(f, "0 0 0 0\n");
  uint64_t ne = (uint64_t)ev->nedges + m->ntris + m->ntets;
  fprintf(f, "$EndNodes\n$Elements\n%u %llu %d %llu\n", g3[0].nval + g3[1].nval + g3[2].nval,
          (unsigned long long)ne, ne ? 1 : 0, (unsigned long long)ne);
  TR_CHECK(write_elements(f, m, ev, g3, 41, 0, threads));
  fprintf(f, "$EndElements\n");
  return TR_OK;
}

static tr_status write22(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                         const struct groups *g3, int threads)
{
  fprintf(f, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%u\n", m->nverts);
  TR_CHECK(tr_io_write_blocks(f, m->nverts, TR_IO_XYZ_MAX, node_rows22, m, threads));
  fprintf(f, "$EndNodes\n$Elements\n%llu\n",
          (unsigned long long)ev->nedges + m->ntris + m->ntets);
  TR_CHECK(write_elements(f, m, ev, g3, 22, 0, threads));
  fprintf(f, "$EndElements\n");
  return TR_OK;
}

/* Binary forms. Gmsh's binary .msh keeps the text of the section names and of the few
 * counts of format 2.2, and puts every number of the bulk in the writer's native layout,
 * stating its byte order by the int 1 after the header; tetrec always writes
 * little-endian (the encoders of put_number.h), so the file is the same on every host.
 * Integers are 4-byte ints and, in 4.1, 8-byte size_t where Gmsh uses size_t.
 * The binary blocks are encoded on one thread (TR_IO_BINARY_THREADS, blocks.h). */
static void put(FILE *f, const unsigned char *b, const unsigned char *e)
{
  fwrite(b, 1, (size_t)(e - b), f);
}

static void header_binary(FILE *f, const char *version)
{
  unsigned char b[4];
  fprintf(f, "$MeshFormat\n%s 1 8\n", version);
  put(f, b, tr_le32(b, 1));
  fprintf(f, "\n$EndMeshFormat\n");
}

static tr_status write41b(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                          const struct groups *g3, int threads)
{
  unsigned char b[128], *p;
  double box[6];
  bounding_box(m, box);
  int lone = !g3[0].nval && !g3[1].nval && !g3[2].nval;
  header_binary(f, "4.1");
  fprintf(f, "$Entities\n");
  p = tr_le64(b, (uint64_t)lone);
  for (int d = 0; d < 3; d++)
    p = tr_le64(p, g3[d].nval);
  put(f, b, p);
  if (lone) {
    p = tr_le32(b, 1);
    for (int k = 0; k < 3; k++)
      p = tr_le_f64(p, box[k]);
    put(f, b, tr_le64(p, 0));
  }
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    for (uint32_t e = 0; e < g->nval; e++) {
      p = tr_le32(b, e + 1);
      for (int k = 0; k < 6; k++)
        p = tr_le_f64(p, box[k]);
      p = tr_le64(p, g->vals[e] ? 1 : 0);
      if (g->vals[e])
        p = tr_le32(p, (uint32_t)g->vals[e]);
      put(f, b, tr_le64(p, 0)); /* no bounding entities */
    }
  }
  fprintf(f, "\n$EndEntities\n$Nodes\n");
  uint64_t nv = m->nverts;
  p = tr_le64(b, nv ? 1 : 0);
  p = tr_le64(p, nv);
  p = tr_le64(p, nv ? 1 : 0);
  p = tr_le64(p, nv);
  if (nv) {
    int dim = g3[2].nval ? 3 : g3[1].nval ? 2 : g3[0].nval ? 1 : 0;
    p = tr_le32(p, (uint32_t)dim);
    p = tr_le32(p, 1);
    p = tr_le32(p, 0);
    p = tr_le64(p, nv);
  }
  put(f, b, p);
  TR_CHECK(tr_io_write_blocks(f, nv, 8, node_tags41b, m, threads));
  TR_CHECK(tr_io_write_blocks(f, nv, 24, node_xyz41b, m, threads));
  uint64_t ne = (uint64_t)ev->nedges + m->ntris + m->ntets;
  fprintf(f, "\n$EndNodes\n$Elements\n");
  p = tr_le64(b, (uint64_t)g3[0].nval + g3[1].nval + g3[2].nval);
  p = tr_le64(p, ne);
  p = tr_le64(p, ne ? 1 : 0);
  put(f, b, tr_le64(p, ne));
  TR_CHECK(write_elements(f, m, ev, g3, 41, 1, threads));
  fprintf(f, "\n$EndElements\n");
  return TR_OK;
}

static tr_status write22b(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                          const struct groups *g3, int threads)
{
  header_binary(f, "2.2");
  fprintf(f, "$Nodes\n%u\n", m->nverts);
  TR_CHECK(tr_io_write_blocks(f, m->nverts, 28, node_rows22b, m, threads));
  fprintf(f, "\n$EndNodes\n$Elements\n%llu\n",
          (unsigned long long)ev->nedges + m->ntris + m->ntets);
  TR_CHECK(write_elements(f, m, ev, g3, 22, 1, threads));
  fprintf(f, "\n$EndElements\n");
  return TR_OK;
}

tr_status tr_write_msh(const struct tr_mesh_view *m, const char *path, int flags)
{
  return tr_write_msh_edges(m, NULL, path, flags);
}

tr_status tr_write_msh_edges(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path, int flags)
{
  static const struct tr_edge_view none = {0, NULL, NULL};
  const struct tr_edge_view *ev = e ? e : &none;
  int version = TR_WRITE_VERSION(flags), binary = (flags & TR_WRITE_BINARY) != 0;
  if (version != 41 && version != 22)
    return tr_error(TR_ERR_USAGE, "%s: .msh version %d.%d not supported (4.1 or 2.2)", path,
                    version / 10, version % 10);
  /* 2.2 binary numbers nodes and elements with 4-byte ints */
  if (binary && version == 22 &&
      ((uint64_t)m->nverts > INT32_MAX ||
       (uint64_t)ev->nedges + m->ntris + m->ntets > INT32_MAX))
    return tr_error(TR_ERR_UNSUPPORTED, "%s: over 2^31 nodes or elements do not fit binary "
                    ".msh 2.2 (its tags are 4-byte ints): write 4.1", path);
  struct groups g3[3];
  memset(g3, 0, sizeof g3);
  tr_status s = group(ev->edge_marker, ev->nedges, 0, &g3[0]);
  if (s == TR_OK)
    s = group(m->tri_marker, m->ntris, 0, &g3[1]);
  if (s == TR_OK)
    s = group(m->region, m->ntets, 1, &g3[2]);
  if (s != TR_OK) {
    for (int d = 0; d < 3; d++)
      groups_free(&g3[d]);
    return s;
  }
  FILE *f = fopen(path, binary ? "wb" : "w");
  if (!f)
    s = tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  else {
    int th = binary ? TR_IO_BINARY_THREADS : m->threads;
    if (version == 41)
      s = (binary ? write41b : write41)(f, m, ev, g3, th);
    else
      s = (binary ? write22b : write22)(f, m, ev, g3, th);
    int bad = ferror(f);
    if ((fclose(f) != 0 || bad) && s == TR_OK)
      s = tr_error(TR_ERR_IO, "%s: write failed", path);
  }
  for (int d = 0; d < 3; d++)
    groups_free(&g3[d]);
  return s;
}
