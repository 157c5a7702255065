#!/usr/bin/python3
"""A report of one or more ccdlab results files (ccdlab-results/2): `ccdlab report`.

usage: /usr/bin/python3 scripts/report.py RESULTS.json... -o DIR [--title TEXT]

Writes into DIR:
  report.md     the contacts to detect (body-body and body-scenery); per method: the
                zero-miss frontier (largest dt at and below which the method missed
                nothing, of either kind), the cheapest zero-miss cost at or below it
                (the rule of the summary `ccdlab run` prints), the missed contacts per
                dt ("311 of 1535 (20.3 %)") and the cost; with
                several files, one table over all of them; the charts as PNG files beside it
  report.html   the same, self-contained (charts embedded as data: URIs, no script, no
                server): it opens in any browser
  missed.png, cost.png   the charts: every file's runs overlaid (one colour per method,
                one line style per file)
When no method missed a contact at any dt, the report says so first ("Nothing was
missed"); charts of all-zero or single-point series are drawn on a linear axis where a
log axis has nothing to show. The outputs are written to temporary files in DIR and
renamed into place together at the end: on any failure (a full disk, a read-only folder)
every old output stays as it was and no temporary file is left.

Reads results only; a file that is not a results file (or a file given twice) exits with
status 2 and one line naming the file and the field; a failure to write exits with status
1 and one line. Needs Debian's python3-matplotlib.
"""
import argparse
import base64
import html
import io
import math
import os
import signal
import sys

import matplotlib
from results_json import BadInput, by_method, read_results, shown

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIELDS = {"method": str, "dt": float, "missed": int, "missed_fraction": float, "events": int,
          "initial_contacts": int, "seconds_per_simulated_second": float, "continuous": bool,
          "false_positives_per_step": float}
# Counts a record may lack (a results file of a scene without scenery, before `undecided`):
# read as 0, as the results reader does.
OPTIONAL_COUNTS = ("undecided", "static_events", "static_initial_contacts", "static_undecided", "static_missed")
STYLES = ["-", "--", ":", "-."]
MARKERS = "osD^v<>pP*Xh"


# Numbers drawn on a log axis must lie in this range (or be 0): beyond it a chart's axis
# limits and ticks overflow a double.
DRAWABLE = (1e-300, 1e300)


def load(path):
    res = read_results(path)
    name = shown(path)
    records = res.get("records")
    if not isinstance(records, list) or not records:
        raise BadInput(f"{name}: records: must be a non-empty array")
    for key in ("experiment", "scene", "truth", "environment"):
        if key in res and not isinstance(res[key], dict):
            raise BadInput(f"{name}: {key}: must be an object")
    if not isinstance(res.get("experiment", {}).get("name", ""), str):
        raise BadInput(f"{name}: experiment.name: must be a string")
    for i, r in enumerate(records):
        if not isinstance(r, dict):
            raise BadInput(f"{name}: records[{i}]: must be an object")
        for k, kind in FIELDS.items():
            v = r.get(k)
            ok = (isinstance(v, bool) if kind is bool else
                  isinstance(v, str) if kind is str else
                  isinstance(v, int) and not isinstance(v, bool) and v >= 0 if kind is int else
                  isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v >= 0)
            if not ok:
                raise BadInput(f"{name}: records[{i}].{k}: missing or not a {kind.__name__}"
                               + ("" if kind in (bool, str) else " >= 0"))
            if kind is float and v != 0 and not DRAWABLE[0] <= v <= DRAWABLE[1]:
                raise BadInput(f"{name}: records[{i}].{k}: {v:g} is outside [1e-300, 1e300], beyond what a chart "
                               "can draw")
        for k in OPTIONAL_COUNTS:
            v = r.get(k, 0)
            if not isinstance(v, int) or isinstance(v, bool) or v < 0:
                raise BadInput(f"{name}: records[{i}].{k}: not an int >= 0")
        if r["dt"] <= 0:
            raise BadInput(f"{name}: records[{i}].dt: must be > 0")
        count_contacts(r)
    return res


def count_contacts(r):
    """Adds to a record its contacts, body-body and body-scenery together (the rule of
    experiments/record_contacts.hpp): contacts_body and contacts_scenery to detect (the
    events less those in progress at t = 0 and those the truth could not decide),
    contacts_missed, contacts_to_detect and contacts_missed_fraction."""
    r["contacts_body"] = max(0, r["events"] - r["initial_contacts"] - r.get("undecided", 0))
    r["contacts_scenery"] = max(0, r.get("static_events", 0) - r.get("static_initial_contacts", 0)
                                - r.get("static_undecided", 0))
    r["contacts_to_detect"] = r["contacts_body"] + r["contacts_scenery"]
    r["contacts_missed"] = r["missed"] + r.get("static_missed", 0)
    r["contacts_missed_fraction"] = r["contacts_missed"] / r["contacts_to_detect"] if r["contacts_to_detect"] else 0.0


def rate(r):
    """"311 of 1535 (20.3 %)", or "0 of 1535"."""
    if r["contacts_missed"] == 0:
        return f"0 of {r['contacts_to_detect']}"
    return f"{r['contacts_missed']} of {r['contacts_to_detect']} ({fmt(r['contacts_missed_fraction'], pct=True)})"


def load_all(paths):
    """Every file loaded, each once: a file given twice (under any name) or two files with
    the same results are refused (their lines would hide each other)."""
    files, seen = [], []
    for p in paths:
        try:
            st = os.stat(p)
        except OSError as e:
            raise BadInput(f"{shown(p)}: {e.strerror}")
        res = load(p)
        for q, q_st, q_res in seen:
            if (st.st_dev, st.st_ino) == (q_st.st_dev, q_st.st_ino):
                raise BadInput(f"{shown(p)}: given twice (also as {shown(q)})")
            if res == q_res:
                raise BadInput(f"{shown(p)}: the same results as {shown(q)}")
        seen.append((p, st, res))
        files.append((label_of(p, res, paths), res))
    return files


def label_of(path, res, all_paths):
    """A short name for a file: its experiment name, made unique by the file name."""
    name = res.get("experiment", {}).get("name")
    base = os.path.basename(path)
    names = [os.path.basename(p) for p in all_paths]
    return shown(f"{name} ({base})" if name and names.count(base) == 1 else path)


def frontier(runs):
    """The largest dt such that the method missed nothing (body-body or body-scenery) at it
    and at every smaller dt run, and the cheapest run at or below it; (None, None) when it
    missed something at the smallest dt. The summary of `ccdlab run` uses the same rule."""
    best = cheapest = None
    for r in runs:  # ascending dt
        if r["contacts_missed"] != 0:
            break
        best = r
        if cheapest is None or r["seconds_per_simulated_second"] < cheapest["seconds_per_simulated_second"]:
            cheapest = r
    return best, cheapest


def summary_rows(files):
    rows = []
    for label, res in files:
        for method, runs in by_method(res["records"]).items():
            f, cheap = frontier(runs)
            worst = runs[-1]
            rows.append({
                "file": label, "method": method,
                "kind": "continuous" if runs[0]["continuous"] else "discrete",
                "frontier": f["dt"] if f else None,
                "cheapest_cost": cheap["seconds_per_simulated_second"] if cheap else None,
                "cheapest_dt": cheap["dt"] if cheap else None,
                "all_zero": f is worst,
                "largest_dt": worst["dt"], "missed_at_largest": rate(worst),
                "cost_at_largest": worst["seconds_per_simulated_second"],
            })
    return rows


def fmt(x, pct=False):
    if x is None:
        return "none"
    if isinstance(x, str):
        return x
    if pct:
        return f"{100 * x:.3g} %"
    return f"{x:.3g}"


def log_limits(values):
    """Limits of a log axis around the values > 0 (a factor 2 beyond each end, so that a
    single value sits mid-axis); None when no value is > 0."""
    positive = [v for v in values if v > 0]
    return (min(positive) / 2, max(positive) * 2) if positive else None


def chart(files, key, ylabel, title, scale, zero_note):
    """One chart of `key` against dt, every file's runs overlaid. `scale` is "symlog" (zero
    drawn at the bottom, a log axis above the smallest value > 0) or "log" (zeros left
    out); when no value is > 0 the axis is linear and `zero_note` says so on the chart."""
    fig, ax = plt.subplots(figsize=(8, 5))
    methods = sorted({r["method"] for _, res in files for r in res["records"]})
    colours = {m: plt.cm.tab10(i % 10) if len(methods) <= 10 else plt.cm.tab20(i % 20)
               for i, m in enumerate(methods)}
    all_x, all_y = [], []
    for fi, (label, res) in enumerate(files):
        for method, runs in by_method(res["records"]).items():
            xs = [r["dt"] for r in runs]
            ys = [r[key] for r in runs]
            all_x += xs
            all_y += ys
            if scale == "log":
                ys = [y if y > 0 else float("nan") for y in ys]
            name = method if len(files) == 1 else f"{method} [{fi + 1}]"
            ax.plot(xs, ys, STYLES[fi % len(STYLES)], marker=MARKERS[methods.index(method) % len(MARKERS)],
                    color=colours[method], label=name.replace("$", r"\$"), markersize=4)
    ax.set_xscale("log")
    ax.set_xlim(*log_limits(all_x))
    y_range = log_limits(all_y)
    if y_range is None:
        ax.set_ylim(-0.05, 1.0)
        ax.text(0.5, 0.5, zero_note, transform=ax.transAxes, ha="center", va="center", fontsize=14)
    elif scale == "symlog":
        ax.set_yscale("symlog", linthresh=y_range[0] * 2)
        ax.set_ylim(0, max(1.0, y_range[1]))
    else:
        ax.set_yscale("log")
        ax.set_ylim(*y_range)
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


def verdict(files):
    """Sentences on what was missed over all files: "Nothing was missed" when no method
    missed a contact at any dt, else the methods that missed nothing at every dt."""
    records = [r for _, res in files for r in res["records"]]
    methods = sorted({r["method"] for r in records})
    clean = [m for m in methods if all(r["contacts_missed"] == 0 for r in records if r["method"] == m)]
    fp = ("; and no method had a false positive" if all(r["false_positives_per_step"] == 0 for r in records)
          else "")
    if len(clean) == len(methods):
        return (f"Nothing was missed: no method missed a contact at any dt ({len(records)} runs of "
                f"{len(methods)} method{'s' if len(methods) > 1 else ''}){fp}.")
    if clean:
        return "Missed nothing at every dt run: " + ", ".join(clean) + "."
    return "Every method missed a contact at some dt."


def file_notes(files):
    lines = []
    for i, (label, res) in enumerate(files):
        scene = res.get("scene", {}) if isinstance(res.get("scene"), dict) else {}
        env = res.get("environment", {}) if isinstance(res.get("environment"), dict) else {}
        truth = res.get("truth", {}) if isinstance(res.get("truth"), dict) else {}
        parts = [f"[{i + 1}] {label}:"]
        if "bodies" in scene:
            parts.append(shown(f"{scene['bodies']} bodies, horizon {scene.get('horizon')} s"))
        first = res["records"][0]
        scenery = (f" ({first['contacts_body']} body-body, {first['contacts_scenery']} body-scenery)"
                   if first.get("static_events", 0) else "")
        parts.append(f"{first['contacts_to_detect']} contacts to detect{scenery}")
        if "events" in truth:
            parts.append(shown(f"{truth['events']} ground-truth body-body events"))
            if truth.get("static_events"):
                parts.append(shown(f"{truth['static_events']} body-scenery events"))
        if env.get("cpu"):
            parts.append(shown(f"on {env['cpu']}"))
        lines.append(parts[0] + " " + ", ".join(parts[1:]))
    return lines


OUTPUTS = ("report.md", "report.html", "missed.png", "cost.png")


def write_report(paths, out_dir, title):
    files = load_all(paths)
    check_output_folder(out_dir)
    rows = summary_rows(files)
    several = len(files) > 1
    charts = {
        "missed": chart(files, "contacts_missed_fraction", "missed fraction", "Missed contacts against dt", "symlog",
                        "nothing was missed at any dt"),
        "cost": chart(files, "seconds_per_simulated_second", "seconds per simulated second",
                      "Cost against dt", "log", "every cost is 0"),
    }

    head = (["file"] if several else []) + ["method", "kind", "zero-miss frontier dt (s)", "frontier (Hz)",
                                            "cheapest zero-miss cost (s/s)", "at dt (s)", "at (Hz)",
                                            "largest dt (s)", "missed at largest dt", "cost at largest dt (s/s)"]

    def hz(dt):
        return "none" if dt is None else f"{1 / dt:.4g}"

    def cells(r):
        frontier_text = fmt(r["frontier"]) + (" (every dt)" if r["all_zero"] else "")
        return (([r["file"]] if several else []) +
                [shown(r["method"]), r["kind"], frontier_text, hz(r["frontier"]), fmt(r["cheapest_cost"]),
                 fmt(r["cheapest_dt"]), hz(r["cheapest_dt"]), fmt(r["largest_dt"]), r["missed_at_largest"],
                 fmt(r["cost_at_largest"])])

    per_dt = []  # one table per file: missed contacts per (method, dt)
    for label, res in files:
        dts = sorted({r["dt"] for r in res["records"]}, reverse=True)
        table = {shown(m): {r["dt"]: rate(r) if r["contacts_missed"] else "0" for r in runs}
                 for m, runs in by_method(res["records"]).items()}
        per_dt.append((label, dts, table))

    text = {"title": shown(title), "verdict": verdict(files), "notes": file_notes(files),
            "explain": ("Contacts are body-body and body-scenery together (those in progress at t = 0 apart). "
                        "The zero-miss frontier of a method is the largest timestep at which it missed no "
                        "contact, at that timestep and at every smaller one run; the cheapest zero-miss cost is "
                        "the least cost at or below it; cost is the run's seconds per simulated second."),
            "head": head, "rows": [cells(r) for r in rows], "per_dt": per_dt}
    outputs = {"report.md": markdown(text).encode("utf-8"), "report.html": page(text, charts).encode("utf-8"),
               "missed.png": charts["missed"], "cost.png": charts["cost"]}
    write_together(out_dir, outputs)
    return [os.path.join(out_dir, n) for n in OUTPUTS]


def markdown(t):
    md = [f"# {t['title']}", "", t["verdict"], "", t["explain"], ""]
    md += [f"- {n}" for n in t["notes"]] + [""]
    md += ["## Zero-miss frontier and cost", "", "| " + " | ".join(t["head"]) + " |",
           "|" + "---|" * len(t["head"])]
    md += ["| " + " | ".join(row) + " |" for row in t["rows"]]
    md += ["", "![missed fraction against dt](missed.png)", "", "![cost against dt](cost.png)", ""]
    for label, dts, table in t["per_dt"]:
        md += [f"## Missed contacts per dt (s): {label}", "",
               "| method | " + " | ".join(f"{d:.3g}" for d in dts) + " |", "|---|" + "---|" * len(dts)]
        for m, by_dt in table.items():
            md.append(f"| {m} | " + " | ".join(fmt(by_dt.get(d), pct=True) if d in by_dt else "" for d in dts) + " |")
        md.append("")
    return "\n".join(md) + "\n"


def page(t, charts):
    """The self-contained HTML report: every text from the inputs goes through html.escape,
    and the page has no script."""
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
         f"<title>{html.escape(t['title'])}</title>",
         "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em}"
         "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;"
         "text-align:right}td.t,th:first-child{text-align:left}img{max-width:100%}</style>",
         "</head><body>", f"<h1>{html.escape(t['title'])}</h1>",
         f'<p id="verdict"><strong>{html.escape(t["verdict"])}</strong></p>',
         f"<p>{html.escape(t['explain'])}</p>", "<ul>"]
    h += [f"<li>{html.escape(n)}</li>" for n in t["notes"]] + ["</ul>", "<h2>Zero-miss frontier and cost</h2>"]
    h.append(table_html(t["head"], t["rows"]))
    h += [img("missed", "missed fraction against dt"), img("cost", "cost against dt")]
    for label, dts, table in t["per_dt"]:
        h.append(f"<h2>Missed contacts per dt (s): {html.escape(label)}</h2>")
        h.append(table_html(["method"] + [f"{d:.3g}" for d in dts],
                            [[m] + [fmt(by_dt[d], pct=True) if d in by_dt else "" for d in dts]
                             for m, by_dt in table.items()]))
    h.append("</body></html>")
    return "\n".join(h) + "\n"


def check_output_folder(out_dir):
    """-o must name a folder (or nothing yet), and none of the outputs in it may be a folder
    or another file that is not a plain file: checked before the work."""
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise BadInput(f"{shown(out_dir)}: -o must name a folder")
    for name in OUTPUTS:
        path = os.path.join(out_dir, name)
        if os.path.lexists(path) and not os.path.isfile(path):
            raise BadInput(f"{shown(path)}: exists and is not a regular file")


def write_together(out_dir, outputs):
    """Writes every {name: bytes} into out_dir, each to NAME.tmp.PID first (flushed to disk),
    then renames them all into place: on any failure before the renames (a full disk, a
    read-only folder, a signal) the old outputs stay as they were and every temporary file
    is removed. A folder out_dir created here is removed again on failure."""
    created = not os.path.isdir(out_dir)
    if created:
        os.makedirs(out_dir)
    pending = []
    try:
        for name, data in outputs.items():
            tmp = os.path.join(out_dir, f"{name}.tmp.{os.getpid()}")
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            pending.append((tmp, os.path.join(out_dir, name)))
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(data)
                    f.flush()
                    os.fsync(f.fileno())
            except OSError as e:  # a full disk: name the output
                raise OSError(e.errno, e.strerror, os.path.join(out_dir, name)) from None
        while pending:
            tmp, final = pending[0]
            os.replace(tmp, final)
            pending.pop(0)
    finally:
        for tmp, _ in pending:
            try:
                os.unlink(tmp)
            except OSError:
                pass
        if pending and created:
            try:
                os.rmdir(out_dir)
            except OSError:
                pass


def interrupted(signum, frame):
    raise KeyboardInterrupt


def main(argv):
    ap = argparse.ArgumentParser(prog="ccdlab report", description="Report of ccdlab results files")
    ap.add_argument("results", nargs="+", metavar="RESULTS.json")
    ap.add_argument("-o", "--output", required=True, metavar="DIR")
    ap.add_argument("--title", default="ccdlab report")
    args = ap.parse_args(argv)
    for signum in (signal.SIGTERM, signal.SIGHUP):  # leave no temporary file behind
        signal.signal(signum, interrupted)
    try:
        written = write_report(args.results, args.output, args.title)
    except BadInput as e:
        print(f"ccdlab report: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        where = f"{shown(e.filename)}: " if e.filename else ""
        print(f"ccdlab report: {where}{e.strerror or e} (nothing written)", file=sys.stderr)
        return 1
    except MemoryError:
        print("ccdlab report: out of memory (nothing written)", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("ccdlab report: interrupted (nothing written)", file=sys.stderr)
        return 130
    except Exception as e:  # noqa: BLE001  one line, never a traceback
        print(f"ccdlab report: {type(e).__name__}: {shown(e)} (nothing written)", file=sys.stderr)
        return 1
    for p in written:
        print(shown(p))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
