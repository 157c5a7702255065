# ccdlab.Scene, load_scene, scene_from_json, generate: the same scenes as the command line,
# dicts and arrays that round-trip, bad input as ValueError with .file and .field.
import json

import numpy as np
import pytest

import ccdlab
from conftest import write_json


def test_load_scene_matches_the_file(source_dir):
    path = source_dir / "data/scenes/default.json"
    scene = ccdlab.load_scene(str(path))
    raw = json.loads(path.read_text())
    assert len(scene) == len(raw["bodies"]) == 2000
    assert scene.horizon == raw["horizon"]
    assert np.array_equal(scene.radius, [b["radius"] for b in raw["bodies"]])
    assert np.array_equal(scene.position, [b["position"] for b in raw["bodies"]])
    assert np.array_equal(scene.velocity, [b["velocity"] for b in raw["bodies"]])


def test_to_json_round_trips(source_dir):
    scene = ccdlab.load_scene(str(source_dir / "data/scenes/default.json"))
    document = scene.to_json()
    assert document["format"] == "ccdlab-scene/1"
    again = ccdlab.scene_from_json(document)
    assert again.to_json() == document
    assert np.array_equal(again.position, scene.position)


def test_generate_is_the_command_line_generator(tmp_path, cli):
    out = tmp_path / "gas.json"
    cli("scene", "gas", "bodies=64", "seed=5", "-o", out)
    from_cli = json.loads(out.read_text())
    scene = ccdlab.generate("gas", bodies=64, seed=5)
    assert scene.to_json() == from_cli
    assert "gas" in ccdlab.generators()


def test_save_writes_what_load_reads(tmp_path):
    scene = ccdlab.generate("rain", bodies=20, seed=1)
    scene.save(str(tmp_path / "rain.json"))
    assert ccdlab.load_scene(str(tmp_path / "rain.json")).to_json() == scene.to_json()


def test_positions_follow_the_exact_motion():
    # Dyadic numbers: one body at 0.5 m/s in x from x = 0.25, gravity -2 in z, no walls,
    # so x(t) = 0.25 + 0.5 t and z(t) = 1 - t^2 exactly at dyadic t.
    scene = ccdlab.scene_from_json({
        "format": "ccdlab-scene/1", "horizon": 1.0, "gravity": [0, 0, -2],
        "bodies": [{"radius": 0.125, "position": [0.25, 0, 1], "velocity": [0.5, 0, 0]},
                   {"radius": 0.125, "position": [4, 4, 4], "velocity": [0, 0, 0]}]})
    p = scene.positions([0.0, 0.5, 1.0])
    assert p.shape == (3, 2, 3)
    assert p[:, 0, 0].tolist() == [0.25, 0.5, 0.75]
    assert p[:, 0, 2].tolist() == [1.0, 0.75, 0.0]
    assert p[:, 1, 2].tolist() == [4.0, 3.75, 3.0]
    assert scene.max_acceleration == 2.0


def test_bad_scene_file_names_file_and_field(tmp_path, source_dir):
    document = json.loads((source_dir / "data/scenes/default.json").read_text())
    document["bodies"][3]["radius"] = -1
    path = write_json(tmp_path / "bad.json", document)
    with pytest.raises(ValueError) as err:
        ccdlab.load_scene(str(path))
    assert isinstance(err.value, ccdlab.InputError)
    assert err.value.file == str(path)
    assert err.value.field == "bodies[3].radius"
    assert "must be > 0" in str(err.value)


def test_bad_scene_dict_and_missing_file(tmp_path):
    with pytest.raises(ValueError) as err:
        ccdlab.scene_from_json({"format": "ccdlab-scene/1", "horizon": -1, "bodies": []})
    assert err.value.field == "horizon"
    with pytest.raises(ValueError) as err:
        ccdlab.load_scene(str(tmp_path / "missing.json"))
    assert err.value.file == str(tmp_path / "missing.json")
    with pytest.raises(ValueError):
        ccdlab.scene_from_json({"horizon": float("nan")})


def test_bad_generator_or_parameter():
    with pytest.raises(ValueError) as err:
        ccdlab.generate("no_such_generator")
    assert err.value.file == "ccdlab.generate(no_such_generator)"
    with pytest.raises(ValueError) as err:
        ccdlab.generate("gas", bodies=-3)
    assert "bodies" in str(err.value)
    with pytest.raises(ValueError):
        ccdlab.generate("gas", no_such_parameter=1)
    scene = ccdlab.generate("gas", bodies=8, seed=1, horizon=1.0)
    with pytest.raises(ValueError) as err:
        scene.positions([0.5, 2.0])
    assert err.value.field == "times[1]"
