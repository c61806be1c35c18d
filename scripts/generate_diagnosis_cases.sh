#!/usr/bin/env bash
# Cyclic test data with hidden effects for `isolab diagnose`: every truth in models/diagnosis/
# (the bilinear base plus one effect, the base alone, two effects at once, and the real devices'
# asymmetric strength and backlash) driven at 10, 25, 50, 100, 150 and 200 mm, at periods 2 s and
# 0.5 s, three cycles of
# 200 samples, with 1 % Gaussian force noise and a fixed seed per case, written as
# test,time,displacement,force CSV. tests/diagnosis/hidden_effect_cases.h draws the same data in
# process; keep the two in step.
# Campaigns on one specimen: the degradation and the rate truths
# driven through the same twelve tests one after another on one specimen (isolab cyclic
# --sequential; each test starts from the state the previous left), written with the
# "# specimen: one, in order" header as campaign_<truth>.csv; tests/diagnosis draws them in
# process with seeds 21 and 22.
# Usage: scripts/generate_diagnosis_cases.sh [OUTPUT_DIR]   (default build/diagnosis)
# ISOLAB names the binary (default build/isolab; scripts/doc_tables/diagnosis_cases.py passes the
# one it checks the docs with).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/diagnosis}"
isolab="${ISOLAB:-build/isolab}"
mkdir -p "$out"
seed=11
for truth in null rate_dependence amplitude_dependent_dissipation large_amplitude_hardening \
             cyclic_degradation two_effects asymmetric_strength backlash; do
  "$isolab" cyclic "models/diagnosis/$truth.yaml" -a 10,25,50,100,150,200 -T 2,0.5 -n 3 \
    --steps-per-cycle 200 --test-data "$out/$truth.csv" --noise 0.01 --seed "$seed" > /dev/null
  echo "$out/$truth.csv"
  seed=$((seed + 1))
done
seed=21
for truth in cyclic_degradation rate_dependence; do
  "$isolab" cyclic "models/diagnosis/$truth.yaml" -a 10,25,50,100,150,200 -T 2,0.5 -n 3 \
    --steps-per-cycle 200 --sequential --test-data "$out/campaign_$truth.csv" --noise 0.01 \
    --seed "$seed" > /dev/null
  echo "$out/campaign_$truth.csv"
  seed=$((seed + 1))
done
