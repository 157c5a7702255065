#!/usr/bin/python3
"""Prints what the launch scripts need to know about an experiment file.

usage: scripts/experiment-info.py EXPERIMENT.json

Two lines: the experiment's name (its `name`, else the file name without `.json`), then
the scene, either `file ABSOLUTE_PATH` (a scene file, resolved against the experiment's
folder as `ccdlab run` does) or `generator NAME KEY=VALUE ...` (the arguments of
`ccdlab scene` that write the same generated scene). Exits 2 on unreadable input;
`ccdlab run` reports every other problem with the file.
"""
import json
import os
import sys


def value(v):
    if isinstance(v, list):
        return ",".join(value(x) for x in v)
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ValueError(f"generator parameter {json.dumps(v)} is not a number")
    return repr(v)


def main(argv):
    if len(argv) != 2:
        print("usage: scripts/experiment-info.py EXPERIMENT.json", file=sys.stderr)
        return 2
    path = argv[1]
    try:
        with open(path) as f:
            e = json.load(f)
        name = e.get("name") or os.path.basename(path).removesuffix(".json")
        scene = e["scene"]
        if isinstance(scene, str):
            where = "file " + os.path.abspath(os.path.join(os.path.dirname(path), scene))
        else:
            params = dict(scene)
            where = "generator " + " ".join([params.pop("generator")] +
                                            [f"{k}={value(v)}" for k, v in params.items()])
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as err:
        print(f"experiment-info: {path}: {err}", file=sys.stderr)
        return 2
    print(name)
    print(where)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
