#!/usr/bin/env bash
# Submits one experiment to Slurm as three dependent jobs (docs/experiments.md):
#   1. truth.sbatch  `ccdlab truth`: the scene's ground truth, once, into DIR/truth.json
#   2. shard.sbatch  a job array of N tasks; task K runs `ccdlab run --shard K/N
#                    --truth DIR/truth.json` into DIR/shards/NAME.shardKofN.json
#   3. merge.sbatch  `ccdlab merge`: the N shards into DIR/NAME.json
# Each job waits for the previous one to succeed (--dependency=afterok); when one fails,
# the jobs after it never start. Slurm's own logs go to DIR/logs/, the job ids to
# DIR/jobs.txt (one `truth|shards|merge ID` a line).
#
# usage: scripts/slurm/submit.sh EXPERIMENT.json [--shards N] [--threads T] [--out DIR]
#                                [--ccdlab PATH] [--modules "MODULE ..."] [-- SBATCH_OPTION ...]
#   --shards N    array size (default 8)
#   --threads T   CPUs of the truth job and of each shard task (--cpus-per-task), and
#                 ccdlab's --threads there (default 1); the merge job takes 1 CPU
#   --out DIR     where everything lands, on a file system every node sees
#                 (default results/slurm/NAME in this clone); must be empty or absent
#   --ccdlab PATH the ccdlab binary the jobs run (default build/ccdlab, or
#                 $CCDLAB_BUILD_DIR/ccdlab)
#   --modules L   environment modules each job loads first (`module load L`)
#   -- ...        options for sbatch, given to all three jobs (--partition, --account,
#                 --time, --mem, ...)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/scripts/slurm

usage() {
  sed -n '/^# usage:/,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}
die() { echo "submit.sh: $*" >&2; exit 2; }

[[ $# -ge 1 && $1 != -* ]] || usage
experiment=$(realpath "$1") || die "$1: no such file"
shift
shards=8 threads=1 out="" modules=""
ccdlab=${CCDLAB_BUILD_DIR:-$root/build}/ccdlab
sbatch_options=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --shards) [[ $# -ge 2 ]] || usage; shards=$2; shift 2 ;;
    --threads) [[ $# -ge 2 ]] || usage; threads=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; out=$2; shift 2 ;;
    --ccdlab) [[ $# -ge 2 ]] || usage; ccdlab=$2; shift 2 ;;
    --modules) [[ $# -ge 2 ]] || usage; modules=$2; shift 2 ;;
    --) shift; sbatch_options=("$@"); break ;;
    *) usage ;;
  esac
done
[[ $shards =~ ^[1-9][0-9]*$ ]] || die "--shards needs a positive integer"
[[ $threads =~ ^[1-9][0-9]*$ ]] || die "--threads needs a positive integer"
[[ -x $ccdlab ]] || die "$ccdlab not found: build first (./scripts/build.sh -DCCDLAB_NATIVE=OFF)"
ccdlab=$(realpath "$ccdlab")
command -v sbatch >/dev/null || die "sbatch not found: not on a Slurm cluster (or its module is not loaded)"

{ read -r name; read -r kind scene; } < <(/usr/bin/env python3 "$root/scripts/experiment-info.py" "$experiment") ||
  die "cannot read $experiment"
out=${out:-$root/results/slurm/$name}
if [[ -d $out && -n $(ls -A "$out") ]]; then
  die "$out already holds a run: remove it or give another --out"
fi
mkdir -p "$out/shards" "$out/logs"
out=$(realpath "$out")
# Should a submission fail half-way, cancel the jobs already queued and remove DIR again.
submitted=()
trap 'rc=$?; if [[ $rc -ne 0 ]]; then
  [[ ${#submitted[@]} -eq 0 ]] || scancel "${submitted[@]}"
  rm -rf "$out"
  echo "submit.sh: submission failed; nothing left queued" >&2
fi' EXIT

# What the job scripts read (sbatch passes the submitting environment on by default).
export CCDLAB=$ccdlab CCDLAB_EXPERIMENT=$experiment CCDLAB_NAME=$name CCDLAB_SHARDS=$shards
export CCDLAB_RUN_DIR=$out CCDLAB_MODULES=$modules CCDLAB_SCENE="" CCDLAB_SCENE_GENERATOR=""
export CCDLAB_TRUTH=$out/truth.json
if [[ $kind == file ]]; then CCDLAB_SCENE=$scene; else CCDLAB_SCENE_GENERATOR=$scene; fi

submit() {  # submit VAR SBATCH_ARGS...: sets VAR to the job id
  local var=$1 id
  shift
  id=$(sbatch --parsable "${sbatch_options[@]}" "$@" | cut -d';' -f1)
  [[ $id =~ ^[0-9]+$ ]] || return 1
  submitted+=("$id")
  printf -v "$var" %s "$id"
}

submit truth_job --cpus-per-task="$threads" --output="$out/logs/truth-%j.out" "$here/truth.sbatch"
echo "truth $truth_job" >"$out/jobs.txt"
submit shard_job --cpus-per-task="$threads" --array="1-$shards" --dependency="afterok:$truth_job" \
  --output="$out/logs/shard-%a-%A.out" "$here/shard.sbatch"
echo "shards $shard_job" >>"$out/jobs.txt"
submit merge_job --cpus-per-task=1 --dependency="afterok:$shard_job" --output="$out/logs/merge-%j.out" \
  "$here/merge.sbatch"
echo "merge $merge_job" >>"$out/jobs.txt"

echo "submitted: $(tr '\n' ' ' <"$out/jobs.txt")(squeue --me to follow)"
echo "merged results, once job $merge_job has completed: $out/$name.json"
