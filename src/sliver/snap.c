/* Snapshots of the mesh and their exact undo (snap.h). */
#include "sliver/snap.h"

#include <stdlib.h>
#include <string.h>

void tr_sliver_snap_free(tr_sliver_snap *z)
{
  free(z->tv_own);
  free(z->region);
  free(z->v2t);
  free(z->flags);
  free(z->free_tn);
  tr_subfaces_free(&z->sub);
  memset(z, 0, sizeof *z);
}

tr_status tr_sliver_snap_take(const tr_sliver_ctx *c, const tr_subfaces *sub, tr_sliver_snap *z)
{
  const struct tr_mesh *m = c->m;
  memset(z, 0, sizeof *z);
  z->tv = tr_sliver_shape_keys(c, &z->stride);
  z->nv = m->nv;
  z->nt = m->nt;
  z->free_head = m->free_head;
  z->nfree = m->nfree;
  uint32_t nfree = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    nfree += tr_tet_is_free(m, t);
  size_t nt = m->nt ? m->nt : 1, nv = m->nv ? m->nv : 1, ns = sub->n ? sub->n : 1;
  if (!z->tv) {
    z->tv = z->tv_own = malloc(sizeof *z->tv * 4 * nt);
    z->stride = 4;
  }
  z->flags = malloc(nt);
  z->region = m->region ? malloc(sizeof *z->region * nt) : NULL;
  z->v2t = malloc(sizeof *z->v2t * nv);
  z->free_tn = malloc(sizeof *z->free_tn * 5 * ((size_t)nfree + 1));
  z->sub.v = malloc(sizeof *z->sub.v * 3 * ns);
  z->sub.tri = malloc(sizeof *z->sub.tri * ns);
  if (!z->tv || !z->flags || (m->region && !z->region) || !z->v2t || !z->free_tn ||
      !z->sub.v || !z->sub.tri) {
    tr_sliver_snap_free(z);
    return tr_error(TR_ERR_NOMEM, "out of memory for a snapshot of %u tets", m->nt);
  }
  if (z->tv_own)
    memcpy(z->tv_own, m->tv, sizeof *z->tv * 4 * (size_t)m->nt);
  memcpy(z->flags, m->flags, m->nt);
  if (m->region)
    memcpy(z->region, m->region, sizeof *z->region * (size_t)m->nt);
  memcpy(z->v2t, m->v2t, sizeof *z->v2t * (size_t)m->nv);
  uint32_t *f = z->free_tn;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_free(m, t)) {
      *f++ = t;
      memcpy(f, m->tn + 4 * (size_t)t, 4 * sizeof *f);
      f += 4;
    }
  z->nfree_slots = nfree;
  z->sub.n = sub->n;
  memcpy(z->sub.v, sub->v, sizeof *sub->v * 3 * (size_t)sub->n);
  memcpy(z->sub.tri, sub->tri, sizeof *sub->tri * (size_t)sub->n);
  return TR_OK;
}

/* Links face k of slot t to what the face map holds for the same face (its other tet,
 * both ways), or enters it there. */
static tr_status link_face(struct tr_mesh *m, tr_vtmap *faces, uint32_t t, int k)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  uint32_t key[3], code = 4 * t + (uint32_t)k, other;
  tr_vtkey_face(v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]], key);
  TR_CHECK(tr_vtmap_put(faces, 3, key, code, &other));
  if (other != code) {
    m->tn[code] = other;
    m->tn[other] = code;
  }
  return TR_OK;
}

/* The mesh and sub-faces as they were at the snapshot (which is consumed). The slots
 * whose tets changed get their old tets, linked to each other and to the unchanged
 * tets around them through their shared faces: in a valid mesh each face has at most
 * one tet on either side, so these are exactly the old links. */
tr_status tr_sliver_snap_restore(struct tr_mesh *m, tr_subfaces *sub, tr_sliver_snap *z)
{
  for (uint32_t v = z->nv; v < m->nv; v++)
    if (m->vq && m->vq[v]) {
      tr_qpoint_clear(m->vq[v]);
      free(m->vq[v]);
      m->vq[v] = NULL;
    }
  /* which slots changed, compared once: the rim scan below asks about every slot's four
   * neighbours (on a mesh of 230k tets the comparisons were most of an undo) */
  uint32_t nold = z->nt < m->nt ? z->nt : m->nt;
  uint8_t *chg = malloc(nold ? nold : 1);
  if (!chg)
    return tr_error(TR_ERR_NOMEM, "out of memory undoing a constraint trial of %u tets", m->nt);
  for (uint32_t t = 0; t < nold; t++)
    chg[t] = (uint8_t)tr_sliver_snap_changed(m, z, t);
#define CHANGED(u) ((u) >= nold || chg[u])
  /* the unchanged tets' faces whose link went to a changed slot (or none: a hull face,
   * or one the trial left unlinked), in slot order */
  tr_u32buf rim = {0};
  tr_status s = TR_OK;
  for (uint32_t t = 0; t < z->nt && s == TR_OK; t++) {
    if (tr_tet_is_free(m, t) || CHANGED(t))
      continue;
    for (int k = 0; k < 4 && s == TR_OK; k++) {
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
      if (c == TR_NONE || CHANGED(c >> 2))
        s = tr_u32buf_push(&rim, 4 * t + (uint32_t)k);
    }
  }
  tr_vtmap faces = {0};
  for (uint32_t t = 0; t < z->nt && s == TR_OK; t++) {
    if (!CHANGED(t))
      continue;
    memcpy(m->tv + 4 * (size_t)t, z->tv + z->stride * (size_t)t, 4 * sizeof *z->tv);
    if (tr_tet_is_free(m, t))
      continue; /* its links: below */
    for (int k = 0; k < 4; k++)
      m->tn[4 * (size_t)t + (size_t)k] = TR_NONE;
    for (int k = 0; k < 4 && s == TR_OK; k++)
      s = link_face(m, &faces, t, k);
  }
  for (size_t i = 0; i < rim.n && s == TR_OK; i++) {
    uint32_t t = rim.a[i] >> 2;
    int k = (int)(rim.a[i] & 3);
    m->tn[rim.a[i]] = TR_NONE;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    uint32_t key[3];
    tr_vtkey_face(v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]], key);
    uint32_t other = tr_vtmap_get(&faces, 3, key);
    if (other != TR_VTMAP_NONE) {
      m->tn[rim.a[i]] = other;
      m->tn[other] = rim.a[i];
    }
  }
#undef CHANGED
  free(chg);
  tr_vtmap_free(&faces);
  tr_u32buf_free(&rim);
  for (uint32_t i = 0; i < z->nfree_slots; i++)
    memcpy(m->tn + 4 * (size_t)z->free_tn[5 * (size_t)i], z->free_tn + 5 * (size_t)i + 1,
           4 * sizeof *z->free_tn);
  m->nv = z->nv;
  m->nt = z->nt;
  m->free_head = z->free_head;
  m->nfree = z->nfree;
  memcpy(m->flags, z->flags, z->nt);
  if (m->region && z->region)
    memcpy(m->region, z->region, sizeof *z->region * (size_t)z->nt);
  memcpy(m->v2t, z->v2t, sizeof *z->v2t * (size_t)z->nv);
  tr_subfaces_free(sub);
  *sub = z->sub;
  memset(&z->sub, 0, sizeof z->sub);
  tr_sliver_snap_free(z);
  if (s != TR_OK)
    return tr_error(TR_ERR_NOMEM, "out of memory undoing a constraint trial of %u tets",
                    m->nt);
  return TR_OK;
}

int tr_sliver_snap_real(const tr_sliver_snap *z, uint32_t t)
{
  const uint32_t *v = z->tv + z->stride * (size_t)t;
  return v[0] != TR_NONE && v[3] != TR_GHOST;
}

/* 1 when slot u holds another tet than at the snapshot (or none was there) */
int tr_sliver_snap_changed(const struct tr_mesh *m, const tr_sliver_snap *z, uint32_t u)
{
  return u >= z->nt || u >= m->nt ||
         memcmp(m->tv + 4 * (size_t)u, z->tv + z->stride * (size_t)u, 4 * sizeof *z->tv);
}

/* snap.h */
tr_status tr_sliver_trial_ctx(const tr_sliver_ctx *c, const tr_subfaces *sub, uint32_t nv0,
                              tr_sliver_ctx *tc)
{
  TR_CHECK(tr_sliver_ctx_init(tc, c->m, sub, NULL, 0, c->bound));
  /* The trial measures without a cache: one of its own, as long as the slots, was the
   * largest block of memory the whole run held (CGAL's elephant under -a 4e-7: 8.4 of
   * 54 MB at the peak), and c's holds the snapshot's slots (tr_sliver_snap_take). It
   * measures only the few tets around its points, each a few times. */
  free(tc->shapes);
  tc->shapes = NULL;
  memset(tc->movable, 0, nv0 < c->m->nv ? nv0 : c->m->nv);
  tc->insert_bound = c->insert_bound;
  tc->point_budget = c->point_budget;
  tc->keep = c->keep;
  tc->memo = c->memo;
  tc->ratio_start = c->ratio_start;
  return TR_OK;
}
