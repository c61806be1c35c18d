#!/usr/bin/env bash
# isolab against OpenSees 3.8 per time step, on identical models (docs/benchmarks.md, "Against
# OpenSees, side by side"): an SDOF and 5- and 1000-story shear buildings on a bilinear isolator (Steel01 in
# OpenSees, bhm2 in isolab), stiffness-proportional story damping, a seeded random record of
# 100,000 steps at 0.01 s for the SDOF and the five-story building (STEPS), 10,000 for the
# 1000-story building. OpenSees runs its fastest set-up (test NormUnbalance, no recorders, an
# absolute tolerance of 1e-6 kN: at 1e-10 the 1000-story building's unbalance stalls at round-off
# and the analysis fails); isolab runs with every history written to tmpfs and with
# --summary-only. Both do about one solve a step.
#
# Per-step CPU = (CPU of an N-step run - CPU of a 1-step run) / (N - 1), the CPU being the
# process's task-clock, so start-up, reading and set-up cancel. The small models' 10,000 steps
# are 1 to 7 ms of isolab's CPU, about what one process differs from the next: their record is
# ten times longer (the peers' generator, same seed and peak), so that a step's cost resolves.
# The runs are paired and alternate (isolab histories, isolab summary, OpenSees), REPEAT times
# (default 5); medians.
#
# It needs the packed OpenSees of ../shared/peers/opensees (its README) and perf: where that
# folder is missing it says so and compares nothing (exit 0). Never part of the tests or CI.
#   benchmarks/opensees_side_by_side.sh [ISOLAB] [REPEAT] [PEERS] [STEPS]
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
repeat=${2:-5}
peers=${3:-../shared/peers/opensees}
steps=${4:-100000}  # the SDOF's and the five-story building's (at least 2); 1000 stories: 10,000
[ "$steps" -ge 2 ] || { echo "STEPS must be at least 2, not $steps" >&2; exit 2; }
tarball="$peers/opensees-3.8-debian12.tar.xz"
if [ ! -f "$tarball" ]; then
  echo "OpenSees is not at hand ($tarball missing): nothing compared"
  exit 0
fi
command -v perf >/dev/null || { echo "perf is missing (Debian's linux-perf): nothing compared"; exit 1; }
peers=$(realpath "$peers")
shm=/dev/shm
[ -d "$shm" ] || shm=${TMPDIR:-/tmp}
work=$(mktemp -d "${TMPDIR:-/tmp}/isolab_opensees.XXXXXX")
fast=$(mktemp -d "$shm/isolab_opensees.XXXXXX")
trap 'rm -rf "$work" "$fast"' EXIT

tar -xJf "$tarball" -C "$work"
opensees=$(find "$work" -maxdepth 2 -type f -name opensees | head -1)
mkdir -p "$work/motions" "$work/models"
/usr/bin/python3 "$peers/gen_motion.py" random "$work/motions/random_10001.txt" 10001 0.01 3.0 1
/usr/bin/python3 "$peers/gen_motion.py" sine "$work/motions/sine_10001.txt" 10001 0.01 2.0 1.0
/usr/bin/python3 "$peers/gen_motion.py" random "$work/motions/random_long.txt" $((steps + 1)) \
  0.01 3.0 1
/usr/bin/python3 "$peers/make_isolab_models.py" "$work/models" "$work/motions" >/dev/null
# The same models under the long record; their 1-step twins read it too, as OpenSees' 1-step runs
# do, so that reading it cancels for both.
for model in sdof_random sdof_random_short building_N5_stiff building_N5_stiff_short; do
  sed 's#random_10001\.txt#random_long.txt#' "$work/models/$model.yaml" \
    >"$work/models/${model}_long.yaml"
done

# CPU seconds of a command (perf's task-clock: every thread and child, to the microsecond, where
# bash's time has milliseconds), its output discarded. isolab's results file is new each run:
# replacing the last run's would charge the run with freeing the old file's pages, and a 1-step
# run that replaced the long run's file would take that cost off the per-step figure (at five
# stories and 100,000 steps, 0.06 us a step of 0.43).
cpu() {
  rm -f "$fast/run.h5"
  perf stat -x, -o "$work/perf.txt" -e task-clock -- "$@" >/dev/null 2>&1
  awk -F, '$3 == "task-clock" { printf "%.6f\n", $1 / 1000 }' "$work/perf.txt"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

isolab_run() {  # MODEL histories|summary: the command line
  local output=(-o "$fast/run.h5")
  [ "$2" = summary ] && output+=(--summary-only)
  # The record's length with no free vibration; a 1-step twin fixes its duration, which already
  # leaves free vibration out (and isolab refuses --free-vibration with it).
  grep -Eq '^analysis:.*[{ ,]duration:' "$work/models/$1" || output+=(--free-vibration 0)
  echo "$isolab" run "$work/models/$1" -q "${output[@]}"
}
opensees_run() {  # SCRIPT RECORD STEPS ARGS...: the command line
  local script=$1 record=$2 steps=$3
  shift 3
  echo "$opensees" "$peers/$script" -noHeader acc="$work/motions/$record" dt=0.01 \
    n="$steps" rec=0 test=NormUnbalance tol=1.0e-6 "$@"
}

# One case: prints "name isolab-histories isolab-summary opensees" in us per step (medians).
measure() {  # NAME LONG_MODEL SHORT_MODEL RECORD STEPS SCRIPT ARGS...
  local name=$1 long=$2 short=$3 record=$4 n=$5 script=$6
  shift 6
  # Each command once, checked: a run that fails or is refused would otherwise be timed as if it
  # were one (a refused 1-step run makes every per-step figure too large).
  # shellcheck disable=SC2046  # the command lines split into words, as they should
  for command in "$(isolab_run "$long" histories)" "$(isolab_run "$long" summary)" \
    "$(isolab_run "$short" histories)" "$(isolab_run "$short" summary)" \
    "$(opensees_run "$script" "$record" "$n" "$@")" "$(opensees_run "$script" "$record" 1 "$@")"; do
    if ! $command >"$work/check.txt" 2>&1 || grep -q "analyze failed" "$work/check.txt"; then
      echo "$name: failed: $command" >&2
      cat "$work/check.txt" >&2
      exit 1
    fi
  done
  local h=() s=() o=()
  # shellcheck disable=SC2046  # the command lines split into words, as they should
  for ((r = 0; r < repeat; ++r)); do
    h+=("$(awk -v a="$(cpu $(isolab_run "$long" histories))" -v b="$(cpu $(isolab_run "$short" histories))" \
      -v n="$n" 'BEGIN { print (a - b) / (n - 1) * 1e6 }')")
    s+=("$(awk -v a="$(cpu $(isolab_run "$long" summary))" -v b="$(cpu $(isolab_run "$short" summary))" \
      -v n="$n" 'BEGIN { print (a - b) / (n - 1) * 1e6 }')")
    o+=("$(awk -v a="$(cpu $(opensees_run "$script" "$record" "$n" "$@"))" \
      -v b="$(cpu $(opensees_run "$script" "$record" 1 "$@"))" \
      -v n="$n" 'BEGIN { print (a - b) / (n - 1) * 1e6 }')")
  done
  printf '%s %s %s %s\n' "$name" "$(printf '%s\n' "${h[@]}" | median)" \
    "$(printf '%s\n' "${s[@]}" | median)" "$(printf '%s\n' "${o[@]}" | median)"
}

{
  measure SDOF sdof_random_long.yaml sdof_random_short_long.yaml random_long.txt "$steps" \
    sbs_sdof.tcl m=1.0 k=100.0 fy=1.0 b=0.1 zeta=0.05
  measure "5 stories" building_N5_stiff_long.yaml building_N5_stiff_short_long.yaml \
    random_long.txt "$steps" sbs_shear.tcl N=5 damp=stiff
  measure "1000 stories" building_N1000_stiff.yaml building_N1000_stiff_short.yaml \
    random_10001.txt 10000 sbs_shear.tcl N=1000 damp=stiff
} | awk -v repeat="$repeat" -v steps="$steps" '
  BEGIN {
    printf "| model | isolab, every history (us/step) | isolab, summary only | OpenSees NormUnbalance | OpenSees / isolab: histories, summary |\n|---|---|---|---|---|\n"
  }
  {
    name = $1; for (i = 2; i <= NF - 3; ++i) name = name " " $i
    h = $(NF - 2); s = $(NF - 1); o = $NF
    printf "| %s | %.3g | %.3g | %.4g | %.1f, %.1f |\n", name, h, s, o, o / h, o / s
  }
  END {
    printf "\nmedians of %d paired runs; per step = (N steps - 1 step) / (N - 1)", repeat
    printf " of the process CPU;"
    printf " N = %d (SDOF, 5 stories), 10000 (1000 stories)\n", steps
  }'
