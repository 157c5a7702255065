#!/usr/bin/env bash
# Installs the Debian packages ccdlab needs, only those missing (quick when all are there).
# Run as root, or as a user with sudo. Extra package names may be passed as arguments.
set -euo pipefail
pkgs=(build-essential cmake git libeigen3-dev libboost-dev libgsl-dev catch2 nlohmann-json3-dev libcli11-dev libtbb-dev
      libbenchmark-dev libxsimd-dev python3-matplotlib libfcl-dev libbullet-dev libgmp-dev
      python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-hypothesis libjs-three chromium parallel
      python3-pandas python3-tqdm python3-build "$@")
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "ccdlab: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
