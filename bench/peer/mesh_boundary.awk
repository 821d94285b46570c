# The boundary of an ASCII Medit tet mesh (e.g. fTetWild's .mesh, which has no Triangles):
# the faces of one tet only, outward for a positive tet, as OFF with every vertex of the
# mesh and its coordinates copied as written, so that `tetrec check BOUNDARY.off MESH`
# judges the tets against their own boundary exactly (every vertex is an input point).
# usage: awk -f bench/peer/mesh_boundary.awk MESH >BOUNDARY.off
function key(a, b, c,   t) {
  if (a > b) { t = a; a = b; b = t }
  if (b > c) { t = b; b = c; c = t }
  if (a > b) { t = a; a = b; b = t }
  return a " " b " " c
}
function face(a, b, c,   k) { k = key(a, b, c); n[k]++; f[k] = (a - 1) " " (b - 1) " " (c - 1) }
$1 == "Vertices" {
  getline nv
  for (i = 0; i < nv; i++) { getline; v[i] = $1 " " $2 " " $3 }
  next
}
$1 == "Tetrahedra" {
  getline nt
  for (i = 0; i < nt; i++) {
    getline
    face($2, $3, $4); face($1, $4, $3); face($1, $2, $4); face($1, $3, $2)
  }
  next
}
END {
  nf = 0
  for (k in n) if (n[k] == 1) nf++
  print "OFF"
  print nv + 0, nf, 0
  for (i = 0; i < nv; i++) print v[i]
  for (k in n) if (n[k] == 1) print 3, f[k]
}
