#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (docs/errors.md):
# configures build-sanitize/ with -DISOLAB_SANITIZE=ON, builds it and runs ctest there. Too long
# for CI beside the ordinary build (a second full build); run it before a release or after a
# change to memory handling. Extra arguments go to ctest (e.g. -R RunCommand).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-sanitize
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# The Python module is left out: it would run inside an uninstrumented python3, which cannot load
# an ASan library without LD_PRELOAD (and then reports the interpreter's own allocations).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DISOLAB_SANITIZE=ON \
  -DISOLAB_BUILD_PYTHON=OFF -DISOLAB_BUILD_BENCHMARKS=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "${ISOLAB_JOBS:-$(nproc)}"

suppressions="$PWD/scripts/lsan_suppressions.txt"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# MPI ranks (mpirun) unwind every allocation's stack in full (slow, so only there). OpenMPI
# unloads its plugins (mca_*.so) in MPI_Finalize, so at exit LeakSanitizer can no longer name the
# plugin that made an allocation it keeps; with the fast unwinder, which stops at the first frame
# without a frame pointer (Debian's libraries have none), the stack is that one unnamed frame and
# no suppression matches: each rank reported ~3300 of OpenMPI's allocations and aborted (exit
# 134). The full stack reaches libopen-rte, libmpi or libevent, which the suppressions name.
export OMPI_MCA_mca_base_env_list="ASAN_OPTIONS=$ASAN_OPTIONS:fast_unwind_on_malloc=0"
ctest --test-dir "$build" --output-on-failure -j "${ISOLAB_JOBS:-$(nproc)}" "$@"
