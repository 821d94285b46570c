#!/bin/sh
# `tetrec mesh --exact` then `tetrec check` on the result: the exact .node passes the exact
# conformity and volume checks, a double .node whose points conform as written passes them
# too, one with its Steiner point moved off passes the orientation check and says what it
# cannot verify, and an exact .node with one digit of a Steiner coordinate changed fails.
# usage: round_cli.sh TETREC SURFACE WORKDIR
set -u
tetrec=$1
in=$2
work=$3
mkdir -p "$work"
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

# --keep-steiner: the Steiner point stays on its edge (by default it is moved inside as a
# double, where a changed digit leaves a valid mesh)
"$tetrec" mesh "$in" -o "$work/exact.node" --keep-steiner --exact --stats "$work/exact.json" 2>"$work/mesh.log" ||
  say "mesh --exact exited $?: $(cat "$work/mesh.log")"
head -1 "$work/exact.node" | grep -q '^# tetrec exact rationals' || say "no exact header"
grep -q '[0-9]/[0-9]' "$work/exact.node" || say "no num/den coordinate in the exact .node"
grep -q '"rounding_repairs"' "$work/exact.json" || say "no rounding_repairs in the stats"

for m in exact.node exact.ele; do
  "$tetrec" check "$in" "$work/$m" 2>"$work/check.log" ||
    say "check $m exited $?: $(cat "$work/check.log")"
  for w in 'Steiner points read exactly' 'conforms exactly' 'volume equals'; do
    grep -q "$w" "$work/check.log" || say "check $m does not say '$w': $(cat "$work/check.log")"
  done
done

"$tetrec" mesh "$in" -o "$work/double.node" --keep-steiner 2>"$work/mesh.log" || say "mesh exited $?"
grep -q '/' "$work/double.node" && say "num/den in a double .node"
"$tetrec" check "$in" "$work/double.node" 2>"$work/check.log" ||
  say "check double.node exited $?: $(cat "$work/check.log")"
# Schoenhardt's point, at its nearest doubles, is still exactly where it conforms: check
# verifies the doubles exactly as written
grep -q 'Steiner points as written, exactly' "$work/check.log" ||
  say "check of doubles that conform does not verify them exactly: $(cat "$work/check.log")"
# moved off by 1e-10 it no longer conforms exactly: check says what it cannot verify
awk 'BEGIN { CONVFMT = "%.17g" } NR == 1 { n = $1 } NR == n + 1 { $2 = $2 + 1e-10 } { print }' "$work/double.node" \
  >"$work/moved.node"
cp "$work/double.ele" "$work/moved.ele"
cmp -s "$work/double.node" "$work/moved.node" && say "moving the point changed nothing"
"$tetrec" check "$in" "$work/moved.node" 2>"$work/check.log" ||
  say "check moved.node exited $?: $(cat "$work/check.log")"
grep -q 'cannot be verified' "$work/check.log" ||
  say "check of rounded Steiner points does not say what it skips: $(cat "$work/check.log")"

# change the last digit of the numerator of the first rational coordinate of the last point
awk 'NR == FNR { n = FNR; next }
     FNR == n && !done { for (i = 2; i <= 4; i++) if (!done && index($i, "/")) {
         split($i, q, "/"); d = substr(q[1], length(q[1]), 1);
         $i = substr(q[1], 1, length(q[1]) - 1) ((d + 1) % 10) "/" q[2]; done = 1 } }
     { print }' "$work/exact.node" "$work/exact.node" >"$work/bad.node"
cp "$work/exact.ele" "$work/bad.ele"
cp "$work/exact.face" "$work/bad.face"
cmp -s "$work/exact.node" "$work/bad.node" && say "tampering changed nothing"
"$tetrec" check "$in" "$work/bad.node" 2>"$work/check.log"
rc=$?
[ $rc -eq 9 ] || say "check of a tampered exact .node exited $rc, expected 9 (TR_ERR_INVALID_MESH)"
exit $fail
