# ccdlab.rigid_toi: the rigid ground truth's certified bracket search on two bodies given as
# arrays. Dyadic cases with a known answer: boxes meeting face to face without spin and
# spinning about the line they approach on (the face stays square to it), a sphere pair
# against the exact solver, a miss, an overlap at t = 0; and bad arrays named.
import math

import numpy as np
import pytest

import ccdlab

BOX = {"kind": "box", "half_extents": [0.5, 0.5, 0.5]}


def within(value, exact, error):
    return abs(value - exact) <= error


def approach(**kw):
    """Two unit cubes 4 apart closing at 2 m/s: faces meet at t = 1.5, part at t = 2.5."""
    return ccdlab.rigid_toi(BOX, [-2.0, 0.0, 0.0], [1.0, 0.0, 0.0], BOX, np.array([2.0, 0.0, 0.0]),
                            np.array([-1.0, 0.0, 0.0]), 4.0, **kw)


def test_boxes_without_spin_meet_when_their_faces_do():
    r = approach()
    assert r["status"] == "hit" and r["hit"]
    assert r["time_tolerance"] == math.ldexp(4.0, -30)
    assert within(r["toi"], 1.5, r["toi_error"])
    assert 0.0 <= r["toi_error"] <= r["time_tolerance"]
    assert len(r["events"]) == 1 and r["intervals"] == [(r["events"][0]["enter"], r["events"][0]["exit"])]
    e = r["events"][0]
    assert within(e["exit"], 2.5, e["exit_error"]) and e["exit_error"] <= r["time_tolerance"]
    assert not e["grazing"] and not e["undecided"]
    assert r["complete"] and r["evaluations"] < 1000


def test_a_given_tolerance_is_used():
    r = approach(time_tolerance=2.0**-10)
    assert r["time_tolerance"] == 2.0**-10
    assert within(r["toi"], 1.5, r["toi_error"]) and r["toi_error"] <= 2.0**-10


def test_spin_about_the_approach_line_keeps_the_contact_time():
    # A quarter turn about x (orientation [cos 45, sin 45, 0, 0]) and a spin about x: the
    # face square to x stays square to it, so the faces still meet at 1.5 and part at 2.5.
    q = [math.sqrt(0.5), math.sqrt(0.5), 0.0, 0.0]
    r = approach(orientation_a=q, angular_velocity_a=[3.0, 0.0, 0.0], angular_velocity_b=[-5.0, 0.0, 0.0])
    assert r["status"] == "hit"
    # The bracket holds the exact time; spin widens it to a few time tolerances (the
    # search stops at pieces of that width), far below the motion's own scale.
    assert within(r["toi"], 1.5, r["toi_error"]) and 0.0 < r["toi_error"] <= 64 * r["time_tolerance"]
    # Parting face to face while spinning exhausts the search's evaluations: the exit is
    # then one wide bracket, still holding the exact time.
    e = r["events"][0]
    assert within(e["exit"], 2.5, e["exit_error"]) and not r["complete"]
    assert r["evaluations"] >= 1000000


def test_a_spinning_box_meets_no_later_than_its_inscribed_ball_and_no_earlier_than_its_enclosing_one():
    # A box spinning about z against a sphere coming along x: contact lies between the
    # times the enclosing ball (radius sqrt(3)/2) and the inscribed ball (0.5) would touch.
    sphere = {"kind": "sphere", "radius": 0.5}
    r = ccdlab.rigid_toi(BOX, [0, 0, 0], [0, 0, 0], sphere, [4, 0, 0], [-1, 0, 0], 4.0,
                         angular_velocity_a=[0, 0, 7.0])
    assert r["status"] == "hit"
    earliest, latest = 4.0 - (0.5 + math.sqrt(3) / 2), 3.0
    assert earliest - r["toi_error"] <= r["toi"] <= latest + r["toi_error"]
    assert r["toi_error"] <= 64 * r["time_tolerance"]


def test_spheres_agree_with_the_exact_solver():
    sphere = {"kind": "sphere", "radius": 0.75}
    r = ccdlab.rigid_toi(sphere, [0, 0, 0], [2, 0, 0], sphere, [8, 1, 0], [-2, 0, 0], 4.0)
    exact = ccdlab.sphere_sphere_toi([0, 0, 0], [2, 0, 0], 0.75, [8, 1, 0], [-2, 0, 0], 0.75, 4.0)
    assert exact["hit"] and r["hit"]
    assert within(r["toi"], exact["toi"], r["toi_error"]) and r["toi_error"] <= r["time_tolerance"]


def test_a_miss_and_an_overlap_at_the_start():
    miss = ccdlab.rigid_toi(BOX, [-2, 0, 0], [1, 0, 0], BOX, [2, 3, 0], [-1, 0, 0], 4.0)
    assert miss["status"] == "miss" and not miss["hit"]
    assert miss["toi"] is None and miss["toi_error"] is None and miss["intervals"] == []
    start = ccdlab.rigid_toi(BOX, [0, 0, 0], [0, 0, 0], BOX, [0.5, 0.25, 0], [0, 0, 0], 1.0)
    assert start["status"] == "overlapping" and start["toi"] == 0.0 and start["toi_error"] == 0.0
    assert start["events"][0]["exit"] == 1.0 and start["events"][0]["exit_error"] == 0.0


@pytest.mark.parametrize("change, field", [
    ({"position_a": [0.0, 0.0]}, "position_a"),
    ({"velocity_b": [1.0, float("nan"), 0.0]}, "velocity_b[1]"),
    ({"velocity_a": [[1.0, 0.0, 0.0]]}, "velocity_a"),
    ({"orientation_a": [1.0, 1.0, 0.0, 0.0]}, "orientation_a"),
    ({"orientation_b": [1.0, 0.0, 0.0]}, "orientation_b"),
    ({"angular_velocity_b": [0.0, float("inf"), 0.0]}, "angular_velocity_b[1]"),
    ({"shape_b": 0.5}, "shape_b"),
    ({"shape_a": {"kind": "box", "half_extents": [0.5, -1.0, 0.5]}}, "shape_a.half_extents"),
    ({"shape_a": {"kind": "cone", "radius": 1.0}}, "shape_a.kind"),
    ({"shape_b": {"kind": "sphere"}}, "shape_b"),
    ({"duration": 0.0}, "duration"),
    ({"duration": float("nan")}, "duration"),
    ({"time_tolerance": -1.0}, "time_tolerance"),
])
def test_bad_input_names_the_argument(change, field):
    args = dict(shape_a=BOX, position_a=[-2.0, 0.0, 0.0], velocity_a=[1.0, 0.0, 0.0], shape_b=BOX,
                position_b=[2.0, 0.0, 0.0], velocity_b=[-1.0, 0.0, 0.0], duration=4.0)
    args.update(change)
    with pytest.raises(ccdlab.InputError) as err:
        ccdlab.rigid_toi(**args)
    assert err.value.file == "ccdlab.rigid_toi"
    assert err.value.field.startswith(field), str(err.value)
    assert str(err.value).startswith("ccdlab.rigid_toi: " + field)
