#!/usr/bin/env python3
"""Plot of `isolab diagnose`'s residual (the OUT.residual.csv it writes): the loops of the test
with the largest amplitude, measured against the base and final models, and the final residual
against displacement for every test, coloured by the direction of motion, in units of each
test's noise. A residual that is noise lies in a band of +-2 about zero; an offset between the
two directions is a strength that differs by direction, a step after each reversal a clearance.

Usage: plot_diagnosis.py RESIDUAL.csv -o residual.png [--title TEXT]
       plot_diagnosis.py --check   (exits 0 when the plotting stack imports)
"""
import argparse
import sys

from plot_common import import_modules


def read(path):
    with open(path, encoding="utf-8") as handle:
        lines = handle.read().splitlines()
    units = {"force": "kN", "length": "mm"}
    for line in lines:
        if line.startswith("#") and "units" in line and ":" in line:
            for part in line.split(":", 1)[1].split(","):
                words = part.split()
                if len(words) == 2:
                    units[words[0].lower()] = words[1]
    rows = [line.split(",") for line in lines if line and not line.startswith("#")]
    header = rows[0]
    columns = {name: [] for name in header}
    for row in rows[1:]:
        for name, value in zip(header, row):
            columns[name].append(value)
    return columns, units


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("residual", nargs="?")
    parser.add_argument("-o", "--output")
    parser.add_argument("--title", default="")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    _, plt, np = import_modules()
    if args.check:
        return 0
    if not args.residual or not args.output:
        parser.error("RESIDUAL.csv and -o are required")
    columns, units = read(args.residual)
    tests = np.array(columns["test"])
    number = {name: np.array(columns[name], dtype=float)
              for name in columns if name != "test"}
    force, length = units["force"], units["length"]

    figure, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    # The test with the largest displacement.
    names = list(dict.fromkeys(tests))
    widest = max(names, key=lambda n: np.max(np.abs(number["displacement"][tests == n])))
    chosen = tests == widest
    u = number["displacement"][chosen]
    axes[0].plot(u, number["measured"][chosen], color="0.55", linewidth=1.2, label="measured")
    axes[0].plot(u, number["base"][chosen], "--", color="tab:orange", linewidth=0.9,
                 label="base model")
    axes[0].plot(u, number["final"][chosen], color="tab:blue", linewidth=0.9,
                 label="final model")
    axes[0].set_xlabel(f"displacement [{length}]")
    axes[0].set_ylabel(f"force [{force}]")
    axes[0].set_title(f"Loops of test {widest}", fontsize=10)
    axes[0].grid(True, linewidth=0.3)
    axes[0].legend(fontsize=8)

    noise = np.where(number["noise"] > 0, number["noise"], 1.0)
    scaled = number["residual"] / noise
    # At most 20,000 points, drawn in a random order so neither direction hides the other.
    order = np.random.default_rng(1).permutation(len(scaled))[:20000]
    moving_up = number["velocity"][order] > 0
    axes[1].scatter(number["displacement"][order], scaled[order], s=1.0, linewidths=0,
                    c=np.where(moving_up, "tab:red", "tab:blue"))
    axes[1].plot([], [], ".", markersize=5, color="tab:red", label="moving + (v > 0)")
    axes[1].plot([], [], ".", markersize=5, color="tab:blue", label="moving - (v < 0)")
    axes[1].axhspan(-2, 2, color="0.85", zorder=0, label="+-2 x noise")
    axes[1].set_xlabel(f"displacement [{length}]")
    axes[1].set_ylabel("final residual / noise [-]")
    axes[1].set_title("Final residual, every test", fontsize=10)
    axes[1].grid(True, linewidth=0.3)
    axes[1].legend(fontsize=8)
    if args.title:
        figure.suptitle(args.title, fontsize=11)
    figure.tight_layout()
    figure.savefig(args.output, dpi=130)
    return 0


if __name__ == "__main__":
    sys.exit(main())
