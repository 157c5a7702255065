# ccdlab.plot: the charts of scripts/plot.py as matplotlib Figures of a run's results (a
# ccdlab.Results or a plain results dict), nothing written; scripts/plot.py draws its files
# with the same functions.
import json
import os

import matplotlib

matplotlib.use("Agg")
from matplotlib.figure import Figure  # noqa: E402
import pytest  # noqa: E402

import ccdlab  # noqa: E402
from conftest import SOURCE_DIR  # noqa: E402

CONTINUOUS = ["swept_aabb/sap", "capsule/grid"]
DISCRETE = ["aabb/sap", "sphere/grid", "obb/brute"]
DT = [0.25, 0.0625, 0.015625]


@pytest.fixture(scope="module")
def results():
    res = ccdlab.run({"format": "ccdlab-experiment/1", "name": "charts", "dt": DT,
                      "methods": DISCRETE + CONTINUOUS, "scene": ccdlab.generate("gas", bodies=300, seed=3)},
                     threads=2)
    assert sum(r["missed"] for r in res["records"]) > 0  # lines that are not all zero
    return res


def lines(ax):
    return [line for line in ax.get_lines() if line.get_label() and not line.get_label().startswith("_")]


@pytest.mark.parametrize("chart", ["missed", "false_positives", "cost"])
def test_line_charts_draw_one_line_per_method(results, chart):
    fig = getattr(ccdlab.plot, chart)(results)
    assert isinstance(fig, Figure)
    assert len(fig.axes) == 1
    ax = fig.axes[0]
    assert [line.get_label() for line in lines(ax)] == results.methods()
    assert ax.get_xscale() == "log" and ax.get_xlabel() == "timestep dt (s)"
    for line in lines(ax):
        assert sorted(line.get_xdata()) == DT[::-1]
    assert "charts: 300 bodies" in ax.get_title()


def test_penetration_draws_the_discrete_methods_only(results):
    fig = ccdlab.plot.penetration(results)
    assert [line.get_label() for line in lines(fig.axes[0])] == DISCRETE
    only_continuous = dict(results, records=[r for r in results["records"] if r["continuous"]])
    with pytest.raises(ValueError, match="continuous"):
        ccdlab.plot.penetration(only_continuous)


def test_speed_accuracy_has_a_point_set_per_method_and_the_zero_miss_panel(results):
    fig = ccdlab.plot.speed_accuracy(results, cost="cpu")
    assert len(fig.axes) == 2
    points, bars = fig.axes
    assert len(points.collections) == len(results.methods())  # one scatter per method
    assert [line.get_label() for line in lines(points)] == ["Pareto front"]
    # A bar per method that missed nothing at some dt; the others are listed without one.
    zero_somewhere = [m for m in results.methods() if any(r["missed"] == 0 for r in results.records if r["method"] == m)]
    never = [m for m in results.methods() if m not in zero_somewhere]
    assert len(bars.patches) == len(zero_somewhere)
    assert [t.get_text() for t in bars.texts].count("misses at every dt") == len(never)
    assert [t.get_text() for t in bars.get_yticklabels()] == sorted(
        results.methods(), key=lambda m: (m in never, min((r["cpu_seconds_per_simulated_second"] for r in
                                                            results.records if r["method"] == m and r["missed"] == 0),
                                                           default=0), m))
    assert "CPU" in points.get_xlabel()


def test_every_chart_from_a_plain_dict_and_nothing_written(results, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    plain = json.loads(json.dumps(results))
    figures = ccdlab.plot.charts(plain)
    assert list(figures) == list(ccdlab.plot.CHARTS)
    assert all(isinstance(f, Figure) for f in figures.values())
    assert os.listdir(tmp_path) == []
    figures["missed"].savefig(tmp_path / "missed.png")  # savefig is the caller's
    assert (tmp_path / "missed.png").stat().st_size > 0


def test_bad_input():
    with pytest.raises(ValueError, match="records"):
        ccdlab.plot.missed({"records": []})
    with pytest.raises(ValueError, match="cost"):
        ccdlab.plot.cost({"records": [{}]}, cost="gpu")


def test_scripts_plot_draws_with_the_package_module(results, tmp_path):
    import importlib
    import sys
    sys.path.insert(0, str(SOURCE_DIR / "scripts"))
    try:
        script = importlib.import_module("plot")
    finally:
        sys.path.pop(0)
    assert os.path.samefile(script.charts.__file__, SOURCE_DIR / "python" / "ccdlab" / "plot.py")
    assert script.style is script.charts.style and script.by_method is script.charts.by_method
    path = tmp_path / "results.json"
    path.write_text(json.dumps(results))
    script.main([str(path), "-o", str(tmp_path / "plots"), "--format", "png"])
    assert sorted(os.listdir(tmp_path / "plots")) == sorted(f"{c}.png" for c in ccdlab.plot.CHARTS)
