#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix, checks that no build option of
# ccdlab's own (-march=native, sanitizers, warnings) reaches the exported targets, then
# configures, builds and runs tests/packaging/consumer against the installed package.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
targets=$(ls "$work"/prefix/lib*/cmake/ccdlab/ccdlabTargets*.cmake)
if grep -nE -- '-march|-fsanitize|-Werror|-Wall|ccdlab_options|ccdlab_warnings' $targets; then
  echo "install_test: a build option of ccdlab leaks into the installed package" >&2
  exit 1
fi
test -x "$work/prefix/bin/ccdlab"
test -f "$work/prefix/include/ccdlab/ccd/scene/scene.hpp"
cmake -S "$src/tests/packaging/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer" -j2 >/dev/null
"$work/consumer/consumer"
"$work/consumer/consumer_core"
"$work/prefix/bin/ccdlab" --version
# The installed `ccdlab view` carries its page (embedded at build time): the whole page,
# three.js included, from the installed program alone.
"$work/prefix/bin/ccdlab" view "$src/data/scenes/example.json" -o "$work/view.html" >/dev/null
grep -q 'data-missed' "$work/view.html" && grep -q 'REVISION' "$work/view.html" || {
  echo "install_test: the installed ccdlab view wrote an incomplete page" >&2
  exit 1
}
# The installed scripts behind `ccdlab report` and `ccdlab animate` load (with their shared
# reader): a missing results file is bad input (status 2), not an import failure.
for command in report animate; do
  status=0
  if [ "$command" = report ]; then
    "$work/prefix/bin/ccdlab" report "$work/none.json" -o "$work/report" 2>/dev/null || status=$?
  else
    "$work/prefix/bin/ccdlab" animate "$src/data/scenes/example.json" --results "$work/none.json" \
      --method aabb/sap --dt 0.1 -o "$work/a.gif" 2>/dev/null || status=$?
  fi
  if [ "$status" -ne 2 ]; then
    echo "install_test: the installed ccdlab $command exits $status on a missing results file, not 2" >&2
    exit 1
  fi
done
