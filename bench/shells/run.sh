#!/usr/bin/env bash
# Many-shell nesting benchmark: a sphere holding N^3 spherical cavities (gen_cavities.py).
# Runs, in the same run: `tetrec mesh` (this build), `tetrec delaunay` on the same
# vertices (what the scene costs without any input check or recovery), optionally an
# older tetrec (BASE, e.g. built from the commit before a change) and the peer
# (`tetgen -pQ`), and prints CPU times (user + sys, /usr/bin/time) and ratios.
#
# usage: bench/shells/run.sh BUILD [N=10] [TETGEN=tetgen] [BASE_TETREC]
set -eu
build=$1
n=${2:-10}
tetgen=${3:-tetgen}
base=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
tetrec=$build/src/cli/tetrec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/gen_cavities.py" "$work/cav.off" "$n" 2 4
# tetgen reads .off too; give it its own copy so its outputs land beside it
cp "$work/cav.off" "$work/peer.off"
cpu() { # command... -> prints CPU seconds, fails if the command fails
  local t
  t=$( { /usr/bin/time -f "%U %S" "$@" >/dev/null 2>"$work/err" || { cat "$work/err" >&2; echo FAIL; }; } 2>&1 )
  tail -n1 "$work/err" | awk '{printf "%.2f", $1 + $2}'
}
tris=$(sed -n 2p "$work/cav.off" | awk '{print $2}')
echo "scene: sphere with $((n * n * n)) cavities, $tris triangles"
mesh=$(cpu "$tetrec" mesh "$work/cav.off" -o "$work/out.mesh" -q)
del=$(cpu "$tetrec" delaunay "$work/cav.off" -o "$work/del.mesh")
peer=$(cpu "$tetgen" -pQ "$work/peer.off")
printf "%-28s %8s s\n" "tetrec mesh" "$mesh" "tetrec delaunay (same pts)" "$del" "tetgen -pQ" "$peer"
"$tetrec" check "$work/cav.off" "$work/out.mesh" 2>&1 | tail -n1
awk -v m="$mesh" -v d="$del" -v p="$peer" 'BEGIN {
  printf "ratio mesh / delaunay      %6.2f\n", m / d
  printf "ratio mesh / tetgen -pQ    %6.2f\n", m / p }'
if [ -n "$base" ]; then
  old=$(cpu "$base" mesh "$work/cav.off" -o "$work/old.mesh" -q)
  printf "%-28s %8s s\n" "base tetrec mesh" "$old"
  awk -v m="$mesh" -v o="$old" 'BEGIN { printf "ratio mesh / base mesh     %6.2f\n", m / o }'
fi
