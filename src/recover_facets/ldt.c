/* A small exact Delaunay tetrahedralization (see ldt.h). */
#include "recover_facets/ldt.h"

#include <stdlib.h>
#include <string.h>


int tr_ldt_cmp_face(const void *pa, const void *pb)
{
  const tr_ldt_face *a = pa, *b = pb;
  int c = tr_cmp_face_key(a->k, b->k);
  if (c)
    return c;
  if (a->tet != b->tet)
    return a->tet < b->tet ? -1 : 1;
  return (a->face > b->face) - (a->face < b->face);
}

void tr_ldt_face_of(const uint32_t *t, int k, uint32_t out[3])
{
  for (int i = 0; i < 3; i++)
    out[i] = t[tr_face_vtx[k][i]];
}

/* 1 iff (a, b, c) is a rotation of (x, y, z): the same face turning the same way. */
int tr_ldt_same_turn(const uint32_t a[3], const uint32_t x[3])
{
  for (int r = 0; r < 3; r++)
    if (a[0] == x[r] && a[1] == x[(r + 1) % 3] && a[2] == x[(r + 2) % 3])
      return 1;
  return 0;
}

void tr_ldt_free(tr_ldt *D)
{
  free(D->t);
  free(D->cf);
  free(D->fk);
  memset(D, 0, sizeof *D);
}

static tr_status ldt_reserve(tr_ldt *D, uint32_t n)
{
  if (n <= D->cap)
    return TR_OK;
  uint32_t nc = D->cap ? D->cap : 64;
  while (nc < n)
    nc *= 2;
  void *t = realloc(D->t, nc * sizeof *D->t);
  if (!t)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  D->t = t;
  void *c = realloc(D->cf, nc);
  if (!c)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  D->cf = c;
  D->cap = nc;
  return TR_OK;
}

static tr_status fk_reserve(tr_ldt *D, size_t n)
{
  if (n <= D->capfk)
    return TR_OK;
  size_t nc = D->capfk ? D->capfk : 256;
  while (nc < n)
    nc *= 2;
  tr_ldt_face *f = realloc(D->fk, nc * sizeof *f);
  if (!f)
    return tr_error(TR_ERR_NOMEM, "cavity: out of memory");
  D->fk = f;
  D->capfk = nc;
  return TR_OK;
}

static tr_status ldt_push(tr_ldt *D, const uint32_t v[4])
{
  TR_CHECK(ldt_reserve(D, D->n + 1));
  memcpy(D->t[D->n++], v, 4 * sizeof *v);
  return TR_OK;
}

static int has_vertices(const uint32_t *t, const uint32_t k[3])
{
  int c = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 4; j++)
      c += t[j] == k[i];
  return c == 3;
}

/* Bowyer-Watson insertion of point i. The conflict region is every real tet whose open
 * circumball holds p (connected and star-shaped from p in any Delaunay mesh), and every
 * ghost whose hull face p sees strictly, or sees edge-on while the real tet behind the
 * face conflicts (then p is strictly inside that face's circumcircle: the new tet on it
 * would otherwise be flat). *ok = 0 when nothing conflicts (p repeats a point). */
static tr_status ldt_insert(tr_ldt *D, uint32_t i, int *ok)
{
  const tr_point *P = D->p, *pp = &D->p[i];
  *ok = 0;
  int any = 0;
  for (uint32_t j = 0; j < D->n; j++) {
    const uint32_t *t = D->t[j];
    if (t[3] == TR_LDT_GHOST) {
      int o = tr_orient3d_p(&P[t[0]], &P[t[1]], &P[t[2]], pp);
      D->cf[j] = o > 0 ? 1 : o == 0 ? 2 : 0;
    } else {
      D->cf[j] = tr_insphere_p(&P[t[0]], &P[t[1]], &P[t[2]], &P[t[3]], pp) > 0;
    }
  }
  for (uint32_t j = 0; j < D->n; j++) {
    if (D->cf[j] != 2)
      continue;
    D->cf[j] = 0;
    for (uint32_t r = 0; r < D->n; r++)
      if (D->t[r][3] != TR_LDT_GHOST && has_vertices(D->t[r], D->t[j])) {
        D->cf[j] = D->cf[r] == 1;
        break;
      }
  }
  size_t nf = 0;
  for (uint32_t j = 0; j < D->n; j++)
    nf += 4 * (D->cf[j] != 0);
  TR_CHECK(fk_reserve(D, nf));
  nf = 0;
  for (uint32_t j = 0; j < D->n; j++) {
    if (!D->cf[j])
      continue;
    any = 1;
    for (uint32_t k = 0; k < 4; k++) {
      tr_ldt_face_of(D->t[j], (int)k, D->fk[nf].k);
      tr_sort3(D->fk[nf].k);
      D->fk[nf].tet = j;
      D->fk[nf++].face = k;
    }
  }
  if (!any)
    return TR_OK;
  qsort(D->fk, nf, sizeof *D->fk, tr_ldt_cmp_face);
  /* the new tets: each boundary face of the region (a face listed once) with its vertex
   * opposite replaced by p, which keeps the orientation (p sees the face from that
   * vertex's side); they go after the old tets, then the conflict tets are dropped */
  uint32_t nold = D->n;
  for (size_t a = 0; a < nf;) {
    size_t b = a + 1;
    while (b < nf && tr_cmp_face_key(D->fk[a].k, D->fk[b].k) == 0)
      b++;
    if (b == a + 1) {
      uint32_t v[4];
      memcpy(v, D->t[D->fk[a].tet], sizeof v);
      v[D->fk[a].face] = i;
      TR_CHECK(ldt_push(D, v));
    }
    a = b;
  }
  uint32_t keep = 0;
  for (uint32_t j = 0; j < D->n; j++)
    if (j >= nold || !D->cf[j])
      memmove(D->t[keep++], D->t[j], sizeof D->t[j]);
  D->n = keep;
  *ok = 1;
  return TR_OK;
}

static int collinear(const tr_point *a, const tr_point *b, const tr_point *c)
{
  return !tr_orient2d_proj_p(a, b, c, 0) && !tr_orient2d_proj_p(a, b, c, 1) &&
         !tr_orient2d_proj_p(a, b, c, 2);
}

/* The Delaunay mesh of p[0..n) inserted in index order, from the first four points in
 * general position. *ok = 0 when the points span less than 3D or one repeats. */
tr_status tr_ldt_build(tr_ldt *D, const tr_point *p, uint32_t n, int *ok)
{
  D->p = p;
  D->n = 0;
  *ok = 0;
  uint32_t c = 2, d;
  while (c < n && collinear(&p[0], &p[1], &p[c]))
    c++;
  if (n < 4 || c == n)
    return TR_OK;
  int o = 0;
  for (d = 2; d < n; d++)
    if (d != c && (o = tr_orient3d_p(&p[0], &p[1], &p[c], &p[d])) != 0)
      break;
  if (d == n)
    return TR_OK;
  uint32_t t0[4] = {0, 1, c, d};
  if (o < 0) {
    t0[1] = c;
    t0[2] = 1;
  }
  TR_CHECK(ldt_push(D, t0));
  for (int k = 0; k < 4; k++) {
    uint32_t f[3];
    tr_ldt_face_of(t0, k, f);
    uint32_t gh[4] = {f[0], f[2], f[1], TR_LDT_GHOST}; /* hull face turned outward */
    TR_CHECK(ldt_push(D, gh));
  }
  for (uint32_t i = 1; i < n; i++) {
    if (i == 1 || i == c || i == d)
      continue;
    int in;
    TR_CHECK(ldt_insert(D, i, &in));
    if (!in)
      return TR_OK;
  }
  *ok = 1;
  return TR_OK;
}

tr_status tr_ldt_faces(const tr_ldt *D, tr_ldt_face **ft, uint32_t *nft)
{
  *nft = 0;
  free(*ft);
  *ft = malloc(4 * (size_t)(D->n ? D->n : 1) * sizeof **ft);
  if (!*ft)
    return tr_error(TR_ERR_NOMEM, "local Delaunay: out of memory");
  for (uint32_t j = 0; j < D->n; j++) {
    if (D->t[j][3] == TR_LDT_GHOST)
      continue;
    for (uint32_t k = 0; k < 4; k++) {
      tr_ldt_face *f = &(*ft)[(*nft)++];
      tr_ldt_face_of(D->t[j], (int)k, f->k);
      tr_sort3(f->k);
      f->tet = j;
      f->face = k;
    }
  }
  qsort(*ft, *nft, sizeof **ft, tr_ldt_cmp_face);
  return TR_OK;
}

/* The first entry of ft whose sorted key is >= key. */
static size_t lower(const tr_ldt_face *ft, uint32_t nft, const uint32_t key[3])
{
  size_t lo = 0, hi = nft;
  while (lo < hi) {
    size_t mid = (lo + hi) / 2;
    if (tr_cmp_face_key(ft[mid].k, key) < 0)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

uint32_t tr_ldt_find_turned(const tr_ldt *D, const tr_ldt_face *ft, uint32_t nft,
                            const uint32_t loc[3])
{
  uint32_t key[3] = {loc[0], loc[1], loc[2]};
  tr_sort3(key);
  for (size_t i = lower(ft, nft, key); i < nft && tr_cmp_face_key(ft[i].k, key) == 0; i++) {
    uint32_t f[3];
    tr_ldt_face_of(D->t[ft[i].tet], (int)ft[i].face, f);
    if (tr_ldt_same_turn(loc, f))
      return ft[i].tet;
  }
  return TR_NONE;
}

uint32_t tr_ldt_across(const tr_ldt *D, const tr_ldt_face *ft, uint32_t nft, uint32_t j,
                       uint32_t face)
{
  uint32_t key[3];
  tr_ldt_face_of(D->t[j], (int)face, key);
  tr_sort3(key);
  for (size_t i = lower(ft, nft, key); i < nft && tr_cmp_face_key(ft[i].k, key) == 0; i++)
    if (ft[i].tet != j)
      return ft[i].tet;
  return TR_NONE;
}
