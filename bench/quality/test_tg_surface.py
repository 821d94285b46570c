#!/usr/bin/env python3
"""Checks of tg_surface.py on hand-made TetGen outputs (run by hand: python3 THIS_FILE).

Input: the unit square split along 0-2 into two triangles, with corner 3 lifted by h
(h = 0: exactly coplanar; h = 2^-60: not coplanar, though no double dihedral angle sees
it). Each case writes a .face (and the .node, input points first, then Steiner points)
and checks the printed "E N M P"; the last cases give the square as one quad.
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def run(tmp, h, steiner, faces, quad=False):
    off = os.path.join(tmp, "in.off")
    with open(off, "w") as f:
        f.write("OFF\n4 %d 0\n0 0 0\n1 0 0\n1 1 0\n0 1 %r\n%s\n"
                % (1 if quad else 2, h, "4 0 1 2 3" if quad else "3 0 1 2\n3 0 2 3"))
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, h)] + steiner
    stem = os.path.join(tmp, "in.1")
    with open(stem + ".node", "w") as f:
        f.write("%d 3 0 0\n" % len(pts))
        for i, p in enumerate(pts):
            f.write("%d %r %r %r\n" % (i, *p))
    with open(stem + ".face", "w") as f:
        f.write("%d 1\n" % len(faces))
        for i, t in enumerate(faces):
            f.write("%d %d %d %d -1\n" % (i, *t))
    out = subprocess.run([sys.executable, os.path.join(HERE, "tg_surface.py"), off, stem],
                         capture_output=True, text=True, check=True).stdout
    return tuple(int(x) for x in out.split())


def main():
    tiny = 2.0 ** -60
    cases = [
        # the input's own triangles: every edge kept
        ("input triangles", 0.0, [], [(0, 1, 2), (0, 2, 3)], (5, 0, 0, 0)),
        # the other diagonal (TetGen merged the two into one facet): 0-2 dropped
        ("coplanar, flipped", 0.0, [], [(0, 1, 3), (1, 2, 3)], (5, 1, 0, 0)),
        ("non-coplanar, flipped", tiny, [], [(0, 1, 3), (1, 2, 3)], (5, 1, 1, 0)),
        # 0-1 split at a Steiner point on it (and 1-2 at two): kept as chains
        ("Steiner points on edges", 0.0, [(0.5, 0, 0), (1, 0.25, 0), (1, 0.75, 0)],
         [(0, 4, 2), (4, 1, 5), (4, 5, 2), (5, 6, 2), (0, 2, 3)], (5, 0, 0, 0)),
        # the diagonal 0-2 through a Steiner point at its midpoint: kept; through a point
        # off it (by far more than the tolerance): dropped (between coplanar faces)
        ("Steiner point on the diagonal", 0.0, [(0.5, 0.5, 0)],
         [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)], (5, 0, 0, 0)),
        ("Steiner point off the diagonal", 0.0, [(0.5, 0.5 + 1e-6, 0)],
         [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)], (5, 1, 0, 0)),
        # a border edge (one input face) dropped counts as not between coplanar faces
        ("border edge dropped", 0.0, [(0.5, 1e-6, 0)],
         [(0, 4, 2), (4, 1, 2), (0, 2, 3)], (5, 1, 1, 0)),
        # the square as one quad: its 4 sides kept either way; lifted, it is a
        # non-planar polygon, whichever diagonal TetGen took
        ("flat quad", 0.0, [], [(0, 1, 3), (1, 2, 3)], (4, 0, 0, 0), True),
        ("non-planar quad", tiny, [], [(0, 1, 2), (0, 2, 3)], (4, 0, 0, 1), True),
    ]
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, h, steiner, faces, want, *quad in cases:
            got = run(tmp, h, steiner, faces, bool(quad))
            ok = got == want
            bad += not ok
            print("%s: %s (got %s, want %s)" % ("ok" if ok else "FAIL", name, got, want))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
