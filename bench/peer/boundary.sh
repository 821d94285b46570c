#!/usr/bin/env bash
# Compares the boundary of a tet mesh with the input surface (bench/peer/run.sh, for
# tetrec --keep-surface and tetgen -Y): boundary faces are the faces of exactly one tet.
# usage: bench/peer/boundary.sh IN.node IN.face OUT.node OUT.ele
# IN.* is the input as `tetrec convert MODEL IN.node` writes it. Vertices are matched by
# their coordinates printed as %.17g, so both programs' numbering is irrelevant.
# Prints: exact missing extra steiner_boundary steiner_interior
#   exact             yes when every input triangle is a face of the mesh and every
#                     boundary face is an input triangle, else NO
#   missing / extra   input triangles that are no face / boundary faces that are no input
#                     triangle
#   steiner_boundary  vertices that are not input vertices, on some boundary face
#   steiner_interior  the other vertices that are not input vertices (points on internal
#                     facets count here)
set -euo pipefail
awk '
function key(a, b, c,   t) {
  if (a > b) { t = a; a = b; b = t }
  if (b > c) { t = b; b = c; c = t }
  if (a > b) { t = a; a = b; b = t }
  return a " " b " " c
}
FNR == 1 { f++; head = 0 }
{ sub(/#.*/, "") }
NF == 0 { next }
!head { head = 1; next }
f == 1 {
  # duplicate input points (both programs merge them) take the id of the first
  k = sprintf("%.17g %.17g %.17g", $2 + 0, $3 + 0, $4 + 0)
  if (!(k in inp)) inp[k] = $1
  same[$1] = inp[k]
  next
}
f == 2 { tri[++nt] = same[$2] SUBSEP same[$3] SUBSEP same[$4]; next }
f == 3 {
  k = sprintf("%.17g %.17g %.17g", $2 + 0, $3 + 0, $4 + 0)
  if (k in inp) in2out[inp[k]] = $1; else steiner[$1] = 1
  next
}
f == 4 {
  v[0] = $2; v[1] = $3; v[2] = $4; v[3] = $5
  for (i = 0; i < 4; i++) face[key(v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4])]++
}
END {
  for (i = 1; i <= nt; i++) {
    split(tri[i], t, SUBSEP)
    if (!(t[1] in in2out) || !(t[2] in in2out) || !(t[3] in in2out)) { missing++; continue }
    k = key(in2out[t[1]], in2out[t[2]], in2out[t[3]])
    if (k in face) isinput[k] = 1; else missing++
  }
  for (k in face) {
    if (face[k] != 1) continue
    if (!(k in isinput)) extra++
    split(k, t, " ")
    for (j = 1; j <= 3; j++) if (t[j] in steiner) onb[t[j]] = 1
  }
  for (s in steiner) { ns++; if (s in onb) nb++ }
  printf "%s %d %d %d %d\n", missing + extra == 0 ? "yes" : "NO", missing, extra, nb, ns - nb
}' "$@"
