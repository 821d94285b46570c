/* Gmsh .msh input, formats 4.1 and 2.2, ASCII or binary (what Gmsh, meshio and most FE
 * tools write).
 *
 * Surface input: triangles (type 2) and quadrangles (type 3, as polygons) with their
 * physical tag as marker: in 4.1 the first physical tag of the element's entity (from
 * $Entities; 0 when it has none, is not declared there, or the file has no $Entities), in
 * 2.2 the element's first tag. Tetrahedra (type 4) go to plc->tets for `tetrec check`.
 * Points (15) and lines (1) are skipped: in a surface mesh they are corners and edges of
 * the triangles. Any other element type (higher order, hexahedra, ...) is an error naming
 * it, as are format 4.0 (a different node layout), parametric nodes and partitioned
 * entities. Sections that carry no geometry ($PhysicalNames, $NodeData, ...) are skipped
 * to their $End line.
 *
 * Binary files (file type 1) keep the section names, and in 2.2 the counts of $Nodes and
 * $Elements, as text; the numbers of $Entities, $Nodes and $Elements are in the writer's
 * byte order, which the int 1 after the header states. Little-endian files are read on
 * any host (bytes decoded one by one); a big-endian file is refused by name, as is a data
 * size other than 8 (4.1's size_t). Messages inside binary data give byte offsets.
 *
 * Node tags are arbitrary positive integers (sparse in general): they are mapped to
 * indices through a sorted table of the tags read, never an array sized by a declared
 * maximum tag. Every declared count is checked against the bytes left before allocation,
 * in binary data against the bytes its entries take. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "lex.h"
#include "put_number.h"
#include "soup.h"

struct tagidx {
  uint64_t tag;
  uint32_t idx;
};

struct msh {
  int version; /* 41 or 22, 0 before $MeshFormat */
  int binary;
  struct tagidx *nodes, *ents;
  uint32_t nnodes, cap_nodes, nents, cap_ents;
  int nodes_sorted, ents_sorted;
  int nodes_in_order; /* node tags first, first + 1, ... in file order: index = tag - first */
};

static int cmp_tag(const void *a, const void *b)
{
  uint64_t x = ((const struct tagidx *)a)->tag, y = ((const struct tagidx *)b)->tag;
  return (x > y) - (x < y);
}

static tr_status push(struct tagidx **a, uint32_t *n, uint32_t *cap, uint64_t tag, uint32_t idx)
{
  if (*n == *cap) {
    uint32_t nc = *cap ? 2 * *cap : 64;
    if (nc > TR_IO_MAX_COUNT)
      return tr_error(TR_ERR_NOMEM, "too many tags");
    struct tagidx *na = realloc(*a, sizeof *na * nc);
    if (!na)
      return tr_error(TR_ERR_NOMEM, "out of memory reading .msh");
    *a = na;
    *cap = nc;
  }
  (*a)[*n].tag = tag;
  (*a)[(*n)++].idx = idx;
  return TR_OK;
}

static const struct tagidx *find(const struct tagidx *a, uint32_t n, uint64_t tag)
{
  /* sorted, no tag twice: contiguous tags (what Gmsh and tetrec write) are found by their
   * offset; the search cost 2/3 of reading a .msh of 2.7x10^7 tets (16 s) */
  if (n && a[n - 1].tag - a[0].tag == n - 1)
    return tag >= a[0].tag && tag - a[0].tag < n ? a + (tag - a[0].tag) : NULL;
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (a[mid].tag < tag)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n && a[lo].tag == tag ? a + lo : NULL;
}

/* Sorts a tag table and rejects a tag given twice. */
static tr_status seal(tr_lex *lx, struct tagidx *a, uint32_t n, const char *what)
{
  uint32_t k = 1;
  while (k < n && a[k].tag > a[k - 1].tag)
    k++;
  if (k < n) /* not in increasing order already */
    qsort(a, n, sizeof *a, cmp_tag);
  for (uint32_t i = 1; i < n; i++)
    if (a[i].tag == a[i - 1].tag)
      return tr_error(TR_ERR_INPUT, "%s: %s tag %llu defined twice", lx->name, what,
                      (unsigned long long)a[i].tag);
  return TR_OK;
}

/* The node tags sorted, and whether they are the file's order from the first tag on: then
 * an element's nodes are found without reading the table, whose random reads were most
 * of the rest of reading 2.7x10^7 tets. */
static tr_status seal_nodes(tr_lex *lx, struct msh *g)
{
  TR_CHECK(seal(lx, g->nodes, g->nnodes, "node"));
  g->nodes_sorted = 1;
  g->nodes_in_order = g->nnodes > 0;
  for (uint32_t i = 0; i < g->nnodes && g->nodes_in_order; i++)
    g->nodes_in_order = g->nodes[i].idx == i && g->nodes[i].tag == g->nodes[0].tag + i;
  return TR_OK;
}

static tr_status need(tr_lex *lx, const char *word)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, word);
  if (!tr_lex_is(lx, word))
    return tr_error(TR_ERR_PARSE, "%s:%lu: expected %s, found '%.*s'", lx->name, lx->tokline,
                    word, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
  return TR_OK;
}

static tr_status count(tr_lex *lx, const char *what, size_t min_bytes, uint64_t *n)
{
  TR_CHECK(tr_lex_u64(lx, what, n));
  return tr_check_room(lx->name, lx->tokline, *n, what, tr_lex_left(lx), min_bytes,
                       TR_IO_MAX_COUNT / 4);
}

/* Binary data: a cursor over the bytes after a section line, bounds-checked by every read.
 * Offsets in messages count from the start of the file. */
struct bin {
  const unsigned char *p, *end, *start;
  const char *name;
};

/* Starts binary data at the end of the current text line: Gmsh writes exactly one '\n'
 * (a "\r\n" is taken too) between a section line and its data. */
static tr_status bin_begin(tr_lex *lx, const char *buf, struct bin *c)
{
  const char *q = lx->p;
  if (q < lx->end && *q == '\r')
    q++;
  if (q >= lx->end || *q != '\n')
    return tr_error(TR_ERR_PARSE, "%s:%lu: binary data must start on the next line",
                    lx->name, lx->line);
  c->p = (const unsigned char *)q + 1;
  c->end = (const unsigned char *)lx->end;
  c->start = (const unsigned char *)buf;
  c->name = lx->name;
  return TR_OK;
}

/* Back to text after binary data (the section's $End line follows it). */
static void bin_end(tr_lex *lx, const struct bin *c)
{
  lx->p = (const char *)c->p;
}

static unsigned long bin_at(const struct bin *c)
{
  return (unsigned long)(c->p - c->start);
}

static tr_status bin_need(const struct bin *c, size_t n, const char *what)
{
  if ((size_t)(c->end - c->p) < n)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: file ends inside %s", c->name, bin_at(c), what);
  return TR_OK;
}

/* An untrusted count of entries of at least `per` bytes each, checked against the bytes
 * left before anything is allocated for it. */
static tr_status bin_room(const struct bin *c, uint64_t n, uint64_t per, const char *what)
{
  uint64_t left = (uint64_t)(c->end - c->p);
  if (per && n > left / per)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: %llu %s declared but the file has room for at "
                    "most %llu", c->name, bin_at(c), (unsigned long long)n, what,
                    (unsigned long long)(left / per));
  if (n > TR_IO_MAX_COUNT / 4)
    return tr_error(TR_ERR_NOMEM, "%s: byte %lu: %llu %s exceed the limit of %lu", c->name,
                    bin_at(c), (unsigned long long)n, what, (unsigned long)(TR_IO_MAX_COUNT / 4));
  return TR_OK;
}

static tr_status bin_u64(struct bin *c, const char *what, uint64_t *x)
{
  TR_CHECK(bin_need(c, 8, what));
  *x = tr_get_le64(c->p);
  c->p += 8;
  return TR_OK;
}

static tr_status bin_i32(struct bin *c, const char *what, int32_t *x)
{
  TR_CHECK(bin_need(c, 4, what));
  *x = (int32_t)tr_get_le32(c->p);
  c->p += 4;
  return TR_OK;
}

static tr_status bin_xyz(struct bin *c, double p[3])
{
  TR_CHECK(bin_need(c, 24, "a node's coordinates"));
  for (int k = 0; k < 3; k++) {
    p[k] = tr_get_le_f64(c->p + 8 * k);
    if (!isfinite(p[k]))
      return tr_error(TR_ERR_INPUT, "%s: byte %lu: node coordinate is NaN or infinite", c->name,
                      bin_at(c) + 8 * (unsigned long)k);
  }
  c->p += 24;
  return TR_OK;
}

static tr_status mesh_format(tr_lex *lx, const char *buf, struct msh *g)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, "the format version");
  unsigned long line = lx->tokline;
  if (tr_lex_is(lx, "4.1"))
    g->version = 41;
  else if (lx->toklen >= 2 && lx->tok[0] == '2' && lx->tok[1] == '.')
    g->version = 22; /* 2.0 .. 2.2 share the layout read here */
  else
    return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: .msh format %.*s not supported (4.1 or 2.2; "
                    "gmsh -save -format msh41)", lx->name, line,
                    (int)(lx->toklen > 20 ? 20 : lx->toklen), lx->tok);
  int64_t type, size;
  TR_CHECK(tr_lex_i64(lx, "the file type", &type));
  TR_CHECK(tr_lex_i64(lx, "the data size", &size));
  if (type != 0 && type != 1)
    return tr_error(TR_ERR_PARSE, "%s:%lu: file type %lld (0 ASCII or 1 binary)", lx->name,
                    line, (long long)type);
  g->binary = type == 1;
  if (g->binary) {
    if (size != 8)
      return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: binary .msh with data size %lld not "
                      "supported (8: 64-bit size_t and doubles)", lx->name, line,
                      (long long)size);
    struct bin c = {NULL, NULL, NULL, NULL};
    TR_CHECK(bin_begin(lx, buf, &c));
    TR_CHECK(bin_need(&c, 4, "the byte-order int"));
    uint32_t one = tr_get_le32(c.p);
    if (one == 0x01000000u)
      return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: big-endian binary .msh not supported "
                      "(the int 1 after the header reads 16777216 little-endian): save it "
                      "on a little-endian machine or as ASCII", lx->name, line + 1);
    if (one != 1)
      return tr_error(TR_ERR_PARSE, "%s:%lu: binary .msh: the int after the header is %lu, "
                      "not 1 (file damaged?)", lx->name, line + 1, (unsigned long)one);
    c.p += 4;
    bin_end(lx, &c);
  }
  return need(lx, "$EndMeshFormat");
}

static tr_status entities(tr_lex *lx, struct msh *g)
{
  uint64_t n[4];
  for (int d = 0; d < 4; d++)
    TR_CHECK(count(lx, "entities", 16, &n[d]));
  for (int d = 0; d < 4; d++)
    for (uint64_t i = 0; i < n[d]; i++) {
      int64_t tag, np, nb, phys = 0, x;
      double c;
      TR_CHECK(tr_lex_i64(lx, "an entity tag", &tag));
      for (int k = 0; k < (d ? 6 : 3); k++)
        TR_CHECK(tr_lex_double(lx, "an entity bounding box", &c));
      TR_CHECK(tr_lex_i64(lx, "a number of physical tags", &np));
      if (np < 0)
        return tr_error(TR_ERR_PARSE, "%s:%lu: negative number of physical tags", lx->name,
                        lx->tokline);
      for (int64_t k = 0; k < np; k++) {
        TR_CHECK(tr_lex_i64(lx, "a physical tag", &x));
        if (k == 0)
          phys = x;
      }
      if (d > 0) {
        TR_CHECK(tr_lex_i64(lx, "a number of bounding entities", &nb));
        if (nb < 0)
          return tr_error(TR_ERR_PARSE, "%s:%lu: negative number of bounding entities",
                          lx->name, lx->tokline);
        for (int64_t k = 0; k < nb; k++)
          TR_CHECK(tr_lex_i64(lx, "a bounding entity tag", &x));
      }
      if (tag < 0 || tag > INT32_MAX || phys < INT32_MIN || phys > INT32_MAX)
        return tr_error(TR_ERR_INPUT, "%s:%lu: entity tag %lld or physical tag %lld out of range",
                        lx->name, lx->tokline, (long long)tag, (long long)phys);
      /* key: dimension and tag; value: the physical tag as int32 bits */
      TR_CHECK(push(&g->ents, &g->nents, &g->cap_ents, ((uint64_t)d << 32) | (uint64_t)tag,
                    (uint32_t)(int32_t)phys));
    }
  TR_CHECK(seal(lx, g->ents, g->nents, "entity"));
  g->ents_sorted = 1;
  return need(lx, "$EndEntities");
}

static tr_status node(tr_lex *lx, struct msh *g, tr_soup *s, uint64_t tag)
{
  if (tag == 0)
    return tr_error(TR_ERR_INPUT, "%s:%lu: node tag 0 (tags start at 1)", lx->name, lx->tokline);
  return push(&g->nodes, &g->nnodes, &g->cap_nodes, tag, s->npoints);
}

static tr_status point(tr_lex *lx, tr_soup *s)
{
  double p[3];
  for (int k = 0; k < 3; k++)
    TR_CHECK(tr_lex_double(lx, "a node coordinate", &p[k]));
  return tr_soup_add_point(s, p);
}

static tr_status nodes(tr_lex *lx, struct msh *g, tr_soup *s)
{
  if (g->nnodes)
    return tr_error(TR_ERR_PARSE, "%s:%lu: a second $Nodes section", lx->name, lx->tokline);
  uint64_t nblocks = 1, total, x;
  if (g->version == 41) {
    TR_CHECK(count(lx, "node blocks", 8, &nblocks));
    TR_CHECK(count(lx, "nodes", 8, &total));
    TR_CHECK(tr_lex_u64(lx, "the smallest node tag", &x));
    TR_CHECK(tr_lex_u64(lx, "the largest node tag", &x));
  } else
    TR_CHECK(count(lx, "nodes", 8, &total));
  TR_CHECK(tr_soup_reserve_points(s, (uint32_t)total));
  for (uint64_t b = 0; b < nblocks; b++) {
    uint64_t n = total;
    if (g->version == 41) {
      int64_t dim, ent, param;
      TR_CHECK(tr_lex_i64(lx, "the entity dimension", &dim));
      TR_CHECK(tr_lex_i64(lx, "the entity tag", &ent));
      TR_CHECK(tr_lex_i64(lx, "the parametric flag", &param));
      if (param != 0)
        return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: parametric nodes not supported", lx->name,
                        lx->tokline);
      TR_CHECK(count(lx, "nodes in the block", 8, &n));
      uint32_t first = s->npoints;
      for (uint64_t i = 0; i < n; i++) {
        TR_CHECK(tr_lex_u64(lx, "a node tag", &x));
        TR_CHECK(node(lx, g, s, x));
        g->nodes[g->nnodes - 1].idx = first + (uint32_t)i;
      }
      for (uint64_t i = 0; i < n; i++)
        TR_CHECK(point(lx, s));
    } else
      for (uint64_t i = 0; i < n; i++) {
        TR_CHECK(tr_lex_u64(lx, "a node tag", &x));
        TR_CHECK(node(lx, g, s, x));
        TR_CHECK(point(lx, s));
      }
  }
  if (g->nnodes != total)
    return tr_error(TR_ERR_PARSE, "%s:%lu: %u nodes in the blocks, %llu declared", lx->name,
                    lx->tokline, g->nnodes, (unsigned long long)total);
  TR_CHECK(seal_nodes(lx, g));
  return need(lx, "$EndNodes");
}

/* Nodes per element of the types Gmsh numbers 1..15 (0: unknown to this reader). */
static int nodes_of_type(int64_t t)
{
  static const int n[16] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1};
  return t >= 1 && t <= 15 ? n[t] : 0;
}

static int supported_type(int64_t type)
{
  return type == 1 || type == 2 || type == 3 || type == 4 || type == 15;
}

static tr_status unsupported_type(const char *name, const char *unit, unsigned long at,
                                  int64_t type)
{
  return tr_error(TR_ERR_UNSUPPORTED, "%s:%s%lu: element type %lld not supported (points, "
                  "lines, triangles, quadrangles and tetrahedra of order 1 are)", name, unit,
                  at, (long long)type);
}

/* One element of a supported type from its node tags: a facet, a tet, or nothing (points
 * and lines). `unit` and `at` place it for messages: "" and a line, or " byte " and an
 * offset. */
static tr_status store(struct msh *g, tr_soup *s, int64_t type, int32_t marker,
                       const uint64_t *tag, const char *name, const char *unit,
                       unsigned long at)
{
  int nn = nodes_of_type(type);
  uint32_t v[4];
  for (int k = 0; k < nn; k++) {
    uint64_t first = g->nnodes ? g->nodes[0].tag : 0;
    if (g->nodes_in_order && tag[k] >= first && tag[k] - first < g->nnodes) {
      if (k < 4)
        v[k] = (uint32_t)(tag[k] - first);
      continue;
    }
    const struct tagidx *t = find(g->nodes, g->nnodes, tag[k]);
    if (!t)
      return tr_error(TR_ERR_INPUT, "%s:%s%lu: node tag %llu is not defined in $Nodes", name,
                      unit, at, (unsigned long long)tag[k]);
    if (k < 4)
      v[k] = t->idx;
  }
  if (type == 2 || type == 3) {
    TR_CHECK(tr_soup_begin_facet(s, marker, at));
    TR_CHECK(tr_soup_begin_loop(s));
    for (int k = 0; k < nn; k++)
      TR_CHECK(tr_soup_add_index(s, v[k]));
  } else if (type == 4)
    for (int k = 0; k < 4; k++)
      TR_CHECK(tr_u32vec_push(&s->tets, v[k]));
  return TR_OK;
}

static tr_status element(tr_lex *lx, struct msh *g, tr_soup *s, int64_t type, int32_t marker)
{
  if (!supported_type(type))
    return unsupported_type(lx->name, "", lx->tokline, type);
  int nn = nodes_of_type(type);
  uint64_t tag[4];
  unsigned long line = lx->tokline;
  for (int k = 0; k < nn; k++)
    TR_CHECK(tr_lex_u64(lx, "an element node tag", &tag[k]));
  return store(g, s, type, marker, tag, lx->name, "", line);
}

static tr_status elements(tr_lex *lx, struct msh *g, tr_soup *s)
{
  if (!g->nodes_sorted)
    return tr_error(TR_ERR_PARSE, "%s:%lu: $Elements before $Nodes", lx->name, lx->tokline);
  uint64_t nblocks, total, x;
  int64_t tag;
  if (g->version == 41) {
    TR_CHECK(count(lx, "element blocks", 8, &nblocks));
    TR_CHECK(count(lx, "elements", 4, &total));
    TR_CHECK(tr_lex_u64(lx, "the smallest element tag", &x));
    TR_CHECK(tr_lex_u64(lx, "the largest element tag", &x));
    uint64_t seen = 0;
    for (uint64_t b = 0; b < nblocks; b++) {
      int64_t dim, ent, type;
      uint64_t n;
      TR_CHECK(tr_lex_i64(lx, "the entity dimension", &dim));
      TR_CHECK(tr_lex_i64(lx, "the entity tag", &ent));
      TR_CHECK(tr_lex_i64(lx, "the element type", &type));
      TR_CHECK(count(lx, "elements in the block", 4, &n));
      int32_t marker = 0;
      if (g->ents_sorted && dim >= 0 && dim <= 3 && ent >= 0 && ent <= INT32_MAX) {
        /* An entity missing from $Entities has no physical tag to give: meshio writes such
         * files (blocks of an entity it does not declare), and Gmsh reads them. */
        const struct tagidx *e = find(g->ents, g->nents, ((uint64_t)dim << 32) | (uint64_t)ent);
        marker = e ? (int32_t)e->idx : 0;
      }
      for (uint64_t i = 0; i < n; i++) {
        TR_CHECK(tr_lex_i64(lx, "an element tag", &tag));
        TR_CHECK(element(lx, g, s, type, marker));
      }
      seen += n;
    }
    if (seen != total)
      return tr_error(TR_ERR_PARSE, "%s:%lu: %llu elements in the blocks, %llu declared",
                      lx->name, lx->tokline, (unsigned long long)seen, (unsigned long long)total);
  } else {
    TR_CHECK(count(lx, "elements", 8, &total));
    for (uint64_t i = 0; i < total; i++) {
      int64_t type, ntags, t, marker = 0;
      TR_CHECK(tr_lex_i64(lx, "an element tag", &tag));
      TR_CHECK(tr_lex_i64(lx, "an element type", &type));
      TR_CHECK(tr_lex_i64(lx, "a number of tags", &ntags));
      if (ntags < 0)
        return tr_error(TR_ERR_PARSE, "%s:%lu: negative number of tags", lx->name, lx->tokline);
      for (int64_t k = 0; k < ntags; k++) {
        TR_CHECK(tr_lex_i64(lx, "an element tag", &t));
        if (k == 0)
          marker = t;
      }
      if (marker < INT32_MIN || marker > INT32_MAX)
        return tr_error(TR_ERR_INPUT, "%s:%lu: physical tag %lld out of range", lx->name,
                        lx->tokline, (long long)marker);
      TR_CHECK(element(lx, g, s, type, (int32_t)marker));
    }
  }
  return need(lx, "$EndElements");
}

/* ---- binary sections ---- */

/* 4.1: four size_t counts, then per entity its tag, bounding box (a point: its
 * coordinates), physical tags and, above dimension 0, bounding entities. */
static tr_status entities_bin(tr_lex *lx, const char *buf, struct msh *g)
{
  struct bin c = {NULL, NULL, NULL, NULL};
  uint64_t n[4];
  TR_CHECK(bin_begin(lx, buf, &c));
  for (int d = 0; d < 4; d++)
    TR_CHECK(bin_u64(&c, "the entity counts", &n[d]));
  for (int d = 0; d < 4; d++) {
    /* the fewest bytes an entity of dimension d takes */
    TR_CHECK(bin_room(&c, n[d], d ? 4 + 48 + 16 : 4 + 24 + 8, "entities"));
    for (uint64_t i = 0; i < n[d]; i++) {
      int32_t tag, phys = 0, x;
      uint64_t np, nb;
      TR_CHECK(bin_i32(&c, "an entity tag", &tag));
      TR_CHECK(bin_need(&c, d ? 48 : 24, "an entity bounding box"));
      c.p += d ? 48 : 24;
      TR_CHECK(bin_u64(&c, "a number of physical tags", &np));
      TR_CHECK(bin_room(&c, np, 4, "physical tags"));
      for (uint64_t k = 0; k < np; k++) {
        TR_CHECK(bin_i32(&c, "a physical tag", &x));
        if (k == 0)
          phys = x;
      }
      if (d > 0) {
        TR_CHECK(bin_u64(&c, "a number of bounding entities", &nb));
        TR_CHECK(bin_room(&c, nb, 4, "bounding entities"));
        c.p += 4 * nb;
      }
      if (tag < 0)
        return tr_error(TR_ERR_INPUT, "%s: byte %lu: negative entity tag %ld", c.name,
                        bin_at(&c), (long)tag);
      TR_CHECK(push(&g->ents, &g->nents, &g->cap_ents, ((uint64_t)d << 32) | (uint64_t)tag,
                    (uint32_t)phys));
    }
  }
  bin_end(lx, &c);
  TR_CHECK(seal(lx, g->ents, g->nents, "entity"));
  g->ents_sorted = 1;
  return need(lx, "$EndEntities");
}

static tr_status node_bin(const struct bin *c, struct msh *g, tr_soup *s, uint64_t tag)
{
  if (tag == 0 || tag > INT64_MAX)
    return tr_error(TR_ERR_INPUT, "%s: byte %lu: node tag %llu (tags run from 1 to 2^63-1)",
                    c->name, bin_at(c) - 8, (unsigned long long)tag);
  return push(&g->nodes, &g->nnodes, &g->cap_nodes, tag, s->npoints);
}

/* 4.1: four size_t (blocks, nodes, smallest and largest tag), then per block its entity
 * dimension, tag and parametric flag (ints), its size (size_t), the node tags (size_t)
 * and the coordinates. 2.2: the count as text, then per node an int tag and three
 * doubles. */
static tr_status nodes_bin(tr_lex *lx, const char *buf, struct msh *g, tr_soup *s)
{
  if (g->nnodes)
    return tr_error(TR_ERR_PARSE, "%s:%lu: a second $Nodes section", lx->name, lx->tokline);
  struct bin c = {NULL, NULL, NULL, NULL};
  uint64_t nblocks = 0, total, x;
  if (g->version == 22)
    TR_CHECK(count(lx, "nodes", 28, &total));
  TR_CHECK(bin_begin(lx, buf, &c));
  if (g->version == 41) {
    TR_CHECK(bin_u64(&c, "the number of node blocks", &nblocks));
    TR_CHECK(bin_u64(&c, "the number of nodes", &total));
    TR_CHECK(bin_u64(&c, "the smallest node tag", &x));
    TR_CHECK(bin_u64(&c, "the largest node tag", &x));
    TR_CHECK(bin_room(&c, nblocks, 20, "node blocks"));
    TR_CHECK(bin_room(&c, total, 32, "nodes"));
  } else
    TR_CHECK(bin_room(&c, total, 28, "nodes"));
  TR_CHECK(tr_soup_reserve_points(s, (uint32_t)total));
  double p[3];
  if (g->version == 22)
    for (uint64_t i = 0; i < total; i++) {
      int32_t tag;
      TR_CHECK(bin_i32(&c, "a node tag", &tag));
      if (tag < 1)
        return tr_error(TR_ERR_INPUT, "%s: byte %lu: node tag %ld (tags start at 1)", c.name,
                        bin_at(&c) - 4, (long)tag);
      TR_CHECK(node_bin(&c, g, s, (uint64_t)tag));
      TR_CHECK(bin_xyz(&c, p));
      TR_CHECK(tr_soup_add_point(s, p));
    }
  for (uint64_t b = 0; b < nblocks; b++) {
    int32_t dim, ent, param;
    uint64_t n;
    TR_CHECK(bin_i32(&c, "the entity dimension", &dim));
    TR_CHECK(bin_i32(&c, "the entity tag", &ent));
    TR_CHECK(bin_i32(&c, "the parametric flag", &param));
    if (param != 0)
      return tr_error(TR_ERR_UNSUPPORTED, "%s: byte %lu: parametric nodes not supported",
                      c.name, bin_at(&c));
    TR_CHECK(bin_u64(&c, "the number of nodes in the block", &n));
    TR_CHECK(bin_room(&c, n, 32, "nodes in the block"));
    if (n > total - g->nnodes)
      return tr_error(TR_ERR_PARSE, "%s: byte %lu: the blocks hold more than the %llu nodes "
                      "declared", c.name, bin_at(&c), (unsigned long long)total);
    uint32_t first = s->npoints;
    for (uint64_t i = 0; i < n; i++) {
      TR_CHECK(bin_u64(&c, "a node tag", &x));
      TR_CHECK(node_bin(&c, g, s, x));
      g->nodes[g->nnodes - 1].idx = first + (uint32_t)i;
    }
    for (uint64_t i = 0; i < n; i++) {
      TR_CHECK(bin_xyz(&c, p));
      TR_CHECK(tr_soup_add_point(s, p));
    }
  }
  if (g->nnodes != total)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: %u nodes in the blocks, %llu declared",
                    c.name, bin_at(&c), g->nnodes, (unsigned long long)total);
  bin_end(lx, &c);
  TR_CHECK(seal_nodes(lx, g));
  return need(lx, "$EndNodes");
}

/* 4.1: four size_t (blocks, elements, smallest and largest tag), then per block its entity
 * dimension and tag and the element type (ints), its size (size_t), and per element its
 * tag and node tags (size_t). 2.2: the count as text, then groups: a header of three ints
 * (type, elements following, tags per element), then per element its number, its tags
 * (the first is the physical tag, the marker) and its node tags, all ints. */
static tr_status elements_bin(tr_lex *lx, const char *buf, struct msh *g, tr_soup *s)
{
  if (!g->nodes_sorted)
    return tr_error(TR_ERR_PARSE, "%s:%lu: $Elements before $Nodes", lx->name, lx->tokline);
  struct bin c = {NULL, NULL, NULL, NULL};
  uint64_t nblocks = 0, total, x, seen = 0;
  if (g->version == 22)
    TR_CHECK(count(lx, "elements", 8, &total));
  TR_CHECK(bin_begin(lx, buf, &c));
  if (g->version == 41) {
    TR_CHECK(bin_u64(&c, "the number of element blocks", &nblocks));
    TR_CHECK(bin_u64(&c, "the number of elements", &total));
    TR_CHECK(bin_u64(&c, "the smallest element tag", &x));
    TR_CHECK(bin_u64(&c, "the largest element tag", &x));
    TR_CHECK(bin_room(&c, nblocks, 20, "element blocks"));
  }
  for (uint64_t b = 0; g->version == 41 && b < nblocks; b++) {
    int32_t dim, ent, type;
    uint64_t n, tag[5];
    TR_CHECK(bin_i32(&c, "the entity dimension", &dim));
    TR_CHECK(bin_i32(&c, "the entity tag", &ent));
    TR_CHECK(bin_i32(&c, "the element type", &type));
    if (!supported_type(type))
      return unsupported_type(c.name, " byte ", bin_at(&c) - 4, type);
    TR_CHECK(bin_u64(&c, "the number of elements in the block", &n));
    int nn = nodes_of_type(type);
    TR_CHECK(bin_room(&c, n, 8 * (1 + (uint64_t)nn), "elements in the block"));
    int32_t marker = 0;
    if (g->ents_sorted && dim >= 0 && dim <= 3 && ent >= 0) {
      const struct tagidx *e = find(g->ents, g->nents, ((uint64_t)dim << 32) | (uint64_t)ent);
      marker = e ? (int32_t)e->idx : 0;
    }
    for (uint64_t i = 0; i < n; i++) {
      unsigned long at = bin_at(&c);
      for (int k = 0; k <= nn; k++)
        TR_CHECK(bin_u64(&c, "an element", &tag[k]));
      TR_CHECK(store(g, s, type, marker, tag + 1, c.name, " byte ", at));
    }
    seen += n;
  }
  while (g->version == 22 && seen < total) {
    int32_t type, follow, ntags, v;
    TR_CHECK(bin_i32(&c, "an element group's type", &type));
    TR_CHECK(bin_i32(&c, "an element group's size", &follow));
    TR_CHECK(bin_i32(&c, "an element group's number of tags", &ntags));
    if (!supported_type(type))
      return unsupported_type(c.name, " byte ", bin_at(&c) - 12, type);
    int nn = nodes_of_type(type);
    if (follow < 1 || (uint64_t)follow > total - seen || ntags < 0)
      return tr_error(TR_ERR_PARSE, "%s: byte %lu: element group of %ld elements with %ld tags "
                      "(%llu elements left of the %llu declared)", c.name, bin_at(&c) - 8,
                      (long)follow, (long)ntags, (unsigned long long)(total - seen),
                      (unsigned long long)total);
    TR_CHECK(bin_room(&c, (uint64_t)follow, 4 * (1 + (uint64_t)ntags + (uint64_t)nn),
                      "elements in the group"));
    for (int32_t i = 0; i < follow; i++) {
      unsigned long at = bin_at(&c);
      int32_t marker = 0;
      uint64_t tag[4];
      TR_CHECK(bin_i32(&c, "an element number", &v));
      for (int32_t k = 0; k < ntags; k++) {
        TR_CHECK(bin_i32(&c, "an element tag", &v));
        if (k == 0)
          marker = v;
      }
      for (int k = 0; k < nn; k++) {
        TR_CHECK(bin_i32(&c, "an element node tag", &v));
        tag[k] = v < 1 ? 0 : (uint64_t)v; /* 0 is no tag: reported as undefined */
      }
      TR_CHECK(store(g, s, type, marker, tag, c.name, " byte ", at));
    }
    seen += (uint64_t)follow;
  }
  if (seen != total)
    return tr_error(TR_ERR_PARSE, "%s: byte %lu: %llu elements in the blocks, %llu declared",
                    c.name, bin_at(&c), (unsigned long long)seen, (unsigned long long)total);
  bin_end(lx, &c);
  return need(lx, "$EndElements");
}

/* Skips a section we do not read, up to its $End line. */
static tr_status skip_section(tr_lex *lx)
{
  char end[72] = "$End";
  size_t n = lx->toklen - 1;
  if (n > sizeof end - 5)
    n = sizeof end - 5;
  memcpy(end + 4, lx->tok + 1, n);
  end[4 + n] = '\0';
  unsigned long line = lx->tokline;
  while (tr_lex_next(lx))
    if (tr_lex_is(lx, end))
      return TR_OK;
  return tr_error(TR_ERR_PARSE, "%s:%lu: section $%s has no %s line", lx->name, line, end + 4,
                  end);
}

static tr_status parse(tr_lex *lx, const char *buf, tr_soup *s, struct msh *g)
{
  while (tr_lex_next(lx)) {
    if (lx->tok[0] != '$')
      return tr_error(TR_ERR_PARSE, "%s:%lu: expected a section ($Name), found '%.*s'", lx->name,
                      lx->tokline, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
    if (tr_lex_is(lx, "$MeshFormat")) {
      TR_CHECK(mesh_format(lx, buf, g));
      continue;
    }
    if (!g->version)
      return tr_error(TR_ERR_PARSE, "%s:%lu: no $MeshFormat section first", lx->name,
                      lx->tokline);
    if (tr_lex_is(lx, "$Entities") && g->version == 41)
      TR_CHECK(g->binary ? entities_bin(lx, buf, g) : entities(lx, g));
    else if (tr_lex_is(lx, "$PartitionedEntities"))
      return tr_error(TR_ERR_UNSUPPORTED, "%s:%lu: partitioned meshes not supported", lx->name,
                      lx->tokline);
    else if (tr_lex_is(lx, "$Nodes"))
      TR_CHECK(g->binary ? nodes_bin(lx, buf, g, s) : nodes(lx, g, s));
    else if (tr_lex_is(lx, "$Elements"))
      TR_CHECK(g->binary ? elements_bin(lx, buf, g, s) : elements(lx, g, s));
    else
      TR_CHECK(skip_section(lx));
  }
  if (!g->version)
    return tr_error(TR_ERR_PARSE, "%s: not a Gmsh file (no $MeshFormat)", lx->name);
  if (!g->nodes_sorted)
    return tr_error(TR_ERR_PARSE, "%s: no $Nodes section", lx->name);
  return TR_OK;
}

tr_status tr_read_msh_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc)
{
  tr_lex lx;
  tr_soup s;
  struct msh g;
  memset(&g, 0, sizeof g);
  tr_lex_init(&lx, buf, len, name, 0);
  tr_soup_init(&s, lx.name);
  tr_status st = parse(&lx, buf, &s, &g);
  free(g.nodes);
  free(g.ents);
  if (st == TR_OK)
    st = tr_soup_to_plc(&s, plc);
  tr_soup_free(&s);
  if (st != TR_OK)
    tr_plc_clear(plc);
  return st;
}
