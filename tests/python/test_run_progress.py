# Progress of ccdlab.run (the runner's own progress, experiments/progress.hpp, reported
# through python/interruptible.hpp): the callback sees the jobs (method x dt) finish up
# to their total on the calling thread; an exception in it stops the run; progress=True
# draws a bar with or without tqdm.
import sys
import threading

import pytest

import ccdlab

METHODS = ["aabb/sap", "sphere/grid", "swept_aabb/brute"]
DT = [0.25, 0.125, 0.0625, 0.03125]


@pytest.fixture(scope="module")
def experiment():
    return {"format": "ccdlab-experiment/1", "name": "progress", "dt": DT, "methods": METHODS,
            "scene": ccdlab.generate("gas", bodies=200, seed=2)}


def test_callback_sees_every_job_to_the_total(experiment):
    calls = []
    main = threading.get_ident()
    results = ccdlab.run(experiment, threads=2,
                         progress=lambda d, n: calls.append((d, n, threading.get_ident())))
    jobs = len(METHODS) * len(DT)
    assert len(results["records"]) == jobs
    assert calls[-1][:2] == (jobs, jobs)
    assert all(c[1] == jobs for c in calls)
    assert all(c[2] == main for c in calls)
    done = [c[0] for c in calls]
    assert done == sorted(set(done))  # strictly increasing: each count reported once
    assert 0 <= done[0] <= jobs


def test_an_exception_in_the_callback_stops_the_run(experiment):
    def stop(done, total):
        raise RuntimeError("enough")
    with pytest.raises(RuntimeError, match="enough"):
        ccdlab.run(experiment, progress=stop)


def test_progress_must_be_callable(experiment):
    with pytest.raises(ccdlab.InputError, match=r"^ccdlab.run: progress: "):
        ccdlab.run(experiment, progress=3)


def test_a_bar_with_tqdm_and_without(experiment, capsys, monkeypatch):
    pytest.importorskip("tqdm")
    ccdlab.run(experiment, progress=True)
    err = capsys.readouterr().err
    assert "ccdlab run" in err and "100%" in err and "12/12" in err  # tqdm's bar
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm now fails
    ccdlab.run(experiment, progress=True)
    err = capsys.readouterr().err
    assert "ccdlab run: 100%" in err and "12/12" not in err


def test_without_progress_the_results_are_the_same(experiment):
    from test_run import counts
    assert counts(ccdlab.run(experiment, progress=lambda d, n: None)) == counts(ccdlab.run(experiment))
