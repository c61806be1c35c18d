#!/usr/bin/env bash
# The BNCS study of docs/bncs.md, end to end, from the measured data in shared/measured/bncs:
# the isolator's measured history of both motions (isolab shaketable), the isolation layer fitted
# to ICA50 as a BHM2 and as a Table 9-style THM1 assembly (isolab fit; writes the fitted files in
# models/bncs/), LAC100 predicted with each (isolab shaketable --predict) and the plots in
# docs/images/. With --diagnose also isolab diagnose on the ICA50 isolator history (about 2.5
# minutes on a 2-core machine; writes models/bncs/bncs_diagnosed.fitted.yaml) and the predictions
# of the diagnosed model.
# Usage: scripts/bncs_study.sh [--diagnose] [DATA_DIR]   (default ../shared/measured/bncs)
set -euo pipefail
cd "$(dirname "$0")/.."
diagnose=0
if [[ "${1:-}" == "--diagnose" ]]; then diagnose=1; shift; fi
data="${1:-../shared/measured/bncs}"
out=build/bncs
mkdir -p "$out"
for motion in ica50 lac100; do
  zcat "$data/bncs_$motion.csv.gz" > "$out/bncs_$motion.csv"
  build/isolab shaketable "$out/bncs_$motion.csv" --model models/bncs/bncs.yaml \
    --isolator "$out/${motion}_isolator.csv" -q
done
build/isolab fit "$out/ica50_isolator.csv" --model models/bncs/bhm2_spec.yaml --budget 6000 \
  -o models/bncs/bncs_bhm2.fitted.yaml -q > "$out/fit_bhm2.txt"
build/isolab fit "$out/ica50_isolator.csv" --model models/bncs/thm1_spec.yaml --budget 20000 \
  -o models/bncs/bncs_thm1.fitted.yaml -q > "$out/fit_thm1.txt"
for family in bhm2 thm1; do
  model=models/bncs/bncs.yaml
  [[ $family == thm1 ]] && model=models/bncs/bncs_thm1.yaml
  for motion in ica50 lac100; do
    build/isolab shaketable "$out/bncs_$motion.csv" --model "$model" --predict -q \
      --results "$out/${motion}_$family.h5" --comparison "$out/${motion}_${family}_comparison.csv" \
      > "$out/${motion}_${family}_prediction.txt"
  done
done
python3=/usr/bin/python3
"$python3" scripts/plot_shaketable.py loop "$out/ica50_isolator.csv" "$out/lac100_isolator.csv" \
  -o docs/images/bncs_isolator_loop.png
if [[ $diagnose == 1 ]]; then
  build/isolab diagnose "$out/ica50_isolator.csv" --base models/bncs/bhm2_spec.yaml \
    --out "$out/ica50_diagnosis" -q > "$out/ica50_diagnosis.txt"
  cp "$out/ica50_diagnosis.model.yaml" models/bncs/bncs_diagnosed.fitted.yaml
fi
overlays=("$out/lac100_thm1_comparison.csv")
if [[ -f models/bncs/bncs_diagnosed.fitted.yaml ]]; then
  for motion in ica50 lac100; do
    build/isolab shaketable "$out/bncs_$motion.csv" --model models/bncs/bncs_isolation_diagnosed.yaml \
      --predict -q --results "$out/${motion}_diagnosed.h5" \
      --comparison "$out/${motion}_diagnosed_comparison.csv" > "$out/${motion}_diagnosed_prediction.txt"
  done
  overlays+=("$out/lac100_diagnosed_comparison.csv")
fi
"$python3" scripts/plot_shaketable.py overlay "${overlays[@]}" \
  -o docs/images/bncs_lac100_prediction.png --title "LAC100 predicted from ICA50 fits"
head -n 20 "$out"/*_prediction.txt
