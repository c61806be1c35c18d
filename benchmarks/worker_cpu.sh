#!/usr/bin/env bash
# The extra CPU a job costs when studies run on several worker processes (issue 48 item 6's
# 2-core proxy for the 16-worker excess): the process tree's CPU (perf stat task-clock, which
# counts the workers) of one compare study at -j 1 and at -j 2, per job, and the part of it spent
# in the kernel (system time: writing the per-run files, forking). Beside them, the
# machine's own share: two -j 1 studies run at once, as two separate processes (-j 1 runs its
# jobs in its own process, forking none), so that both cores are busy with no workers. What
# -j 2 costs beyond that pair is the workers' own. Each round runs the three in turn; medians of
# REPEAT rounds (default 9). RUNS (compare's --runs: none, summary or full; without it, what the
# study says, full by default) says which per-run files the studies write, so that writing them
# can be told from running them.
# Run by hand on a quiet machine; never in CI.
#   benchmarks/worker_cpu.sh [ISOLAB] [REPEAT] [STUDY] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
repeat=${2:-9}
study=${3:-benchmarks/five_story_40_runs.yaml}
runs=()
[ -n "${4:-}" ] && runs=(--runs "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The study's jobs: the rows of its summary, from one run.
"$isolab" compare "$study" -q -j 1 "${runs[@]}" -o "$work/count" >/dev/null 2>&1
jobs=$(($(wc -l <"$work/count/summary.csv") - 1))
rm -rf "$work/count"
# The whole process tree's task-clock and, of it, its time in the kernel (ms): cpu_ms JOBS NAME;
# fails with the study.
cpu_ms() {
  perf stat -x, -e task-clock,system_time -o "$work/stat_$2" "$isolab" compare "$study" -q \
    -j "$1" "${runs[@]}" -o "$work/out_$2" >/dev/null 2>&1 || return 1
  rm -rf "$work/out_$2"
  awk -F, '$3 == "task-clock" { t = $1 } $3 == "system_time" { s = $1 / 1e6 }
    END { if (t == "") exit 1; print t, s + 0 }' "$work/stat_$2"
}
for _ in $(seq "$repeat"); do
  one=$(cpu_ms 1 one)
  cpu_ms 1 first >"$work/first" &
  first=$!
  cpu_ms 1 second >"$work/second" &
  second=$!
  wait "$first"  # a study that failed ends the script (set -e), as below
  wait "$second"
  pair=$(awk '{ t += $1; s += $2 } END { print t / 2, s / 2 }' "$work/first" "$work/second")
  two=$(cpu_ms 2 two)  # its own assignment, so that a study that failed ends the script
  echo "$one $pair $two" >>"$work/rounds"
done
median() { sort -g | awk '{ t[NR] = $1 } END { print t[int((NR + 1) / 2)] }'; }
column() { awk -v c="$1" '{ print $c }' "$work/rounds" | median; }
ratio() { awk -v a="$1" -v b="$2" '{ print $a / $b }' "$work/rounds" | median; }
per_job() { awk -v c="$1" -v n="$jobs" 'BEGIN { printf "%.2f", c / n }'; }
echo "study $study, $jobs jobs, --runs ${4:-as the study says}, $repeat rounds on $(nproc) cores"
# A round's columns: task-clock and system time of -j 1, of the pair (each), of -j 2.
echo "CPU per job (medians): -j 1 $(per_job "$(column 1)") ms; two -j 1 studies at once" \
  "$(per_job "$(column 3)") ms each; -j 2 $(per_job "$(column 5)") ms"
echo "of which in the kernel: -j 1 $(per_job "$(column 2)") ms; the pair" \
  "$(per_job "$(column 4)") ms each; -j 2 $(per_job "$(column 6)") ms"
echo "per round, medians: -j 2 / -j 1 $(ratio 5 1); the pair / -j 1 $(ratio 3 1);" \
  "-j 2 / the pair $(ratio 5 3)"
