#!/usr/bin/env bash
# Installs isolab's Debian packages (only those missing, so a second run is fast) and builds
# isolab in build/. Non-interactive; safe to run any number of times, in any order.
#
#   scripts/setup.sh          build/isolab, the front: run, spectrum and bounds, all the README's
#                             first run needs (the solver's libraries alone)
#   scripts/setup.sh --all    every command (fit, diagnose, cyclic and shaketable in
#                             libexec/isolab/isolab-search; compare, design and synth in
#                             libexec/isolab/isolab-studies) and the Python module (build/python)
#   scripts/setup.sh --tests  all that, the test suite and the benchmarks, which
#                             `ctest --test-dir build` runs
#
# It installs the packages of what it builds: those the programs build and plot with, then
# pybind11 and Python's headers for the module, then GoogleTest, Google Benchmark, pytest, pandas
# and Tcl for the tests. A new build/ is configured without what was not asked for; a part that
# build/ already has stays (with its packages), and the objects built are kept either way.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-}"
case "$mode" in
  "") targets=(--target isolab) ;;
  --all | --tests) targets=() ;;
  *) echo "usage: scripts/setup.sh [--all | --tests]" >&2; exit 2 ;;
esac

# ON when the mode asks for it or build/ (a Ninja build of isolab's) already has it, else OFF.
part() {
  local option="$1" wanted="$2" cache=build/CMakeCache.txt
  if [ "$wanted" = yes ] || { grep -qx "$option:BOOL=ON" "$cache" 2>/dev/null &&
    grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' "$cache"; }; then
    echo ON
  else
    echo OFF
  fi
}
python=$(part ISOLAB_BUILD_PYTHON "$([ -n "$mode" ] && echo yes)")
tests=$(part ISOLAB_BUILD_TESTS "$([ "$mode" = --tests ] && echo yes)")
benchmarks=$(part ISOLAB_BUILD_BENCHMARKS "$([ "$mode" = --tests ] && echo yes)")

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsundials-dev libsuitesparse-dev libyaml-cpp-dev libhdf5-dev
  libcli11-dev libfmt-dev nlohmann-json3-dev libpagmo-dev libopenmpi-dev openmpi-bin
  python3-matplotlib python3-h5py python3-numpy
)
if [ "$python" = ON ]; then packages+=(python3-dev pybind11-dev); fi
if [ "$tests" = ON ]; then packages+=(libgtest-dev python3-pytest python3-pandas tcl); fi
if [ "$benchmarks" = ON ]; then packages+=(libbenchmark-dev); fi

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
configure_build build -DCMAKE_BUILD_TYPE=Release -DISOLAB_BUILD_PYTHON="$python" \
  -DISOLAB_BUILD_TESTS="$tests" -DISOLAB_BUILD_BENCHMARKS="$benchmarks"
cmake --build build -j "$(nproc)" "${targets[@]}"
