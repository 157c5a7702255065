#!/usr/bin/python3
"""Checks that two ccdlab results files hold the same results count for count.

usage: scripts/compare-results.py EXPECTED.json ACTUAL.json

Compares the experiment, the scene, the ground truth's counts and every record, field by
field, and ignores what legitimately differs between two runs of one experiment: timings
(every field whose name contains `seconds`), `environment` (host, threads, build),
`shard`, `peak_memory_bytes` and where the ground truth came from (`truth.source`). A count
added to the format later (`undecided`, `static_undecided`) reads as 0 where a file lacks it,
as the library's results reader does.
A sharded run merged with `ccdlab merge` must equal a single run of the same experiment.
Prints one line (`same: N records` or the first differences) and exits 0 when equal,
1 when not, 2 on unreadable input.
"""
import json
import sys

IGNORED_TOP = {"environment", "shard", "peak_memory_bytes"}
IGNORED_TRUTH = {"source"}
# Counts newer than some files: absent reads as 0 (experiments/results_file.cpp does the same).
DEFAULT_ZERO = {"undecided", "static_undecided", "undecided_events"}


def strip(value):
    """The value without timing fields, recursively."""
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if "seconds" not in k}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


def differences(a, b, where, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                if k in DEFAULT_ZERO and (a if k in a else b)[k] == 0:
                    continue
                out.append(f"{where}.{k}: only in {'expected' if k in a else 'actual'}")
            else:
                differences(a[k], b[k], f"{where}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            differences(x, y, f"{where}[{i}]", out)
    elif isinstance(a, list) and isinstance(b, list):
        out.append(f"{where}: expected {len(a)} entries, got {len(b)}")
    elif a != b or type(a) is not type(b):
        out.append(f"{where}: expected {json.dumps(a)}, got {json.dumps(b)}")


def comparable(results):
    r = {k: v for k, v in results.items() if k not in IGNORED_TOP}
    if isinstance(r.get("truth"), dict):
        r["truth"] = {k: v for k, v in r["truth"].items() if k not in IGNORED_TRUTH}
    return strip(r)


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        expected, actual = (json.load(open(p)) for p in argv[1:])
    except (OSError, ValueError) as e:
        print(f"compare-results: {e}", file=sys.stderr)
        return 2
    out = []
    differences(comparable(expected), comparable(actual), "", out)
    if out:
        print(f"{len(out)} difference(s): " + "; ".join(out[:5]) + (" ..." if len(out) > 5 else ""))
        return 1
    print(f"same: {len(expected.get('records', []))} records")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
