#!/bin/sh
# tetrec mesh --recovery MODE: every mode meshes the inputs into an exact mesh that
# `tetrec check` finds conforming exactly; --recovery paper never reports a facet
# recovered by cavity retriangulation; an unknown or missing mode is a usage error that
# names the choices.
# usage: recovery_cli.sh TETREC WORKDIR SURFACE...
set -u
tetrec=$1
work=$2
shift 2
mkdir -p "$work"
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }
for in in "$@"; do
  b=$(basename "$in" .off)
  for mode in default paper no-facet-flips; do
    out="$work/$b.$mode"
    rm -f "$out.node" "$out.ele" "$out.face" "$out.json"
    "$tetrec" mesh "$in" -o "$out.node" --exact --recovery "$mode" --stats "$out.json" -q \
      2>"$out.log" || { say "$b --recovery $mode: exit $?: $(tail -2 "$out.log")"; continue; }
    "$tetrec" check "$in" "$out.node" >"$out.chk" 2>&1 ||
      say "$b --recovery $mode: check exited $?: $(cat "$out.chk")"
    grep -q 'conforms exactly' "$out.chk" ||
      say "$b --recovery $mode: check does not say it conforms exactly: $(cat "$out.chk")"
    grep -q '"facets_recovered_by_cavity": ' "$out.json" ||
      say "$b --recovery $mode: --stats has no facets_recovered_by_cavity"
    if [ "$mode" = paper ]; then
      grep -Eq '"facets_recovered_by_cavity": 0,?$' "$out.json" ||
        say "$b --recovery paper: facets recovered by the cavity: $(grep cavity "$out.json")"
    fi
    echo "$b --recovery $mode: $(grep -E 'points_added|recovered' "$out.json" | tr -d ' \n')"
  done
done
for bad in bogus PAPER ""; do
  "$tetrec" mesh "$1" -o "$work/bad.mesh" --recovery "$bad" 2>"$work/bad.log"
  rc=$?
  [ $rc -eq 1 ] && grep -q "recovery needs 'default', 'paper' or 'no-facet-flips'" "$work/bad.log" ||
    say "--recovery '$bad': exit $rc, want 1 with a message: $(cat "$work/bad.log")"
done
exit $fail
