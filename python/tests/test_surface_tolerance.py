"""surface_tolerance (docs/simplify.md): the surface may move within EPS times the
bounding box diagonal, both ways, proven. A cube whose sides are fans around raised
points near a corner: those points go, the reported bound is within EPS, every tet is positive exactly,
every vertex of the mesh's boundary is an input point (collapses keep coordinates), and
bad values raise."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import cube
from exact import det, frac_points


def bumped_fan_cube(bump=1e-4, near=0.04):
    """The unit cube, each side four triangles around a point raised by bump, `near` of the
    way from a corner to the side's centre: two of its triangles have angles of a degree or
    so, which the collapse of that point into the corner removes."""
    pts, tris = cube()
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1),
             (4, 5, 7, 6)]
    pts = [list(p) for p in pts]
    out = []
    for q in quads:
        c = np.array(pts[q[0]]) + near * (np.mean([pts[i] for i in q], axis=0) - pts[q[0]])
        n = np.cross(np.array(pts[q[1]]) - pts[q[0]], np.array(pts[q[2]]) - pts[q[0]])
        c = c + bump * n / np.linalg.norm(n)
        pts.append(list(c))
        ci = len(pts) - 1
        out += [(q[i], q[(i + 1) % 4], ci) for i in range(4)]
    return np.array(pts), np.array(out, dtype=np.uint32)


def test_the_centres_go_within_the_bound_and_every_tet_is_positive():
    pts, tris = bumped_fan_cube()
    eps = 1e-3
    mesh = tetrec.tetrahedralize(pts, tris, quality=1.414, surface_tolerance=eps)
    assert mesh.stats["surface_collapses"] > 0
    assert 0 < mesh.stats["surface_tolerance_bound"] <= eps
    exact = frac_points(mesh.points)
    for t in mesh.tets.tolist():
        assert det(*(exact[i] for i in t)) > 0
    inputs = {tuple(map(Fraction, p)) for p in pts.tolist()}
    centres = {tuple(map(Fraction, p)) for p in pts[8:].tolist()}
    on = {tuple(map(Fraction, mesh.points[v])) for f in mesh.boundary_faces.tolist()
          for v in f}
    # some centre went (collapsed into a corner); the cube's corners stay
    assert len(centres & on) < len(centres)
    assert len((inputs - centres) & on) == 8


def test_without_the_option_the_mesh_is_the_same_as_before():
    pts, tris = bumped_fan_cube()
    a = tetrec.tetrahedralize(pts, tris, quality=1.414)
    b = tetrec.tetrahedralize(pts, tris, quality=1.414, surface_tolerance=None)
    assert np.array_equal(a.tets, b.tets) and np.array_equal(a.points, b.points)
    assert a.stats["surface_collapses"] == 0 and a.stats["surface_flips"] == 0


@pytest.mark.parametrize("bad", [0.0, -1e-3, float("nan"), float("inf")])
def test_a_non_positive_or_non_finite_tolerance_raises(bad):
    pts, tris = bumped_fan_cube()
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(pts, tris, surface_tolerance=bad)
