/* Phase timers of the Delaunay build, compiled in with -DTR_DT_STATS (bw.c, par.c,
 * canon.c): STAT_LAP(name) prints the process CPU time and the wall time since the
 * previous STAT_LAP of the same file (STAT_LAP(NULL) starts a series), on stderr. With
 * several threads the CPU time is the sum over the threads: the wall time says what a
 * phase costs in the run, the ratio of the two how well it uses the threads. */
#ifndef TR_DTSTAT_H
#define TR_DTSTAT_H

#ifdef TR_DT_STATS
#include <stdio.h>
#include <time.h>

static inline double stat_clock(clockid_t c)
{
  struct timespec ts;
  clock_gettime(c, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline void stat_lap(const char *what)
{
  static double cpu0, wall0;
  const double cpu = stat_clock(CLOCK_PROCESS_CPUTIME_ID), wall = stat_clock(CLOCK_MONOTONIC);
  if (what)
    fprintf(stderr, "  %-14s cpu %.3f s  wall %.3f s\n", what, cpu - cpu0, wall - wall0);
  cpu0 = cpu;
  wall0 = wall;
}
#define STAT_LAP(what) stat_lap(what)
#else
#define STAT_LAP(what) ((void)0)
#endif

#endif
