/* Canonical storage order of a Delaunay mesh.
 *
 * The perturbed Delaunay tetrahedralization is unique, but the slots its tets land in,
 * and which of a tet's 12 positive vertex orders is stored, depend on the insertion
 * order (and, with several threads, on scheduling). Every later stage walks tets in slot
 * order, so this pass makes the store a function of the tetrahedralization alone: each
 * tet rotated (an even permutation: orientation kept) so that its smallest vertex comes
 * first and the smallest of the other three second, ghosts rotated among their first
 * three slots (TR_GHOST stays in slot 3); real tets first, sorted by vertex tuple, then
 * the ghosts sorted by their hull face; free slots dropped, neighbours renumbered.
 * tr_delaunay_build calls it on insertion ids (Hilbert order, a function of the input),
 * then maps the ids back to input indices.
 *
 * Cost: one counting sort on the first vertex (a bucket holds ~6.7 tets on random points;
 * a bucket of a vertex with a huge star falls back to qsort), a pass to write the new
 * arrays. Linear in the number of tets. */
#include <stdlib.h>
#include <string.h>

#include "delaunay.h"

/* PERM[r]: new slot j takes old slot PERM[r][j]. 0..11: real tets, r = 3k + s where k is
 * the old slot of the smallest vertex and s the rotation of the other three, listed from
 * OTH[k] (an order that makes (k, OTH[k]) even); 12..14: ghosts, rotations of slots
 * 0..2. All twelve are the even permutations (orientation kept). INV: the inverses. */
static const uint8_t OTH[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
static const uint8_t PERM[15][4] = {
    {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2}, {1, 3, 2, 0},
    {1, 2, 0, 3}, {2, 0, 1, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {3, 0, 2, 1},
    {3, 2, 1, 0}, {3, 1, 0, 2}, {0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}};
static const uint8_t INV[15][4] = {
    {0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 0, 3, 2}, {3, 0, 2, 1},
    {2, 0, 1, 3}, {1, 2, 0, 3}, {3, 1, 0, 2}, {2, 3, 0, 1}, {1, 3, 2, 0},
    {3, 2, 1, 0}, {2, 1, 3, 0}, {0, 1, 2, 3}, {2, 0, 1, 3}, {1, 2, 0, 3}};

/* The rotation of tet v (see PERM). */
static uint8_t rotation(const uint32_t *v)
{
  if (v[3] == TR_GHOST) {
    const int s = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    return (uint8_t)(12 + s);
  }
  int k = 0;
  for (int j = 1; j < 4; j++)
    k = v[j] < v[k] ? j : k;
  const uint8_t *o = OTH[k];
  const int s = v[o[0]] < v[o[1]] ? (v[o[0]] < v[o[2]] ? 0 : 2) : (v[o[1]] < v[o[2]] ? 1 : 2);
  return (uint8_t)(3 * k + s);
}

/* A tet in the sort: its canonical slots 1..3 (slot 0 is the bucket) and old slot. The
 * records of a bucket are contiguous, so its sort touches one short run of memory. */
typedef struct skey {
  uint32_t v[3];
  uint32_t t;
} skey;

static int skey_cmp(const void *a, const void *b)
{
  const skey *x = a, *y = b;
  for (int j = 0; j < 3; j++)
    if (x->v[j] != y->v[j])
      return x->v[j] < y->v[j] ? -1 : 1;
  return 0;
}

static inline int skey_less(const skey *x, const skey *y)
{
  if (x->v[0] != y->v[0])
    return x->v[0] < y->v[0];
  if (x->v[1] != y->v[1])
    return x->v[1] < y->v[1];
  return x->v[2] < y->v[2];
}

tr_status tr_delaunay_canonical(struct tr_mesh *m)
{
  const uint32_t nt = m->nt, nv = m->nv;
  const size_t nb = 2 * (size_t)nv + 1; /* buckets: real by first vertex, then ghosts */
  uint8_t *rot = malloc(nt ? nt : 1);
  uint32_t *start = calloc(nb + 1, sizeof *start);
  uint32_t *newid = malloc((nt ? nt : 1) * sizeof *newid);
  skey *sk = malloc((nt ? nt : 1) * sizeof *sk);
  uint32_t *tv = malloc(4 * (size_t)(m->cap_t ? m->cap_t : 1) * sizeof *tv);
  uint32_t *tn = malloc(4 * (size_t)(m->cap_t ? m->cap_t : 1) * sizeof *tn);
  tr_status s = TR_OK;
  if (!rot || !start || !newid || !sk || !tv || !tn) {
    s = tr_error(TR_ERR_NOMEM, "out of memory ordering %u tets", nt);
    goto done;
  }
  /* the bucket of each live tet (newid, for now) */
  for (uint32_t t = 0; t < nt; t++) {
    const uint32_t *v = m->tv + 4 * (size_t)t;
    if (v[0] == TR_NONE) {
      newid[t] = TR_NONE;
      continue;
    }
    const uint8_t r = rotation(v);
    rot[t] = r;
    newid[t] = (r < 12 ? 0 : nv) + v[PERM[r][0]];
    start[newid[t] + 1]++;
  }
  for (size_t b = 0; b < nb; b++)
    start[b + 1] += start[b];
  const uint32_t nlive = start[nb];
  for (uint32_t t = 0; t < nt; t++)
    if (newid[t] != TR_NONE) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      const uint8_t *p = PERM[rot[t]];
      skey *k = &sk[start[newid[t]]++];
      k->v[0] = v[p[1]];
      k->v[1] = v[p[2]];
      k->v[2] = v[p[3]];
      k->t = t;
    }
  /* start[b] is now the end of bucket b: sort each bucket by the other three vertices */
  uint32_t lo = 0;
  for (size_t b = 0; b < nb; b++) {
    const uint32_t hi = start[b];
    if (hi - lo > 32) {
      qsort(sk + lo, hi - lo, sizeof *sk, skey_cmp);
    } else {
      for (uint32_t i = lo + 1; i < hi; i++) {
        const skey x = sk[i];
        uint32_t j = i;
        while (j > lo && skey_less(&x, &sk[j - 1])) {
          sk[j] = sk[j - 1];
          j--;
        }
        sk[j] = x;
      }
    }
    lo = hi;
  }
  for (uint32_t i = 0; i < nlive; i++)
    newid[sk[i].t] = i;
  /* in old slot order: the reads stream, the writes go to two lines per tet */
  for (uint32_t t = 0; t < nt; t++) {
    const uint32_t o = newid[t];
    if (o == TR_NONE)
      continue;
    const uint8_t *p = PERM[rot[t]];
    for (int j = 0; j < 4; j++) {
      tv[4 * (size_t)o + j] = m->tv[4 * (size_t)t + p[j]];
      const uint32_t c = m->tn[4 * (size_t)t + p[j]];
      const uint32_t u = c >> 2;
      tn[4 * (size_t)o + j] = 4 * newid[u] + INV[rot[u]][c & 3];
    }
  }
  free(m->tv);
  free(m->tn);
  m->tv = tv;
  m->tn = tn;
  tv = tn = NULL;
  m->nt = nlive;
  m->free_head = TR_NONE;
  m->nfree = 0;
  memset(m->flags, 0, m->cap_t);
done:
  free(rot);
  free(start);
  free(newid);
  free(tv);
  free(tn);
  free(sk);
  return s;
}
