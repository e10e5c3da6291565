"""The Scene API over numpy arrays: equal to the C++ Scene's answers (a separate C++ program on
the same scene) and to deciding every pair with the query API."""

import numpy as np
import pytest

import exactccd
from conftest import run


def grid(n, z, jitter, rng):
    """An n x n sheet of vertices in the plane z, triangulated."""
    xs, ys = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    vertices = np.stack([xs.ravel(), ys.ravel(), np.full(n * n, z)], axis=1)
    vertices += rng.uniform(-jitter, jitter, size=vertices.shape)
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            faces += [[a, b, d], [a, d, c]]
    return vertices, np.array(faces, dtype=np.int64)


@pytest.fixture()
def two_meshes():
    """A falling wavy sheet and a rising smaller sheet under it: they pass through each other."""
    rng = np.random.default_rng(7)
    top, top_faces = grid(5, 0.3, 0.02, rng)
    top_end = top + [0.05, 0.0, -0.6] + rng.uniform(-0.05, 0.05, size=top.shape)
    bottom, bottom_faces = grid(4, -0.1, 0.02, rng)
    bottom = bottom * [0.8, 0.8, 1] + [0.1, 0.1, 0]
    bottom_end = bottom + [0.0, 0.03, 0.2]
    return [(top, top_end, top_faces), (bottom, bottom_end, bottom_faces)]


def build(meshes):
    scene = exactccd.Scene()
    for start, end, faces in meshes:
        mesh = scene.add_mesh(start, faces)
        scene.set_motion(mesh, start, end)
    return scene


def write_scene(path, meshes):
    lines = [f"meshes {len(meshes)}"]
    for start, end, faces in meshes:
        lines.append(f"moving {len(start)} {len(faces)}")
        lines += [" ".join(float(x).hex() for x in (*s, *e)) for s, e in zip(start, end)]
        lines += [" ".join(str(int(i)) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def describe(pair):
    return (f"{pair.type} {pair.first_mesh} {pair.first_index} {pair.second_mesh} "
            f"{pair.second_index}")


def test_equal_to_cpp_scene(two_meshes, tmp_path, scene_reference):
    path = tmp_path / "scene.txt"
    write_scene(path, two_meshes)
    done = run([scene_reference, path])
    assert done.returncode == 0, done.stderr
    expected = done.stdout.splitlines()

    scene = build(two_meshes)
    result = scene.find_contacts(record_candidates=True)
    got = [f"contact {describe(c.pair)} {c.toi_lo.hex()} {c.toi_hi.hex()}" for c in result.contacts]
    got.append(f"candidates {len(result.candidates)} vf {result.stats.vertex_face_candidates} "
               f"ee {result.stats.edge_edge_candidates}")
    earliest = scene.earliest_contact(record_candidates=True)
    if earliest.collides:
        c = earliest.contact
        got.append(f"earliest {describe(c.pair)} {c.toi_lo.hex()} {c.toi_hi.hex()}")
    else:
        got.append("earliest none")
    # float.hex() and C's %a differ in spelling ("0x1.8p-1" both, but 0 is "0x0.0p+0" / "0x0p+0"):
    # compare the values.
    def values(lines):
        out = []
        for line in lines:
            fields = line.split()
            out.append([float.fromhex(f) if f.startswith(("0x", "-0x")) else f for f in fields])
        return out
    assert values(got) == values(expected)
    assert len(result.contacts) > 0  # the scene does collide: the comparison is not vacuous
    assert result.earliest.pair == earliest.contact.pair


def test_cross_mesh_contacts_equal_all_pairs(two_meshes):
    """Without self-collision, every contact is a pair of the two meshes: deciding all of them
    one by one must find exactly the scene's contacts and TOIs."""
    scene = build(two_meshes)
    result = scene.find_contacts(self_collision=False)
    expected = []
    n_vertices = [len(m[0]) for m in two_meshes]
    n_faces = [len(m[2]) for m in two_meshes]
    pairs, queries = [], []
    for a, b in ((0, 1), (1, 0)):
        for v in range(n_vertices[a]):
            for f in range(n_faces[b]):
                pair = exactccd.ScenePair("vertex-face", a, v, b, f)
                pairs.append(pair)
                queries.append(scene.vertex_face_query(pair))
    vf = exactccd.vertex_face_ccd_batch(np.array(queries))
    expected += [(p, lo, hi) for p, c, lo, hi in zip(pairs, vf.collides, vf.toi_lo, vf.toi_hi) if c]
    pairs, queries = [], []
    for e0 in range(len(scene.edges(0))):
        for e1 in range(len(scene.edges(1))):
            pair = exactccd.ScenePair("edge-edge", 0, e0, 1, e1)
            pairs.append(pair)
            queries.append(scene.edge_edge_query(pair))
    ee = exactccd.edge_edge_ccd_batch(np.array(queries))
    expected += [(p, lo, hi) for p, c, lo, hi in zip(pairs, ee.collides, ee.toi_lo, ee.toi_hi) if c]
    got = [(c.pair, c.toi_lo, c.toi_hi) for c in result.contacts]
    assert sorted(got, key=lambda x: x[0]) == sorted(expected, key=lambda x: x[0])
    assert len(got) > 0


def test_pair_types_are_an_enum_and_no_contact_is_infinity(two_meshes):
    scene = build(two_meshes)
    result = scene.find_contacts()
    types = {c.pair.type for c in result.contacts}
    assert types == {exactccd.QueryType.vertex_face, exactccd.QueryType.edge_edge}
    assert all(isinstance(t, exactccd.QueryType) for t in types)
    # Members are also their names in query files.
    assert exactccd.QueryType.vertex_face == "vertex-face"
    assert f"{exactccd.QueryType.edge_edge}" == "edge-edge"
    p = result.contacts[0].pair
    for kind in (p.type, str(p.type)):
        assert exactccd.ScenePair(kind, p.first_mesh, p.first_index, p.second_mesh,
                                  p.second_index) == p
    # Without a contact: +infinity TOIs, as in C++ (once, None).
    (start, _, faces), _ = two_meshes
    apart = exactccd.Scene()
    mesh = apart.add_mesh(start, faces)
    apart.set_motion(mesh, start, start + [0.0, 0.0, 0.1])
    apart.add_static_mesh(start + [0.0, 0.0, 10.0], faces)
    none = apart.find_contacts(self_collision=False)
    assert none.contacts == [] and none.earliest.toi_lo == none.earliest.toi_hi == np.inf
    first = apart.earliest_contact(self_collision=False)
    assert not first.collides and first.contact.toi_lo == first.contact.toi_hi == np.inf
    # With contacts, the earliest as before.
    assert result.earliest.toi_lo == min(c.toi_lo for c in result.contacts)


def test_mesh_accessors_and_static_mesh(two_meshes):
    (start, end, faces), (other, _, other_faces) = two_meshes
    scene = exactccd.Scene()
    moving = scene.add_mesh(start, faces)
    scene.set_motion(moving, start, end)
    fixed = scene.add_static_mesh(other, other_faces.astype(np.int32))
    assert scene.mesh_count == 2 and not scene.is_static(moving) and scene.is_static(fixed)
    assert np.array_equal(scene.triangles(moving), faces)
    assert np.array_equal(scene.start_positions(moving), start)
    assert np.array_equal(scene.end_positions(moving), end)
    assert np.array_equal(scene.end_positions(fixed), other)
    edges = scene.edges(moving)
    assert edges.shape[1] == 2 and (edges[:, 0] < edges[:, 1]).all()
    result = scene.find_contacts()
    assert all(c.pair.first_mesh == c.pair.second_mesh == moving or
               fixed in (c.pair.first_mesh, c.pair.second_mesh) for c in result.contacts)
    assert repr(result.stats).startswith("SceneStats(")


def test_bad_scene_input(two_meshes):
    (start, end, faces), _ = two_meshes
    scene = exactccd.Scene()
    with pytest.raises(ValueError, match="out of range|index"):
        scene.add_mesh(start, faces + len(start))
    with pytest.raises(ValueError):
        scene.add_mesh(start, -faces - 1)
    with pytest.raises(ValueError, match="out of range"):
        scene.add_mesh(start, np.full((1, 3), 2 ** 40))
    with pytest.raises(TypeError, match="integer"):
        scene.add_mesh(start, faces.astype(float))
    with pytest.raises(ValueError, match="shape"):
        scene.add_mesh(start[:, :2], faces)
    bad = start.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError):
        scene.add_mesh(bad, faces)
    mesh = scene.add_mesh(start, faces)
    with pytest.raises(ValueError):
        scene.set_motion(mesh, start, end[:-1])
    with pytest.raises(IndexError):
        scene.set_motion(mesh + 5, start, end)
    with pytest.raises(ValueError, match='mode must be "float_only", "filtered" or "exact"'):
        scene.find_contacts(mode="fast")
    with pytest.raises(ValueError, match="t_max"):
        scene.find_contacts(t_max=-1e-300)
    with pytest.raises(ValueError):
        scene.earliest_contact(broad_phase="static_bvh")
    for threads in (-1, 65537):  # TBB's arena crashed on 65537 before it was refused
        with pytest.raises(ValueError, match="max_threads"):
            scene.find_contacts(max_threads=threads)
        with pytest.raises(ValueError, match="max_threads"):
            scene.earliest_contact(max_threads=threads)
    with pytest.raises(IndexError):
        scene.vertex_face_query(exactccd.ScenePair("vf", 0, 10 ** 6, 0, 0))
    with pytest.raises(ValueError):
        scene.vertex_face_query(exactccd.ScenePair("ee", 0, 0, 0, 1))


def test_mode_filtered_and_its_old_name_default(two_meshes):
    # "filtered" is the default argument; "default", its old name, gives the same contacts.
    scene = build(two_meshes)
    runs = [[(c.pair, c.toi_lo, c.toi_hi) for c in scene.find_contacts(**options).contacts]
            for options in ({}, {"mode": "filtered"}, {"mode": "default"})]
    assert runs[0] and runs[0] == runs[1] == runs[2]
    first = [scene.earliest_contact(mode=mode) for mode in ("filtered", "default")]
    assert first[0].collides and first[1].collides
    assert first[0].contact.toi_lo == first[1].contact.toi_lo


def test_one_scene_from_several_python_threads(two_meshes):
    """Calls run without the GIL; the module serialises them on one Scene (the C++ Scene must
    not be used from two threads at once), so every thread gets the single-threaded answer."""
    import concurrent.futures
    scene = build(two_meshes)
    expected = [(c.pair, c.toi_lo, c.toi_hi) for c in scene.find_contacts().contacts]
    (start, end, _), _ = two_meshes

    def work(k):
        if k % 3 == 2:
            scene.set_motion(0, start, end)  # the same motion again: the answers do not change
            return expected
        return [(c.pair, c.toi_lo, c.toi_hi) for c in scene.find_contacts().contacts]

    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        for result in pool.map(work, range(24)):
            assert result == expected


def test_min_separation_equals_every_pair_with_delta():
    """Two sheets passing 0.01 apart: no contact, but every pair that comes within delta = 0.02
    is found (the boxes inflated by delta), each with the query API's answer at delta."""
    rng = np.random.default_rng(11)
    top, top_faces = grid(4, 0.2, 0.0, rng)
    bottom, bottom_faces = grid(4, 0.0, 0.0, rng)
    meshes = [(top, top + [0.3, 0.0, -0.19], top_faces), (bottom, bottom, bottom_faces)]
    scene = build(meshes)
    assert scene.find_contacts().contacts == []
    delta = 0.02
    result = scene.find_contacts(min_separation=delta, record_candidates=True)
    assert len(result.contacts) > 0
    expected = []
    for pair in result.candidates:
        if pair.type == "vertex-face":
            r = exactccd.vertex_face_ccd(*scene.vertex_face_query(pair), min_separation=delta)
        else:
            r = exactccd.edge_edge_ccd(*scene.edge_edge_query(pair), min_separation=delta)
        if r.collides:
            expected.append((pair, r.toi_lo, r.toi_hi))
    got = [(c.pair, c.toi_lo, c.toi_hi) for c in result.contacts]
    assert sorted(got, key=lambda x: x[0]) == sorted(expected, key=lambda x: x[0])
    earliest = scene.earliest_contact(min_separation=delta)
    assert earliest.contact.toi_lo == min(lo for _, lo, _ in expected)
    with pytest.raises(ValueError):
        scene.find_contacts(min_separation=-1.0)


def test_set_edges_keeps_the_simulators_numbering():
    # Two triangles falling onto a static one: the same contacts with libigl's edge order, the
    # edge-edge pairs indexing it.
    floor = np.array([[-2, -2, 0], [2, -2, 0], [0, 2, 0]], dtype=float)
    sheet = np.array([[-0.5, -0.5, 0.5], [0.7, -0.5, 0.25], [0.5, 0.6, 0.75], [-0.5, 0.5, 0.5]])
    two = np.array([[0, 1, 2], [0, 2, 3]])

    def contacts(edges):
        scene = exactccd.Scene()
        scene.add_static_mesh(floor, np.array([[0, 1, 2]]))
        mesh = scene.add_mesh(sheet, two)
        scene.set_motion(mesh, sheet, sheet - [0, 0, 1.5])
        if edges is not None:
            scene.set_edges(mesh, edges)
        out = set()
        for c in scene.find_contacts().contacts:
            p = c.pair
            if p.type == "edge-edge":
                a = tuple(sorted(scene.edges(p.first_mesh)[p.first_index]))
                b = tuple(sorted(scene.edges(p.second_mesh)[p.second_index]))
                out.add(("ee", p.first_mesh, a, p.second_mesh, b, c.toi_lo))
            else:
                out.add(("vf", p.first_mesh, p.first_index, p.second_mesh, p.second_index,
                         c.toi_lo))
        return out

    libigl = np.array([[1, 0], [2, 0], [3, 0], [2, 1], [3, 2]])  # sorted by (j, i), as (j, i)
    assert contacts(libigl) == contacts(None)
    with pytest.raises(ValueError, match=r"the side \(0, 3\) of mesh 1 is missing"):
        scene = exactccd.Scene()
        scene.add_mesh(sheet, two)
        scene.add_mesh(sheet, two)
        scene.set_edges(1, libigl[[0, 1, 3, 4]])
    with pytest.raises(ValueError, match=r"edges must have shape \(E, 2\)"):
        exactccd.Scene().set_edges(0, np.zeros((3, 3), dtype=int))
