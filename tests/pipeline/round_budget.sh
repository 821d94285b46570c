#!/bin/sh
# The rounding repair stops at its budget (once a fuzz_pipeline timeout: the search ran
# for minutes on a cluster of Steiner points) with a clear error and exit status 9 for a
# double output, while the exact output is written and passes the exact check. The surface
# (tests/hard's gridbox_8_ulps: a grid box moved by ulps) meshed by the paper's recovery
# (--recovery paper: fixed, unlike the flips, which now recover every edge of the ulp
# inputs without a point) needs repaired Steiner points: with --round-budget 1 the repair
# runs out; with the default budget the same input is written as doubles.
# --keep-steiner: the point stays on the surface (by default it is taken off it, and then
# needs no repair).
# usage: round_budget.sh TETREC SURFACE WORKDIR
set -u
tetrec=$1
in=$2
work=$3
mkdir -p "$work"
rm -f "$work/double.mesh" "$work/exact.node" "$work/exact.ele" "$work/exact.face" "$work/stats.json"
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

"$tetrec" mesh "$in" -o "$work/double.mesh" --recovery paper --keep-steiner --round-budget 1 2>"$work/mesh.log"
rc=$?
[ $rc -eq 9 ] || say "double output: exit $rc, want 9: $(tail -2 "$work/mesh.log")"
grep -q "the repair's budget; the exact mesh is valid: write it with --exact" "$work/mesh.log" ||
  say "the error does not say how to get a valid mesh: $(tail -2 "$work/mesh.log")"
[ -s "$work/double.mesh" ] && say "an invalid double mesh was written"
"$tetrec" mesh "$in" -o "$work/exact.node" --recovery paper --keep-steiner --exact 2>"$work/exact.log" ||
  say "mesh --exact exited $?: $(tail -2 "$work/exact.log")"
"$tetrec" check "$in" "$work/exact.node" 2>"$work/check.log" ||
  say "check of the exact mesh exited $?: $(cat "$work/check.log")"
grep -q 'conforms exactly' "$work/check.log" || say "check does not say it conforms exactly"
"$tetrec" mesh "$in" -o "$work/double.mesh" --recovery paper --keep-steiner --stats "$work/stats.json" 2>"$work/default.log" ||
  say "default budget: exit $?: $(tail -2 "$work/default.log")"
grep -Eq '"rounding_repairs": [1-9][0-9]*,' "$work/stats.json" ||
  say "the surface no longer needs a repair: pick another surface"
"$tetrec" check "$in" "$work/double.mesh" 2>"$work/check2.log" ||
  say "check of the repaired double mesh exited $?: $(cat "$work/check2.log")"
for bad in 0 -1 1e6 12x ""; do
  "$tetrec" mesh "$in" -o "$work/bad.mesh" --round-budget "$bad" 2>"$work/bad.log"
  rc=$?
  [ $rc -eq 1 ] && grep -q "round-budget needs a whole number" "$work/bad.log" ||
    say "--round-budget '$bad': exit $rc, want 1 with a message: $(cat "$work/bad.log")"
done
exit $fail
