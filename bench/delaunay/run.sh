#!/usr/bin/env bash
# Delaunay peer benchmark: tetrec vs CGAL Delaunay_triangulation_3<Epick> (range insertion,
# spatially sorted) vs tetgen (Debian 1.5, Delaunay only: `tetgen -NEF`, no output files).
# Cases: 10^5 and 10^6 uniform random points in the unit cube, 2.5x10^5 and 10^6 points on
# the unit sphere (nearly cospherical everywhere: the exact stages of insphere decide most
# tests among close points), the 100^3 integer grid (exactly cospherical: the symbolic
# perturbation decides).
# tetrec runs twice: one thread (the serial build) and NJ threads (default every core);
# the ratios to CGAL are printed for both, and the wall-time speed-up of NJ threads over
# one (whole process, and the triangulation alone). 4x10^6 uniform points: CASES=random4000000.
# For each program: the in-process triangulation CPU time (dt: reading excluded; for
# tetgen its own "Delaunay seconds", which is clock() time), the whole-process wall time,
# CPU time (user + sys: reading the points, sorting, triangulating, freeing) and peak RSS
# (GNU time, i.e. getrusage of the child), and the ratios tetrec/CGAL and tetrec/tetgen
# of each. CPU times are the figures to compare on a shared, loaded machine; wall times
# are printed as measured.
# The grid (and 10^5 random) mesh of tetrec is validated (links, exact orientation,
# Euler, perturbed Delaunay property) in a separate, untimed run.
#
# usage: bench/delaunay/run.sh [build-dir]      (default build-bench, a release build)
#   REPEAT=n   best of n runs per measurement (default 1)
#   CASES="random100000 random1000000 sphere250000 sphere1000000 grid100"   subset to run
#   NO_TETGEN=1   skip tetgen
#   TETGEN=path   the tetgen binary (default: tetgen on PATH, Debian's 1.5), e.g. TetGen 1.6
#                 built by bench/peer/build_tetgen.sh
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build-bench}
REPEAT=${REPEAT:-1}
NJ=${NJ:-$(nproc)} # threads of the parallel run (default: every core)
CASES=${CASES:-"random100000 random1000000 sphere250000 sphere1000000 grid100"}
OUT=$ROOT/bench/out/delaunay
mkdir -p "$OUT"
if [ ! -f "$BUILD/build.ninja" ]; then
  meson setup "$BUILD" "$ROOT" --buildtype=release -Dbench=true >/dev/null
fi
ninja -C "$BUILD" -j2 bench/delaunay/bench_tetrec >/dev/null
TR=$BUILD/bench/delaunay/bench_tetrec
CG=$BUILD/bench/delaunay/bench_cgal
ninja -C "$BUILD" -j2 bench/delaunay/bench_cgal >/dev/null 2>&1 || CG=""
TG=${TETGEN:-$(command -v tetgen || true)}
[ -n "${NO_TETGEN:-}" ] && TG=""

# measure <label> <cmd...>: best of REPEAT; sets M_DT M_WALL M_CPU (user + sys) M_RSS (KB)
measure() {
  local label=$1
  shift
  M_DT=""; M_WALL=""; M_CPU=""; M_RSS=""
  for _ in $(seq "$REPEAT"); do
    /usr/bin/time -o "$OUT/time.txt" -f "%e %U %S %M" "$@" >"$OUT/stdout.txt" 2>&1 || {
      echo "$label failed:"; cat "$OUT/stdout.txt"; exit 1; }
    local dt wall user sys rss
    dt=$(sed -n 's/.*dt_cpu=\([0-9.]*\).*/\1/p; s/^Delaunay seconds: *\([0-9.e+-]*\).*/\1/p' \
         "$OUT/stdout.txt" | head -1)
    read -r wall user sys rss <"$OUT/time.txt"
    if [ -z "$M_WALL" ] || awk "BEGIN{exit !($wall < $M_WALL)}"; then
      M_DT=$dt; M_WALL=$wall; M_CPU=$(awk "BEGIN{print $user + $sys}"); M_RSS=$rss
    fi
  done
  printf "  %-8s dt(cpu) %7.3f s   wall %8.2f s   process cpu %8.2f s   peak RSS %8.1f MB   %s\n" \
    "$label" "${M_DT:-0}" "$M_WALL" "$M_CPU" "$(awk "BEGIN{print $M_RSS/1024}")" \
    "$(grep -o 'tets=[0-9]*' "$OUT/stdout.txt" || sed -n 's/^ *Mesh tetrahedra: */tets=/p' "$OUT/stdout.txt")"
}
# dtwall <threads>: the in-process triangulation wall time of one more run (dt_seconds)
dtwall() { "$TR" run "$OUT/$c.bin" -j"$1" | sed -n 's/.*dt_seconds=\([0-9.]*\).*/\1/p'; }
ratio() { awk "BEGIN{ if ($2 > 0) printf \"%.2f\", $1 / $2; else printf \"n/a\" }"; }

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for c in $CASES; do
  case $c in
    random*) kind=random; n=${c#random} ;;
    sphere*) kind=sphere; n=${c#sphere} ;;
    grid*) kind=grid; n=${c#grid} ;;
    *) echo "unknown case $c"; exit 2 ;;
  esac
  "$TR" gen "$kind" "$n" "$OUT/$c.bin" "$OUT/$c.node"
  echo "== $c"
  measure tetrec "$TR" run "$OUT/$c.bin"
  t_dt=$M_DT; t_wall=$M_WALL; t_rss=$M_RSS; t_cpu=$M_CPU
  measure "tetrec-j$NJ" "$TR" run "$OUT/$c.bin" -j"$NJ"
  j_dt=$M_DT; j_wall=$M_WALL; j_rss=$M_RSS; j_cpu=$M_CPU
  echo "  tetrec 1 -> $NJ threads: wall speed-up $(ratio "$t_wall" "$j_wall"), dt wall speed-up $(ratio "$(dtwall 1)" "$(dtwall "$NJ")")"
  if [ -n "$CG" ]; then
    measure cgal "$CG" "$OUT/$c.bin"
    echo "  tetrec/CGAL:   dt $(ratio "$t_dt" "$M_DT")   wall $(ratio "$t_wall" "$M_WALL")   process cpu $(ratio "$t_cpu" "$M_CPU")   peak RSS $(ratio "$t_rss" "$M_RSS")"
    echo "  tetrec-j$NJ/CGAL: wall $(ratio "$j_wall" "$M_WALL")   process cpu $(ratio "$j_cpu" "$M_CPU")   peak RSS $(ratio "$j_rss" "$M_RSS")"
  fi
  if [ -n "$TG" ]; then
    measure tetgen "$TG" -NEF "$OUT/$c.node"
    echo "  tetrec/tetgen: dt $(ratio "$t_dt" "$M_DT")   wall $(ratio "$t_wall" "$M_WALL")   process cpu $(ratio "$t_cpu" "$M_CPU")   peak RSS $(ratio "$t_rss" "$M_RSS")"
  fi
  if [ "$kind" = grid ] || [ "$n" -le 100000 ]; then
    "$TR" run "$OUT/$c.bin" check | sed -n 's/^tetrec validator/  validator/p'
  fi
  rm -f "$OUT/$c.bin" "$OUT/$c.node"
done
