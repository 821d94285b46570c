#!/bin/sh
# `tetrec mesh --exact` then `tetrec check` on the multi-region, crack and cavity cases:
# check must verify conformity and the volume of the domain (not the plain triangle sum,
# which counts internal facets and cracks wrongly: regression, it reported "total volume
# differs" on tetrec's own valid meshes), and on the ulp-moved Chazelle polyhedron, whose
# exact Steiner points have up to 20,615 bits. usage: check_cli.sh TETREC GEN_HARD WORKDIR
set -u
tetrec=$1
gen=$2
work=$3
mkdir -p "$work"
"$gen" "$work" >/dev/null || { echo "FAIL: gen_hard"; exit 1; }
fail=0
for c in two_regions_matching two_regions_inverted crack_inside_box fin_attached_inside \
         nested_cavity cavity_and_crack chazelle_g4_ulps; do
  "$tetrec" mesh "$work/$c.off" -o "$work/$c.node" --exact 2>"$work/$c.mesh.log" ||
    { echo "FAIL: $c: mesh exited $?: $(tail -1 "$work/$c.mesh.log")"; fail=1; continue; }
  "$tetrec" check "$work/$c.off" "$work/$c.node" 2>"$work/$c.check.log" ||
    { echo "FAIL: $c: check exited $?: $(tail -1 "$work/$c.check.log")"; fail=1; continue; }
  grep -q "volume equals the enclosed volume" "$work/$c.check.log" ||
    { echo "FAIL: $c: check did not verify the volume: $(tail -1 "$work/$c.check.log")"; fail=1; }
done
exit $fail
