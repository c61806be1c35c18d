#!/usr/bin/python3
"""The synthetic friction damper's characterisation campaign as cyclic test data (kip, in): ten
sinusoidal tests, 0.25 to 2 Hz and 0.5 to 1.5 in, seven cycles each from rest, sampled at 1024 Hz
(150,538 samples), through models/diagnosis/friction_damper.yaml (a friction damper with
backlash and asymmetric friction), its force channel carrying Gaussian noise of 0.02 kip through a
load cell's anti-alias filter (a 4th-order Butterworth low-pass at 50 Hz). With --decimate K,
every K-th sample: the same tests at a lower rate. tests/diagnosis/friction_damper_case.h draws
the same campaign in process (its noise from another generator, so not the same samples).

The forces come from isolab itself: each test's displacement history is a path that
isolab.cyclic(model, path=...) drives the model along.

Usage: PYTHONPATH=build/python scripts/generate_friction_damper.py OUT.csv [--decimate 8]
       [--seed 1]
"""
import argparse
import math
import os
import sys
import tempfile

import numpy as np

import isolab

PROTOCOL = [(4.0, 0.5), (4.0, 1.0), (4.0, 1.5), (2.0, 0.5), (2.0, 1.0), (2.0, 1.5), (1.0, 0.5),
            (1.0, 1.0), (0.5, 0.5), (0.5, 1.0)]
RATE, CYCLES, SIGMA, CUTOFF = 1024.0, 7, 0.02, 50.0


def butterworth(x, rate, cutoff):
    """4th-order Butterworth low-pass, two bilinear-transform biquads."""
    k = math.tan(math.pi * cutoff / rate)
    for q in (0.54119610, 1.30656296):
        norm = 1.0 / (1.0 + k / q + k * k)
        b0 = k * k * norm
        b1, b2 = 2 * b0, b0
        a1, a2 = 2 * (k * k - 1) * norm, (1 - k / q + k * k) * norm
        y = np.empty_like(x)
        x1 = x2 = y1 = y2 = 0.0
        for i, v in enumerate(x):
            out = b0 * v + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2
            x2, x1, y2, y1 = x1, v, y1, out
            y[i] = out
        x = y
    return x


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--decimate", type=int, default=1)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    model = os.path.join(here, "..", "models", "diagnosis", "friction_damper.yaml")
    random = np.random.default_rng(args.seed)
    rows = ["# units: force kip, length in", "test,time,displacement,force"]
    with tempfile.TemporaryDirectory() as folder:
        for period, amplitude in PROTOCOL:
            name = f"f={1 / period:g}_u={amplitude:g}"
            n = round(CYCLES * period * RATE)
            t = np.arange(n + 1) / RATE
            u = amplitude * np.sin(2 * np.pi * np.arange(n + 1) / (period * RATE))
            path = os.path.join(folder, "path.csv")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write("# units: force kip, length in\ntime,displacement\n")
                handle.writelines(f"{a:.9f},{b:.12g}\n" for a, b in zip(t, u))
            force = isolab.cyclic(model, path=path)[0]["force"]
            settle = 4096
            noise = butterworth(random.standard_normal(n + 1 + settle), RATE, CUTOFF)[settle:]
            noise *= SIGMA / np.sqrt(np.mean(noise ** 2))
            for k in range(0, n + 1, args.decimate):
                rows.append(f"{name},{t[k]:.9f},{u[k]:.12g},{force[k] + noise[k]:.9g}")
    with open(args.output, "w", encoding="utf-8") as handle:
        handle.write("\n".join(rows) + "\n")
    print(f"{args.output}: {len(rows) - 2} samples", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
