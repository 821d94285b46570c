"""tetrec.tetrahedralize on arrays and on the repository's test surfaces: every mesh is
checked exactly (orientation, volume, conformity, boundary tiling) by exact.py."""
from collections import Counter
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import DATA, cube
from exact import (check_faces_in_their_triangles, check_mesh, det, enclosed_volume6,
                   frac_points, tets_volume6)

OFF_FILES = sorted(DATA.glob("*.off")) + sorted((DATA / "regressions").glob("*.off"))


def is_closed(triangles):
    """Every edge in an even number of triangles. Not half of them each way: tetrec
    orients the triangles of each shell itself, and fuzz finds such as
    tests/data/volume_blocked.off come with some of them scrambled."""
    uses = Counter()
    for a, b, c in triangles:
        for u, v in ((a, b), (b, c), (c, a)):
            uses[(min(int(u), int(v)), max(int(u), int(v)))] += 1
    return all(k % 2 == 0 for k in uses.values())


def test_cube_volume_is_exactly_one(unit_cube):
    pts, tris = unit_cube
    mesh = tetrec.tetrahedralize(pts, tris)
    check_mesh(mesh, pts, tris)
    assert tets_volume6(frac_points(mesh.points), mesh.tets) == 6


def test_cube_needs_no_steiner_point_and_keeps_its_triangles(unit_cube):
    pts, tris = unit_cube
    mesh = tetrec.tetrahedralize(pts, tris, smooth=False)
    assert len(mesh.points) == 8
    assert mesh.stats["volume_nodes"] == 8
    assert mesh.stats["volume_elements"] == len(mesh.tets)
    assert {tuple(sorted(f)) for f in mesh.boundary_faces.tolist()} == \
        {tuple(sorted(t)) for t in tris.tolist()}


def test_scaled_cube_volume_is_exact():
    pts, tris = cube(-0.1, 0.3)
    mesh = tetrec.tetrahedralize(pts, tris)
    check_mesh(mesh, pts, tris)
    assert tets_volume6(mesh.exact_points(), mesh.tets) == 6 * (Fraction(0.3) - Fraction(-0.1)) ** 3


@pytest.mark.parametrize("path", OFF_FILES, ids=lambda p: p.name)
def test_repository_surface_meshes_exactly_or_is_refused_as_open(path):
    surface = tetrec.read(path)
    if not is_closed(surface.triangles):
        with pytest.raises(tetrec.Error) as e:
            tetrec.tetrahedralize(surface)
        assert e.value.status == "TR_ERR_OPEN"
        return
    try:
        mesh = tetrec.tetrahedralize(surface)
    except tetrec.Error as e:
        # the self-intersecting soups of tests/resolve: refused as given, meshed as the
        # solid of their winding number (every tet positive, exactly)
        assert e.status == "TR_ERR_SELF_INTERSECT" and path.name.startswith("resolve_")
        try:
            mesh = tetrec.tetrahedralize(surface, resolve=True)
        except tetrec.Error as r:
            # resolve_grid_*: corners at 2^52, where one ulp is a unit, so two exact
            # corners share a nearest double and no mesh of doubles exists; the message
            # says so and points to the exact output, which exact=True keeps
            # (test_resolve.py checks that mesh in full)
            assert path.name.startswith("resolve_grid_") and r.status == "TR_ERR_INVALID_MESH"
            assert "--exact" in r.message
            mesh = tetrec.tetrahedralize(surface, resolve=True, exact=True)
        xp = mesh.exact_points()
        assert all(det(*(xp[v] for v in t)) > 0 for t in mesh.tets)
        assert len(mesh.tets) == mesh.stats["volume_elements"] > 0
        return
    meshed, _ = tetrec.validate(surface)
    check_mesh(mesh, meshed.points, meshed.triangles)
    assert len(mesh.tets) == mesh.stats["volume_elements"]
    assert len(mesh.points) == mesh.stats["volume_nodes"]


def test_steiner_points_lie_exactly_on_their_constraints():
    """Schoenhardt's polyhedron has no tetrahedralization without Steiner points."""
    surface = tetrec.read(DATA / "schoenhardt.off")
    mesh = tetrec.tetrahedralize(surface)
    assert len(mesh.points) > len(surface.points)
    check_mesh(mesh, surface.points, surface.triangles)


def test_markers_round_trip_to_boundary_faces(unit_cube):
    pts, tris = unit_cube
    markers = np.repeat(np.arange(10, 16, dtype=np.int32), 2)
    mesh = tetrec.tetrahedralize(pts, tris, markers=markers)
    owner = check_mesh(mesh, pts, tris)
    assert mesh.boundary_markers.tolist() == [int(markers[i]) for i in owner]
    assert (mesh.boundary_markers == markers[mesh.boundary_triangles]).all()


def test_file_markers_are_passed_with_a_surface():
    surface = tetrec.read(DATA / "cube_facets.poly")
    assert sorted(set(surface.markers.tolist())) == [1, 2, 3, 4, 5, 6]
    mesh = tetrec.tetrahedralize(surface)
    owner = check_mesh(mesh, surface.points, surface.triangles)
    assert mesh.boundary_markers.tolist() == [int(surface.markers[i]) for i in owner]


@pytest.mark.parametrize("name", ["schoenhardt.off", "star_rounding_budget.off"])
def test_without_smoothing_each_face_lies_in_its_named_triangle(name):
    surface = tetrec.read(DATA / name)
    mesh = tetrec.tetrahedralize(surface, smooth=False)
    check_mesh(mesh, surface.points, surface.triangles)
    check_faces_in_their_triangles(mesh, surface.points, surface.triangles)


def test_cavity_given_facing_into_itself_is_meshed_as_a_cavity():
    # cavity.off gives both cubes facing inward: the outer one is repaired, the inner one
    # faces into itself as given, so it is a cavity (facing outward it would be an
    # inclusion, meshed as a region of its own)
    surface = tetrec.read(DATA / "cavity.off")
    meshed, report = tetrec.validate(surface)
    assert report
    assert enclosed_volume6(surface.points, surface.triangles) == -6 * (64 + 8)
    assert enclosed_volume6(meshed.points, meshed.triangles) == 6 * (64 - 8)
    mesh = tetrec.tetrahedralize(surface)
    assert tets_volume6(mesh.exact_points(), mesh.tets) == 6 * (64 - 8)


def test_progress_sees_every_stage_start_and_end(unit_cube):
    seen = []
    tetrec.tetrahedralize(*unit_cube, progress=lambda s, f: seen.append((s, f)))
    stages = [s for s, f in seen if f == 0.0]
    assert stages and [s for s, f in seen if f == 1.0] == stages
    assert "delaunay" in stages and "edge_recovery" in stages


def test_progress_returning_true_cancels(unit_cube):
    with pytest.raises(tetrec.Error) as e:
        tetrec.tetrahedralize(*unit_cube, progress=lambda s, f: s == "delaunay")
    assert e.value.status == "TR_ERR_CANCELLED"


def test_exception_in_progress_cancels_and_propagates(unit_cube):
    def boom(stage, fraction):
        raise KeyError(stage)
    with pytest.raises(KeyError):
        tetrec.tetrahedralize(*unit_cube, progress=boom)


def test_stats_hold_every_stage_time(unit_cube):
    stats = tetrec.tetrahedralize(*unit_cube).stats
    assert set(stats["stage_seconds"]) >= {"validation", "delaunay", "edge_recovery",
                                           "facet_recovery", "coloring", "suppression",
                                           "rounding"}
    assert all(t >= 0 for t in stats["stage_seconds"].values())


def test_same_input_same_arrays():
    surface = tetrec.read(DATA / "star_rounding_budget.off")
    a = tetrec.tetrahedralize(surface)
    b = tetrec.tetrahedralize(surface)
    for name in ("points", "tets", "regions", "boundary_faces", "boundary_markers"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_inputs_in_any_array_form_give_the_same_mesh(unit_cube):
    pts, tris = unit_cube
    a = tetrec.tetrahedralize(pts, tris)
    b = tetrec.tetrahedralize(pts.astype(np.int64).tolist(),
                              np.asfortranarray(tris.astype(np.int64)))
    assert np.array_equal(a.tets, b.tets) and np.array_equal(a.points, b.points)


def test_disjoint_cubes_give_tets_inside_one_or_the_other():
    surface = tetrec.read(DATA / "two_cubes.off")
    mesh = tetrec.tetrahedralize(surface)
    check_mesh(mesh, surface.points, surface.triangles)
    xs = mesh.points[mesh.tets][:, :, 0]
    assert ((xs.max(axis=1) <= 1) | (xs.min(axis=1) >= 2)).all()


def test_arrays_are_read_only(unit_cube):
    mesh = tetrec.tetrahedralize(*unit_cube)
    with pytest.raises(ValueError):
        mesh.points[0, 0] = 5.0


def test_threads_mesh_at_once_and_give_the_sequential_meshes():
    """tetrahedralize releases the GIL; the C library is thread-safe on distinct inputs."""
    from concurrent.futures import ThreadPoolExecutor

    names = ["star_rounding_budget.off", "schoenhardt.off", "cavity.off", "two_cubes.off"]
    surfaces = [tetrec.read(DATA / n) for n in names]
    alone = [tetrec.tetrahedralize(s) for s in surfaces]
    with ThreadPoolExecutor(max_workers=4) as pool:
        together = list(pool.map(tetrec.tetrahedralize, surfaces))
    for a, b in zip(alone, together):
        assert np.array_equal(a.tets, b.tets) and np.array_equal(a.points, b.points)


def test_version_is_the_package_version():
    from importlib.metadata import version

    assert tetrec.__version__ == version("tetrec")


def test_internal_facet_splits_two_regions():
    """Two unit cubes side by side, their common square given once as an internal facet:
    two regions, tets on either side, the facet's faces listed once."""
    a, ta = cube(0.0, 1.0)
    b, tb = cube(0.0, 1.0)
    b = b + [1.0, 0.0, 0.0]
    pts = np.vstack([a, b])
    # b's -x side coincides with a's +x side: keep a's +x side as the internal facet
    # (triangles 2 and 3 of a), drop b's -x side (triangles 0 and 1 of b), and glue
    # b's points on it to a's
    glue = {8 + i: j for i in range(8) for j in range(8) if (b[i] == a[j]).all()}
    tris = [t for t in ta.tolist()] + [[glue.get(v + 8, v + 8) for v in t]
                                        for t in tb.tolist()[2:]]
    used = sorted({v for t in tris for v in t})
    renum = {v: k for k, v in enumerate(used)}
    pts = pts[used]
    tris = np.array([[renum[v] for v in t] for t in tris], dtype=np.uint32)
    mesh = tetrec.tetrahedralize(pts, tris)
    check_mesh(mesh, pts, tris, internal={2, 3})
    assert tets_volume6(frac_points(mesh.points), mesh.tets) == 6 * 2
    xs = mesh.points[mesh.tets][:, :, 0]
    left = xs.max(axis=1) <= 1
    assert (left | (xs.min(axis=1) >= 1)).all()
    assert len(set(mesh.regions[left].tolist())) == 1
    assert len(set(mesh.regions[~left].tolist())) == 1
    assert set(mesh.regions[left].tolist()) != set(mesh.regions[~left].tolist())
    on_facet = [f for f in mesh.boundary_faces.tolist() if (mesh.points[f][:, 0] == 1).all()]
    assert on_facet and len(on_facet) == len({tuple(sorted(f)) for f in on_facet})


def test_duplicate_vertex_is_merged_and_the_mesh_follows_the_validated_surface(unit_cube):
    pts, tris = unit_cube
    pts = np.vstack([pts, pts[:1]])
    tris = tris.copy()
    tris[tris == 0] = np.where(np.arange(tris.size).reshape(tris.shape)[tris == 0] % 2, 8, 0)
    assert (tris == 8).any() and (tris == 0).any()
    meshed, report = tetrec.validate(pts, tris)
    assert len(meshed.points) == 8 and report
    mesh = tetrec.tetrahedralize(pts, tris)
    check_mesh(mesh, meshed.points, meshed.triangles)
