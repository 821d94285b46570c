#!/usr/bin/env python3
"""`tetrec resolve IN -o OUT` on the command line: the two rotated cubes written as .off,
.stl and .mesh pass `check-surface` and `mesh` (and `check` against the written surface);
--internal says which triangles are internal; a soup whose rounding cycles exits 7 naming
the pair and writes nothing; missing -o, an unknown or volume-only format, an open input
and an inside-out one are errors naming what, with no file written.
Usage: cli_resolve_cmd.py TETREC tests/data"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
from clitest import Cli  # noqa: E402

cli = Cli(os.path.abspath(sys.argv[1]))
data = os.path.abspath(sys.argv[2])
run, expect = cli.run, cli.expect

with tempfile.TemporaryDirectory() as d:
    rot = os.path.join(data, "resolve_cubes3_rot.off")
    rc, _, err = run(["check-surface", rot], d)
    expect(rc == 7, f"the soup itself self-intersects: check-surface exit {rc}")
    for out in ("r.off", "r.stl", "r.mesh"):
        rc, _, err = run(["resolve", rot, "-o", out], d)
        expect(rc == 0 and os.path.exists(os.path.join(d, out)), f"resolve -o {out}: exit {rc}: {err}")
        expect("improper pairs" in err and "rounded to" in err and "no self-intersection" in err,
               f"resolve -o {out}: the report: {err}")
        if out == "r.stl":
            expect("floats (STL)" in err, f"STL rounds to floats: {err}")
        rc, _, err2 = run(["check-surface", out], d)
        # parts of the solid touching along an edge are the only thing check-surface may list
        touching = "edges of more than two triangles" in err
        expect(rc == 0 or (touching and rc == 6 and "0 self-intersecting pairs, 0 open edges" in err2),
               f"check-surface {out}: exit {rc}: {err2}")
        rc, _, err2 = run(["mesh", out, "-o", out + ".1.mesh", "-q"], d)
        expect(rc == 0, f"mesh {out}: exit {rc}: {err2}")
        rc, _, err2 = run(["check", out, out + ".1.mesh"], d)
        expect(rc == 0 and "conforms exactly" in err2, f"check {out}: exit {rc}: {err2}")
    # the same input, the same bytes
    run(["resolve", rot, "-o", "again.off"], d)
    expect(open(os.path.join(d, "r.off"), "rb").read() == open(os.path.join(d, "again.off"), "rb").read(),
           "two runs write different bytes")
    rc, _, err = run(["resolve", os.path.join(data, "resolve_cubes2.off"), "-o", "i.off", "--internal"], d)
    expect(rc == 0 and "the last 12 (triangles 36..47) are internal facets" in err,
           f"--internal: exit {rc}: {err}")
    # a cycling rounding: exit 7, the pair named, nothing written
    rc, _, err = run(["resolve", os.path.join(data, "resolve_grid_cycle.off"), "-o", "c.off"], d)
    expect(rc == 7 and "triangles" in err and "nothing written" in err
           and not os.path.exists(os.path.join(d, "c.off")), f"cycle: exit {rc}: {err}")
    rc, _, err = run(["resolve", os.path.join(data, "resolve_grid_cycle.off"), "-o", "c.off",
                      "--rounds", "0"], d)
    expect(rc == 1 and "--rounds" in err, f"--rounds 0: exit {rc}: {err}")
    # usage: no -o, a format tetrec does not write, a mesh-only one
    rc, _, err = run(["resolve", rot], d)
    expect(rc == 1 and "-o OUT" in err, f"no -o: exit {rc}: {err}")
    rc, _, err = run(["resolve", rot, "-o", "x.xyz"], d)
    expect(rc == 1 and "x.xyz" in err, f"bad format: exit {rc}: {err}")
    rc, _, err = run(["resolve", rot, "-o", "x.off", "--quality", "2"], d)
    expect(rc == 1 and "does not apply" in err, f"a mesh option: exit {rc}: {err}")
    # soups without a solid
    lines = [l.strip() for l in open(os.path.join(data, "resolve_cube.off"))
             if l.strip() and not l.startswith("#")]
    n, m, _ = map(int, lines[1].split())
    pts, tris = lines[2:2 + n], lines[2 + n:2 + n + m]
    with open(os.path.join(d, "open.off"), "w") as f:
        f.write(f"OFF\n{len(pts)} {len(tris) - 1} 0\n" + "\n".join(pts + tris[:-1]) + "\n")
    rc, _, err = run(["resolve", "open.off", "-o", "o.off"], d)
    expect(rc == 6 and "open.off" in err and not os.path.exists(os.path.join(d, "o.off")),
           f"open: exit {rc}: {err}")
    flipped = ["3 %s %s %s" % (t.split()[1], t.split()[3], t.split()[2]) for t in tris]
    with open(os.path.join(d, "inside_out.off"), "w") as f:
        f.write(f"OFF\n{len(pts)} {len(tris)} 0\n" + "\n".join(pts + flipped) + "\n")
    rc, _, err = run(["resolve", "inside_out.off", "-o", "o.off"], d)
    expect(rc == 4 and "inside out" in err and not os.path.exists(os.path.join(d, "o.off")),
           f"inside out: exit {rc}: {err}")
    rc, _, err = run(["resolve", "missing.off", "-o", "o.off"], d)
    expect(rc == 2, f"missing input: exit {rc}: {err}")
cli.finish("cli_resolve_cmd")
