/* Generic "replace these tets by those": the gluing step shared by every flip and every
 * Steiner-point split. Faces are matched by their vertex sets, so callers only list the
 * new tets' vertices; a new set that does not fill exactly the old region is refused
 * before anything is modified. A 2-3 or 3-2 flip, most of the calls, has its links read
 * off its shape instead of matched (pair_23, pair_32), with the same result. */
#include "mesh.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct face_rec {
  uint32_t v[3];  /* sorted vertex ids */
  uint32_t who;   /* index of the new tet, TR_NONE for a face of the old region's boundary */
  uint32_t code;  /* new: face slot k; boundary: the outside neighbour code (or TR_NONE) */
} face_rec;

/* Pairs the records with equal faces through a small open-addressing table: mate[i] =
 * the other record of i's face. Returns the index of a record whose face is not shared
 * by exactly two records, one of them new, or SIZE_MAX when every face pairs up. Gluing
 * does not depend on the order in which pairs are found, so this needs no sort (flips
 * list a few dozen records; sorting them was a tenth of the time of a flip search). */
static size_t pair_recs(const face_rec *r, size_t n, uint32_t *slot, size_t cap,
                        uint32_t *mate, int open)
{
  for (size_t i = 0; i < cap; i++)
    slot[i] = TR_NONE;
  for (size_t i = 0; i < n; i++) {
    mate[i] = TR_NONE;
    size_t k = (size_t)(tr_hash3(r[i].v) >> 32) & (cap - 1);
    while (slot[k] != TR_NONE && memcmp(r[slot[k]].v, r[i].v, sizeof r[i].v) != 0)
      k = (k + 1) & (cap - 1);
    if (slot[k] == TR_NONE) {
      slot[k] = (uint32_t)i;
      continue;
    }
    size_t j = slot[k];
    if (mate[j] != TR_NONE)
      return i; /* a third record of the same face */
    if (r[i].who == TR_NONE && r[j].who == TR_NONE)
      return i; /* two old-boundary faces: the new tets leave a hole */
    mate[j] = (uint32_t)i;
    mate[i] = (uint32_t)j;
  }
  for (size_t i = 0; i < n; i++)
    if (mate[i] == TR_NONE && !(open && (r[i].who != TR_NONE || r[i].code == TR_NONE)))
      return i;
  return SIZE_MAX;
}

/* The vertices of face k of tet tv, sorted (the face's key from either side). */
static void face_sorted(const uint32_t *tv, int k, uint32_t out[3])
{
  for (int i = 0; i < 3; i++)
    out[i] = tv[tr_face_vtx[k][i]];
  tr_sort3(out);
}

/* Puts the new tets in place of the old ones (marks cleared, slots reused in order, the
 * rest freed or taken from the free list, v2t repaired), neighbours left to the caller;
 * capacity for nnew - nold more tets must be there. */
static void commit_tets(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                        const uint32_t *newv, uint32_t nnew, uint32_t *ids)
{
  for (uint32_t i = 0; i < nold; i++) {
    m->flags[old[i]] &= (uint8_t)~TR_TF_MARK;
    for (int k = 0; k < 4; k++) {
      uint32_t v = m->tv[4 * (size_t)old[i] + (size_t)k];
      if (v != TR_GHOST)
        m->v2t[v] = TR_NONE;
    }
  }
  for (uint32_t i = nnew; i < nold; i++)
    tr_tet_free(m, old[i]);
  for (uint32_t i = 0; i < nnew; i++) {
    const uint32_t *v = newv + 4 * (size_t)i;
    if (i < nold) {
      uint32_t t = old[i];
      memcpy(m->tv + 4 * (size_t)t, v, 4 * sizeof *v);
      for (int k = 0; k < 4; k++)
        if (v[k] != TR_GHOST)
          m->v2t[v[k]] = t;
      m->flags[t] = 0;
      ids[i] = t;
    } else {
      (void)tr_tet_new(m, v[0], v[1], v[2], v[3], &ids[i]); /* capacity reserved above */
    }
  }
}

/* ---- 2-3 and 3-2: the pairing read off the configuration ----
 * Most replacements are the 2-3 and 3-2 flips of the recovery searches and their undos
 * (on 65395.stl --keep-surface 9 in 10 of 545,000), where hashing 18 or 20 face records
 * cost more than the rest of the flip. Their shape tells every pairing: with the old
 * tets' vertex sets checked against it below, the new tets have exactly the old region's
 * boundary, so the links are the ones the general matching would find, and the commit
 * is the same code: the mesh ends up the same, slot for slot. Any other shape goes the
 * general way. link[4i+k]: the outside neighbour code of face k of new tet i (TR_NONE:
 * none), or with inner[4i+k] set, 4j+k' for face k' of new tet j. */

static int slot_of(const uint32_t *tv, uint32_t v)
{
  for (int k = 0; k < 4; k++)
    if (tv[k] == v)
      return k;
  return -1;
}

/* Old tets t, u sharing face f (t's apex a, u's apex b); the new tets (a, b, two of f)
 * around the edge ab, each missing another vertex of f. */
static int pair_23(const struct tr_mesh *m, const uint32_t *old, const uint32_t *newv,
                   uint32_t link[12], uint8_t inner[12])
{
  uint32_t t = old[0], u = old[1];
  const uint32_t *tt = m->tv + 4 * (size_t)t, *tu = m->tv + 4 * (size_t)u;
  int k = -1;
  for (int q = 0; q < 4; q++) {
    uint32_t c = m->tn[4 * (size_t)t + (size_t)q];
    if (c != TR_NONE && c >> 2 == u) {
      if (k >= 0)
        return 0;
      k = q;
    }
  }
  if (k < 0)
    return 0;
  int ku = (int)(m->tn[4 * (size_t)t + (size_t)k] & 3);
  uint32_t a = tt[k], b = tu[ku], f[3];
  int ft[3], fu[3]; /* slots of f[q] in t and in u */
  for (int q = 0, n = 0; q < 4; q++)
    if (q != k) {
      f[n] = tt[q];
      ft[n] = q;
      if ((fu[n] = slot_of(tu, f[n])) < 0)
        return 0;
      n++;
    }
  if (slot_of(tu, a) >= 0 || slot_of(tt, b) >= 0)
    return 0;
  int z[3], sa[3], sb[3], used = 0; /* per new tet: missing f vertex, slots of a and b */
  for (int i = 0; i < 3; i++) {
    const uint32_t *v = newv + 4 * i;
    int mask = 0;
    sa[i] = sb[i] = -1;
    for (int s = 0; s < 4; s++) {
      if (v[s] == a && sa[i] < 0)
        sa[i] = s;
      else if (v[s] == b && sb[i] < 0)
        sb[i] = s;
      else if (v[s] == f[0] && !(mask & 1))
        mask |= 1;
      else if (v[s] == f[1] && !(mask & 2))
        mask |= 2;
      else if (v[s] == f[2] && !(mask & 4))
        mask |= 4;
      else
        return 0;
    }
    if (sa[i] < 0 || sb[i] < 0)
      return 0;
    z[i] = mask == 6 ? 0 : mask == 5 ? 1 : 2; /* the other two slots: two of f */
    if (used & (1 << z[i]))
      return 0;
    used |= 1 << z[i];
  }
  int by_z[3]; /* the new tet missing f[q] */
  for (int i = 0; i < 3; i++)
    by_z[z[i]] = i;
  for (int i = 0; i < 3; i++) {
    const uint32_t *v = newv + 4 * i;
    for (int s = 0; s < 4; s++) {
      int x = 4 * i + s;
      inner[x] = 0;
      if (s == sa[i]) {
        link[x] = m->tn[4 * (size_t)u + (size_t)fu[z[i]]]; /* (b, the other two of f) */
      } else if (s == sb[i]) {
        link[x] = m->tn[4 * (size_t)t + (size_t)ft[z[i]]];
      } else {
        /* face (a, b, y), y the other f vertex of tet i: shared with the tet missing v[s],
         * which lists f[z[i]] where tet i has v[s] */
        int q = v[s] == f[0] ? 0 : v[s] == f[1] ? 1 : 2, j = by_z[q];
        link[x] = 4 * (uint32_t)j + (uint32_t)slot_of(newv + 4 * j, f[z[i]]);
        inner[x] = 1;
      }
    }
  }
  return 1;
}

/* Old tets around edge ab, each (a, b, two of the ring r0 r1 r2), every pair of the ring
 * once; the new tets (ring, a) and (ring, b). */
static int pair_32(const struct tr_mesh *m, const uint32_t *old, const uint32_t *newv,
                   uint32_t link[8], uint8_t inner[8])
{
  const uint32_t *t0 = m->tv + 4 * (size_t)old[0];
  uint32_t ab[2];
  int n = 0;
  for (int q = 0; q < 4; q++)
    if (slot_of(m->tv + 4 * (size_t)old[1], t0[q]) >= 0 &&
        slot_of(m->tv + 4 * (size_t)old[2], t0[q]) >= 0) {
      if (n == 2)
        return 0;
      ab[n++] = t0[q];
    }
  if (n != 2)
    return 0;
  uint32_t pr[3][2], r[3];
  int nr = 0;
  for (int o = 0; o < 3; o++) {
    const uint32_t *to = m->tv + 4 * (size_t)old[o];
    for (int q = 0, w = 0; q < 4; q++)
      if (to[q] != ab[0] && to[q] != ab[1]) {
        if (w == 2)
          return 0;
        pr[o][w++] = to[q];
        int seen = 0;
        for (int x = 0; x < nr; x++)
          seen |= r[x] == to[q];
        if (!seen) {
          if (nr == 3)
            return 0;
          r[nr++] = to[q];
        }
      }
  }
  if (nr != 3)
    return 0;
  /* three distinct pairs of the three ring vertices: its three edges */
  for (int o = 0; o < 3; o++)
    for (int p = o + 1; p < 3; p++)
      if ((pr[o][0] == pr[p][0] && pr[o][1] == pr[p][1]) ||
          (pr[o][0] == pr[p][1] && pr[o][1] == pr[p][0]))
        return 0;
  int apex[2];
  for (int i = 0; i < 2; i++) {
    const uint32_t *v = newv + 4 * i;
    int mask = 0;
    apex[i] = -1;
    for (int s = 0; s < 4; s++) {
      int hit = -1;
      for (int x = 0; x < 3; x++)
        if (v[s] == r[x])
          hit = x;
      if (hit >= 0 && !(mask & (1 << hit)))
        mask |= 1 << hit;
      else if (hit < 0 && apex[i] < 0 && (v[s] == ab[0] || v[s] == ab[1]))
        apex[i] = s;
      else
        return 0;
    }
  }
  if (newv[apex[0]] == newv[4 + apex[1]])
    return 0;
  for (int i = 0; i < 2; i++) {
    const uint32_t *v = newv + 4 * i;
    uint32_t other = newv[4 * (1 - i) + apex[1 - i]];
    for (int s = 0; s < 4; s++) {
      int x = 4 * i + s;
      if (s == apex[i]) {
        link[x] = 4 * (uint32_t)(1 - i) + (uint32_t)apex[1 - i];
        inner[x] = 1;
        continue;
      }
      /* face (apex, the two ring vertices besides v[s]): the old tet of that pair, across
       * from the other apex */
      int o = 0;
      while (o < 3 && (pr[o][0] == v[s] || pr[o][1] == v[s]))
        o++;
      const uint32_t *to = m->tv + 4 * (size_t)old[o];
      link[x] = m->tn[4 * (size_t)old[o] + (size_t)slot_of(to, other)];
      inner[x] = 0;
    }
  }
  return 1;
}

/* The fast path: 1 when the replacement was a 2-3 or 3-2 and is done (s = TR_OK), 0 to
 * go the general way (nothing changed), -1 on a failure reported in *s (nothing
 * changed). The old tets are marked and checked. */
static int replace_flip(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                        const uint32_t *newv, uint32_t nnew, uint32_t *new_ids, tr_status *s)
{
  uint32_t link[12];
  uint8_t inner[12];
  if (!(nold == 2 && nnew == 3 && pair_23(m, old, newv, link, inner)) &&
      !(nold == 3 && nnew == 2 && pair_32(m, old, newv, link, inner)))
    return 0;
  if (nnew > nold && m->nfree < nnew - nold &&
      (*s = tr_mesh_reserve_tets(m, m->nt + (nnew - nold - m->nfree))) != TR_OK)
    return -1;
  uint32_t ids[3];
  commit_tets(m, old, nold, newv, nnew, ids);
  for (uint32_t i = 0; i < nnew; i++)
    for (uint32_t k = 0; k < 4; k++) {
      uint32_t x = 4 * i + k, c = link[x];
      if (inner[x]) {
        m->tn[4 * (size_t)ids[i] + k] = 4 * ids[c >> 2] + (c & 3);
      } else {
        m->tn[4 * (size_t)ids[i] + k] = c;
        if (c != TR_NONE)
          m->tn[c] = 4 * ids[i] + k;
      }
    }
  if (new_ids)
    memcpy(new_ids, ids, nnew * sizeof *ids);
  *s = TR_OK;
  return 1;
}

static tr_status replace(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                         const uint32_t *newv, uint32_t nnew, uint32_t *new_ids, int open)
{
  for (uint32_t i = 0; i < nold; i++)
    if (old[i] >= m->nt || tr_tet_is_free(m, old[i]) || (m->flags[old[i]] & TR_TF_MARK)) {
      for (uint32_t j = 0; j < i; j++)
        m->flags[old[j]] &= (uint8_t)~TR_TF_MARK;
      return tr_error(TR_ERR_INTERNAL, "replace: old tet %u is free, out of range or listed twice",
                      old[i]);
    }
    else
      m->flags[old[i]] |= TR_TF_MARK;

  if (!open) {
    tr_status fs = TR_OK;
    int r = replace_flip(m, old, nold, newv, nnew, new_ids, &fs);
    if (r != 0) {
      if (r < 0)
        for (uint32_t i = 0; i < nold; i++)
          m->flags[old[i]] &= (uint8_t)~TR_TF_MARK;
      return fs;
    }
  }
  size_t nrec = 0, caprec = 4 * ((size_t)nold + nnew), cap = 16;
  while (cap < 2 * caprec)
    cap *= 2;
  /* records, their mates and the pairing table: on the stack for most flips */
  face_rec local[128];
  uint32_t lmate[128], lslot[256];
  face_rec *rec = caprec <= 128 ? local : malloc(caprec * sizeof *rec);
  uint32_t *mate = caprec <= 128 ? lmate : malloc(caprec * sizeof *mate);
  uint32_t *slot = cap <= 256 ? lslot : malloc(cap * sizeof *slot);
  tr_status s = TR_OK;
  if (!rec || !mate || !slot) {
    s = tr_error(TR_ERR_NOMEM, "replace: out of memory");
    goto done;
  }
  for (uint32_t i = 0; i < nold; i++) {
    uint32_t t = old[i];
    for (int k = 0; k < 4; k++) {
      uint32_t nc = m->tn[4 * (size_t)t + (size_t)k];
      if (nc != TR_NONE && (m->flags[nc >> 2] & TR_TF_MARK))
        continue;
      face_rec *r = &rec[nrec++];
      face_sorted(m->tv + 4 * (size_t)t, k, r->v);
      r->who = TR_NONE;
      r->code = nc;
    }
  }
  for (uint32_t i = 0; i < nnew; i++)
    for (int k = 0; k < 4; k++) {
      face_rec *r = &rec[nrec++];
      face_sorted(newv + 4 * (size_t)i, k, r->v);
      r->who = i;
      r->code = (uint32_t)k;
    }
  /* Every face must be listed exactly twice, by at least one new tet. */
  size_t bad = pair_recs(rec, nrec, slot, cap, mate, open);
  if (bad != SIZE_MAX) {
    s = tr_error(TR_ERR_INTERNAL,
                 "replace: face (%u,%u,%u) is not shared by exactly one old-boundary or new "
                 "face: the %u new tets do not fill the region of the %u old ones",
                 rec[bad].v[0], rec[bad].v[1], rec[bad].v[2], nnew, nold);
    goto done;
  }
  if (nnew > nold && m->nfree < nnew - nold)
    if ((s = tr_mesh_reserve_tets(m, m->nt + (nnew - nold - m->nfree))) != TR_OK)
      goto done;

  /* Commit: nothing below can fail. */
  uint32_t ids_local[32], *ids = nnew <= 32 ? ids_local : malloc(nnew * sizeof *ids);
  if (!ids) {
    s = tr_error(TR_ERR_NOMEM, "replace: out of memory");
    goto done;
  }
  commit_tets(m, old, nold, newv, nnew, ids);
  for (size_t i = 0; i < nrec; i++) {
    if (mate[i] == TR_NONE) { /* open: a new face on the boundary, or an old one gone */
      if (rec[i].who != TR_NONE)
        m->tn[4 * (size_t)ids[rec[i].who] + rec[i].code] = TR_NONE;
      continue;
    }
    if (mate[i] < i)
      continue; /* glued from its mate */
    const face_rec *a = &rec[i], *b = &rec[mate[i]];
    if (b->who == TR_NONE) {
      const face_rec *x = a;
      a = b;
      b = x;
    }
    if (a->who == TR_NONE) {
      uint32_t t = ids[b->who];
      m->tn[4 * (size_t)t + b->code] = a->code;
      if (a->code != TR_NONE)
        m->tn[a->code] = 4 * t + b->code;
    } else {
      tr_glue(m, ids[a->who], (int)a->code, ids[b->who], (int)b->code);
    }
  }
  if (new_ids)
    memcpy(new_ids, ids, nnew * sizeof *ids);
  if (ids != ids_local)
    free(ids);
  nold = 0; /* committed: the old tets' marks are gone (their slots may hold new tets) */

done:
  for (uint32_t i = 0; i < nold; i++)
    m->flags[old[i]] &= (uint8_t)~TR_TF_MARK;
  if (rec != local)
    free(rec);
  if (mate != lmate)
    free(mate);
  if (slot != lslot)
    free(slot);
  return s;
}

tr_status tr_mesh_replace(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                          const uint32_t *newv, uint32_t nnew, uint32_t *new_ids)
{
  return replace(m, old, nold, newv, nnew, new_ids, 0);
}

tr_status tr_mesh_replace_open(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                               const uint32_t *newv, uint32_t nnew, uint32_t *new_ids)
{
  return replace(m, old, nold, newv, nnew, new_ids, 1);
}
