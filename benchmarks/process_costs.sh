#!/usr/bin/env bash
# Whole-process costs of `isolab run` (docs/benchmarks.md, "Process costs"): start-up
# (`isolab --version`, shared libraries), a one-step run, the set-up of a 1000-story building and
# the memory peak of a 1000-story run of 10,000 steps (no free vibration after the record), with
# summary-only output, every 10th step and every step written. Times are medians of REPEAT runs (default
# 9), wall and CPU (user + system; less sensitive to other load). Run by hand on a quiet
# machine; never in CI.
#   benchmarks/process_costs.sh [ISOLAB] [REPEAT]
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
repeat=${2:-9}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median_ms() {  # "wall W ms, CPU C ms": medians over REPEAT runs of a command (CPU = user + system)
  local TIMEFORMAT='%3R %3U %3S'
  for _ in $(seq "$repeat"); do { time "$@" >/dev/null 2>&1; } 2>>"$work/times"; done
  local wall cpu
  wall=$(awk '{ print $1 * 1000 }' "$work/times" | sort -n | awk '{ t[NR] = $1 } END { print t[int((NR + 1) / 2)] }')
  cpu=$(awk '{ print ($2 + $3) * 1000 }' "$work/times" | sort -n | awk '{ t[NR] = $1 } END { print t[int((NR + 1) / 2)] }')
  rm "$work/times"
  echo "wall $wall ms, CPU $cpu ms"
}

# A 1000-story building (25 t floors, 76 kN/mm stories, 2 % Rayleigh on modes 1 and 2) on a
# linear isolator that never yields (2.5 s, 10 % on the whole mass), under 100 s of isolab's
# seeded noise at 0.01 s: 10,000 steps. The same model with a one-sample record is one step.
"$isolab" synth noise --duration 100 --pga 0.35 -o "$work/noise_100s.at2" >/dev/null
printf 'PEER STRONG MOTION DATABASE RECORD\none step\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   2, DT=   .0100 SEC\n0.0 0.01\n' \
  >"$work/one_step.at2"
building() {  # building RECORD > model
  cat <<EOF
units: {force: kN, length: mm, time: s}
structure:
  type: shear_building
  base_mass: 25 t
  stories: {count: 1000, mass: 25 t, stiffness: 76 kN/mm, height: 3.2 m}
  damping: {type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}
isolation:
  components:
    - {name: spring, type: linear_spring, k: 158.07}
    - {name: dashpot, type: dashpot, c: 12.579}
excitation:
  ground_motion: {file: $1}
analysis: {dt: 0.01}
EOF
}
building "$work/noise_100s.at2" >"$work/stories_1000.yaml"
building "$work/one_step.at2" >"$work/stories_1000_one_step.yaml"
sed "s#file: ../../ground_motions/fwn_firm_seed1.at2, scale: 0.6#file: $work/one_step.at2#" \
  models/buildings/five_story_table9.yaml >"$work/five_story_one_step.yaml"

echo "isolab: $isolab ($("$isolab" --version))"
echo "isolab --version:                  $(median_ms "$isolab" --version)"
echo "shared libraries (ldd):            $(ldd "$isolab" | wc -l)"
echo "shared libraries loaded (--version): $(LD_DEBUG=libs "$isolab" --version 2>&1 | grep -c 'calling init:')"
echo "one-step run, five-story Table 9:  $(median_ms "$isolab" run "$work/five_story_one_step.yaml" --free-vibration 0 -o "$work/one.h5")"
echo "one-step run, 1000 stories:        $(median_ms "$isolab" run "$work/stories_1000_one_step.yaml" --free-vibration 0 -o "$work/one.h5") (set-up)"
peak() {  # peak resident memory of a command
  /usr/bin/time -v "$@" >"$work/run.txt" 2>"$work/time.txt"
  echo "wall $(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt"), peak RSS $(awk '/Maximum resident set size/ { printf "%.1f MiB", $6 / 1024 }' "$work/time.txt")"
}
echo "isolab --version:                  $(peak "$isolab" --version)"
for output in --summary-only "--every 10" ""; do
  rm -f "$work/run.h5"
  echo "1000 stories, 10,000 steps, ${output:-every step}: $(peak "$isolab" run "$work/stories_1000.yaml" --free-vibration 0 -o "$work/run.h5" $output)"
  echo "  $(grep -o 'Newton: .*' "$work/run.txt"), results $(du -m "$work/run.h5" | cut -f1) MB"
done
