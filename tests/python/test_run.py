# ccdlab.run and ccdlab.methods: the same results as `ccdlab run` and `ccdlab methods`,
# from a path or a dict; missed events listed on request; errors, Ctrl-C and the GIL.
import json
import os
import signal
import threading
import time

import pytest

import ccdlab
from conftest import write_json

# What a results file's counts are: every record field but the times and the environment.
TIMES = {"bound_seconds", "broad_seconds", "narrow_seconds", "total_seconds",
         "seconds_per_simulated_second", "first_broad_seconds", "cpu_seconds",
         "cpu_seconds_per_simulated_second"}


def counts(results):
    return [{k: v for k, v in r.items() if k not in TIMES} for r in results["records"]]


def small_experiment(scene_file):
    return {"format": "ccdlab-experiment/1", "name": "small", "scene": str(scene_file),
            "dt": [0.25, 0.0625, 0.0078125],
            "methods": ["sphere/grid", "aabb/sap", "capsule/grid", "horn:4/sap", "swept_aabb/brute"]}


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("run") / "gas.json"
    ccdlab.generate("gas", bodies=400, seed=3).save(str(path))
    return path


def test_run_gives_the_counts_of_the_command_line(tmp_path, cli, scene_file):
    experiment = write_json(tmp_path / "small.json", small_experiment(scene_file))
    out = tmp_path / "results.json"
    cli("run", experiment, "-o", out, "--quiet", "--threads", "2")
    from_cli = json.loads(out.read_text())
    from_path = ccdlab.run(str(experiment), threads=2)
    from_dict = ccdlab.run(small_experiment(scene_file), threads=1)
    assert set(from_path) == set(from_cli)
    assert counts(from_path) == counts(from_cli)
    assert counts(from_dict) == counts(from_cli)
    assert from_path["truth"]["events"] == from_cli["truth"]["events"] > 0
    assert from_path["experiment"] == from_cli["experiment"]
    missed = {}
    for r in from_cli["records"]:
        missed[r["method"]] = missed.get(r["method"], 0) + r["missed"]
    assert missed["aabb/sap"] > 0 and missed["capsule/grid"] == 0  # the run can tell methods apart


def without_times(results):
    """The results but their times and environment: what the same run gives twice."""
    out = {k: v for k, v in results.items() if k not in ("environment", "records", "peak_memory_bytes")}
    out["records"] = counts(results)
    out["truth"] = {k: v for k, v in results["truth"].items() if k != "seconds"}
    return out


def test_run_and_the_command_line_share_one_preparation(tmp_path, cli, scene_file):
    # A stored truth (its digest checked by both), the same results document but its times.
    truth = tmp_path / "truth.json"
    cli("truth", scene_file, "-o", truth, "--quiet")
    experiment = write_json(tmp_path / "small.json", small_experiment(scene_file))
    out = tmp_path / "results.json"
    cli("run", experiment, "-o", out, "--quiet", "--truth", truth, "--list-missed")
    from_cli = json.loads(out.read_text())
    from_python = ccdlab.run(str(experiment), truth=str(truth), missed_events=True)
    assert from_cli["truth"]["source"] == from_python["truth"]["source"] == str(truth)
    assert without_times(from_python) == without_times(from_cli)
    # The same refusals, in the same words: a truth of another scene, the work limit, and a
    # dt the horizon cannot resolve.
    other_scene = tmp_path / "other.json"
    ccdlab.generate("gas", bodies=10, seed=4).save(str(other_scene))
    other_truth = tmp_path / "other-truth.json"
    cli("truth", other_scene, "-o", other_truth, "--quiet")
    huge = write_json(tmp_path / "huge.json", dict(small_experiment(scene_file), dt=[1e-10]))
    tiny = write_json(tmp_path / "tiny.json", dict(small_experiment(scene_file), dt=[1e-300]))
    for path, truth_file in ((experiment, other_truth), (huge, None), (tiny, None)):
        args = ["run", path, "-o", tmp_path / "none.json", "--quiet"] + (["--truth", truth_file] if truth_file else [])
        run = cli(*args, check=False)
        with pytest.raises(ValueError) as err:
            ccdlab.run(str(path), truth=str(truth_file) if truth_file else None)
        assert run.returncode == 2
        assert run.stderr == f"ccdlab run: {err.value}\n"
    assert not (tmp_path / "none.json").exists()


def test_missed_events_are_listed_on_request(tmp_path, cli, scene_file):
    results = ccdlab.run(small_experiment(scene_file), missed_events=True)
    a, b, enter, exit = ccdlab.truth(ccdlab.load_scene(str(scene_file)))
    events = {(int(x), int(y), float(e0), float(e1)) for x, y, e0, e1 in zip(a, b, enter, exit)}
    for r in results["records"]:
        listed = r["missed_events"]
        assert len(listed) == r["missed"]
        keys = [(m["a"], m["b"], m["enter"], m["exit"]) for m in listed]
        assert keys == sorted(keys, key=lambda k: (k[2], k[0], k[1]))
        for k in keys:
            assert k in events and k[2] > 0.0  # truth events; never one in progress at t = 0
        if r["knowledge"] == "instant":
            # A discrete method misses only events that contain no sample time k dt.
            for _, _, e0, e1 in keys:
                k = int(e0 // r["dt"]) + 1
                assert k * r["dt"] > e1 or k * r["dt"] > results["scene"]["horizon"]
    assert sum(r["missed"] for r in results["records"]) > 0
    assert "missed_events" not in ccdlab.run(small_experiment(scene_file))["records"][0]
    # The same lists as `ccdlab run --list-missed`.
    experiment = write_json(tmp_path / "small.json", small_experiment(scene_file))
    cli("run", experiment, "-o", tmp_path / "r.json", "--quiet", "--list-missed")
    from_cli = json.loads((tmp_path / "r.json").read_text())
    assert [r["missed_events"] for r in from_cli["records"]] == [r["missed_events"] for r in results["records"]]


def test_methods_lists_the_registries(cli):
    listed = ccdlab.methods()
    names = cli("methods", "--names").stdout.split()
    assert listed["methods"] == names
    assert {b["name"] for b in listed["bounds"]} >= {"aabb", "capsule", "horn"}
    horn = next(b for b in listed["bounds"] if b["name"] == "horn")
    assert horn["knowledge"] == "bounded" and horn["conservative"] and "pieces" in horn["parameters"]


def test_bad_experiment_names_file_and_field(tmp_path, scene_file):
    bad = small_experiment(scene_file)
    bad["dt"] = [0.1, -1]
    with pytest.raises(ValueError) as err:
        ccdlab.run(bad)
    assert err.value.file == "experiment" and err.value.field.startswith("dt")
    path = write_json(tmp_path / "bad.json", dict(bad, methods=["aabb/nope"], dt=[0.1]))
    with pytest.raises(ValueError) as err:
        ccdlab.run(str(path))
    assert err.value.file == str(path) and err.value.field.startswith("methods")
    with pytest.raises(ValueError) as err:
        ccdlab.run(dict(small_experiment(scene_file), scene=str(tmp_path / "missing.json")))
    assert err.value.file == str(tmp_path / "missing.json")


def long_experiment():
    # Brute force over 3,000 bodies at a small dt: minutes of work, cancelled after 0.3 s.
    return {"format": "ccdlab-experiment/1", "name": "long",
            "scene": {"generator": "gas", "bodies": 3000, "seed": 1},
            "dt": [0.0001], "methods": ["aabb/brute"]}


def test_ctrl_c_raises_keyboard_interrupt():
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            ccdlab.run(long_experiment(), threads=1)
    finally:
        timer.cancel()


def test_long_calls_release_the_gil():
    # While another thread is inside ccdlab.truth, this thread keeps running Python. Were
    # the GIL held, this thread would stand still for the whole call: one gap between its
    # ticks as long as the call.
    scene = ccdlab.generate("gas", bodies=6000, seed=2)
    span = {}

    def work():
        span["start"] = time.monotonic()
        ccdlab.truth(scene, threads=1)
        span["end"] = time.monotonic()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.monotonic())
    worker.join()
    inside = [t for t in ticks if span["start"] <= t <= span["end"]]
    assert len(inside) > 10
    gaps = [y - x for x, y in zip([span["start"]] + inside, inside + [span["end"]])]
    assert max(gaps) < 0.5 * (span["end"] - span["start"])
