#!/usr/bin/env python3
"""Interop: meshio reads our .mesh and .vtu output with the counts we wrote.
Skipped (77) when meshio is not installed."""
import os
import subprocess
import sys
import tempfile

try:
    import meshio
except ImportError:
    # Debian's python3-meshio lives with Debian's interpreter; a python3 from another
    # installation first on PATH (pyenv, venv) cannot see it, so hand over to the system
    # interpreter once before giving up.
    system_python = "/usr/bin/python3"
    if os.path.realpath(sys.executable) != os.path.realpath(system_python) \
            and os.path.exists(system_python) and not os.environ.get("TETREC_REEXEC"):
        os.environ["TETREC_REEXEC"] = "1"
        os.execv(system_python, [system_python] + sys.argv)
    print("meshio not installed: skipped")
    sys.exit(77)

tetrec, data = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
fails = 0
with tempfile.TemporaryDirectory() as d:
    for ext in (".mesh", ".vtu"):
        out = os.path.join(d, "cube" + ext)
        p = subprocess.run([tetrec, "delaunay", "-Q", os.path.join(data, "../../examples/data/cube.off"),
                            "-o", out], capture_output=True, text=True)
        if p.returncode != 0:
            print("tetrec failed:", p.stderr)
            sys.exit(1)
        m = meshio.read(out)
        ntet = sum(len(c.data) for c in m.cells if c.type == "tetra")
        if len(m.points) != 8 or ntet != 6:
            print(f"FAILED {ext}: {len(m.points)} points, {ntet} tets (8, 6 expected)")
            fails += 1
sys.exit(1 if fails else 0)
