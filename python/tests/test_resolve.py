"""resolve=True (tr_options.resolve): the solid of a self-intersecting surface by winding
number. A valid surface gives the same mesh as without it; two overlapping cubes give
their union, checked exactly (positive tets, conformity, volume 2 - 1/8); an open box is
an error naming the edge."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import cube
from exact import check_mesh, faces_of_tets, face_key, det, tets_volume6


def two_cubes():
    a, ta = cube(0.0, 1.0)
    b, tb = cube(0.5, 1.5)
    return np.vstack([a, b]), np.vstack([ta, tb + 8]).astype(np.uint32)


def test_valid_surface_gives_the_same_mesh_with_resolve(unit_cube):
    pts, tris = unit_cube
    m0 = tetrec.tetrahedralize(pts, tris)
    m1 = tetrec.tetrahedralize(pts, tris, resolve=True)
    check_mesh(m1, pts, tris)
    assert (m0.points == m1.points).all() and (m0.tets == m1.tets).all()
    assert (m0.boundary_faces == m1.boundary_faces).all()


def test_two_overlapping_cubes_mesh_their_union_exactly():
    pts, tris = two_cubes()
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(pts, tris)
    assert e.value.status == "TR_ERR_SELF_INTERSECT"
    m = tetrec.tetrahedralize(pts, tris, resolve=True)
    xp = m.exact_points()
    for t in m.tets:
        assert det(*(xp[v] for v in t)) > 0
    faces = faces_of_tets(m.tets)
    assert max(faces.values()) <= 2
    hull = {f for f, k in faces.items() if k == 1}
    assert hull == {face_key(f) for f in m.boundary_faces}
    assert tets_volume6(xp, m.tets) == Fraction(45, 4)  # 6 x (2 - 1/8)
    # internal facets kept: the common cube's 12 pieces inside, the same volume
    mi = tetrec.tetrahedralize(pts, tris, resolve="internal")
    assert tets_volume6(mi.exact_points(), mi.tets) == Fraction(45, 4)
    assert len(mi.boundary_faces) >= len(m.boundary_faces) + 12


def test_open_box_is_an_error_naming_the_edge(unit_cube):
    pts, tris = unit_cube
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(pts, tris[:10], resolve=True)
    assert e.value.status == "TR_ERR_OPEN" and "winding number is not defined" in e.value.message


def test_resolve_takes_true_false_or_internal(unit_cube):
    pts, tris = unit_cube
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(pts, tris, resolve="yes")


def test_rational_corners_are_exact_mesh_vertices():
    # the second box [0.5, 2] x [0.5, 1.5]^2: the diagonals of its faces y = 0.5, 1.5 and
    # z = 0.5, 1.5 cross the first cube's face x = 1 at 0.5 + 1/3, no double
    a, ta = cube(0.0, 1.0)
    b, tb = cube(0.0, 1.0)
    b = b * np.array([1.5, 1.0, 1.0]) + 0.5
    pts, tris = np.vstack([a, b]), np.vstack([ta, tb + 8]).astype(np.uint32)
    m = tetrec.tetrahedralize(pts, tris, resolve=True)
    xp = m.exact_points()
    third = [p for p in xp if any(c.denominator % 3 == 0 for c in p)]
    assert third and all(p[0] == 1 for p in third)
    for t in m.tets:
        assert det(*(xp[v] for v in t)) > 0
    faces = faces_of_tets(m.tets)
    hull = {f for f, k in faces.items() if k == 1}
    assert hull == {face_key(f) for f in m.boundary_faces}
    assert tets_volume6(xp, m.tets) == Fraction(57, 4)  # 6 x (1 + 1.5 - 1/8)
