#!/usr/bin/python3
"""A report of one or more ccdlab results files (ccdlab-results/2): `ccdlab report`.

usage: /usr/bin/python3 scripts/report.py RESULTS.json... -o DIR [--title TEXT]

Writes into DIR:
  report.md     per method: the zero-miss frontier (largest dt at and below which the
                method missed nothing), the missed fraction per dt and the cost; with
                several files, one table over all of them; the charts as PNG files beside it
  report.html   the same, self-contained (charts embedded as data: URIs, no script, no
                server): it opens in any browser
  missed.png, cost.png   the charts: every file's runs overlaid (one colour per method,
                one line style per file)
Reads results only; a file that is not a results file exits with status 2 and one line
naming the file and the field. Needs Debian's python3-matplotlib.
"""
import argparse
import base64
import html
import io
import json
import math
import os
import sys

import matplotlib
from results_json import BadInput, by_method, read_results

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIELDS = {"method": str, "dt": float, "missed": int, "missed_fraction": float, "events": int,
          "initial_contacts": int, "seconds_per_simulated_second": float, "continuous": bool,
          "false_positives_per_step": float}
STYLES = ["-", "--", ":", "-."]
MARKERS = "osD^v<>pP*Xh"


def load(path):
    res = read_results(path)
    records = res.get("records")
    if not isinstance(records, list) or not records:
        raise BadInput(f"{path}: records: must be a non-empty array")
    for i, r in enumerate(records):
        if not isinstance(r, dict):
            raise BadInput(f"{path}: records[{i}]: must be an object")
        for k, kind in FIELDS.items():
            v = r.get(k)
            ok = (isinstance(v, bool) if kind is bool else
                  isinstance(v, str) if kind is str else
                  isinstance(v, int) and not isinstance(v, bool) and v >= 0 if kind is int else
                  isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v >= 0)
            if not ok:
                raise BadInput(f"{path}: records[{i}].{k}: missing or not a {kind.__name__}"
                               + ("" if kind in (bool, str) else " >= 0"))
        if r["dt"] <= 0:
            raise BadInput(f"{path}: records[{i}].dt: must be > 0")
    return res


def label_of(path, res, all_paths):
    """A short name for a file: its experiment name, made unique by the file name."""
    name = res.get("experiment", {}).get("name") if isinstance(res.get("experiment"), dict) else None
    base = os.path.basename(path)
    names = [os.path.basename(p) for p in all_paths]
    return f"{name} ({base})" if name and names.count(base) == 1 else path


def frontier(runs):
    """The largest dt such that the method missed nothing at it and at every smaller dt run;
    None when it missed something at the smallest dt."""
    best = None
    for r in runs:  # ascending dt
        if r["missed"] != 0:
            break
        best = r
    return best


def summary_rows(files):
    rows = []
    for label, res in files:
        for method, runs in by_method(res["records"]).items():
            f = frontier(runs)
            worst = runs[-1]
            rows.append({
                "file": label, "method": method,
                "kind": "continuous" if runs[0]["continuous"] else "discrete",
                "frontier": f["dt"] if f else None,
                "frontier_cost": f["seconds_per_simulated_second"] if f else None,
                "all_zero": f is worst,
                "largest_dt": worst["dt"], "missed_at_largest": worst["missed_fraction"],
                "cost_at_largest": worst["seconds_per_simulated_second"],
            })
    return rows


def fmt(x, pct=False):
    if x is None:
        return "none"
    if pct:
        return f"{100 * x:.3g} %"
    return f"{x:.3g}"


def chart(files, key, ylabel, title, log_y):
    fig, ax = plt.subplots(figsize=(8, 5))
    methods = sorted({r["method"] for _, res in files for r in res["records"]})
    colours = {m: plt.cm.tab10(i % 10) if len(methods) <= 10 else plt.cm.tab20(i % 20)
               for i, m in enumerate(methods)}
    for fi, (label, res) in enumerate(files):
        for method, runs in by_method(res["records"]).items():
            xs = [r["dt"] for r in runs]
            ys = [r[key] for r in runs]
            if log_y:
                ys = [y if y > 0 else float("nan") for y in ys]
            name = method if len(files) == 1 else f"{method} [{fi + 1}]"
            ax.plot(xs, ys, STYLES[fi % len(STYLES)], marker=MARKERS[methods.index(method) % len(MARKERS)],
                    color=colours[method], label=name, markersize=4)
    ax.set_xscale("log")
    if log_y:
        ax.set_yscale("log")
    ax.set_xlabel("dt (s)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    png = io.BytesIO()
    fig.savefig(png, format="png", dpi=110)
    plt.close(fig)
    return png.getvalue()


def file_notes(files):
    lines = []
    for i, (label, res) in enumerate(files):
        scene = res.get("scene", {}) if isinstance(res.get("scene"), dict) else {}
        env = res.get("environment", {}) if isinstance(res.get("environment"), dict) else {}
        truth = res.get("truth", {}) if isinstance(res.get("truth"), dict) else {}
        parts = [f"[{i + 1}] {label}:"]
        if "bodies" in scene:
            parts.append(f"{scene['bodies']} bodies, horizon {scene.get('horizon')} s")
        if "events" in truth:
            parts.append(f"{truth['events']} ground-truth events")
        if env.get("cpu"):
            parts.append(f"on {env['cpu']}")
        lines.append(parts[0] + " " + ", ".join(parts[1:]))
    return lines


def write_report(paths, out_dir, title):
    files = []
    for p in paths:
        res = load(p)
        files.append((label_of(p, res, paths), res))
    rows = summary_rows(files)
    several = len(files) > 1
    charts = {
        "missed": chart(files, "missed_fraction", "missed fraction", "Missed contacts against dt", True),
        "cost": chart(files, "seconds_per_simulated_second", "seconds per simulated second",
                      "Cost against dt", True),
    }
    os.makedirs(out_dir, exist_ok=True)
    for name, png in charts.items():
        with open(os.path.join(out_dir, f"{name}.png"), "wb") as f:
            f.write(png)

    head = (["file"] if several else []) + ["method", "kind", "zero-miss frontier dt (s)",
                                            "cost there (s/s)", "largest dt (s)", "missed at largest dt",
                                            "cost at largest dt (s/s)"]

    def cells(r):
        frontier_text = fmt(r["frontier"]) + (" (every dt)" if r["all_zero"] else "")
        return (([r["file"]] if several else []) +
                [r["method"], r["kind"], frontier_text, fmt(r["frontier_cost"]), fmt(r["largest_dt"]),
                 fmt(r["missed_at_largest"], pct=True), fmt(r["cost_at_largest"])])

    per_dt = []  # one table per file: missed fraction per (method, dt)
    for label, res in files:
        dts = sorted({r["dt"] for r in res["records"]}, reverse=True)
        table = {m: {r["dt"]: r["missed_fraction"] for r in runs} for m, runs in by_method(res["records"]).items()}
        per_dt.append((label, dts, table))

    notes = file_notes(files)
    explain = ("The zero-miss frontier of a method is the largest timestep at which it missed no "
               "contact, at that timestep and at every smaller one run; cost is the run's seconds per "
               "simulated second.")

    md = [f"# {title}", "", explain, ""]
    md += [f"- {n}" for n in notes] + [""]
    md += ["## Zero-miss frontier and cost", "", "| " + " | ".join(head) + " |",
           "|" + "---|" * len(head)]
    md += ["| " + " | ".join(cells(r)) + " |" for r in rows]
    md += ["", "![missed fraction against dt](missed.png)", "", "![cost against dt](cost.png)", ""]
    for label, dts, table in per_dt:
        md += [f"## Missed fraction per dt: {label}", "",
               "| method | " + " | ".join(f"{d:.3g}" for d in dts) + " |", "|---|" + "---|" * len(dts)]
        for m, by_dt in table.items():
            md.append(f"| {m} | " + " | ".join(fmt(by_dt.get(d), pct=True) if d in by_dt else "" for d in dts) + " |")
        md.append("")

    def img(name, alt):
        data = base64.b64encode(charts[name]).decode("ascii")
        return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'

    def table_html(header, body):
        out = ["<table>", "<tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in header) + "</tr>"]
        def td(c):  # numbers right-aligned, words left-aligned
            numeric = c[:1].isdigit() or c == "none" or c == ""
            return f"<td>{html.escape(c)}</td>" if numeric else f'<td class="t">{html.escape(c)}</td>'
        out += ["<tr>" + "".join(td(c) for c in row) + "</tr>" for row in body]
        return "\n".join(out + ["</table>"])

    h = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
         f"<title>{html.escape(title)}</title>",
         "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em}"
         "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;"
         "text-align:right}td.t,th:first-child{text-align:left}img{max-width:100%}</style>",
         "</head><body>", f"<h1>{html.escape(title)}</h1>", f"<p>{html.escape(explain)}</p>", "<ul>"]
    h += [f"<li>{html.escape(n)}</li>" for n in notes] + ["</ul>", "<h2>Zero-miss frontier and cost</h2>"]
    h.append(table_html(head, [cells(r) for r in rows]))
    h += [img("missed", "missed fraction against dt"), img("cost", "cost against dt")]
    for label, dts, table in per_dt:
        h.append(f"<h2>Missed fraction per dt: {html.escape(label)}</h2>")
        h.append(table_html(["method"] + [f"{d:.3g}" for d in dts],
                            [[m] + [fmt(by_dt[d], pct=True) if d in by_dt else "" for d in dts]
                             for m, by_dt in table.items()]))
    h.append("</body></html>")

    write_atomic(os.path.join(out_dir, "report.md"), "\n".join(md) + "\n")
    write_atomic(os.path.join(out_dir, "report.html"), "\n".join(h) + "\n")
    return [os.path.join(out_dir, n) for n in ("report.md", "report.html", "missed.png", "cost.png")]


def write_atomic(path, text):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    ap = argparse.ArgumentParser(prog="ccdlab report", description="Report of ccdlab results files")
    ap.add_argument("results", nargs="+", metavar="RESULTS.json")
    ap.add_argument("-o", "--output", required=True, metavar="DIR")
    ap.add_argument("--title", default="ccdlab report")
    args = ap.parse_args(argv)
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        print(f"ccdlab report: {args.output}: -o must name a folder", file=sys.stderr)
        return 2
    try:
        written = write_report(args.results, args.output, args.title)
    except BadInput as e:
        print(f"ccdlab report: {e}", file=sys.stderr)
        return 2
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
