"""The meshing options that reach the C library: keep_surface, quality, max_volume, holes
and regions. Every mesh is checked exactly (exact.check_mesh)."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import DATA, cube
from exact import check_mesh, cross, dot, face_key, frac_points, sub, tets_volume6


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


def test_keep_surface_with_quality_adds_interior_points_only():
    surface = tetrec.read(str(DATA / "schoenhardt.off"))
    mesh = tetrec.tetrahedralize(surface.points, surface.triangles, keep_surface=True,
                                 quality=1.414, max_volume=0.05)
    check_mesh(mesh, surface.points, surface.triangles)
    assert mesh.stats["points_added_for_quality"] > 0
    got = sorted(face_key(f) for f in mesh.boundary_faces.tolist())
    want = sorted(face_key(t) for t in surface.triangles.tolist())
    assert got == want
    pts = frac_points(mesh.points)
    for t in mesh.tets.tolist():
        assert tets_volume6(pts, [t]) <= Fraction(6) * Fraction(0.05)
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(surface.points, surface.triangles, keep_surface=True,
                              quality=1.414, subface_quality=2.0)
    assert e.value.status == "TR_ERR_USAGE"


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


def slab():
    """The box [0,8] x [0,1] x [0,1]: its long sides are two triangles of radius-edge
    ratio about 4 each."""
    p, t = cube()
    return p * np.array([8.0, 1.0, 1.0]), t


def face_ratio2(pts, f):
    """The squared radius-edge ratio of triangle f, exactly: R^2 = |ab|^2 |bc|^2 |ca|^2 /
    (4 |ab x ac|^2), over its shortest squared edge."""
    a, b, c = (pts[i] for i in f)
    e = [dot(sub(b, a), sub(b, a)), dot(sub(c, b), sub(c, b)), dot(sub(a, c), sub(a, c))]
    n = cross(sub(b, a), sub(c, a))
    return e[0] * e[1] * e[2] / (4 * dot(n, n)) / min(e)


def test_subface_quality_bounds_every_boundary_face_ratio():
    # under quality=1.414 the tets alone now split the slab's long edges enough (the close
    # splits of src/refine/refine.c): its faces' worst ratio is 1.12 either way; under 3
    # they leave faces of ratio 2.06, which subface_quality=1.5 splits
    points, tris = slab()
    plain = tetrec.tetrahedralize(points, tris, quality=3)
    split = tetrec.tetrahedralize(points, tris, quality=3, subface_quality=1.5)
    for mesh in (plain, split):
        check_mesh(mesh, points, tris)
    worst = []
    for mesh in (plain, split):
        pts = frac_points(mesh.points)
        worst.append(max(face_ratio2(pts, f) for f in mesh.boundary_faces.tolist()))
    # the box has only right angles, so no small input angle excuses a face over S
    assert worst[1] <= Fraction(1.5) ** 2 < worst[0]
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(points, tris, quality=1.414, subface_quality=0.5)
    assert e.value.status == "TR_ERR_USAGE"


def test_refine_budget_stops_refinement_with_an_error():
    points, tris = slab()
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(points, tris, quality=1.414, max_volume=1e-4, refine_budget=10)
    assert e.value.status == "TR_ERR_NOMEM"
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(points, tris, quality=1.414, refine_budget=0)
    mesh = tetrec.tetrahedralize(points, tris, quality=1.414, refine_budget=10**6)
    check_mesh(mesh, points, tris)
    assert mesh.stats["refine_budget_reached"] == 0


def test_refine_partial_returns_the_mesh_made_at_the_budget():
    points, tris = slab()
    with pytest.warns(UserWarning, match="stopped at its point budget"):
        mesh = tetrec.tetrahedralize(points, tris, quality=1.414, max_volume=1e-2,
                                     refine_budget=150, refine_partial=True)
    check_mesh(mesh, points, tris)
    assert mesh.stats["refine_budget_reached"] == 1
    assert mesh.stats["points_added_for_quality"] == 150
    assert mesh.stats["points_added_for_sliver"] == 0
    assert 0 < mesh.stats["tets_over_bounds"] <= mesh.stats["volume_elements"]
    with pytest.raises(TypeError):
        tetrec.tetrahedralize(points, tris, quality=1.414, refine_partial="yes")


def test_stats_count_the_tets_under_10_degrees_on_thin_input_triangles():
    # a prism over a triangle with a 5-degree corner: its two ends are thin input
    # triangles, and refinement without sliver removal leaves tets under 10 degrees there
    points = [[0, 0, 0], [10, 0, 0], [10, 0.875, 0], [0, 0, 2], [10, 0, 2], [10, 0.875, 2]]
    tris = [[0, 2, 1], [3, 4, 5], [0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4], [2, 0, 3],
            [2, 3, 5]]
    mesh = tetrec.tetrahedralize(points, tris, quality=1.414, optimize=0)
    check_mesh(mesh, points, tris)
    assert mesh.stats["thin_input_triangles"] == 2
    assert 0 < mesh.stats["tets_dihedral_below_10_on_thin_input"] \
        <= mesh.stats["tets_dihedral_below_10"]


def test_refinement_options_without_refinement_warn(unit_cube):
    for kw in ({"optimize": 2}, {"subface_quality": 1.5}, {"refine_budget": 5},
               {"keep_edges": True}, {"spacing_radii": False}):
        with pytest.warns(UserWarning, match="no effect without quality refinement"):
            mesh = tetrec.tetrahedralize(*unit_cube, **kw)
        check_mesh(mesh, *unit_cube)


def test_spacing_radii_meets_the_ratio_bound_where_insertion_radii_refuse():
    # the box [0,1] x [0,0.1] x [0,0.1]: the points split into its long edges keep an
    # insertion radius of 0.5, so with spacing_radii=False later circumcentres near them
    # are refused as too close and tets over the bound stay; by default the rule takes
    # their current spacing (tests/refine/test_merge.c has the same case in C)
    p, tris = cube()
    points = p * np.array([1.0, 0.1, 0.1])
    radii = tetrec.tetrahedralize(points, tris, quality=1.414, optimize=0,
                                  spacing_radii=False)
    spacing = tetrec.tetrahedralize(points, tris, quality=1.414, optimize=0)
    explicit = tetrec.tetrahedralize(points, tris, quality=1.414, optimize=0,
                                     spacing_radii=True)
    assert np.array_equal(spacing.points, explicit.points)  # True is the default
    assert np.array_equal(spacing.tets, explicit.tets)
    for mesh in (radii, spacing):
        check_mesh(mesh, points, tris)
    assert radii.stats["max_radius_edge"] > 1.414
    assert spacing.stats["max_radius_edge"] <= 1.414
    with pytest.raises(TypeError):
        tetrec.tetrahedralize(points, tris, quality=1.414, spacing_radii="yes")


def test_stats_report_the_bytes_a_tet_costs_at_the_peak(unit_cube):
    mesh = tetrec.tetrahedralize(*unit_cube, quality=1.414)
    check_mesh(mesh, *unit_cube)
    st = mesh.stats
    assert st["volume_elements"] > 0
    assert st["bytes_per_tet"] == pytest.approx(st["peak_memory_bytes"] / st["volume_elements"])


def test_sizing_grades_the_mesh_and_bad_arrays_are_refused(unit_cube):
    pts, tris = unit_cube
    h = 0.04 + 0.1 * pts.sum(axis=1)  # linear: interpolated exactly
    mesh = tetrec.tetrahedralize(pts, tris, sizing=h, optimize=0)
    check_mesh(mesh, pts, tris)
    assert mesh.stats["points_added_for_quality"] > 100
    p = mesh.points
    t = mesh.tets
    hv = 0.04 + 0.1 * p.sum(axis=1)
    longest = np.zeros(len(t))
    for i in range(4):
        for j in range(i + 1, 4):
            longest = np.maximum(longest, np.linalg.norm(p[t[:, i]] - p[t[:, j]], axis=1))
    assert np.all(longest <= hv[t].mean(axis=1) * (1 + 1e-9))
    # same field, fewer tets for a coarser one
    coarse = tetrec.tetrahedralize(pts, tris, sizing=2 * h, optimize=0)
    assert len(coarse.tets) < len(mesh.tets)
    with pytest.raises(ValueError):
        tetrec.tetrahedralize(pts, tris, sizing=h[:7])
    bad = h.copy()
    bad[3] = -1
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(pts, tris, sizing=bad)
    assert e.value.status == "TR_ERR_USAGE" and "sizing[3]" in e.value.message
