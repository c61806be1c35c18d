#!/usr/bin/env bash
# Synthetic HDRB cyclic tests for `isolab fit`: the paper's Table 9 THM1
# system driven at 5, 30, 50, 70, 100, 120, 140, 160, 180 and 200 mm, three cycles at 0.5 Hz,
# written without noise and with 1 % Gaussian force noise (seed 1), in test,time,displacement,force
# CSV. Usage: scripts/generate_hdrb_tests.sh [OUTPUT_DIR]   (default build/hdrb)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/hdrb}"
mkdir -p "$out"
for noise in 0 0.01; do
  build/isolab cyclic models/paper/table9_thm1_system.yaml \
    -a 5,30,50,70,100,120,140,160,180,200 -T 2 -n 3 --steps-per-cycle 200 \
    --test-data "$out/hdrb_noise_${noise}.csv" --noise "$noise" --seed 1 > /dev/null
  echo "$out/hdrb_noise_${noise}.csv"
done
