#!/usr/bin/env bash
# The refinement options of `tetrec mesh`: --quality R bounds the radius-edge ratio, a dihedral
# target D is worked towards by sliver removal (out of (0, 70] or with -O 0: exit 1; a
# warning when tets stay under it), bad bounds and the options on other
# commands are usage errors (exit 1; --subface-quality under 1 too), --subface-quality and
# --keep-edges without refinement are warned about, the point budget stops a run with exit 8, a
# message and the mesh made so far written, and --stats carries the quality rows; `check
# --quality R/D -a V` counts the tets over the bounds; --refine-rounds gives the same mesh on
# 1 and 2 threads; quality figures are measured only where shown (--stats, the notes), the
# mesh the same either way. Every mesh written is checked.
# usage: cli_options.sh TETREC SURFACE WORKDIR THIN (THIN: a surface with thin triangles)
set -u
T=$1 S=$2 W=$3 THIN=$4
rm -rf "$W" # "no mesh written" below means by this run
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
expect 0 "" -- mesh --quality 1.414 "$S" -o "$W/a.node" --exact --stats "$W/a.json"
expect 0 "conforms exactly" -- check "$S" "$W/a.node"
grep -q '"points_added_for_quality"' "$W/a.json" && grep -q '"min_dihedral"' "$W/a.json" &&
  grep -q '"radius_edge_histogram": \[' "$W/a.json" || { echo "FAIL: stats rows"; fails=$((fails + 1)); }
# check --quality R counts the tets over R on the file's doubles: the mesh's own count
expect 0 "bounds: [0-9]+ tets, [0-9]+ \([0-9.]+%\) over radius-edge 1.414$" -- check "$S" "$W/a.node" --quality 1.414
over=$(sed -n 's/.*bounds: [0-9]* tets, \([0-9]*\) .*/\1/p' "$W/out")
want=$(sed -n 's/.*"tets_over_bounds": \([0-9]*\).*/\1/p' "$W/a.json")
[ -n "$over" ] && [ "$over" = "$want" ] || { echo "FAIL: check counts $over tets over 1.414, --stats $want"; fails=$((fails + 1)); }
expect 0 "" -- mesh "$S" --quality 1.2 -a 0.05 -o "$W/b.node" --exact -q
expect 0 "conforms exactly.*volume equals" -- check "$S" "$W/b.node"
expect 0 "" -- mesh "$S" --quality 1.2/15 -a 0.05 -o "$W/d.node" --exact --stats "$W/d.json"
expect 0 "conforms exactly" -- check "$S" "$W/d.node"
expect 0 "over volume 0.05, [0-9]+ \([0-9.]+%\) with a dihedral angle under 15 degrees" -- check "$S" "$W/d.node" --quality 1.2/15 -a 0.05
grep -q "bounds: .* 0 (0.00%) over volume 0.05" "$W/out" || { echo "FAIL: tets over -a 0.05 in a mesh refined under it"; cat "$W/out"; fails=$((fails + 1)); }
expect 0 "keep a dihedral angle under the target 70 degrees" -- mesh "$S" --quality 1.2/70 -o "$W/e.node"
expect 1 "in \(0, 70\] degrees" -- mesh "$S" --quality 1.2/75 -o "$W/c.node"
expect 1 "which .-optimize 0 turns off" -- mesh "$S" --quality 1.2/15 -O 0 -o "$W/c.node"
expect 1 "at least 1" -- mesh "$S" --quality 0.5 -o "$W/c.node"
expect 0 "" -- mesh "$S" --quality 1.414 --subface-quality 1.414 -a 0.05 -o "$W/f.node" --exact -q
expect 0 "conforms exactly.*volume equals" -- check "$S" "$W/f.node"
expect 1 "ratio of at least 1" -- mesh "$S" --quality 1.414 --subface-quality 0.5 -o "$W/c.node"
expect 0 "" -- mesh "$S" --quality 1.414 --keep-edges -o "$W/g.node" --exact -q
expect 0 "conforms exactly.*volume equals" -- check "$S" "$W/g.node"
expect 0 "warning: --subface-quality has no effect without quality refinement" -- mesh "$S" --subface-quality 2 -o "$W/h.node"
expect 0 "warning: --keep-edges has no effect without quality refinement" -- mesh "$S" --keep-edges -o "$W/h.node"
expect 1 "positive volume" -- mesh "$S" -a -1 -o "$W/c.node"
expect 1 "does not apply to 'delaunay'" -- delaunay "$S" --quality 1.414
# a bound asking for more than 8 tets per budget point (1,000 tets, 50 points) is refused
# before refinement
expect 8 "asks for at least 1e\+03 tets .* budget of 50 points" -- mesh "$S" -a 0.001 --refine-budget 50 -o "$W/c.node"
expect 1 "whole number" -- mesh "$S" --refine-budget 0 -o "$W/c.node"
[ ! -e "$W/c.node" ] || { echo "FAIL: a refused run wrote a mesh"; fails=$((fails + 1)); }
# one within that (130 points) runs until the budget stops it: exit 8, the mesh made so
# far written, conforming, and its tets over the bound counted in the message and --stats
expect 8 "holds the mesh made so far, valid and conforming, with [1-9][0-9]* of its [0-9]* tets over the bounds" -- mesh "$S" -a 0.001 --refine-budget 130 -o "$W/p.node" --exact --stats "$W/p.json"
grep -q "point budget of 130 points" "$W/out" || { echo "FAIL: the budget is not named"; fails=$((fails + 1)); }
expect 0 "conforms exactly.*volume equals" -- check "$S" "$W/p.node"
grep -q '"status": "TR_ERR_NOMEM"' "$W/p.json" && grep -q '"refine_budget_reached": 1' "$W/p.json" &&
  grep -qE '"tets_over_bounds": [1-9]' "$W/p.json" &&
  grep -q '"points_added_for_quality": 130,' "$W/p.json" &&
  grep -q '"points_added_for_sliver": 0,' "$W/p.json" || { echo "FAIL: budget stats rows"; cat "$W/p.json"; fails=$((fails + 1)); }
# --refine-rounds N: refinement's rounds of parallel insertion (docs/refinement.md), the
# same files on 1 and 2 threads, conforming exactly; N = 0 is a usage error
expect 0 "refinement rounds: [1-9][0-9]*, [1-9][0-9]* points inserted in them" -- mesh "$S" -a 0.0005 --refine-rounds 256 -j 1 -v -o "$W/r1.node" --exact
expect 0 "" -- mesh "$S" -a 0.0005 --refine-rounds 256 -j 2 -q -o "$W/r2.node" --exact
cmp -s "$W/r1.node" "$W/r2.node" && cmp -s "$W/r1.ele" "$W/r2.ele" || { echo "FAIL: --refine-rounds: 1 and 2 threads differ"; fails=$((fails + 1)); }
expect 0 "conforms exactly.*volume equals" -- check "$S" "$W/r2.node"
expect 1 "refine-rounds needs a whole number from 1 to 4294967295, not .0." -- mesh "$S" --quality 1.414 --refine-rounds 0 -o "$W/r0.node"
# without --stats no quality figure is measured unless a note shows it: the same files, the
# stats rows there with --stats, and the note on thin input triangles (refinement) and the
# dihedral target's warning (above) still printed
expect 0 "" -- mesh "$S" -o "$W/n1.node" -q
expect 0 "" -- mesh "$S" -o "$W/n2.node" -q --stats "$W/n2.json"
cmp -s "$W/n1.node" "$W/n2.node" && cmp -s "$W/n1.ele" "$W/n2.ele" && cmp -s "$W/n1.face" "$W/n2.face" ||
  { echo "FAIL: the mesh differs with --stats"; fails=$((fails + 1)); }
grep -qE '"min_dihedral": [1-9]' "$W/n2.json" || { echo "FAIL: --stats without quality figures"; fails=$((fails + 1)); }
expect 0 "stand on input triangles with a corner under 10 degrees" -- mesh "$THIN" --quality 1.414 -o "$W/t.node" --exact
expect 0 "conforms exactly" -- check "$THIN" "$W/t.node"
exit $((fails != 0))
