#!/usr/bin/env bash
# Regenerates the charts shown in README.md's "Results" section: the default
# experiment's speed-against-accuracy chart, the tunnelling study's missed-events chart and
# the tunnelling picture (`ccdlab animate`).
# Run after ./scripts/build.sh (or the quick start); takes about two minutes.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
mkdir -p "$root/results" "$root/docs/images"
"$build/ccdlab" run "$root/data/experiments/default.json" -o "$root/results/default.json" --quiet
/usr/bin/python3 "$root/scripts/plot.py" "$root/results/default.json" -o "$root/results/default-plots" --format png >/dev/null
cp "$root/results/default-plots/speed_accuracy.png" "$root/docs/images/default-speed-accuracy.png"
"$root/scripts/study.sh" tunnelling --publish >/dev/null
# The tunnelling picture: what aabb/sap missed at dt = 0.019 s (a record of the study).
"$build/ccdlab" scene bullets bodies=1000 bullets=50 seed=1 -o "$root/results/tunnelling-scene.json" >/dev/null
"$build/ccdlab" animate "$root/results/tunnelling-scene.json" --results "$root/results/studies/tunnelling/tunnelling.json" \
  --method aabb/sap --dt 0.019 --from 0.46 --to 0.52 --frames-per-step 8 -o "$root/docs/images/tunnelling.gif" 2>/dev/null
# The report's overlay chart (docs/python.md): the default experiment and the tunnelling study.
"$build/ccdlab" report "$root/results/default.json" "$root/results/studies/tunnelling/tunnelling.json" \
  -o "$root/results/report" >/dev/null
cp "$root/results/report/missed.png" "$root/docs/images/report-missed.png"
echo "$root/docs/images/default-speed-accuracy.png"
echo "$root/docs/studies/tunnelling-missed.png"
echo "$root/docs/images/tunnelling.gif"
echo "$root/docs/images/report-missed.png"
