"""tetrahedralize(), read(), Mesh and Surface: the Python face of the C library.

Input checks that belong to Python (shapes, dtypes, integer ranges) raise TypeError or
ValueError here; everything about the geometry is decided by the C library and comes
back as tetrec.Error with the library's status name and message.
"""
from fractions import Fraction
import os
import warnings
from typing import NamedTuple

import numpy as np

from . import _tetrec

Error = _tetrec.Error

_STATUS_INPUT = 4  # TR_ERR_INPUT


class Surface(NamedTuple):
    """A surface as read from a file: points (n,3) float64, triangles (m,3) uint32
    (0-based), markers (m,) int32 (0 where the format has none)."""

    points: np.ndarray
    triangles: np.ndarray
    markers: np.ndarray


def read(path, *, resolve=False) -> Surface:
    """Reads a surface (.off .stl .obj .ply .mesh .node .poly .smesh; the extension picks
    the reader). Polygons come back triangulated in their plane. Segments on no
    triangle and volume tets in the file are not part of a Surface: a warning says how
    many were left out.

    resolve=True reads the surface as tetrahedralize(..., resolve=True) takes it: a
    polygon of one loop that cannot be triangulated in its plane (self-overlapping, or
    all corners collinear) comes back as the fan of its loop from its first corner, with
    a warning naming it, instead of an error."""
    points, triangles, markers, nsegs, ntets, fans = _tetrec.read(os.fspath(path),
                                                                  bool(resolve))
    if fans:
        warnings.warn(f"tetrec.read({os.fspath(path)!r}): {fans}", stacklevel=2)
    for n, what in ((nsegs, "segments on no triangle"), (ntets, "tetrahedra")):
        if n:
            warnings.warn(f"tetrec.read({os.fspath(path)!r}): {n} {what} left out "
                          f"(a Surface holds points, triangles and markers)", stacklevel=2)
    return Surface(points, triangles, markers)


class Mesh:
    """A tetrahedral mesh returned by tetrahedralize().

    points (n,3) float64: the surface's points first (as validate() gives them: the
        input's, in input order, unless exact duplicates were merged), then Steiner
        points (at doubles chosen so that every tet is positive in doubles;
        exact_points() gives their exact rational positions). Under
        tetrahedralize(exact=True) the Steiner points and resolve's rational corners are
        at their nearest doubles, unrepaired: a tet may be flat or inverted there, and
        exact_points() is the mesh;
    tets (m,4) uint32: positively oriented, det[v1-v0, v2-v0, v3-v0] > 0;
    regions (m,) int32: region id of each tet;
    boundary_faces (f,3) uint32: the mesh faces on input triangles (the boundary and
        internal facets alike), each with its right-hand normal pointing the way its
        input triangle's does (outward on the boundary), sorted by input triangle;
    boundary_markers (f,) int32: the marker of each face's input triangle;
    boundary_triangles (f,) uint32: each face's input triangle, indexed in the surface
        as meshed (validate()'s; the input itself when nothing needed repair);
    stats: the rows of the C library's tr_stats (the seed paper's Table 14, times,
        peak memory, stage_seconds per pipeline stage).
    """

    def __init__(self, handle, stats, exact):
        self._handle = handle
        arrays = handle.arrays()
        self.points = arrays["points"]
        self.tets = arrays["tets"]
        self.regions = arrays["regions"]
        self.boundary_faces = arrays["boundary_faces"]
        self.boundary_markers = arrays["boundary_markers"]
        self.boundary_triangles = arrays["boundary_triangles"]
        self.stats = stats
        self.exact = exact
        for a in (self.points, self.tets, self.regions, self.boundary_faces,
                  self.boundary_markers, self.boundary_triangles):
            a.flags.writeable = False

    def __repr__(self):
        return (f"tetrec.Mesh({len(self.points)} points, {len(self.tets)} tets, "
                f"{len(self.boundary_faces)} boundary faces)")

    def exact_points(self, vertices=None):
        """Exact coordinates as fractions.Fraction triples: the Steiner points exactly on
        the edges and facets they were built on, the input points as given. vertices:
        an iterable of indices, or None for all."""
        if vertices is None:
            vertices = range(len(self.points))
        return [tuple(Fraction(c) for c in self._handle.exact_point(int(v)))
                for v in vertices]

    def write(self, path, exact=None):
        """Writes the mesh through the C library; the extension picks the format:
        .mesh (Medit), .vtu (VTK XML), .node/.ele/.face or a TetGen base name.
        exact (default: the exact= given to tetrahedralize): Steiner points as exact
        rationals num/den in the .node file."""
        if exact is None:
            exact = self.exact
        self._handle.write(os.fspath(path), bool(exact))

    def to_meshio(self):
        """A meshio.Mesh with a "tetra" block and a "triangle" block (the boundary
        faces); cell_data "tetrec:ref" holds the regions of the tets and the markers of
        the triangles."""
        import meshio

        return meshio.Mesh(
            np.array(self.points),
            [("tetra", np.array(self.tets, dtype=np.int64)),
             ("triangle", np.array(self.boundary_faces, dtype=np.int64))],
            cell_data={"tetrec:ref": [np.array(self.regions), np.array(self.boundary_markers)]},
        )


def _as_points(points):
    a = np.asarray(points)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"points: expected shape (n, 3), got {a.shape}")
    if a.dtype.kind in "iu":
        p = a.astype(np.float64)
        # Large integers do not all have a double: refuse rather than move a point.
        if not np.array_equal(p.astype(a.dtype), a):
            raise ValueError("points: an integer coordinate is not exactly a double")
        return np.ascontiguousarray(p)
    if a.dtype.kind != "f":
        raise TypeError(f"points: expected floats, got dtype {a.dtype}")
    if a.dtype.itemsize > 8:
        p = a.astype(np.float64)
        if not np.array_equal(p.astype(a.dtype), a):
            raise ValueError(f"points: a {a.dtype} coordinate is not exactly a double")
        return np.ascontiguousarray(p)
    return np.ascontiguousarray(a, dtype=np.float64)


def _as_index_array(x, name, ncols, dtype, lo, hi):
    a = np.asarray(x)
    if a.dtype.kind not in "iu":
        # An empty list has dtype float64; it still has no index to misread.
        if a.size == 0:
            a = a.astype(np.int64)
        else:
            raise TypeError(f"{name}: expected integers, got dtype {a.dtype}")
    shape = (a.shape[0], ncols) if ncols else (a.shape[0],) if a.ndim else None
    if a.ndim != (2 if ncols else 1) or a.shape != shape:
        want = f"(m, {ncols})" if ncols else "(m,)"
        raise ValueError(f"{name}: expected shape {want}, got {a.shape}")
    if a.size and (a.min() < lo or a.max() > hi):
        bad = int(np.flatnonzero((a < lo) | (a > hi))[0]) // max(ncols, 1)
        raise _tetrec.error(_STATUS_INPUT, f"{name}: row {bad} has a value outside "
                                           f"[{lo}, {hi}]: {a[bad].tolist()}")
    return np.ascontiguousarray(a, dtype=dtype)


def _prepare(points, triangles, markers):
    """points, triangles, markers as the C layer takes them; a Surface may stand for
    all three (its markers unless markers is given)."""
    if triangles is None:
        if not isinstance(points, Surface):
            raise TypeError("expected (points, triangles) or a Surface")
        if markers is None:
            markers = points.markers
        points, triangles = points.points, points.triangles
    pts = _as_points(points)
    tris = _as_index_array(triangles, "triangles", 3, np.uint32, 0, 2**32 - 2)
    mk = None
    if markers is not None:
        mk = _as_index_array(markers, "markers", 0, np.int32, -2**31, 2**31 - 1)
        if len(mk) != len(tris):
            raise ValueError(f"markers: {len(mk)} values for {len(tris)} triangles")
    return pts, tris, mk


def validate(points, triangles=None, *, markers=None):
    """The surface as tetrahedralize() meshes it, and what was repaired: exact duplicate
    vertices merged, duplicate triangles removed, each closed shell oriented outward
    (cavities inward). Returns (Surface, report), report one line per repair ("" if
    none). Raises tetrec.Error for what cannot be repaired (open surface,
    self-intersection, zero-area triangle, ...)."""
    p, t, m, report = _tetrec.validate(*_prepare(points, triangles, markers))
    return Surface(p, t, m), report


def tetrahedralize(points, triangles=None, *, markers=None, holes=None, regions=None,
                   keep_surface=False, keep_steiner=False, quality=None, max_volume=None,
                   optimize=None, keep_edges=False, subface_quality=None,
                   refine_budget=None, refine_partial=False, spacing_radii=True, exact=False,
                   smooth=True, round_budget=None, verbose=0, progress=None, threads=0,
                   sizing=None, resolve=False, surface_tolerance=None):
    """Tetrahedralizes the volume enclosed by a triangulated surface.

    points (n,3) floats and triangles (m,3) 0-based indices, or a Surface from read()
    as the only positional argument (its markers are used unless markers= is given).
    markers: one int32 per triangle, carried to the boundary faces.
    holes: rows (x, y, z), each point's cell is left empty. regions: rows (x, y, z,
    attribute, max_volume), the tets of each point's cell carry the attribute in
    .regions, and a max_volume > 0 bounds their volumes (quality refinement).
    keep_surface: no Steiner point on the surface, the boundary faces are exactly the
    input triangles (tetrec.Error when that cannot be done); with quality or max_volume,
    refinement then adds interior points only (subface_quality with it is an error).
    keep_steiner: the recovery's Steiner points stay on the input edges and facets (by
    default they are removed or moved inside where that can be done exactly). quality: R
    or (R, D), the radius-edge bound of constrained Delaunay refinement and a minimum
    dihedral angle D in degrees that sliver removal works towards (a warning counts the
    tets left under it); max_volume: refinement until every tet's volume is at most it.
    keep_edges: under refinement, every input edge stays a chain of mesh edges (by
    default the edges between exactly coplanar input triangles of the same marker are
    merged away, and refinement's sub-faces may cross them).
    optimize: sliver removal after refinement, 0 off, 1 flips, 2 flips and smoothing of
    interior points, 3 (default) also new points at slivers: interior ones, and
    exact ones on the input edges and facets under the worst tets.
    subface_quality: S >= 1, refinement also splits the boundary triangles whose
    radius-edge ratio is above S, except where a small input angle forces it, and
    splits an input-edge piece once under a boundary angle over 120 degrees.
    spacing_radii: True (default), refinement refuses a circumcentre only within a
    vertex's current spacing; no termination proof, so the radius-edge refinement stops
    (valid mesh, bad tets left) at 20 points per input point + 10,000; max_volume still
    holds. False: within its insertion radius, fewer points and less CPU, more tets over
    the ratio bound and more slivers on long thin parts.
    refine_budget: the points refinement may add before it stops (tetrec.Error,
    TR_ERR_NOMEM); by default 100 per input point + 100,000, + 20 per max_volume in
    the domain's volume, at most 2^24 or 8 per input point. A volume bound asking for
    more than 8 tets per budget point raises TR_ERR_NOMEM before refinement starts.
    refine_partial: at the budget, return the mesh made so far instead (valid and
    conforming, the bounds not met everywhere; sliver removal adds no point to it), with
    a UserWarning and stats["refine_budget_reached"] = 1; stats["tets_over_bounds"]
    counts its tets over the radius-edge or volume bound (the CLI writes such a mesh and
    exits 8).
    sizing: a size field, one target edge length per point of points (a float array of
    length n; 0: no bound at that point), interpolated linearly in between: refinement
    (on by itself) splits every tet whose longest edge is over the mean of its vertices'
    sizes, and every boundary edge and triangle that is (not under keep_surface); it
    composes with quality and max_volume. A field asking for more points than the
    budget raises TR_ERR_NOMEM before refinement starts.
    resolve: True meshes the solid of a self-intersecting or defective surface, the cells
    where the input's winding number is >= 1, bounded by the exact arrangement of its
    triangles; "internal" also keeps the pieces between two solid cells as internal
    facets. A surface whose winding number is not defined (open, or triangles oriented
    against their neighbours) raises tetrec.Error (TR_ERR_OPEN) naming the edge; one that
    already bounds its solid is meshed as without resolve. Boundary vertices that are
    rational points are meshed exactly; with them, surface_tolerance and holes are not
    implemented yet (TR_ERR_UNSUPPORTED naming the mode; regions work).
    Options the C library does not offer raise NotImplementedError
    (tetrec.SUPPORTED_OPTIONS lists what it offers).
    exact: the exact mesh is what is kept (tr_options.keep_exact, the CLI's --exact):
    Mesh.exact_points() holds it, every tet positive on them, and Mesh.write() defaults
    to writing the exact rationals (to a .node file; other formats refuse a mesh whose
    tets are not all positive in doubles). Mesh.points are then the nearest doubles,
    not repaired: a mesh is returned even where no doubles keep every tet positive (with
    resolve, two exact corners that share a nearest double), and no time goes to the
    repair.
    smooth: surface diagonal swaps before recovery. round_budget: star checks the
    rounding repair may spend. verbose: 0 quiet, 1 normal, 2 chatty (on stderr).
    progress: called as progress(stage, fraction) at the start (0.0) and end (1.0) of
    each pipeline stage; a true return value or an exception cancels the run (then
    tetrec.Error with status TR_ERR_CANCELLED, or the exception). Ctrl-C cancels too.
    threads: threads for the Delaunay stage, 0 (default) every core; the mesh is the
    same for any value.
    surface_tolerance: EPS > 0, the surface may be re-triangulated (edge collapses)
    within EPS times the bounding box diagonal of the input, both ways, proven
    (stats["surface_tolerance_bound"] measures it); sharp edges, marker boundaries and
    segments stay (docs/simplify.md). The mesh's boundary is then that surface.

    Returns a Mesh; raises tetrec.Error (.status, .code, .message) when the library
    refuses the input (open surface, self-intersection, ...).
    """
    # Every option that is not at its default goes to the C layer, which raises
    # NotImplementedError for any it does not know: none is dropped on the way.
    options = {name: value for name, value in (("holes", holes), ("regions", regions),
                                               ("quality", quality),
                                               ("max_volume", max_volume),
                                               ("optimize", optimize),
                                               ("subface_quality", subface_quality),
                                               ("refine_budget", refine_budget),
                                               ("round_budget", round_budget),
                                               ("surface_tolerance", surface_tolerance))
               if value is not None}
    if keep_surface:
        options["keep_surface"] = keep_surface
    if keep_steiner:
        options["keep_steiner"] = keep_steiner
    if exact:
        options["exact"] = True
    # flags, not truth values: keep_edges="no" must not turn it on
    for name, flag, default in (("keep_edges", keep_edges, False),
                                ("spacing_radii", spacing_radii, True),
                                ("refine_partial", refine_partial, False)):
        if not isinstance(flag, (bool, np.bool_)):
            raise TypeError(f"{name} must be True or False, not {type(flag).__name__}")
        if bool(flag) != default:
            options[name] = bool(flag)
    if resolve is not False:
        if resolve is True or (isinstance(resolve, np.bool_) and resolve):
            options["resolve"] = 1
        elif resolve == "internal":
            options["resolve"] = 2
        elif not (resolve is None or (isinstance(resolve, np.bool_) and not resolve)):
            raise ValueError(f"resolve is True, False or 'internal', not {resolve!r}")
    if not smooth:
        options["smooth"] = 0
    if verbose:
        options["verbose"] = int(verbose)
    if progress is not None:
        options["progress"] = progress
    if threads:
        options["threads"] = int(threads)
    # the refinement options act only when refinement runs: say so rather than drop them
    refined = (quality is not None or (max_volume is not None and max_volume > 0) or
               sizing is not None)
    if regions is not None and not refined:
        try:
            r = np.asarray(regions, dtype=float)
            refined = r.ndim == 2 and r.shape[1] == 5 and bool(np.any(r[:, 4] > 0))
        except (TypeError, ValueError):
            refined = True  # malformed: the C layer names what is wrong with it
    if not refined:
        idle = [name for name in ("optimize", "subface_quality", "refine_budget", "keep_edges",
                                     "spacing_radii", "refine_partial")
                if name in options]
        if idle:
            warnings.warn(f"tetrahedralize({', '.join(idle)}): no effect without quality "
                          "refinement (quality, max_volume or a region's max_volume)",
                          stacklevel=2)
    pts, tris, mk = _prepare(points, triangles, markers)
    if sizing is not None:
        h = np.ascontiguousarray(sizing, dtype=np.float64)
        if h.ndim != 1 or len(h) != len(pts):
            raise ValueError(f"sizing: {h.shape} values for {len(pts)} points: one target "
                             "edge length per point")
        options["sizing"] = h
    handle, stats = _tetrec.tetrahedralize(pts, tris, mk, options)
    if stats.get("refine_budget_reached"):
        warnings.warn(f"tetrahedralize: refinement stopped at its point budget: the mesh is "
                      f"valid and conforming, but {stats['tets_over_bounds']} of its "
                      f"{stats['volume_elements']} tets are over the bounds (raise "
                      "refine_budget or relax quality/max_volume)", stacklevel=2)
    return Mesh(handle, stats, bool(exact))
