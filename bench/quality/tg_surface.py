#!/usr/bin/env python3
"""Does a TetGen output hold the input surface's edges? (bench/quality, issue 17)

usage: tg_surface.py MODEL.off STEM [-v]
  MODEL.off  the input surface given to TetGen
  STEM       TetGen's output stem (STEM.node and STEM.face: its boundary faces)
  -v         also list the dropped edges (input vertex ids, 0-based, and their class)
prints one line "E N M P": E input edges (the sides of the OFF faces; the diagonals that
a mesher adds to split a polygon are its own choice and are not counted), N of them not
a chain of edges of TetGen's boundary faces, M of those N not between two exactly
coplanar faces (an edge of one face or of three or more counts there too), and P the
polygons (faces of more than 3 sides) whose vertices are not exactly coplanar. Such a
polygon has no surface of its own: tetrec keeps the diagonals it splits it with as
constraints (src/io/polytri.c), TetGen takes it as one facet and picks its own, so a
model with P > 0 is no like-for-like comparison even when N = 0.

TetGen -p merges adjacent facets whose dihedral angle is within its tolerance of flat
(facet_separate_ang_tol, 179.9 degrees by default) and then no longer keeps the edge
between them; where the faces are not exactly coplanar its surface is not the input
surface. This is a report on a peer's output, written with rounded decimals: the
Steiner points on an input edge are found as boundary-face vertices within 1e-9 of the
input's bounding-box diagonal from the edge's line. The coplanarity of the two faces
at a dropped edge is decided exactly (rational orient3d of the input doubles).
Exit status 0 with the line printed, 1 if the files cannot be read or do not match.
"""
import math
import sys
from fractions import Fraction

REL_TOL = 1e-9


def fail(msg):
    print("tg_surface: " + msg, file=sys.stderr)
    sys.exit(1)


def tokens(path):
    """Lines of whitespace-separated words, '#' comments and blank lines dropped."""
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                yield words


def read_off(path):
    """Vertices (tuples of floats) and faces (lists of vertex ids) of an OFF file."""
    lines = tokens(path)
    head = next(lines)
    if not head[0].upper().endswith("OFF"):
        fail("%s: not an OFF file" % path)
    counts = head[1:] if len(head) > 1 else next(lines)
    nv, nf = int(counts[0]), int(counts[1])
    pts = []
    for _ in range(nv):
        w = next(lines)
        pts.append((float(w[0]), float(w[1]), float(w[2])))
    faces = []
    for _ in range(nf):
        w = next(lines)
        k = int(w[0])
        faces.append([int(x) for x in w[1:1 + k]])
    return pts, faces


def read_tetgen(stem):
    """TetGen's points (index base removed) and boundary faces."""
    lines = tokens(stem + ".node")
    n = int(next(lines)[0])
    pts = []
    base = None
    for _ in range(n):
        w = next(lines)
        if base is None:
            base = int(w[0])
        pts.append((float(w[1]), float(w[2]), float(w[3])))
    lines = tokens(stem + ".face")
    nf = int(next(lines)[0])
    faces = []
    for _ in range(nf):
        w = next(lines)
        faces.append((int(w[1]) - base, int(w[2]) - base, int(w[3]) - base))
    return pts, faces


def exact_coords(pts):
    """The points as integer triples: every double is an integer over a power of two, so
    one common power of two makes all of them integers (exact, whatever the range)."""
    shift = max(x.as_integer_ratio()[1] for p in pts for x in p).bit_length() - 1
    return [tuple(int(Fraction(x) * (1 << shift)) for x in p) for p in pts]


def orient(a, b, c, d):
    """Exact sign of the orientation determinant of four integer points."""
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def collinear(a, b, c):
    """Exactly: do three integer points lie on one line?"""
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    return (u[1] * v[2] == u[2] * v[1] and u[2] * v[0] == u[0] * v[2]
            and u[0] * v[1] == u[1] * v[0])


def coplanar_faces(pts, f, g):
    """Exactly: do all vertices of faces f and g (pts: integer points) lie on one plane?"""
    vs = list(dict.fromkeys(f + g))
    a = vs[0]
    b = next((v for v in vs if pts[v] != pts[a]), None)
    if b is None:
        return True
    c = next((v for v in vs if not collinear(pts[a], pts[b], pts[v])), None)
    if c is None:
        return True
    return all(orient(pts[a], pts[b], pts[c], pts[v]) == 0 for v in vs)


def main():
    args = [a for a in sys.argv[1:] if a != "-v"]
    verbose = len(args) != len(sys.argv) - 1
    if len(args) != 2:
        fail("usage: tg_surface.py MODEL.off STEM [-v]")
    try:
        ip, ifaces = read_off(args[0])
        tp, tfaces = read_tetgen(args[1])
    except (OSError, ValueError, IndexError, StopIteration) as e:
        fail("cannot read the input or TetGen's output: %s" % e)

    edge_faces = {}
    for fi, f in enumerate(ifaces):
        for j in range(len(f)):
            a, b = f[j], f[(j + 1) % len(f)]
            if a != b:
                edge_faces.setdefault((min(a, b), max(a, b)), []).append(fi)
    lo = [min(p[i] for p in ip) for i in range(3)]
    hi = [max(p[i] for p in ip) for i in range(3)]
    tol = REL_TOL * math.sqrt(sum((hi[i] - lo[i]) ** 2 for i in range(3)))
    # TetGen renumbers its points when it drops unused or duplicate input points; it
    # prints 17 significant digits, so an input point reads back as the same double
    where = {}
    for i, p in enumerate(tp):
        where.setdefault(p, i)
    image = {}
    for v in {v for e in edge_faces for v in e}:
        if ip[v] not in where:
            fail("input point %d (%r) is not among TetGen's points" % (v, ip[v]))
        image[v] = where[ip[v]]
    is_input = [False] * len(tp)
    for i in image.values():
        is_input[i] = True

    adj = [set() for _ in range(len(tp))]
    for f in tfaces:
        for j in range(3):
            a, b = f[j], f[(j + 1) % 3]
            adj[a].add(b)
            adj[b].add(a)

    def chain(a, b):
        """Is a-b a chain of boundary-face edges through Steiner points on it? The walk
        goes from a to the nearest Steiner neighbour further along the edge."""
        if b in adj[a]:
            return True
        pa, pb = tp[a], tp[b]
        u = [pb[i] - pa[i] for i in range(3)]
        uu = sum(x * x for x in u)
        cur, tcur = a, 0.0
        while True:
            best, tbest = None, 1.0
            for q in adj[cur]:
                if is_input[q]:
                    continue
                w = [tp[q][i] - pa[i] for i in range(3)]
                t = sum(u[i] * w[i] for i in range(3)) / uu
                if not tcur < t < tbest:
                    continue
                if math.sqrt(sum((w[i] - t * u[i]) ** 2 for i in range(3))) < tol:
                    best, tbest = q, t
            if best is None:
                return False
            if b in adj[best]:
                return True
            cur, tcur = best, tbest

    xp = None
    nonplanar = 0
    for f in ifaces:
        if len(set(f)) > 3:
            if xp is None:
                xp = exact_coords(ip)
            nonplanar += not coplanar_faces(xp, f, [])
    dropped = noncoplanar = 0
    for (a, b), fs in sorted(edge_faces.items()):
        if image[a] == image[b] or chain(image[a], image[b]):
            continue
        dropped += 1
        if xp is None:
            xp = exact_coords(ip)
        flat = len(fs) == 2 and coplanar_faces(xp, ifaces[fs[0]], ifaces[fs[1]])
        if not flat:
            noncoplanar += 1
        if verbose:
            print("dropped %d %d %s" % (a, b, "coplanar" if flat else "non-coplanar"))
    print(len(edge_faces), dropped, noncoplanar, nonplanar)


if __name__ == "__main__":
    main()
