#!/usr/bin/env python3
"""Interop: meshio reads our .mesh, .vtu, .vtk and .msh (4.1, 2.2) output with the counts we
wrote.
Skipped (77) when meshio is not installed."""
import os
import subprocess
import sys
import tempfile

from meshio_import import require_meshio

meshio = require_meshio()

tetrec, data = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
fails = 0
with tempfile.TemporaryDirectory() as d:
    for ext in (".mesh", ".vtu", ".vtk", ".msh", "22.msh"):
        out = os.path.join(d, "cube" + ext)
        p = subprocess.run([tetrec, "delaunay", "-q", os.path.join(data, "../../examples/data/cube.off"),
                            "-o", out] + (["--msh-version", "2.2"] if ext == "22.msh" else []),
                           capture_output=True, text=True)
        if p.returncode != 0:
            print("tetrec failed:", p.stderr)
            sys.exit(1)
        m = meshio.read(out)
        ntet = sum(len(c.data) for c in m.cells if c.type == "tetra")
        if len(m.points) != 8 or ntet != 6:
            print(f"FAILED {ext}: {len(m.points)} points, {ntet} tets (8, 6 expected)")
            fails += 1
        if ext.endswith(".msh"):
            # the physical tags of the tets are their regions, of the triangles their markers
            phys = m.cell_data.get("gmsh:physical")
            ntri = sum(len(c.data) for c in m.cells if c.type == "triangle")
            if phys is None or ntri != 12:
                print(f"FAILED {ext}: {ntri} boundary triangles (12), physical tags {phys is not None}")
                fails += 1
    # the other way: .msh files meshio writes (4.1 declares only the volume entity) read
    # back with their physical tags as markers and their tets
    import numpy as np
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    m = meshio.Mesh(pts, [("triangle", np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])),
                          ("tetra", np.array([[0, 1, 2, 3]]))],
                    cell_data={"gmsh:physical": [np.array([7, 7, 8, 8]), np.array([3])],
                               "gmsh:geometrical": [np.array([1, 1, 2, 2]), np.array([1])]},
                    point_data={"gmsh:dim_tags": np.array([[3, 1]] * 4)})
    for fmt in ("gmsh", "gmsh22"):
        src, dst = os.path.join(d, fmt + ".msh"), os.path.join(d, fmt + ".mesh")
        meshio.write(src, m, file_format=fmt, binary=False)
        p = subprocess.run([tetrec, "convert", src, dst], capture_output=True, text=True)
        back = meshio.read(dst) if p.returncode == 0 else None
        ti = [i for i, c in enumerate(back.cells) if c.type == "triangle"] if back else []
        tri = [back.cells[i] for i in ti]
        refs = list(back.cell_data["medit:ref"][ti[0]]) if ti else []
        if p.returncode != 0 or len(tri) != 1 or len(tri[0].data) != 4:
            print(f"FAILED reading meshio's {fmt}: {p.returncode} {p.stderr}")
            fails += 1
        elif fmt == "gmsh22" and sorted(refs) != [7, 7, 8, 8]:
            print(f"FAILED {fmt}: markers {refs} (7 7 8 8)")
            fails += 1
sys.exit(1 if fails else 0)
