#!/usr/bin/env python3
"""One closed sphere surface, written as OFF: the nearly cospherical input of issue 19.

Usage: gen_sphere.py OUT.off KIND [SUB=7]
KIND icosphere: an icosphere (20 * 4^SUB triangles; SUB=7: 327,680) with every vertex on
the unit sphere, rounded to doubles: nearly every insphere test among close vertices
needs the exact stages. KIND bumpy: the same mesh with each vertex moved radially by a
smooth bump of amplitude 5% (r = 1 + 0.05 sin(5x) sin(4y) cos(3z)): as many triangles,
no longer cospherical. The surface stays star-shaped about the centre, so it is closed
and free of self-intersections. Deterministic: the same arguments give the same file."""
import math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_cavities import icosphere  # noqa: E402  (the shared icosphere builder)

def main():
    if len(sys.argv) < 3 or sys.argv[2] not in ("icosphere", "bumpy"):
        sys.exit("usage: gen_sphere.py OUT.off icosphere|bumpy [SUB=7]")
    out, kind = sys.argv[1], sys.argv[2]
    sub = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    v, f = icosphere(sub)
    if kind == "bumpy":
        v = [tuple(c * (1 + 0.05 * math.sin(5 * p[0]) * math.sin(4 * p[1]) * math.cos(3 * p[2]))
                   for c in p) for p in v]
    with open(out, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        o.writelines("%.17g %.17g %.17g\n" % p for p in v)
        o.writelines("3 %d %d %d\n" % t for t in f)

main()
