#!/usr/bin/env bash
# The cluster test: runs the default experiment on a real Slurm cluster of one node started
# on this machine, and checks that the merged shards equal a single-machine run count for
# count; then the same for several shard counts in random order with GNU parallel.
#
#   1. installs slurm-wlm, munge and parallel when missing (scripts/install-deps.sh) and
#      builds ccdlab (scripts/build.sh, quick when up to date)
#   2. runs the default experiment on this machine: the reference
#   3. starts munged, slurmctld and slurmd from a temporary directory that holds
#      everything (a munge key, a slurm.conf generated for this host with 2 CPUs on free
#      local ports, state, spool, logs, pid files); nothing under /etc, /var or systemd
#   4. submits the default experiment with scripts/slurm/submit.sh (a truth job, an
#      8-task shard array, a merge job), waits at most $CCDLAB_CLUSTER_TIMEOUT seconds
#      (default 900), and compares the merged results with the reference
#   5. runs a small experiment with scripts/parallel-run.sh as 1, 2, 3, 5, 8, 12 and 13
#      shards (12 jobs: one shard per job, and one shard with none) in shuffled order,
#      and compares each merged result with a single run
#   6. stops every daemon it started by process id, and any process they left (found by
#      a marker in their environment), also when a step fails or on Ctrl-C
# Prints one line per check; exits 0 when all pass, 1 otherwise. Run as root (slurmd
# starts the jobs). About 2 to 2.5 minutes on a 2-core machine, most of it the two runs of
# the default experiment. Set CCDLAB_CLUSTER_KEEP=1 to keep the temporary directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
ccdlab=$build/ccdlab
timeout=${CCDLAB_CLUSTER_TIMEOUT:-900}
shards=8
started=$SECONDS

checks=0 failures=0 interrupted=""
pass() { checks=$((checks + 1)); printf 'ok    %s\n' "$*"; }
fail() { checks=$((checks + 1)) failures=$((failures + 1)); printf 'FAIL  %s\n' "$*"; }
abort() { fail "$*"; exit 1; }  # a failed step that the later ones need
elapsed() { echo $((SECONDS - $1)); }
truth_sources() {  # truth_sources RESULTS.json...: where their ground truth came from, each once
  python3 -c 'import json, sys
print(" ".join(sorted({json.load(open(f))["truth"].get("source", "?") for f in sys.argv[1:]})))' "$@"
}

[[ $(id -u) -eq 0 ]] || { echo "cluster-test.sh: run as root (slurmd starts the jobs as their user)" >&2; exit 2; }

# --- the temporary cluster and how to take it down -------------------------------------
tmp=$(mktemp -d /tmp/ccdlab-cluster.XXXXXX)
chmod 711 "$tmp"  # munged wants every folder above its socket searchable by all
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool" "$tmp/log"
conf=$tmp/slurm.conf
export SLURM_CONF=$conf
# Every process this test starts carries this variable: the daemons, the job steps they
# fork, the jobs and the shards. Whatever is left with it at the end is ours to stop.
marker="CCDLAB_CLUSTER_TEST=$tmp"
declare -A pid=()
daemons=(slurmd slurmctld munged)  # the order they are stopped in

start() {  # start NAME COMMAND...: runs a daemon in the foreground of a background job
  local name=$1
  shift
  env "$marker" "$@" >"$tmp/log/$name.out" 2>&1 &
  pid[$name]=$!
}

marked() {  # the process ids that carry the marker
  grep -lsz "^$marker\$" /proc/[0-9]*/environ 2>/dev/null | cut -d/ -f3 || true
}

stop() {  # stop PID: SIGTERM, then SIGKILL after 10 s
  local p=$1 i
  kill -TERM "$p" 2>/dev/null || return 0
  for ((i = 0; i < 100; i++)); do
    kill -0 "$p" 2>/dev/null || break
    # a child of this shell stays a zombie (kill -0 succeeds) until reaped
    [[ $(ps -o stat= -p "$p" 2>/dev/null) == Z* ]] && break
    sleep 0.1
  done
  kill -KILL "$p" 2>/dev/null || true
  wait "$p" 2>/dev/null || true
}

cleanup() {
  local rc=$? name p left
  set +e
  trap - EXIT INT TERM
  if [[ -n ${pid[slurmctld]:-} ]] && kill -0 "${pid[slurmctld]}" 2>/dev/null; then
    # cancel what is still queued or running, so that no job step outlives slurmd
    ids=$(timeout 10 squeue -h -o %A 2>/dev/null | sort -u)
    if [[ -n $ids ]]; then
      timeout 10 scancel $ids 2>/dev/null
      for ((i = 0; i < 30; i++)); do
        [[ -z $(timeout 5 squeue -h -o %A 2>/dev/null) ]] && break
        sleep 1
      done
    fi
  fi
  stopped=()
  for name in "${daemons[@]}"; do
    [[ -n ${pid[$name]:-} ]] || continue
    stop "${pid[$name]}"
    stopped+=("$name ${pid[$name]}")
  done
  for p in $(marked); do stop "$p"; done
  sleep 0.5
  left=$(marked | tr '\n' ' ')
  if [[ -n $left ]]; then
    fail "processes left running: $left"
  elif [[ ${#stopped[@]} -gt 0 ]]; then
    pass "stopped $(IFS=,; echo "${stopped[*]}" | sed 's/,/, /g'); no process of this test left"
  fi
  [[ $rc -ne 0 || $failures -eq 0 ]] || rc=1
  if [[ $rc -ne 0 ]]; then
    for f in "$tmp"/log/*.out "$tmp"/log/*.log "$tmp"/slurm/logs/*.out; do
      [[ -s $f ]] || continue
      echo "--- last lines of $f" >&2
      tail -n 5 "$f" >&2
    done
  fi
  if [[ ${CCDLAB_CLUSTER_KEEP:-0} == 1 ]]; then
    echo "kept $tmp" >&2
  else
    rm -rf "$tmp"
  fi
  if [[ -n $interrupted ]]; then
    printf 'cluster test: interrupted by %s after %d s\n' "$interrupted" "$(elapsed "$started")"
  elif [[ $rc -eq 0 ]]; then
    printf 'cluster test: all %d checks passed in %d s\n' "$checks" "$(elapsed "$started")"
  else
    printf 'cluster test: FAILED (%d of %d checks failed) after %d s\n' "$failures" "$checks" "$(elapsed "$started")"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'interrupted=SIGINT; exit 130' INT
trap 'interrupted=SIGTERM; exit 143' TERM

# --- 1. packages and build -------------------------------------------------------------
"$root/scripts/install-deps.sh" slurm-wlm munge parallel
pass "packages: slurm-wlm $(dpkg-query -W -f='${Version}' slurm-wlm), munge, parallel installed"
"$root/scripts/build.sh" --target ccdlab >/dev/null
[[ -x $ccdlab ]] || abort "build: $ccdlab missing"
pass "build: $ccdlab"

# --- 2. the reference: one machine -----------------------------------------------------
t=$SECONDS
"$ccdlab" run "$root/data/experiments/default.json" --threads 2 --quiet -o "$tmp/single.json" >/dev/null ||
  abort "single machine: ccdlab run default.json failed"
pass "single machine: default experiment, $(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["records"]))' "$tmp/single.json") records in $(elapsed $t) s (--threads 2)"

# --- 3. a one-node Slurm cluster -------------------------------------------------------
node=$(hostname -s)
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
socket=$tmp/munge/munge.socket
mungekey --create --keyfile="$tmp/munge/munge.key"
start munged munged --foreground --socket="$socket" --key-file="$tmp/munge/munge.key" \
  --pid-file="$tmp/munge/munged.pid" --seed-file="$tmp/munge/munged.seed" --log-file="$tmp/log/munged.log"
for ((i = 0; i < 100; i++)); do [[ -S $socket ]] && break; sleep 0.1; done
munge -n -S "$socket" | unmunge -S "$socket" >/dev/null 2>&1 ||
  abort "munged (pid ${pid[munged]}): no working socket at $socket"
pass "munged (pid ${pid[munged]}): a credential encoded and decoded through $socket"

cat >"$conf" <<EOF
# A one-node cluster on 127.0.0.1 for scripts/cluster-test.sh; everything under $tmp.
ClusterName=ccdlab
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
SchedulerType=sched/builtin
# a job whose dependency can no longer be met (a shard failed) is cancelled, not held
DependencyParameters=kill_invalid_depend
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# trust the CPU count below, whatever the hardware
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=3600
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=ccdlab Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
start slurmctld slurmctld -D -f "$conf"
start slurmd slurmd -D -f "$conf" -N "$node"
state=""
for ((i = 0; i < 60; i++)); do
  state=$(timeout 5 sinfo -h -n "$node" -o '%t %c' 2>/dev/null || true)
  [[ $state == idle* ]] && break
  sleep 1
done
[[ $state == idle* ]] || abort "slurm: node $node not idle after 60 s (sinfo: '${state:-no answer}')"
pass "slurmctld (pid ${pid[slurmctld]}), slurmd (pid ${pid[slurmd]}): node $node idle, ${state#idle } CPUs, ports $ctld_port and $slurmd_port"

# --- 4. the default experiment as an 8-shard job array ----------------------------------
t=$SECONDS
env "$marker" "$root/scripts/slurm/submit.sh" "$root/data/experiments/default.json" --shards "$shards" \
  --threads 1 --out "$tmp/slurm" --ccdlab "$ccdlab" >"$tmp/log/submit.out" 2>&1 ||
  abort "submit.sh failed: $(tail -n 1 "$tmp/log/submit.out")"
declare -A job=()
while read -r what id; do job[$what]=$id; done <"$tmp/slurm/jobs.txt"
ids=$(tr '\n' ' ' <"$tmp/slurm/jobs.txt" | awk '{for (i = 2; i <= NF; i += 2) printf "%s%s", (i > 2 ? "," : ""), $i}')
pass "submitted: $(tr '\n' ' ' <"$tmp/slurm/jobs.txt")(submit.sh)"

while queued=$(timeout 10 squeue -h -j "$ids" -o '%i %r' 2>/dev/null || echo "? no answer from squeue"); [[ -n $queued ]]; do
  (($(elapsed $t) < timeout)) || abort "slurm: jobs $ids still queued or running after $timeout s"
  # kill_invalid_depend cancels such jobs; should they stay, waiting would be in vain
  grep -qv DependencyNeverSatisfied <<<"$queued" || break
  sleep 2
done
states=$(for id in ${ids//,/ }; do scontrol -o show job "$id"; done | grep -o 'JobState=[A-Z_]* .*ExitCode=[0-9:]*' |
  sed 's/JobState=\([A-Z_]*\).*ExitCode=\([0-9:]*\)/\1 \2/' | sort | uniq -c | awk '{printf "%s%s x%d (exit %s)", (NR > 1 ? ", " : ""), $2, $1, $3}')
expected=$((shards + 2))  # the truth job, the shard tasks, the merge job
[[ $states == "COMPLETED x$expected (exit 0:0)" ]] ||
  abort "slurm: jobs ended as: $states (expected COMPLETED x$expected (exit 0:0))"
pass "slurm: ${#job[@]} jobs, $expected tasks COMPLETED with exit 0 in $(elapsed $t) s"

merged=$tmp/slurm/default.json
[[ -f $merged ]] || abort "slurm: no merged results at $merged"
sources=$(truth_sources "$tmp"/slurm/shards/*.json)
if [[ $sources == "$tmp/slurm/truth.json" ]]; then
  pass "slurm: all $shards shards read the one truth file (truth.source)"
else
  fail "slurm: shards took their truth from: $sources (expected $tmp/slurm/truth.json)"
fi
if out=$(python3 "$root/scripts/compare-results.py" "$tmp/single.json" "$merged"); then
  pass "slurm: merged $shards shards = the single-machine run ($out)"
else
  fail "slurm: merged $shards shards differ from the single-machine run: $out"
fi

# --- 5. GNU parallel: any shard count, any order ----------------------------------------
cat >"$tmp/small.json" <<'EOF'
{ "format": "ccdlab-experiment/1", "name": "small",
  "scene": {"generator": "gas", "bodies": 150, "seed": 3, "horizon": 0.5},
  "dt": [0.1, 0.02, 0.005],
  "methods": ["aabb/sap", "sphere/grid", "capsule/sap", "horn:2/brute"] }
EOF
"$ccdlab" run "$tmp/small.json" --threads 2 --quiet -o "$tmp/small-single.json" >/dev/null ||
  abort "single machine: ccdlab run small.json failed"
for n in 1 2 3 5 8 12 13; do
  t=$SECONDS
  if ! env "$marker" "$root/scripts/parallel-run.sh" "$tmp/small.json" --shards "$n" --jobs 2 \
      --out "$tmp/parallel-$n" --ccdlab "$ccdlab" >"$tmp/log/parallel-$n.out" 2>&1; then
    fail "parallel: $n shards: parallel-run.sh failed: $(tail -n 1 "$tmp/log/parallel-$n.out")"
    continue
  fi
  # parallel writes its job log as the shards finish: the completion order
  order=$(tail -n +2 "$tmp/parallel-$n/joblog.txt" | grep -o -- '--shard [0-9]*' | cut -d' ' -f2 | tr '\n' ' ')
  what="parallel: $n shard(s) finished in the order ${order% } ($(elapsed $t) s)"
  sources=$(truth_sources "$tmp/parallel-$n"/shards/*.json)
  if [[ $sources != "$tmp/parallel-$n/truth.json" ]]; then
    fail "$what: the shards took their truth from $sources, not the one truth file"
  elif out=$(python3 "$root/scripts/compare-results.py" "$tmp/small-single.json" "$tmp/parallel-$n/small.json"); then
    pass "$what: merged = single run ($out)"
  else
    fail "$what: merged differs from the single run: $out"
  fi
done
