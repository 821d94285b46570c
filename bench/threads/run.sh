#!/usr/bin/env bash
# Thread-count invariance on real inputs (issue 19: "output byte-identical for 1 and 2
# threads on the corpus and the hard cases"): every CGAL sample surface (libcgal-dev's
# data.tar.gz, data/meshes/*.off, extracted into the build dir as bench/peer does), every
# hard case written by BUILD/tests/hard/gen_hard and every surface of tests/data is meshed
# with `--threads 1` and `--threads 2` (also `--threads 3`: more threads than cores), the
# .node/.ele/.face files are compared byte for byte, and the 2-thread mesh goes through
# `tetrec check`. Inputs below the parallel threshold of the Delaunay stage (a serial prefix
# of a few thousand points per thread) are meshed serially whatever N is; the table says
# how many vertices each input has so the ones that exercised the threads can be seen.
# An input tetrec rejects (exit 2..7) must be rejected the same way with every N.
#
# usage: bench/threads/run.sh [BUILD_DIR]   (default build-peer; a release build is set
#        up there if missing)
#   ONLY=regex      only the inputs whose name matches (grep -E)
#   TR_FLAGS=...    extra tetrec switches for every run (e.g. "--quality 1.414")
#   TIMEOUT=s       per-run wall-clock limit (default 300)
# Output: a table on stdout and in BUILD/bench-threads/table.txt; exit 1 if any input's
# outputs differ between thread counts or its 2-thread mesh fails the check.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-build-peer}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
ONLY=${ONLY:-}
TR_FLAGS=${TR_FLAGS:-}
TIMEOUT=${TIMEOUT:-300}

if [ ! -f "$BUILD/build.ninja" ]; then
  meson setup "$BUILD" "$ROOT" --buildtype=release >/dev/null
fi
ninja -C "$BUILD" -j2 src/cli/tetrec >/dev/null
if ninja -C "$BUILD" -t targets all 2>/dev/null | grep -q '^tests/hard/gen_hard:'; then
  ninja -C "$BUILD" -j2 tests/hard/gen_hard >/dev/null
fi
TR=$BUILD/src/cli/tetrec
OUT=$BUILD/bench-threads
WORK=$OUT/work
rm -rf "$WORK"
mkdir -p "$WORK"

DATA=$BUILD/bench-peer
mkdir -p "$DATA"
[ -d "$DATA/data/meshes" ] ||
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$DATA" --wildcards 'data/meshes/*.off'
inputs=("$DATA"/data/meshes/*.off)
if [ -x "$BUILD/tests/hard/gen_hard" ]; then
  mkdir -p "$OUT/hard"
  "$BUILD/tests/hard/gen_hard" "$OUT/hard" >"$OUT/hard.log" 2>&1
  for f in "$OUT"/hard/*; do
    case $f in *.off|*.poly|*.smesh|*.stl|*.ply|*.mesh) inputs+=("$f") ;; esac
  done
fi
for f in "$ROOT"/tests/data/*.off "$ROOT"/tests/data/*.poly "$ROOT"/tests/data/regressions/*.off; do
  [ -f "$f" ] && inputs+=("$f")
done

TABLE=$OUT/table.txt
printf '%-34s %9s %-10s %-9s %s\n' input vertices outcome identical check | tee "$TABLE"
fail=0 n_same=0 n_par=0 n_all=0
for f in "${inputs[@]}"; do
  name=$(basename "$f")
  [ -z "$ONLY" ] || printf '%s\n' "$name" | grep -Eq "$ONLY" || continue
  n_all=$((n_all + 1))
  w=$WORK/${name%.*}
  mkdir -p "$w"
  codes=()
  for j in 1 2 3; do
    set +e
    # shellcheck disable=SC2086
    timeout "$TIMEOUT" "$TR" mesh "$f" -q --threads $j -o "$w/j$j.node" $TR_FLAGS 2>"$w/j$j.err"
    codes+=($?)
    set -e
  done
  outcome=ok identical=yes check=-
  if [ "${codes[0]}" -ne 0 ]; then
    outcome="exit${codes[0]}"
    [ "${codes[1]}" = "${codes[0]}" ] && [ "${codes[2]}" = "${codes[0]}" ] || identical=NO
  else
    for j in 2 3; do
      [ "${codes[$((j - 1))]}" -eq 0 ] || identical=NO
      for e in node ele face; do
        cmp -s "$w/j1.$e" "$w/j$j.$e" || identical=NO
      done
    done
    if "$TR" check "$f" "$w/j2.node" -q >"$w/check.log" 2>&1; then check=valid; else check=FAIL; fi
  fi
  verts=$(awk '!/^[ \t]*(#|$)/ { print $1; exit }' "$w/j1.node" 2>/dev/null || true)
  printf '%-34s %9s %-10s %-9s %s\n' "$name" "${verts:--}" "$outcome" "$identical" "$check" | tee -a "$TABLE"
  if [ "$identical" != yes ] || [ "$check" = FAIL ]; then fail=1; fi
  [ "$identical" = yes ] && n_same=$((n_same + 1))
  if [ "$outcome" = ok ] && [ "${verts:-0}" -ge 8192 ]; then n_par=$((n_par + 1)); fi
  rm -f "$w"/j*.node "$w"/j*.ele "$w"/j*.face "$w"/j*.edge
done
echo "identical for 1, 2 and 3 threads: $n_same of $n_all inputs ($n_par meshed with at least 8192 vertices, where the Delaunay stage runs in parallel)" | tee -a "$TABLE"
exit $fail
