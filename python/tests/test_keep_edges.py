"""keep_edges under quality refinement: by default the edges between exactly coplanar input
triangles of one marker are merged away (one planar facet, whose refinement may cross
them); with keep_edges=True every input edge stays a chain of mesh edges. Every mesh is
checked exactly (exact.check_mesh)."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import cube
from exact import check_mesh, cross, dot, oriented_plane, sub


def box_with_a_fanned_top():
    """The box [0,2] x [0,1] x [0,1/4], outward, its sides two triangles each and its top
    four triangles around the top's centre (point 8): 14 triangles, 9 inner edges between
    coplanar triangles (a diagonal on each of the 5 sides, 4 spokes on the top)."""
    pts, tris = cube()
    pts = pts * np.array([2.0, 1.0, 0.25])
    top = [4, 5, 7, 6]  # side +z, counter-clockwise seen from above
    fan = [(top[i], top[(i + 1) % 4], 8) for i in range(4)]
    pts = np.vstack([pts, [[1.0, 0.5, 0.25]]])
    tris = np.vstack([tris[:10], np.array(fan, dtype=np.uint32)]).astype(np.uint32)
    return pts, tris


def coplanar_inner_edges(pts, tris, markers=None):
    """The edges whose two triangles lie in one plane, oriented alike, of one marker:
    what the library merges (counted here exactly, independently of it)."""
    exact = [tuple(Fraction(float(c)) for c in p) for p in pts]
    owners = {}
    for i, t in enumerate(tris.tolist()):
        for k in range(3):
            owners.setdefault(frozenset((t[k], t[(k + 1) % 3])), []).append(i)
    merged = set()
    for e, o in owners.items():
        if len(o) != 2:
            continue
        i, j = o
        same_plane = oriented_plane(*(exact[v] for v in tris[i])) == \
            oriented_plane(*(exact[v] for v in tris[j]))
        if same_plane and (markers is None or markers[i] == markers[j]):
            merged.add(e)
    return merged


def broken_input_edges(mesh, tris):
    """The input edges that are no chain of mesh edges: the mesh vertices exactly on the
    closed segment, in order along it, must be joined by edges of tets."""
    xp = mesh.exact_points()
    edges = {frozenset((int(t[a]), int(t[b]))) for t in mesh.tets
             for a in range(4) for b in range(a + 1, 4)}
    broken = []
    inputs = {frozenset((t[k], t[(k + 1) % 3])) for t in tris.tolist() for k in range(3)}
    for e in sorted(tuple(sorted(e)) for e in inputs):
        a, b = xp[e[0]], xp[e[1]]
        d = sub(b, a)
        on = []
        for v, p in enumerate(xp):
            w = sub(p, a)
            if cross(d, w) == (0, 0, 0) and 0 <= dot(w, d) <= dot(d, d):
                on.append((dot(w, d), v))
        chain = [v for _, v in sorted(on)]
        if not all(frozenset(pair) in edges for pair in zip(chain, chain[1:])):
            broken.append(e)
    return broken


def test_fanned_box_keep_edges_keeps_every_input_edge_a_chain_of_mesh_edges():
    pts, tris = box_with_a_fanned_top()
    mesh = tetrec.tetrahedralize(pts, tris, quality=1.414, keep_edges=True)
    check_mesh(mesh, pts, tris)
    assert mesh.stats["points_added_for_quality"] > 0
    assert mesh.stats["input_edges_merged"] == 0
    assert broken_input_edges(mesh, tris) == []


def test_fanned_box_without_keep_edges_is_valid_and_its_stats_count_the_merged_edges():
    pts, tris = box_with_a_fanned_top()
    merged = coplanar_inner_edges(pts, tris)
    assert len(merged) == 9
    mesh = tetrec.tetrahedralize(pts, tris, quality=1.414)
    check_mesh(mesh, pts, tris)
    assert mesh.stats["points_added_for_quality"] > 0
    assert mesh.stats["input_edges_merged"] == len(merged)
    # refinement crosses some merged edges (what keep_edges prevents), and only those:
    # the box's own edges stay chains
    crossed = {frozenset(e) for e in broken_input_edges(mesh, tris)}
    assert crossed and crossed <= merged


def test_fanned_box_triangles_of_different_markers_merge_no_edge():
    pts, tris = box_with_a_fanned_top()
    markers = np.arange(len(tris), dtype=np.int32)
    assert coplanar_inner_edges(pts, tris, markers) == set()
    mesh = tetrec.tetrahedralize(pts, tris, markers=markers, quality=1.414)
    check_mesh(mesh, pts, tris)
    assert mesh.stats["input_edges_merged"] == 0
    assert broken_input_edges(mesh, tris) == []


def test_keep_edges_numpy_bool_is_a_flag(unit_cube):
    mesh = tetrec.tetrahedralize(*unit_cube, quality=1.414, keep_edges=np.bool_(True))
    check_mesh(mesh, *unit_cube)
    assert mesh.stats["input_edges_merged"] == 0


@pytest.mark.parametrize("bad", ["yes", "False", 1, 1.0, None, [True], np.array([True, False])],
                         ids=["str", "str_False", "int", "float", "None", "list", "array"])
def test_keep_edges_of_a_type_other_than_bool_raises_type_error(unit_cube, bad):
    with pytest.raises(TypeError, match="keep_edges"):
        tetrec.tetrahedralize(*unit_cube, quality=1.414, keep_edges=bad)
