"""Reading ccdlab results files (ccdlab-results/2) for the scripts that draw them
(report.py, animate.py, plot.py): one place for opening, parsing and the format check.

Parsing is as strict as the C++ reader (ccd/io/json_reader.hpp), so that a file means one
thing and no input ends in a traceback: the text must be UTF-8, a key may appear once per
object, objects and arrays nest at most 64 deep, numbers must fit a double (no NaN or
Infinity), and a file is at most 1 GiB. Every failure raises BadInput naming the file.
"""
import json
import math
import os
import stat

MAX_DEPTH = 64  # ccd::kMaxJsonDepth
MAX_BYTES = 1 << 30  # ccd::kMaxJsonBytes


class BadInput(Exception):
    """Input that is not what the script reads: the message names the file and the field."""


def shown(text):
    """`text` (a file name, a field, a value from a file) for a one-line message: characters
    that are not printable as escapes (\\n, \\x1b, \\u2028), bytes that were not UTF-8 in a
    file name (os.fsdecode's stand-ins) as \\xNN."""
    out = []
    for c in str(text):
        if "\udc80" <= c <= "\udcff":
            out.append(f"\\x{ord(c) - 0xdc00:02x}")
        elif c.isprintable():
            out.append(c)
        else:
            out.append(c.encode("unicode_escape", "backslashreplace").decode("ascii"))
    return "".join(out)


def _no_twice(pairs):
    out = {}
    for key, value in pairs:
        if key in out:
            raise BadInput(f"{shown(key)}: given twice in one object")
        out[key] = value
    return out


def _constant(name):
    raise BadInput(f"{name}: not a JSON number (NaN and Infinity are not JSON)")


def _float(text):
    x = float(text)
    if not math.isfinite(x):
        raise BadInput(f"{shown(text[:40])}: the number does not fit a double")
    return x


def _int(text):
    if len(text.lstrip("-")) > 309:
        raise BadInput(f"{shown(text[:40])}...: the number does not fit a double")
    return int(text)


def _depth(value):
    """The nesting depth of objects and arrays (1 for a flat object)."""
    deepest, stack = 0, [(value, 1)]
    while stack:
        v, d = stack.pop()
        if isinstance(v, (dict, list)):
            deepest = max(deepest, d)
            if d > MAX_DEPTH:
                break
            stack.extend((x, d + 1) for x in (v.values() if isinstance(v, dict) else v))
    return deepest


def parse_json(path):
    """The parsed JSON file `path`; BadInput naming the file for what cannot be read."""
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            raise BadInput(f"{shown(path)}: not a regular file")
        with open(path, "rb") as f:
            raw = f.read(MAX_BYTES + 1)
    except OSError as e:
        raise BadInput(f"{shown(path)}: {e.strerror}")
    if len(raw) > MAX_BYTES:
        raise BadInput(f"{shown(path)}: larger than 1 GiB")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise BadInput(f"{shown(path)}: not UTF-8 (byte {e.start} is 0x{raw[e.start]:02x})")
    try:
        doc = json.loads(text, object_pairs_hook=_no_twice, parse_constant=_constant, parse_float=_float,
                         parse_int=_int)
    except BadInput as e:
        raise BadInput(f"{shown(path)}: {e}")
    except json.JSONDecodeError as e:
        raise BadInput(f"{shown(path)}: not JSON ({e.msg} at line {e.lineno})")
    except RecursionError:
        raise BadInput(f"{shown(path)}: nests deeper than {MAX_DEPTH} objects and arrays")
    except ValueError as e:  # e.g. an integer of more digits than Python converts
        raise BadInput(f"{shown(path)}: not JSON ({shown(e)})")
    if _depth(doc) > MAX_DEPTH:
        raise BadInput(f"{shown(path)}: nests deeper than {MAX_DEPTH} objects and arrays")
    return doc


def read_results(path):
    """The parsed results file; BadInput for a file that cannot be read, is not JSON, or is
    not ccdlab-results/2."""
    res = parse_json(path)
    if not isinstance(res, dict) or res.get("format") != "ccdlab-results/2":
        raise BadInput(f'{shown(path)}: format: must be "ccdlab-results/2"')
    return res


def by_method(records):
    """Records grouped by method (in first-seen order), each group sorted by dt."""
    out = {}
    for r in records:
        out.setdefault(r["method"], []).append(r)
    for rs in out.values():
        rs.sort(key=lambda r: r["dt"])
    return out
