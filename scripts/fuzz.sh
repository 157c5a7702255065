#!/usr/bin/env bash
# Runs the libFuzzer harnesses of fuzz/ (clang, AddressSanitizer + UndefinedBehaviorSanitizer;
# docs/fuzzing.md), each on its seed corpus (fuzz/corpus/NAME, read only) and a working
# corpus that grows across runs (WORK/corpus/NAME), with the dictionary fuzz/ccdlab.dict,
# several harnesses at once. A crash, a sanitizer report, a broken invariant, an input taking
# over 10 s or 2 GB is a finding: the input and the log are kept in WORK/findings/NAME/.
# Prints a table (harness, executions, seconds, working corpus, result), also written to a
# file, and exits 1 when any harness found something.
#
#   ./scripts/fuzz.sh                        # builds build-fuzz/, every harness 60 s
#   ./scripts/fuzz.sh 3600 scene             # one harness for an hour
#   ./scripts/fuzz.sh --runs 1000000         # every harness to 10^6 executions
#   ./scripts/fuzz.sh --runs 1000000 --jobs 16 --bin-dir DIR --table table.md
#                                            # prebuilt harnesses in DIR, no compiler needed
#   ./scripts/fuzz.sh --bundle DIR           # builds, then copies what --bin-dir needs to DIR
#   ./build-fuzz/fuzz_scene build-fuzz/findings/scene/crash-*   # replay a finding
#
# Options:
#   SECONDS          time per harness (default 60; with --runs: no time limit unless given)
#   --runs N         stop each harness after N executions (libFuzzer -runs=N)
#   --jobs J         harnesses run at once (default: the number of cores)
#   --bin-dir DIR    run the fuzz_* executables in DIR instead of building (shared libraries
#                    in DIR/lib are found there)
#   --corpus-dir D   the seed corpora (default fuzz/corpus)
#   --dict FILE      the dictionary (default fuzz/ccdlab.dict)
#   --work-dir DIR   working corpora, findings and logs (default: the build folder, or
#                    ./fuzz-work with --bin-dir)
#   --table FILE     where the table is written (default WORK/fuzz-table.md)
#   --bundle DIR     build, then copy the harnesses and their shared libraries (DIR/bin,
#                    DIR/bin/lib), the seeds, the dictionary and this script into DIR; run
#                    there as DIR/scripts/fuzz.sh --bin-dir DIR/bin ...
#   NAME...          harnesses to run (default: every fuzz/fuzz_NAME.cpp, or every
#                    DIR/fuzz_NAME with --bin-dir)
#
# Building: clang in build-fuzz/ (or $CCDLAB_FUZZ_BUILD_DIR). CCDLAB_FUZZ_FLAGS sets the
# optimisation and debug flags (default -O2 -g -DNDEBUG; CI uses -O1 -g1). With
# CCDLAB_FUZZ_CONFIGURED=1 the build folder is already configured with -DCCDLAB_FUZZ=ON
# (CI's sanitizer build, which builds the tests and the harnesses in one tree) and keeps
# its settings.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds="" runs="" jobs=$(nproc) bin_dir="" bundle="" table="" work=""
corpus_dir="$root/fuzz/corpus" dict="$root/fuzz/ccdlab.dict"
targets=()
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2; exit 2; }
need() { [ $# -ge 2 ] && [ -n "$2" ] || { echo "fuzz.sh: $1 needs a value" >&2; exit 2; }; }
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) need "$@"; runs=$2; shift 2 ;;
    --jobs) need "$@"; jobs=$2; shift 2 ;;
    --bin-dir) need "$@"; bin_dir=$(cd "$2" && pwd); shift 2 ;;
    --corpus-dir) need "$@"; corpus_dir=$(cd "$2" && pwd); shift 2 ;;
    --dict) need "$@"; dict=$2; shift 2 ;;
    --work-dir) need "$@"; work=$2; shift 2 ;;
    --table) need "$@"; table=$2; shift 2 ;;
    --bundle) need "$@"; bundle=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "fuzz.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) if [ -z "$seconds" ] && [ ${#targets[@]} -eq 0 ] && [[ $1 =~ ^[0-9]+$ ]]; then seconds=$1; else targets+=("$1"); fi
       shift ;;
  esac
done
for n in "$runs" "$jobs" "$seconds"; do
  [ -z "$n" ] || [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "fuzz.sh: '$n' is not a positive integer" >&2; exit 2; }
done
[ -n "$seconds" ] || [ -n "$runs" ] || seconds=60
[ -f "$dict" ] || { echo "fuzz.sh: no dictionary $dict" >&2; exit 2; }

if [ -n "$bin_dir" ]; then
  [ -n "$bundle" ] && { echo "fuzz.sh: --bundle builds; it does not take --bin-dir" >&2; exit 2; }
  if [ ${#targets[@]} -eq 0 ]; then
    for f in "$bin_dir"/fuzz_*; do [ -x "$f" ] && targets+=("${f##*/fuzz_}"); done
  fi
  [ -d "$bin_dir/lib" ] && export LD_LIBRARY_PATH="$bin_dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  work=${work:-$PWD/fuzz-work}
else
  if [ ${#targets[@]} -eq 0 ]; then
    for f in "$root"/fuzz/fuzz_*.cpp; do n=${f##*/fuzz_}; targets+=("${n%.cpp}"); done
  fi
  build=${CCDLAB_FUZZ_BUILD_DIR:-$root/build-fuzz}
  command -v clang++ >/dev/null || "$root/scripts/install-deps.sh" clang libclang-rt-dev
  if [ "${CCDLAB_FUZZ_CONFIGURED:-0}" = 1 ]; then
    grep -q '^CCDLAB_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null ||
      { echo "fuzz.sh: CCDLAB_FUZZ_CONFIGURED=1 but $build is not configured with -DCCDLAB_FUZZ=ON" >&2; exit 2; }
  else
    CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCCDLAB_FUZZ=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="${CCDLAB_FUZZ_FLAGS:--O2 -g -DNDEBUG}" \
      -DCCDLAB_BENCHMARKS=OFF -DBUILD_TESTING=OFF >/dev/null
  fi
  cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
  bin_dir=$build
  work=${work:-$build}
fi
[ ${#targets[@]} -gt 0 ] || { echo "fuzz.sh: no harnesses to run" >&2; exit 2; }
for t in "${targets[@]}"; do
  [ -x "$bin_dir/fuzz_$t" ] || { echo "fuzz.sh: no harness $bin_dir/fuzz_$t" >&2; exit 2; }
done

if [ -n "$bundle" ]; then
  mkdir -p "$bundle/bin/lib" "$bundle/scripts" "$bundle/fuzz"
  for t in "${targets[@]}"; do
    cp "$bin_dir/fuzz_$t" "$bundle/bin/"
    # Shared libraries other than the C library's own (those stay the machine's).
    ldd "$bin_dir/fuzz_$t" | awk '$3 ~ /^\// {print $3}' |
      grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' | xargs -r cp -L -t "$bundle/bin/lib/"
  done
  cp "$0" "$bundle/scripts/fuzz.sh"
  rm -rf "$bundle/fuzz/corpus"
  cp -r "$corpus_dir" "$bundle/fuzz/corpus"
  cp "$dict" "$bundle/fuzz/ccdlab.dict"
  echo "fuzz.sh: bundle in $bundle ($(du -sh "$bundle" | cut -f1)); run there:"
  echo "  cd $bundle && ./scripts/fuzz.sh --bin-dir bin --runs 1000000 --table fuzz-table.md"
  exit 0
fi

table=${table:-$work/fuzz-table.md}
# One harness: its log is WORK/findings/NAME/last-run.log; its exit status goes to .rc.
run_one() {
  local t=$1 out="$work/findings/$1"
  mkdir -p "$work/corpus/$t" "$out"
  local seeds=()
  [ -d "$corpus_dir/$t" ] && seeds=("$corpus_dir/$t")
  local limits=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1)
  [ -n "$seconds" ] && limits+=(-max_total_time="$seconds")
  [ -n "$runs" ] && limits+=(-runs="$runs")
  local start=$SECONDS rc=0
  "$bin_dir/fuzz_$t" "$work/corpus/$t" "${seeds[@]}" -dict="$dict" "${limits[@]}" \
    -artifact_prefix="$out/" >"$out/last-run.log" 2>&1 || rc=$?
  echo "$rc $((SECONDS - start))" >"$out/.rc"
}

echo "fuzz.sh: ${#targets[@]} harnesses, $jobs at a time, ${runs:+$runs executions}${runs:+${seconds:+ or }}${seconds:+$seconds s} each"
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
  run_one "$t" &
  running=$((running + 1))
done
wait

status=0
{
  echo "| harness | executions | seconds | working corpus | result |"
  echo "|---|---:|---:|---:|---|"
  for t in "${targets[@]}"; do
    out="$work/findings/$t"
    read -r rc took <"$out/.rc"
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/last-run.log" | tail -1)
    corpus=$(find "$work/corpus/$t" -type f | wc -l)
    if [ "$rc" -eq 0 ]; then
      result="no findings"
    else
      status=1
      kind=$(grep -m1 -oE "ERROR: [A-Za-z]+: [a-z-]+|invariant broken|runtime error|deadly signal|timeout|out-of-memory" \
        "$out/last-run.log" || echo "exit $rc")
      result="FINDING ($kind): $out/"
    fi
    echo "| fuzz_$t | ${execs:-?} | $took | $corpus | $result |"
  done
} >"$table.tmp"
mv "$table.tmp" "$table"
cat "$table"
echo "fuzz.sh: table written to $table"
if [ $status -ne 0 ]; then
  for t in "${targets[@]}"; do
    read -r rc _ <"$work/findings/$t/.rc"
    [ "$rc" -eq 0 ] && continue
    echo "== fuzz_$t (log: $work/findings/$t/last-run.log)"
    grep -m5 -E "ERROR|invariant broken|runtime error|deadly signal|timeout|out-of-memory" \
      "$work/findings/$t/last-run.log" || tail -20 "$work/findings/$t/last-run.log"
  done
fi
exit $status
