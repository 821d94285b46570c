"""Failures: tetrec.Error carries the C library's status name and message; options the
C library does not offer raise NotImplementedError instead of being dropped."""
import numpy as np
import pytest

import tetrec
from conftest import DATA

UNOFFERED = [("holes", [[0.5, 0.5, 0.5]]), ("regions", [[0.5, 0.5, 0.5, 1, 0.0]]),
             ("keep_surface", True), ("quality", 2.0), ("max_volume", 0.01)]


def status_of(call):
    with pytest.raises(tetrec.Error) as e:
        call()
    assert isinstance(e.value, Exception)
    assert e.value.message and str(e.value) == e.value.message
    assert tetrec.status_name(e.value.code) == e.value.status
    return e.value


def test_open_surface_file_is_refused_as_open():
    s = tetrec.read(DATA / "bad" / "open.off")
    e = status_of(lambda: tetrec.tetrahedralize(s))
    assert e.status == "TR_ERR_OPEN" and e.code == 6
    assert "open" in e.message


def test_cube_missing_a_triangle_is_refused_as_open(unit_cube):
    pts, tris = unit_cube
    e = status_of(lambda: tetrec.tetrahedralize(pts, tris[1:]))
    assert e.status == "TR_ERR_OPEN"


def test_self_intersecting_surface_is_refused():
    s = tetrec.read(DATA / "bad" / "selfint.off")
    e = status_of(lambda: tetrec.tetrahedralize(s))
    assert e.status == "TR_ERR_SELF_INTERSECT" and e.code == 7


def test_overlapping_cubes_are_refused_as_self_intersecting(unit_cube):
    pts, tris = unit_cube
    both = np.vstack([pts, pts + 0.5])
    e = status_of(lambda: tetrec.tetrahedralize(both, np.vstack([tris, tris + 8])))
    assert e.status == "TR_ERR_SELF_INTERSECT"


def test_index_past_the_points_is_invalid_input(unit_cube):
    pts, tris = unit_cube
    bad = tris.copy()
    bad[3, 1] = 8
    assert status_of(lambda: tetrec.tetrahedralize(pts, bad)).status == "TR_ERR_INPUT"


def test_negative_index_is_invalid_input(unit_cube):
    pts, tris = unit_cube
    bad = tris.astype(np.int64)
    bad[0, 0] = -1
    assert status_of(lambda: tetrec.tetrahedralize(pts, bad)).status == "TR_ERR_INPUT"


def test_nan_coordinate_is_invalid_input(unit_cube):
    pts, tris = unit_cube
    pts = pts.copy()
    pts[2, 1] = np.nan
    assert status_of(lambda: tetrec.tetrahedralize(pts, tris)).status == "TR_ERR_INPUT"


def test_flat_surface_is_refused(unit_cube):
    pts, tris = unit_cube
    flat = pts.copy()
    flat[:, 2] = 0.0
    e = status_of(lambda: tetrec.tetrahedralize(flat, tris))
    assert e.status != "TR_OK"


def test_missing_file_is_an_io_error(tmp_path):
    e = status_of(lambda: tetrec.read(tmp_path / "nothing.off"))
    assert e.status == "TR_ERR_IO"


def test_malformed_file_is_a_parse_error():
    assert status_of(lambda: tetrec.read(DATA / "bad" / "truncated.off")).status == "TR_ERR_PARSE"


def test_unwritable_path_is_an_io_error(unit_cube, tmp_path):
    mesh = tetrec.tetrahedralize(*unit_cube)
    e = status_of(lambda: mesh.write(tmp_path / "no" / "such" / "dir.vtu"))
    assert e.status == "TR_ERR_IO"


@pytest.mark.parametrize("name,value", UNOFFERED, ids=[n for n, _ in UNOFFERED])
def test_option_the_library_lacks_raises_not_implemented(unit_cube, name, value):
    if name in tetrec.SUPPORTED_OPTIONS:
        pytest.skip(f"the C library offers {name}")
    with pytest.raises(NotImplementedError, match=name):
        tetrec.tetrahedralize(*unit_cube, **{name: value})


def test_options_at_their_defaults_are_accepted(unit_cube):
    mesh = tetrec.tetrahedralize(*unit_cube, holes=None, regions=None, keep_surface=False,
                                 quality=None, max_volume=None, exact=False)
    assert len(mesh.tets) > 0


@pytest.mark.parametrize("bad", [np.zeros((8, 2)), np.zeros(24), [["a", "b", "c"]] * 8])
def test_points_of_the_wrong_shape_or_type_are_refused(unit_cube, bad):
    with pytest.raises((ValueError, TypeError)):
        tetrec.tetrahedralize(bad, unit_cube[1])


def test_integer_coordinate_without_a_double_is_refused(unit_cube):
    pts, tris = unit_cube
    big = pts.astype(np.int64)
    big[0, 0] = 2**53 + 1
    with pytest.raises(ValueError, match="not exactly a double"):
        tetrec.tetrahedralize(big, tris)


def test_one_marker_per_triangle(unit_cube):
    pts, tris = unit_cube
    with pytest.raises(ValueError, match="markers"):
        tetrec.tetrahedralize(pts, tris, markers=np.zeros(len(tris) - 1, dtype=np.int32))


def test_error_pickles_with_its_status(tmp_path):
    """multiprocessing pickles the exceptions of its workers."""
    import pickle

    e = status_of(lambda: tetrec.read(tmp_path / "nothing.off"))
    f = pickle.loads(pickle.dumps(e))
    assert type(f) is tetrec.Error
    assert (f.status, f.code, f.message) == (e.status, e.code, e.message)
