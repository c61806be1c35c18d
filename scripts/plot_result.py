#!/usr/bin/python3
"""Figures of an `isolab run` result (HDF5; layout in include/isolab/analysis/results_file.h).

    scripts/plot_result.py RESULT.h5 [-o DIR] [-q] [--metadata]

writes, named after the result file's stem, each as a 300 dpi PNG and a vector PDF (and, with
--metadata, a JSON file of its axes' labels, units and data ranges):
    <stem>_overview.png    the isolator's loop and its displacement history, the free vibration
                           after the excitation shaded (isolated models only); for a building in
                           plan, each isolator's orbit (x against y), the resultant of its
                           displacement against time and each level's rotation against time
    <stem>_hysteresis.png  isolator force against isolator displacement: total and each component
    <stem>_histories.png   displacement and absolute acceleration (in g) of the isolator (base) and
                           roof
    <stem>_envelopes.png   peaks over height: displacement, story drift, absolute acceleration,
                           story shear (buildings only)
    <stem>_energy.png      input energy against kinetic + damping + elastic + hysteretic, stacked
A building in plan's histories and envelopes are of resultants |(x, y)|, its hysteresis each
isolator's x and y loops. Panels that a model does not have (no isolator, no stories) are left
out. Runs on Debian's
/usr/bin/python3 with python3-matplotlib and python3-h5py (scripts/setup.sh installs them);
`--check` only tests that they import (isolab run --plot calls it before the analysis).
"""
import argparse
import math
import os
import sys

from plot_common import g_per, import_modules, mark_reference, save, short_name, text, wrap_title


def units_of(dataset):
    return text(dataset.attrs.get("units", ""))


def step_profile(values):
    """A per-story quantity as a staircase over levels: story s spans levels s to s + 1."""
    xs, ys = [], []
    for story, value in enumerate(values):
        xs += [value, value]
        ys += [story, story + 1]
    return xs, ys


def columns_of(dataset):
    return [text(c) for c in dataset.attrs.get("columns", [])]


def resultants(np, values, two):
    """Pairs of columns (x, y) as their resultants |(x, y)| in plan; the columns as they are in
    one direction."""
    if not two:
        return values
    return np.hypot(values[:, 0::2], values[:, 1::2])


class Result:
    """The datasets plot_result needs, and where the isolator and roof are. In plan (`two`), every
    translation has an x and a y column, kept as their resultant."""

    def __init__(self, h5py, np, path):
        with h5py.File(path, "r") as f:
            self.time = f["time"][:]
            self.time_unit = units_of(f["time"])
            self.two = any(c.endswith(".y") for c in columns_of(f["displacement"]))
            self.displacement = resultants(np, f["displacement"][:], self.two)
            self.length = units_of(f["displacement"])
            self.relative_acceleration = resultants(np, f["acceleration"][:], self.two)
            self.absolute_acceleration = resultants(np, f["absolute_acceleration"][:], self.two)
            self.acceleration_unit = units_of(f["absolute_acceleration"])
            ground = f["ground_acceleration"][:] if "ground_acceleration" in f else None
            if ground is not None and ground.ndim == 2:
                ground = np.hypot(ground[:, 0], ground[:, 1])
            self.ground = ground
            self.rotation = f["rotation"][:] if "rotation" in f else None
            self.level_names = [c[:-2] for c in columns_of(f["displacement"])[0::2]] \
                if self.two else columns_of(f["displacement"])
            self.isolated = "isolator" in f
            if self.isolated:
                g = f["isolator"]
                self.isolator_displacement = g["displacement"][:]
                self.isolator_force = g["force"][:]
                self.force_unit = units_of(g["force"])
                self.component_force = g["component_force"][:]
                self.component_names = [text(n) for n in g["component_force"].attrs["columns"]]
                self.isolator_names = [text(n) for n in g["resultant"].attrs["columns"]] \
                    if self.two else ["isolator"]
                if self.two:
                    self.isolator_resultant = g["resultant"][:].reshape(len(self.time), -1)
            self.stories = 0
            if "story" in f:
                self.drift = resultants(np, f["story/drift"][:], self.two)
                self.shear = resultants(np, f["story/shear"][:], self.two)
                self.force_unit = units_of(f["story/shear"])
                self.stories = self.drift.shape[1]
            self.energy = {name: f["energy/" + name][:]
                           for name in ("input", "kinetic", "damping", "elastic", "hysteretic")}
            self.energy_unit = units_of(f["energy/input"])
            self.excitation_end = float(f.attrs.get("excitation_end", self.time[-1]))
            self.residual = float(f.attrs.get("residual_isolator_displacement", math.nan))
            self.title = short_name(text(f.attrs.get("model_file", path)))
            record = text(f.attrs.get("record", ""))
            if record:
                self.title += f" under {short_name(record)}"
            if text(f.attrs.get("termination", "completed")) != "completed":
                self.title += " (run stopped early)"
        levels = self.displacement.shape[1]
        # Level 0 is the base when isolated, then the floors; an SDOF has one level.
        self.base_dof = 0 if (self.isolated and levels == self.stories + 1 and self.stories) \
            else None
        self.roof_dof = levels - 1
        self.ground_acceleration = self.ground if self.ground is not None else \
            self.absolute_acceleration[:, 0] - self.relative_acceleration[:, 0]


def acceleration_in_g(r, values):
    """Accelerations in g where the unit is a length per s^2 (engineers read floors in g)."""
    g = g_per(r.acceleration_unit)
    return (values / g, "g") if g else (values, r.acceleration_unit)


def plot_overview(plt, np, r, path, metadata):
    """The isolator's loop beside its displacement history: the run at a glance."""
    fig, (loop, history) = plt.subplots(1, 2, figsize=(7.2, 3.2), layout="constrained",
                                        gridspec_kw={"width_ratios": [1, 1.6]})
    loop.plot(r.isolator_displacement, r.isolator_force, lw=0.6, color="C0")
    loop.set_xlabel(f"isolator displacement [{r.length}]")
    loop.set_ylabel(f"isolator force [{r.force_unit}]")
    loop.set_title("isolator hysteresis")
    history.plot(r.time, r.isolator_displacement, lw=0.6, color="C0", label="isolator")
    if r.excitation_end < r.time[-1]:
        mark_reference(history.axvspan(r.excitation_end, r.time[-1], color="0.9", zorder=0,
                                       label="free vibration"))
    if not math.isnan(r.residual):
        mark_reference(history.axhline(r.residual, color="C3", lw=0.8, ls="--",
                                       label=f"residual {r.residual:.3g} {r.length}"))
    history.legend(loc="best")
    history.set_xlabel(f"time [{r.time_unit}]")
    history.set_ylabel(f"isolator displacement [{r.length}]")
    history.set_title("isolator displacement")
    for ax in (loop, history):
        mark_reference(ax.axhline(0, color="0.6", lw=0.5))
    fig.suptitle(wrap_title(r.title, 7.2))
    return save(plt, np, fig, path, metadata)


def plot_plan_overview(plt, np, r, path, metadata):
    """A building in plan at a glance: where each isolator went (its orbit), how far (the
    resultant against time) and how the levels twisted."""
    panels = 3 if r.rotation is not None else 2
    fig, axes = plt.subplots(1, panels, figsize=(10.8, 3.4), layout="constrained",
                             gridspec_kw={"width_ratios": [1.0] + [1.3] * (panels - 1)})
    orbit, history = axes[0], axes[1]
    for i, name in enumerate(r.isolator_names):
        orbit.plot(r.isolator_displacement[:, 2 * i], r.isolator_displacement[:, 2 * i + 1],
                   lw=0.5, label=name)
        history.plot(r.time, r.isolator_resultant[:, i], lw=0.6, label=name)
    orbit.set_aspect("equal", adjustable="datalim")
    orbit.set_xlabel(f"isolator displacement x [{r.length}]")
    orbit.set_ylabel(f"isolator displacement y [{r.length}]")
    orbit.set_title("isolator orbits")
    mark_reference(orbit.axhline(0, color="0.6", lw=0.5), orbit.axvline(0, color="0.6", lw=0.5))
    if r.excitation_end < r.time[-1]:
        mark_reference(history.axvspan(r.excitation_end, r.time[-1], color="0.9", zorder=0,
                                       label="free vibration"))
    history.legend(loc="upper right", fontsize=7, ncols=2)
    history.set_xlabel(f"time [{r.time_unit}]")
    history.set_ylabel(f"resultant displacement [{r.length}]")
    history.set_title("isolator displacement |(x, y)|")
    if r.rotation is not None:
        twist = axes[2]
        for k, name in enumerate(r.level_names):
            twist.plot(r.time, 1000.0 * r.rotation[:, k], lw=0.5, label=name)
        twist.legend(loc="upper right", fontsize=7, ncols=2)
        twist.set_xlabel(f"time [{r.time_unit}]")
        twist.set_ylabel("rotation [mrad]")
        twist.set_title("level rotations")
        mark_reference(twist.axhline(0, color="0.6", lw=0.5))
    fig.suptitle(wrap_title(r.title, 10.8))
    return save(plt, np, fig, path, metadata)


def plot_plan_hysteresis(plt, np, r, path, metadata):
    """Each isolator's force against its displacement, along x and along y."""
    fig, axes = plt.subplots(1, 2, figsize=(7.2, 3.4), layout="constrained", sharey=True)
    for d, axis in enumerate("xy"):
        ax = axes[d]
        for i, name in enumerate(r.isolator_names):
            ax.plot(r.isolator_displacement[:, 2 * i + d], r.isolator_force[:, 2 * i + d], lw=0.5,
                    label=name)
        ax.set_xlabel(f"isolator displacement {axis} [{r.length}]")
        ax.set_ylabel(f"isolator force {axis} [{r.force_unit}]")
        ax.set_title(f"along {axis}")
        mark_reference(ax.axhline(0, color="0.6", lw=0.5), ax.axvline(0, color="0.6", lw=0.5))
    axes[1].tick_params(labelleft=True)
    axes[0].legend(loc="upper left", fontsize=7)
    fig.suptitle(wrap_title(f"Isolator hysteresis: {r.title}", 7.2))
    return save(plt, np, fig, path, metadata)


def plot_hysteresis(plt, np, r, path, metadata):
    panels = [("total", r.isolator_force)]
    if len(r.component_names) > 1:
        panels += [(name, r.component_force[:, c]) for c, name in enumerate(r.component_names)]
    columns = min(3, len(panels))
    rows = math.ceil(len(panels) / columns)
    width = max(4.4, 2.5 * columns + 0.4)  # one panel (an SDOF's) as large as a report's figure
    height = 3.6 if len(panels) == 1 else 2.3 * rows + 0.5
    fig, axes = plt.subplots(rows, columns, figsize=(width, height), squeeze=False, sharex=True,
                             layout="constrained")
    for k, (name, force) in enumerate(panels):
        ax = axes[k // columns][k % columns]
        ax.plot(r.isolator_displacement, force, lw=0.6, color="C0" if k == 0 else "C1")
        ax.set_title(name if k == 0 else f"component {name}")
        mark_reference(ax.axhline(0, color="0.6", lw=0.5), ax.axvline(0, color="0.6", lw=0.5))
        ax.set_xlabel(f"isolator displacement [{r.length}]")
        ax.set_ylabel(f"force [{r.force_unit}]")
        ax.tick_params(labelbottom=True)  # every panel readable alone, whatever is hidden below
    for k in range(len(panels), rows * columns):
        axes[k // columns][k % columns].set_visible(False)
    fig.suptitle(wrap_title(f"Isolator hysteresis: {r.title}", width))
    return save(plt, np, fig, path, metadata)


def plot_histories(plt, np, r, path, metadata):
    columns = []
    if r.base_dof is not None:
        columns.append(("isolator (base)", r.base_dof))
    columns.append(("roof" if r.stories else "mass", r.roof_dof))
    width = 3.6 * len(columns) + 0.3
    fig, axes = plt.subplots(2, len(columns), figsize=(width, 4.6), squeeze=False,
                             sharex=True, layout="constrained")
    for c, (name, dof) in enumerate(columns):
        u = r.displacement[:, dof]
        a, a_unit = acceleration_in_g(r, r.absolute_acceleration[:, dof])
        axes[0][c].plot(r.time, u, lw=0.6)
        axes[0][c].set_title(f"{name}: peak |u| = {np.max(np.abs(u)):.4g} {r.length}")
        axes[0][c].set_ylabel(f"displacement [{r.length}]")
        axes[1][c].plot(r.time, a, lw=0.6, color="C3")
        axes[1][c].set_title(f"{name}: peak |a| = {np.max(np.abs(a)):.3g} {a_unit}")
        axes[1][c].set_ylabel(f"absolute acceleration [{a_unit}]")
        axes[1][c].set_xlabel(f"time [{r.time_unit}]")
        for ax in (axes[0][c], axes[1][c]):
            mark_reference(ax.axhline(0, color="0.6", lw=0.5))
    fig.suptitle(wrap_title(r.title, width))
    return save(plt, np, fig, path, metadata)


def plot_envelopes(plt, np, r, path, metadata):
    n = r.stories
    levels = np.arange(n + 1)
    peak_u = np.max(np.abs(r.displacement), axis=0)
    peak_a, a_unit = acceleration_in_g(r, np.max(np.abs(r.absolute_acceleration), axis=0))
    pga, _ = acceleration_in_g(r, np.max(np.abs(r.ground_acceleration)))
    if r.base_dof is not None:  # level 0 is the base on the isolators
        u_levels, a_levels, ground = peak_u, peak_a, "base"
    else:  # fixed base: level 0 is the ground
        u_levels = np.concatenate([[0.0], peak_u])
        a_levels = np.concatenate([[pga], peak_a])
        ground = "ground"
    fig, axes = plt.subplots(1, 4, figsize=(7.2, 3.0), sharey=True, layout="constrained")
    axes[0].plot(u_levels, levels, "o-", ms=3)
    axes[0].set_xlabel(f"peak displacement [{r.length}]")
    axes[1].plot(*step_profile(np.max(np.abs(r.drift), axis=0)), "-", color="C1")
    axes[1].set_xlabel(f"peak story drift [{r.length}]")
    axes[2].plot(a_levels, levels, "o-", ms=3, color="C3")
    mark_reference(axes[2].axvline(pga, color="0.5", lw=0.8, ls="--", label="peak ground"))
    axes[2].legend(loc="best")
    axes[2].set_xlabel(f"peak absolute\nacceleration [{a_unit}]")
    axes[3].plot(*step_profile(np.max(np.abs(r.shear), axis=0)), "-", color="C2")
    axes[3].set_xlabel(f"peak story shear [{r.force_unit}]")
    axes[0].set_yticks(levels)
    axes[0].set_yticklabels([ground] + [f"floor {k}" for k in range(1, n + 1)])
    if r.two:  # resultants of x and y
        for ax in axes:
            ax.set_xlabel(ax.get_xlabel().replace("peak ", "peak |(x, y)|\n", 1))
    axes[0].set_ylabel("level")
    for ax in axes:
        ax.set_xlim(left=0)
    fig.suptitle(wrap_title(f"Peak envelopes: {r.title}", 7.2))
    return save(plt, np, fig, path, metadata)


def plot_energy(plt, np, r, path, metadata):
    e = r.energy
    fig, ax = plt.subplots(figsize=(7.2, 3.4), layout="constrained")
    ax.stackplot(r.time, e["kinetic"], e["damping"], e["elastic"], e["hysteretic"],
                 labels=["kinetic", "damping", "elastic", "hysteretic"], alpha=0.8)
    ax.plot(r.time, e["input"], color="k", lw=1.0, label="input")
    ax.set_xlabel(f"time [{r.time_unit}]")
    ax.set_ylabel(f"energy [{r.energy_unit}]")
    # Beside the axes: the stack fills the area a legend inside would cover.
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    ax.set_title(wrap_title(f"Energy balance: {r.title}", 6.0))
    return save(plt, np, fig, path, metadata)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("result", nargs="?", help="HDF5 file written by isolab run")
    parser.add_argument("-o", "--output-dir", help="directory for the PNGs (default: the "
                        "result's)")
    parser.add_argument("-q", "--quiet", action="store_true", help="do not list the files")
    parser.add_argument("--metadata", action="store_true",
                        help="beside each figure, a JSON file of its axes: labels, units and "
                        "the range of the data drawn")
    parser.add_argument("--check", action="store_true",
                        help="only check that matplotlib and h5py import")
    args = parser.parse_args()
    h5py, plt, np = import_modules()
    if args.check:
        return 0
    if not args.result:
        parser.error("the result file is required")
    if not os.path.isfile(args.result):
        print(f"plot_result.py: {args.result}: no such file", file=sys.stderr)
        return 2
    directory = args.output_dir or os.path.dirname(args.result) or "."
    os.makedirs(directory, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.result))[0]
    r = Result(h5py, np, args.result)
    plots = []
    if r.isolated:
        plots.append(("overview", plot_plan_overview if r.two else plot_overview))
        plots.append(("hysteresis", plot_plan_hysteresis if r.two else plot_hysteresis))
    plots.append(("histories", plot_histories))
    if r.stories:
        plots.append(("envelopes", plot_envelopes))
    plots.append(("energy", plot_energy))
    for name, plot in plots:
        path = plot(plt, np, r, os.path.join(directory, f"{stem}_{name}.png"), args.metadata)
        if not args.quiet:
            print(f"plot: {path} (and .pdf)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
