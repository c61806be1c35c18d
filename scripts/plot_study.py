#!/usr/bin/python3
"""Bar charts of an `isolab compare` summary: each quantity per variant, mean and max over the
records, one panel per scale factor.

    scripts/plot_study.py SUMMARY.h5|SUMMARY.csv [-o DIR] [--metadata]

Writes DIR/study_<quantity>.png for each quantity and DIR/study_overview.png (every quantity,
every scale) into DIR (default: the summary's folder), each a 300 dpi PNG with a vector PDF
beside it (and, with --metadata, a JSON file of its axes' labels, units and data ranges). Reads the HDF5 summary with h5py or the
CSV with the standard library; both hold the same numbers (include/isolab/study/summary_file.h).
Debian's python3-matplotlib and python3-h5py (scripts/setup.sh installs both).
"""

import argparse
import csv
import math
import os
import re
import sys

from plot_common import import_modules, save, text, wrap_title

_, plt, np = import_modules()

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
    import h5py  # imported (or its absence reported) by import_modules

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


def axis_label(key, unit):
    """The quantity and its unit, as every axis of a report states them."""
    return f"{LABELS.get(key, key.replace('_', ' '))} [{unit}]"


def draw(axis, study, key, s, unit, label_y=True):
    """Mean as a solid bar, max as a lighter bar behind it, per variant."""
    positions = range(len(study.variants))
    means = [study.mean[key][v][s] for v in positions]
    maxima = [study.max[key][v][s] for v in positions]
    colours = ["tab:orange" if name == study.reference else "tab:blue" for name in study.variants]
    axis.bar(positions, [0 if math.isnan(m) else m for m in maxima], color=colours, alpha=0.3,
             width=0.7)
    axis.bar(positions, [0 if math.isnan(m) else m for m in means], color=colours, width=0.45)
    for v, mean in enumerate(means):
        if math.isnan(mean):
            axis.text(v, 0, "n/a", ha="center", va="bottom", fontsize=7, color="grey")
    axis.set_xticks(list(positions))
    axis.set_xticklabels(study.variants, rotation=30, ha="right", fontsize=7.5)
    axis.set_title(f"scale {study.scales[s]:g}")
    if label_y:
        axis.set_ylabel(wrap_title(axis_label(key, unit), 2.2, 9))
    axis.grid(axis="x", visible=False)


def figure_with_legend_row(width, down, across, sharey):
    """A figure whose first row holds the legend, outside every panel (inside one it covered a
    bar), and the panels below it: (figure, legend axes, down x across panels)."""
    figure = plt.figure(figsize=(width, 0.35 + 2.5 * down + 0.5), layout="constrained")
    grid = figure.add_gridspec(2, 1, height_ratios=[0.35, 2.5 * down])
    legend_axes = figure.add_subplot(grid[0])
    legend_axes.axis("off")
    axes = grid[1].subgridspec(down, across).subplots(squeeze=False, sharey=sharey)
    return figure, legend_axes, axes


def legend(legend_axes, study):
    from matplotlib.patches import Patch

    handles = [Patch(color="tab:blue", label="mean over records"),
               Patch(color="tab:blue", alpha=0.3, label="max over records"),
               Patch(color="tab:orange", label=f"reference: {study.reference}")]
    legend_axes.legend(handles=handles, loc="center", ncol=3, frameon=False)


def plot_quantity(study, key, unit, directory, metadata):
    panels = len(study.scales)
    width = max(4.2, 2.6 * panels + 0.8)
    figure, legend_axes, axes = figure_with_legend_row(width, 1, panels, True)
    for s in range(panels):
        draw(axes[0][s], study, key, s, unit, label_y=s == 0)
    figure.suptitle(wrap_title(LABELS.get(key, key).capitalize(), width))
    legend(legend_axes, study)
    return save(plt, np, figure, os.path.join(directory, f"study_{key}.png"), metadata)


def plot_overview(study, directory, metadata):
    quantities, scales = len(study.quantities), len(study.scales)
    # A panel per quantity and scale: quantities down, scales across; a single scale's panels in
    # a grid, not a one-column strip.
    across = scales if scales > 1 else min(3, quantities)
    down = quantities if scales > 1 else math.ceil(quantities / across)
    width = 2.5 * across + 0.9
    figure, legend_axes, axes = figure_with_legend_row(width, down, across, False)
    for q, (key, unit) in enumerate(study.quantities):
        for s in range(scales):
            row, column = (q, s) if scales > 1 else divmod(q, across)
            ax = axes[row][column]
            draw(ax, study, key, s, unit, label_y=column == 0 or scales == 1)
            if scales == 1:
                ax.set_title(wrap_title(LABELS.get(key, key), 2.3, 9.5))
    for k in range(quantities * scales, down * across):
        axes[k // across][k % across].set_visible(False)
    figure.suptitle(wrap_title(f"Mean and max over records of each variant"
                               f"{'' if scales > 1 else f', scale {study.scales[0]:g}'}", width))
    legend(legend_axes, study)
    return save(plt, np, figure, os.path.join(directory, "study_overview.png"), metadata)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("summary", nargs="?",
                        help="summary.h5 or summary.csv written by isolab compare")
    parser.add_argument("-o", "--output", help="folder for the PNG files (default: the summary's)")
    parser.add_argument("--metadata", action="store_true",
                        help="beside each figure, a JSON file of its axes: labels, units and "
                        "the range of the data drawn")
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
        print(plot_quantity(study, key, unit, directory, arguments.metadata))
    print(plot_overview(study, directory, arguments.metadata))


if __name__ == "__main__":
    main()
