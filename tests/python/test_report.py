# `ccdlab report`: the zero-miss frontier and the tables from known records, the charts
# embedded in a self-contained HTML file, several files overlaid, bad input exit 2; a
# headless chromium render where Debian's chromium is installed.
import base64
import copy
import json
import os
import re
import subprocess

import pytest

import ccdlab
from conftest import write_json


@pytest.fixture(scope="module")
def real_results(tmp_path_factory):
    """A small real run: three dyadic dt, a discrete and a continuous method."""
    folder = tmp_path_factory.mktemp("report")
    scene = folder / "gas.json"
    ccdlab.generate("gas", bodies=300, seed=9).save(str(scene))
    experiment = {"format": "ccdlab-experiment/1", "name": "gas300", "scene": str(scene),
                  "dt": [0.25, 0.0625, 0.015625], "methods": ["aabb/sap", "capsule/grid"]}
    return ccdlab.run(experiment)


def with_missed(results, method_missed):
    """A copy of `results` whose records have the given missed counts per method (ascending dt)."""
    out = copy.deepcopy(results)
    for method, counts in method_missed.items():
        records = sorted((r for r in out["records"] if r["method"] == method), key=lambda r: r["dt"])
        for r, m in zip(records, counts):
            r["missed"] = m
            r["detected"] = r["events"] - r["initial_contacts"] - m  # as the results reader checks
            r["missed_fraction"] = m / max(1, r["events"] - r["initial_contacts"])
    return out


def frontier_cell(markdown, method):
    row = next(line for line in markdown.splitlines() if line.startswith(f"| {method} |"))
    return [c.strip() for c in row.strip("|").split("|")][2]


def test_frontier_tables_and_charts(tmp_path, cli, real_results):
    # aabb/sap misses at dt = 0.25 only: frontier 0.0625. capsule/grid misses nothing: every dt.
    results = with_missed(real_results, {"aabb/sap": [0, 0, 3], "capsule/grid": [0, 0, 0]})
    path = write_json(tmp_path / "r.json", results)
    out = tmp_path / "report"
    run = cli("report", path, "-o", out)
    assert run.returncode == 0
    md = (out / "report.md").read_text()
    assert frontier_cell(md, "aabb/sap") == "0.0625"
    assert frontier_cell(md, "capsule/grid") == "0.25 (every dt)"
    assert "![missed fraction against dt](missed.png)" in md
    for name in ("missed.png", "cost.png"):
        assert (out / name).read_bytes().startswith(b"\x89PNG")


def test_frontier_needs_every_smaller_dt(tmp_path, cli, real_results):
    # Zero at the largest dt but not at the middle one: the frontier is the smallest dt;
    # a miss at the smallest dt: no frontier.
    results = with_missed(real_results, {"aabb/sap": [0, 1, 0], "capsule/grid": [2, 0, 0]})
    out = tmp_path / "report"
    cli("report", write_json(tmp_path / "r.json", results), "-o", out)
    md = (out / "report.md").read_text()
    assert frontier_cell(md, "aabb/sap") == "0.0156"
    assert frontier_cell(md, "capsule/grid") == "none"


def test_html_is_self_contained_and_overlays_files(tmp_path, cli, real_results):
    first = write_json(tmp_path / "first.json", real_results)
    other = copy.deepcopy(real_results)
    other["experiment"]["name"] = "other-machine"
    second = write_json(tmp_path / "second.json", other)
    out = tmp_path / "report"
    cli("report", first, second, "-o", out)
    page = (out / "report.html").read_text()
    sources = re.findall(r'(?:src|href)="([^"]*)"', page)
    assert sources and all(s.startswith("data:image/png;base64,") for s in sources)
    for s in sources:
        assert base64.b64decode(s.split(",", 1)[1]).startswith(b"\x89PNG")
    assert "<script" not in page and "http" not in page
    md = (out / "report.md").read_text()
    assert "gas300 (first.json)" in md and "other-machine (second.json)" in md
    rows = [line for line in md.splitlines() if line.startswith("| gas300") or line.startswith("| other-machine")]
    assert len(rows) == 4  # one table over both files: 2 files x 2 methods


@pytest.mark.parametrize("edit, field", [
    (lambda r: r["records"][1].__setitem__("missed", -1), "records[1].missed"),
    (lambda r: r["records"][0].pop("dt"), "records[0].dt"),
    (lambda r: r.__setitem__("format", "ccdlab-results/1"), "format"),
    (lambda r: r.__setitem__("records", []), "records"),
])
def test_bad_results_exit_2_naming_the_field(tmp_path, cli, real_results, edit, field):
    bad = copy.deepcopy(real_results)
    edit(bad)
    path = write_json(tmp_path / "bad.json", bad)
    run = cli("report", path, "-o", tmp_path / "out", check=False)
    assert run.returncode == 2
    assert run.stderr.strip() == run.stderr.strip().splitlines()[0]
    assert f"{path}: {field}:" in run.stderr
    assert not (tmp_path / "out" / "report.html").exists()


def test_not_json_exits_2(tmp_path, cli):
    (tmp_path / "x.json").write_text("{")
    run = cli("report", tmp_path / "x.json", "-o", tmp_path / "out", check=False)
    assert run.returncode == 2 and "x.json: malformed JSON" in run.stderr


@pytest.mark.skipif(not os.path.exists("/usr/bin/chromium"), reason="Debian's chromium is not installed")
def test_chromium_renders_the_report(tmp_path, cli, real_results):
    out = tmp_path / "report"
    cli("report", write_json(tmp_path / "r.json", real_results), "-o", out)
    dom = subprocess.run(["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
                          (out / "report.html").as_uri()], capture_output=True, text=True, timeout=120)
    assert dom.returncode == 0
    assert dom.stdout.count("<img") == 2 and "capsule/grid" in dom.stdout
    shot = tmp_path / "shot.png"
    subprocess.run(["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", f"--screenshot={shot}",
                    "--window-size=1200,1600", (out / "report.html").as_uri()], capture_output=True, timeout=120)
    assert shot.read_bytes().startswith(b"\x89PNG") and shot.stat().st_size > 20000


@pytest.fixture(scope="module")
def floor_run(tmp_path_factory):
    """floor_ramp (a floor and ramps) through `ccdlab run`: at 60 Hz aabb/grid misses no
    body-body contact but floor contacts; the results and the summary beside them."""
    from conftest import ccdlab_cli
    folder = tmp_path_factory.mktemp("floor")
    experiment = write_json(folder / "floor.json", {
        "format": "ccdlab-experiment/1", "name": "floor", "scene": {"generator": "floor_ramp"},
        "hz": [60, 120, 240], "methods": ["aabb/grid", "swept_aabb/grid"]})
    ccdlab_cli("run", experiment, "-o", folder / "r.json", "--quiet", "--threads", "2")
    return folder / "r.json", (folder / "r.summary.md").read_text()


def cells_of(markdown, method):
    """The cells of every Markdown table row of `method`."""
    return [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in markdown.splitlines() if line.startswith(f"| {method} |")]


def test_floor_contacts_count_and_the_summary_agrees(tmp_path, cli, floor_run):
    path, summary = floor_run
    records = json.loads(path.read_text())["records"]
    at60 = next(r for r in records if r["method"] == "aabb/grid" and r["hz"] == 60)
    assert at60["missed"] == 0 and at60["static_missed"] > 0  # the case: only floor contacts missed
    out = tmp_path / "report"
    cli("report", path, "-o", out)
    md = (out / "report.md").read_text()
    assert "1535 contacts to detect (1023 body-body, 512 body-scenery)" in md
    report_row = cells_of(md, "aabb/grid")[0]
    # The frontier is 120 Hz (1/120 s), not 60 Hz; the per-dt table counts the floor misses.
    assert report_row[2:4] == ["0.00833", "120"]
    assert cells_of(md, "aabb/grid")[1][1].startswith(f"{at60['static_missed']} of 1535 (")
    # The summary of `ccdlab run` gives the same frontier and the same cheapest zero-miss point.
    summary_row = cells_of(summary, "aabb/grid")[0]
    assert summary_row[1] == report_row[3]          # frontier (Hz)
    assert summary_row[2] == report_row[4]          # cheapest zero-miss cost (s/s)
    assert summary_row[3] == report_row[6]          # at (Hz)
    assert f"{1 / float(report_row[6]):.3g}" == report_row[5]  # the same dt in seconds
    assert cells_of(summary, "aabb/grid")[1][1].startswith(f"{at60['static_missed']} (")
