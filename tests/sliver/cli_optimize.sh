#!/usr/bin/env bash
# The sliver removal option of `tetrec mesh`: -O/--optimize 0|1|2|3 (default 3) after quality
# refinement, its --stats rows (points_added_for_sliver is 0 below level 3, flips and moved
# points by level), a bad level and the option on another command are usage errors (exit 1), and
# without refinement it warns that it has no effect. Every mesh written is checked exactly.
# usage: cli_optimize.sh TETREC SURFACE WORKDIR
set -u
T=$1 S=$2 W=$3
mkdir -p "$W"
fails=0
expect() { # expect CODE PATTERN -- ARGS...
  local code=$1 pat=$2
  shift 3
  "$T" "$@" >"$W/out" 2>&1
  local rc=$?
  if [ $rc -ne "$code" ] || { [ -n "$pat" ] && ! grep -qE "$pat" "$W/out"; }; then
    echo "FAIL: tetrec $* -> $rc (want $code, /$pat/):"; cat "$W/out"; fails=$((fails + 1))
  fi
}
row() { sed -n "s/.*\"$2\": \([0-9]*\).*/\1/p" "$1"; }
for level in 0 1 2 3; do
  expect 0 "" -- mesh "$S" --quality 1.414 -O $level -o "$W/o$level.node" --exact --stats "$W/o$level.json"
  expect 0 "conforms exactly" -- check "$S" "$W/o$level.node"
done
expect 0 "" -- mesh "$S" --quality 1.414 -o "$W/d.node" --exact --stats "$W/d.json"
[ "$(row "$W/o0.json" sliver_flips)" = 0 ] && [ "$(row "$W/o0.json" sliver_points_smoothed)" = 0 ] ||
  { echo "FAIL: -O 0 changed the mesh"; fails=$((fails + 1)); }
[ "$(row "$W/o1.json" sliver_flips)" -gt 0 ] && [ "$(row "$W/o1.json" sliver_points_smoothed)" = 0 ] ||
  { echo "FAIL: -O 1 is flips only"; fails=$((fails + 1)); }
[ "$(row "$W/o2.json" sliver_flips)" -gt 0 ] && [ "$(row "$W/o2.json" sliver_points_smoothed)" -gt 0 ] ||
  { echo "FAIL: -O 2 flips and smooths"; fails=$((fails + 1)); }
for level in 0 1 2; do
  [ "$(row "$W/o$level.json" points_added_for_sliver)" = 0 ] ||
    { echo "FAIL: -O $level added points"; fails=$((fails + 1)); }
done
cmp -s "$W/o3.ele" "$W/d.ele" && cmp -s "$W/o3.node" "$W/d.node" ||
  { echo "FAIL: the default is not -O 3"; fails=$((fails + 1)); }
expect 0 "optimize" -- mesh --help
expect 1 "level 0, 1, 2 or 3" -- mesh "$S" --quality 1.414 -O 4 -o "$W/c.node"
expect 1 "level 0, 1, 2 or 3" -- mesh "$S" --quality 1.414 --optimize x -o "$W/c.node"
expect 1 "does not apply to 'delaunay'" -- delaunay "$S" -O 1
expect 0 "no effect without quality refinement" -- mesh "$S" -O 2 -o "$W/e.node"
[ ! -e "$W/c.node" ] || { echo "FAIL: a refused run wrote a mesh"; fails=$((fails + 1)); }
# the too-close rule: spacings by default, --insertion-radii the rule of insertion radii
expect 0 "" -- mesh "$S" --quality 1.414 --spacing-radii -o "$W/sp.node" --exact
expect 0 "" -- mesh "$S" --quality 1.414 --insertion-radii -o "$W/ir.node" --exact --stats "$W/ir.json"
expect 0 "conforms exactly" -- check "$S" "$W/ir.node"
cmp -s "$W/sp.ele" "$W/d.ele" && cmp -s "$W/sp.node" "$W/d.node" ||
  { echo "FAIL: the default is not --spacing-radii"; fails=$((fails + 1)); }
cmp -s "$W/ir.ele" "$W/d.ele" &&
  { echo "FAIL: --insertion-radii changed nothing"; fails=$((fails + 1)); }
expect 0 "insertion-radii has no effect without quality refinement" -- mesh "$S" --insertion-radii -o "$W/e.node"
expect 0 "spacing-radii has no effect without quality refinement" -- mesh "$S" --spacing-radii -o "$W/e.node"
exit $((fails != 0))
