#!/usr/bin/env bash
# Runs one experiment as N shards launched by GNU parallel, in shuffled order, and merges
# them: the same split as scripts/slurm/submit.sh without a batch system, on this machine
# or, with parallel's own --sshlogin options after `--`, on several (docs/experiments.md).
#   1. `ccdlab truth`: the scene's ground truth, once, into DIR/truth.json
#   2. `parallel --shuf`: the N shards `ccdlab run --shard K/N --truth DIR/truth.json`,
#      J at a time in random order, into DIR/shards/NAME.shardKofN.json (the order they
#      ran in is in DIR/joblog.txt)
#   3. `ccdlab merge` of the shard files, given in another random order, into DIR/NAME.json
#
# usage: scripts/parallel-run.sh EXPERIMENT.json [--shards N] [--jobs J] [--threads T]
#                                [--out DIR] [--ccdlab PATH] [-- PARALLEL_OPTION ...]
#   --shards N    number of shards (default 8)
#   --jobs J      shards running at once (default: the number of cores)
#   --threads T   ccdlab's --threads in each shard (default 1)
#   --out DIR     where everything lands (default results/parallel/NAME in this clone);
#                 must be empty or absent
#   --ccdlab PATH the ccdlab binary (default build/ccdlab, or $CCDLAB_BUILD_DIR/ccdlab)
# Prints the merged results file's path. Needs GNU parallel (Debian package `parallel`).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

usage() {
  sed -n '/^# usage:/,/^# Prints/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}
die() { echo "parallel-run.sh: $*" >&2; exit 2; }

[[ $# -ge 1 && $1 != -* ]] || usage
experiment=$(realpath "$1") || die "$1: no such file"
shift
shards=8 jobs=$(nproc) threads=1 out=""
ccdlab=${CCDLAB_BUILD_DIR:-$root/build}/ccdlab
parallel_options=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --shards) [[ $# -ge 2 ]] || usage; shards=$2; shift 2 ;;
    --jobs) [[ $# -ge 2 ]] || usage; jobs=$2; shift 2 ;;
    --threads) [[ $# -ge 2 ]] || usage; threads=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; out=$2; shift 2 ;;
    --ccdlab) [[ $# -ge 2 ]] || usage; ccdlab=$2; shift 2 ;;
    --) shift; parallel_options=("$@"); break ;;
    *) usage ;;
  esac
done
for v in shards jobs threads; do
  [[ ${!v} =~ ^[1-9][0-9]*$ ]] || die "--$v needs a positive integer"
done
[[ -x $ccdlab ]] || die "$ccdlab not found: run ./scripts/build.sh first"
ccdlab=$(realpath "$ccdlab")
command -v parallel >/dev/null || die "GNU parallel not found (Debian package 'parallel')"

{ read -r name; read -r kind scene; } < <(/usr/bin/env python3 "$root/scripts/experiment-info.py" "$experiment") ||
  die "cannot read $experiment"
out=${out:-$root/results/parallel/$name}
if [[ -d $out && -n $(ls -A "$out") ]]; then
  die "$out already holds a run: remove it or give another --out"
fi
mkdir -p "$out/shards"
out=$(realpath "$out")

if [[ $kind == generator ]]; then
  # shellcheck disable=SC2086  # the generator's arguments, one word each
  "$ccdlab" scene $scene -o "$out/scene.json" >/dev/null
  scene=$out/scene.json
fi
"$ccdlab" truth "$scene" --threads "$(nproc)" --quiet -o "$out/truth.json"

parallel --will-cite --shuf --jobs "$jobs" --halt now,fail=1 --joblog "$out/joblog.txt" "${parallel_options[@]}" -q \
  "$ccdlab" run "$experiment" --shard "{}/$shards" --threads "$threads" --quiet --truth "$out/truth.json" \
  -o "$out/shards/$name.shard{}of$shards.json" ::: $(seq 1 "$shards") >/dev/null

mapfile -t files < <(for ((k = 1; k <= shards; k++)); do echo "$out/shards/$name.shard${k}of$shards.json"; done | shuf)
"$ccdlab" merge "${files[@]}" -o "$out/$name.json" >/dev/null
echo "$out/$name.json"
