# ccdlab.scene_from_arrays (python/ccdlab/arrays.py): the scene of a file with the same
# bodies, exact dyadic contacts, and every bad array named.
import numpy as np
import pytest

import ccdlab


def test_same_scene_as_the_file_it_stands_for():
    pos = np.array([[1.0, 2.0, 3.0], [4.5, 2.0, 3.0], [8.0, 8.0, 8.0]])
    vel = np.array([[1.0, 0.0, 0.0], [-0.5, 0.0, 0.0], [0.0, 0.0, -2.0]])
    acc = np.array([[0.0, 0.0, 0.0], [0.0, 0.25, 0.0], [0.0, 0.0, 0.0]])
    rad = np.array([0.5, 0.25, 1.0])
    s = ccdlab.scene_from_arrays(pos, vel, rad, accelerations=acc, horizon=4.0, gravity=[0, -1, 0],
                                 box=([0, 0, 0], [10, 10, 10]))
    doc = {"format": "ccdlab-scene/1", "horizon": 4.0, "gravity": [0.0, -1.0, 0.0],
           "box": {"min": [0.0, 0.0, 0.0], "max": [10.0, 10.0, 10.0]},
           "bodies": [{"radius": float(rad[i]), "position": list(pos[i]), "velocity": list(vel[i]),
                       "acceleration": list(acc[i])} for i in range(3)]}
    f = ccdlab.scene_from_json(doc)
    assert s.to_json() == f.to_json()
    assert ccdlab.truth(s).to_json() == ccdlab.truth(f).to_json()


def test_head_on_contact_at_a_dyadic_time():
    # Centres 3 apart closing at 2 m/s, radii 1/2 each: contact exactly at t = 1, apart at t = 2.
    s = ccdlab.scene_from_arrays([[0, 0, 0], [3, 0, 0]], [[1, 0, 0], [-1, 0, 0]], [0.5, 0.5], horizon=4.0)
    t = ccdlab.truth(s)
    assert list(t.enter) == [1.0] and list(t.exit) == [2.0]
    assert len(s) == 2 and s.horizon == 4.0


def test_wrap_around_box():
    s = ccdlab.scene_from_arrays([[0.5, 5, 5], [9.5, 5, 5]], [[0, 0, 0], [0, 0, 0]], [0.25, 0.25], horizon=1.0,
                                 box=([0, 0, 0], [10, 10, 10]), boundary="wrap")
    assert s.to_json()["box"]["boundary"] == ["wrap", "wrap", "wrap"]
    t = ccdlab.truth(s)  # the images are 1 apart: no contact of radii 1/4
    assert len(t) == 0


@pytest.mark.parametrize("args, kwargs, field", [
    (([[0, 0]], [[0, 0, 0]], [1]), {}, "positions"),
    (([[0, 0, 0]], [[0, 0, 0], [1, 1, 1]], [1]), {}, "velocities"),
    (([[0, 0, 0]], [[0, 0, 0]], [[1]]), {}, "radii"),
    (([[0, 0, 0]], [[0, 0, 0]], [1]), {"accelerations": [[0, 0]]}, "accelerations"),
    (([[0, 0, 0]], [[0, 0, 0]], [1]), {"gravity": [0, 0]}, "gravity"),
    (([[0, 0, 0]], [[0, 0, 0]], [1]), {"box": ([0, 0, 0],)}, "box"),
    (([[0, 0, 0]], [[0, 0, 0]], [1]), {"boundary": "wrap"}, "boundary"),
    (([[0, 0, 0], [5, 0, 0]], [[0, 0, 0], [0, 0, 0]], [1, -1]), {}, "bodies[1].radius"),
    (([[0, 0, 0]], [[np.nan, 0, 0]], [1]), {}, "velocities[0, 0]"),
    (([[0, 0, 0]], [[0, 0, 0]], [1]), {"horizon": np.inf}, "horizon"),
    (([[0, 0, 0], [4, 0, 0]], [[0, 0, 0], [0, 0, 0]], [1, 1]), {"horizon": -1.0}, "horizon"),
])
def test_bad_arrays_are_named(args, kwargs, field):
    kwargs = {"horizon": 1.0, **kwargs}
    with pytest.raises(ccdlab.InputError, match=field.replace("[", r"\[").replace("]", r"\]")):
        ccdlab.scene_from_arrays(*args, **kwargs)
