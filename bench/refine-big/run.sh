#!/usr/bin/env bash
# Refinement at scale (issue 48, "Big meshes"): `tetrec mesh --quality R -a V` against
# TetGen 1.6 `-pqRaV` on one CGAL model sized to give millions of tets (default CGAL's
# elephant.off with -a 8e-9: about 10^7 tets), one run each, side by side: whole-process
# wall and CPU time (user + sys), peak RSS (GNU time), bytes per tet (peak RSS / tets: the
# issue's bound is 150) and the tet count, then tetrec's -v stage times and its peaks. The
# machine's load is printed: on a shared machine compare CPU, not wall.
#
# usage: bench/refine-big/run.sh [build-dir]   (default build-rel, a release build)
#   MODEL=path  the .off to mesh (default the CGAL corpus's elephant.off under the build
#               dir's realworld link: ln -s <corpus> <build>/realworld)
#   A=v         volume bound (default 8e-9)   R=r  radius-edge bound (default 1.414)
#   THREADS=n   tetrec --threads (default 1)
#   ROUNDS=n    tetrec --refine-rounds n: refinement's rounds of parallel insertion from n
#               queued bad tets (default none: the serial loop; docs/refinement.md)
#   TETGEN=path TetGen 1.6 (default tetgen on PATH; none: tetrec only)
#   KEEP=1      keep the output files (1 GB or more at the default size) in bench/out/refine-big
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build-rel}
MODEL=${MODEL:-$BUILD/realworld/cgal/data/meshes/elephant.off}
A=${A:-8e-9}
R=${R:-1.414}
THREADS=${THREADS:-1}
ROUNDS=${ROUNDS:-}
TETGEN=${TETGEN:-$(command -v tetgen || true)}
OUT=$ROOT/bench/out/refine-big
mkdir -p "$OUT"
[ -f "$MODEL" ] || { echo "no model $MODEL (set MODEL=...)"; exit 1; }
if [ ! -f "$BUILD/build.ninja" ]; then
  meson setup "$BUILD" "$ROOT" --buildtype=release -Dbench=false >/dev/null
fi
ninja -C "$BUILD" -j2 src/cli/tetrec >/dev/null
TR=$BUILD/src/cli/tetrec

# row <label> <tets>: one line from the last run's time.txt
row() {
  local wall user sys rss
  read -r wall user sys rss <"$OUT/time.txt"
  awk -v l="$1" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" -v n="$2" 'BEGIN {
    printf "  %-7s wall %8.2f s  cpu %8.2f s  peak RSS %8.1f MB  bytes/tet %6.1f  tets %d\n",
      l, w, u + s, r / 1024, (n > 0 ? r * 1024 / n : 0), n }'
}

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $(basename "$MODEL") -q $R -a $A${ROUNDS:+ --refine-rounds $ROUNDS} --threads $THREADS"
/usr/bin/time -o "$OUT/time.txt" -f "%e %U %S %M" "$TR" mesh "$MODEL" -o "$OUT/tetrec.mesh" \
  --quality "$R" -a "$A" --threads "$THREADS" ${ROUNDS:+--refine-rounds "$ROUNDS"} -v --stats "$OUT/stats.json" >"$OUT/tetrec.log" 2>&1 ||
  { echo "tetrec failed:"; tail -5 "$OUT/tetrec.log"; exit 1; }
tets=$(sed -n 's/.*"volume_elements": \([0-9]*\).*/\1/p' "$OUT/stats.json")
row tetrec "$tets"
cp "$OUT/time.txt" "$OUT/tetrec.time"
if [ -n "$TETGEN" ]; then
  cp "$MODEL" "$OUT/tg.off"
  rm -f "$OUT"/tg.1.*
  /usr/bin/time -o "$OUT/time.txt" -f "%e %U %S %M" "$TETGEN" "-pq${R}a${A}Q" "$OUT/tg.off" \
    >"$OUT/tetgen.log" 2>&1 || { echo "TetGen failed:"; tail -5 "$OUT/tetgen.log"; exit 1; }
  row tetgen "$(head -1 "$OUT/tg.1.ele" | awk '{print $1}')"
fi
echo "tetrec stages (-v):"
grep -E '^tetrec: [a-z_]+ +[0-9.]+ s' "$OUT/tetrec.log" | sed 's/^tetrec: /  /'
if [ "${KEEP:-0}" != 1 ]; then
  rm -f "$OUT/tetrec.mesh" "$OUT"/tg.1.* "$OUT/tg.off"
fi
