#!/usr/bin/env bash
# Throughput of `isolab compare` (runs per second) on the bundled study, on 1 and 2 MPI ranks and
# on 1 and 2 threads: each configuration REPEAT times (default 7), median and best of the rate
# isolab reports (first job handed out to last result; MPI start-up and the summary excluded).
# Run by hand on a quiet machine (docs/benchmarks.md); never in CI.
#   benchmarks/compare_throughput.sh [STUDY] [REPEAT]
set -euo pipefail
cd "$(dirname "$0")/.."
study=${1:-models/studies/five_story_isolators.yaml}
repeat=${2:-7}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

rate() {  # runs/s from isolab's closing stderr line: "36 runs in 0.21 s on 2 threads: 171.4 runs/s; 0 failed"
  "$@" 2>&1 >/dev/null | sed -n 's/.*: \([0-9.]*\) runs\/s;.*/\1/p'
}

measure() {
  local label=$1
  shift
  local rates=()
  for _ in $(seq "$repeat"); do rates+=("$(rate "$@")"); done
  printf '%s\n' "${rates[@]}" | sort -g | awk -v label="$label" '
    { r[NR] = $1 }
    END { printf "%-12s median %7.1f runs/s   best %7.1f runs/s   (%d repeats)\n", label, r[int((NR + 1) / 2)], r[NR], NR }'
}

mpi=(mpirun --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi
measure "mpi -np 1" "${mpi[@]}" -np 1 build/isolab compare "$study" -o "$out/m1"
measure "mpi -np 2" "${mpi[@]}" -np 2 build/isolab compare "$study" -o "$out/m2"
measure "threads 1" build/isolab compare "$study" -j 1 -o "$out/t1"
measure "threads 2" build/isolab compare "$study" -j 2 -o "$out/t2"
