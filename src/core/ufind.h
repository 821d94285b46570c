/* Union-find over uint32_t ids (par[x] == x at a root): the smaller root stays on a union,
 * so a root is its group's smallest id and groups come out the same whatever order the
 * unions came in. Shared by the input's cells, its planar facets and refinement's cap
 * clusters. */
#ifndef TR_CORE_UFIND_H
#define TR_CORE_UFIND_H

#include <stdint.h>

static inline uint32_t tr_uf_find(uint32_t *par, uint32_t x)
{
  while (par[x] != x) {
    par[x] = par[par[x]]; /* path halving */
    x = par[x];
  }
  return x;
}

static inline void tr_uf_unite(uint32_t *par, uint32_t a, uint32_t b)
{
  a = tr_uf_find(par, a);
  b = tr_uf_find(par, b);
  if (a != b)
    par[a < b ? b : a] = a < b ? a : b;
}

#endif
