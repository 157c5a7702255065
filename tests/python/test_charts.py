# Every chart of scripts/plot.py and scripts/plot_study.py on the smallest results: a file
# where every number a chart draws is 0 (nothing missed, no false positive, cost 0) and a
# file of one record (issue 36: a log scale of non-positive data, a single point). Each
# chart must be written as a PNG, exit 0, no traceback; what a study needs beyond the
# records, when missing, is one line and exit 2.
import copy
import importlib
import json
import subprocess
import sys

import pytest

from conftest import BINARY, SOURCE_DIR, write_json
from results_fixtures import never_meeting_results, single_record_results

PLOT = SOURCE_DIR / "scripts" / "plot.py"
PLOT_STUDY = SOURCE_DIR / "scripts" / "plot_study.py"
STUDIES = ("tunnelling", "sap-coherence", "equal-endpoints", "grazing", "precision", "bound-violation",
           "mixed-sizes", "scaling", "scheduling", "spinning", "fit", "thin-obstacles")


@pytest.fixture(scope="module")
def smallest(tmp_path_factory):
    """{"all-zero": path, "one-record": path}, each with a scene source that every study
    reads (an elongation for fit, an acceleration for bound-violation)."""
    folder = tmp_path_factory.mktemp("charts")
    out = {}
    for name, make in (("all-zero", never_meeting_results), ("one-record", single_record_results)):
        res = make(folder / name)
        res["scene"]["source"] = {"generator": "test", "elongation": 4.0, "max_acceleration": 1.0}
        out[name] = write_json(folder / f"{name}.json", res)
    return out


def script(*args):
    return subprocess.run(["/usr/bin/python3", *map(str, args)], capture_output=True, text=True, timeout=300)


def in_process(module, args, capsys):
    """Runs scripts/MODULE.py's main(args) in this interpreter (a second start of Python and
    matplotlib per chart would make the test slow): (exit status, stdout, stderr)."""
    sys.path.insert(0, str(SOURCE_DIR / "scripts"))
    try:
        main = importlib.import_module(module).main
    finally:
        sys.path.pop(0)
    try:
        main([str(a) for a in args])
        status = 0
    except SystemExit as e:
        status = e.code
    out = capsys.readouterr()
    return subprocess.CompletedProcess(args, status, out.out, out.err)


def written_pngs(run):
    paths = [line for line in run.stdout.splitlines() if line.endswith(".png")]
    for p in paths:
        with open(p, "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n", p
    return paths


@pytest.mark.parametrize("kind", ["all-zero", "one-record"])
def test_plot_draws_every_chart(tmp_path, smallest, kind, capsys):
    run = in_process("plot", [smallest[kind], "-o", tmp_path / "plots", "--format", "png"], capsys)
    assert run.returncode == 0, run.stderr
    assert "Traceback" not in run.stderr
    names = sorted(p.rsplit("/", 1)[1] for p in written_pngs(run))
    assert names == ["cost.png", "false_positives.png", "missed.png", "penetration.png", "speed_accuracy.png"]


@pytest.mark.parametrize("kind", ["all-zero", "one-record"])
@pytest.mark.parametrize("study", STUDIES)
def test_plot_study_draws_every_study(tmp_path, smallest, kind, study, capsys):
    run = in_process("plot_study", [study, smallest[kind], "-o", tmp_path / "plots", "--ccdlab", BINARY], capsys)
    assert run.returncode == 0, run.stderr
    assert "Traceback" not in run.stderr
    assert len(written_pngs(run)) >= 1


def cloth_results(records):
    return {"format": "ccdlab-cloth-results/1",
            "scene": {"source": "drape", "triangles": 2, "steps": 10, "step": 0.01, "thickness": 0.001},
            "truth": {"events": 0}, "records": records}


@pytest.mark.parametrize("count", [1, 4])
def test_plot_study_cloth_all_zero(tmp_path, count, capsys):
    # Every count 0, no check run (checks = 0: once a division by zero).
    zero = {"method": "bvh", "mode": "continuous", "culler": "bvh", "k": 1, "missed": 0, "events": 0,
            "candidates": 0, "false_positives": 0, "checks": 0, "seconds_per_simulated_second": 0.0,
            "conservative": True}
    records = [dict(zero, k=2 ** i, dt=0.01 * 2 ** i) for i in range(count)]
    path = write_json(tmp_path / "cloth.json", cloth_results(records))
    run = in_process("plot_study", ["cloth", path, "-o", tmp_path / "plots"], capsys)
    assert run.returncode == 0, run.stderr
    assert len(written_pngs(run)) == 1


@pytest.mark.parametrize("study, edit, message", [
    ("fit", lambda res: res["scene"].__setitem__("source", "scene.json"), "scene.source.elongation: missing"),
    ("bound-violation", lambda res: res["scene"].__setitem__("source", {"max_acceleration": 0}),
     "scene.max_acceleration: must be > 0"),
])
def test_plot_study_names_what_a_study_needs(tmp_path, smallest, study, edit, message):
    res = json.loads(smallest["one-record"].read_text())
    edit(res)
    path = write_json(tmp_path / "r.json", copy.deepcopy(res))
    run = script(PLOT_STUDY, study, path, "-o", tmp_path / "plots")
    assert run.returncode == 2
    assert run.stderr.strip() == f"plot_study.py: {path}: {message}" + run.stderr.strip().split(message, 1)[1]


@pytest.mark.parametrize("text, message", [
    (b"{\"format\": \"ccdlab-results/2\", \"x\": \"\xff\"}", "not UTF-8"),
    (b"[" * 100000 + b"]" * 100000, "nests deeper than 64"),
    (b"{\"format\": \"ccdlab-results/2\", \"records\": NaN}", "NaN and Infinity are not JSON"),
], ids=["invalid-utf8", "deep", "nan"])
def test_plot_refuses_hostile_files_in_one_line(tmp_path, text, message):
    path = tmp_path / "bad.json"
    path.write_bytes(text)
    run = script(PLOT, path, "-o", tmp_path / "plots")
    assert run.returncode == 2
    assert len(run.stderr.strip().splitlines()) == 1 and message in run.stderr
