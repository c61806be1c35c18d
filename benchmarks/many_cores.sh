#!/usr/bin/env bash
# How `isolab compare -j N` scales with cores (issue #27's table), against the same runs launched
# as N separate `isolab run` processes from a shell (xargs -P N): the ceiling a scheduler inside
# isolab has to reach.
#   * compare: benchmarks/five_story_200_runs.yaml (5 bearings x 5 records x 8 scales = 200 runs)
#     with every history on disk (TMPDIR) and on tmpfs (/dev/shm), summary files and none;
#     wall seconds of the whole process, isolab's own rate (first job handed out to last result)
#     and the share of the jobs' time spent waiting on one another.
#   * processes: 160 runs of the five-story building (5 records x 8 scales x 4) as separate
#     `isolab run` processes, each writing its own file to tmpfs: summary only, or every history.
# Each configuration REPEAT times (default 4), alternating; medians, with the speed-up over
# N = 1. N runs over 1, 2, 4, ... up to the hardware threads (or MAXJ). Run by hand, on a quiet
# machine; never in CI. ISOLAB may be a copy carried to another machine (its libexec/ beside it;
# scripts/pack_binaries.sh). STUDY replaces the compare study (a larger one shows the parallel
# part with less start-up around it); ROWS limits the rows to some of: full-disk full-tmpfs
# summary none processes-summary processes-full.
#   [STUDY=...] [ROWS="..."] benchmarks/many_cores.sh [ISOLAB] [REPEAT] [MAXJ]
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
repeat=${2:-4}
max_jobs=${3:-$(nproc)}
study=${STUDY:-benchmarks/five_story_200_runs.yaml}
read -r -a rows <<<"${ROWS:-full-disk full-tmpfs summary none processes-summary processes-full}"
building=models/buildings/five_story_table9.yaml
records=(ground_motions/elcentro_1940_ns.at2 ground_motions/fwn_firm_seed1.at2
  ground_motions/fwn_soft_seed2.at2 ground_motions/h2_fwn_firm_seed3.at2
  ground_motions/pulse_tp2.at2)
shm=/dev/shm
[ -d "$shm" ] || shm=${TMPDIR:-/tmp}
disk=$(mktemp -d "${TMPDIR:-/tmp}/isolab_many_cores.XXXXXX")
fast=$(mktemp -d "$shm/isolab_many_cores.XXXXXX")
trap 'rm -rf "$disk" "$fast"' EXIT

jobs=()
for ((n = 1; n <= max_jobs; n *= 2)); do jobs+=("$n"); done
[ "${jobs[-1]}" -eq "$max_jobs" ] || jobs+=("$max_jobs")

# Runs a command (its output discarded): prints "WALL CPU", seconds, CPU being the user and
# system time of every process it started (the workers' too: a worker slowed down by its
# neighbours shows as CPU time above N = 1's, a core left idle as wall x N above CPU).
timed() {
  local TIMEFORMAT='%R %U %S' times
  times=$({ time "$@" >/dev/null 2>&1; } 2>&1)
  awk '{ printf "%s %.3f\n", $1, $2 + $3 }' <<<"$times"
}

compare() {  # compare FOLDER RUNS JOBS: the log in FOLDER.log
  rm -rf "$1"
  "$isolab" compare "$study" --runs "$2" -j "$3" -o "$1" 2>"$1.log"
}

# One compare: prints "WALL CPU RATE WAITING", RATE and WAITING from isolab's closing lines
# ("200 runs in 0.21 s on 2 processes: 950.4 runs/s; 0 failed", "waiting on one another: 0.4 %
# of the jobs' time").
compare_once() {  # compare_once FOLDER RUNS JOBS
  local wall_cpu
  wall_cpu=$(timed compare "$@")
  awk -v wall_cpu="$wall_cpu" '
    function percent() { for (i = 1; i <= NF; ++i) if ($i == "%") return $(i - 1) }
    /runs\/s;/ { for (i = 1; i <= NF; ++i) if ($i == "runs/s;") rate = $(i - 1) }
    /^waiting on one another/ { waiting = percent() }
    END { printf "%s %s %s\n", wall_cpu, rate, waiting == "" ? "-" : waiting }' "$1.log"
}

# The 160 runs as separate processes, N at a time.
# shellcheck disable=SC2016 # the single-quoted script is sh's; xargs gives its arguments
processes() {  # processes FOLDER JOBS [--summary-only]: a file each in FOLDER
  rm -rf "$1" && mkdir "$1"
  for copy in 1 2 3 4; do
    for record in "${records[@]}"; do
      for scale in 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8; do
        # No blank at a line's end: xargs -L would join the next line to it.
        echo "$record $scale $1/r_${copy}_$(basename "$record" .at2)_$scale.h5${3:+ $3}"
      done
    done
  done | xargs -P "$2" -L 1 sh -c '"$0" run "$1" --record "$2" --scale "$3" -o "$4" $5 -q' \
    "$isolab" "$building"
}

declare -A row_names=([full-disk]="compare full, disk" [full-tmpfs]="compare full, tmpfs"
  [summary]="compare summary, tmpfs" [none]="compare none"
  [processes-summary]="processes, summary only" [processes-full]="processes, full to tmpfs")
configurations=()
for n in "${jobs[@]}"; do
  for row in "${rows[@]}"; do configurations+=("${row_names[$row]:?unknown row $row}|$n"); done
done
declare -A walls cpus rates waits
echo "study: $study ($(grep -c . <<<"${jobs[*]}") worker counts: ${jobs[*]})"
echo "machine: $(nproc) hardware threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-)"
echo "disk folder: $disk ($(df -T "$disk" | awk 'NR == 2 { print $2 }')); tmpfs: $shm"
compare_once "$fast/run" none "$max_jobs" >/dev/null  # warm-up: page cache, first-touch costs
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for _ in $(seq "$repeat"); do
  for c in "${configurations[@]}"; do
    IFS='|' read -r what n <<<"$c"
    case $what in
      "compare full, disk") read -r wall cpu rate wait < <(compare_once "$disk/run" full "$n") ;;
      "compare full, tmpfs") read -r wall cpu rate wait < <(compare_once "$fast/run" full "$n") ;;
      "compare summary, tmpfs")
        read -r wall cpu rate wait < <(compare_once "$fast/run" summary "$n")
        ;;
      "compare none") read -r wall cpu rate wait < <(compare_once "$fast/run" none "$n") ;;
      "processes, summary only")
        read -r wall cpu < <(timed processes "$fast/p" "$n" --summary-only)
        rate=- wait=-
        ;;
      "processes, full to tmpfs")
        read -r wall cpu < <(timed processes "$fast/p" "$n")
        rate=- wait=-
        ;;
    esac
    walls[$c]+="$wall "
    cpus[$c]+="$cpu "
    rates[$c]+="$rate "
    waits[$c]+="$wait "
  done
done
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"

# Median (the mean of the middle two for an even count; "-" when there are no numbers) and range.
median() {
  tr ' ' '\n' | grep -v '^$' | sort -g | awk '$1 != "-" { r[++n] = $1 }
    END { if (n == 0) print "-"; else print (r[int((n + 1) / 2)] + r[int(n / 2) + 1]) / 2 }'
}
range() { tr ' ' '\n' | grep -v '^$' | sort -g | awk 'NR == 1 { lo = $1 } { hi = $1 } END { printf "%.3g-%.3g", lo, hi }'; }
printf '\n%-24s %3s %7s %12s %8s %7s %9s %8s %8s %8s\n' what N "wall s" range speed-up "CPU s" \
  "CPU/N=1" "runs/s" speed-up waiting
for row in "${rows[@]}"; do
  what=${row_names[$row]}
  first="$what|${jobs[0]}"
  for n in "${jobs[@]}"; do
    c="$what|$n"
    awk -v what="$what" -v n="$n" -v range="$(range <<<"${walls[$c]}")" \
      -v w="$(median <<<"${walls[$c]}")" -v w1="$(median <<<"${walls[$first]}")" \
      -v cpu="$(median <<<"${cpus[$c]}")" -v cpu1="$(median <<<"${cpus[$first]}")" \
      -v r="$(median <<<"${rates[$c]}")" -v r1="$(median <<<"${rates[$first]}")" \
      -v wait="$(median <<<"${waits[$c]}")" 'BEGIN {
        rs = r == "-" ? "-" : sprintf("%.1f", r)
        rx = r == "-" ? "-" : sprintf("%.2f", r / r1)
        ws = wait == "-" ? "-" : sprintf("%.2f %%", wait)
        printf "%-24s %3d %7.3f %12s %8.2f %7.2f %9.2f %8s %8s %8s\n", what, n, w, range, w1 / w,
          cpu, cpu / cpu1, rs, rx, ws }'
  done
done
