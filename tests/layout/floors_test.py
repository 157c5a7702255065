#!/usr/bin/env python3
"""No folder includes a folder above it (docs/architecture.md, "Floors").

Reads every #include of the project's C++ sources and fails, naming the file, the line and
both floors, where a file includes a header from a higher floor. Relative includes
("../experiments/runner.hpp") are resolved against the including file's folder.

Usage: floors_test.py SOURCE_DIR
"""
import pathlib
import re
import sys

# Bottom first. A file belongs to the first entry that is a prefix of its path; files of the
# same floor may include each other. The narrow phases call the exact solvers of ccd/truth/,
# so truth sits under narrow.
FLOORS = [
    ["ccd/geometry/"],
    ["ccd/util/"],
    ["ccd/io/"],
    ["ccd/shape/"],
    ["ccd/scene/"],
    ["ccd/motion/"],
    ["ccd/queries/"],
    ["ccd/broad_phase/"],
    ["ccd/truth/"],
    ["ccd/narrow/"],
    ["bounds/"],
    ["pipeline/"],
    ["cloth/"],
    ["generators/"],
    ["experiments/"],  # the runners, results, the viewer's data
    ["cli/"],
    ["python/", "benchmarks/", "fuzz/", "tests/", "examples/"],
]
INCLUDE = re.compile(r'\s*#\s*include\s*([<"])([^>"]+)[>"]')


def floor_of(path):
    """Index of the floor of `path` (relative, '/'-separated), or None outside the floors."""
    best = None
    for index, prefixes in enumerate(FLOORS):
        for prefix in prefixes:
            if path == prefix or path.startswith(prefix):
                if best is None or len(prefix) > best[1]:
                    best = (index, len(prefix))
    return None if best is None else best[0]


def resolve(root, source, kind, name):
    """The project path an include names, or None (a system or third-party header)."""
    if kind == '"':
        local = (source.parent / name).resolve()
        if local.exists():
            return local.relative_to(root).as_posix()
    candidate = root / name
    return name if candidate.exists() else None


def upward_includes(root):
    found = []
    folders = sorted({p.split("/")[0] for floor in FLOORS for p in floor})
    for folder in folders:
        base = root / folder.rstrip("/")
        files = [base] if base.is_file() else sorted(base.rglob("*.[ch]pp"))
        for source in files:
            path = source.relative_to(root).as_posix()
            own = floor_of(path)
            for number, line in enumerate(source.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(root, source, *match.groups())
                if target is None:
                    continue
                other = floor_of(target)
                if own is not None and other is not None and other > own:
                    found.append(f"{path}:{number}: includes {target} ({FLOORS[other][0]} is above "
                                 f"{FLOORS[own][0]})")
    return found


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    found = upward_includes(root)
    for line in found:
        print(line)
    # The check must see the tree: an empty walk would pass anything.
    if not (root / "ccd" / "truth").is_dir() or not (root / "cli").is_dir():
        print(f"{root}: not the ccdlab source tree")
        return 1
    print(f"{len(found)} upward include(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
