/* Table instantiation on the mesh (see decompose.h). */
#include "recover_edges/decompose.h"

#include <string.h>

#include "qpoint.h"

const tr_pipel *tr_pipe_find(const tr_pipel *pipe, uint32_t npipe, uint32_t e)
{
  for (uint32_t i = 0; i < npipe; i++)
    if (pipe[i].iEle == e)
      return &pipe[i];
  return NULL;
}

/* Face code of the face {a,b,c} in tet t, or -1. */
static int face_in(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c)
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  int miss = -1, hits = 0;
  for (int k = 0; k < 4; k++) {
    if (v[k] == a || v[k] == b || v[k] == c)
      hits++;
    else
      miss = k;
  }
  return hits == 3 ? miss : -1;
}

/* Where each new face gets its neighbour from, resolved before the mesh changes. */
typedef struct link_plan {
  uint32_t code; /* 4*t'+k' of an outside tet, or TR_NONE */
} link_plan;

tr_status tr_dec_apply(struct tr_mesh *m, const tr_dectable *t, const uint32_t *old,
                       const uint32_t ids[TR_DV_COUNT], const tr_pipel *pipe, uint32_t npipe,
                       uint32_t *out)
{
  if (t->nnew > TR_MAX_DEC_TETS)
    return tr_error(TR_ERR_INTERNAL, "%s: %d new tets exceed TR_MAX_DEC_TETS", t->name,
                    t->nnew);
  /* 1. exact positivity of every new tet, before any change */
  for (int r = 0; r < t->nnew; r++) {
    tr_point p[4];
    for (int i = 0; i < 4; i++)
      p[i] = tr_mesh_point(m, ids[t->tets[r].v[i]]);
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) <= 0)
      return tr_error(TR_ERR_INTERNAL,
                      "%s: new tet %d (%u %u %u %u) is not positively oriented on old tet %u",
                      t->name, r + 1, ids[t->tets[r].v[0]], ids[t->tets[r].v[1]],
                      ids[t->tets[r].v[2]], ids[t->tets[r].v[3]], old[0]);
  }
  /* 2. resolve NG and Phi links while the old links are intact */
  link_plan plan[TR_MAX_DEC_TETS][4];
  for (int r = 0; r < t->nnew; r++)
    for (int k = 0; k < 4; k++) {
      const tr_dnb *n = &t->tets[r].n[k];
      plan[r][k].code = TR_NONE;
      if (n->kind == TR_DNB_INTERNAL)
        continue;
      uint32_t ot = old[n->kind == TR_DNB_NG ? n->tet : 0];
      int kk = tr_ncode(m, ot, ids[n->vtx]);
      if (kk < 0)
        return tr_error(TR_ERR_INTERNAL, "%s row %d N%d: vertex %u not in old tet %u", t->name,
                        r + 1, k + 1, ids[n->vtx], ot);
      uint32_t c = m->tn[4 * (size_t)ot + (size_t)kk];
      if (c == TR_NONE)
        continue;
      if (n->kind == TR_DNB_NG) {
        /* the neighbour may itself be one of the old tets only if the table were wrong */
        for (int j = 0; j < t->nold; j++)
          if ((c >> 2) == old[j])
            return tr_error(TR_ERR_INTERNAL, "%s row %d N%d: NG face is interior", t->name,
                            r + 1, k + 1);
        plan[r][k].code = c;
      } else {
        const tr_pipel *pl = tr_pipe_find(pipe, npipe, c >> 2);
        if (!pl)
          return tr_error(TR_ERR_UNSUPPORTED,
                          "%s row %d N%d: tet %u across a split face of %u is not a pipel",
                          t->name, r + 1, k + 1, c >> 2, ot);
        if (pl->nTets == 0)
          continue; /* glued when that pipel is decomposed */
        uint32_t f[3];
        for (int i = 0, q = 0; i < 4; i++)
          if (i != k)
            f[q++] = ids[t->tets[r].v[i]];
        int found = 0;
        for (int i = 0; i < pl->nTets && !found; i++) {
          int fk = face_in(m, pl->dectets[i], f[0], f[1], f[2]);
          if (fk >= 0) {
            plan[r][k].code = 4 * pl->dectets[i] + (uint32_t)fk;
            found = 1;
          }
        }
        if (!found)
          return tr_error(TR_ERR_INTERNAL,
                          "%s row %d N%d: decomposed neighbour pipel %u has no sub-face "
                          "(%u %u %u): the two sides split their face differently",
                          t->name, r + 1, k + 1, pl->iEle, f[0], f[1], f[2]);
      }
    }
  /* 3. replace: free the old slots first so the new tets reuse them */
  for (int j = 0; j < t->nold; j++)
    tr_tet_free(m, old[j]);
  for (int r = 0; r < t->nnew; r++) {
    const uint8_t *v = t->tets[r].v;
    TR_CHECK(tr_tet_new(m, ids[v[0]], ids[v[1]], ids[v[2]], ids[v[3]], &out[r]));
  }
  for (int r = 0; r < t->nnew; r++)
    for (int k = 0; k < 4; k++) {
      const tr_dnb *n = &t->tets[r].n[k];
      if (n->kind == TR_DNB_INTERNAL) {
        if (n->tet < r)
          continue; /* glued from the other side */
        const tr_dtet *o = &t->tets[n->tet];
        int back = -1;
        for (int kk = 0; kk < 4; kk++)
          if (o->n[kk].kind == TR_DNB_INTERNAL && o->n[kk].tet == r)
            back = kk;
        tr_glue(m, out[r], k, out[n->tet], back);
      } else if (plan[r][k].code != TR_NONE) {
        tr_glue(m, out[r], k, plan[r][k].code >> 2, (int)(plan[r][k].code & 3));
      }
    }
  return TR_OK;
}

static const uint8_t even_perms[12][4] = {
  {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 3, 2, 0},
  {2, 0, 1, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 2, 1, 0},
};

/* 1 iff the local simplex car[0..n) equals the image under perm of the table carrier. */
static int same_carrier(const tr_dsteiner *s, const uint8_t perm[4], const uint8_t *car, int n)
{
  if (s->ncar != n)
    return 0;
  for (int i = 0; i < n; i++) {
    int found = 0;
    for (int j = 0; j < n; j++)
      found |= perm[s->car[i]] == car[j];
    if (!found)
      return 0;
  }
  return 1;
}

int tr_dec_match(const tr_dectable *t, const uint32_t tv[4], int nst, const uint8_t car[][4],
                 const uint8_t *ncar, const uint32_t *sid, int prefer,
                 uint32_t ids[TR_DV_COUNT])
{
  if (t->nold != 1 || nst != t->nsteiner || nst > 2)
    return 0;
  for (int pass = prefer >= 0 ? 0 : 1; pass < 2; pass++)
    for (int p = 0; p < 12; p++) {
      /* perm[name] = local code playing that name */
      const uint8_t *perm = even_perms[p];
      if (pass == 0 && perm[TR_DV_A] != prefer)
        continue;
      /* try the identity assignment of points to names, then the swapped one */
      for (int sw = 0; sw < (nst == 2 ? 2 : 1); sw++) {
        int ok = 1;
        for (int i = 0; i < nst && ok; i++) {
          int pi = sw ? 1 - i : i;
          ok = same_carrier(&t->steiner[i], perm, car[pi], ncar[pi]);
        }
        if (!ok)
          continue;
        for (int n = 0; n < TR_DV_COUNT; n++)
          ids[n] = TR_NONE;
        for (int n = 0; n < 4; n++)
          ids[t->old[0][n]] = tv[perm[n]];
        for (int i = 0; i < nst; i++)
          ids[t->steiner[i].name] = sid[sw ? 1 - i : i];
        return 1;
      }
    }
  return 0;
}
