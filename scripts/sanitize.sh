#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (-DISOLAB_SANITIZE=ON;
# docs/development.md, docs/errors.md), in a build of its own beside build/.
#
#   scripts/sanitize.sh [CTEST ARGUMENTS]       every test, in build-sanitize/: -O2 -g, so reports
#                                               name files and lines
#   scripts/sanitize.sh --ci [CTEST ARGUMENTS]  CI's stage (.ci/run), in build-sanitize-ci/: -Og
#                                               without -g, isolab and the test executables of
#                                               kCiTests only (a whole sanitized build is too long)
#
# Extra arguments go to ctest (e.g. -R RunCommand); ISOLAB_JOBS=N sets the parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."

ci=false
if [[ "${1:-}" == "--ci" ]]; then
  ci=true
  shift
fi

# CI's test executables, chosen by what they put through memory handling: every reader under
# seeded mutation of the bundled files, the atomic files and HDF5 (failed writes too), the element
# laws, both integrators, and every command end to end through the isolab executables (readers,
# elements, solvers and writers again, compare under mpirun), the installed package and the
# out-of-memory exit. Left out: the libraries' other unit tests, and the long optimisation runs
# (fits, diagnosis, constant-ductility spectra, plots: ~1,400 of the suite's ~1,500 CPU seconds
# sanitized, repeating code the others reach). docs/development.md has the costs.
kCiTests=(reader_fuzz_test atomic_file_test hdf5_write_failure_test results_writer_test
          law_update_test plan_assembly_test newmark_test ida_test run_command_test
          plan_run_command_test cyclic_command_test compare_command_test spectrum_command_test
          synth_command_test output_refusal_test shaketable_command_test design_command_test
          out_of_memory_test path_replay_test)
# Tests of those executables left out: the building diagnosis end to end (a building fit repeated
# per candidate effect, 106-122 s sanitized, a quarter of the stage's test time), whose fit the
# shake-table fit test puts through the same code. ctest keeps one -E: an -E given to --ci
# replaces this one.
kCiLongRuns=('ShakeTableCommand\.DiagnoseBuildingNamesTheViscousPartTheModelLacks')

if $ci; then
  build="build-sanitize-ci"
  # -Og, not -O1: a third less compile time for the same test time (docs/development.md).
  flags=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-Og -DNDEBUG"
         "-DCMAKE_C_FLAGS_RELEASE=-Og -DNDEBUG")
  targets=(--target isolab isolab_search isolab_studies "${kCiTests[@]}")
  # Labels are the executables' names (tests/CMakeLists.txt); "install" is the package test.
  selection=(-L "^($(IFS='|'; echo "${kCiTests[*]}")|install)\$"
             -E "^($(IFS='|'; echo "${kCiLongRuns[*]}"))\$")
else
  build="build-sanitize"
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
  targets=()
  selection=()
fi
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
jobs="${ISOLAB_JOBS:-$(nproc)}"
# The Python module is left out: it would run inside an uninstrumented python3, which cannot load
# an ASan library without LD_PRELOAD (and then reports the interpreter's own allocations).
source scripts/configure_build.sh
configure_build "$build" "${flags[@]}" -DISOLAB_SANITIZE=ON -DISOLAB_BUILD_PYTHON=OFF \
  -DISOLAB_BUILD_BENCHMARKS=OFF "${launcher[@]}"
cmake --build "$build" -j "$jobs" "${targets[@]}"

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
ctest --test-dir "$build" --output-on-failure -j "$jobs" "${selection[@]}" "$@"
