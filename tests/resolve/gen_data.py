#!/usr/bin/env python3
"""Writes the resolve test corpus, tests/data/resolve_*.off (issue 49 step 5): small soups
whose solids have known volumes. Each shape is a closed, outward surface with its own
vertices (the soup's parts are its connected components, which tests/cgal/resolve_volume
unites with CGAL's Nef polyhedra):

  cubes2     two unit cubes, the second moved by (1/2, 1/2, 1/2): 6V = 45/4
  cubes3     the same and a third at (1/4, 3/4, -1/2): 6V = 267/16 (inclusion-exclusion)
  dupshell   a unit cube given twice: 6V = 6
  coplanar   a unit cube, a box [1/2, 3/2] x [0, 1] x [0, 1] overlapping it on three
             coplanar faces, and a unit cube at (0, 0, 1) touching both along a face:
             6V = 15
  spheres    an icosphere (level 2) of radius 1, one (level 1) of radius 0.8 at (0.9, 0, 0)
             overlapping it, and one (level 1) of radius 0.3 at (-0.3, 0.2, 0.1) nested
             inside the first: volume by CGAL only

and each again as NAME_rot (every point turned by the rational rotation Rz(3/5, 4/5)
Rx(5/13, 12/13) about the origin, rounded to the nearest doubles: the crossings are
rational points, no doubles) and NAME_ulp (every coordinate of the parts after the first
moved up by one ulp). Usage: gen_data.py tests/data"""
import math
import os
import sys
from fractions import Fraction as F


def cube(lo, hi):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    p = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    # outward triangles of the box with corners p[i], bit 0 = x, bit 1 = y, bit 2 = z
    t = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
         (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    return p, t


def icosphere(level, r, c):
    g = (1 + math.sqrt(5)) / 2
    v = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g),
         (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    v = [tuple(x / math.sqrt(1 + g * g) for x in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        mid = {}

        def m(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                p = [(v[a][i] + v[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                mid[k] = len(v) - 1
            return mid[k]
        g2 = []
        for a, b, cc in f:
            ab, bc, ca = m(a, b), m(b, cc), m(cc, a)
            g2 += [(a, ab, ca), (b, bc, ab), (cc, ca, bc), (ab, bc, ca)]
        f = g2
    return [tuple(c[i] + r * p[i] for i in range(3)) for p in v], f


def vol6(p, t):
    s = F(0)
    for a, b, c in t:
        A, B, C = [tuple(F(x) for x in p[i]) for i in (a, b, c)]
        s += (A[0] * (B[1] * C[2] - B[2] * C[1]) - A[1] * (B[0] * C[2] - B[2] * C[0]) +
              A[2] * (B[0] * C[1] - B[1] * C[0]))
    return s


ROT = None


def rot():
    cz, sz, cx, sx = F(3, 5), F(4, 5), F(5, 13), F(12, 13)
    rz = [[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]]
    rx = [[1, 0, 0], [0, cx, -sx], [0, sx, cx]]
    return [[sum(rz[i][k] * rx[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def write(path, parts):
    pts, tris = [], []
    for p, t in parts:
        assert vol6(p, t) > 0, path
        b = len(pts)
        pts += p
        tris += [tuple(i + b for i in x) for x in t]
    with open(path, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        for p in pts:
            o.write("%r %r %r\n" % tuple(float(x) for x in p))
        for t in tris:
            o.write("3 %d %d %d\n" % t)


def main():
    out = sys.argv[1]
    h = 0.5
    shapes = {
        "cubes2": [cube((0, 0, 0), (1, 1, 1)), cube((h, h, h), (1 + h, 1 + h, 1 + h))],
        "cubes3": [cube((0, 0, 0), (1, 1, 1)), cube((h, h, h), (1 + h, 1 + h, 1 + h)),
                   cube((0.25, 0.75, -0.5), (1.25, 1.75, 0.5))],
        "dupshell": [cube((0, 0, 0), (1, 1, 1)), cube((0, 0, 0), (1, 1, 1))],
        "coplanar": [cube((0, 0, 0), (1, 1, 1)), cube((h, 0, 0), (1 + h, 1, 1)),
                     cube((0, 0, 1), (1, 1, 2))],
        "spheres": [icosphere(2, 1.0, (0, 0, 0)), icosphere(1, 0.8, (0.9, 0, 0)),
                    icosphere(1, 0.3, (-0.3, 0.2, 0.1))],
    }
    R = rot()
    for name, parts in shapes.items():
        write(os.path.join(out, "resolve_%s.off" % name), parts)
        rp = []
        for p, t in parts:
            q = [tuple(float(sum(R[i][k] * F(x[k]) for k in range(3))) for i in range(3))
                 for x in p]
            rp.append((q, t))
        write(os.path.join(out, "resolve_%s_rot.off" % name), rp)
        up = [parts[0]] + [([tuple(math.nextafter(float(x), math.inf) for x in pt)
                             for pt in p], t) for p, t in parts[1:]]
        write(os.path.join(out, "resolve_%s_ulp.off" % name), up)


main()
