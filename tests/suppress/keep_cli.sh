#!/bin/sh
# `tetrec mesh --keep-surface` / `-Y` from the command line: on Schoenhardt's prism it
# writes a mesh with no Steiner point on the surface (stats rows) that `tetrec check`
# verifies exactly as written (the interior point is a double); on a fin attached inside a box (a Steiner point on the fin's edge, which has
# tets of one region on both sides) it exits 11 naming the point and the edge, and writes
# nothing; --keep-surface with --keep-steiner is a usage error.
# usage: keep_cli.sh TETREC GEN_HARD SCHOENHARDT.off WORKDIR
set -u
tetrec=$1
gen=$2
schoen=$3
work=$4
mkdir -p "$work"
rm -f "$work"/*.node "$work"/*.ele "$work"/*.face "$work"/*.json
"$gen" "$work" >/dev/null || { echo "FAIL: gen_hard"; exit 1; }
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

for opt in --keep-surface -Y; do
  "$tetrec" mesh "$schoen" -o "$work/s.node" $opt --stats "$work/s.json" 2>"$work/s.log" ||
    say "$opt: mesh exited $?: $(tail -1 "$work/s.log")"
  grep -q '"steiner_on_edges": 0,' "$work/s.json" && grep -q '"steiner_on_facets": 0,' "$work/s.json" ||
    say "$opt: Steiner points left on the surface: $(grep steiner "$work/s.json")"
  grep -q '"steiner_relocated": 1' "$work/s.json" || say "$opt: the point was not moved inside"
  # the interior point is a plain double: check verifies the mesh exactly as written
  "$tetrec" check "$schoen" "$work/s.node" -v 2>"$work/s.check" ||
    say "$opt: check exited $?: $(tail -1 "$work/s.check")"
  grep -q "conforms exactly to the surface, volume equals the enclosed volume" "$work/s.check" ||
    say "$opt: check did not verify the doubles exactly: $(cat "$work/s.check")"
done

"$tetrec" mesh "$work/fin_attached_inside.off" -o "$work/fin.node" -Y 2>"$work/fin.log"
rc=$?
[ $rc -eq 11 ] || say "fin: exit $rc, want 11 (TR_ERR_UNSUPPORTED)"
grep -q -- "--keep-surface: Steiner point .* on input edge (" "$work/fin.log" ||
  say "fin: the message does not name the point and the edge: $(cat "$work/fin.log")"
[ -e "$work/fin.node" ] && say "fin: a mesh was written"

"$tetrec" mesh "$schoen" -o "$work/u.node" -Y --keep-steiner 2>"$work/u.log"
rc=$?
[ $rc -eq 1 ] || say "-Y --keep-steiner: exit $rc, want 1"
exit $fail
