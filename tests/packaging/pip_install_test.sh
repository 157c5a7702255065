#!/usr/bin/env bash
# `pip install --no-build-isolation` of the Python package (pyproject.toml, setup.py) into a
# fresh venv, offline, and `pip wheel`: the venv's ccdlab is the installed module and computes
# a truth equal to the build tree's module. Then `python3 -m build --no-isolation --wheel`
# (Debian's python3-build): its wheel installs into another fresh venv and imports. The build reuses this build folder
# (CCDLAB_BUILD_DIR: only the module target, up to date here) so the test takes seconds; a
# user's `pip install` configures and builds its own (setup.py).
# Usage: pip_install_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# setuptools builds in the project folder: a copy of what the package build reads, so the
# source tree gets no egg-info or build/ leftovers.
mkdir "$work/project"
cp "$src/pyproject.toml" "$src/setup.py" "$src/README.md" "$src/CMakeLists.txt" "$work/project/"
mkdir "$work/project/python"
cp -r "$src/python/ccdlab" "$work/project/python/"
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
export CCDLAB_BUILD_DIR=$build PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
unset PYTHONPATH
"$work/venv/bin/pip" install -q --no-build-isolation "$work/project"
"$work/venv/bin/pip" wheel -q --no-build-isolation --no-deps -w "$work/wheels" "$work/project"
ls "$work"/wheels/ccdlab-*-cp3*-linux_*.whl >/dev/null
cd "$work"
"$work/venv/bin/python" - "$src" "$build" <<'PY'
import json, pathlib, subprocess, sys
import ccdlab
src, build = sys.argv[1:]
where = pathlib.Path(ccdlab.__file__).resolve()
assert "venv" in where.parts and "site-packages" in where.parts, f"imported {where}, not the venv's module"
scene = ccdlab.load_scene(f"{src}/data/scenes/example.json")
truth = ccdlab.truth(scene)
mine = truth.to_json()
# The build tree's module (PYTHONPATH), in another process: the same truth.
theirs = subprocess.run([sys.executable, "-c",
    "import ccdlab, json, sys; assert sys.argv[2] in ccdlab.__file__, ccdlab.__file__; "
    "print(json.dumps(ccdlab.truth(ccdlab.load_scene(sys.argv[1])).to_json()))",
    f"{src}/data/scenes/example.json", build], env={"PYTHONPATH": f"{build}/python"},
    capture_output=True, text=True, check=True).stdout
assert mine == json.loads(theirs), "the installed module's truth differs from the build tree's"
assert len(truth.a) > 0
print(f"pip install: {where} gives the build tree's truth ({len(truth.a)} events)")
PY

# `python3 -m build --no-isolation --wheel` (Debian's python3-build) makes a wheel that a
# fresh venv installs offline and imports, with its compiled module.
/usr/bin/python3 -m build --no-isolation --wheel --outdir "$work/built" "$work/project" >"$work/build.log" 2>&1 ||
  { cat "$work/build.log"; exit 1; }
wheel=$(ls "$work"/built/ccdlab-*-cp3*-linux_*.whl)
/usr/bin/python3 -m venv --system-site-packages "$work/fresh"
"$work/fresh/bin/pip" install -q --no-deps "$wheel"
"$work/fresh/bin/python" - <<'PY'
import pathlib
import ccdlab
where = pathlib.Path(ccdlab.__file__).resolve()
assert "fresh" in where.parts and "site-packages" in where.parts, f"imported {where}, not the wheel's module"
assert (where.parent / "plot.py").exists() and ccdlab.plot.CHARTS
r = ccdlab.rigid_toi({"kind": "sphere", "radius": 0.5}, [0, 0, 0], [1, 0, 0],
                     {"kind": "sphere", "radius": 0.5}, [3, 0, 0], [0, 0, 0], 4.0)
assert abs(r["toi"] - 2.0) <= r["toi_error"], r
print(f"python3 -m build: the wheel installs into a fresh venv and imports from {where.parent}")
PY
