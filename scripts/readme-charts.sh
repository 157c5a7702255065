#!/usr/bin/env bash
# Regenerates the charts shown in README.md's "Results" section: the default
# experiment's speed-against-accuracy chart and the tunnelling study's missed-events chart.
# Run after ./scripts/build.sh (or the quick start); takes about two minutes.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
mkdir -p "$root/results" "$root/docs/images"
"$build/ccdlab" run "$root/data/experiments/default.json" -o "$root/results/default.json" --quiet
/usr/bin/python3 "$root/scripts/plot.py" "$root/results/default.json" -o "$root/results/default-plots" --format png >/dev/null
cp "$root/results/default-plots/speed_accuracy.png" "$root/docs/images/default-speed-accuracy.png"
"$root/scripts/study.sh" tunnelling --publish >/dev/null
echo "$root/docs/images/default-speed-accuracy.png"
echo "$root/docs/studies/tunnelling-missed.png"
