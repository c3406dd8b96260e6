#!/usr/bin/env bash
# Installs the Debian 12 packages sph-mol needs (only those missing), then configures and
# builds the Release preset into build/release. Safe to re-run; works as root on a fresh machine.
# Arguments are passed to the configure step (scripts/check.sh passes -DSPHMOL_MPI=ON).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          libsundials-dev libeigen3-dev libcgal-dev libgsl-dev catch2
          libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libbenchmark-dev
          gnuplot-nox clang-14 libclang-rt-14-dev
          libopenmpi-dev openmpi-bin libtrilinos-zoltan-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

preset="${SPHMOL_PRESET:-release}"
cmake --preset "$preset" "$@" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
