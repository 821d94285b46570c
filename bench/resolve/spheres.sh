#!/usr/bin/env bash
# Issue 49's benchmark case: the union of gcherchi/InteractiveAndRobustMeshBooleans'
# data/spheres/ (703 disjoint spheres, 320 triangles each), each scaled by 1.5 about the
# centre of its bounding box so that 1,303 pairs overlap; 224,960 triangles. Builds the
# soup (OFF) from the repository at a pinned commit, then runs `tetrec mesh --resolve`
# on it: CPU (user + system) and peak memory of the whole command against the issue's
# bound of 30 s of CPU, the tets, and `tetrec check --resolve` of the exact output.
# With FTETWILD= it also runs fTetWild on the same soup (one thread, -e 1e-3) and
# prints the ratio (the issue's bound: tetrec at most 0.25x).
#
# usage: bench/resolve/spheres.sh BUILD [WORK]
#   BUILD    a tetrec build directory (BUILD/src/cli/tetrec)
#   WORK     where the clone, the soup and the outputs go (default BUILD/bench-spheres)
#   TETREC_CORPUS_MIRROR=path   clone from path/OWNER+NAME/repo instead of GitHub
#   FTETWILD=path               an fTetWild binary (bench/peer/build_ftetwild.sh)
#   CHECK=0                     skip the exact check (it takes about 10x the meshing)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:?usage: spheres.sh BUILD [WORK]}" && pwd)
WORK=${2:-$BUILD/bench-spheres}
TETREC=$BUILD/src/cli/tetrec
URL=https://github.com/gcherchi/InteractiveAndRobustMeshBooleans
SHA=7bd6c2697695f555f9a15d7e154e084d841316f0
[ -x "$TETREC" ] || { echo "no $TETREC: build first" >&2; exit 1; }
command -v python3 >/dev/null || { echo "needs python3" >&2; exit 1; }
mkdir -p "$WORK"
repo=$WORK/irmb
if [ ! -d "$repo/.git" ]; then
  if [ -n "${TETREC_CORPUS_MIRROR:-}" ]; then
    git clone -q --no-checkout "$TETREC_CORPUS_MIRROR/gcherchi+InteractiveAndRobustMeshBooleans/repo" "$repo"
  else
    git clone -q --no-checkout --filter=blob:none "$URL" "$repo"
  fi
fi
git -C "$repo" checkout -q "$SHA" -- data/spheres
soup=$WORK/spheres_x1.5.off
python3 - "$repo/data/spheres" "$soup" <<'PY'
import os, sys
src, out = sys.argv[1], sys.argv[2]
files = sorted((f for f in os.listdir(src) if f.endswith('.obj')), key=lambda f: int(f[:-4]))
pts, tris = [], []
for f in files:
    v, t = [], []
    for line in open(os.path.join(src, f)):
        w = line.split()
        if w and w[0] == 'v':
            v.append([float(x) for x in w[1:4]])
        elif w and w[0] == 'f':
            t.append([int(x.split('/')[0]) - 1 for x in w[1:4]])
    lo = [min(p[k] for p in v) for k in range(3)]
    hi = [max(p[k] for p in v) for k in range(3)]
    c = [(lo[k] + hi[k]) / 2 for k in range(3)]
    base = len(pts)
    pts += [[c[k] + 1.5 * (p[k] - c[k]) for k in range(3)] for p in v]
    tris += [[base + i for i in x] for x in t]
with open(out, 'w') as o:
    o.write('OFF\n%d %d 0\n' % (len(pts), len(tris)))
    o.writelines('%.17g %.17g %.17g\n' % tuple(p) for p in pts)
    o.writelines('3 %d %d %d\n' % tuple(x) for x in tris)
print('%d spheres, %d points, %d triangles' % (len(files), len(pts), len(tris)))
PY
cpu() { awk '{ printf "%.2f", $1 + $2 }' "$1"; }
/usr/bin/time -f "%U %S %M" -o "$WORK/tetrec.time" "$TETREC" mesh "$soup" --resolve -q \
  -o "$WORK/tetrec.node" --stats "$WORK/tetrec.json"
t_cpu=$(cpu "$WORK/tetrec.time")
t_mb=$(awk '{ printf "%.0f", $3 / 1024 }' "$WORK/tetrec.time")
tets=$(head -1 "$WORK/tetrec.ele" | awk '{ print $1 }')
echo "tetrec mesh --resolve: $t_cpu s CPU (issue 49: under 30 s), $t_mb MB peak, $tets tets"
if [ "${CHECK:-1}" != 0 ]; then
  "$TETREC" mesh "$soup" --resolve --exact -q -o "$WORK/exact.node"
  /usr/bin/time -f "%U %S %M" -o "$WORK/check.time" \
    "$TETREC" check --resolve "$soup" "$WORK/exact.node" -q && v=valid || v=INVALID
  echo "tetrec check --resolve of the --exact output: $v ($(cpu "$WORK/check.time") s CPU)"
fi
if [ -n "${FTETWILD:-}" ]; then
  /usr/bin/time -f "%U %S %M" -o "$WORK/ftetwild.time" "$FTETWILD" -i "$soup" \
    -o "$WORK/ftetwild.mesh" -e 1e-3 --max-threads 1 > "$WORK/ftetwild.log" 2>&1 &&
    f=ok || f="exit $?"
  f_cpu=$(cpu "$WORK/ftetwild.time")
  echo "fTetWild -e 1e-3: $f, $f_cpu s CPU; tetrec/fTetWild CPU: $(awk -v a="$t_cpu" -v b="$f_cpu" \
    'BEGIN { printf "%.3fx", b > 0 ? a / b : 0 }') (issue 49: at most 0.25x)"
fi
