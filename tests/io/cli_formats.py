#!/usr/bin/env python3
"""CLI of issue 18: output names checked before any work, unwritable outputs found before
meshing, --stats written on failure, --exact with a TetGen base name, per-command help,
.msh/.vtk outputs that `tetrec check` validates, check-surface's full listing and files,
and the deviation of written doubles against an independent exact computation."""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
from fractions import Fraction as F

from clitest import Cli

tetrec, data = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
cli = Cli(tetrec)
run, expect = cli.run, cli.expect


def read_off(path):
    body = [l for l in open(path).read().split("\n") if l.strip() and not l.strip().startswith("#")]
    nv, nf = map(int, body[1].split()[:2])
    pts = [[float(t) for t in l.split()[:3]] for l in body[2:2 + nv]]
    tris = [[int(t) for t in l.split()[1:4]] for l in body[2 + nv:2 + nv + nf]]
    return pts, tris


def write_off(path, pts, tris):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        for p in pts:
            f.write("%r %r %r\n" % tuple(p))
        for t in tris:
            f.write("3 %d %d %d\n" % tuple(t))


def read_node(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    n = int(rows[0][0])
    # num/den exactly; a decimal is a %.17g double: its value is the double's, not the decimal's
    return [[F(c) if "/" in c else F(float(c)) for c in r[1:4]] for r in rows[1:1 + n]]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def constraint_dist2(q, p, pts, tris):
    """Squared distance of p from the edge line or plane of the first input triangle that
    holds the exact point q (barycentric signs in exact fractions)."""
    for t in tris:
        a, b, c = (list(map(F, pts[i])) for i in t)
        n = cross(sub(b, a), sub(c, a))
        if dot(n, sub(q, a)) != 0:
            continue
        # signed areas of the sub-triangles along n: all >= 0 iff q is in the closed triangle
        w = [dot(n, cross(sub(b, q), sub(c, q))), dot(n, cross(sub(c, q), sub(a, q))),
             dot(n, cross(sub(a, q), sub(b, q)))]
        if min(w) < 0:
            continue
        pf = list(map(F, p))
        zeros = [i for i in range(3) if w[i] == 0]
        if len(zeros) == 1:  # on the edge opposite that corner
            e = [x for i, x in enumerate((a, b, c)) if i != zeros[0]]
            u, v = sub(e[1], e[0]), sub(pf, e[0])
            return dot(cross(u, v), cross(u, v)) / dot(u, u)
        return dot(n, sub(pf, a)) ** 2 / dot(n, n)
    return None


with tempfile.TemporaryDirectory() as d:
    shutil.copy(os.path.join(data, "tet.off"), os.path.join(d, "t.off"))
    shutil.copy(os.path.join(data, "two_cubes.off"), os.path.join(d, "c.off"))

    # an unknown output extension: usage error before any work, nothing written
    before = sorted(os.listdir(d))
    rc, _, err = run(["mesh", "c.off", "-o", "out.vtkx", "--stats", "s.json"], d)
    expect(rc == 1 and "does not write '.vtkx'" in err, f"unknown extension -> 1: {rc} {err}")
    expect("valid" not in err, f"the input was read before the name was refused: {err}")
    st = json.load(open(os.path.join(d, "s.json")))
    expect(st["status"] == "TR_ERR_USAGE" and ".vtkx" in st["message"], f"stats on usage error {st}")
    os.remove(os.path.join(d, "s.json"))
    expect(sorted(os.listdir(d)) == before, f"files left behind: {sorted(os.listdir(d))}")
    rc, _, err = run(["convert", "c.off", "c.xyz"], d)
    expect(rc == 1 and "does not write '.xyz'" in err, f"convert to .xyz -> 1: {rc} {err}")
    expect(not os.path.exists(os.path.join(d, "c.xyz.node")), "convert wrote TetGen files")
    rc, _, err = run(["mesh", "c.off", "-o", "m.stl"], d)
    expect(rc == 1 and "does not write '.stl' files of a tetrahedral mesh" in err,
           f"mesh to .stl -> 1: {rc} {err}")

    # unwritable outputs are found before meshing; --stats says why
    rc, _, err = run(["mesh", "c.off", "-o", "nodir/x.mesh", "--stats", "s.json"], d)
    expect(rc == 2 and "nodir/x.mesh: cannot create" in err, f"unwritable -o -> 2: {rc} {err}")
    expect("tetrahedra" not in err, f"meshed before finding the output unwritable: {err}")
    st = json.load(open(os.path.join(d, "s.json")))
    expect(st["status"] == "TR_ERR_IO" and "nodir/x.mesh" in st["message"]
           and st["volume_elements"] == 0, f"stats of the I/O failure {st}")
    rc, _, err = run(["mesh", "c.off", "-o", "x.mesh", "--stats", "nodir/s.json"], d)
    expect(rc == 2 and "nodir/s.json: cannot create" in err, f"unwritable --stats -> 2: {rc} {err}")
    expect(not os.path.exists(os.path.join(d, "x.mesh")), "meshed with an unwritable --stats")

    # --stats on a failing input carries the status and the message
    rc, _, err = run(["mesh", os.path.join(data, "bad", "selfint.off"), "-o", "y.mesh",
                      "--stats", "f.json"], d)
    st = json.load(open(os.path.join(d, "f.json")))
    expect(rc == 7 and st["status"] == "TR_ERR_SELF_INTERSECT" and "intersect" in st["message"],
           f"stats of a failed run: {rc} {st}")

    # --exact with a base name without extension, and refused where it cannot go; on
    # Schoenhardt's prism, which cannot be meshed without a Steiner point (the header
    # marks a file that has one)
    shutil.copy(os.path.join(data, "schoenhardt.off"), os.path.join(d, "s.off"))
    rc, _, err = run(["mesh", "-q", "s.off", "-o", "ex", "--exact"], d)
    expect(rc == 0 and open(os.path.join(d, "ex.node")).readline().startswith("# tetrec exact"),
           f"--exact to a base name: {rc} {err}")
    rc, _, err = run(["check", "s.off", "ex.node"], d)
    expect(rc == 0 and "conform" in err, f"check of the exact base-name output: {rc} {err}")
    rc, _, err = run(["mesh", "c.off", "-o", "ex.vtu", "--exact"], d)
    expect(rc == 1 and "--exact" in err, f"--exact to .vtu -> 1: {rc} {err}")

    # one help per command, listing only its options
    helps = {}
    for c in ("mesh", "delaunay", "check", "check-surface", "convert"):
        rc, out, _ = run([c, "--help"], d)
        expect(rc == 0 and out.startswith("usage: tetrec " + c), f"{c} --help: {out[:60]}")
        helps[c] = out
    expect(len(set(helps.values())) == 5, "every command has its own help")
    expect("--round-budget" in helps["mesh"] and "--round-budget" not in helps["check"],
           "help lists the command's options only")
    rc, _, err = run(["check", "--exact", "c.off", "ex.node"], d)
    expect(rc == 1 and "does not apply" in err, f"option of another command -> 1: {rc} {err}")
    rc, _, err = run(["mesh", "c.off", "--msh-version", "3"], d)
    expect(rc == 1 and "4.1, 2.2, 4.1b or 2.2b" in err, f"--msh-version 3 -> 1: {rc} {err}")

    # .msh (both versions) and .vtk outputs; `check` validates the .msh
    for args, out in ((["-o", "m41.msh"], "m41.msh"), (["-o", "m22.msh", "--msh-version", "2.2"],
                                                       "m22.msh")):
        rc, _, err = run(["mesh", "-q", "c.off"] + args, d)
        expect(rc == 0, f"mesh -> {out}: {rc} {err}")
        rc, _, err = run(["check", "c.off", out], d)
        expect(rc == 0 and "valid" in err, f"check {out}: {rc} {err}")
    head = open(os.path.join(d, "m22.msh")).read(40)
    expect(head.startswith("$MeshFormat\n2.2 0 8"), f"2.2 header: {head!r}")
    rc, _, err = run(["convert", "m41.msh", "back.off"], d)
    expect(rc == 0, f"convert .msh -> .off: {rc} {err}")
    rc, _, err = run(["mesh", "-q", "c.off", "-o", "m.vtk"], d)
    expect(rc == 0 and open(os.path.join(d, "m.vtk")).readline().startswith("# vtk DataFile"),
           f"mesh -> .vtk: {rc} {err}")

    # check-surface: every pair, every open edge, the non-planar polygon; files for viewers
    pts, tris = read_off(os.path.join(data, "tet.off"))
    k = len(pts)
    # a copy shifted into the first through one corner (3 pairs with it), and an open fan
    pts2 = pts + [[x + 0.25 for x in p] for p in pts] + [[5, 5, 5], [6, 5, 5], [6, 6, 5.5], [5, 6, 5]]
    tris2 = tris + [[a + k for a in t] for t in tris]
    write_off(os.path.join(d, "bad.off"), pts2, tris2)
    with open(os.path.join(d, "bad.off"), "a") as f:
        f.write("4 %d %d %d %d\n" % (2 * k, 2 * k + 1, 2 * k + 2, 2 * k + 3))
    lines = open(os.path.join(d, "bad.off")).read().split("\n")
    lines[1] = "%d %d 0" % (len(pts2), len(tris2) + 1)
    open(os.path.join(d, "bad.off"), "w").write("\n".join(lines))
    rc, out, err = run(["check-surface", "bad.off", "-o", "bad.vtk"], d)
    pairs = [l for l in out.split("\n") if l.startswith("self-intersection")]
    opens = [l for l in out.split("\n") if l.startswith("open edge")]
    nonplanar = [l for l in out.split("\n") if l.startswith("non-planar polygon")]
    expect(rc == 7, f"check-surface of intersecting shells -> 7: {rc} {err}")
    expect(len(pairs) >= 2, f"every intersecting pair, not only the first: {pairs}")
    expect(len(opens) == 4, f"the 4 boundary edges of the open quad: {opens}")
    expect(len(nonplanar) == 1 and "input face 8" in nonplanar[0], f"the lifted quad: {nonplanar}")
    vtk = open(os.path.join(d, "bad.vtk")).read()
    ntri_out = 2 * len(pairs) + 2
    expect(("CELLS %d" % (ntri_out + 4)) in vtk, f"bad.vtk: {ntri_out} triangles + 4 edges")
    rc, out2, _ = run(["check-surface", "bad.off", "-o", "bad.msh"], d)
    expect(rc == 7 and out2 == out and os.path.getsize(os.path.join(d, "bad.msh")) > 0,
           "check-surface -o .msh: the same listing")
    rc, _, err = run(["check-surface", "bad.off", "-o", "bad.mesh"], d)
    expect(rc == 1, f"check-surface -o .mesh -> 1: {rc} {err}")
    rc, out, err = run(["check-surface", os.path.join(data, "bad", "dup_tri.off")], d)
    dups = [l for l in out.split("\n") if l.startswith("duplicate triangle")]
    expect(rc == 4 and len(dups) == 1 and "non-manifold" not in out,
           f"a duplicate triangle is listed as such, not as non-manifold edges: {rc} {out}")
    rc, out, err = run(["check-surface", "c.off"], d)
    expect(rc == 0 and out == "" and "no defect" in err, f"check-surface of a valid surface: {rc} {err}")
    expect("corner under 10 degrees" not in err, f"a cube has no thin triangle: {err}")
    # a prism whose two ends are triangles with a 5-degree corner: valid, and said to be thin
    write_off(os.path.join(d, "thin.off"),
              [(0, 0, 0), (10, 0, 0), (10, 0.875, 0), (0, 0, 2), (10, 0, 2), (10, 0.875, 2)],
              [(0, 2, 1), (3, 4, 5), (0, 1, 4), (0, 4, 3), (1, 2, 5), (1, 5, 4), (2, 0, 3),
               (2, 3, 5)])
    rc, out, err = run(["check-surface", "thin.off"], d)
    expect(rc == 0 and out == "" and "no defect" in err and
           "2 triangles have a corner under 10 degrees" in err and "has 5 degrees at vertex 0" in err,
           f"check-surface notes the thin triangles of a valid surface: {rc} {err}")
    rc, _, err = run(["mesh", "-q", "bad.off", "--check-only"], d)
    rc, _, err = run(["convert", "bad.off", "conv.off"], d)
    expect("warning" in err and "not planar" in err, f"non-planar polygon warning: {err}")

    # many non-planar polygons: the first 10 are listed, one line says how many more; -v
    # lists every one (a box whose top is a 5 x 5 grid of quads, inner grid points lifted
    # by 1/1024 in a checkerboard: 23 top quads are bent, the two corner quads whose one
    # inner corner is not lifted are flat, and so are the sides)
    n = 5
    top = {}
    pts = [[0, 0, 0], [n, 0, 0], [n, n, 0], [0, n, 0]]
    for j in range(n + 1):
        for i in range(n + 1):
            inner = 0 < i < n and 0 < j < n
            top[i, j] = len(pts)
            pts.append([i, j, n + ((i + j) % 2 == 0 and inner) / 1024.0])
    faces = [[3, 2, 1, 0]]
    for j in range(n):
        for i in range(n):
            faces.append([top[i, j], top[i + 1, j], top[i + 1, j + 1], top[i, j + 1]])
    faces.append([0, 1] + [top[i, 0] for i in range(n, -1, -1)])
    faces.append([1, 2] + [top[n, j] for j in range(n, -1, -1)])
    faces.append([2, 3] + [top[i, n] for i in range(n + 1)])
    faces.append([3, 0] + [top[0, j] for j in range(n + 1)])
    with open(os.path.join(d, "bent.off"), "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(faces)))
        f.writelines("%r %r %r\n" % tuple(map(float, q)) for q in pts)
        f.writelines("%d %s\n" % (len(q), " ".join(map(str, q))) for q in faces)
    rc, _, err = run(["mesh", "bent.off", "-o", "bent.node"], d)
    listed = [l for l in err.split("\n") if "is not planar" in l]
    more = [l for l in err.split("\n") if "more polygons are not planar" in l]
    expect(rc == 0 and len(listed) == 10 and len(more) == 1 and " 13 more " in more[0],
           f"23 bent quads: 10 listed and one line for the 13 more: {rc} {err}")
    rc, _, err = run(["mesh", "-v", "bent.off", "-o", "bent.node"], d)
    listed = [l for l in err.split("\n") if "is not planar" in l]
    expect(rc == 0 and len(listed) == 23 and "more polygons" not in err,
           f"-v lists all 23 bent quads: {rc} {len(listed)}")

    # deviation of written doubles, model translated by 2^40: stats against an exact oracle
    # (Schoenhardt's prism: it always needs a Steiner point; rotated: off every axis)
    pts, tris = read_off(os.path.join(data, "schoenhardt_rotated.off"))
    pts = [[x + 2.0 ** 40 for x in p] for p in pts]
    write_off(os.path.join(d, "far.off"), pts, tris)
    # --keep-steiner: the deviation is that of Steiner points left on the surface, which
    # the suppression stage would otherwise move inside (where any double is exact)
    rc, _, err = run(["mesh", "far.off", "-o", "far.node", "--stats", "far.json",
                      "--keep-steiner"], d)
    st = json.load(open(os.path.join(d, "far.json")))
    expect(rc == 0 and "warning" in err and "2^-40" in err, f"far model: warning: {rc} {err}")
    rc2, _, err2 = run(["mesh", "-q", "far.off", "-o", "farx.node", "--exact",
                        "--keep-steiner"], d)
    expect(rc2 == 0, f"far model --exact: {rc2} {err2}")
    dbl, exact = read_node(os.path.join(d, "far.node")), read_node(os.path.join(d, "farx.node"))
    expect(len(dbl) == len(exact), "the same vertices with and without --exact")
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    diag = math.sqrt(sum((hi[i] - lo[i]) ** 2 for i in range(3)))
    worst = 0.0
    for v in range(len(pts), min(len(dbl), len(exact))):
        d2 = constraint_dist2(exact[v], dbl[v], pts, tris)
        expect(d2 is not None, f"Steiner point {v} lies on no input triangle")
        worst = max(worst, math.sqrt(float(d2)) / diag) if d2 is not None else worst
    expect(worst > 2.0 ** -40 and abs(st["double_deviation"] - worst) <= 1e-12 * worst,
           f"double_deviation {st['double_deviation']!r}, exact oracle {worst!r}")
    # `check` on the rounded doubles: the distance from the surface, a lower bound of it
    rc, _, err = run(["check", "far.off", "far.node"], d)
    got = [l for l in err.split("\n") if "lie at most" in l]
    val = float(got[0].split("lie at most ")[1].split()[0]) if got else -1
    expect(rc == 0 and 2.0 ** -40 < val <= st["double_deviation"] * (1 + 1e-3) and "above 2^-40" in got[0],
           f"check reports the distance of the rounded Steiner points: {rc} {err}")
    # refined: interior points near the surface are no deviation; only the points on the
    # mesh boundary are measured (all were measured once: 0.087 of the diagonal here)
    rc, _, err = run(["mesh", "far.off", "-o", "farq.node", "--quality", "1.2", "--stats",
                      "farq.json"], d)
    st = json.load(open(os.path.join(d, "farq.json")))
    expect(rc == 0 and st["points_added_for_quality"] > 0, f"far model refined: {rc} {err}")
    rc, _, err = run(["check", "far.off", "farq.node"], d)
    got = [l for l in err.split("\n") if "lie at most" in l]
    val = float(got[0].split("lie at most ")[1].split()[0]) if got else -1
    expect(rc == 0 and 2.0 ** -40 < val <= st["double_deviation"] * (1 + 1e-3),
           f"check on a refined mesh measures the points on the surface only: {rc} {err}")
    rc, _, err = run(["mesh", "far.off", "-o", "far2.mesh", "--strict-doubles", "--stats", "s9.json",
                      "--keep-steiner"], d)
    st = json.load(open(os.path.join(d, "s9.json")))
    expect(rc == 9 and "--strict-doubles" in err and st["status"] == "TR_ERR_INVALID_MESH",
           f"--strict-doubles -> 9: {rc} {err}")
    expect(not os.path.exists(os.path.join(d, "far2.mesh")), "--strict-doubles wrote the mesh")
    rc, _, err = run(["mesh", "-q", "c.off", "-o", "near.mesh", "--strict-doubles"], d)
    expect(rc == 0, f"--strict-doubles on a model at the origin: {rc} {err}")

    # the progress line: every stage of the pipeline rewritten in place on stderr, ending
    # at 100% with a newline; without --progress and with stderr not a terminal, none
    # (bytes: text mode would turn the carriage returns into newlines)
    def run_bytes(args):
        p = subprocess.run([tetrec] + args, capture_output=True, cwd=d)
        return p.returncode, p.stderr.decode()
    rc, err = run_bytes(["mesh", "c.off", "-o", "p.mesh", "--progress"])
    line = err.split("\n")[1] if err.count("\n") > 1 else ""
    stages = [x.split()[1] for x in line.split("\r") if x.startswith("tetrec: ")]
    expect(rc == 0 and stages[:1] == ["validation"] and "delaunay" in stages and
           "rounding" in stages and line.endswith("100%"), f"--progress: {rc} {err!r}")
    rc, err = run_bytes(["mesh", "c.off", "-o", "p.mesh"])
    expect(rc == 0 and "\r" not in err, f"a progress line without a terminal: {err!r}")

cli.finish()
