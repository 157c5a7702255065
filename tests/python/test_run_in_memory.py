# ccdlab.run on a scene held in memory: a ccdlab.Scene or a ccdlab-scene dict in the
# experiment's `scene` field gives the counts of the same scene run from its file, reads
# and writes no file, and bad input names the field and the index as the command line does.
import json
import os

import pytest

import ccdlab
from conftest import SOURCE_DIR, write_json
from test_run import counts

METHODS = ["sphere/grid", "aabb/sap", "capsule/grid", "swept_aabb/brute"]


def experiment(scene, dt=(0.25, 0.0625, 0.0078125), methods=METHODS):
    return {"format": "ccdlab-experiment/1", "name": "in-memory", "scene": scene, "dt": list(dt),
            "methods": list(methods)}


@pytest.fixture(scope="module")
def gas(tmp_path_factory):
    """(scene file, the counts of running it from the file)."""
    path = tmp_path_factory.mktemp("memory") / "gas.json"
    ccdlab.generate("gas", bodies=300, seed=5).save(str(path))
    from_file = ccdlab.run(experiment(str(path)), threads=2)
    assert from_file["truth"]["events"] > 0
    assert sum(r["missed"] for r in from_file["records"]) > 0  # counts that can differ
    return path, counts(from_file)


def test_a_scene_object_and_a_scene_dict_run_as_their_file(gas):
    path, from_file = gas
    scene = ccdlab.load_scene(str(path))
    assert counts(ccdlab.run(experiment(scene), threads=2)) == from_file
    assert counts(ccdlab.run(experiment(scene.to_json()), threads=1)) == from_file
    assert counts(ccdlab.run(experiment(json.loads(path.read_text())), threads=2)) == from_file


def test_a_scene_from_arrays_runs_as_its_file(tmp_path):
    scene = ccdlab.scene_from_arrays([[0, 0, 0], [4, 0, 0], [0, 4, 0]], [[1, 0, 0], [-1, 0, 0], [0, -1, 0]],
                                     [0.5, 0.5, 0.25], horizon=4.0, box=([-8, -8, -8], [8, 8, 8]))
    path = tmp_path / "arrays.json"
    scene.save(str(path))
    from_file = ccdlab.run(experiment(str(path), dt=(1.0, 0.125)))
    assert from_file["truth"]["events"] >= 1
    assert counts(ccdlab.run(experiment(scene, dt=(1.0, 0.125)))) == counts(from_file)


def test_rigid_bodies_in_memory_run_as_their_file():
    path = SOURCE_DIR / "data" / "scenes" / "rigid-example.json"
    methods = ["aabb/sap", "obb/brute"]
    from_file = ccdlab.run(experiment(str(path), dt=(0.25, 0.0625), methods=methods), threads=2)
    assert from_file["truth"]["events"] > 0
    scene = ccdlab.load_scene(str(path))
    assert counts(ccdlab.run(experiment(scene, dt=(0.25, 0.0625), methods=methods), threads=2)) == counts(from_file)
    doc = json.loads(path.read_text())
    assert counts(ccdlab.run(experiment(doc, dt=(0.25, 0.0625), methods=methods), threads=1)) == counts(from_file)


def test_no_scene_file_is_read_or_written(gas, tmp_path, monkeypatch):
    path, from_file = gas
    copy = tmp_path / "copy.json"
    copy.write_text(path.read_text())
    scene = ccdlab.load_scene(str(copy))
    copy.unlink()  # the run cannot read it
    monkeypatch.chdir(tmp_path)
    before = sorted(os.listdir(tmp_path))
    given = experiment(scene)
    results = ccdlab.run(given, threads=2)
    assert counts(results) == from_file
    assert sorted(os.listdir(tmp_path)) == before
    assert given["scene"] is scene  # the caller's dict is left as it was
    # The results name the scene as held in memory; the rest of the experiment as given.
    assert results["experiment"]["scene"] == "<in memory>"
    assert results["scene"]["source"] == "<in memory>"
    assert results["experiment"]["methods"] == METHODS


def test_a_generator_spec_is_still_a_generator():
    spec = {"generator": "gas", "bodies": 20, "seed": 1}
    results = ccdlab.run(experiment(spec, dt=(0.5,), methods=["aabb/sap"]))
    assert results["experiment"]["scene"] == spec


def bad_scene():
    return {"format": "ccdlab-scene/1", "horizon": 2.0,
            "bodies": [{"radius": 0.5, "position": [0, 0, 0]}, {"radius": -1.0, "position": [3, 0, 0]}]}


def test_bad_inline_scene_names_the_field_and_index():
    with pytest.raises(ccdlab.InputError) as err:
        ccdlab.run(experiment(bad_scene()))
    assert err.value.file == "experiment"
    assert err.value.field == "scene.bodies[1].radius"
    assert str(err.value).startswith("experiment: scene.bodies[1].radius: ")
    doc = bad_scene()
    doc["bodies"][1] = {"radius": 0.5, "position": [3, 0, float("nan")]}
    with pytest.raises(ccdlab.InputError, match="not JSON"):
        ccdlab.run(experiment(doc))
    doc = bad_scene()
    del doc["horizon"]
    with pytest.raises(ccdlab.InputError, match=r"^experiment: scene.horizon: "):
        ccdlab.run(experiment(doc))


def test_the_command_line_words_for_a_bad_scene_file(tmp_path, cli):
    # The same message but the file name and the field's prefix: the scene is the experiment's.
    scene_file = write_json(tmp_path / "bad.json", bad_scene())
    exp = write_json(tmp_path / "exp.json", experiment(str(scene_file)))
    run = cli("run", exp, "-o", tmp_path / "out.json", "--quiet", check=False)
    assert run.returncode == 2
    line = run.stderr.strip().splitlines()[-1]
    with pytest.raises(ccdlab.InputError) as err:
        ccdlab.run(experiment(bad_scene()))
    assert line.endswith(str(err.value).split("scene.bodies[1].radius: ", 1)[1])
    assert "bodies[1].radius" in line


def test_an_in_memory_scene_is_checked_against_the_experiment(gas):
    path, _ = gas
    scene = ccdlab.load_scene(str(path))
    with pytest.raises(ccdlab.InputError, match=r"^experiment: dt: .*horizon"):
        ccdlab.run(experiment(scene, dt=(scene.horizon * 2,)))
