#!/bin/sh
# `tetrec mesh --keep-surface` / `-Y` from the command line: on Schoenhardt's prism it
# writes a mesh with no Steiner point on the surface (stats rows) that `tetrec check`
# verifies exactly as written (the interior point is a double); a fin attached inside a box
# (an internal facet, tets of one region on both sides) is meshed with its surface as
# given; with --recovery paper (a Steiner point on the fin's edge, whose star meets the
# fin) it exits 11 naming the point and the edge, and writes nothing; --keep-surface with
# --keep-steiner is a usage error. With --quality, refinement adds interior points only:
# Schoenhardt's prism under -Y -q 1.414 -a 0.05 gets points, none on its surface, and check
# verifies the result; --subface-quality with -Y is a usage error (it splits the boundary
# triangles -Y keeps).
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

# the fin: its edges come back by flips alone, so the surface is kept as given
"$tetrec" mesh "$work/fin_attached_inside.off" -o "$work/fin.node" -Y --stats "$work/fin.json" \
  2>"$work/fin.log" || say "fin: mesh exited $?: $(tail -1 "$work/fin.log")"
grep -q '"steiner_on_edges": 0,' "$work/fin.json" && grep -q '"steiner_on_facets": 0,' "$work/fin.json" ||
  say "fin: Steiner points left on the surface: $(grep steiner "$work/fin.json")"
"$tetrec" check "$work/fin_attached_inside.off" "$work/fin.node" -v 2>"$work/fin.check" ||
  say "fin: check exited $?: $(tail -1 "$work/fin.check")"
grep -q "conforms exactly to the surface, volume equals the enclosed volume" "$work/fin.check" ||
  say "fin: check did not verify the mesh: $(cat "$work/fin.check")"

# the paper's algorithm has no general flips: it puts a point on the fin's edge (7, 100),
# whose star meets the fin (an internal facet); refused, naming the point and the edge
"$tetrec" mesh "$work/fin_attached_inside.off" -o "$work/finp.node" -Y --recovery paper \
  2>"$work/finp.log"
rc=$?
[ $rc -eq 11 ] || say "fin, paper: exit $rc, want 11 (TR_ERR_UNSUPPORTED)"
grep -q -- "--keep-surface: Steiner point .* on input edge (" "$work/finp.log" ||
  say "fin, paper: the message does not name the point and the edge: $(cat "$work/finp.log")"
[ -e "$work/finp.node" ] && say "fin, paper: a mesh was written"

"$tetrec" mesh "$schoen" -o "$work/u.node" -Y --keep-steiner 2>"$work/u.log"
rc=$?
[ $rc -eq 1 ] || say "-Y --keep-steiner: exit $rc, want 1"
# quality refinement under -Y: interior points only, and the volume bound still holds
"$tetrec" mesh "$schoen" -o "$work/q.node" -Y --quality 1.414 -a 0.05 --stats "$work/q.json" \
  2>"$work/q.log" || say "-Y -q: mesh exited $?: $(tail -1 "$work/q.log")"
grep -q '"points_added_for_quality": 0,' "$work/q.json" && say "-Y -q: refinement added no point"
grep -q '"steiner_on_edges": 0,' "$work/q.json" && grep -q '"steiner_on_facets": 0,' "$work/q.json" ||
  say "-Y -q: Steiner points on the surface: $(grep steiner "$work/q.json")"
grep -q "0 on edges, 0 on facets" "$work/q.log" ||
  say "-Y -q: refinement put points on the surface: $(grep refinement "$work/q.log")"
"$tetrec" check "$schoen" "$work/q.node" -v 2>"$work/q.check" ||
  say "-Y -q: check exited $?: $(tail -1 "$work/q.check")"
grep -q "conforms exactly to the surface, volume equals the enclosed volume" "$work/q.check" ||
  say "-Y -q: check did not verify the mesh: $(cat "$work/q.check")"
"$tetrec" mesh "$schoen" -o "$work/qs.node" -Y --quality 1.414 --subface-quality 2 2>"$work/qs.log"
rc=$?
[ $rc -eq 1 ] || say "-Y --subface-quality: exit $rc, want 1"
grep -q -- "--subface-quality splits boundary triangles, which --keep-surface keeps" "$work/qs.log" ||
  say "-Y --subface-quality: message: $(cat "$work/qs.log")"
exit $fail
