#!/usr/bin/env bash
# tetrec mesh --surface-tolerance and tetrec check --surface-tolerance on a box of bumped
# fans (test_simplify write): the mesh checks within the tolerance, not within a tenth of
# the bumps; the stats report the bound; bad values are usage errors (exit 1).
set -euo pipefail
tetrec=$1 gen=$2
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
"$gen" write 12 1e-4 "$w/box.off"
"$tetrec" mesh "$w/box.off" -o "$w/out.mesh" --stats "$w/s.json" --quality 1.414 \
  --surface-tolerance 1e-3 -q
grep -q '"surface_collapses": [1-9]' "$w/s.json" || { echo "no collapse"; exit 1; }
grep -q '"surface_tolerance_bound": [0-9]' "$w/s.json" || { echo "no bound in stats"; exit 1; }
"$tetrec" check "$w/box.off" "$w/out.mesh" --surface-tolerance 1e-3 2>"$w/check.log" ||
  { cat "$w/check.log"; echo "check failed within the tolerance"; exit 1; }
grep -q 'proven' "$w/check.log" || { cat "$w/check.log"; exit 1; }
rc=0
"$tetrec" check "$w/box.off" "$w/out.mesh" --surface-tolerance 1e-6 -q 2>/dev/null || rc=$?
[ "$rc" = 9 ] || { echo "check within 1e-6 exited $rc, not 9"; exit 1; }
# without the tolerance the exact conformity check fails: the surface moved
rc=0
"$tetrec" check "$w/box.off" "$w/out.mesh" -q 2>/dev/null || rc=$?
[ "$rc" != 0 ] || { echo "exact check passed on a moved surface"; exit 1; }
for bad in 0 -1 nan inf 1e-3x ''; do
  rc=0
  "$tetrec" mesh "$w/box.off" -o "$w/bad.mesh" --surface-tolerance "$bad" -q 2>/dev/null || rc=$?
  [ "$rc" = 1 ] || { echo "--surface-tolerance '$bad' exited $rc, not 1"; exit 1; }
done
echo ok
