#!/usr/bin/env python3
"""The parallel writers (issue 48) write what the serial writers wrote, byte for byte.

`tetrec delaunay` on 20,000 fixed points (about 130k tets: 32 blocks of tets, 5 of
vertices) in every output format, with --threads 1, 2 and 3: each file's SHA-256 must be
the one the writers of commit 5b99ad5 (before the block writers) gave. `tetrec convert`
of that mesh gives the same bytes for 1, 2 and 3 threads. --stats of `delaunay` reports
bytes_per_tet = peak_memory_bytes / volume_elements, and -v the three stage times.

usage: cli_parallel_bytes.py TETREC WORKDIR"""
import hashlib
import json
import os
import random
import subprocess
import sys

# (case, file extension): SHA-256 of the file commit 5b99ad5's `tetrec delaunay` wrote
GOLDEN = {
    ("mesh", "mesh"): "fa527406cfed7b6aa39074b22f729974ba5b82916a7e52cfa0a4647b49a516e6",
    ("vtu", "vtu"): "16b42c9fecc2c19763660e11412eb5aa6c7d7d29a1b2cbe934f74af9053a471e",
    ("vtu_binary", "vtu"): "4c556b4069d444cd09c3cc357b5a8a9452a22426a01653dcd7bbb26ec96cee47",
    ("vtk", "vtk"): "705b49f28f71a543e7d1d3d99e8f488f68d6570d2291c2469b47b5fcca96ff87",
    ("vtk_binary", "vtk"): "581d4519024e09c24d53f839d8977eb439537a10cf99cf8efeaf9981c30229a3",
    ("msh41", "msh"): "3cc1c1d43be43f7e24472225bfbe649308497ea0d5147008baa8471600a55fc2",
    ("msh41_binary", "msh"): "f45a7801105d49a2f053aa52c61d2acf39dc074df3f9e0b2225573cc8d7586cd",
    ("msh22", "msh"): "b9cbeb1911e9167fd75686201c60aff7524f33ce90abd5803496d0106f0203f3",
    ("msh22_binary", "msh"): "e1960ef52899892abdb1760da3084775019081b18a15ff24187077459722bd0c",
    ("meshb", "meshb"): "f6bbf249fa4c3782d979443a571ddea72c6c453fa7557189ecf9da999b9807ce",
    ("tetgen", "node"): "080e65ea40a618e85fa4d31614bb1a2212bc7f071f409b06d993cc7d90421aa5",
    ("tetgen", "ele"): "ba1001a1e255f9b7402e23cca6a41b142a0c02190faa71905092aadf71202c91",
    ("tetgen", "face"): "3aa2e501ce3e1047028c7a78cba76a0cea269c788a92c536d7016a925ec28a65",
}
CASES = [("mesh", "mesh", []), ("vtu", "vtu", []), ("vtu_binary", "vtu", ["--binary"]),
         ("vtk", "vtk", []), ("vtk_binary", "vtk", ["--binary"]), ("msh41", "msh", []),
         ("msh41_binary", "msh", ["--binary"]), ("msh22", "msh", ["--msh-version", "2.2"]),
         ("msh22_binary", "msh", ["--msh-version", "2.2b"]), ("meshb", "meshb", []),
         ("tetgen", "node", [])]

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def main():
    tetrec, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    points = os.path.join(work, "points.node")
    rng = random.Random(48)  # Mersenne Twister: the same doubles on every machine
    with open(points, "w") as f:
        f.write("20000 3 0 0\n")
        for i in range(20000):
            f.write("%d %.17g %.17g %.17g\n" % (i + 1, rng.random(), rng.random(), rng.random()))
    for name, ext, opt in CASES:
        for j in (1, 2, 3):
            base = os.path.join(work, "%s_%d" % (name, j))
            r = subprocess.run([tetrec, "delaunay", points, "-q", "-j", str(j),
                                "-o", base + "." + ext] + opt, capture_output=True, text=True)
            check(r.returncode == 0, "%s -j %d exited %d: %s" % (name, j, r.returncode, r.stderr))
            for e in (("node", "ele", "face") if ext == "node" else (ext,)):
                path = base + "." + e
                got = sha(path) if os.path.exists(path) else "missing"
                check(got == GOLDEN[(name, e)], "%s -j %d: .%s differs from the serial writer's "
                      "(sha256 %s)" % (name, j, e, got))
                if j > 1 and os.path.exists(path):
                    os.remove(path)  # the 1-thread files stay: convert reads one
    # convert: a mesh read back and written on 1, 2, 3 threads
    src = os.path.join(work, "msh41_1.msh")
    for ext in ("vtu", "mesh", "msh", "node"):
        outs = []
        for j in (1, 2, 3):
            out = os.path.join(work, "conv_%d.%s" % (j, ext))
            r = subprocess.run([tetrec, "convert", src, out, "-j", str(j)], capture_output=True,
                               text=True)
            check(r.returncode == 0, "convert to .%s -j %d: %s" % (ext, j, r.stderr))
            outs.append(sha(out) if r.returncode == 0 else str(j))
        check(outs[0] == outs[1] == outs[2], "convert to .%s: 1, 2, 3 threads differ" % ext)
    # --stats: bytes per tet; -v: the stage times
    stats = os.path.join(work, "stats.json")
    r = subprocess.run([tetrec, "delaunay", points, "-v", "-j", "2", "--stats", stats, "-o",
                        os.path.join(work, "stats.vtu")], capture_output=True, text=True)
    check(r.returncode == 0, "delaunay --stats exited %d: %s" % (r.returncode, r.stderr))
    s = json.load(open(stats))
    check(s["volume_elements"] > 100000 and s["peak_memory_bytes"] > 0,
          "stats: %d tets, peak %d bytes" % (s["volume_elements"], s["peak_memory_bytes"]))
    check(s["bytes_per_tet"] == s["peak_memory_bytes"] / s["volume_elements"],
          "bytes_per_tet %r is not peak_memory_bytes / volume_elements" % s["bytes_per_tet"])
    for stage in ("reading", "delaunay", "writing"):
        check(("tetrec: " + stage) in r.stderr, "-v prints no %s time: %s" % (stage, r.stderr))
        check(s["stage_seconds"][stage] > 0, "stage_seconds has no %s time" % stage)
    if failures:
        sys.exit("%d check(s) failed" % len(failures))
    print("1, 2, 3 threads: the serial writers' bytes in %d formats; convert the same; "
          "bytes_per_tet %.1f" % (len(CASES), s["bytes_per_tet"]))


if __name__ == "__main__":
    main()
