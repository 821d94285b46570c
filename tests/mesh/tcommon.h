/* Tiny helpers shared by the mesh and delaunay tests: a deterministic generator and a
 * failure macro that names the property being checked. */
#ifndef TR_TESTS_MESH_TCOMMON_H
#define TR_TESTS_MESH_TCOMMON_H

#include <stdint.h>
#include <stdio.h>

static uint64_t t_rng = 88172645463325252ull;
static inline uint64_t t_next(void)
{
  t_rng ^= t_rng << 13;
  t_rng ^= t_rng >> 7;
  t_rng ^= t_rng << 17;
  return t_rng;
}
/* uniform in [0, 1) with 53 random bits */
static inline double t_unif(void) { return (double)(t_next() >> 11) * 0x1p-53; }

#define EXPECT(cond, ...)                                                     \
  do {                                                                        \
    if (!(cond)) {                                                            \
      fprintf(stderr, "%s:%d: FAILED %s: ", __FILE__, __LINE__, #cond);       \
      fprintf(stderr, __VA_ARGS__);                                           \
      fprintf(stderr, "\n");                                                  \
      return 1;                                                               \
    }                                                                         \
  } while (0)

#define EXPECT_OK(expr, what)                                                 \
  do {                                                                        \
    tr_status s_ = (expr);                                                    \
    EXPECT(s_ == TR_OK, "%s: %s: %s", what, tr_status_name(s_), tr_last_error()); \
  } while (0)

#endif
