# ccdlab.Bound.prepare gives the bound the scene's motion, shapes and spin included: the
# orientation-aware bounds (frame_aabb, obb) box each body's shape in its pose, not the
# ball that encloses it. The poses come from `ccdlab poses` (the C++ motion model); the
# boxes expected are built here from the scene file's shapes and those poses.
import json

import numpy as np
import pytest

import ccdlab

SCENE = "data/scenes/rigid-example.json"


def rotation(qw, qx, qy, qz):
    """The rotation matrix of a unit quaternion (body to world)."""
    return np.array([
        [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy)],
        [2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx)],
        [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)],
    ])


def shape_of(doc, body):
    """(points in the body frame, radius) of a body of the scene file: the shape's convex
    proxy (capsule: its segment on the body x axis; box: its corners; hull: its points), or
    the body's centre and radius for a plain sphere."""
    b = doc["bodies"][body]
    if "shape" not in b:
        return np.zeros((1, 3)), b["radius"]
    s = next(x for x in doc["shapes"] if x["name"] == b["shape"])
    if s["kind"] == "capsule":
        h = s["half_length"]
        return np.array([[-h, 0, 0], [h, 0, 0]]), s["radius"]
    if s["kind"] == "box":
        e = np.array(s["half_extents"])
        corners = [[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
        return np.array(corners) * e, 0.0
    return np.array(s["points"], dtype=float), 0.0


def poses_at(cli, path, t):
    """Every body's (centre, rotation) at t, as `ccdlab poses` writes them."""
    out = cli("poses", path, "--times", f"{t}:{t}:1", "-o", "-").stdout.splitlines()
    assert out[0] == "body,t,x,y,z,qw,qx,qy,qz"
    poses = []
    for line in out[1:]:
        v = [float(x) for x in line.split(",")]
        poses.append((np.array(v[2:5]), rotation(*v[5:9])))
    return poses


def frame_aabb(points, radius, centre, rot):
    world = points @ rot.T + centre
    return np.array([world.min(axis=0) - radius, world.max(axis=0) + radius])


def obb_hull(points, radius, centre, rot):
    # The body-frame box of the shape, turned: the world box of that oriented box.
    lo, hi = points.min(axis=0) - radius, points.max(axis=0) + radius
    c = centre + rot @ ((lo + hi) / 2)
    half = np.abs(rot) @ ((hi - lo) / 2)
    return np.array([c - half, c + half])


@pytest.mark.parametrize("name,expected", [("frame_aabb", frame_aabb), ("obb", obb_hull)])
def test_orientation_aware_bounds_box_the_shapes_in_their_poses(cli, source_dir, name, expected):
    path = source_dir / SCENE
    doc = json.loads(path.read_text())
    scene = ccdlab.load_scene(str(path))
    bound = ccdlab.Bound(name)
    assert bound.knowledge == "instant"
    shaped = 0
    for t in (0.0, 0.375, 1.25, 2.0):
        poses = poses_at(cli, path, t)
        assert len(poses) == len(doc["bodies"])
        boxes = bound.prepare(scene, t)
        for body, (centre, rot) in enumerate(poses):
            points, radius = shape_of(doc, body)
            want = expected(points, radius, centre, rot)
            # Equal up to the bounds' rounding slack (tens of ulps of the coordinates).
            assert np.allclose(boxes[body], want, rtol=0, atol=1e-9), (name, t, body, boxes[body], want)
            # Not the enclosing ball's box: a shaped body's box is tighter on some axis.
            ball = scene.radius[body]
            if "shape" in doc["bodies"][body]:
                shaped += 1
                assert np.any(boxes[body][1] - boxes[body][0] < 2 * ball - 1e-3)
    assert shaped == 12
