#!/usr/bin/env python3
"""A sphere containing N^3 disjoint spherical cavities, written as OFF.

Usage: gen_cavities.py OUT.off [N=10] [SUB=2] [OUTER_SUB=4]
Each sphere is an icosphere (20 * 4^SUB triangles; SUB=2: 320) with vertices on the
sphere, rounded to doubles; the cavities sit on an N x N x N grid with spacing 1 and
radius 0.4, the outer sphere (OUTER_SUB) has radius 1.2 * (the grid's half diagonal).
The outer sphere faces outward, the cavities face into themselves (cavities, not
inclusions). Deterministic: the same arguments give the same file."""
import math, sys

def icosphere(sub):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(sub):
        mid = {}
        def m(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                p = [(v[a][i] + v[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                mid[k] = len(v) - 1
            return mid[k]
        g = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            g += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = g
    return v, f

def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    sub = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    osub = int(sys.argv[4]) if len(sys.argv) > 4 else 4
    sv, sf = icosphere(sub)
    ov, of = icosphere(osub)
    h = (n - 1) / 2
    R = 1.2 * (math.sqrt(3) * h + 0.4) + 0.5
    pts = [tuple(R * c for c in p) for p in ov]
    tris = list(of)
    for i in range(n):
        for j in range(n):
            for k in range(n):
                base = len(pts)
                c = (i - h, j - h, k - h)
                pts += [tuple(c[d] + 0.4 * p[d] for d in range(3)) for p in sv]
                tris += [(base + a, base + cc, base + b) for a, b, cc in sf]  # inward
    with open(out, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        o.writelines("%.17g %.17g %.17g\n" % p for p in pts)
        o.writelines("3 %d %d %d\n" % t for t in tris)

if __name__ == "__main__":
    main()
