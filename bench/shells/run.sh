#!/usr/bin/env bash
# Many-shell nesting benchmark: a sphere holding N^3 spherical cavities (gen_cavities.py).
# Runs, in the same run: `tetrec mesh` (this build), `tetrec delaunay` on the same
# vertices (what the scene costs without any input check or recovery), optionally an
# older tetrec (BASE, e.g. built from the commit before a change) and the peer
# (`tetgen -pQ`, e.g. TetGen 1.6 built by bench/peer/build_tetgen.sh), and prints CPU
# times (user + sys of the whole process, /usr/bin/time) and ratios; a run that fails
# prints FAIL and its error, and its ratios n/a.
#
# usage: bench/shells/run.sh BUILD [N=10] [TETGEN=tetgen] [BASE_TETREC]
#   TG_FLAGS=...  tetgen's switches (default -pQ)
set -eu
build=$1
n=${2:-10}
tetgen=${3:-tetgen}
base=${4:-}
tg_flags=${TG_FLAGS:--pQ}
here=$(cd "$(dirname "$0")" && pwd)
tetrec=$build/src/cli/tetrec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/gen_cavities.py" "$work/cav.off" "$n" 2 4
# tetgen reads .off too; give it its own copy so its outputs land beside it
cp "$work/cav.off" "$work/peer.off"
cpu() { # command... -> prints CPU seconds, or FAIL (its error on stderr)
  if /usr/bin/time -o "$work/time" -f "%U %S" "$@" >/dev/null 2>"$work/err"; then
    awk '{printf "%.2f", $1 + $2}' "$work/time"
  else
    tail -n 3 "$work/err" >&2
    echo FAIL
  fi
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%6.2f", a / b; else printf "   n/a" }'; }
tris=$(sed -n 2p "$work/cav.off" | awk '{print $2}')
echo "scene: sphere with $((n * n * n)) cavities, $tris triangles"
mesh=$(cpu "$tetrec" mesh "$work/cav.off" -o "$work/out.mesh" -q)
del=$(cpu "$tetrec" delaunay "$work/cav.off" -o "$work/del.mesh")
# shellcheck disable=SC2086 # TG_FLAGS may hold several switches
peer=$(cpu "$tetgen" $tg_flags "$work/peer.off")
tg_version=$("$tetgen" -h 2>/dev/null | sed -n 's/^Version *//p' | head -n 1 || true)
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); tetgen ${tg_version:-(version unknown)}"
printf "%-28s %8s s\n" "tetrec mesh" "$mesh" "tetrec delaunay (same pts)" "$del" "tetgen $tg_flags" "$peer"
if [ "$mesh" != FAIL ]; then
  if "$tetrec" check "$work/cav.off" "$work/out.mesh" >"$work/check" 2>&1; then
    grep -m1 'valid' "$work/check"
  else
    echo "tetrec mesh: INVALID: $(grep -m1 error "$work/check")"
  fi
fi
printf "%-26s %s\n" "ratio mesh / delaunay" "$(ratio "$mesh" "$del")" \
  "ratio mesh / tetgen $tg_flags" "$(ratio "$mesh" "$peer")"
if [ -n "$base" ]; then
  old=$(cpu "$base" mesh "$work/cav.off" -o "$work/old.mesh" -q)
  printf "%-28s %8s s\n" "base tetrec mesh" "$old"
  printf "%-26s %s\n" "ratio mesh / base mesh" "$(ratio "$mesh" "$old")"
fi
