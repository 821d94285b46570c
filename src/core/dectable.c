/* Symbolic checks of decomposition tables (format in dectable.h). Geometry is verified
 * separately, in the tests, on exact configurations. */
#include "dectable.h"

#include <stddef.h>

static const char *const dv_names[TR_DV_COUNT] = {"A", "B", "C", "D", "E", "F",
                                                   "P1", "P2", "P3", "P4", "H"};

const char *tr_dv_name(uint8_t v)
{
  return v < TR_DV_COUNT ? dv_names[v] : "?";
}

static void sort3(uint8_t a[3])
{
  uint8_t t;
  if (a[0] > a[1]) { t = a[0]; a[0] = a[1]; a[1] = t; }
  if (a[1] > a[2]) { t = a[1]; a[1] = a[2]; a[2] = t; }
  if (a[0] > a[1]) { t = a[0]; a[0] = a[1]; a[1] = t; }
}

void tr_dtet_face_sorted(const tr_dtet *d, int k, uint8_t out[3])
{
  int m = 0;
  for (int i = 0; i < 4; i++)
    if (i != k)
      out[m++] = d->v[i];
  sort3(out);
}

int tr_dectable_old_index(const tr_dectable *t, int j, uint8_t x)
{
  for (int i = 0; i < 4; i++)
    if (t->old[j][i] == x)
      return i;
  return -1;
}

const tr_dsteiner *tr_dectable_steiner(const tr_dectable *t, uint8_t x)
{
  for (int i = 0; i < t->nsteiner; i++)
    if (t->steiner[i].name == x)
      return &t->steiner[i];
  return NULL;
}

static int same3(const uint8_t a[3], const uint8_t b[3])
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* 1 iff name x lies in the closed face of old[0] opposite `vtx`. */
static int in_old_face(const tr_dectable *t, uint8_t vtx, uint8_t x)
{
  if (x == vtx)
    return 0;
  if (tr_dectable_old_index(t, 0, x) >= 0)
    return 1;
  const tr_dsteiner *s = tr_dectable_steiner(t, x);
  if (!s)
    return 0;
  for (int i = 0; i < s->ncar; i++)
    if (s->car[i] == vtx || tr_dectable_old_index(t, 0, s->car[i]) < 0)
      return 0;
  return 1;
}

#define FAIL(...) return tr_error(TR_ERR_INTERNAL, __VA_ARGS__)

tr_status tr_dectable_check(const tr_dectable *t)
{
  if (t->nold < 1 || t->nold > TR_DEC_MAX_OLD || t->nnew < 1)
    FAIL("%s: bad sizes (nold %d, nnew %d)", t->name, t->nold, t->nnew);
  for (int r = 0; r < t->nnew; r++) {
    const tr_dtet *d = &t->tets[r];
    for (int i = 0; i < 4; i++) {
      if (d->v[i] >= TR_DV_COUNT)
        FAIL("%s row %d: bad vertex code %d", t->name, r + 1, d->v[i]);
      for (int j = 0; j < i; j++)
        if (d->v[i] == d->v[j])
          FAIL("%s row %d: vertex %s repeated", t->name, r + 1, tr_dv_name(d->v[i]));
      if (d->v[i] >= TR_DV_P1 && !tr_dectable_steiner(t, d->v[i]))
        FAIL("%s row %d: Steiner point %s has no carrier", t->name, r + 1,
             tr_dv_name(d->v[i]));
    }
    for (int k = 0; k < 4; k++) {
      const tr_dnb *n = &d->n[k];
      uint8_t f[3], g[3];
      tr_dtet_face_sorted(d, k, f);
      switch (n->kind) {
      case TR_DNB_INTERNAL: {
        if (n->tet >= t->nnew || n->tet == r)
          FAIL("%s row %d N%d: bad internal index %d", t->name, r + 1, k + 1, n->tet);
        const tr_dtet *o = &t->tets[n->tet];
        int back = -1;
        for (int kk = 0; kk < 4; kk++)
          if (o->n[kk].kind == TR_DNB_INTERNAL && o->n[kk].tet == r)
            back = kk;
        if (back < 0)
          FAIL("%s row %d N%d: row %d does not link back", t->name, r + 1, k + 1,
               n->tet + 1);
        tr_dtet_face_sorted(o, back, g);
        if (!same3(f, g))
          FAIL("%s row %d N%d: faces with row %d differ", t->name, r + 1, k + 1, n->tet + 1);
        break;
      }
      case TR_DNB_NG: {
        if (n->tet >= t->nold)
          FAIL("%s row %d N%d: bad old tet %d", t->name, r + 1, k + 1, n->tet + 1);
        int m = 0, vi = tr_dectable_old_index(t, n->tet, n->vtx);
        if (vi < 0)
          FAIL("%s row %d N%d: %s not in t%d", t->name, r + 1, k + 1, tr_dv_name(n->vtx),
               n->tet + 1);
        for (int i = 0; i < 4; i++)
          if (i != vi)
            g[m++] = t->old[n->tet][i];
        sort3(g);
        if (!same3(f, g))
          FAIL("%s row %d N%d: NG face differs from the new tet's face", t->name, r + 1,
               k + 1);
        break;
      }
      case TR_DNB_PHI:
        for (int i = 0; i < 3; i++)
          g[i] = n->fac[i];
        sort3(g);
        if (!same3(f, g))
          FAIL("%s row %d N%d: Phi face differs from the new tet's face", t->name, r + 1,
               k + 1);
        if (tr_dectable_old_index(t, 0, n->vtx) < 0)
          FAIL("%s row %d N%d: Phi vertex %s not in t", t->name, r + 1, k + 1,
               tr_dv_name(n->vtx));
        for (int i = 0; i < 3; i++)
          if (!in_old_face(t, n->vtx, f[i]))
            FAIL("%s row %d N%d: %s not on the face of t opposite %s", t->name, r + 1, k + 1,
                 tr_dv_name(f[i]), tr_dv_name(n->vtx));
        break;
      default:
        FAIL("%s row %d N%d: no neighbour spec", t->name, r + 1, k + 1);
      }
    }
  }
  return TR_OK;
}
