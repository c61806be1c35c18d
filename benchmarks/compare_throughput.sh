#!/usr/bin/env bash
# Throughput of `isolab compare` (runs per second) on one and two local workers (this process;
# two worker processes) and on 1 and 2 MPI ranks, with per-run files (full histories, summaries
# only) and without: each configuration REPEAT
# times (default 7), alternating, median and range of the rate isolab reports (first job handed
# out to last result; MPI start-up and the summary excluded), the speed-up of 2 over 1 from the
# medians, the share of the jobs' time spent waiting on one another (a lock, a full pipe to the
# coordinator: the Amdahl bound) and the share spent writing their files (no lock: the output's
# cost).
# Output goes to tmpfs (/dev/shm) where there is one, so the cost measured is isolab's and
# HDF5's, not a disk's. Run by hand, on as quiet a machine as there is (docs/benchmarks.md); the
# load average is printed before and after; never in CI.
#   benchmarks/compare_throughput.sh [STUDY] [REPEAT] [RUNS...]
#   (default: benchmarks/five_story_40_runs.yaml, 7, "full summary none")
set -euo pipefail
cd "$(dirname "$0")/.."
study=${1:-benchmarks/five_story_40_runs.yaml}
repeat=${2:-7}
shift $(($# < 2 ? $# : 2))
modes=("$@")
[ ${#modes[@]} -eq 0 ] && modes=(full summary none)
base=/dev/shm
[ -d "$base" ] || base=${TMPDIR:-/tmp}
out=$(mktemp -d "$base/isolab_throughput.XXXXXX")
trap 'rm -rf "$out"' EXIT

mpi=(mpirun --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi

# One run: prints "RATE WAITING WRITING" from isolab's closing stderr lines:
#   "40 runs in 0.21 s on 2 processes: 190.4 runs/s; 0 failed"
#   "waiting on one another: 0.01 % of the jobs' time"
#   "per-run files (full): 35.9 % of the jobs' time writing them"
once() {
  local folder=$1
  shift
  rm -rf "$folder"
  "$@" -o "$folder" 2>&1 >/dev/null | awk '
    function percent() { for (i = 1; i <= NF; ++i) if ($i == "%") return $(i - 1) }
    /runs\/s;/ { for (i = 1; i <= NF; ++i) if ($i == "runs/s;") rate = $(i - 1) }
    /^waiting on one another/ { waiting = percent() }
    /^per-run files/ { writing = percent() }
    END { printf "%s %s %s\n", rate, waiting == "" ? "-" : waiting, writing == "" ? "-" : writing }'
}

# Median, range and the shares for each configuration, the configurations alternating.
declare -A rates waits writes
configurations=()
add() { configurations+=("$1"); }
for runs in "${modes[@]}"; do
  add "$runs|local 1|build/isolab compare $study --runs $runs -j 1"
  add "$runs|local 2|build/isolab compare $study --runs $runs -j 2"
  add "$runs|mpi -np 1|${mpi[*]} -np 1 build/isolab compare $study --runs $runs"
  add "$runs|mpi -np 2|${mpi[*]} -np 2 build/isolab compare $study --runs $runs"
done
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for _ in $(seq "$repeat"); do
  for c in "${configurations[@]}"; do
    IFS='|' read -r runs label command <<<"$c"
    # shellcheck disable=SC2086
    read -r rate wait write < <(once "$out/run" $command)
    rates[$c]+="$rate "
    waits[$c]+="$wait "
    writes[$c]+="$write "
  done
done
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ r[NR] = $1 } END { print r[int((NR + 1) / 2)] }'; }
lowest() { tr ' ' '\n' | grep -v '^$' | sort -g | head -1; }
highest() { tr ' ' '\n' | grep -v '^$' | sort -g | tail -1; }
declare -A medians
for c in "${configurations[@]}"; do
  IFS='|' read -r runs label _ <<<"$c"
  m=$(median <<<"${rates[$c]}")
  medians[$runs|$label]=$m
  printf 'runs %-8s %-10s median %7.1f runs/s  range %7.1f-%-7.1f  waiting %s %%  writing %s %%\n' \
    "$runs" "$label" "$m" "$(lowest <<<"${rates[$c]}")" "$(highest <<<"${rates[$c]}")" \
    "$(median <<<"${waits[$c]}")" "$(median <<<"${writes[$c]}")"
done
for runs in "${modes[@]}"; do
  awk -v r="$runs" -v t1="${medians[$runs|local 1]}" -v t2="${medians[$runs|local 2]}" \
    -v m1="${medians[$runs|mpi -np 1]}" -v m2="${medians[$runs|mpi -np 2]}" \
    'BEGIN { printf "runs %-8s speed-up of 2 over 1: processes %.2f, MPI ranks %.2f\n", r, t2 / t1, m2 / m1 }'
done
