# ccdlab.import_frames (python/import_binding.cpp): the scene `ccdlab import` makes of the
# same frames, bit for bit, and bad arrays named.
import csv

import numpy as np
import pytest

import ccdlab


def frames():
    rng = np.random.default_rng(11)
    times = np.array([0.0, 0.125, 0.25, 0.5, 1.0]) + 3.0  # time 0 is the first frame
    positions = rng.uniform(0, 4, (len(times), 6, 3))
    radii = rng.uniform(0.1, 0.6, 6)
    return positions, times, radii


def test_same_scene_as_ccdlab_import(tmp_path, cli):
    positions, times, radii = frames()
    path = tmp_path / "frames.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["body", "t", "x", "y", "z", "radius"])
        for k, t in enumerate(times):
            for b in range(positions.shape[1]):
                w.writerow([b, repr(float(t)), *(repr(float(x)) for x in positions[k, b]), repr(float(radii[b]))])
    cli("import", path, "-o", tmp_path / "scene.json")
    theirs = ccdlab.load_scene(str(tmp_path / "scene.json"))
    mine = ccdlab.import_frames(positions, times, radii=radii)
    assert mine.to_json() == theirs.to_json()
    assert ccdlab.truth(mine).to_json() == ccdlab.truth(theirs).to_json()
    # The frames are on the trajectories (linear between them), time shifted to 0.
    np.testing.assert_array_equal(mine.positions(times - times[0]), positions)


def test_one_radius_for_every_body():
    # Two balls of radius 1/2 closing linearly: centres 3, 1.5 and 0.5 apart at t = 0, 1, 2;
    # the distance is 1 (contact) at t = 3/2 exactly.
    p = np.zeros((3, 2, 3))
    p[:, 1, 0] = [3.0, 1.5, 0.5]
    t = ccdlab.truth(ccdlab.import_frames(p, np.array([0.0, 1.0, 2.0]), radius=0.5))
    assert len(t) == 1 and t.enter[0] == 1.5 and t.exit[0] == 2.0


@pytest.mark.parametrize("kwargs, field", [
    ({"positions": np.zeros((2, 3))}, "positions"),
    ({"times": np.zeros(3)}, "times"),
    ({"radii": np.ones(4)}, "radii"),
    ({"radii": None}, "radii"),
    ({"radius": 1.0}, "radii"),
    ({"positions": np.array([[[0, 0, 0]], [[np.nan, 0, 0]]], dtype=float), "radii": np.ones(1)}, r"positions\[1, 0, 0\]"),
    ({"positions": np.zeros((3, 2, 3)), "times": np.array([0.0, 0.0, 1.0])}, "line 4"),
    ({"radii": np.array([1.0, -1.0])}, "radius"),
])
def test_bad_frames_are_named(kwargs, field):
    args = {"positions": np.zeros((2, 2, 3)), "times": np.array([0.0, 1.0]), "radii": np.ones(2)}
    args.update(kwargs)
    with pytest.raises(ccdlab.InputError, match=field):
        ccdlab.import_frames(args.pop("positions"), args.pop("times"), **args)
