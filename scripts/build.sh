#!/usr/bin/env bash
# Configures and builds ccdlab (Release) in build/ (or $CCDLAB_BUILD_DIR).
#
#   ./scripts/build.sh                          # everything: program, tests, benchmarks, Python
#   ./scripts/build.sh --target ccdlab          # only the program (and the libraries it needs)
#   ./scripts/build.sh --progress -DCCDLAB_WERROR=ON
#
# Options:
#   --target NAME   build only NAME (repeatable); default: every target
#   --progress      show the build's progress on one line (the compiler's output goes to
#                   BUILD/build.log, whose end is printed when the build fails)
#   -D...           any other argument is passed to CMake's configure step
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
targets=() progress=0 cmake_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --target)
      [ $# -ge 2 ] && [ -n "$2" ] || { echo "build.sh: --target needs a target name" >&2; exit 2; }
      targets+=(--target "$2"); shift 2 ;;
    --progress) progress=1; shift ;;
    *) cmake_args+=("$1"); shift ;;
  esac
done
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release ${cmake_args[@]+"${cmake_args[@]}"} >/dev/null
if [ "$progress" -eq 0 ]; then
  exec cmake --build "$build" -j"$(nproc)" ${targets[@]+"${targets[@]}"}
fi

# Progress: the "[ NN%]" marks of the build, on one line (a terminal) or one line per tenth.
log="$build/build.log"
start=$SECONDS
show() {
  local last=-10 line pct
  while IFS= read -r line; do
    printf '%s\n' "$line" >>"$log"
    [[ $line =~ ^\[\ *([0-9]+)%\] ]] || continue
    pct=${BASH_REMATCH[1]}
    if [ -t 2 ]; then
      printf '\rccdlab: building ... %3d%%  (%d s)' "$pct" $((SECONDS - start)) >&2
    elif [ "$pct" -ge $((last + 10)) ]; then
      printf 'ccdlab: building ... %3d%%  (%d s)\n' "$pct" $((SECONDS - start)) >&2
      last=$pct
    fi
  done
}
: >"$log"
status=0
cmake --build "$build" -j"$(nproc)" ${targets[@]+"${targets[@]}"} 2>&1 | show || status=$?  # pipefail: the build's status
[ -t 2 ] && printf '\n' >&2
if [ "$status" -ne 0 ]; then
  tail -n 40 "$log" >&2
  echo "ccdlab: the build failed; the whole log is $log" >&2
  exit 1
fi
echo "ccdlab: built in $((SECONDS - start)) s" >&2
