#!/usr/bin/env bash
# Simulations per second of a building fit against MPI ranks (issue 48 item 3): the same fit on
# one process, on 1 and on RANKS ranks under mpirun (one thread each: the ranks are the
# parallelism), and on one process with as many threads as ranks for comparison. The BNCS building
# (models/bncs/building_spec.yaml, 16 parameters, both public motions as one specimen) where its
# measurements are at DATA (default ../shared/measured/bncs); the bundled Bouc-Wen sine sweep
# (3 parameters) otherwise, said so. Every configuration must give the same fit: the script
# checks the objectives agree to the last digit. Run by hand on a quiet machine; never in CI.
#   benchmarks/fit_ranks.sh [ISOLAB] [RANKS] [BUDGET] [DATA]
# BUDGET defaults to 400 simulations for the BNCS building (the refinement alone) and 2,000 for the
# sweep (half of them CMA-ES).
set -euo pipefail
cd "$(dirname "$0")/.."
isolab=$(realpath "${1:-build/isolab}")
ranks=${2:-2}
budget=${3:-}
data=${4:-../shared/measured/bncs}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -f "$data/bncs_ica50.csv.gz" ]; then
  for motion in ica50 lac100; do zcat "$data/bncs_$motion.csv.gz" >"$work/$motion.csv"; done
  fit=("$work/lac100.csv" "$work/ica50.csv" --specimen sequential
    --building "$PWD/models/bncs/building_spec.yaml")
  budget=${budget:-400}
  echo "the BNCS building fit, budget $budget simulations"
else
  budget=${budget:-2000}
  echo "no BNCS measurements at $data: the bundled Bouc-Wen sine sweep instead, budget $budget"
  /usr/bin/python3 - "$work" <<'PY'
import sys
folder = sys.argv[1]
rows = [l.strip() for l in open("tests/data/boucwen/sinesweep_first_30000.csv")
        if l.strip() and not l.startswith("#") and "u_N" not in l][:6000]
with open(f"{folder}/sweep.csv", "w") as out:
    out.write("# units: force N, length m\ntest,time,displacement,force\n")
    for k, row in enumerate(rows):
        force, displacement = row.split(",")[:2]
        out.write(f"sweep,{k / 750.0},{displacement},{force}\n")
open(f"{folder}/boucwen.yaml", "w").write(
    "units: {force: N, length: m, time: s}\nstructure: {type: sdof, mass: 2}\n"
    "isolation:\n  components:\n    - {name: k, type: linear_spring, k: 5.0e4}\n"
    "    - {name: z, type: bouc_wen, alpha: 5.0e4, beta: 1.0e3, gamma: 0.8, delta: -1.1, nu: 1}\n"
    "    - {name: c, type: dashpot, c: 10}\n")
open(f"{folder}/spec.yaml", "w").write(
    "model: boucwen.yaml\ninput: force\nsubsteps: 4\nparameters:\n"
    "  - {name: isolation.k.k, start: 3.5e4}\n  - {name: isolation.c.c, start: 15}\n"
    "  - {name: isolation.z.gamma, start: 0.5}\n")
PY
  # CMA-ES for half the budget: the sweep's refinement alone converges in a few dozen.
  fit=("$work/sweep.csv" --building "$work/spec.yaml" --global-budget "$((budget / 2))")
fi
mpirun=(mpirun --allow-run-as-root --oversubscribe)
run() {  # label, command...
  local label=$1 file
  file=$(echo "$1" | tr -c 'A-Za-z0-9\n' '_')
  shift
  local start end
  start=$(date +%s.%N)
  "$@" "${fit[@]}" --budget "$budget" --json -q -o "$work/$file.yaml" >"$work/$file.json"
  end=$(date +%s.%N)
  /usr/bin/python3 - "$work/$file.json" "$label" "$start" "$end" <<'PY'
import json, sys
fit = json.load(open(sys.argv[1]))
wall = float(sys.argv[4]) - float(sys.argv[3])
print(f"| {sys.argv[2]} | {fit['evaluations']} | {wall:.2f} | {fit['evaluations'] / wall:.1f} "
      f"| {fit['objective']!r} |")
PY
}
same() {  # every configuration's objective, to the last digit
  if [ "$(awk -F'|' '/^\| [0-9m]/ { print $6 }' "$work/table" | sort -u | wc -l)" != 1 ]; then
    echo "the configurations disagree: a fit on ranks or threads must give one result" >&2
    exit 1
  fi
}
{
  echo "| configuration | simulations | wall s | simulations/s | objective |"
  echo "|---|---|---|---|---|"
  run "1 process, 1 thread" "$isolab" fit --threads 1
  run "mpirun -np 1" "${mpirun[@]}" -np 1 "$isolab" fit --threads 1
  run "mpirun -np $ranks" "${mpirun[@]}" -np "$ranks" "$isolab" fit --threads 1
  run "1 process, $ranks threads" "$isolab" fit --threads "$ranks"
} | tee "$work/table"
same
