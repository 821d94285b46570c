/* Generic "replace these tets by those": the gluing step shared by every flip and every
 * Steiner-point split. Faces are matched by their vertex sets, so callers only list the
 * new tets' vertices; a new set that does not fill exactly the old region is refused
 * before anything is modified. */
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
