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
 * tags are 1-based and contiguous, edges first, then triangles. Doubles in %.17g read back bitwise. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "put_number.h"
#include "write.h"

/* Elements grouped by value: vals[0..nval) the distinct values in increasing order,
 * order[] the elements sorted by (entity, index), first[e] the start of entity e there. */
struct groups {
  uint32_t nval;
  int32_t *vals;
  uint32_t *order, *first;
};

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
  g->vals = malloc(sizeof *g->vals * (n ? n : 1));
  g->order = malloc(sizeof *g->order * (n ? n : 1));
  g->first = calloc((size_t)n + 2, sizeof *g->first);
  if (!g->vals || !g->order || !g->first) {
    groups_free(g);
    return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
  }
  for (uint32_t i = 0; i < n; i++)
    g->vals[i] = val ? val[i] : dflt;
  qsort(g->vals, n, sizeof *g->vals, cmp_i32);
  for (uint32_t i = 0; i < n; i++)
    if (i == 0 || g->vals[i] != g->vals[g->nval - 1])
      g->vals[g->nval++] = g->vals[i];
  /* counting sort by entity keeps index order inside each entity */
  for (uint32_t i = 0; i < n; i++)
    g->first[entity_of(g, val ? val[i] : dflt) + 1]++;
  for (uint32_t e = 0; e < g->nval; e++)
    g->first[e + 1] += g->first[e];
  uint32_t *at = malloc(sizeof *at * (g->nval ? g->nval : 1));
  if (!at) {
    groups_free(g);
    return tr_error(TR_ERR_NOMEM, "out of memory writing .msh");
  }
  memcpy(at, g->first, sizeof *at * g->nval);
  for (uint32_t i = 0; i < n; i++)
    g->order[at[entity_of(g, val ? val[i] : dflt)]++] = i;
  free(at);
  return TR_OK;
}

/* Gmsh element types of the simplices of dimension 1, 2, 3: line, triangle, tetrahedron. */
static const int type_of[4] = {15, 1, 2, 4};

static void put_xyz(FILE *f, const double *x) { tr_io_put_xyz(f, -1, x, "\n"); }

static void write41(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                    const struct groups *g3)
{
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (uint32_t i = 0; i < m->nverts; i++)
    for (int k = 0; k < 3; k++) {
      double x = m->xyz[3 * (size_t)i + k];
      if (i == 0 || x < lo[k])
        lo[k] = x;
      if (i == 0 || x > hi[k])
        hi[k] = x;
    }
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
    for (uint32_t i = 0; i < m->nverts; i++) {
      int64_t t = (int64_t)i + 1;
      tr_io_put_ints(f, &t, 1);
    }
    for (uint32_t i = 0; i < m->nverts; i++)
      put_xyz(f, m->xyz + 3 * (size_t)i);
  } else
    fprintf(f, "0 0 0 0\n");
  uint64_t ne = (uint64_t)ev->nedges + m->ntris + m->ntets;
  fprintf(f, "$EndNodes\n$Elements\n%u %llu %d %llu\n", g3[0].nval + g3[1].nval + g3[2].nval,
          (unsigned long long)ne, ne ? 1 : 0, (unsigned long long)ne);
  uint64_t tag = 1;
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    int per = dim + 1;
    const uint32_t *cv = dim == 1 ? ev->edges : dim == 2 ? m->tris : m->tets;
    for (uint32_t e = 0; e < g->nval; e++) {
      fprintf(f, "%d %u %d %u\n", dim, e + 1, type_of[dim], g->first[e + 1] - g->first[e]);
      for (uint32_t j = g->first[e]; j < g->first[e + 1]; j++) {
        int64_t row[5] = {(int64_t)tag++};
        for (int k = 0; k < per; k++)
          row[k + 1] = (int64_t)cv[(size_t)per * g->order[j] + k] + 1;
        tr_io_put_ints(f, row, per + 1);
      }
    }
  }
  fprintf(f, "$EndElements\n");
}

static void write22(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                    const struct groups *g3)
{
  fprintf(f, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%u\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++) {
    fprintf(f, "%u ", i + 1);
    put_xyz(f, m->xyz + 3 * (size_t)i);
  }
  fprintf(f, "$EndNodes\n$Elements\n%llu\n",
          (unsigned long long)ev->nedges + m->ntris + m->ntets);
  uint64_t tag = 1;
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    int per = dim + 1;
    const uint32_t *cv = dim == 1 ? ev->edges : dim == 2 ? m->tris : m->tets;
    for (uint32_t e = 0; e < g->nval; e++)
      for (uint32_t j = g->first[e]; j < g->first[e + 1]; j++) {
        int64_t row[5];
        for (int k = 0; k < per; k++)
          row[k] = (int64_t)cv[(size_t)per * g->order[j] + k] + 1;
        fprintf(f, "%llu %d 2 %d %u ", (unsigned long long)tag++, type_of[dim], (int)g->vals[e],
                e + 1);
        tr_io_put_ints(f, row, per);
      }
  }
  fprintf(f, "$EndElements\n");
}

/* Binary forms. Gmsh's binary .msh keeps the text of the section names and of the few
 * counts of format 2.2, and puts every number of the bulk in the writer's native layout,
 * stating its byte order by the int 1 after the header; tetrec always writes
 * little-endian (the encoders of put_number.h), so the file is the same on every host.
 * Integers are 4-byte ints and, in 4.1, 8-byte size_t where Gmsh uses size_t. */
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

static void write41b(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                     const struct groups *g3)
{
  unsigned char b[128], *p;
  double box[6] = {0, 0, 0, 0, 0, 0};
  for (uint32_t i = 0; i < m->nverts; i++)
    for (int k = 0; k < 3; k++) {
      double x = m->xyz[3 * (size_t)i + k];
      if (i == 0 || x < box[k])
        box[k] = x;
      if (i == 0 || x > box[3 + k])
        box[3 + k] = x;
    }
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
  for (uint64_t i = 0; i < nv; i++)
    put(f, b, tr_le64(b, i + 1));
  for (uint32_t i = 0; i < m->nverts; i++) {
    p = b;
    for (int k = 0; k < 3; k++)
      p = tr_le_f64(p, m->xyz[3 * (size_t)i + k]);
    put(f, b, p);
  }
  uint64_t ne = (uint64_t)ev->nedges + m->ntris + m->ntets;
  fprintf(f, "\n$EndNodes\n$Elements\n");
  p = tr_le64(b, (uint64_t)g3[0].nval + g3[1].nval + g3[2].nval);
  p = tr_le64(p, ne);
  p = tr_le64(p, ne ? 1 : 0);
  put(f, b, tr_le64(p, ne));
  uint64_t tag = 1;
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    int per = dim + 1;
    const uint32_t *cv = dim == 1 ? ev->edges : dim == 2 ? m->tris : m->tets;
    for (uint32_t e = 0; e < g->nval; e++) {
      p = tr_le32(b, (uint32_t)dim);
      p = tr_le32(p, e + 1);
      p = tr_le32(p, (uint32_t)type_of[dim]);
      put(f, b, tr_le64(p, g->first[e + 1] - g->first[e]));
      for (uint32_t j = g->first[e]; j < g->first[e + 1]; j++) {
        p = tr_le64(b, tag++);
        for (int k = 0; k < per; k++)
          p = tr_le64(p, (uint64_t)cv[(size_t)per * g->order[j] + k] + 1);
        put(f, b, p);
      }
    }
  }
  fprintf(f, "\n$EndElements\n");
}

static void write22b(FILE *f, const struct tr_mesh_view *m, const struct tr_edge_view *ev,
                     const struct groups *g3)
{
  unsigned char b[64], *p;
  header_binary(f, "2.2");
  fprintf(f, "$Nodes\n%u\n", m->nverts);
  for (uint32_t i = 0; i < m->nverts; i++) {
    p = tr_le32(b, i + 1);
    for (int k = 0; k < 3; k++)
      p = tr_le_f64(p, m->xyz[3 * (size_t)i + k]);
    put(f, b, p);
  }
  fprintf(f, "\n$EndNodes\n$Elements\n%llu\n",
          (unsigned long long)ev->nedges + m->ntris + m->ntets);
  uint32_t tag = 1;
  for (int dim = 1; dim <= 3; dim++) {
    const struct groups *g = g3 + dim - 1;
    int per = dim + 1;
    const uint32_t *cv = dim == 1 ? ev->edges : dim == 2 ? m->tris : m->tets;
    for (uint32_t e = 0; e < g->nval; e++) {
      /* one header per entity: type, elements following, tags per element (physical,
       * elementary) */
      p = tr_le32(b, (uint32_t)type_of[dim]);
      p = tr_le32(p, g->first[e + 1] - g->first[e]);
      put(f, b, tr_le32(p, 2));
      for (uint32_t j = g->first[e]; j < g->first[e + 1]; j++) {
        p = tr_le32(b, tag++);
        p = tr_le32(p, (uint32_t)g->vals[e]);
        p = tr_le32(p, e + 1);
        for (int k = 0; k < per; k++)
          p = tr_le32(p, cv[(size_t)per * g->order[j] + k] + 1);
        put(f, b, p);
      }
    }
  }
  fprintf(f, "\n$EndElements\n");
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
    if (version == 41)
      (binary ? write41b : write41)(f, m, ev, g3);
    else
      (binary ? write22b : write22)(f, m, ev, g3);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad)
      s = tr_error(TR_ERR_IO, "%s: write failed", path);
  }
  for (int d = 0; d < 3; d++)
    groups_free(&g3[d]);
  return s;
}
