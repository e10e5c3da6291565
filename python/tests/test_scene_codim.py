"""Codimensional, 2D and plane scenes (Scene.add_edge_mesh, add_points, add_plane,
Scene(dimension=2)): find_contacts must return exactly the colliding pairs found by enumerating
every pair of the scene in Python and deciding each with the pair functions (vertex_face_ccd,
edge_edge_ccd, point_edge_ccd, point_point_ccd, point_plane_ccd; in 2D point_edge_ccd /
point_point_ccd on 2-vectors, C++ point_edge_ccd_2d / point_point_ccd_2d), with identical TOIs;
earliest_contact must equal find_contacts().earliest.

The pairs of a scene (exactccd/scene.hpp): in 3D every vertex against every triangle
(vertex-face), every edge against every edge (edge-edge), every point (a vertex of an edge mesh
or point set on none of its edges) against every edge (point-edge) and every other point
(point-point), every vertex of a moving mesh against every plane (point-plane); in 2D every
vertex against every edge it is not on (point-edge) and points against points. Pairs within one
mesh only with self_collision and for a moving mesh, never sharing a vertex; never two static
meshes."""

import itertools

import numpy as np
import pytest

import exactccd

# ---------------------------------------------------------------------------------------------
# The scene as the test describes it (independently of the Scene's own bookkeeping).


class Mesh:
    """kind: "triangles", "edges", "points" or "plane"."""

    def __init__(self, kind, start=None, end=None, faces=None, edges=None, static=False,
                 origin=None, normal=None):
        self.kind, self.static = kind, static
        self.start = None if start is None else np.asarray(start, dtype=float)
        self.end = self.start if end is None else np.asarray(end, dtype=float)
        self.faces = np.zeros((0, 3), dtype=np.int64) if faces is None else np.asarray(faces)
        if kind == "triangles":
            sides = {tuple(sorted((int(f[i]), int(f[(i + 1) % 3])))) for f in self.faces
                     for i in range(3)}
            edges = sorted(sides)
        self.edges = (np.zeros((0, 2), dtype=np.int64) if edges is None or len(edges) == 0
                      else np.asarray(edges, dtype=np.int64))
        self.origin, self.normal = origin, normal

    @property
    def vertex_count(self):
        return 0 if self.kind == "plane" else len(self.start)

    @property
    def moving(self):
        return self.kind != "plane" and not self.static

    def points(self):
        """Vertices on none of the mesh's edges, for edge meshes and point sets."""
        if self.kind not in ("edges", "points"):
            return []
        on_edge = set(self.edges.ravel().tolist())
        return [v for v in range(self.vertex_count) if v not in on_edge]


def add_to_scene(scene, mesh):
    if mesh.kind == "plane":
        return scene.add_plane(mesh.origin, mesh.normal)
    if mesh.kind == "triangles":
        add = scene.add_static_mesh if mesh.static else scene.add_mesh
        mid = add(mesh.start, mesh.faces)
    elif mesh.kind == "edges":
        mid = scene.add_edge_mesh(mesh.start, mesh.edges, static=mesh.static)
    else:
        mid = scene.add_points(mesh.start)
    if mesh.moving:
        scene.set_motion(mid, mesh.start, mesh.end)
    return mid


def build(meshes, dimension=3, as_2d=()):
    """The Scene; in 2D, the meshes numbered in as_2d given as (V, 2) arrays."""
    scene = exactccd.Scene(dimension)
    for k, mesh in enumerate(meshes):
        if k in as_2d:
            flat = Mesh(mesh.kind, mesh.start[:, :2], mesh.end[:, :2], mesh.faces, mesh.edges,
                        mesh.static)
            assert add_to_scene(scene, flat) == k
        else:
            assert add_to_scene(scene, mesh) == k
    return scene


# ---------------------------------------------------------------------------------------------
# Every pair of the scene, in Python.


def mesh_pairs(meshes, self_collision):
    n = len(meshes)
    for a in range(n):
        for b in range(a, n):
            if "plane" in (meshes[a].kind, meshes[b].kind):
                continue
            if a == b and not (self_collision and meshes[a].moving):
                continue
            if a != b and meshes[a].static and meshes[b].static:
                continue
            yield a, b


def all_pairs(meshes, dimension, self_collision):
    """Every pair of the scene, each with the pair function's query: (type, a, i, b, j, rows)."""
    pairs = []

    def ordered(a, b):
        return [(a, b)] if a == b else [(a, b), (b, a)]

    for a, b in mesh_pairs(meshes, self_collision):
        for x, y in ordered(a, b):
            mx, my = meshes[x], meshes[y]
            if dimension == 3:
                for v in range(mx.vertex_count):
                    for f, face in enumerate(my.faces):
                        if x == y and v in face:
                            continue
                        rows = [mx.start[v], *my.start[face], mx.end[v], *my.end[face]]
                        pairs.append(("vertex-face", x, v, y, f, rows))
            # Point-edge: in 3D the points, in 2D every vertex not on the edge.
            vertices = mx.points() if dimension == 3 else range(mx.vertex_count)
            for v in vertices:
                for e, (e0, e1) in enumerate(my.edges):
                    if x == y and v in (e0, e1):
                        continue
                    rows = [mx.start[v], my.start[e0], my.start[e1], mx.end[v], my.end[e0],
                            my.end[e1]]
                    pairs.append(("point-edge", x, v, y, e, rows))
        ma, mb = meshes[a], meshes[b]
        if dimension == 3:
            for i, j in itertools.product(range(len(ma.edges)), range(len(mb.edges))):
                if a == b and (j <= i or set(ma.edges[i]) & set(mb.edges[j])):
                    continue
                (a0, a1), (b0, b1) = ma.edges[i], mb.edges[j]
                rows = [ma.start[a0], ma.start[a1], mb.start[b0], mb.start[b1], ma.end[a0],
                        ma.end[a1], mb.end[b0], mb.end[b1]]
                pairs.append(("edge-edge", a, i, b, j, rows))
        for i, j in itertools.product(ma.points(), mb.points()):
            if a == b and j <= i:
                continue
            rows = [ma.start[i], mb.start[j], ma.end[i], mb.end[j]]
            pairs.append(("point-point", a, i, b, j, rows))
    for p, plane in enumerate(meshes):
        if plane.kind != "plane":
            continue
        for m, mesh in enumerate(meshes):
            if not mesh.moving:
                continue
            for v in range(mesh.vertex_count):
                rows = [mesh.start[v], plane.origin, plane.normal, mesh.end[v], plane.origin,
                        plane.normal]
                pairs.append(("point-plane", m, v, p, 0, rows))
    return pairs


def decide(kind, rows, dimension, **options):
    if dimension == 2:
        rows = [np.asarray(r)[:2] for r in rows]  # the pair functions' 2D form
    function = {"vertex-face": exactccd.vertex_face_ccd, "edge-edge": exactccd.edge_edge_ccd,
                "point-edge": exactccd.point_edge_ccd, "point-point": exactccd.point_point_ccd,
                "point-plane": exactccd.point_plane_ccd}[kind]
    return function(*rows, **options)


def brute_force(meshes, dimension, self_collision, **options):
    """{ScenePair: (toi_lo, toi_hi)} of every colliding pair, and the number of pairs."""
    found = {}
    pairs = all_pairs(meshes, dimension, self_collision)
    for kind, a, i, b, j, rows in pairs:
        r = decide(kind, rows, dimension, **options)
        if r.collides:
            found[exactccd.ScenePair(kind, a, i, b, j)] = (r.toi_lo, r.toi_hi)
    return found, pairs


QUERY = {"vertex-face": "vertex_face_query", "edge-edge": "edge_edge_query",
         "point-edge": "point_edge_query", "point-point": "point_point_query",
         "point-plane": "point_plane_query"}


def check_scene(scene, meshes, dimension, self_collision, t_max=1.0, min_separation=0.0):
    """find_contacts equals the brute force, earliest_contact its earliest; returns the
    contacts' kinds (to check the scene is not vacuous)."""
    options = dict(t_max=t_max, min_separation=min_separation)
    expected, pairs = brute_force(meshes, dimension, self_collision, **options)
    result = scene.find_contacts(self_collision=self_collision, record_candidates=True, **options)
    got = {c.pair: (c.toi_lo, c.toi_hi) for c in result.contacts}
    assert len(got) == len(result.contacts)  # no pair twice
    missing = sorted(set(expected) - set(got))
    extra = sorted(set(got) - set(expected))
    assert not missing and not extra, f"missing {missing[:5]}, extra {extra[:5]}"
    for pair, toi in expected.items():
        assert got[pair] == toi, f"{pair}: scene {got[pair]}, pair function {toi}"
    # In pair order, the earliest the smallest toi_lo (ties: pair order).
    assert [c.pair for c in result.contacts] == sorted(got)
    candidates = set(result.candidates)
    assert set(got) <= candidates
    all_keys = {exactccd.ScenePair(k, a, i, b, j) for k, a, i, b, j, _ in pairs}
    assert candidates <= all_keys, sorted(candidates - all_keys)[:5]
    # Each contact's query from the scene is the one the test built.
    rows = {exactccd.ScenePair(k, a, i, b, j): r for k, a, i, b, j, r in pairs}
    for pair in got:
        query = getattr(scene, QUERY[str(pair.type)])(pair)
        assert np.array_equal(query, np.array(rows[pair])), pair
    # The earliest.
    first = scene.earliest_contact(self_collision=self_collision, **options)
    if expected:
        lo = min(lo for lo, _ in expected.values())
        pair = min(p for p, (l, _) in expected.items() if l == lo)
        assert result.earliest.pair == pair
        assert (result.earliest.toi_lo, result.earliest.toi_hi) == expected[pair]
        assert first.collides
        assert first.contact.pair == result.earliest.pair
        assert (first.contact.toi_lo, first.contact.toi_hi) == expected[pair]
    else:
        assert result.earliest.toi_lo == np.inf and not first.collides
        assert first.contact.toi_lo == np.inf
    counts = result.stats
    point_kinds = sum(1 for p in result.candidates
                      if p.type in ("point-edge", "point-point", "point-plane"))
    assert counts.point_candidates == point_kinds
    assert "point_candidates=" in repr(counts)
    return {str(p.type) for p in got}


# ---------------------------------------------------------------------------------------------
# Random scenes.


def motion(rng, start, scale):
    return start + rng.uniform(-scale, scale, size=start.shape)


def sheet(rng, n, z, jitter):
    xs, ys = np.meshgrid(np.linspace(0.1, 0.9, n), np.linspace(0.1, 0.9, n))
    vertices = np.stack([xs.ravel(), ys.ravel(), np.full(n * n, z)], axis=1)
    vertices += rng.uniform(-jitter, jitter, size=vertices.shape)
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            faces += [[a, b, d], [a, d, c]]
    return vertices, np.array(faces, dtype=np.int64)


def rod(rng, n, extra_points):
    """A random polyline of n vertices in the unit cube, then extra_points vertices on no edge
    (points of the edge mesh); one edge given the other way round (the numbering is as given)."""
    vertices = rng.uniform(0, 1, size=(n + extra_points, 3))
    edges = [[k, k + 1] for k in range(n - 1)]
    edges[1] = edges[1][::-1]
    return vertices, np.array(edges, dtype=np.int64)


# Points and segments in general position and motion almost never meet in 3D (a point meets a
# moving segment on a set of measure zero): the plane z = PLANE_Z and the line y = LINE_Y,
# z = PLANE_Z hold primitives that stay in them, so that point-edge contacts (in the plane) and
# point-point contacts (on the line) happen at delta = 0 too.
PLANE_Z, LINE_Y = 0.75, 0.25


def in_plane(rng, count):
    v = rng.uniform(0, 1, size=(count, 3))
    v[:, 2] = PLANE_Z
    return v


def on_line(rng, count):
    v = in_plane(rng, count)
    v[:, 1] = LINE_Y
    return v


def constrained_motion(rng, start, scale, kinds):
    """kinds[i]: "free" (any motion), "plane" (stays in z = PLANE_Z), "line" (moves along x)."""
    end = motion(rng, start, scale)
    for i, kind in enumerate(kinds):
        if kind in ("plane", "line"):
            end[i, 2] = start[i, 2]
        if kind == "line":
            end[i, 1] = start[i, 1]
    return end


def scene_3d(seed):
    rng = np.random.default_rng(seed)
    tri, faces = sheet(rng, 3, 0.5, 0.1)
    ground, ground_faces = sheet(rng, 3, 0.3, 0.1)
    # A rod in the plane, with a point of its own in the plane and one on the line.
    _, rod_edges = rod(rng, 6, 0)  # its topology; its 6 + 2 vertices:
    rod_start = np.concatenate([in_plane(rng, 7), on_line(rng, 1)])
    rod_kinds = ["plane"] * 7 + ["line"]
    wire_start, wire_edges = rod(rng, 4, 0)
    points = np.concatenate([rng.uniform(0, 1, size=(3, 3)), in_plane(rng, 3), on_line(rng, 3)])
    point_kinds = ["free"] * 3 + ["plane"] * 3 + ["line"] * 3
    normal = np.array([rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), 1.0])
    return [
        Mesh("triangles", tri, motion(rng, tri, 0.4), faces=faces),
        Mesh("edges", rod_start, constrained_motion(rng, rod_start, 0.5, rod_kinds),
             edges=rod_edges),
        Mesh("plane", origin=np.array([0.5, 0.5, 0.4]), normal=normal),
        Mesh("points", points, constrained_motion(rng, points, 0.5, point_kinds)),
        Mesh("triangles", ground, faces=ground_faces, static=True),
        Mesh("edges", wire_start, edges=wire_edges, static=True),
        Mesh("plane", origin=np.array([0.0, 0.9, 0.0]), normal=np.array([0.0, -3.0, 0.5])),
    ]


def scene_2d(seed):
    """Two moving edge meshes (an open chain with a point of its own, a closed loop), a point
    set and static walls with a static point; some points move along the line y = LINE_Y, so
    that point-point contacts happen at delta = 0 too."""
    rng = np.random.default_rng(seed)

    def flat(v):
        return np.concatenate([v, np.zeros((len(v), 1))], axis=1)

    def moved(v, scale, on_line=()):
        end = flat(motion(rng, v[:, :2], scale))
        end[list(on_line), 1] = v[list(on_line), 1]
        return end

    chain = flat(rng.uniform(0, 1, size=(7, 2)))  # 6 on the polyline, 1 point
    chain[6, 1] = LINE_Y
    chain_edges = np.array([[0, 1], [2, 1], [2, 3], [3, 4], [4, 5]])
    loop = flat(rng.uniform(0, 1, size=(4, 2)))
    loop_edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    points = flat(rng.uniform(0, 1, size=(8, 2)))
    points[5:, 1] = LINE_Y
    walls = flat(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, LINE_Y]]))
    wall_edges = np.array([[0, 1], [1, 2], [3, 0]])  # vertex 4 a static point, on the line
    return [
        Mesh("edges", chain, moved(chain, 0.5, on_line=[6]), edges=chain_edges),
        Mesh("points", points, moved(points, 0.6, on_line=[5, 6, 7])),
        Mesh("edges", walls, edges=wall_edges, static=True),
        Mesh("edges", loop, moved(loop, 0.5), edges=loop_edges),
    ]


OPTIONS = [
    pytest.param(dict(self_collision=True, min_separation=0.0), id="self-contact"),
    pytest.param(dict(self_collision=False, min_separation=0.0), id="no-self-contact"),
    pytest.param(dict(self_collision=True, min_separation=0.03), id="self-delta"),
    pytest.param(dict(self_collision=False, min_separation=0.03, t_max=0.6),
                 id="no-self-delta-tmax"),
]


@pytest.mark.parametrize("options", OPTIONS)
def test_3d_scene_equals_every_pair(options):
    kinds = set()
    for seed in range(8):
        meshes = scene_3d(seed)
        scene = build(meshes)
        assert scene.dimension == 3
        assert [scene.is_plane(k) for k in range(len(meshes))] == \
            [m.kind == "plane" for m in meshes]
        for k, mesh in enumerate(meshes):
            if mesh.kind != "plane":
                assert np.array_equal(scene.edges(k), mesh.edges)
        kinds |= check_scene(scene, meshes, 3, **options)
    expected = {"vertex-face", "edge-edge", "point-edge", "point-point", "point-plane"}
    assert kinds == expected, f"no contact of the kinds {expected - kinds}: a vacuous test"


@pytest.mark.parametrize("options", OPTIONS)
def test_2d_scene_equals_every_pair(options):
    kinds = set()
    for seed in range(10):
        meshes = scene_2d(seed)
        # Mesh 0 and 2 given as (V, 2) arrays, 1 and 3 as (V, 3) with z = 0.
        scene = build(meshes, dimension=2, as_2d=(0, 2))
        assert scene.dimension == 2
        for k, mesh in enumerate(meshes):
            assert np.array_equal(scene.start_positions(k), mesh.start)  # (V, 3), z = 0
            assert np.array_equal(scene.end_positions(k), mesh.end)
        kinds |= check_scene(scene, meshes, 2, **options)
    assert kinds == {"point-edge", "point-point"}


def test_a_rod_through_a_point_set_on_a_floor():
    """A small hand-made scene: a rod falls onto a plane through a cloud of points; every
    contact's kind, the earliest, and the contact geometry of the point kinds."""
    rod_start = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [2.0, 0.0, 1.0]])
    rod_end = rod_start - [0.0, 0.0, 2.0]
    points = np.array([[0.5, 0.0, 0.5], [1.5, 0.0, 0.25], [5.0, 5.0, 5.0]])
    scene = exactccd.Scene()
    rod_id = scene.add_edge_mesh(rod_start, [[0, 1], [1, 2]])
    scene.set_motion(rod_id, rod_start, rod_end)
    cloud = scene.add_points(points)
    floor = scene.add_plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    assert scene.plane(floor)[0].shape == (3,)
    assert np.array_equal(scene.plane(floor)[1], [0.0, 0.0, 1.0])
    assert scene.start_positions(floor).shape == (0, 3) and scene.edges(cloud).shape == (0, 2)
    result = scene.find_contacts()
    got = {(str(c.pair.type), c.pair.first_mesh, c.pair.first_index, c.pair.second_mesh,
            c.pair.second_index): (c.toi_lo, c.toi_hi) for c in result.contacts}
    # Point 0 (at height 0.5) meets edge 0 at t = 0.25, point 1 (0.25) edge 1 at t = 0.375; the
    # rod's vertices meet the floor at t = 0.5; the points stand still (no floor pairs).
    assert got == {("point-edge", cloud, 0, rod_id, 0): (0.25, 0.25),
                   ("point-edge", cloud, 1, rod_id, 1): (0.375, 0.375),
                   ("point-plane", rod_id, 0, floor, 0): (0.5, 0.5),
                   ("point-plane", rod_id, 1, floor, 0): (0.5, 0.5),
                   ("point-plane", rod_id, 2, floor, 0): (0.5, 0.5)}
    assert result.earliest.pair == exactccd.ScenePair("pe", cloud, 0, rod_id, 0)
    assert result.earliest.pair.type is exactccd.QueryType.point_edge
    assert exactccd.QueryType.point_plane == "point-plane"
    assert exactccd.QueryType("point-point") is exactccd.QueryType.point_point
    pe = next(c for c in result.contacts if c.pair.type == "point-edge")
    geometry = scene.contact_geometry(pe)
    assert (geometry.point[:, 0] <= [0.5, 0.0, 0.5]).all()  # an enclosure [lo, hi] per axis
    assert ([0.5, 0.0, 0.5] <= geometry.point[:, 1]).all()
    pl = next(c for c in result.contacts if c.pair.type == "point-plane")
    plane_geometry = scene.contact_geometry(pl)  # the floor's unit normal, from above
    assert plane_geometry.kind == "point"
    assert plane_geometry.normal_oriented
    assert (plane_geometry.normal[:, 0] <= [0, 0, 1]).all()
    assert ([0, 0, 1] <= plane_geometry.normal[:, 1]).all()
    assert np.array_equal(scene.point_plane_query(pl.pair),
                          [rod_start[0], [0, 0, 0], [0, 0, 1], rod_end[0], [0, 0, 0], [0, 0, 1]])
    # A point set against itself: point-point pairs.
    pp = exactccd.Scene()
    cloud = pp.add_points([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    pp.set_motion(cloud, [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    (contact,) = pp.find_contacts().contacts
    assert contact.pair == exactccd.ScenePair("point-point", 0, 0, 0, 1)
    assert (contact.toi_lo, contact.toi_hi) == (0.5, 0.5)
    assert pp.point_point_query(contact.pair).shape == (4, 3)
    assert pp.find_contacts(self_collision=False).contacts == []


def test_pair_type_names():
    for name, short in (("vertex-face", "vf"), ("edge-edge", "ee"), ("point-edge", "pe"),
                        ("point-point", "pp"), ("point-plane", "pl")):
        long_pair = exactccd.ScenePair(name, 0, 1, 2, 3)
        assert long_pair == exactccd.ScenePair(short, 0, 1, 2, 3)
        assert long_pair == exactccd.ScenePair(exactccd.QueryType(name), 0, 1, 2, 3)
        assert long_pair.type == name and isinstance(long_pair.type, exactccd.QueryType)
        assert repr(long_pair) == f"ScenePair('{name}', 0, 1, 2, 3)"
    with pytest.raises(ValueError, match="point-plane"):
        exactccd.ScenePair("point-triangle", 0, 0, 0, 0)


# ---------------------------------------------------------------------------------------------
# Errors.


def test_bad_dimension():
    for bad in (1, 4, 0, -3, 2.0, 3.5, True, "3", None):
        with pytest.raises((ValueError, TypeError), match="dimension must be 3 or 2"):
            exactccd.Scene(bad)
    assert exactccd.Scene(dimension=2).dimension == 2
    assert exactccd.Scene(np.int32(3)).dimension == 3


def test_2d_scene_errors():
    scene = exactccd.Scene(2)
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    with pytest.raises(ValueError, match="z = 0"):
        scene.add_edge_mesh([[0.0, 0.0, 0.0], [1.0, 0.0, 1e-300]], [[0, 1]])
    with pytest.raises(ValueError, match="z = 0"):
        scene.add_points([[0.0, 0.0, 0.5]])
    with pytest.raises(ValueError, match="z = 0"):
        scene.add_edge_mesh([[0.0, 0.0, 0.0], [1.0, 0.0, 1.0]], [[0, 1]], static=True)
    with pytest.raises(ValueError, match=r"\(N, 2\) or \(N, 3\)"):
        scene.add_points(np.zeros((3, 4)))
    with pytest.raises(ValueError, match=r"\(N, 2\) or \(N, 3\)"):
        scene.add_points([1.0, 2.0])
    with pytest.raises(ValueError, match="2D"):
        scene.add_mesh(np.zeros((3, 3)), [[0, 1, 2]])
    with pytest.raises(ValueError, match="2D"):
        scene.add_static_mesh(np.zeros((3, 3)), [[0, 1, 2]])
    with pytest.raises(ValueError):
        scene.add_rigid_body(np.zeros((3, 3)), [[0, 1, 2]])
    with pytest.raises(ValueError, match="2D"):
        scene.add_plane([0, 0, 0], [0, 1, 0])
    mesh = scene.add_edge_mesh(square, [[0, 1], [1, 2]])
    with pytest.raises(ValueError, match="z = 0"):
        scene.set_motion(mesh, square, np.concatenate([square, np.ones((3, 1))], axis=1))
    scene.set_motion(mesh, square, square + 0.5)  # (V, 2) accepted
    assert np.array_equal(scene.end_positions(mesh)[:, :2], square + 0.5)
    # A 3D scene takes (V, 3) only.
    with pytest.raises(ValueError, match="shape"):
        exactccd.Scene().add_points(square)
    with pytest.raises(ValueError, match="repeats|twice"):
        exactccd.Scene().add_edge_mesh(np.zeros((3, 3)), [[0, 1], [1, 0]])
    with pytest.raises(ValueError, match="repeats"):
        exactccd.Scene().add_edge_mesh(np.zeros((3, 3)), [[1, 1]])
    with pytest.raises(ValueError, match="out of range"):
        exactccd.Scene().add_edge_mesh(np.zeros((3, 3)), [[0, 3]])
    with pytest.raises(TypeError, match="integer"):
        exactccd.Scene().add_edge_mesh(np.zeros((3, 3)), [[0.0, 1.0]])


def test_plane_errors():
    scene = exactccd.Scene()
    with pytest.raises(ValueError, match="zero"):
        scene.add_plane([0, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="non-finite"):
        scene.add_plane([0, 0, np.nan], [0, 0, 1])
    with pytest.raises(ValueError, match="non-finite"):
        scene.add_plane([0, 0, 0], [0, np.inf, 1])
    with pytest.raises(ValueError, match="shape"):
        scene.add_plane([0, 0], [0, 0, 1])
    points = scene.add_points([[0.0, 0.0, 1.0]])
    floor = scene.add_plane([0, 0, 0], [0, 0, 1])
    with pytest.raises(ValueError, match="not a plane"):
        scene.plane(points)
    with pytest.raises(IndexError):
        scene.plane(7)
    with pytest.raises(ValueError):
        scene.set_motion(floor, np.zeros((0, 3)), np.zeros((0, 3)))


def test_rigid_body_falling_on_a_plane():
    # A rigid triangle turning and falling onto a floor: its point-plane contacts are exactly
    # each vertex decided by rigid_point_plane_ccd.
    scene = exactccd.Scene()
    tri = np.array([[0.0, 0.0, 0.5], [1.0, 0.0, 0.75], [0.0, 1.0, 1.0]])
    body = scene.add_rigid_body(tri, [[0, 1, 2]])
    motion = exactccd.RigidMotion(pivot=(0.25, 0.25, 0.75), translation=(0, 0, -0.75),
                                  cayley=(0.25, -0.125, 0))
    scene.set_rigid_motion(body, motion)
    floor = scene.add_plane([0, 0, 0], [0, 0, 2])
    for delta in (0.0, 0.05):
        got = [c for c in scene.find_contacts(min_separation=delta).contacts
               if c.pair.type == "point-plane"]
        want = []
        for v in range(3):
            r = exactccd.rigid_point_plane_ccd(tri[v], motion, [0, 0, 0], [0, 0, 2],
                                               min_separation=delta)
            if r.collides:
                want.append((v, r.toi_lo, r.toi_hi))
        assert want, "the body should reach the floor"
        assert [(c.pair.first_index, c.toi_lo, c.toi_hi) for c in got] == want
        assert all(c.pair.first_mesh == body and c.pair.second_mesh == floor for c in got)
    # The contact geometry on request: the floor's unit normal, from above.
    hits = [exactccd.rigid_point_plane_ccd(x, motion, [0, 0, 0], [0, 0, 2], contact=True)
            for x in tri]
    assert any(r.collides for r in hits)
    for r in hits:
        if r.collides:
            assert r.contact.kind == "point" and r.contact.normal_oriented
            assert np.array_equal(r.contact.normal[2], [1.0, 1.0])
        else:
            assert r.contact is None
    with pytest.raises(ValueError, match="certified mode"):
        exactccd.rigid_point_plane_ccd(tri[0], motion, [0, 0, 0], [0, 0, 2], contact=True,
                                       mode="float_only")
    with pytest.raises(TypeError, match="RigidMotion"):
        exactccd.rigid_point_plane_ccd(tri[0], None, [0, 0, 0], [0, 0, 1])
    with pytest.raises(ValueError, match="normal"):
        exactccd.rigid_point_plane_ccd(tri[0], motion, [0, 0, 0], [0, 0, 0])


def test_pair_query_errors():
    scene = exactccd.Scene()
    rod_id = scene.add_edge_mesh(np.eye(3), [[0, 1], [1, 2]])
    cloud = scene.add_points([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    floor = scene.add_plane([0, 0, 0], [0, 0, 1])
    tri = scene.add_mesh(np.eye(3), [[0, 1, 2]])
    pe = exactccd.ScenePair("point-edge", cloud, 0, rod_id, 1)
    assert scene.point_edge_query(pe).shape == (6, 3)
    for bad in (exactccd.ScenePair("point-edge", cloud, 2, rod_id, 0),
                exactccd.ScenePair("point-edge", cloud, 0, rod_id, 2),
                exactccd.ScenePair("point-edge", cloud, 0, cloud, 0),  # a point set: no edges
                exactccd.ScenePair("point-edge", cloud, 0, 9, 0)):
        with pytest.raises(IndexError):
            scene.point_edge_query(bad)
    with pytest.raises(ValueError, match="point-edge pair"):
        scene.point_edge_query(exactccd.ScenePair("pp", cloud, 0, cloud, 1))
    assert scene.point_point_query(exactccd.ScenePair("pp", cloud, 0, cloud, 1)).shape == (4, 3)
    with pytest.raises(IndexError):
        scene.point_point_query(exactccd.ScenePair("pp", cloud, 0, cloud, 2))
    with pytest.raises(IndexError):
        scene.point_point_query(exactccd.ScenePair("pp", cloud, 0, floor, 0))
    pl = exactccd.ScenePair("point-plane", rod_id, 2, floor, 0)
    assert scene.point_plane_query(pl).shape == (6, 3)
    with pytest.raises(IndexError):
        scene.point_plane_query(exactccd.ScenePair("point-plane", rod_id, 3, floor, 0))
    with pytest.raises(IndexError):
        scene.point_plane_query(exactccd.ScenePair("point-plane", rod_id, 0, floor, 1))
    with pytest.raises(ValueError, match="not a plane"):
        scene.point_plane_query(exactccd.ScenePair("point-plane", rod_id, 0, tri, 0))
    # The older kinds check their own indices: a vertex of the rod against the triangle, an
    # edge of the rod against an edge of the triangle.
    assert scene.vertex_face_query(exactccd.ScenePair("vf", rod_id, 2, tri, 0)).shape == (8, 3)
    with pytest.raises(IndexError):
        scene.vertex_face_query(exactccd.ScenePair("vf", rod_id, 0, rod_id, 0))
    assert scene.edge_edge_query(exactccd.ScenePair("ee", rod_id, 1, tri, 2)).shape == (8, 3)
    with pytest.raises(IndexError):
        scene.edge_edge_query(exactccd.ScenePair("ee", rod_id, 2, tri, 0))
    with pytest.raises(IndexError):
        scene.edge_edge_query(exactccd.ScenePair("ee", cloud, 0, tri, 0))
