#!/usr/bin/env bash
# Installs isolab's Debian packages (only those missing, so a second run is fast) and builds
# isolab in build/: the programs (build/isolab and the executables it hands commands to), which
# is all a run needs; with --tests, everything else too (the test suite, the benchmarks and the
# Python module), which `ctest --test-dir build` runs. Non-interactive; safe to run any number of
# times, in either order.
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(--target isolab)
case "${1:-}" in
  "") ;;
  --tests) targets=() ;;
  *) echo "usage: scripts/setup.sh [--tests]" >&2; exit 2 ;;
esac

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsundials-dev libsuitesparse-dev libyaml-cpp-dev libhdf5-dev
  libcli11-dev libfmt-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
  libpagmo-dev libopenmpi-dev openmpi-bin python3-matplotlib python3-h5py python3-pandas
  python3-dev python3-numpy python3-pytest pybind11-dev tcl
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

source scripts/configure_build.sh
configure_build build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" "${targets[@]}"
