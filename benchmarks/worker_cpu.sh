#!/usr/bin/env bash
# The extra CPU a job costs when studies run on several worker processes (issue 48 item 6's
# 2-core proxy for the 16-worker excess): the process tree's CPU (perf stat task-clock, which
# counts the workers) of one compare study at -j 1 and at -j 2, runs alternating, per job,
# medians of REPEAT pairs (default 9). Run by hand on a quiet machine; never in CI.
#   benchmarks/worker_cpu.sh [ISOLAB] [REPEAT] [STUDY]
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
repeat=${2:-9}
study=${3:-benchmarks/five_story_40_runs.yaml}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The study's jobs: the rows of its summary, from one run.
"$isolab" compare "$study" -q -j 1 -o "$work/count" >/dev/null 2>&1
jobs=$(($(wc -l <"$work/count/summary.csv") - 1))
rm -rf "$work/count"
cpu_ms() {  # task-clock of the whole process tree, ms
  perf stat -x, -e task-clock -o "$work/stat" "$isolab" compare "$study" -q -j "$1" \
    -o "$work/out_$1_$2" >/dev/null 2>&1
  rm -rf "$work/out_$1_$2"
  awk -F, '/task-clock/ { print $1 }' "$work/stat"
}
for i in $(seq "$repeat"); do
  echo "$(cpu_ms 1 "$i") $(cpu_ms 2 "$i")" >>"$work/pairs"
done
median() { sort -n | awk '{ t[NR] = $1 } END { print t[int((NR + 1) / 2)] }'; }
one=$(awk '{ print $1 }' "$work/pairs" | median)
two=$(awk '{ print $2 }' "$work/pairs" | median)
ratio=$(awk '{ print $2 / $1 }' "$work/pairs" | median)
echo "study $study, $jobs jobs, $repeat pairs on $(nproc) cores"
echo "CPU per job: -j 1 $(awk -v c="$one" -v n="$jobs" 'BEGIN { printf "%.2f", c / n }') ms," \
  "-j 2 $(awk -v c="$two" -v n="$jobs" 'BEGIN { printf "%.2f", c / n }') ms;" \
  "-j 2 / -j 1 per pair: median $ratio"
