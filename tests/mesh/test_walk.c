/* Brent's cycle detection for non-Delaunay walks (src/mesh/walk.h), against the walk's
 * own history: random walks on functional graphs whose next step depends on the node and
 * the step mod the period, as rf_locate's does. Usage: test_walk <case>. */
#include <stdlib.h>
#include <string.h>

#include "mesh/walk.h"
#include "tcommon.h"

enum { NODES = 64, PERIOD = 4, SINK = NODES, MAXSTEPS = 4 * NODES * PERIOD + 8 };

/* next[node][phase]: another node, or SINK (the walk ends: the point was found) */
static uint32_t next[NODES][PERIOD];

static void random_graph(int sinks)
{
  for (int v = 0; v < NODES; v++)
    for (int p = 0; p < PERIOD; p++)
      next[v][p] = sinks && t_next() % 16 == 0 ? SINK : (uint32_t)(t_next() % NODES);
}

/* A walk is stopped only if a state (node, step mod PERIOD) repeats, and then by step
 * 2 T + 3 L + 2 (T the step of the first state on the cycle, L the cycle's length: the
 * kept state is at step 2^k - 1, and 2^k is under 2 max(T + 1, L) when it is first on the
 * cycle with a span of at least L); a walk that reaches SINK never is. */
static int stops_only_cycles_and_soon(void)
{
  static int64_t first[NODES][PERIOD]; /* step a state was first seen, -1: never */
  int cycles = 0, ends = 0;
  for (int g = 0; g < 400; g++) {
    random_graph(g % 2);
    for (uint32_t start = 0; start < NODES; start += 7) {
      memset(first, -1, sizeof first);
      tr_walk_cycle w;
      tr_walk_cycle_init(&w, start);
      uint32_t t = start;
      int64_t tail = -1, len = -1, stopped = -1;
      first[t][0] = 0;
      for (uint64_t step = 0; step < MAXSTEPS; step++) {
        t = next[t][step % PERIOD];
        if (t == SINK)
          break;
        int64_t *f = &first[t][(step + 1) % PERIOD];
        if (*f >= 0 && tail < 0) {
          tail = *f;
          len = (int64_t)step + 1 - *f;
        } else if (*f < 0)
          *f = (int64_t)step + 1;
        if (tr_walk_cycle_seen(&w, t, step + 1, PERIOD)) {
          stopped = (int64_t)step + 1;
          break;
        }
      }
      if (t == SINK) {
        ends++;
        EXPECT(stopped < 0, "graph %d start %u: a walk that ends was stopped", g, start);
        continue;
      }
      cycles++;
      EXPECT(tail >= 0, "graph %d start %u: stopped at %lld before any state repeated", g,
             start, (long long)stopped);
      EXPECT(stopped >= 0 && stopped <= 2 * tail + 3 * len + 2,
             "graph %d start %u: tail %lld cycle %lld, stopped at step %lld", g, start,
             (long long)tail, (long long)len, (long long)stopped);
    }
  }
  EXPECT(cycles > 100 && ends > 100, "too few of each kind: %d cycles, %d ends", cycles, ends);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  if (!strcmp(argv[1], "brent"))
    return stops_only_cycles_and_soon();
  fprintf(stderr, "unknown case %s\n", argv[1]);
  return 2;
}
