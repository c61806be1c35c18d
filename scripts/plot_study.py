#!/usr/bin/python3
"""Bar charts of an `isolab compare` summary: each quantity per variant, mean and max over the
records, one panel per scale factor.

    scripts/plot_study.py SUMMARY.h5|SUMMARY.csv [-o DIR]

Writes DIR/study_<quantity>.png for each quantity and DIR/study_overview.png (every quantity,
every scale) into DIR (default: the summary's folder). Reads the HDF5 summary with h5py or the
CSV with the standard library; both hold the same numbers (include/isolab/study/summary_file.h).
Debian's python3-matplotlib and python3-h5py (scripts/setup.sh installs both).
"""

import argparse
import csv
import math
import os
import re
import sys

from plot_common import text

import matplotlib

matplotlib.use("Agg")  # files only: no display on build machines
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {
    "isolator_displacement": "peak isolator displacement",
    "base_shear": "peak base shear",
    "story_drift_ratio": "peak story drift ratio",
    "floor_acceleration": "peak floor absolute acceleration",
    "residual_isolator_displacement": "residual isolator displacement",
    "resultant_isolator_displacement": "peak resultant isolator displacement",
    "resultant_base_shear": "peak resultant base shear",
    "floor_rotation": "peak floor rotation",
    "torsional_amplification": "torsional amplification",
}


class Study:
    """variants, scales, reference, quantities [(key, unit)], mean/max[key][variant][scale]."""

    def __init__(self):
        self.variants, self.scales, self.quantities = [], [], []
        self.reference = ""
        self.mean, self.max = {}, {}


def read_hdf5(path):
    import h5py

    study = Study()
    with h5py.File(path, "r") as f:
        study.variants = [text(v) for v in f["variants"][()]]
        study.scales = [float(s) for s in f["scales"][()]]
        study.reference = text(f.attrs["reference"])
        order = [k for k in LABELS if k in f["mean"]] + [k for k in f["mean"] if k not in LABELS]
        for key in order:
            study.quantities.append((key, text(f["mean"][key].attrs["units"])))
            study.mean[key] = f["mean"][key][()].tolist()
            study.max[key] = f["max"][key][()].tolist()
    return study


def number(field):
    return float(field) if field != "" else math.nan


def read_csv(path):
    study = Study()
    with open(path, newline="") as stream:
        rows = list(csv.reader(stream))
    header = rows[0]
    columns = []
    for index, name in enumerate(header):
        match = re.fullmatch(r"(\w+) \[(.*)\]", name)
        if match:
            columns.append((index, match.group(1), match.group(2)))
    study.quantities = [(key, unit) for _, key, unit in columns]
    statistics = [row for row in rows[1:] if row[1] in ("mean", "max")]
    for row in rows[1:]:
        if row[0] not in study.variants:
            study.variants.append(row[0])
        scale = float(row[2])
        if scale not in study.scales:
            study.scales.append(scale)
    for _, key, _ in columns:
        study.mean[key] = [[math.nan] * len(study.scales) for _ in study.variants]
        study.max[key] = [[math.nan] * len(study.scales) for _ in study.variants]
    ratio_column = header.index("ratio " + columns[0][1])
    for row in statistics:
        v, s = study.variants.index(row[0]), study.scales.index(float(row[2]))
        target = study.mean if row[1] == "mean" else study.max
        for index, key, _ in columns:
            target[key][v][s] = number(row[index])
        # A CSV has no metadata: the reference is the first variant whose mean is its own ratio
        # base, ratio exactly 1 (value / value).
        if row[1] == "mean" and row[ratio_column] == "1" and not study.reference:
            study.reference = row[0]
    return study


def draw(axis, study, key, s, unit):
    """Mean as a solid bar, max as a lighter bar behind it, per variant."""
    positions = range(len(study.variants))
    means = [study.mean[key][v][s] for v in positions]
    maxima = [study.max[key][v][s] for v in positions]
    colours = ["tab:orange" if name == study.reference else "tab:blue" for name in study.variants]
    axis.bar(positions, [0 if math.isnan(m) else m for m in maxima], color=colours, alpha=0.3,
             width=0.7, label="max over records")
    axis.bar(positions, [0 if math.isnan(m) else m for m in means], color=colours, width=0.45,
             label="mean over records")
    for v, mean in enumerate(means):
        if math.isnan(mean):
            axis.text(v, 0, "n/a", ha="center", va="bottom", fontsize=8, color="grey")
    axis.set_xticks(list(positions))
    axis.set_xticklabels(study.variants, rotation=30, ha="right", fontsize=8)
    axis.set_title(f"scale {study.scales[s]:g}", fontsize=9)
    axis.set_ylabel(f"[{unit}]", fontsize=8)
    axis.grid(axis="y", alpha=0.3)


def plot_quantity(study, key, unit, directory):
    figure, axes = plt.subplots(1, len(study.scales), figsize=(3.2 * len(study.scales), 3.6),
                                sharey=True, squeeze=False)
    for s in range(len(study.scales)):
        draw(axes[0][s], study, key, s, unit)
    axes[0][0].legend(fontsize=7, loc="upper left")
    figure.suptitle(f"{LABELS.get(key, key)} (orange: reference {study.reference})", fontsize=10)
    figure.tight_layout()
    path = os.path.join(directory, f"study_{key}.png")
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path


def plot_overview(study, directory):
    rows, columns = len(study.quantities), len(study.scales)
    figure, axes = plt.subplots(rows, columns, figsize=(3.0 * columns, 2.6 * rows),
                                squeeze=False)
    for q, (key, unit) in enumerate(study.quantities):
        for s in range(columns):
            draw(axes[q][s], study, key, s, unit)
            if s == 0:
                axes[q][s].set_ylabel(f"{LABELS.get(key, key)}\n[{unit}]", fontsize=8)
            if q < rows - 1:
                axes[q][s].set_xticklabels([])
    axes[0][0].legend(fontsize=7, loc="upper left")
    figure.suptitle(f"mean (solid) and max (light) over records; orange: reference "
                    f"{study.reference}", fontsize=10)
    figure.tight_layout()
    path = os.path.join(directory, "study_overview.png")
    figure.savefig(path, dpi=100)
    plt.close(figure)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("summary", nargs="?",
                        help="summary.h5 or summary.csv written by isolab compare")
    parser.add_argument("-o", "--output", help="folder for the PNG files (default: the summary's)")
    parser.add_argument("--check", action="store_true",
                        help="only check that matplotlib and h5py import (isolab compare --plot "
                        "calls it before the runs)")
    arguments = parser.parse_args()
    if arguments.check:
        import h5py  # noqa: F401
        return
    if not arguments.summary:
        parser.error("the summary file is required")
    if not os.path.isfile(arguments.summary):
        sys.exit(f"plot_study.py: {arguments.summary}: no such file")
    study = read_csv(arguments.summary) if arguments.summary.endswith(".csv") else read_hdf5(
        arguments.summary)
    directory = arguments.output or os.path.dirname(os.path.abspath(arguments.summary))
    os.makedirs(directory, exist_ok=True)
    for key, unit in study.quantities:
        print(plot_quantity(study, key, unit, directory))
    print(plot_overview(study, directory))


if __name__ == "__main__":
    main()
