"""Reading ccdlab results files (ccdlab-results/2) for the scripts that draw them
(report.py, animate.py, plot.py): one place for opening, parsing and the format check."""
import json


class BadInput(Exception):
    """Input that is not what the script reads: the message names the file and the field."""


def read_results(path):
    """The parsed results file; BadInput for a file that cannot be read, is not JSON, or is
    not ccdlab-results/2."""
    try:
        with open(path) as f:
            res = json.load(f)
    except OSError as e:
        raise BadInput(f"{path}: {e.strerror}")
    except json.JSONDecodeError as e:
        raise BadInput(f"{path}: not JSON ({e.msg} at line {e.lineno})")
    if not isinstance(res, dict) or res.get("format") != "ccdlab-results/2":
        raise BadInput(f'{path}: format: must be "ccdlab-results/2"')
    return res


def by_method(records):
    """Records grouped by method (in first-seen order), each group sorted by dt."""
    out = {}
    for r in records:
        out.setdefault(r["method"], []).append(r)
    for rs in out.values():
        rs.sort(key=lambda r: r["dt"])
    return out
