# repr() of every object the package returns says what it holds: every class of the
# package is made here (a class added without a case fails the first test), and no repr
# is Python's default `<... object at 0x...>`.
import re

import pytest

import ccdlab
from conftest import SOURCE_DIR


def sphere_scene():
    return ccdlab.scene_from_arrays([[0, 0, 0], [3, 0, 0]], [[1, 0, 0], [-1, 0, 0]], [0.5, 0.5], horizon=2.0,
                                    box=([-4, -4, -4], [4, 4, 4]), boundary="wrap")


def results():
    return ccdlab.run({"format": "ccdlab-experiment/1", "name": "shown", "scene": sphere_scene(),
                       "dt": [0.5, 0.25], "methods": ["aabb/sap", "capsule/grid"]})


def bound():
    b = ccdlab.Bound("horn:4")
    b.prepare(sphere_scene(), 0.0, 0.5)
    return b


# class name -> (a way to make one, what its repr must hold)
CASES = {
    "Scene": [
        (sphere_scene, [r"^<ccdlab\.Scene 2 bodies, box \(wraps\), horizon 2 s, from scene>$"]),
        (lambda: ccdlab.load_scene(str(SOURCE_DIR / "data/scenes/rigid-example.json")),
         [r"4 bodies \(3 shaped\)", r", box, gravity, horizon 2 s, from .*rigid-example\.json>$"]),
        (lambda: ccdlab.generate("pinball", bodies=10, obstacles=4, seed=1),
         [r"10 bodies, \d+ scenery polygons", r"from ccdlab\.generate\(pinball\)>$"]),
    ],
    "Truth": [(lambda: ccdlab.truth(sphere_scene()), [r"^<ccdlab\.Truth \d+ events, 0 static events, horizon 2 s>$"])],
    "Results": [(results, [r"^<ccdlab\.Results 4 records: 2 methods x 2 timesteps, dt 0\.25 to 0\.5 s>$"])],
    "BroadPhase": [(lambda: ccdlab.BroadPhase("grid:cell=2"), [r"^<ccdlab\.BroadPhase grid:cell=2, options \{.*'cell': 2\.0"])],
    "Bound": [(bound, [r"^<ccdlab\.Bound horn:4: [a-z-]+, (not )?conservative, options \{.*\}>$"])],
}


def package_classes():
    return sorted(name for name in dir(ccdlab) if isinstance(getattr(ccdlab, name), type)
                  and not issubclass(getattr(ccdlab, name), BaseException) and not name.startswith("_"))


def test_every_class_of_the_package_has_a_case():
    assert package_classes() == sorted(CASES)


@pytest.mark.parametrize("name", sorted(CASES))
def test_repr_says_what_the_object_holds(name):
    for make, patterns in CASES[name]:
        obj = make()
        assert type(obj).__name__ == name
        text = repr(obj)
        assert " object at 0x" not in text
        for pattern in patterns:
            assert re.search(pattern, text), (pattern, text)


def test_an_input_error_shows_its_message():
    with pytest.raises(ccdlab.InputError) as err:
        ccdlab.scene_from_arrays([[0, 0, 0]], [[0, 0, 0]], [-1.0], horizon=1.0)
    assert "bodies[0].radius" in repr(err.value)
