#!/usr/bin/python3
"""The figures of an `isolab design` report, from the files it wrote in its output folder.

    scripts/plot_design.py DIR [--metadata]

Writes into DIR, each a 300 dpi PNG with a vector PDF beside it (and, with --metadata, a JSON
file of its axes' labels, units and data ranges):
  design_spectra.png  the scaled suite's spectra, their mean and the target, the scaling range
                      shaded (design_spectra.csv)
  design_loops.png    the worst bearing's force against displacement along x at each bound
                      (histories/runs/<bound>/*.h5)
  design_orbits.png   the four bearings that move most, their displacement orbits, per bound
  design_drifts.png   each story's peak drift ratio per bound, against the limit
                      (design_values.csv)
Debian's python3-matplotlib and python3-h5py (scripts/setup.sh installs both).
"""

import argparse
import csv
import glob
import os
import sys

from plot_common import import_modules, save, text, wrap_title

h5py, plt, np = import_modules()

BOUNDS = ("lower", "nominal", "upper")
COLOURS = {"lower": "tab:blue", "nominal": "tab:gray", "upper": "tab:red"}


def read_spectra(directory):
    with open(os.path.join(directory, "design_spectra.csv"), newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array([[float(v) for v in row] for row in rows[1:]])
    return header, data


def plot_spectra(directory, metadata):
    header, data = read_spectra(directory)
    period, in_range, target, mean = data[:, 0], data[:, 1] > 0.5, data[:, 2], data[:, -1]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for column in range(3, len(header) - 1):
        ax.plot(period, data[:, column], color="0.7", linewidth=0.6,
                label="each scaled record" if column == 3 else None)
    ax.plot(period, mean, color="tab:blue", linewidth=1.8, label="mean of the suite")
    ax.plot(period, target, color="black", linestyle="--", linewidth=1.4, label="target")
    low, high = period[in_range].min(), period[in_range].max()
    ax.axvspan(low, high, color="tab:orange", alpha=0.15,
               label=f"scaling range {low:.2f} to {high:.2f} s")
    ax.set_xscale("log")
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("spectral acceleration Sa [g] (5 % damping)")
    ax.legend(loc="lower left")
    fig.suptitle(wrap_title("The scaled suite's spectra against the design target", 6.5))
    fig.tight_layout()
    return save(plt, np, fig, os.path.join(directory, "design_spectra.png"), metadata)


def histories(directory):
    """{bound: open h5py.File} of the histories the design kept."""
    files = {}
    for bound in BOUNDS:
        found = sorted(glob.glob(os.path.join(directory, "histories", "runs", bound, "*.h5")))
        if found:
            files[bound] = h5py.File(found[0], "r")
    if not files:
        sys.exit(f"plot_design.py: {directory}/histories/runs holds no run")
    return files


def record_of(run):
    """The record's name, from the run file's ("pair05_x1.h5": pair05)."""
    return os.path.basename(run.filename).rsplit("_x", 1)[0]


def units_of(run):
    return text(run["isolator/displacement"].attrs["units"]), text(
        run["isolator/force"].attrs["units"])


def worst_bearings(run, count):
    """Indices of the `count` isolators of largest peak resultant displacement."""
    peaks = np.max(np.asarray(run["isolator/resultant"]), axis=0)
    return list(np.argsort(peaks)[::-1][:count])


def plot_loops(directory, runs, metadata):
    fig, ax = plt.subplots(figsize=(6.5, 4.4))
    any_run = next(iter(runs.values()))
    length, force = units_of(any_run)
    plan = "isolator/resultant" in any_run
    worst = worst_bearings(any_run, 1)[0] if plan else 0
    name = (text(any_run["isolator/resultant"].attrs["columns"][worst]) if plan
            else "the isolation layer")
    # In plan, the bearing's direction of larger travel.
    axis = 0
    if plan:
        u = np.asarray(any_run["isolator/displacement"])
        axis = int(np.max(np.abs(u[:, 2 * worst + 1])) > np.max(np.abs(u[:, 2 * worst])))
    direction = "xy"[axis]
    for bound, run in runs.items():
        u = np.asarray(run["isolator/displacement"])
        f = np.asarray(run["isolator/force"])
        if plan:
            u, f = u[:, 2 * worst + axis], f[:, 2 * worst + axis]
        ax.plot(u, f, color=COLOURS[bound], linewidth=0.7, label=f"{bound} bound")
    ax.set_xlabel(f"displacement along {direction} [{length}]")
    ax.set_ylabel(f"force along {direction} [{force}]")
    ax.legend(loc="upper left")
    fig.suptitle(wrap_title(f"{'Bearing ' if plan else ''}{name} at the three bounds, "
                            f"{record_of(any_run)}", 6.5))
    fig.tight_layout()
    return save(plt, np, fig, os.path.join(directory, "design_loops.png"), metadata)


def plot_orbits(directory, runs, metadata):
    """None for a building in one direction, which has no orbits."""
    if "isolator/resultant" not in next(iter(runs.values())):
        return None
    fig, axes = plt.subplots(1, len(runs), figsize=(2.4 * len(runs), 4.4), sharex=True,
                             sharey=True)
    axes = np.atleast_1d(axes)
    for ax, (bound, run) in zip(axes, runs.items()):
        length, _ = units_of(run)
        names = [text(n) for n in run["isolator/resultant"].attrs["columns"]]
        u = np.asarray(run["isolator/displacement"])
        for i in worst_bearings(run, 4):
            ax.plot(u[:, 2 * i], u[:, 2 * i + 1], linewidth=0.5, label=names[i])
        ax.set_aspect("equal", adjustable="box")
        ax.set_title(f"{bound} bound")
        ax.set_xlabel(f"u_x [{length}]")
        ax.legend(loc="lower right", fontsize=6)
    axes[0].set_ylabel(f"u_y [{length}]")
    fig.suptitle(wrap_title("Orbits of the four bearings that move most, "
                            f"{record_of(next(iter(runs.values())))}", 2.4 * len(runs)))
    fig.tight_layout()
    return save(plt, np, fig, os.path.join(directory, "design_orbits.png"), metadata)


def drift_limit(directory):
    """The design's story drift limit (%), from design_values.csv."""
    with open(os.path.join(directory, "design_values.csv"), newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["quantity"] == "drift_limit":
                return float(row["value"])
    return None


def plot_drifts(directory, runs, metadata):
    """None for a building without story heights, which has no drift ratios."""
    if "story/drift_ratio" not in next(iter(runs.values())):
        return None
    fig, ax = plt.subplots(figsize=(5.0, 4.2))
    for bound, run in runs.items():
        ratio = np.abs(np.asarray(run["story/drift_ratio"]).reshape(len(run["time"]), -1))
        peaks = np.max(ratio, axis=0)
        columns = [text(n) for n in run["story/drift_ratio"].attrs["columns"]]
        stories = list(dict.fromkeys(c.rsplit(".", 1)[0] for c in columns))  # in order
        per_story = [max(peaks[i] for i, c in enumerate(columns) if c.rsplit(".", 1)[0] == s)
                     for s in stories]
        levels = np.arange(1, len(stories) + 1)
        ax.plot(per_story, levels, marker="o", color=COLOURS[bound], label=f"{bound} bound")
    limit = drift_limit(directory)
    if limit is not None:
        ax.axvline(limit, color="black", linestyle="--", linewidth=1.0, label=f"limit {limit:g} %")
    ax.set_xlabel("peak story drift ratio [%]")
    ax.set_ylabel("story [-]")
    ax.set_yticks(levels)
    ax.set_xlim(left=0)
    ax.legend(loc="lower right")
    fig.suptitle(wrap_title(f"Peak story drift ratios, {record_of(next(iter(runs.values())))}",
                            5.0))
    fig.tight_layout()
    return save(plt, np, fig, os.path.join(directory, "design_drifts.png"), metadata)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", nargs="?", help="the output folder of isolab design")
    parser.add_argument("--metadata", action="store_true",
                        help="beside each figure, a JSON file of its axes: labels, units and "
                        "the range of the data drawn")
    parser.add_argument("--check", action="store_true",
                        help="only check that matplotlib and h5py import (isolab design calls "
                        "it before the runs)")
    arguments = parser.parse_args()
    if arguments.check:
        return
    if not arguments.directory or not os.path.isdir(arguments.directory):
        parser.error("the design's output folder is required")
    print(plot_spectra(arguments.directory, arguments.metadata))
    runs = histories(arguments.directory)
    print(plot_loops(arguments.directory, runs, arguments.metadata))
    orbits = plot_orbits(arguments.directory, runs, arguments.metadata)
    if orbits:
        print(orbits)
    drifts = plot_drifts(arguments.directory, runs, arguments.metadata)
    if drifts:
        print(drifts)


if __name__ == "__main__":
    main()
