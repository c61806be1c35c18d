#!/usr/bin/python3
"""PNG plots of an `isolab run` result (HDF5; layout in include/isolab/analysis/results_file.h).

    scripts/plot_result.py RESULT.h5 [-o DIR] [-q]

writes, named after the result file's stem:
    <stem>_overview.png    the isolator's loop and its displacement history, the free vibration
                           after the excitation shaded (isolated models only)
    <stem>_hysteresis.png  isolator force against isolator displacement: total and each component
    <stem>_histories.png   displacement and absolute acceleration of the isolator (base) and roof
    <stem>_envelopes.png   peaks over height: displacement, story drift, absolute acceleration,
                           story shear (buildings only)
    <stem>_energy.png      input energy against kinetic + damping + elastic + hysteretic, stacked
Panels that a model does not have (no isolator, no stories) are left out. Runs on Debian's
/usr/bin/python3 with python3-matplotlib and python3-h5py (scripts/setup.sh installs them);
`--check` only tests that they import (isolab run --plot calls it before the analysis).
"""
import argparse
import math
import os
import sys

from plot_common import import_modules, text


def units_of(dataset):
    return text(dataset.attrs.get("units", ""))


def step_profile(values):
    """A per-story quantity as a staircase over levels: story s spans levels s to s + 1."""
    xs, ys = [], []
    for story, value in enumerate(values):
        xs += [value, value]
        ys += [story, story + 1]
    return xs, ys


class Result:
    """The datasets plot_result needs, and where the isolator and roof are."""

    def __init__(self, h5py, np, path):
        with h5py.File(path, "r") as f:
            self.time = f["time"][:]
            self.time_unit = units_of(f["time"])
            self.displacement = f["displacement"][:]
            self.length = units_of(f["displacement"])
            self.relative_acceleration = f["acceleration"][:]
            self.absolute_acceleration = f["absolute_acceleration"][:]
            self.acceleration_unit = units_of(f["absolute_acceleration"])
            self.isolated = "isolator" in f
            if self.isolated:
                g = f["isolator"]
                self.isolator_displacement = g["displacement"][:]
                self.isolator_force = g["force"][:]
                self.force_unit = units_of(g["force"])
                self.component_force = g["component_force"][:]
                self.component_names = [text(n) for n in g["component_force"].attrs["columns"]]
            self.stories = 0
            if "story" in f:
                self.drift = f["story/drift"][:]
                self.shear = f["story/shear"][:]
                self.force_unit = units_of(f["story/shear"])
                self.stories = self.drift.shape[1]
            self.energy = {name: f["energy/" + name][:]
                           for name in ("input", "kinetic", "damping", "elastic", "hysteretic")}
            self.energy_unit = units_of(f["energy/input"])
            self.excitation_end = float(f.attrs.get("excitation_end", self.time[-1]))
            self.residual = float(f.attrs.get("residual_isolator_displacement", math.nan))
            self.title = os.path.basename(text(f.attrs.get("model_file", path)))
            record = text(f.attrs.get("record", ""))
            if record:
                self.title += f" under {os.path.basename(record)}"
            if text(f.attrs.get("termination", "completed")) != "completed":
                self.title += " (run stopped early)"
        dofs = self.displacement.shape[1]
        # Shear buildings: DOF 0 is the base when isolated, then the floors; an SDOF has one DOF.
        self.base_dof = 0 if (self.isolated and dofs == self.stories + 1 and self.stories) else None
        self.roof_dof = dofs - 1
        self.ground_acceleration = self.absolute_acceleration[:, 0] - self.relative_acceleration[:, 0]


def plot_overview(plt, np, r, path):
    """The isolator's loop beside its displacement history: the run at a glance."""
    fig, (loop, history) = plt.subplots(1, 2, figsize=(11, 3.8),
                                        gridspec_kw={"width_ratios": [1, 1.6]})
    loop.plot(r.isolator_displacement, r.isolator_force, lw=0.7, color="C0")
    loop.set_xlabel(f"isolator displacement [{r.length}]")
    loop.set_ylabel(f"isolator force [{r.force_unit}]")
    loop.set_title("isolator hysteresis", fontsize=10)
    history.plot(r.time, r.isolator_displacement, lw=0.7, color="C0")
    if r.excitation_end < r.time[-1]:
        history.axvspan(r.excitation_end, r.time[-1], color="0.9", zorder=0,
                        label="free vibration")
    if not math.isnan(r.residual):
        history.axhline(r.residual, color="C3", lw=0.8, ls="--",
                        label=f"residual {r.residual:.3g} {r.length}")
    history.legend(fontsize=8, loc="upper right")
    history.set_xlabel(f"time [{r.time_unit}]")
    history.set_ylabel(f"isolator displacement [{r.length}]")
    history.set_title("isolator displacement", fontsize=10)
    for ax in (loop, history):
        ax.axhline(0, color="0.7", lw=0.5)
        ax.tick_params(labelsize=8)
    fig.suptitle(r.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_hysteresis(plt, np, r, path):
    panels = [("total", r.isolator_force)]
    if len(r.component_names) > 1:
        panels += [(name, r.component_force[:, c]) for c, name in enumerate(r.component_names)]
    columns = min(4, len(panels))
    rows = math.ceil(len(panels) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.0 * rows), squeeze=False,
                             sharex=True)
    for k, (name, force) in enumerate(panels):
        ax = axes[k // columns][k % columns]
        ax.plot(r.isolator_displacement, force, lw=0.7, color="C0" if k == 0 else "C1")
        ax.set_title(name, fontsize=9)
        ax.axhline(0, color="0.7", lw=0.5)
        ax.axvline(0, color="0.7", lw=0.5)
        ax.set_xlabel(f"isolator displacement [{r.length}]", fontsize=8)
        ax.set_ylabel(f"force [{r.force_unit}]", fontsize=8)
        ax.tick_params(labelsize=7)
    for k in range(len(panels), rows * columns):
        axes[k // columns][k % columns].set_visible(False)
    fig.suptitle(f"isolator hysteresis: {r.title}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_histories(plt, np, r, path):
    columns = []
    if r.base_dof is not None:
        columns.append(("isolator (base)", r.base_dof))
    columns.append(("roof" if r.stories else "mass", r.roof_dof))
    fig, axes = plt.subplots(2, len(columns), figsize=(6.0 * len(columns), 5.5), squeeze=False,
                             sharex=True)
    for c, (name, dof) in enumerate(columns):
        u = r.displacement[:, dof]
        a = r.absolute_acceleration[:, dof]
        axes[0][c].plot(r.time, u, lw=0.7)
        axes[0][c].set_title(f"{name}: peak |u| = {np.max(np.abs(u)):.4g} {r.length}", fontsize=9)
        axes[0][c].set_ylabel(f"displacement [{r.length}]")
        axes[1][c].plot(r.time, a, lw=0.7, color="C3")
        axes[1][c].set_title(f"{name}: peak |a| = {np.max(np.abs(a)):.4g} {r.acceleration_unit}",
                             fontsize=9)
        axes[1][c].set_ylabel(f"absolute acceleration [{r.acceleration_unit}]")
        axes[1][c].set_xlabel(f"time [{r.time_unit}]")
        for ax in (axes[0][c], axes[1][c]):
            ax.axhline(0, color="0.7", lw=0.5)
    fig.suptitle(r.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_envelopes(plt, np, r, path):
    n = r.stories
    levels = np.arange(n + 1)
    peak_u = np.max(np.abs(r.displacement), axis=0)
    peak_a = np.max(np.abs(r.absolute_acceleration), axis=0)
    pga = np.max(np.abs(r.ground_acceleration))
    if r.base_dof is not None:  # level 0 is the base on the isolators
        u_levels, a_levels, ground = peak_u, peak_a, "base"
    else:  # fixed base: level 0 is the ground
        u_levels = np.concatenate([[0.0], peak_u])
        a_levels = np.concatenate([[pga], peak_a])
        ground = "ground"
    fig, axes = plt.subplots(1, 4, figsize=(13, 4.2), sharey=True)
    axes[0].plot(u_levels, levels, "o-")
    axes[0].set_xlabel(f"peak displacement [{r.length}]")
    axes[1].plot(*step_profile(np.max(np.abs(r.drift), axis=0)), "-", color="C1")
    axes[1].set_xlabel(f"peak story drift [{r.length}]")
    axes[2].plot(a_levels, levels, "o-", color="C3")
    axes[2].axvline(pga, color="0.5", lw=0.8, ls="--", label="peak ground")
    axes[2].legend(fontsize=7)
    axes[2].set_xlabel(f"peak absolute acceleration [{r.acceleration_unit}]")
    axes[3].plot(*step_profile(np.max(np.abs(r.shear), axis=0)), "-", color="C2")
    axes[3].set_xlabel(f"peak story shear [{r.force_unit}]")
    axes[0].set_yticks(levels)
    axes[0].set_yticklabels([ground] + [f"floor {k}" for k in range(1, n + 1)])
    for ax in axes:
        ax.set_xlim(left=0)
        ax.grid(alpha=0.3)
    fig.suptitle(f"peak envelopes: {r.title}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_energy(plt, np, r, path):
    e = r.energy
    fig, ax = plt.subplots(figsize=(9, 4.5))
    ax.stackplot(r.time, e["kinetic"], e["damping"], e["elastic"], e["hysteretic"],
                 labels=["kinetic", "damping", "elastic", "hysteretic"], alpha=0.8)
    ax.plot(r.time, e["input"], color="k", lw=1.0, label="input")
    ax.set_xlabel(f"time [{r.time_unit}]")
    ax.set_ylabel(f"energy [{r.energy_unit}]")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(f"energy balance: {r.title}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("result", nargs="?", help="HDF5 file written by isolab run")
    parser.add_argument("-o", "--output-dir", help="directory for the PNGs (default: the "
                        "result's)")
    parser.add_argument("-q", "--quiet", action="store_true", help="do not list the files")
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
        plots.append(("overview", plot_overview))
        plots.append(("hysteresis", plot_hysteresis))
    plots.append(("histories", plot_histories))
    if r.stories:
        plots.append(("envelopes", plot_envelopes))
    plots.append(("energy", plot_energy))
    for name, plot in plots:
        path = os.path.join(directory, f"{stem}_{name}.png")
        plot(plt, np, r, path)
        if not args.quiet:
            print(f"plot: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
