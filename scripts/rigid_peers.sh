#!/usr/bin/env bash
# FCL 0.7's continuous collision side by side with ccdlab's conservative advancement on
# spinning sticks (with small balls) and spinning crates (docs/peers.md, "Spinning bodies").
# Generates the two scenes with `ccdlab scene`, computes their certified truth with
# `ccdlab truth`, then prints one table per scene from `rigid_peers` (misses against that
# truth, false alarms, late reports, CPU time per query).
#
#   scripts/rigid_peers.sh [--quick] [OUT_DIR]     (OUT_DIR default: results/rigid_peers)
#
# --quick: small scenes and one timing pass (the test suite's run). The build folder is
# $CCDLAB_BUILD_DIR or build/; it needs `ccdlab` and `rigid_peers` (built when FCL is found).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
bodies=600 repeats=5
if [[ ${1:-} == --quick ]]; then
  bodies=60 repeats=1
  shift
fi
out=${1:-$root/results/rigid_peers}
mkdir -p "$out"
# Sticks: half length 1, radius 0.05, half of the bodies balls of radius 0.5; crates:
# 1 x 0.45 x 0.2 half extents. Spin up to 30 rad/s, 30 steps over 1 s: at most 1 rad per step.
"$build/ccdlab" scene sticks bodies=$bodies spheres=0.5 elongation=20 spin_max=30 fraction=0.1 seed=1 \
  -o "$out/sticks.json"
"$build/ccdlab" scene crates bodies=$bodies elongation=5 spin_max=30 fraction=0.1 seed=1 -o "$out/crates.json"
status=0
for s in sticks crates; do
  "$build/ccdlab" truth "$out/$s.json" -o "$out/$s-truth.json" --quiet >/dev/null
  "$build/rigid_peers" --scene "$out/$s.json" --truth "$out/$s-truth.json" --steps=30 --repeats=$repeats || status=$?
  echo
done
exit $status
