#!/usr/bin/env python3
"""CLI side of the malformed-input table: each file gives the documented exit code
(= tr_status) and its message on stderr. Also checks the CLI conventions: --help
documents the exit codes, --version, usage errors, default output names, --stats."""
import json
import os
import shutil
import sys
import tempfile

from clitest import Cli

tetrec, data, table = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
cli = Cli(tetrec)
run, expect = cli.run, cli.expect


n = 0
for line in open(table):
    line = line.rstrip("\n")
    if not line or line.startswith("#"):
        continue
    f, status, code, msg, cmd = line.split("|")
    rc, _, err = run(cmd.split() + [os.path.join(data, "bad", f)])
    expect(rc == int(code), f"{f}: exit {rc}, expected {code} ({err.strip()})")
    expect(msg in err, f"{f}: stderr lacks '{msg}': {err.strip()}")
    if int(code) != 0:
        expect(status in err, f"{f}: stderr lacks the status name {status}")
    n += 1
expect(n >= 20, f"only {n} cases")

rc, out, _ = run(["--help"])
expect(rc == 0 and "exit status" in out and "7 self-intersecting" in out, "--help documents exit codes")
rc, out, _ = run(["--version"])
expect(rc == 0 and out.startswith("tetrec "), "--version")
rc, _, err = run(["frobnicate", "x.off"])
expect(rc == 1 and "unknown command" in err, f"unknown command -> 1: {rc} {err}")
rc, _, err = run(["mesh"])
expect(rc == 1, "missing file -> usage error 1")
rc, _, err = run(["mesh", "--bogus", "x.off"])
expect(rc == 1 and "unknown option" in err, "unknown option -> 1")
rc, _, err = run(["mesh", "/nonexistent/x.off"])
expect(rc == 2 and "cannot open" in err, f"missing file -> I/O error 2: {rc} {err}")
rc, _, err = run(["mesh", "x.xyz"])
expect(rc == 1 and "unknown file extension" in err, f"unknown extension -> 1: {rc}")

with tempfile.TemporaryDirectory() as d:
    src = os.path.join(data, "tet.off")
    shutil.copy(src, os.path.join(d, "t.off"))
    rc, _, err = run(["mesh", "-q", "t.off", "-o", "m.mesh"], cwd=d)
    if rc == 11:  # the pipeline is not wired in this build
        expect("not implemented" in err, f"mesh -> 11 names what is missing: {err}")
    else:
        expect(rc == 0, f"mesh of a tetrahedron: {rc} {err}")
        rc, _, err = run(["check", "t.off", "m.mesh"], cwd=d)
        expect(rc == 0, f"check of the meshed tetrahedron: {rc} {err}")
    rc, _, err = run(["mesh", "--check-only", "--stats", "s.json", "t.off"], cwd=d)
    expect(rc == 0, f"--check-only: {rc} {err}")
    st = json.load(open(os.path.join(d, "s.json")))
    expect(st["surface_nodes"] == 4 and st["surface_facets"] == 4, f"stats json {st}")
    # --stats writes also when the run fails: its value forgotten (`--stats IN OUT`), the
    # JSON went over the surface IN; a mesh-like name, or the input itself, is refused
    before = open(os.path.join(d, "t.off"), "rb").read()
    rc, _, err = run(["mesh", "--stats", "t.off", "out.mesh"], cwd=d)
    expect(rc == 1 and "--stats OUT.json IN" in err, f"--stats with a surface name -> 1: {rc} {err}")
    os.symlink("t.off", os.path.join(d, "link.json"))
    rc, _, err = run(["mesh", "--stats", "link.json", "t.off"], cwd=d)
    expect(rc == 1 and "names the input file" in err, f"--stats naming the input -> 1: {rc} {err}")
    expect(open(os.path.join(d, "t.off"), "rb").read() == before, "the input is left as it was")
    rc, _, err = run(["delaunay", "-q", "t.off"], cwd=d)
    expect(rc == 0 and err == "", f"delaunay -q: {rc} {err}")
    for ext in (".node", ".ele", ".face"):
        expect(os.path.exists(os.path.join(d, "t.1" + ext)), "default output t.1" + ext)
    rc, _, err = run(["check", "t.off", "t.1.node"], cwd=d)
    expect(rc == 0, f"check of the Delaunay mesh of a tetrahedron: {rc} {err}")
    rc, _, err = run(["delaunay", "-q", "t.off", "-o", "a.mesh"], cwd=d)
    rc2, _, _ = run(["delaunay", "-q", "t.off", "-o", "b.mesh"], cwd=d)
    expect(rc == 0 and rc2 == 0 and open(os.path.join(d, "a.mesh")).read() == open(os.path.join(d, "b.mesh")).read(),
           "same input, same output byte for byte")
    rc, _, err = run(["convert", os.path.join(data, "forms.obj"), "c.off"], cwd=d)
    expect(rc == 0, f"convert obj -> off: {rc} {err}")
    rc, _, err = run(["mesh", "--check-only", "c.off"], cwd=d)
    expect(rc == 0, f"converted surface valid: {rc} {err}")
    # a tet flipped in the mesh file must be reported by check
    lines = open(os.path.join(d, "a.mesh")).read().split("\n")
    i = lines.index("Tetrahedra") + 2
    v = lines[i].split()
    v[0], v[1] = v[1], v[0]
    lines[i] = " ".join(v)
    open(os.path.join(d, "bad.mesh"), "w").write("\n".join(lines))
    rc, _, err = run(["check", "t.off", "bad.mesh"], cwd=d)
    expect(rc == 9, f"check of an inverted tet -> 9: {rc} {err}")
    # an input point on no triangle: kept when it lies in the domain, and when it lies
    # outside (where no tet can hold it) the mesh says so instead of dropping it quietly
    for name, where, n_out in (("in.off", "0.25 0.25 0.25", 5), ("out.off", "2 2 2", 4)):
        open(os.path.join(d, name), "w").write(
            "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + where + "\n"
            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
        rc, _, err = run(["mesh", name, "-o", name + ".mesh"], cwd=d)
        warned = "1 input point on no triangle lies outside the domain" in err
        expect(rc == 0 and warned == (n_out == 4), f"{name}: isolated point at {where}: {rc} {err}")
        expect(f"mesh: {n_out} vertices" in err or f".mesh: {n_out} vertices" in err,
               f"{name}: {n_out} vertices expected: {err}")
        rc, _, err = run(["check", name, name + ".mesh"], cwd=d)
        expect(rc == 0, f"{name}: check: {rc} {err}")

cli.finish()
