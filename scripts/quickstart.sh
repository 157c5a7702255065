#!/usr/bin/env bash
# Quick-start command 1: install what is missing, build, run the default experiment,
# draw its charts, and print where the results and charts are.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
echo "ccdlab: building the program (Release; ./scripts/test.sh builds the tests too) ..." >&2
"$root/scripts/build.sh" --target ccdlab --progress
build=${CCDLAB_BUILD_DIR:-$root/build}
mkdir -p "$root/results"
echo "program: $build/ccdlab  (on PATH: export PATH=\"$build:\$PATH\", or install it: README.md, \"Installing\")"
"$build/ccdlab" run "$root/data/experiments/default.json" -o "$root/results/default.json"
echo "charts:"
/usr/bin/python3 "$root/scripts/plot.py" "$root/results/default.json" -o "$root/results/default-plots"
