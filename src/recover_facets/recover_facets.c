/* Stage 3 driver: every input triangle in input order, with its sub-faces. */
#include "recover_facets/recover_facets.h"

#include <stdlib.h>
#include <string.h>

#include "recover_edges/edgeset.h"
#include "recover_facets/facet.h"

/* The sub-faces listed so far and the constraint edges: what the flips of later facets
 * must keep. Only the facets that are not faces already ask (the flips, the cavity), and
 * on a fine surface there may be none: the sets are filled at the first such facet
 * (built), with every constraint edge and the sub-faces listed before it. */
typedef struct keep {
  tr_edgeset cons;
  tr_vtmap faces; /* sorted sub-face -> 0 (a set) */
  int built;
} keep;

static tr_status keep_face(keep *k, const uint32_t *v)
{
  uint32_t o[3];
  tr_vtkey_face(v[0], v[1], v[2], o);
  return tr_vtmap_put(&k->faces, 3, o, 0, NULL);
}

/* The constraint edges: the pieces of the input edges when chains are given; without
 * chains the triangles' edges are mesh edges (the caller recovered them without Steiner
 * points). Unprotected, the flips for one facet could take away an edge of another,
 * whose cluster is then ill-formed. Then the faces listed so far, listed[0..nlisted). */
static tr_status keep_build(keep *k, const uint32_t *tris, uint32_t n,
                            const tr_edge_chains *chains, const uint32_t *listed, size_t nlisted)
{
  k->built = 1;
  /* sized at once (hints: the puts grow the sets anyway): grown from 8 keys, they were
   * rehashed a dozen times on a fine surface */
  (void)tr_vtmap_reserve(&k->cons.m, 2,
                         chains ? chains->start[chains->n] - chains->start[0]
                                : (uint32_t)(3 * (size_t)n / 2));
  (void)tr_vtmap_reserve(&k->faces, 3, (uint32_t)(nlisted / 3 + 16));
  for (uint32_t c = 0; chains && c < chains->n; c++)
    for (uint32_t j = chains->start[c]; j + 1 < chains->start[c + 1]; j++)
      TR_CHECK(tr_edgeset_put(&k->cons, chains->v[j], chains->v[j + 1], c));
  for (uint32_t i = 0; !chains && i < n; i++)
    for (int q = 0; q < 3; q++)
      TR_CHECK(tr_edgeset_put(&k->cons, tris[3 * i + q], tris[3 * i + (q + 1) % 3], i));
  for (size_t j = 0; j < nlisted; j += 3)
    TR_CHECK(keep_face(k, listed + j));
  return TR_OK;
}

static int keep_guard(void *ud, const uint32_t *v, int nv)
{
  const keep *k = ud;
  if (nv == 2)
    return tr_edgeset_get(&k->cons, v[0], v[1]) != TR_EDGESET_NONE;
  uint32_t o[3];
  tr_vtkey_face(v[0], v[1], v[2], o);
  return tr_vtmap_get(&k->faces, 3, o) != TR_VTMAP_NONE;
}

void tr_subfaces_free(tr_subfaces *s)
{
  if (!s)
    return;
  free(s->v);
  free(s->tri);
  s->v = NULL;
  s->tri = NULL;
  s->n = 0;
}

/* `chains` only feeds the set of constraint edges the flips must keep (the pieces of the
 * input edges): the cluster of a facet is found from its corners, and its boundary
 * vertices (the chains' Steiner points) show up as on-plane clusterel nodes. */
tr_status tr_recover_facets(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                            const tr_edge_chains *chains, tr_subfaces *sub,
                            tr_facet_recovery_stats *st)
{
  return tr_recover_facets_ex(m, tris, n, chains, NULL, sub, st, NULL);
}

tr_status tr_recover_facets_ex(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                               const tr_edge_chains *chains, const tr_facet_recovery_opts *fo,
                               tr_subfaces *sub, tr_facet_recovery_stats *st,
                               uint32_t **hint_out)
{
  if (hint_out)
    *hint_out = NULL;
  tr_facet_detail d = {0};
  tr_facet_opts opt = {0};
  opt.no_flips = opt.no_cavity = fo && fo->paper;
  opt.no_flips |= fo && fo->no_flips;
  keep kp;
  memset(&kp, 0, sizeof kp);
  opt.guard = keep_guard;
  opt.guard_ud = &kp;
  /* Which facets are faces already, in one pass over the tets instead of a ball search
   * per facet (most facets of a fine surface are). */
  uint32_t *hint = malloc(sizeof *hint * (n ? n : 1));
  if (!hint) {
    tr_edgeset_free(&kp.cons);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u facet hints", n);
  }
  tr_status hs = tr_mesh_find_faces(m, tris, n, hint);
  if (hs != TR_OK) {
    free(hint);
    tr_edgeset_free(&kp.cons);
    return hs;
  }
  opt.hint = hint;
  tr_facet_recovery_stats s = {0};
  if (sub)
    memset(sub, 0, sizeof *sub);
  /* Each facet's faces are listed right after its recovery: a later facet never splits
   * them (its Steiner points lie in its own open interior, which meets no other input
   * triangle), and the tests check the final listing against the final mesh. */
  tr_u32buf v = {0}, tri = {0}, tet = {0};
  tr_status r = TR_OK;
  for (uint32_t i = 0; i < n && r == TR_OK; i++) {
    int outcome;
    size_t before = v.n;
    /* a hint still naming a tet with the facet: present, no flips, the sets not asked
     * (a hint goes stale only after flips, i.e. after the sets were filled) */
    uint32_t ht = hint[i];
    if (!kp.built &&
        !(ht != TR_NONE && ht < m->nt && tr_tet_is_real(m, ht) &&
          tr_fcode(m, ht, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2]) >= 0) &&
        (r = keep_build(&kp, tris, n, chains, v.a, v.n)) != TR_OK)
      break;
    r = tr_recover_facet(m, i, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], &opt, &d,
                         &outcome, &v);
    if (r != TR_OK)
      break;
    if (outcome != TR_FACET_PRESENT)
      s.missing_facets++;
    if (outcome == TR_FACET_BY_SWAP32 || outcome == TR_FACET_BY_FLIPS)
      s.recovered_by_swap++;
    else if (outcome == TR_FACET_BY_CAVITY)
      s.recovered_by_cavity++;
    for (size_t k = before; k < v.n && r == TR_OK; k += 3) {
      r = tr_u32buf_push(&tri, i);
      /* a facet present from the start is the face the one pass over the tets found */
      if (r == TR_OK && hint_out)
        r = tr_u32buf_push(&tet, outcome == TR_FACET_PRESENT ? hint[i] : TR_NONE);
      if (r == TR_OK && kp.built)
        r = keep_face(&kp, v.a + k);
    }
  }
  tr_edgeset_free(&kp.cons);
  tr_vtmap_free(&kp.faces);
  free(hint);
  s.points_added = d.steiner + d.h_points;
  s.by_flips = d.by_flips;
  s.flip23 = d.flips.flip23;
  s.flip32 = d.flips.flip32;
  s.flip44 = d.flips.flip44;
  s.flipn = d.flips.flipn;
  s.flips_undone = d.flips.undone;
  s.cavity_tried = d.cavity.tried;
  s.cavity_expanded = d.cavity.expanded;
  if (st)
    *st = s;
  if (r != TR_OK || !sub) {
    tr_u32buf_free(&v);
    tr_u32buf_free(&tri);
    tr_u32buf_free(&tet);
    return r;
  }
  sub->n = (uint32_t)tri.n;
  sub->v = v.a;
  sub->tri = tri.a;
  if (hint_out)
    *hint_out = tet.a;
  return TR_OK;
}
