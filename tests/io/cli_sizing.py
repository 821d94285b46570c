#!/usr/bin/env python3
"""The size field on the command line (--sizing / -m FILE, a TetGen .mtr): a graded cube
meshes, validates and is the same byte for byte on 1 and 2 threads; every kind of bad .mtr
gives its exit code (= tr_status) and a message naming the file and line."""
import os
import sys
import tempfile

from clitest import Cli

tetrec = os.path.abspath(sys.argv[1])
cli = Cli(tetrec)
run, expect = cli.run, cli.expect

CUBE = """OFF
8 12 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7
"""
SUMS = [0, 1, 2, 1, 1, 2, 3, 2]  # x + y + z of each corner


with tempfile.TemporaryDirectory() as d:
    open(os.path.join(d, "cube.off"), "w").write(CUBE)
    good = "# a TetGen .mtr: count, values per point\n8 1\n" + "".join(
        "%g  # corner %d\n" % (0.04 + 0.1 * s, i) for i, s in enumerate(SUMS))
    open(os.path.join(d, "cube.mtr"), "w").write(good)
    outs = []
    for th, opt in (("1", "--sizing"), ("2", "-m")):
        rc, _, err = run(["mesh", "-q", "cube.off", opt, "cube.mtr", "--quality", "1.414",
                          "--threads", th, "-o", "c%s.mesh" % th], d)
        expect(rc == 0, f"graded cube on {th} threads: exit {rc}: {err}")
        rc, out, err = run(["check", "cube.off", "c%s.mesh" % th], d)
        expect(rc == 0 and "valid" in out + err, f"check of the graded cube: {rc} {out} {err}")
        outs.append(open(os.path.join(d, "c%s.mesh" % th), "rb").read())
    expect(outs[0] == outs[1], "the graded cube differs between 1 and 2 threads")
    rc, _, err = run(["mesh", "cube.off", "-o", "u.mesh"], d)
    ntets_plain = os.path.getsize(os.path.join(d, "u.mesh"))
    expect(len(outs[0]) > 10 * ntets_plain, "the size field refined nothing")

    bad = [
        ("count.mtr", "7 1\n" + "0.1\n" * 7, 4, "count.mtr:1:", "7 points"),
        ("negative.mtr", "8 1\n" + "0.1\n" * 4 + "-0.2\n" + "0.1\n" * 3, 4, "negative.mtr:6:",
         "size -0.2 of point 4"),
        ("nan.mtr", "8 1\n" + "0.1\n" * 2 + "nan\n" + "0.1\n" * 5, 4, "nan.mtr:4:", "not a finite"),
        ("word.mtr", "8 1\n" + "0.1\n" * 2 + "abc\n" + "0.1\n" * 5, 3, "word.mtr:4:", ""),
        ("short.mtr", "8 1\n" + "0.1\n" * 5, 3, "short.mtr", "end of file"),
        ("trailing.mtr", "8 1\n" + "0.1\n" * 8 + "0.1\n", 3, "trailing.mtr:10:", "after the 8"),
        ("aniso.mtr", "8 6\n" + "0.1 0 0 0.1 0 0.1\n" * 8, 11, "aniso.mtr:1:", "6 values per point"),
        ("header.mtr", "8 1 5\n" + "0.1\n" * 8, 3, "header.mtr:1:", "first line"),
        ("empty.mtr", "", 3, "empty.mtr", ""),
        ("huge.mtr", "4000000000 1\n0.1\n", 4, "huge.mtr:1:", "4000000000 points"),
    ]
    for name, text, code, where, msg in bad:
        open(os.path.join(d, name), "w").write(text)
        rc, _, err = run(["mesh", "cube.off", "--sizing", name, "-o", "x.mesh"], d)
        expect(rc == code, f"{name}: exit {rc}, expected {code}: {err.strip()}")
        expect(where in err and msg in err, f"{name}: stderr lacks '{where}' / '{msg}': {err.strip()}")
    rc, _, err = run(["mesh", "cube.off", "--sizing", "missing.mtr"], d)
    expect(rc == 2 and "missing.mtr" in err, f"missing .mtr: {rc} {err}")
    rc, _, err = run(["mesh", "cube.off", "-m"], d)
    expect(rc == 1 and "needs an argument" in err, f"-m without FILE: {rc} {err}")
    rc, _, err = run(["delaunay", "cube.off", "-m", "cube.mtr"], d)
    expect(rc == 1 and "does not apply" in err, f"-m with delaunay: {rc} {err}")
    # a field asking for far more points than the budget: refused up front
    open(os.path.join(d, "tiny.mtr"), "w").write("8 1\n" + "1e-4\n" * 8)
    rc, _, err = run(["mesh", "cube.off", "--sizing", "tiny.mtr", "-o", "x.mesh"], d)
    expect(rc == 8 and "size field" in err, f"a field over the budget: {rc} {err}")

cli.finish("cli_sizing")
