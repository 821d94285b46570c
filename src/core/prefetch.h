/* Cache hints for the random walks over tet slots (the Delaunay kernel's cavities, the
 * canonical renumbering, the sliver stage's cavities): the code knows which slots it
 * reads next before it gets there. A hint only; compilers without the builtin drop it. */
#ifndef TR_CORE_PREFETCH_H
#define TR_CORE_PREFETCH_H

#if defined(__GNUC__) || defined(__clang__)
#define TR_PREFETCH(p) __builtin_prefetch(p)
#define TR_PREFETCH_W(p) __builtin_prefetch(p, 1)
#else
#define TR_PREFETCH(p) ((void)(p))
#define TR_PREFETCH_W(p) ((void)(p))
#endif

#endif
