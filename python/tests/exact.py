"""Exact checks of a tetrec.Mesh against its input surface, in rational arithmetic
(fractions.Fraction holds every double exactly), independent of the C validator."""
from collections import Counter
from fractions import Fraction


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def det(a, b, c, d):
    """det[b-a; c-a; d-a]: six times the signed volume of tet abcd."""
    return dot(sub(b, a), cross(sub(c, a), sub(d, a)))


def frac_points(points):
    return [tuple(Fraction(float(c)) for c in p) for p in points]


def enclosed_volume6(points, triangles, internal=()):
    """Six times the volume an outward-oriented closed surface encloses (divergence
    theorem: each triangle contributes det[a; b; c]); the triangles numbered in
    `internal` are facets inside the volume and add nothing."""
    o = (Fraction(0),) * 3
    pts = frac_points(points)
    return sum((det(o, pts[a], pts[b], pts[c]) for i, (a, b, c) in enumerate(triangles)
                if i not in internal), Fraction(0))


def tets_volume6(points, tets):
    return sum((det(*(points[v] for v in t)) for t in tets), Fraction(0))


def face_key(f):
    return tuple(sorted(int(v) for v in f))


def faces_of_tets(tets):
    """Counter of each unordered tet face."""
    c = Counter()
    for t in tets:
        a, b, cc, d = (int(v) for v in t)
        for f in ((b, cc, d), (a, cc, d), (a, b, d), (a, b, cc)):
            c[face_key(f)] += 1
    return c


def oriented_plane(a, b, c):
    """A key equal for every triangle in one plane with the same orientation."""
    n = cross(sub(b, a), sub(c, a))
    s = next(abs(x) for x in n if x != 0)
    n = tuple(x / s for x in n)
    return n, dot(n, a)


def in_closed_triangle(p, a, b, c, normal):
    """p in the closed triangle abc, p in its plane."""
    return all(dot(cross(sub(v, u), sub(p, u)), normal) >= 0
               for u, v in ((a, b), (b, c), (c, a)))


def check_boundary_covers_input(exact_pts, faces, in_points, in_tris):
    """The boundary faces tile the input surface: each lies in the plane of input
    triangles oriented like it, its centroid in one of them, and the faces in each
    oriented plane add up to the exact vector area of its input triangles (surface
    smoothing may swap diagonals between coplanar triangles, so the tiling is checked
    per plane). Returns, for each face, the input triangle holding its centroid."""
    ipts = frac_points(in_points)
    tris = [tuple(ipts[int(v)] for v in t) for t in in_tris]
    groups = {}
    for i, t in enumerate(tris):
        groups.setdefault(oriented_plane(*t), []).append(i)
    area = {k: (Fraction(0),) * 3 for k in groups}
    owner = []
    for f in faces:
        p = [exact_pts[int(v)] for v in f]
        key = oriented_plane(*p)
        assert key in groups, f"boundary face {list(f)} is in no plane of input triangles"
        g = (sum((q[k] for q in p), Fraction(0)) / 3 for k in range(3))
        g = tuple(g)
        inside = [i for i in groups[key] if in_closed_triangle(g, *tris[i], key[0])]
        assert inside, f"boundary face {list(f)} is outside the input triangles"
        owner.append(inside[0])
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        area[key] = tuple(x + y for x, y in zip(area[key], n))
    for key, members in groups.items():
        want = (Fraction(0),) * 3
        for i in members:
            a, b, c = tris[i]
            want = tuple(x + y for x, y in zip(want, cross(sub(b, a), sub(c, a))))
        assert area[key] == want, f"input triangles {members} are not covered exactly"
    return owner


def check_mesh(mesh, in_points, in_tris, internal=()):
    """The properties every mesh tetrec returns must have, checked exactly."""
    n = len(mesh.points)
    assert mesh.points.shape == (n, 3) and mesh.points.dtype.name == "float64"
    assert mesh.tets.ndim == 2 and mesh.tets.shape[1] == 4
    assert len(mesh.regions) == len(mesh.tets)
    assert mesh.boundary_faces.shape[1] == 3
    assert len(mesh.boundary_markers) == len(mesh.boundary_faces)
    # input points first, unchanged
    assert (mesh.points[:len(in_points)] == in_points).all()
    assert mesh.tets.max() < n
    dpts = frac_points(mesh.points)
    for t in mesh.tets:
        assert det(*(dpts[v] for v in t)) > 0, f"tet {list(t)} not positive in doubles"
    xpts = mesh.exact_points()
    assert xpts[:len(in_points)] == frac_points(in_points)
    for t in mesh.tets:
        assert det(*(xpts[v] for v in t)) > 0, f"tet {list(t)} not positive exactly"
    assert tets_volume6(xpts, mesh.tets) == enclosed_volume6(in_points, in_tris, internal)
    # conformity: each face in at most two tets; the faces in one tet are the boundary
    faces = faces_of_tets(mesh.tets)
    assert max(faces.values()) <= 2
    hull = {f for f, k in faces.items() if k == 1}
    listed = Counter(face_key(f) for f in mesh.boundary_faces)
    assert not listed or max(listed.values()) == 1
    assert hull <= set(listed)
    assert len(mesh.boundary_triangles) == len(mesh.boundary_faces)
    assert (mesh.boundary_triangles[:-1] <= mesh.boundary_triangles[1:]).all()
    owner = check_boundary_covers_input(xpts, mesh.boundary_faces, in_points, in_tris)
    # each face's own input triangle is in the plane of the one holding its centroid
    # (the same triangle unless smoothing swapped a diagonal between coplanar ones)
    ipts = frac_points(in_points)
    for f, t, o in zip(mesh.boundary_faces, mesh.boundary_triangles, owner):
        assert oriented_plane(*(ipts[int(v)] for v in in_tris[t])) == \
            oriented_plane(*(ipts[int(v)] for v in in_tris[o])), list(f)
    return owner


def check_faces_in_their_triangles(mesh, in_points, in_tris):
    """Without smoothing, each boundary face lies exactly in the input triangle it names
    and the faces of each triangle add up to its exact vector area."""
    ipts = frac_points(in_points)
    xpts = mesh.exact_points()
    area = {}
    for f, t in zip(mesh.boundary_faces, mesh.boundary_triangles):
        a, b, c = (ipts[int(v)] for v in in_tris[t])
        n = cross(sub(b, a), sub(c, a))
        p = [xpts[int(v)] for v in f]
        assert all(dot(sub(q, a), n) == 0 and in_closed_triangle(q, a, b, c, n) for q in p)
        fn = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        area[int(t)] = tuple(x + y for x, y in zip(area.get(int(t), (0, 0, 0)), fn))
    assert sorted(area) == list(range(len(in_tris)))
    for t, s in area.items():
        a, b, c = (ipts[int(v)] for v in in_tris[t])
        assert s == cross(sub(b, a), sub(c, a)), f"triangle {t} not covered exactly"


def _sign(x):
    return (x > 0) - (x < 0)


def winding_number(p, points, triangles):
    """The winding number of the closed soup (points exact, triangles oriented) about p,
    exactly: signed crossings of a ray from p, each +1 where the ray leaves through a
    triangle's outer side. A ray through an edge or a vertex, or p on a triangle, is
    degenerate: the next direction is tried; None if every one is."""
    for d in ((Fraction(1), Fraction(1, 3), Fraction(1, 7)),
              (Fraction(-1, 5), Fraction(1), Fraction(2, 11)),
              (Fraction(3, 13), Fraction(-2, 17), Fraction(1))):
        w = 0
        for t in triangles:
            u, v, x = (sub(points[int(i)], p) for i in t)
            s = [_sign(dot(cross(u, v), d)), _sign(dot(cross(v, x), d)),
                 _sign(dot(cross(x, u), d))]
            if 1 in s and -1 in s:
                continue  # the ray's line misses the triangle
            # p's side of the plane: the ray meets it ahead iff that is the sign in s
            side = _sign(dot(u, cross(v, x)))
            if 0 in s or side == 0:
                if side in (0, max(s, key=abs)):
                    break  # through an edge or a vertex ahead, or p on the plane
                continue
            if side == s[0]:
                w += s[0]
        else:
            return w
    return None
