#!/usr/bin/env bash
# Quick-start command 1: install what is missing, build, run the default experiment and
# print where its results are.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" >/dev/null
build=${CCDLAB_BUILD_DIR:-$root/build}
mkdir -p "$root/results"
"$build/ccdlab" truth "$root/data/scenes/default.json" -o "$root/results/default-truth.json"
