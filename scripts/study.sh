#!/usr/bin/env bash
# Runs one stability study (docs/studies.md) with one command: every experiment file of
# the study (data/experiments/NAME.json or NAME-*.json) through `ccdlab run` into
# results/studies/NAME/, then its charts (scripts/plot.py per results file, except for the
# cloth study, and scripts/plot_study.py across them), and prints the paths.
#
# usage: scripts/study.sh NAME [--threads N] [--plot-only] [--publish]
#        scripts/study.sh --list
#   --threads N  threads of `ccdlab run` (default 2)
#   --plot-only  do not run: redraw the charts from the results already in results/studies/NAME/
#   --publish    also copy the study's charts into docs/studies/ (as committed there)
# Needs a built ./build/ccdlab (./scripts/build.sh) and /usr/bin/python3 with matplotlib.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ccdlab=${CCDLAB:-$root/build/ccdlab}
python=/usr/bin/python3
studies="tunnelling sap-coherence equal-endpoints grazing precision bound-violation mixed-sizes scaling scheduling spinning fit cloth spin-model thin-obstacles"

usage() {
  echo "usage: scripts/study.sh NAME [--threads N] [--plot-only] [--publish]   (NAME: ${studies// /, })" >&2
  exit 2
}

[[ $# -ge 1 ]] || usage
if [[ $1 == --list ]]; then
  for s in $studies; do echo "$s"; done
  exit 0
fi
name=$1
shift
threads=2
publish=0
plot_only=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --threads) [[ $# -ge 2 ]] || usage; threads=$2; shift 2 ;;
    --publish) publish=1; shift ;;
    --plot-only) plot_only=1; shift ;;
    *) usage ;;
  esac
done
[[ " $studies " == *" $name "* ]] || { echo "study.sh: unknown study '$name'" >&2; usage; }
[[ -x $ccdlab ]] || { echo "study.sh: $ccdlab not found: run ./scripts/build.sh first" >&2; exit 2; }

# spin-model compares two truths (free and constant spin), not methods: its own script.
if [[ $name == spin-model ]]; then
  out=$root/results/studies/$name
  [[ $plot_only == 1 ]] && { echo "study.sh: spin-model has no --plot-only (it runs in minutes)" >&2; exit 2; }
  mkdir -p "$out"
  CCDLAB=$ccdlab "$python" "$root/scripts/spin_model.py" -o "$out" --threads "$threads" --ccdlab "$ccdlab" \
    | tee "$out/summary.md"
  if [[ $publish == 1 ]]; then
    mkdir -p "$root/docs/studies"
    for p in "$out"/plots/*.png; do
      cp "$p" "$root/docs/studies/"
      echo "published docs/studies/$(basename "$p")"
    done
  fi
  exit 0
fi

shopt -s nullglob
files=("$root/data/experiments/$name.json" "$root/data/experiments/$name"-*.json)
existing=()
for f in "${files[@]}"; do [[ -f $f ]] && existing+=("$f"); done
[[ ${#existing[@]} -gt 0 ]] || { echo "study.sh: no experiment files for '$name'" >&2; exit 2; }

out=$root/results/studies/$name
mkdir -p "$out"
results=()
start=$(date +%s.%N)
for f in "${existing[@]}"; do
  stem=$(basename "$f" .json)
  results+=("$out/$stem.json")
  [[ $plot_only == 1 ]] && continue
  t0=$(date +%s.%N)
  "$ccdlab" run "$f" -o "$out/$stem.json" --threads "$threads" --quiet >/dev/null
  t1=$(date +%s.%N)
  printf 'ran %s in %.1f s\n' "$stem" "$(awk "BEGIN{print $t1 - $t0}")"
done
end=$(date +%s.%N)
[[ $plot_only == 1 ]] || printf 'study %s: %d experiment file(s) in %.1f s (--threads %s)\n' "$name" \
  "${#existing[@]}" "$(awk "BEGIN{print $end - $start}")" "$threads"

for r in "${results[@]}"; do
  echo "$r"
  # plot.py draws sphere and rigid results; cloth results are drawn by plot_study.py only.
  [[ $name == cloth ]] && continue
  # Scheduling compares runs of a few milliseconds: by CPU time (docs/studies.md).
  cost=wall
  [[ $name == scheduling ]] && cost=cpu
  "$python" "$root/scripts/plot.py" "$r" --format png --cost "$cost" -o "${r%.json}-plots"
done
"$python" "$root/scripts/plot_study.py" "$name" "${results[@]}" -o "$out/plots" --ccdlab "$ccdlab" \
  | tee "$out/summary.md"

if [[ $publish == 1 ]]; then
  mkdir -p "$root/docs/studies"
  for p in "$out"/plots/*.png; do
    cp "$p" "$root/docs/studies/"
    echo "published docs/studies/$(basename "$p")"
  done
  if [[ $name == scheduling ]]; then
    for f in sparse-gas bullets; do
      cp "$out/scheduling-$f-plots/speed_accuracy.png" "$root/docs/studies/scheduling-$f-speed-accuracy.png"
      echo "published docs/studies/scheduling-$f-speed-accuracy.png"
    done
  fi
  if [[ $name == tunnelling ]]; then
    cp "$out/tunnelling-plots/missed.png" "$root/docs/studies/tunnelling-missed.png"
    echo "published docs/studies/tunnelling-missed.png"
  fi
fi
