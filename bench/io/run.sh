#!/usr/bin/env bash
# Output benchmark (issue 48, "Big meshes"): `tetrec delaunay` on N uniform random points
# (default 4x10^6, a 270 MB .node of %.17g doubles from gen_points.py), writing binary
# Gmsh 4.1 (`-o out.msh --binary`) and TetGen text (`-o out.node`: .node/.ele/.face), with
# 1 and NJ threads (default every core), against CGAL's Delaunay_triangulation_3 on the
# same points (bench/delaunay/bench_cgal, range insertion).
# For each run: the whole-process wall time, CPU time (user + sys) and peak RSS (GNU time),
# tetrec's own stage times (-v: reading, delaunay, writing) and --stats bytes_per_tet. Then
# the ratios: tetrec 1 -> NJ threads (wall speed-up), tetrec / CGAL (wall and CPU).
# CGAL reads the points from a binary file and writes nothing: tetrec's figures include
# parsing 270 MB of text and writing 1.2-1.3 GB; the in-process Delaunay times
# (tetrec's "delaunay" stage, CGAL's dt_seconds) compare the triangulations alone. Wall
# times depend on the load: the script prints it; CPU times are the figures to compare on
# a shared machine.
#
# usage: bench/io/run.sh [build-dir]      (default build-bench, a release build with
#                                          -Dbench=true; the CGAL peer needs CGAL)
#   N=n        points (default 4000000)
#   NJ=n       threads of the parallel runs (default: every core)
#   REPEAT=n   best of n runs per measurement (default 1)
#   KEEP=1     keep the output files (4 GB at the default N) in bench/out/io
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build-bench}
N=${N:-4000000}
NJ=${NJ:-$(nproc)}
REPEAT=${REPEAT:-1}
OUT=$ROOT/bench/out/io
mkdir -p "$OUT"
if [ ! -f "$BUILD/build.ninja" ]; then
  meson setup "$BUILD" "$ROOT" --buildtype=release -Dbench=true >/dev/null
fi
ninja -C "$BUILD" -j2 src/cli/tetrec >/dev/null
TR=$BUILD/src/cli/tetrec
CG=$BUILD/bench/delaunay/bench_cgal
ninja -C "$BUILD" -j2 bench/delaunay/bench_cgal >/dev/null 2>&1 || CG=""

# stage <name>: tetrec's -v time of a stage in the last run's log
stage() { sed -n "s/^tetrec: $1  *\([0-9.]*\) s$/\1/p" "$OUT/log.txt"; }
# measure <label> <cmd...>: best of REPEAT by wall time; sets M_WALL M_CPU M_RSS (KB),
# M_READ M_DT M_WRITE (tetrec's -v stage seconds; CGAL's dt_seconds as M_DT), M_BPT
measure() {
  local label=$1
  shift
  M_WALL=""
  for _ in $(seq "$REPEAT"); do
    /usr/bin/time -o "$OUT/time.txt" -f "%e %U %S %M" "$@" >"$OUT/log.txt" 2>&1 || {
      echo "$label failed:"; cat "$OUT/log.txt"; exit 1; }
    local wall user sys rss
    read -r wall user sys rss <"$OUT/time.txt"
    if [ -z "$M_WALL" ] || awk "BEGIN{exit !($wall < $M_WALL)}"; then
      M_WALL=$wall; M_CPU=$(awk "BEGIN{print $user + $sys}"); M_RSS=$rss
      M_READ=$(stage reading); M_WRITE=$(stage writing); M_DT=$(stage delaunay)
      [ -n "$M_DT" ] || M_DT=$(sed -n 's/.*dt_seconds=\([0-9.]*\).*/\1/p' "$OUT/log.txt")
      M_BPT=$(sed -n 's/.*"bytes_per_tet": \([0-9.]*\).*/\1/p' "$OUT/stats.json" 2>/dev/null || true)
    fi
    rm -f "$OUT"/out.* "$OUT/stats.json"
  done
  printf "  %-10s wall %7.2f s  cpu %7.2f s  peak RSS %7.1f MB  read %6s  delaunay %6s  write %6s  bytes/tet %s\n" \
    "$label" "$M_WALL" "$M_CPU" "$(awk "BEGIN{print $M_RSS/1024}")" "${M_READ:--}" \
    "${M_DT:--}" "${M_WRITE:--}" "$(printf %.1f "${M_BPT:-0}" | sed 's/^0.0$/-/')"
}
ratio() { awk "BEGIN{ if ($2 > 0) printf \"%.2f\", $1 / $2; else printf \"n/a\" }"; }

python3 "$ROOT/bench/io/gen_points.py" "$N" "$OUT/points.node" "$OUT/points.bin"
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $N points, $(du -m "$OUT/points.node" | cut -f1) MB .node"
if [ -n "$CG" ]; then
  measure cgal "$CG" "$OUT/points.bin"
  c_wall=$M_WALL; c_cpu=$M_CPU; c_dt=$M_DT
fi
# label : extension : flag
for c in "mshb:msh:--binary" "node:node:"; do
  IFS=: read -r label ext flags <<<"$c"
  # shellcheck disable=SC2086 # flags: zero or one word
  measure "$label -j1" "$TR" delaunay "$OUT/points.node" -v -j 1 -o "$OUT/out.$ext" $flags \
    --stats "$OUT/stats.json"
  w1=$M_WALL; p1=$M_CPU; d1=$M_DT
  # shellcheck disable=SC2086
  measure "$label -j$NJ" "$TR" delaunay "$OUT/points.node" -v -j "$NJ" -o "$OUT/out.$ext" \
    $flags --stats "$OUT/stats.json"
  echo "  $label: tetrec 1 -> $NJ threads: wall speed-up $(ratio "$w1" "$M_WALL")"
  if [ -n "$CG" ]; then
    echo "  $label: tetrec/CGAL wall: -j1 $(ratio "$w1" "$c_wall"), -j$NJ $(ratio "$M_WALL" "$c_wall");" \
      "cpu: -j1 $(ratio "$p1" "$c_cpu"), -j$NJ $(ratio "$M_CPU" "$c_cpu");" \
      "Delaunay alone (in process, wall): -j1 $(ratio "$d1" "$c_dt"), -j$NJ $(ratio "$M_DT" "$c_dt")"
  fi
done
[ -n "${KEEP:-}" ] || rm -f "$OUT/points.node" "$OUT/points.bin"
