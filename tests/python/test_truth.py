# ccdlab.truth and load_truth: the same events as `ccdlab truth`, as numpy views of one
# table that stay valid after the Truth object is gone.
import json

import numpy as np
import pytest

import ccdlab


@pytest.fixture(scope="module")
def gas():
    return ccdlab.generate("gas", bodies=300, seed=11)


def test_truth_is_the_command_line_truth(tmp_path, cli, gas):
    scene_file = tmp_path / "gas.json"
    gas.save(str(scene_file))
    out = tmp_path / "truth.json"
    cli("truth", scene_file, "-o", out, "--quiet")
    expected = json.loads(out.read_text())
    truth = ccdlab.truth(gas, threads=2)
    assert len(truth) == len(expected["events"]) > 0
    assert truth.a.dtype == np.uint32 and truth.enter.dtype == np.float64
    assert truth.a.tolist() == [e["a"] for e in expected["events"]]
    assert truth.b.tolist() == [e["b"] for e in expected["events"]]
    assert truth.enter.tolist() == [e["enter"] for e in expected["events"]]  # bit for bit
    assert truth.exit.tolist() == [e["exit"] for e in expected["events"]]
    assert truth.scene_sha256 == expected["scene_sha256"]
    assert truth.to_json() == expected
    assert truth.enter_error is None and truth.grazing is None  # exact: no error fields


def test_unpacking_views_and_lifetime(gas):
    truth = ccdlab.truth(gas)
    a, b, enter, exit = truth
    assert np.all(a < b) and np.all(enter <= exit)
    assert np.all(np.diff(enter) >= 0)
    assert not enter.flags.writeable  # read-only views of the event table, not copies
    assert not enter.flags.owndata and enter.strides == (24,)
    expected = enter.tolist()
    del truth
    assert enter.tolist() == expected  # the views keep the table alive


def test_save_and_load_round_trip(tmp_path, gas):
    truth = ccdlab.truth(gas)
    truth.save(str(tmp_path / "t.json"))
    again = ccdlab.load_truth(str(tmp_path / "t.json"))
    for x, y in zip(truth, again):
        assert np.array_equal(x, y)
    assert again.horizon == gas.horizon


def test_error_fields_when_present(tmp_path):
    # A ccdlab-truth/2 file with error fields on its second event only.
    document = {"format": "ccdlab-truth/2", "horizon": 1.0, "scene_sha256": "0" * 64,
                "events": [{"a": 0, "b": 1, "enter": 0.25, "exit": 0.5},
                           {"a": 1, "b": 2, "enter": 0.5, "exit": 0.5, "enter_error": 0.0625,
                            "exit_error": 0.125, "grazing": True}]}
    (tmp_path / "t.json").write_text(json.dumps(document))
    truth = ccdlab.load_truth(str(tmp_path / "t.json"))
    assert truth.enter_error.tolist() == [0.0, 0.0625]
    assert truth.exit_error.tolist() == [0.0, 0.125]
    assert truth.grazing.tolist() == [False, True]
    # Written before `undecided` existed: the grazing event reads as undecided.
    assert truth.undecided.tolist() == [False, True]
    document["events"][1]["undecided"] = False
    (tmp_path / "t.json").write_text(json.dumps(document))
    assert ccdlab.load_truth(str(tmp_path / "t.json")).undecided.tolist() == [False, False]


def test_bad_truth_file_names_the_field(tmp_path):
    document = {"format": "ccdlab-truth/2", "horizon": 1.0, "scene_sha256": "0" * 64,
                "events": [{"a": 0, "b": 1, "enter": 0.5, "exit": 0.25}]}
    (tmp_path / "t.json").write_text(json.dumps(document))
    with pytest.raises(ValueError) as err:
        ccdlab.load_truth(str(tmp_path / "t.json"))
    assert err.value.file == str(tmp_path / "t.json")
    assert err.value.field.startswith("events[0]")
