"""resolve=True (tr_options.resolve): the solid of a self-intersecting surface by winding
number. A valid surface gives the same mesh as without it; two overlapping cubes give
their union, checked exactly (positive tets, conformity, volume 2 - 1/8); an open box is
an error naming the edge."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import DATA, cube
from exact import (check_mesh, cross, det, face_key, faces_of_tets, frac_points,
                   in_closed_triangle, oriented_plane, sub, tets_volume6, winding_number)


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


def test_exact_keeps_the_mesh_where_two_exact_corners_share_a_double(tmp_path):
    # tests/data/resolve_grid_cycle.off: six tetrahedra on a grid at 2^52, where one ulp
    # is a unit, so two exact corners of the union round to one double: no mesh in
    # doubles exists and the default raises, naming exact output; exact=True keeps the
    # exact mesh (tr_options.keep_exact), checked here exactly and independently of the
    # library: every tet positive, its faces a closed boundary listed as such, the tets'
    # volume the boundary's, every tet's centroid of winding number >= 1 in the input,
    # and every boundary face on an input triangle, in its plane and oriented like it
    surface = tetrec.read(DATA / "resolve_grid_cycle.off")
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(surface, resolve=True)
    assert e.value.status == "TR_ERR_INVALID_MESH" and "--exact" in e.value.message
    m = tetrec.tetrahedralize(surface, resolve=True, exact=True)
    assert m.exact and len(m.tets) == m.stats["volume_elements"] > 0
    xp = m.exact_points()
    # the reason: two vertices with one double and two exact points
    by_double = {}
    for v, p in enumerate(m.points.tolist()):
        by_double.setdefault(tuple(p), []).append(v)
    shared = [vs for vs in by_double.values() if len(vs) > 1]
    assert shared and all(len({xp[v] for v in vs}) == len(vs) for vs in shared)
    for t in m.tets:
        assert det(*(xp[v] for v in t)) > 0
    faces = faces_of_tets(m.tets)
    assert max(faces.values()) <= 2
    hull = {f for f, k in faces.items() if k == 1}
    assert hull == {face_key(f) for f in m.boundary_faces}
    o = (Fraction(0),) * 3
    assert tets_volume6(xp, m.tets) == sum(det(o, *(xp[v] for v in f))
                                           for f in m.boundary_faces)
    ipts = frac_points(surface.points)
    assert winding_number((Fraction(0),) * 3, ipts, surface.triangles) == 0  # far outside
    for t in m.tets:
        g = tuple(sum(xp[v][k] for v in t) / 4 for k in range(3))
        assert winding_number(g, ipts, surface.triangles) >= 1, list(t)
    for f in m.boundary_faces:
        p = [xp[int(v)] for v in f]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        assert any(oriented_plane(*p) == oriented_plane(*(ipts[int(v)] for v in tri)) and
                   all(in_closed_triangle(q, *(ipts[int(v)] for v in tri), n) for q in p)
                   for tri in surface.triangles), list(f)
    # only the exact output is a mesh: a format in doubles is refused, the .node written
    # exactly (Mesh.write's default under exact=True)
    with pytest.raises(tetrec.Error) as e:
        m.write(tmp_path / "x.mesh")
    assert e.value.status == "TR_ERR_INVALID_MESH"
    m.write(tmp_path / "x.node")
    assert "/" in (tmp_path / "x.node").read_text()


def test_region_points_work_on_rational_corners_holes_are_refused_by_name():
    # the stretched box of the test above: its union has corners at 0.5 + 1/3; a region
    # point names the whole union (no internal facets), a hole point is not done there
    a, ta = cube(0.0, 1.0)
    b, tb = cube(0.0, 1.0)
    b = b * np.array([1.5, 1.0, 1.0]) + 0.5
    pts, tris = np.vstack([a, b]), np.vstack([ta, tb + 8]).astype(np.uint32)
    m = tetrec.tetrahedralize(pts, tris, resolve=True, regions=[(0.25, 0.25, 0.25, 3, 0)])
    xp = m.exact_points()
    assert any(c.denominator % 3 == 0 for p in xp for c in p)
    assert (m.regions == 3).all() and m.stats["region_points"] == 1
    assert tets_volume6(xp, m.tets) == Fraction(57, 4)
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(pts, tris, resolve=True, holes=[(0.25, 0.25, 0.25)])
    assert e.value.status == "TR_ERR_UNSUPPORTED" and "hole points" in e.value.message


def test_a_skew_quad_is_refused_as_read_and_read_as_its_fan_with_resolve():
    """resolve_skew_quad.obj: a tetrahedron with faces ADC and ACB given as the quad A D C
    B, whose projection along z is a bow-tie. read() refuses it; read(resolve=True) gives
    the fan from A with a warning naming the polygon, and the mesh is the tetrahedron:
    one tet, 6V = 3/2, exactly."""
    path = DATA / "resolve_skew_quad.obj"
    with pytest.raises(tetrec.Error) as e:
        tetrec.read(path)
    assert e.value.status == "TR_ERR_INPUT" and ":8: facet 0: polygon" in str(e.value)
    with pytest.warns(UserWarning, match=r"1 polygon\(s\) .* read as fans .*:8: facet 0"):
        s = tetrec.read(path, resolve=True)
    assert s.triangles.tolist()[:2] == [[0, 3, 2], [0, 2, 1]]
    m = tetrec.tetrahedralize(s, resolve=True)
    check_mesh(m, s.points, s.triangles)
    assert len(m.tets) == 1
    assert tets_volume6(m.exact_points(), m.tets) == Fraction(3, 2)
