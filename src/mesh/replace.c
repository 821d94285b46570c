/* Generic "replace these tets by those": the gluing step shared by every flip and every
 * Steiner-point split. Faces are matched by their vertex sets, so callers only list the
 * new tets' vertices; a new set that does not fill exactly the old region is refused
 * before anything is modified. */
#include "mesh.h"

#include <stdlib.h>
#include <string.h>

typedef struct face_rec {
  uint32_t v[3];  /* sorted vertex ids */
  uint32_t who;   /* index of the new tet, TR_NONE for a face of the old region's boundary */
  uint32_t code;  /* new: face slot k; boundary: the outside neighbour code (or TR_NONE) */
} face_rec;

static int cmp_rec(const void *pa, const void *pb)
{
  const face_rec *a = pa, *b = pb;
  for (int i = 0; i < 3; i++)
    if (a->v[i] != b->v[i])
      return a->v[i] < b->v[i] ? -1 : 1;
  /* deterministic order inside a group: boundary record first, then by new tet */
  if (a->who != b->who)
    return a->who > b->who ? -1 : 1; /* TR_NONE (boundary) sorts first */
  return a->code < b->code ? -1 : a->code > b->code;
}

/* The vertices of face k of tet tv, sorted (the face's key from either side). */
static void face_sorted(const uint32_t *tv, int k, uint32_t out[3])
{
  for (int i = 0; i < 3; i++)
    out[i] = tv[tr_face_vtx[k][i]];
  tr_sort3(out);
}

tr_status tr_mesh_replace(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                          const uint32_t *newv, uint32_t nnew, uint32_t *new_ids)
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

  size_t nrec = 0, caprec = 4 * ((size_t)nold + nnew);
  face_rec *rec = malloc((caprec ? caprec : 1) * sizeof *rec);
  tr_status s = TR_OK;
  if (!rec) {
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
  qsort(rec, nrec, sizeof *rec, cmp_rec);
  /* Every group of equal faces must be a pair with at least one new tet in it. */
  for (size_t i = 0; i < nrec; i += 2) {
    if (i + 1 >= nrec || memcmp(rec[i].v, rec[i + 1].v, sizeof rec[i].v) != 0 ||
        (i + 2 < nrec && memcmp(rec[i].v, rec[i + 2].v, sizeof rec[i].v) == 0) ||
        rec[i + 1].who == TR_NONE) {
      s = tr_error(TR_ERR_INTERNAL,
                   "replace: face (%u,%u,%u) is not shared by exactly one old-boundary or new "
                   "face: the %u new tets do not fill the region of the %u old ones",
                   rec[i].v[0], rec[i].v[1], rec[i].v[2], nnew, nold);
      goto done;
    }
  }
  if (nnew > nold && m->nfree < nnew - nold)
    if ((s = tr_mesh_reserve_tets(m, m->nt + (nnew - nold - m->nfree))) != TR_OK)
      goto done;

  /* Commit: nothing below can fail. */
  uint32_t *ids = malloc((nnew ? nnew : 1) * sizeof *ids);
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
  for (size_t i = 0; i < nrec; i += 2) {
    const face_rec *a = &rec[i], *b = &rec[i + 1];
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
  free(ids);
  free(rec);
  return TR_OK;

done:
  for (uint32_t i = 0; i < nold; i++)
    m->flags[old[i]] &= (uint8_t)~TR_TF_MARK;
  free(rec);
  return s;
}
