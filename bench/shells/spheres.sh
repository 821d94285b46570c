#!/usr/bin/env bash
# Nearly cospherical surfaces (issue 19): an icosphere whose vertices all lie on the unit
# sphere, and a bumpy sphere with the same triangles moved off it (gen_sphere.py), each
# through `tetrec mesh` with one thread and with every core, `tetrec delaunay` on the same
# vertices and the peer (`tetgen -pQ`), in one run: CPU seconds (user + sys of the whole
# process, /usr/bin/time), wall seconds, and the ratios tetrec/peer and icosphere/bumpy
# (what the cospherical points cost over the same mesh off the sphere). Each tetrec mesh
# is checked by `tetrec check` (links, exact orientation, exact conformity, volume).
#
# usage: bench/shells/spheres.sh BUILD [SUB=7] [TETGEN=tetgen]
#   SUB: 20 * 4^SUB triangles per surface (7: 327,680)
#   TG_FLAGS=...  tetgen's switches (default -pQ)
set -eu
build=$1
sub=${2:-7}
tetgen=${3:-tetgen}
tg_flags=${TG_FLAGS:--pQ}
here=$(cd "$(dirname "$0")" && pwd)
tetrec=$build/src/cli/tetrec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # label command... -> sets CPU and WALL (FAIL on failure, its error on stderr)
  local label=$1
  shift
  if /usr/bin/time -o "$work/time" -f "%U %S %e" "$@" >/dev/null 2>"$work/err"; then
    CPU=$(awk '{printf "%.2f", $1 + $2}' "$work/time")
    WALL=$(awk '{printf "%.2f", $3}' "$work/time")
  else
    echo "$label failed: $(tail -n 2 "$work/err")" >&2
    CPU=FAIL
    WALL=FAIL
  fi
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else printf "n/a" }'; }
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-10s %-22s %10s %10s\n" surface program "cpu s" "wall s"
declare -A M1
for kind in icosphere bumpy; do
  python3 "$here/gen_sphere.py" "$work/$kind.off" "$kind" "$sub"
  cp "$work/$kind.off" "$work/peer_$kind.off"
  run "tetrec mesh -j1" "$tetrec" mesh "$work/$kind.off" -o "$work/$kind.node" -q --threads 1
  m1=$CPU
  M1[$kind]=$CPU
  printf "%-10s %-22s %10s %10s\n" "$kind" "tetrec mesh 1 thread" "$CPU" "$WALL"
  if [ "$m1" != FAIL ]; then
    if "$tetrec" check "$work/$kind.off" "$work/$kind.node" >"$work/check" 2>&1; then
      echo "           check: $(grep -m1 -o 'links.*' "$work/check")"
    else
      echo "           check: INVALID: $(grep -m1 error "$work/check")"
    fi
  fi
  run "tetrec mesh" "$tetrec" mesh "$work/$kind.off" -o "$work/${kind}_all.node" -q
  printf "%-10s %-22s %10s %10s\n" "$kind" "tetrec mesh all cores" "$CPU" "$WALL"
  run "tetrec delaunay" "$tetrec" delaunay "$work/$kind.off" -o "$work/${kind}_del.node" --threads 1
  d1=$CPU
  printf "%-10s %-22s %10s %10s\n" "$kind" "tetrec delaunay 1 thr" "$CPU" "$WALL"
  # shellcheck disable=SC2086 # TG_FLAGS may hold several switches
  run "tetgen" "$tetgen" $tg_flags "$work/peer_$kind.off"
  printf "%-10s %-22s %10s %10s\n" "$kind" "tetgen $tg_flags" "$CPU" "$WALL"
  echo "           ratios (cpu, 1 thread): mesh/tetgen $(ratio "$m1" "$CPU"), mesh/delaunay $(ratio "$m1" "$d1")"
done
echo "icosphere / bumpy, tetrec mesh 1 thread cpu: $(ratio "${M1[icosphere]}" "${M1[bumpy]}")"
