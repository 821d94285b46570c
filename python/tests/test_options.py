"""The meshing options that reach the C library: keep_surface, quality, max_volume, holes
and regions. Every mesh is checked exactly (exact.check_mesh)."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import DATA, cube
from exact import check_mesh, face_key, frac_points, tets_volume6


def box_in_box():
    """The cube [0,4]^3 with the cube [1,2]^3 inside it, both facing outward."""
    p0, t0 = cube(0.0, 4.0)
    p1, t1 = cube(1.0, 2.0)
    return np.vstack([p0, p1]), np.vstack([t0, t1 + len(p0)]).astype(np.uint32)


def test_keep_surface_boundary_faces_are_the_input_triangles():
    surface = tetrec.read(str(DATA / "schoenhardt.off"))
    mesh = tetrec.tetrahedralize(surface.points, surface.triangles, keep_surface=True)
    check_mesh(mesh, surface.points, surface.triangles)
    got = sorted(face_key(f) for f in mesh.boundary_faces.tolist())
    want = sorted(face_key(t) for t in surface.triangles.tolist())
    assert got == want
    assert mesh.stats["steiner_on_edges"] == 0 and mesh.stats["steiner_on_facets"] == 0


def test_quality_refinement_adds_points_and_conforms(unit_cube):
    mesh = tetrec.tetrahedralize(*unit_cube, quality=1.414, max_volume=0.05)
    check_mesh(mesh, *unit_cube)
    assert mesh.stats["points_added_for_quality"] > 0
    pts = frac_points(mesh.points)
    for t in mesh.tets.tolist():
        assert tets_volume6(pts, [t]) <= Fraction(6) * Fraction(0.05)


def test_optimize_levels_reach_the_library_and_add_no_point(unit_cube):
    off = tetrec.tetrahedralize(*unit_cube, quality=1.2, max_volume=0.01, optimize=0)
    on = tetrec.tetrahedralize(*unit_cube, quality=1.2, max_volume=0.01, optimize=2)
    for mesh in (off, on):
        check_mesh(mesh, *unit_cube)
        assert mesh.stats["points_added_for_sliver"] == 0
    assert off.stats["sliver_flips"] == 0 and off.stats["sliver_points_smoothed"] == 0
    assert on.stats["min_dihedral"] >= off.stats["min_dihedral"]
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(*unit_cube, quality=1.2, optimize=4)


def test_quality_with_a_dihedral_target_is_worked_towards(unit_cube):
    plain = tetrec.tetrahedralize(*unit_cube, quality=1.414, max_volume=0.01)
    target = tetrec.tetrahedralize(*unit_cube, quality=(1.414, 25.0), max_volume=0.01)
    for mesh in (plain, target):
        check_mesh(mesh, *unit_cube)
    assert target.stats["min_dihedral"] >= plain.stats["min_dihedral"]
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(*unit_cube, quality=(1.414, 75.0))
    assert e.value.status == "TR_ERR_USAGE"


def test_hole_point_empties_its_cell():
    pts, tris = box_in_box()
    mesh = tetrec.tetrahedralize(pts, tris, holes=[[1.5, 1.5, 1.5]])
    vol6 = tets_volume6(frac_points(mesh.points), mesh.tets.tolist())
    assert vol6 == 6 * (64 - 1)


def test_region_points_carry_their_attributes():
    pts, tris = box_in_box()
    mesh = tetrec.tetrahedralize(pts, tris, regions=[[1.5, 1.5, 1.5, 7, 0.0],
                                                     [3.5, 3.5, 3.5, 9, 0.0]])
    assert set(mesh.regions.tolist()) == {7, 9}
    exact = frac_points(mesh.points)
    inner = sum(tets_volume6(exact, [t]) for t, r in zip(mesh.tets.tolist(),
                                                          mesh.regions.tolist()) if r == 7)
    assert inner == 6


def test_bad_hole_and_region_rows_are_refused(unit_cube):
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(*unit_cube, holes=[[0.5, 0.5]])
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(*unit_cube, regions=[[0.5, 0.5, 0.5, 1.5, 0.0]])
