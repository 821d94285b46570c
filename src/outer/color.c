/* Outer removal by coloring: see color.h for the rule and its limits. */
#include <stdlib.h>
#include <string.h>

#include "color.h"
#include "core/vtmap.h"
#include "flage.h"

typedef struct {
  uint32_t k[3]; /* sorted vertex ids */
  uint32_t id;   /* sub-face index */
} fkey;

static int cmp_fkey(const void *pa, const void *pb)
{
  const fkey *a = pa, *b = pb;
  for (int i = 0; i < 3; i++)
    if (a->k[i] != b->k[i])
      return a->k[i] < b->k[i] ? -1 : 1;
  return a->id < b->id ? -1 : a->id > b->id;
}

static void sort4(uint32_t *s)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3 - i; j++)
      if (s[j] > s[j + 1]) {
        uint32_t x = s[j];
        s[j] = s[j + 1];
        s[j + 1] = x;
      }
}

/* The sub-faces by vertex triple in the shared vertex-tuple map (core/vtmap.h), with its
 * filter (most faces of the mesh are no sub-face): the value is the sub-face's id, or for
 * a triple listed more than once FSLOT_RUN | the index of its first key in the sorted
 * keys (the others follow it there). Every tet face is looked up: a binary search over
 * the keys was a tenth of the time of a mesh without Steiner points. */
#define FSLOT_RUN 0x80000000u

static tr_status build_faces(tr_vtmap *h, const fkey *keys, uint32_t n)
{
  if (n >= FSLOT_RUN - 1)
    return tr_error(TR_ERR_NOMEM, "%u sub-faces: more than the coloring can index", n);
  TR_CHECK(tr_vtmap_reserve(h, 3, n));
  TR_CHECK(tr_vtmap_filter(h));
  for (uint32_t j = 0; j < n; j++) {
    if (j && memcmp(keys[j].k, keys[j - 1].k, sizeof keys[j].k) == 0)
      continue;
    int run = j + 1 < n && memcmp(keys[j].k, keys[j + 1].k, sizeof keys[j].k) == 0;
    TR_CHECK(tr_vtmap_put(h, 3, keys[j].k, run ? FSLOT_RUN | j : keys[j].id, NULL));
  }
  return TR_OK;
}

typedef struct {
  uint32_t v[4]; /* smallest tet of the component, sorted vertex ids */
  uint32_t comp;
} ckey;

static int cmp_ckey(const void *pa, const void *pb)
{
  const ckey *a = pa, *b = pb;
  for (int i = 0; i < 4; i++)
    if (a->v[i] != b->v[i])
      return a->v[i] < b->v[i] ? -1 : 1;
  return a->comp < b->comp ? -1 : a->comp > b->comp;
}

static int less4(const uint32_t *a, const uint32_t *b)
{
  for (int i = 0; i < 4; i++)
    if (a[i] != b[i])
      return a[i] < b[i];
  return 0;
}

/* Face k of tet t is a constraint: marked in cmask on both of its sides. */
static void mark_constraint(const struct tr_mesh *m, uint8_t *cmask, uint32_t t, int k)
{
  uint32_t o = TR_NEIG(m, t, k);
  cmask[t] |= (uint8_t)(1u << k);
  if (o != TR_NONE)
    cmask[o] |= (uint8_t)(1u << (m->tn[4 * (size_t)t + (size_t)k] & 3));
}

/* The tet a sub-face is seen from, of the real tet t and o (TR_NONE: none) on its other
 * side: the lower slot if o is real too. Both passes below use this one rule, so the
 * coloring does not depend on which pass found the face; o's kind is read only when
 * o < t (the per-tet pass looks faces up from their lower tet: never). */
static uint32_t seen_from(const struct tr_mesh *m, uint32_t t, uint32_t o)
{
  return o != TR_NONE && o < t && tr_tet_is_real(m, o) ? o : t;
}

tr_status tr_outer_color(struct tr_mesh *m, const tr_subfaces *sub, int keep_hull,
                         const uint8_t *sides, uint32_t *nregions)
{
  return tr_outer_color_ex(m, sub, keep_hull, sides, nregions, NULL, NULL, 0);
}

tr_status tr_outer_color_ex(struct tr_mesh *m, const tr_subfaces *sub, int keep_hull,
                            const uint8_t *sides, uint32_t *nregions, uint32_t *subtet,
                            const uint32_t *hint, uint32_t nhint)
{
  *nregions = 0;
  uint32_t ns = sub->n, nt = m->nt, nk = 0;
  fkey *keys = malloc(sizeof *keys * (ns ? ns : 1)); /* the sub-faces without a hint */
  uint8_t *cmask = calloc(nt ? nt : 1, 1);   /* bit k: face k is a constraint */
  /* seen[j]: the first real tet in slot order with sub-face j as a face, TR_NONE: none */
  uint32_t *seen = subtet ? subtet : malloc(sizeof *seen * (ns ? ns : 1));
  uint32_t *comp = malloc(sizeof *comp * (nt ? nt : 1));
  uint32_t *queue = malloc(sizeof *queue * (nt ? nt : 1));
  uint8_t *cflag = NULL;  /* per component: 1 ghost, 2 inner vote, 4 outer vote */
  ckey *ck = NULL;
  uint32_t *rid = NULL;
  tr_vtmap fh = {0};
  tr_status st = TR_OK;
  if (!keys || !cmask || !seen || !comp || !queue) {
    st = tr_error(TR_ERR_NOMEM, "out of memory coloring %u tets", nt);
    goto done;
  }
  /* A sub-face whose hint still has it as a face is marked on both sides here,
   * and seen[] takes the real tet of the two, the lower slot if both are, as the pass over
   * the tets below would: one random access per sub-face instead of a hash probe per tet
   * face (most of the coloring's time on a fine surface). The others are looked up. */
  for (uint32_t j = 0; j < ns; j++) {
    seen[j] = TR_NONE;
    uint32_t t = hint && j < nhint ? hint[j] : TR_NONE;
    const uint32_t *a = sub->v + 3 * (size_t)j;
    int k = t < nt && tr_tet_is_real(m, t) ? tr_fcode(m, t, a[0], a[1], a[2]) : -1;
    if (k >= 0) {
      seen[j] = seen_from(m, t, TR_NEIG(m, t, k));
      mark_constraint(m, cmask, t, k);
      continue;
    }
    memcpy(keys[nk].k, a, 3 * sizeof(uint32_t));
    tr_sort3(keys[nk].k);
    keys[nk++].id = j;
  }
  qsort(keys, nk, sizeof *keys, cmp_fkey);
  if ((st = build_faces(&fh, keys, nk)) != TR_OK)
    goto done;
  /* Constraint faces, marked on both sides; the FLAGE votes are taken after the
   * components are known. */
  /* Each face is looked up once, from the lower of its two tets, and marked on both.
   * Ghosts take part so that the neighbour's kind is never read (a random access per
   * face): a ghost looks up its one real face, the hull face opposite its ghost vertex
   * (slot 3); seen[] takes the real tet of the two, the first in slot order if both are. */
  for (uint32_t t = 0; t < nt && nk; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    int ghost = tr_tet_is_ghost(m, t);
    for (int k = ghost ? 3 : 0; k < 4; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o != TR_NONE && o < t)
        continue; /* looked up from o's side, which marks both */
      uint32_t real = ghost ? o : seen_from(m, t, o);
      if (real == TR_NONE)
        continue;
      uint32_t s[3];
      for (int i = 0; i < 3; i++)
        s[i] = m->tv[4 * (size_t)t + tr_face_vtx[k][i]];
      tr_sort3(s);
      uint32_t f = tr_vtmap_get(&fh, 3, s);
      if (f == TR_VTMAP_NONE)
        continue;
      if (!(f & FSLOT_RUN) && seen[f] == TR_NONE)
        seen[f] = real;
      /* Duplicated sub-faces (the same face listed twice) all mark the same face. */
      for (const fkey *g = keys + (f & ~FSLOT_RUN); (f & FSLOT_RUN) && g < keys + nk &&
                                                    g->k[0] == s[0] && g->k[1] == s[1] &&
                                                    g->k[2] == s[2]; g++)
        if (seen[g->id] == TR_NONE)
          seen[g->id] = real;
      mark_constraint(m, cmask, t, k);
    }
  }
  for (uint32_t j = 0; j < ns; j++)
    if (seen[j] == TR_NONE) {
      st = tr_error(TR_ERR_INTERNAL,
                    "outer removal: sub-face %u (%u, %u, %u) of input triangle %u is not a "
                    "face of the mesh",
                    j, sub->v[3 * (size_t)j], sub->v[3 * (size_t)j + 1],
                    sub->v[3 * (size_t)j + 2], sub->tri[j]);
      goto done;
    }
  /* Components across non-constraint faces: union-find in one streaming pass over the
   * slots (a breadth-first search reads the tets in a scattered order), each root the
   * smallest slot of its set, then numbered in slot order, which is the order of their
   * smallest slots (deterministic). queue[] holds the parents; TR_NONE: a free slot. */
  uint32_t nc = 0, *up = queue;
  for (uint32_t t = 0; t < nt; t++) {
    if (tr_tet_is_free(m, t)) {
      up[t] = TR_NONE;
      continue;
    }
    up[t] = t;
    int ghost = keep_hull && tr_tet_is_ghost(m, t);
    for (int k = 0; k < 4; k++) {
      if (cmask[t] & (1u << k))
        continue;
      uint32_t o = TR_NEIG(m, t, k);
      if (o == TR_NONE || o > t || up[o] == TR_NONE)
        continue; /* a later slot joins from its own side */
      /* keep_hull: the hull is a barrier, so the outside is the ghosts alone */
      if (keep_hull && tr_tet_is_ghost(m, o) != ghost)
        continue;
      uint32_t a = t, b = o;
      while (up[a] != a)
        a = up[a] = up[up[a]];
      while (up[b] != b)
        b = up[b] = up[up[b]];
      if (a < b)
        up[b] = a;
      else if (b < a)
        up[a] = b;
    }
  }
  for (uint32_t t = 0; t < nt; t++) {
    if (up[t] == TR_NONE) {
      comp[t] = TR_NONE;
      continue;
    }
    uint32_t r = t;
    while (up[r] != r)
      r = up[r];
    comp[t] = r == t ? nc++ : comp[r];
  }
  cflag = calloc(nc ? nc : 1, 1);
  ck = malloc(sizeof *ck * (nc ? nc : 1));
  rid = calloc(nc ? nc : 1, sizeof *rid);
  if (!cflag || !ck || !rid) {
    st = tr_error(TR_ERR_NOMEM, "out of memory coloring %u components", nc);
    goto done;
  }
  for (uint32_t c = 0; c < nc; c++) {
    memset(ck[c].v, 0xff, sizeof ck[c].v);
    ck[c].comp = c;
  }
  for (uint32_t t = 0; t < nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    uint32_t c = comp[t];
    if (tr_tet_is_ghost(m, t)) {
      cflag[c] |= 1;
      continue;
    }
    uint32_t v[4];
    memcpy(v, m->tv + 4 * (size_t)t, sizeof v);
    sort4(v);
    if (less4(v, ck[c].v))
      memcpy(ck[c].v, v, sizeof v);
  }
  /* The FLAGE votes, sub-face by sub-face (of a face listed more than once, the least
   * index: the first to take face k of its seen tet, vmask[t] bit k): its two tets are the
   * one found above and the one across it, so no tet face is looked up again. The votes
   * are OR-ed per component, in any order. cmask is done with: it becomes vmask. */
  uint8_t *vmask = cmask;
  memset(vmask, 0, nt ? nt : 1);
  for (uint32_t id = 0; id < ns; id++) {
    uint32_t t = seen[id];
    const uint32_t *a = sub->v + 3 * (size_t)id;
    int k = tr_fcode(m, t, a[0], a[1], a[2]);
    if (k < 0) {
      st = tr_error(TR_ERR_INTERNAL, "outer removal: tet %u lost sub-face %u", t, id);
      goto done;
    }
    if (vmask[t] & (1u << k))
      continue;
    vmask[t] |= (uint8_t)(1u << k);
    uint32_t side[2] = {t, TR_NEIG(m, t, k)};
    int face[2] = {k, side[1] == TR_NONE ? 0 : (int)(m->tn[4 * (size_t)t + (size_t)k] & 3)};
    for (int i = 0; i < 2; i++) {
      uint32_t w = side[i];
      if (w == TR_NONE || !tr_tet_is_real(m, w))
        continue;
      uint32_t c = comp[w];
      if (!sides && (cflag[c] & 2))
        continue;
      /* FLAGE from the NCodes: the sub-face is ordered like its (outward) triangle. */
      int e = tr_flage(tr_ncode(m, w, a[0]), tr_ncode(m, w, a[1]), tr_ncode(m, w, a[2]),
                       face[i]);
      if (e < 0) {
        st = tr_error(TR_ERR_INTERNAL, "outer removal: FLAGE undefined at tet %u face %d", w,
                      face[i]);
        goto done;
      }
      if (sides) {
        /* FLAGE INNER: w is on the side opposite the triangle's right-hand normal (bit 1) */
        uint8_t sd = sides[sub->tri[id]];
        cflag[c] |= ((e == TR_INNER) ? (sd & 2) : (sd & 1)) ? 2 : 4;
      } else if (e == TR_INNER) {
        cflag[c] |= 2;
      }
    }
  }
  if (sides)
    for (uint32_t c = 0; c < nc; c++)
      if ((cflag[c] & 6) == 6 && !(cflag[c] & 1)) {
        st = tr_error(TR_ERR_INTERNAL,
                      "outer removal: a component of the mesh touches sub-faces that put it "
                      "both inside and outside the domain");
        goto done;
      }
  /* Inner components sorted by their smallest tet: ids 1..k. */
  uint32_t ni = 0;
  for (uint32_t c = 0; c < nc; c++) {
    int inner = !(cflag[c] & 1) && (keep_hull || (cflag[c] & 2));
    if (inner)
      ck[ni++] = ck[c];
  }
  qsort(ck, ni, sizeof *ck, cmp_ckey);
  for (uint32_t i = 0; i < ni; i++)
    rid[ck[i].comp] = i + 1;
  if ((st = tr_mesh_enable_regions(m)) != TR_OK)
    goto done;
  for (uint32_t t = 0; t < nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    m->region[t] = rid[comp[t]];
    if (rid[comp[t]] == 0)
      m->flags[t] |= TR_TF_OUTER;
    else
      m->flags[t] &= (uint8_t)~TR_TF_OUTER;
  }
  *nregions = ni;
done:
  tr_vtmap_free(&fh);
  free(keys);
  free(cmask);
  if (seen != subtet)
    free(seen);
  free(comp);
  free(queue);
  free(cflag);
  free(ck);
  free(rid);
  return st;
}
