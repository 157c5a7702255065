# Progress of ccdlab.truth (python/ccdlab/progress.py, python/interruptible.hpp): the
# callback sees the work advance to its total on the calling thread, an exception in it
# stops the call, progress=True draws a bar with or without tqdm.
import sys
import threading

import pytest

import ccdlab


@pytest.fixture(scope="module")
def scene():
    return ccdlab.generate("gas", bodies=4000, seed=3)


def test_callback_sees_the_work_to_its_end(scene):
    calls = []
    main = threading.get_ident()
    t = ccdlab.truth(scene, threads=1, progress=lambda d, n: calls.append((d, n, threading.get_ident())))
    assert calls and calls[-1][0] == calls[-1][1] > 0
    assert all(c[2] == main for c in calls)
    assert [c[0] for c in calls] == sorted(c[0] for c in calls)
    assert t.to_json() == ccdlab.truth(scene, threads=1).to_json()


def test_an_exception_in_the_callback_stops_the_call(scene):
    def stop(done, total):
        raise RuntimeError("enough")
    with pytest.raises(RuntimeError, match="enough"):
        ccdlab.truth(scene, progress=stop)


def test_progress_must_be_callable(scene):
    with pytest.raises(ccdlab.InputError, match="progress"):
        ccdlab.truth(scene, progress=3)


def test_a_bar_with_tqdm_and_without(scene, capsys, monkeypatch):
    pytest.importorskip("tqdm")
    ccdlab.truth(scene, progress=True)
    err = capsys.readouterr().err
    assert "ccdlab truth" in err and "100%" in err and "it/s" in err  # tqdm's bar
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm now fails
    ccdlab.truth(scene, progress=True)
    err = capsys.readouterr().err
    assert "ccdlab truth: 100%" in err and "it/s" not in err
