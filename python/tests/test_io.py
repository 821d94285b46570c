"""tetrec.read, Mesh.write and Mesh.to_meshio, checked against meshio's readers."""
from fractions import Fraction

import numpy as np
import pytest

import tetrec
from conftest import DATA, REPO

meshio = pytest.importorskip("meshio")


@pytest.fixture
def schoenhardt():
    return tetrec.tetrahedralize(tetrec.read(DATA / "schoenhardt.off"))


def test_read_gives_the_same_surface_as_meshio():
    s = tetrec.read(DATA / "tet.off")
    m = meshio.read(DATA / "tet.off")
    assert s.points.dtype == np.float64 and s.triangles.dtype == np.uint32
    assert np.array_equal(s.points, m.points)
    assert np.array_equal(s.triangles, m.cells_dict["triangle"])
    assert s.markers.shape == (len(s.triangles),)


def test_read_warns_about_tets_it_leaves_out():
    with pytest.warns(UserWarning, match="1 tetrahedra left out"):
        s = tetrec.read(DATA / "tet.mesh")
    assert s.triangles.shape == (4, 3)
    assert s.markers.tolist() == [10, 11, 12, 13]


def test_read_triangulates_polygons():
    s = tetrec.read(DATA / "two_cubes.off")
    assert s.triangles.shape == (24, 3)


def test_to_meshio_counts(schoenhardt):
    m = schoenhardt.to_meshio()
    assert len(m.points) == len(schoenhardt.points)
    assert len(m.cells_dict["tetra"]) == len(schoenhardt.tets)
    assert len(m.cells_dict["triangle"]) == len(schoenhardt.boundary_faces)
    assert np.array_equal(m.cell_data_dict["tetrec:ref"]["tetra"], schoenhardt.regions)
    assert np.array_equal(m.cell_data_dict["tetrec:ref"]["triangle"],
                          schoenhardt.boundary_markers)


@pytest.mark.parametrize("ext", [".vtu", ".mesh"])
def test_written_mesh_reads_back_with_meshio(schoenhardt, tmp_path, ext):
    path = tmp_path / ("out" + ext)
    schoenhardt.write(path)
    m = meshio.read(path)
    assert np.array_equal(m.points, schoenhardt.points)
    assert np.array_equal(m.cells_dict["tetra"], schoenhardt.tets)


def test_written_tetgen_files_hold_every_tet(schoenhardt, tmp_path):
    schoenhardt.write(tmp_path / "out.node")
    ele = (tmp_path / "out.ele").read_text().split("\n")
    assert int(ele[0].split()[0]) == len(schoenhardt.tets)


def exact_coordinate(token):
    """A coordinate of an exact .node file: num/den, or a double in shortest form."""
    return Fraction(token) if "/" in token else Fraction(float(token))


@pytest.mark.parametrize("how", ["exact_mesh", "exact_write"])
def test_exact_node_file_holds_the_exact_points(tmp_path, how):
    # its Steiner points, kept on the surface, are rationals that are not doubles
    surface = tetrec.read(DATA / "chazelle_rounding_budget.off")
    path = tmp_path / "exact.node"
    if how == "exact_mesh":
        mesh = tetrec.tetrahedralize(surface, exact=True, keep_steiner=True)
        mesh.write(path)
    else:
        mesh = tetrec.tetrahedralize(surface, keep_steiner=True)
        mesh.write(path, exact=True)
    lines = [l.split() for l in path.read_text().splitlines() if not l.startswith("#")]
    assert int(lines[0][0]) == len(mesh.points)
    rows = [tuple(exact_coordinate(c) for c in l[1:4]) for l in lines[1:1 + len(mesh.points)]]
    assert rows == mesh.exact_points()
    assert any(r != tuple(Fraction(float(c)) for c in r) for r in rows), \
        "no Steiner point that is not a double: the test shows nothing"


def test_double_node_file_holds_the_doubles(schoenhardt, tmp_path):
    schoenhardt.write(tmp_path / "double.node")
    lines = [l.split() for l in (tmp_path / "double.node").read_text().splitlines()
             if not l.startswith("#")]
    rows = [[float(c) for c in l[1:4]] for l in lines[1:1 + len(schoenhardt.points)]]
    assert np.array_equal(np.array(rows), schoenhardt.points)


def test_meshio_round_trip_through_to_meshio(schoenhardt, tmp_path):
    path = tmp_path / "via_meshio.vtu"
    schoenhardt.to_meshio().write(path)
    m = meshio.read(path)
    assert np.array_equal(m.cells_dict["tetra"], schoenhardt.tets)
    assert np.array_equal(m.points, schoenhardt.points)


def test_readme_example_runs(tmp_path, monkeypatch):
    """The Python example in README.md, run as written from a copy of the repository's
    relative paths."""
    readme = (REPO / "README.md").read_text()
    code = readme.split("```python\n", 1)[1].split("```", 1)[0]
    (tmp_path / "tests").symlink_to(REPO / "tests")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert meshio.read(tmp_path / "two_cubes.vtu").points.shape[1] == 3
