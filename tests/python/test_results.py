# ccdlab.run's Results (python/ccdlab/results.py): the results document as a dict, a pandas
# table of its records, and the missed contacts of a record.
import pytest

import ccdlab
from conftest import SOURCE_DIR

EXPERIMENT = {"format": "ccdlab-experiment/1", "hz": [30, 60, 240],
              "methods": ["aabb/grid", "capsule/grid"]}


@pytest.fixture(scope="module")
def results():
    experiment = dict(EXPERIMENT, scene=str(SOURCE_DIR / "data" / "scenes" / "example.json"))
    return ccdlab.run(experiment, missed_events=True)


def test_results_is_the_document(results):
    assert isinstance(results, ccdlab.Results) and isinstance(results, dict)
    assert results["format"] == "ccdlab-results/2"
    assert results.methods() == ["aabb/grid", "capsule/grid"]
    assert repr(results).startswith("<ccdlab.Results 6 records: 2 methods x 3 timesteps")


def test_to_frame_has_one_row_per_record(results):
    pandas = pytest.importorskip("pandas")
    frame = results.to_frame()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == len(results.records)
    assert list(frame["method"]) == [r["method"] for r in results.records]
    assert list(frame["missed"]) == [r["missed"] for r in results.records]
    assert "options.cell_size" in frame.columns or any(c.startswith("self_check") for c in frame.columns)


def test_missed_lists_the_records_misses(results):
    # aabb at 30 Hz misses the bullet's short contacts on example.json; capsule misses nothing.
    for r in results.records:
        got = results.missed(r["method"], r["dt"])
        assert len(got) == r["missed"] + r.get("static_missed", 0)
        assert got == ccdlab.missed(dict(results), r["method"], r["dt"])
    assert any(results.missed("aabb/grid", 1 / 30))
    assert results.missed("capsule/grid", 1 / 30) == []


def test_missed_names_what_is_wrong(results):
    with pytest.raises(ccdlab.InputError, match="method 'sphere/sap'"):
        results.missed("sphere/sap", 1 / 30)
    with pytest.raises(ccdlab.InputError, match="dt 0.5"):
        results.missed("aabb/grid", 0.5)
    plain = ccdlab.Results({k: v for k, v in results.items() if k != "records"})
    plain["records"] = [{k: v for k, v in r.items() if k != "missed_events"} for r in results.records]
    with pytest.raises(ccdlab.InputError, match="missed_events"):
        plain.missed("aabb/grid", 1 / 30)
