#!/bin/sh
# Regression (fuzz_pipeline timeout): a star whose Steiner points no nearby doubles can
# all make positive. The rounding repair must stop at its budget with a clear error and
# exit status 9 for a double output, while the exact output is written and passes the
# exact check. The star is one of fuzz_pipeline's kind (n = 2) that still hits the budget
# after the recovery changes it went through. usage: round_budget.sh TETREC SURFACE WORKDIR
set -u
tetrec=$1
in=$2
work=$3
mkdir -p "$work"
rm -f "$work/double.mesh" "$work/exact.node" "$work/exact.ele" "$work/exact.face" # no stale outputs
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

"$tetrec" mesh "$in" -o "$work/double.mesh" 2>"$work/mesh.log"
rc=$?
[ $rc -eq 9 ] || say "double output: exit $rc, want 9: $(tail -2 "$work/mesh.log")"
grep -q "the exact mesh is valid: write it with --exact" "$work/mesh.log" ||
  say "the error does not say how to get a valid mesh: $(tail -2 "$work/mesh.log")"
[ -s "$work/double.mesh" ] && say "an invalid double mesh was written"
"$tetrec" mesh "$in" -o "$work/exact.node" --exact 2>"$work/exact.log" ||
  say "mesh --exact exited $?: $(tail -2 "$work/exact.log")"
"$tetrec" check "$in" "$work/exact.node" 2>"$work/check.log" ||
  say "check of the exact mesh exited $?: $(cat "$work/check.log")"
grep -q 'conforms exactly' "$work/check.log" || say "check does not say it conforms exactly"
exit $fail
