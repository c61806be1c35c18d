#!/usr/bin/python3
"""The figures of an `isolab design` report, from the files it wrote in its output folder.

    scripts/plot_design.py DIR [--metadata]

Writes into DIR, each a 300 dpi PNG with a vector PDF beside it (and, with --metadata, a JSON
file of its axes' labels, units and data ranges):
  design_spectra.png  the scaled suite's spectra (RotD100 of pairs), their mean and the target,
                      the scaling range shaded, T_M per bound and the governing period marked;
                      below, the mean over the target against the code's threshold
                      (design_spectra.csv, design_values.csv)
  design_loops.png    the worst bearing's force against displacement at each bound, along x and
                      y in plan, with its ELF secant to D_M (histories/runs/<bound>/*.h5,
                      design_bearings.csv)
  design_orbits.png   the bearings that move most and least, their displacement orbits per
                      bound, one colour per bearing, the design D_TM and the capacity as circles
  design_drifts.png   each story's design drift ratio per bound (the suite's mean or maximum,
                      design_parts.csv), against the limit
Then design.html (scripts/design_html.py): design.md with the figures embedded, one file.
Debian's python3-matplotlib and python3-h5py (scripts/setup.sh installs both).
"""

import argparse
import csv
import glob
import os
import sys

import design_html
from plot_common import import_modules, mark_reference, save, text, wrap_title

h5py, plt, np = import_modules()

BOUNDS = ("lower", "nominal", "upper")
COLOURS = {"lower": "tab:blue", "nominal": "tab:gray", "upper": "tab:red"}


def read_spectra(directory):
    with open(os.path.join(directory, "design_spectra.csv"), newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array([[float(v) for v in row] for row in rows[1:]])
    return header, data


def read_values(directory):
    """{(bound, quantity, statistic): value} of design_values.csv."""
    with open(os.path.join(directory, "design_values.csv"), newline="", encoding="utf-8") as f:
        return {(r["bound"], r["quantity"], r["statistic"]): float(r["value"])
                for r in csv.DictReader(f)}


def read_rows(directory, name):
    with open(os.path.join(directory, name), newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def plot_spectra(directory, metadata):
    """The scaled records, their mean and the target; below, the mean over the target inside the
    scaling range against the code's threshold (1 for ASCE 7-16, 0.9 for EN 1998-1). T_M of each
    bound and the governing period (where the ratio is least) marked on both."""
    header, data = read_spectra(directory)
    values = read_values(directory)
    fraction = values.get(("design", "target_fraction", "rule"), 1.0)
    pairs = values.get(("design", "directions", "model"), 1.0) > 1.5
    # EN 1998-1 (threshold 0.9) takes each component as a time history; ASCE 7-16 a pair's
    # RotD100.
    kind = ("components' " if fraction != 1.0 else "RotD100 ") if pairs else ""
    pga_governs = values.get(("design", "pga_governs", "rule"), 0.0) > 0.5
    period, in_range, target, mean = data[:, 0], data[:, 1] > 0.5, data[:, 2], data[:, -1]
    fig, (ax, ratio_ax) = plt.subplots(2, 1, figsize=(6.5, 5.6), sharex=True,
                                       gridspec_kw={"height_ratios": [3, 1.3]})
    for column in range(3, len(header) - 1):
        ax.plot(period, data[:, column], color="0.75", linewidth=0.6,
                label="each scaled record" if column == 3 else None)
    ax.plot(period, mean, color="tab:blue", linewidth=1.8, label="mean of the suite")
    ax.plot(period, target, color="black", linestyle="--", linewidth=1.4, label="target")
    if fraction != 1.0:
        ax.plot(period, fraction * target, color="black", linestyle=":", linewidth=1.2,
                label=f"{fraction:g} x target")
    low, high = period[in_range].min(), period[in_range].max()
    ratio = mean[in_range] / target[in_range]
    governing = period[in_range][np.argmin(ratio)]
    for axis in (ax, ratio_ax):
        mark_reference(axis.axvspan(low, high, color="tab:orange", alpha=0.12,
                                    label=f"scaling range {low:.2f} to {high:.2f} s"
                                    if axis is ax else None))
    for bound in BOUNDS:
        t_m = values.get((bound, "T_M", "elf"))
        if t_m is not None:
            mark_reference(ax.axvline(t_m, color=COLOURS[bound], linewidth=1.0,
                                      label=f"T_M {bound} {t_m:.2f} s"))
    if not pga_governs:
        mark_reference(ax.axvline(governing, color="tab:green", linestyle="-.", linewidth=1.0,
                                  label=f"governing {governing:.2f} s"))
    ax.set_xscale("log")
    ax.set_ylabel(f"{kind}Sa [g] (5 % damping)")
    ax.legend(loc="lower left", fontsize=7, ncol=2)
    ratio_ax.plot(period[in_range], ratio, color="tab:blue", linewidth=1.5,
                  label="mean / target in the range")
    mark_reference(ratio_ax.axhline(fraction, color="black", linestyle=":", linewidth=1.0,
                                    label=f"threshold {fraction:g}"))
    ratio_ax.set_xlabel("period T [s]")
    ratio_ax.set_ylabel("mean / target [-]")
    ratio_ax.legend(loc="upper left", fontsize=7)
    fig.suptitle(wrap_title(f"The scaled suite's {kind}spectra against the design target"
                            + (" (the mean PGA set the scale)" if pga_governs else ""), 6.5))
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
    """The record's name, from the run file's ("pair05_at90_x1.h5": pair05_at90)."""
    return os.path.basename(run.filename).rsplit("_x", 1)[0]


def case_of(run):
    """The eccentricity case the kept run ran, from its model file's name
    (four_story_plan_lower_ex+ey-.yaml)."""
    model = text(run.attrs.get("model_file", ""))
    for case in ("ex+ey+", "ex+ey-", "ex-ey+", "ex-ey-"):
        if model.endswith(f"_{case}.yaml"):
            return f"eccentricity {case}"
    return "no eccentricity"


def units_of(run):
    return text(run["isolator/displacement"].attrs["units"]), text(
        run["isolator/force"].attrs["units"])


def worst_bearings(run, count):
    """Indices of the `count` isolators of largest peak resultant displacement."""
    peaks = np.max(np.asarray(run["isolator/resultant"]), axis=0)
    return list(np.argsort(peaks)[::-1][:count])


def bearing_secants(directory):
    """{(bound, bearing): (D_M, k_eff)} from design_bearings.csv."""
    secants = {}
    for row in read_rows(directory, "design_bearings.csv"):
        keys = list(row)
        secants[(row["bound"], row["bearing"])] = (float(row[keys[2]]), float(row[keys[3]]))
    return secants


def plot_loops(directory, runs, metadata):
    """The worst bearing's loops, both components in plan (a panel each), each bound with its
    ELF secant k_eff through +-D_M (design_bearings.csv) and D_M marked."""
    any_run = next(iter(runs.values()))
    length, force = units_of(any_run)
    plan = "isolator/resultant" in any_run
    worst = worst_bearings(any_run, 1)[0] if plan else 0
    name = (text(any_run["isolator/resultant"].attrs["columns"][worst]) if plan
            else text(any_run["isolator/force"].attrs["columns"][0]))
    secants = bearing_secants(directory)
    directions = "xy" if plan else "x"
    fig, axes = plt.subplots(1, len(directions), figsize=(3.6 * len(directions) + 0.4, 4.4),
                             sharey=True)
    axes = np.atleast_1d(axes)
    for axis, (ax, direction) in enumerate(zip(axes, directions)):
        for bound, run in runs.items():
            u = np.asarray(run["isolator/displacement"])
            f = np.asarray(run["isolator/force"])
            if plan:
                u, f = u[:, 2 * worst + axis], f[:, 2 * worst + axis]
            else:
                u, f = u[:, 0], f[:, 0]
            ax.plot(u, f, color=COLOURS[bound], linewidth=0.6, label=f"{bound} bound")
            secant = secants.get((bound, name))
            if secant is not None:
                d_m, k_eff = secant
                mark_reference(ax.plot([-d_m, d_m], [-k_eff * d_m, k_eff * d_m],
                                       color=COLOURS[bound], linestyle="--", linewidth=1.0,
                                       marker="o", markersize=3,
                                       label=f"ELF secant to D_M {d_m:.0f} {length}")[0])
        ax.set_xlabel(f"displacement along {direction} [{length}]")
        ax.set_title(f"along {direction}", fontsize=9)
    axes[0].set_ylabel(f"force [{force}]")
    axes[-1].legend(loc="upper left", fontsize=6.5)
    fig.suptitle(wrap_title(f"{'Bearing ' if plan else ''}{name} at the three bounds: "
                            f"{record_of(any_run)}, {case_of(any_run)}",
                            3.6 * len(directions) + 0.4))
    fig.tight_layout()
    return save(plt, np, fig, os.path.join(directory, "design_loops.png"), metadata)


def design_circles(directory):
    """(D_TM, the least displacement capacity or None) of the design (model units)."""
    d_tm = read_values(directory).get(("design", "D_TM", "design"))
    capacities = [float(r["limit"]) for r in read_rows(directory, "design_checks.csv")
                  if r["check"].startswith("D_TM <= displacement capacity")
                  and r["limit"] not in ("", "nan")]
    return d_tm, (min(capacities) if capacities else None)


def plot_orbits(directory, runs, metadata):
    """None for a building in one direction, which has no orbits. The bearings that move most and
    least in the lower bound (the spread is the plan's twist), one colour each in every panel,
    with the design D_TM and the bearings' displacement capacity as circles."""
    if "isolator/resultant" not in next(iter(runs.values())):
        return None
    d_tm, capacity = design_circles(directory)
    first = runs.get("lower", next(iter(runs.values())))
    order = worst_bearings(first, len(first["isolator/resultant"].attrs["columns"]))
    chosen = [order[0], order[-1]] if len(order) > 1 else order
    names = [text(n) for n in first["isolator/resultant"].attrs["columns"]]
    styles = dict(zip(chosen, (("tab:purple", "-"), ("tab:green", "--"))))
    fig, axes = plt.subplots(1, len(runs), figsize=(2.5 * len(runs), 3.9), sharex=True,
                             sharey=True)
    axes = np.atleast_1d(axes)
    angle = np.linspace(0, 2 * np.pi, 181)
    for ax, (bound, run) in zip(axes, runs.items()):
        length, _ = units_of(run)
        u = np.asarray(run["isolator/displacement"])
        for i, role in zip(chosen, ("moves most", "moves least")):
            colour, style = styles[i]
            ax.plot(u[:, 2 * i], u[:, 2 * i + 1], linewidth=0.6, color=colour, linestyle=style,
                    label=f"{names[i]} ({role})")
        for radius, style, label in ((d_tm, "--", "design D_TM"), (capacity, ":", "capacity")):
            if radius:
                mark_reference(ax.plot(radius * np.cos(angle), radius * np.sin(angle),
                                       color="black", linestyle=style, linewidth=0.8,
                                       label=f"{label} {radius:.0f} {length}")[0])
        ax.set_aspect("equal", adjustable="box")
        ax.set_title(f"{bound} bound", fontsize=9)
        ax.set_xlabel(f"u_x [{length}]")
    axes[0].set_ylabel(f"u_y [{length}]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=7, frameon=False)
    fig.suptitle(wrap_title("Orbits of the bearings that move most and least, "
                            f"{record_of(first)}, {case_of(first)}", 2.5 * len(runs)))
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    return save(plt, np, fig, os.path.join(directory, "design_orbits.png"), metadata)


def plot_drifts(directory, runs, metadata):
    """None for a building without story heights, which has no drift ratios. Each story's design
    drift ratio (the suite's mean or maximum, design_parts.csv) per bound, against the limit."""
    rows = [r for r in read_rows(directory, "design_parts.csv")
            if r["quantity"] == "story_drift_ratio" and r["value"] not in ("nan", "")]
    if not rows:
        return None
    values = read_values(directory)
    records = len({r["record"] for r in read_rows(directory, "design_runs.csv")})
    statistic = "mean" if values.get(("design", "mean_of_suite", "rule"), 0.0) > 0.5 else "max"
    fig, ax = plt.subplots(figsize=(5.6, 4.2))
    largest = 0.0
    for bound in BOUNDS:
        mine = [r for r in rows if r["bound"] == bound and r["statistic"] == statistic]
        if not mine:
            continue
        ratios = [float(r["value"]) for r in mine]
        largest = max(largest, max(ratios))
        ax.plot(ratios, np.arange(1, len(ratios) + 1), marker="o", color=COLOURS[bound],
                label=f"{bound} bound")
    stories = [r["part"] for r in rows if r["bound"] == rows[0]["bound"]
               and r["statistic"] == statistic]
    limit = values.get(("design", "drift_limit", "limit"))
    title = "Story drift ratios, design values per bound"
    if limit is not None and limit <= 3 * largest:
        mark_reference(ax.axvline(limit, color="black", linestyle="--", linewidth=1.0,
                                  label=f"limit {limit:g} %"))
        ax.set_xlim(0, 1.1 * limit)
    else:
        # A limit far beyond the values would squeeze them into a sliver: said, not drawn.
        ax.set_xlim(0, 1.25 * largest)
        if limit is not None:
            title += f" (limit {limit:g} %, beyond the scale)"
    ax.set_xlabel(f"design story drift ratio, {'mean' if statistic == 'mean' else 'maximum'}"
                  f" of {records} records [%]")
    ax.set_ylabel("story [-]")
    ax.set_yticks(np.arange(1, len(stories) + 1), stories)
    ax.legend(loc="upper right", fontsize=8)
    fig.suptitle(wrap_title(title, 5.6))
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
    if os.path.isfile(os.path.join(arguments.directory, "design.md")):
        print(design_html.write_html(arguments.directory))


if __name__ == "__main__":
    main()
