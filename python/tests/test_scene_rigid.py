"""Rigid bodies in the Scene (Scene.add_rigid_body, Scene.set_rigid_motion): a cube turning into a
wall at a contact parameter worked out by hand, the same scene through `exactccd rigid`, a rigid
body with q = 0 equal to a moving mesh with translated end positions, a minimum separation
(min_separation=) against every pair's rigid query, and bad input."""

import json
import math
from fractions import Fraction

import numpy as np
import pytest

import exactccd
from conftest import run

CUBE = np.array([[0, 0, 0], [5, 0, 0], [5, 5, 0], [0, 5, 0],
                 [0, 0, 5], [5, 0, 5], [5, 5, 5], [0, 5, 5]], dtype=float)
QUADS = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
CUBE_FACES = np.array([t for q in QUADS for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])])


def wall(x):
    return (np.array([[x, -2, -1], [x, 2, -1], [x, 2, 2], [x, -2, 2]], dtype=float),
            np.array([[0, 1, 2], [0, 2, 3]]))


def cube_and_wall(x_wall, cayley):
    scene = exactccd.Scene()
    body = scene.add_rigid_body(CUBE, CUBE_FACES)
    scene.set_rigid_motion(body, pivot=[0, 0, 0], cayley=cayley)
    scene.add_static_mesh(*wall(x_wall))
    return scene


def test_cube_turns_into_the_wall_at_two_thirds():
    # Clockwise about z by 2 atan(1/2): the corner (5, 5, 0) reaches x = 7 when the Cayley
    # parameter s/2 is 1/3 (cos = 4/5, sin = 3/5), i.e. s = 2/3; time atan(1/3) / atan(1/2).
    scene = cube_and_wall(7, [0, 0, -0.5])
    assert scene.is_rigid(0) and not scene.is_rigid(1)
    result = scene.find_contacts()
    assert len(result.contacts) > 0
    first = result.earliest
    assert Fraction(first.toi_lo) <= Fraction(2, 3) <= Fraction(first.toi_hi)
    assert first.pair.type == "vertex-face"
    assert (first.pair.first_mesh, first.pair.first_index, first.pair.second_mesh) == (0, 2, 1)
    assert first.has_time
    t = math.atan(1 / 3) / math.atan(1 / 2)
    assert first.time_lo - 1e-15 <= t <= first.time_hi + 1e-15
    earliest = scene.earliest_contact()
    assert earliest.collides
    assert (earliest.contact.pair, earliest.contact.toi_lo, earliest.contact.toi_hi) == \
        (first.pair, first.toi_lo, first.toi_hi)
    # Every contact is a pair of the two bodies (none within the cube).
    assert all(c.pair.first_mesh != c.pair.second_mesh for c in result.contacts)
    # mode="float_only" (the uncertified double test) runs on rigid bodies too. With the wall
    # at x = 6.9 every contact is a clear crossing (at x = 7 the corner touches the wall again
    # exactly at s = 1, which a double test may miss), and it finds the same pairs, each TOI one
    # double near the certified enclosure.
    clear = cube_and_wall(6.9, [0, 0, -0.5])
    certified = clear.find_contacts()
    rough = clear.find_contacts(mode="float_only")
    assert len(certified.contacts) > 0
    assert [c.pair for c in rough.contacts] == [c.pair for c in certified.contacts]
    for c, exact in zip(rough.contacts, certified.contacts):
        assert c.toi_lo == c.toi_hi and abs(c.toi_lo - exact.toi_lo) <= 1e-12
    # Clear of the wall (the arc reaches 5 sqrt(2) = 7.0711 at most): no contact.
    assert not cube_and_wall(7.075, [0, 0, -0.5]).earliest_contact().collides
    assert scene.rigid_motion(0).cayley.tolist() == [0, 0, -0.5]


def test_the_command_gives_the_same_contact(cli, tmp_path):
    positions, faces = wall(7)
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps({"bodies": [
        {"kind": "rigid", "positions": CUBE.tolist(), "triangles": CUBE_FACES.tolist(),
         "motion": {"pivot": [0, 0, 0], "cayley": [0, 0, -0.5]}},
        {"kind": "static", "positions": positions.tolist(), "triangles": faces.tolist()}]}))
    done = run([cli, "rigid", "--json", scene_file])
    assert done.returncode == 0, done.stderr  # a contact is an answer, not a disagreement
    contact = json.loads(done.stdout)["steps"][0]["contact"]
    first = cube_and_wall(7, [0, 0, -0.5]).earliest_contact().contact
    assert (contact["s_lo"], contact["s_hi"]) == (first.toi_lo, first.toi_hi)
    assert (contact["time_lo"], contact["time_hi"]) == (first.time_lo, first.time_hi)
    assert contact["first"]["vertex"] == first.pair.first_index
    assert contact["second"]["triangle"] == first.pair.second_index


def test_rigid_turn_and_a_step_from_new_positions():
    q = exactccd.RigidMotion.turn([0, 0, 0], [0, 0, 2], -2 * math.atan(0.5)).cayley
    assert np.allclose(q, [0, 0, -0.5], rtol=0, atol=1e-15)
    scene = exactccd.Scene()
    body = scene.add_rigid_body(CUBE, CUBE_FACES)
    scene.add_static_mesh(*wall(7))
    # Start the cube 10 away from the wall: the same turn no longer reaches it.
    scene.set_rigid_motion(body, cayley=[0, 0, -0.5], start=CUBE - [10, 0, 0])
    assert np.array_equal(scene.start_positions(body), CUBE - [10, 0, 0])
    assert not scene.earliest_contact().collides
    scene.set_rigid_motion(body, cayley=[0, 0, -0.5], start=CUBE)
    assert scene.earliest_contact().collides
    # The same motion as an exactccd.RigidMotion (not together with the keywords).
    same = exactccd.RigidMotion(cayley=[0, 0, -0.5])
    scene.set_rigid_motion(body, same, start=CUBE)
    assert scene.earliest_contact().collides
    with pytest.raises(ValueError, match="not both"):
        scene.set_rigid_motion(body, same, cayley=[0, 0, 1])


def test_zero_rotation_equals_a_moving_mesh():
    # q = 0: every vertex on the line from x0 to x0 + d; with dyadic d the end positions are
    # exact and the moving mesh gives the same contacts and TOIs.
    d = np.array([2.5, 0.25, -0.125])
    positions, faces = wall(7)
    rigid = exactccd.Scene()
    body = rigid.add_rigid_body(CUBE, CUBE_FACES)
    rigid.set_rigid_motion(body, pivot=[1, 2, 3], translation=d)
    rigid.add_static_mesh(positions, faces)
    linear = exactccd.Scene()
    mesh = linear.add_mesh(CUBE, CUBE_FACES)
    linear.set_motion(mesh, CUBE, CUBE + d)
    linear.add_static_mesh(positions, faces)
    got = [(c.pair, c.toi_lo, c.toi_hi) for c in rigid.find_contacts().contacts]
    want = [(c.pair, c.toi_lo, c.toi_hi) for c in linear.find_contacts(self_collision=False).contacts]
    assert got == want and len(got) > 0


def test_bad_rigid_input():
    scene = exactccd.Scene()
    body = scene.add_rigid_body(CUBE, CUBE_FACES)
    moving = scene.add_mesh(CUBE, CUBE_FACES)
    with pytest.raises(ValueError, match="not a rigid body"):
        scene.set_rigid_motion(moving, cayley=[0, 0, 1])
    with pytest.raises(ValueError, match="non-finite"):
        scene.set_rigid_motion(body, cayley=[0, float("nan"), 1])
    with pytest.raises(ValueError):
        scene.set_rigid_motion(body, pivot=[0, 0])
    with pytest.raises(ValueError):
        scene.set_rigid_motion(body, start=CUBE[:7])
    with pytest.raises(IndexError):
        scene.set_rigid_motion(9)
    with pytest.raises(ValueError, match="rigid"):
        scene.set_motion(body, CUBE, CUBE)
    with pytest.raises(ValueError, match="min_separation"):
        scene.find_contacts(min_separation=-1e-3)
    with pytest.raises(ValueError, match="min_separation"):
        scene.earliest_contact(min_separation=math.inf)
    with pytest.raises(ValueError):
        exactccd.RigidMotion.turn([0, 0, 0], [0, 0, 0], 1.0)
    with pytest.raises(ValueError):
        exactccd.RigidMotion.turn([0, 0, 0], [0, 0, 1], 4.0)


def rigid_pairs_within(scene, delta):
    """Every pair of the cube (mesh 0, rigid) and the wall (mesh 1, static) decided one by one
    with the rigid functions and min_separation=delta, as the scene decides a pair with a rigid
    body: the static side as straight lines from its positions to the same positions."""
    x = [scene.start_positions(m) for m in (0, 1)]
    triangles = [scene.triangles(m) for m in (0, 1)]
    edges = [scene.edges(m) for m in (0, 1)]

    def motion(mesh, rows):
        return scene.rigid_motion(mesh) if scene.is_rigid(mesh) else x[mesh][rows]

    found = []
    for a, b in ((0, 1), (1, 0)):
        for v in range(len(x[a])):
            for f, t in enumerate(triangles[b]):
                r = exactccd.rigid_vertex_face_ccd(np.vstack([x[a][[v]], x[b][t]]),
                                                   motion(a, [v]), motion(b, t),
                                                   min_separation=delta)
                if r.collides:
                    found.append(("vertex-face", a, v, b, f, r.toi_lo, r.toi_hi))
    for i, ea in enumerate(edges[0]):
        for j, eb in enumerate(edges[1]):
            r = exactccd.rigid_edge_edge_ccd(np.vstack([x[0][ea], x[1][eb]]), motion(0, ea),
                                             motion(1, eb), min_separation=delta)
            if r.collides:
                found.append(("edge-edge", 0, i, 1, j, r.toi_lo, r.toi_hi))
    return sorted(found)


def test_min_separation_with_a_rigid_body():
    # The turn clear of the wall at x = 7.075 passes it 0.0039 short (5 sqrt(2) = 7.0711): no
    # contact, none within 0.001, some within 0.01. Every delta gives exactly the pairs (and
    # TOIs) of the per-pair rigid queries with that delta: the broad phase drops none.
    scene = cube_and_wall(7.075, [0, 0, -0.5])
    for delta in (0.0, 1e-3, 1e-2):
        result = scene.find_contacts(min_separation=delta)
        got = sorted((c.pair.type, c.pair.first_mesh, c.pair.first_index, c.pair.second_mesh,
                      c.pair.second_index, c.toi_lo, c.toi_hi) for c in result.contacts)
        assert got == rigid_pairs_within(scene, delta), delta
        assert bool(got) == (delta == 1e-2), delta
        earliest = scene.earliest_contact(min_separation=delta)
        assert earliest.collides == bool(got)
        if got:
            assert (earliest.contact.pair, earliest.contact.toi_lo) == \
                (result.earliest.pair, result.earliest.toi_lo)
    # float_only runs with a minimum separation too (uncertified: its verdict is not checked).
    scene.find_contacts(min_separation=1e-2, mode="float_only")
