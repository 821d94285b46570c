/* The output mesh: the domain's tets only, numbered densely and deterministically. */
#include <stdlib.h>
#include <string.h>

#include "pipeline.h"

static int keep(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER);
}

/* written[f] = 1 if sub-face f is a face of a kept tet, from the candidates: when
 * candidate t still has the face, the face's only other tet is its neighbour u across it,
 * whatever changed since, so the two are looked at once. 0 (unusable) if there are none
 * or one is no longer a real tet with its face. */
static int from_candidates(const struct tr_mesh *m, const tr_subfaces *sub,
                           const uint32_t *cand, uint32_t ncand, uint32_t *written)
{
  if (!cand || ncand != sub->n)
    return 0;
  for (uint32_t f = 0; f < sub->n; f++) {
    uint32_t t = cand[f];
    const uint32_t *v = sub->v + 3 * (size_t)f;
    if (t >= m->nt || !tr_tet_is_real(m, t))
      return 0;
    int k = tr_fcode(m, t, v[0], v[1], v[2]);
    if (k < 0)
      return 0;
    uint32_t u = TR_NEIG(m, t, k);
    written[f] = keep(m, t) || (u != TR_NONE && keep(m, u));
  }
  return 1;
}

/* o->attrs from in, renumbered by vmap: the sub-faces that are faces of a kept tet (a
 * facet between two cavities has none), origins, input edges. */
static tr_status attach(struct tr_mesh *o, const struct tr_mesh *m, const uint32_t *vmap,
                        const tr_compact_in *in)
{
  struct tr_mesh_attrs *a = calloc(1, sizeof *a);
  if (!a)
    return tr_error(TR_ERR_NOMEM, "out of memory for the output attributes");
  o->attrs = a;
  const tr_subfaces *sub = in->sub;
  uint32_t n = sub ? sub->n : 0, nv = o->nv;
  uint32_t *tet = malloc(sizeof *tet * (n ? n : 1));
  if (!tet)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u output faces", n);
  tr_status st = TR_OK;
  int done = !n || from_candidates(m, sub, in->subtet, in->nsubtet, tet);
  if (!done)
    st = tr_mesh_find_faces(m, sub->v, n, tet);
  for (uint32_t f = 0; f < n && st == TR_OK && !done; f++) {
    uint32_t t = tet[f];
    /* In no tet: the suppression stage (src/suppress) frees the outer tets, so a facet
     * between two cavities is no mesh face at all; it is written by no kept tet either. */
    if (t == TR_NONE) {
      tet[f] = 0;
      continue;
    }
    int k = tr_fcode(m, t, sub->v[3 * (size_t)f], sub->v[3 * (size_t)f + 1],
                     sub->v[3 * (size_t)f + 2]);
    uint32_t u = k < 0 ? TR_NONE : TR_NEIG(m, t, k);
    tet[f] = keep(m, t) || (u != TR_NONE && keep(m, u)); /* 1: written */
  }
  if (st != TR_OK) {
    free(tet);
    return st;
  }
  a->faces = malloc(sizeof *a->faces * 3 * (size_t)(n ? n : 1));
  a->face_tri = malloc(sizeof *a->face_tri * (n ? n : 1));
  a->face_marker = malloc(sizeof *a->face_marker * (n ? n : 1));
  a->edges = malloc(sizeof *a->edges * 2 * (size_t)(in->nedges ? in->nedges : 1));
  if (in->vkind) {
    a->vkind = malloc(nv ? nv : 1);
    a->vindex = malloc(sizeof *a->vindex * (nv ? nv : 1));
  }
  if (!a->faces || !a->face_tri || !a->face_marker || !a->edges ||
      (in->vkind && (!a->vkind || !a->vindex))) {
    free(tet);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u output faces", n);
  }
  for (uint32_t f = 0; f < n; f++) {
    const uint32_t *v = sub->v + 3 * (size_t)f;
    if (!tet[f])
      continue;
    for (int j = 0; j < 3; j++)
      a->faces[3 * (size_t)a->nfaces + (size_t)j] = vmap[v[j]];
    a->face_tri[a->nfaces] = sub->tri[f];
    a->face_marker[a->nfaces++] = in->tri_marker ? in->tri_marker[sub->tri[f]] : 0;
  }
  free(tet);
  a->nedges = in->nedges;
  if (in->nedges)
    memcpy(a->edges, in->edges, sizeof *a->edges * 2 * (size_t)in->nedges);
  if (in->vkind)
    for (uint32_t v = 0; v < m->nv; v++) {
      uint32_t w = vmap[v];
      if (w == TR_NONE)
        continue;
      a->vkind[w] = in->vkind[v];
      /* input points keep their PLC index (they are m's first vertices) */
      a->vindex[w] = in->vkind[v] == TR_VERTEX_INTERIOR ? w : in->vindex[v];
    }
  return TR_OK;
}

tr_status tr_pipeline_compact(struct tr_mesh *m, const tr_compact_in *in, struct tr_mesh **out)
{
  *out = NULL;
  uint32_t nv = m->nv, nt = m->nt, kt = 0, kv = 0;
  uint32_t *vmap = malloc(sizeof *vmap * (nv ? nv : 1));
  uint32_t *tmap = malloc(sizeof *tmap * (nt ? nt : 1));
  struct tr_mesh *o = NULL;
  tr_status st = TR_OK;
  if (!vmap || !tmap) {
    st = tr_error(TR_ERR_NOMEM, "out of memory compacting the mesh");
    goto done;
  }
  for (uint32_t v = 0; v < nv; v++)
    vmap[v] = TR_NONE;
  for (uint32_t t = 0; t < nt; t++) {
    tmap[t] = TR_NONE;
    if (!keep(m, t))
      continue;
    tmap[t] = kt++;
    for (int k = 0; k < 4; k++)
      vmap[m->tv[4 * (size_t)t + k]] = 0;
  }
  for (uint32_t v = 0; v < nv; v++)
    if (vmap[v] == 0)
      vmap[v] = kv++;
  if ((st = tr_mesh_create(kv, kt, &o)) != TR_OK)
    goto done;
  for (uint32_t v = 0; v < nv && st == TR_OK; v++) {
    if (vmap[v] == TR_NONE)
      continue;
    uint32_t id;
    if (m->vq && m->vq[v]) {
      /* moved, not copied: the working store is destroyed right after; its double too,
       * which need not be the nearest one (refinement's, refine/insert.c) */
      st = tr_mesh_add_steiner(o, m->vq[v], &id);
      if (st == TR_OK) {
        m->vq[v] = NULL;
        memcpy(o->xyz + 3 * (size_t)id, m->xyz + 3 * (size_t)v, 3 * sizeof(double));
      }
    } else
      st = tr_mesh_add_vertex(o, m->xyz + 3 * (size_t)v, &id);
  }
  if (st == TR_OK && m->region)
    st = tr_mesh_enable_regions(o);
  for (uint32_t t = 0; t < nt && st == TR_OK; t++) {
    if (tmap[t] == TR_NONE)
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    uint32_t id;
    st = tr_tet_new(o, vmap[v[0]], vmap[v[1]], vmap[v[2]], vmap[v[3]], &id);
    if (st != TR_OK)
      break;
    for (int k = 0; k < 4; k++) {
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
      o->tn[4 * (size_t)id + (size_t)k] =
          c == TR_NONE || tmap[c >> 2] == TR_NONE ? TR_NONE : 4 * tmap[c >> 2] + (c & 3);
    }
    if (m->region)
      o->region[id] = m->region[t];
  }
  if (st == TR_OK && in)
    st = attach(o, m, vmap, in);
done:
  free(vmap);
  free(tmap);
  if (st != TR_OK)
    tr_mesh_destroy(o);
  else
    *out = o;
  return st;
}

tr_status tr_pipeline_uncompact_steiner(struct tr_mesh *m, struct tr_mesh *res)
{
  /* the renumbering of tr_pipeline_compact: kept vertices in increasing id */
  uint8_t *used = calloc(m->nv ? m->nv : 1, 1);
  if (!used)
    return tr_error(TR_ERR_NOMEM, "out of memory giving the Steiner points back");
  for (uint32_t t = 0; t < m->nt; t++)
    if (keep(m, t))
      for (int k = 0; k < 4; k++)
        used[m->tv[4 * (size_t)t + k]] = 1;
  for (uint32_t v = 0, j = 0; v < m->nv && j < res->nv; v++)
    if (used[v]) {
      if (res->vq && res->vq[j] && m->vq) {
        m->vq[v] = res->vq[j];
        res->vq[j] = NULL;
      }
      j++;
    }
  free(used);
  return TR_OK;
}
