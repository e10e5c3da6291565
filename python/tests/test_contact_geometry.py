"""The contact geometry in Python (contact=True; C++: exactccd::contact_geometry): known
contacts, the enclosures against exact rational evaluation at the ends of the TOI enclosure
(clamped to [0, 1]: proofs/contact_geometry.md#test-criterion), every kind, and bad input."""

from fractions import Fraction

import numpy as np
import pytest

import exactccd


def test_vertex_falling_on_a_triangle():
    a, b, c = (0, 0, 0), (1, 0, 0), (0, 1, 0)
    r = exactccd.vertex_face_ccd((0.25, 0.5, 1), a, b, c, (0.25, 0.5, -1), a, b, c, contact=True)
    g = r.contact
    assert g.kind == "point" and g.normal_oriented
    assert g.parameters.shape == (3, 2) and g.normal.shape == (3, 2) and g.point.shape == (3, 2)
    assert g.parameters.tolist() == [[0.25, 0.25], [0.25, 0.25], [0.5, 0.5]]
    assert g.normal.tolist() == [[0, 0], [0, 0], [1, 1]]
    # From below the normal points down; without contact=True there is none.
    r = exactccd.vertex_face_ccd((0.25, 0.5, -1), a, b, c, (0.25, 0.5, 1), a, b, c, contact=True)
    assert r.contact.normal[2].tolist() == [-1, -1]
    assert exactccd.vertex_face_ccd((0.25, 0.5, -1), a, b, c, (0.25, 0.5, 1), a, b, c).contact \
        is None


def test_edges_and_points():
    r = exactccd.edge_edge_ccd((-1, 0, 1), (1, 0, 1), (0, -0.5, 0), (0, 1.5, 0),
                               (-1, 0, -1), (1, 0, -1), (0, -0.5, 0), (0, 1.5, 0), contact=True)
    assert r.contact.kind == "point"
    assert r.contact.parameters.tolist() == [[0.5, 0.5], [0.25, 0.25]]
    assert r.contact.normal[2].tolist() == [1, 1]
    # Point against a segment in the plane: the segment's parameter only, the normal +y.
    r = exactccd.point_edge_ccd((0.25, 1), (0, 0), (1, 0), (0.25, -1), (0, 0), (1, 0),
                                contact=True)
    assert r.contact.parameters.tolist() == [[0.25, 0.25]]
    assert r.contact.normal[1].tolist() == [1, 1] and r.contact.kind == "point"
    # Two points: no parameters, the normal from q towards p before contact.
    r = exactccd.point_point_ccd((0, 0, 0), (1, 0, 0), (4, 0, 0), (1, 0, 0), contact=True)
    assert r.contact.parameters.shape == (0, 2)
    assert r.contact.normal[0].tolist() == [-1, -1]
    # No contact: no geometry.
    assert exactccd.point_point_ccd((0, 1, 0), (1, 0, 0), (4, 1, 0), (1, 0, 0),
                                    contact=True).contact is None


def _exact_barycentric(points, t):
    """The barycentric coordinates of the vertex's projection at the rational t, exactly."""
    t = Fraction(t)
    x = [[(1 - t) * Fraction(points[i][k]) + t * Fraction(points[i + 4][k]) for k in range(3)]
         for i in range(4)]
    sub = lambda u, v: [u[k] - v[k] for k in range(3)]
    cross = lambda u, v: [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0]]
    dot = lambda u, v: sum(u[k] * v[k] for k in range(3))
    p, a, b, c = x
    n = cross(sub(b, a), sub(c, a))
    nn = dot(n, n)
    return [dot(n, cross(sub(b, p), sub(c, p))) / nn, dot(n, cross(sub(c, p), sub(a, p))) / nn,
            dot(n, cross(sub(a, p), sub(b, p))) / nn]


def test_barycentric_enclosures_hold_exactly_on_random_crossings():
    rng = np.random.default_rng(5)
    checked = 0
    for _ in range(100):
        points = np.array([[0.2, 0.2, 0.5], [0, 0, 0], [1, 0, 0], [0, 1, 0],
                           [0.3, 0.2, -0.5], [0, 0, 0], [1, 0, 0], [0, 1, 0]])
        points += rng.uniform(-0.1, 0.1, (8, 3))
        r = exactccd.vertex_face_ccd(points, contact=True)
        if not r.collides or r.contact.kind != "point":
            continue
        for t in (r.toi_lo, r.toi_hi):
            for value, (lo, hi) in zip(_exact_barycentric(points, t), r.contact.parameters):
                clamped = min(max(value, Fraction(0)), Fraction(1))
                assert Fraction(lo) <= clamped <= Fraction(hi)
        assert r.contact.normal[2][0] > 0.5  # from above: up
        checked += 1
    assert checked > 80


def test_contact_needs_a_certified_contact_query():
    a, b, c = (0, 0, 0), (1, 0, 0), (0, 1, 0)
    args = ((0.25, 0.5, 1), a, b, c, (0.25, 0.5, -1), a, b, c)
    with pytest.raises(ValueError, match="certified mode"):
        exactccd.vertex_face_ccd(*args, mode="float_only", contact=True)
    # With a minimum separation: the closest point inside the triangle, the normal +z.
    r = exactccd.vertex_face_ccd(*args, min_separation=0.125, contact=True)
    assert r.toi_lo == r.toi_hi == 0.4375 and r.contact.kind == "point"
    assert r.contact.normal[2].tolist() == [1, 1]
    assert r.contact.point[2].tolist() == [0, 0]
    assert r.contact.parameters.tolist() == [[0.25, 0.25], [0.25, 0.25], [0.5, 0.5]]
    assert exactccd.vertex_face_ccd(*args, mode="exact", contact=True).contact.kind == "point"


def test_rigid_contact_geometry():
    # A vertex falling onto a triangle that turns about the z axis through its corner: the
    # normal is +z whatever the turn, the barycentric coordinates those of the landing point.
    turn = exactccd.RigidMotion(pivot=(0, 0, 0), cayley=(0, 0, 0.25))
    fall = exactccd.RigidMotion(translation=(0, 0, -1))
    points = np.array([[0.2, 0.2, 0.5], [-1, -1, 0], [2, -1, 0], [-1, 2, 0]])
    r = exactccd.rigid_vertex_face_ccd(points, fall, turn, contact=True)
    assert r.collides and r.toi_lo <= 0.5 <= r.toi_hi
    g = r.contact
    assert g.kind == "point" and g.normal_oriented
    assert g.normal[2][0] > 0.999999 and g.parameters.shape == (3, 2)
    assert (g.parameters[:, 0] >= 0).all() and (g.parameters[:, 1] <= 1).all()
    assert exactccd.rigid_vertex_face_ccd(points, fall, turn).contact is None
    r = exactccd.rigid_edge_edge_ccd(np.array([[-1, 0, 0.5], [1, 0, 0.5], [0, -1, 0], [0, 1, 0]]),
                                     fall, turn, contact=True)
    assert r.contact.kind == "point" and r.contact.normal[2][0] > 0.999999
    # With a minimum separation: the closest point inside the turning triangle, normal +z.
    r = exactccd.rigid_vertex_face_ccd(points, fall, turn, min_separation=0.125, contact=True)
    assert r.contact.kind == "point" and r.contact.normal[2][0] > 0.999999
    assert r.contact.point[2][0] <= 0 <= r.contact.point[2][1]


def test_scene_contact_geometry():
    floor = np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], dtype=float)
    sheet = np.array([[-0.5, -0.5, 0.5], [0.7, -0.5, 0.25], [0.5, 0.6, 0.75], [-0.5, 0.5, 0.5]])
    two = np.array([[0, 1, 2], [0, 2, 3]])
    scene = exactccd.Scene()
    scene.add_static_mesh(floor, two)
    falling = scene.add_mesh(sheet, two)
    scene.set_motion(falling, sheet, sheet - [0, 0, 1.5])
    contacts = scene.find_contacts().contacts
    assert contacts
    for c in contacts:
        g = scene.contact_geometry(c)
        rows = (scene.vertex_face_query(c.pair) if c.pair.type == "vertex-face"
                else scene.edge_edge_query(c.pair))
        assert g.kind in exactccd.CONTACT_KIND_NAMES
        if g.kind == "point" and c.pair.type == "vertex-face" and c.pair.second_mesh == 0:
            # A sheet vertex lands on the floor: the floor's normal, towards where it came from.
            assert g.normal[2][0] > 0.999
        assert rows.shape == (8, 3)


def test_batch_contact_geometry_equals_single_calls():
    rng = np.random.default_rng(3)
    base_vf = np.array([[0.2, 0.2, 0.5], [0, 0, 0], [1, 0, 0], [0, 1, 0],
                        [0.3, 0.2, -0.5], [0, 0, 0], [1, 0, 0], [0, 1, 0]])
    base_ee = np.array([[-1, 0, 0.5], [1, 0, 0.5], [0, -1, 0], [0, 1, 0],
                        [-1, 0, -0.5], [1, 0, -0.5], [0, -1, 0], [0, 1, 0]])
    for base, batch, single, moving in ((base_vf, exactccd.vertex_face_ccd_batch,
                                         exactccd.vertex_face_ccd, [4]),
                                        (base_ee, exactccd.edge_edge_ccd_batch,
                                         exactccd.edge_edge_ccd, [4, 5])):
        queries = base + rng.uniform(-0.2, 0.2, (200, 8, 3))
        for row in moving:  # every third query: the vertex (edge a) stays above
            queries[::3, row, 2] += 2.0
        result = batch(queries, contact=True, threads=2)
        collides, toi_lo, toi_hi, stage = result  # still a 4-tuple
        c = result.contact
        assert c.normal.shape == (200, 3, 2) and c.kind.dtype == np.int8
        assert 20 < collides.sum() < 200
        for i in range(200):
            r = single(queries[i], contact=True)
            if not r.collides:
                assert c.kind[i] == -1 and np.isnan(c.normal[i]).all()
                continue
            g = r.contact
            assert exactccd.CONTACT_KIND_NAMES[c.kind[i]] == g.kind
            assert (c.parameters[i] == g.parameters).all()
            assert (c.normal[i] == g.normal).all() and (c.point[i] == g.point).all()
            assert c.normal_oriented[i] == g.normal_oriented
    assert exactccd.vertex_face_ccd_batch(base_vf[None]).contact is None
    pe = exactccd.point_edge_ccd_batch(np.array([[(0.25, 1), (0, 0), (1, 0), (0.25, -1), (0, 0),
                                                  (1, 0)]]), contact=True)
    assert pe.contact.parameters.tolist() == [[[0.25, 0.25]]]
    with pytest.raises(ValueError, match="certified mode"):
        exactccd.vertex_face_ccd_batch(base_vf[None], mode="float_only", contact=True)
