#!/bin/sh
# Surfaces whose edge recovery once piled Steiner points within an ulp of each other (an
# input edge grazing a sliver, split at its midpoint again and again): the default double
# output must now be written (exit 0, no Steiner point left unrepairable) and pass
# `tetrec check`, and the exact output must conform exactly.
# usage: double_output_cli.sh TETREC WORKDIR SURFACE...
set -u
tetrec=$1
work=$2
shift 2
mkdir -p "$work"
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

for in in "$@"; do
  name=$(basename "$in" .off)
  rm -f "$work/$name".* # no stale outputs
  "$tetrec" mesh "$in" -o "$work/$name.d.node" 2>"$work/$name.mesh.log" ||
    say "$name: double output exited $?: $(tail -2 "$work/$name.mesh.log")"
  grep -q '/' "$work/$name.d.node" 2>/dev/null && say "$name: num/den in a double .node"
  "$tetrec" check "$in" "$work/$name.d.node" 2>"$work/$name.check.log" ||
    say "$name: check of the double mesh exited $?: $(cat "$work/$name.check.log")"
  "$tetrec" mesh "$in" -o "$work/$name.x.node" --exact 2>"$work/$name.exact.log" ||
    say "$name: exact output exited $?: $(tail -2 "$work/$name.exact.log")"
  "$tetrec" check "$in" "$work/$name.x.node" 2>"$work/$name.check.log" ||
    say "$name: check of the exact mesh exited $?: $(cat "$work/$name.check.log")"
  grep -q 'conforms exactly' "$work/$name.check.log" ||
    say "$name: check does not say the exact mesh conforms exactly"
done
exit $fail
