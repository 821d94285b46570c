import pathlib

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"


def cube(lo=0.0, hi=1.0):
    """The cube [lo, hi]^3 as 8 points and 12 outward triangles, two per side; side k
    (-x, +x, -y, +y, -z, +z) holds triangles 2k and 2k+1."""
    pts = np.array([[x, y, z] for z in (lo, hi) for y in (lo, hi) for x in (lo, hi)])
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1),
             (4, 5, 7, 6)]
    tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return pts, np.array(tris, dtype=np.uint32)


@pytest.fixture
def unit_cube():
    return cube()
