#!/usr/bin/env bash
# Configures and builds ccdlab (Release) in build/ (or $CCDLAB_BUILD_DIR).
# Extra CMake options may be passed as arguments, e.g. -DCCDLAB_WERROR=ON.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
