#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, AddressSanitizer + UndefinedBehaviorSanitizer) in
# build-fuzz/ (or $CCDLAB_FUZZ_BUILD_DIR) and runs each for SECONDS seconds (default 60)
# on its seed corpus (fuzz/corpus/TARGET, read only) and a working corpus that grows across
# runs (build-fuzz/corpus/TARGET), with the dictionary fuzz/ccdlab.dict. Prints the
# executions of each target; a crash, a sanitizer report, a broken invariant, a timeout or
# running out of memory is a finding: the input is kept in build-fuzz/findings/TARGET/ and
# the script exits 1.
#
#   ./scripts/fuzz.sh                 # every target, 60 s each
#   ./scripts/fuzz.sh 3600 scene      # one target for an hour
#   ./build-fuzz/fuzz_scene build-fuzz/findings/scene/crash-*   # replay a finding
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene scene_binary experiment truth results merge mesh_ply mesh_obj)
build=${CCDLAB_FUZZ_BUILD_DIR:-$root/build-fuzz}

command -v clang++ >/dev/null || "$root/scripts/install-deps.sh" clang libclang-rt-dev
# CCDLAB_FUZZ_FLAGS: the compiler's optimisation and debug flags (default -O2 -g -DNDEBUG, CMake's;
# CI uses -O1 -g1 -DNDEBUG, which compiles faster for its short smoke run).
# CCDLAB_FUZZ_CONFIGURED=1: $build is already configured with -DCCDLAB_FUZZ=ON (e.g. CI's
# sanitizer build, which builds the tests and the harnesses in one tree); keep its settings.
if [ "${CCDLAB_FUZZ_CONFIGURED:-0}" = 1 ]; then
  grep -q '^CCDLAB_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null ||
    { echo "fuzz.sh: CCDLAB_FUZZ_CONFIGURED=1 but $build is not configured with -DCCDLAB_FUZZ=ON" >&2; exit 2; }
else
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCCDLAB_FUZZ=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="${CCDLAB_FUZZ_FLAGS:--O2 -g -DNDEBUG}" \
    -DCCDLAB_BENCHMARKS=OFF -DBUILD_TESTING=OFF >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

status=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/findings/$t"
  log="$build/findings/$t/last-run.log"
  set +e
  "$build/fuzz_$t" "$build/corpus/$t" "$root/fuzz/corpus/$t" -dict="$root/fuzz/ccdlab.dict" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/findings/$t/" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  corpus=$(ls "$build/corpus/$t" | wc -l)
  if [ $rc -eq 0 ]; then
    echo "fuzz_$t: ${runs:-?} executions in ${seconds} s, working corpus $corpus inputs, no findings"
  else
    status=1
    echo "fuzz_$t: FINDING after ${runs:-?} executions (exit $rc); input and log in $build/findings/$t/"
    grep -m5 -E "ERROR|invariant broken|runtime error|deadly signal|timeout|out-of-memory" "$log" || tail -20 "$log"
  fi
done
exit $status
