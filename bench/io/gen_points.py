#!/usr/bin/env python3
"""Uniform random points in the unit cube for the output benchmark (bench/io/run.sh).

usage: gen_points.py N OUT.node OUT.bin [SEED]

OUT.node: TetGen .node, 1-based, every coordinate as %.17g (reads back to the same
double, and the size of file tetrec itself writes: ~68 bytes a point).
OUT.bin: the same doubles for bench/delaunay/bench_cgal (a uint32 count, then x y z per
point, little-endian), so that CGAL triangulates exactly the points tetrec reads.
The same N and SEED give the same files on any machine (Python's Mersenne Twister)."""
import random
import struct
import sys


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    n = int(sys.argv[1])
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 48)
    with open(sys.argv[2], "w") as node, open(sys.argv[3], "wb") as binf:
        node.write("%d 3 0 0\n" % n)
        binf.write(struct.pack("<I", n))
        chunk, raw = [], []
        for i in range(n):
            x, y, z = rng.random(), rng.random(), rng.random()
            chunk.append("%d %.17g %.17g %.17g\n" % (i + 1, x, y, z))
            raw.append(struct.pack("<3d", x, y, z))
            if len(chunk) == 65536:
                node.write("".join(chunk))
                binf.write(b"".join(raw))
                chunk, raw = [], []
        node.write("".join(chunk))
        binf.write(b"".join(raw))


if __name__ == "__main__":
    main()
