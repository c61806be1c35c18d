#!/usr/bin/python3
"""Figures of response spectra written by `isolab spectrum` (CSV or HDF5; formats in
include/isolab/io/spectrum_file.h).

    scripts/plot_spectrum.py SPECTRUM.csv|SPECTRUM.h5 [-o DIR] [--velocity] [--log] [-q]
                             [--metadata]

writes, named after the spectrum file's stem, each a 300 dpi PNG with a vector PDF beside it
(and, with --metadata, a JSON file of its axes' labels, units and data ranges):
    <stem>_D.png         deformation: elastic D, and D_y = u_y per target ductility
    <stem>_V.png         pseudo-velocity V (and V_y), with --velocity
    <stem>_A.png         pseudo-acceleration A (and A_y) in g
    <stem>_strength.png  normalised yield strength f_y / f_o per ductility (constant-ductility
                         spectra only)
Elastic curves are black, one line style per damping ratio; constant-ductility curves are coloured
by ductility. A pair's spectra (`isolab spectrum H1 H2`) show its five curves: the components
(grey), their geometric mean, RotD50 and RotD100 (coloured). Runs on Debian's /usr/bin/python3 with python3-matplotlib (and python3-h5py for
HDF5 input); `--check` only tests that they import.
"""
import argparse
import csv
import math
import os
import sys

from plot_common import import_modules, save, short_name, wrap_title

STYLES = ["-", "--", ":", "-."]
# A pair's curves (spectrum_file.h): label and colour.
PAIR_CURVES = {"h1": ("H1", "0.55"), "h2": ("H2", "0.75"),
               "geometric_mean": ("geometric mean", "C0"), "rotd50": ("RotD50", "C2"),
               "rotd100": ("RotD100", "C3")}


def number(field):
    """Empty fields are 'not applicable' and 'nan' a strength not found: both plot as gaps."""
    return float(field) if field not in ("", None) else math.nan


class Spectra:
    """Curves keyed by damping ratio (elastic) and by (damping ratio, ductility)."""

    def __init__(self):
        self.length = "m"
        self.elastic = {}  # zeta -> {"T", "D", "V", "A_g"}
        self.inelastic = {}  # (zeta, mu) -> {"T", "D", "V", "A_g", "fy"}
        self.pair = {}  # (curve, zeta) -> {"T", "D", "V", "A_g"}
        self.alpha = None
        self.title = ""


def read_csv(path):
    s = Spectra()
    with open(path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.DictReader(lines))
    if not rows:
        raise ValueError(f"{path}: no spectrum rows")
    header = rows[0].keys()
    d = next(c for c in header if c.startswith("D_"))
    v = next(c for c in header if c.startswith("V_"))
    s.length = d[2:]
    for row in rows:
        zeta = number(row["damping"])
        if row["curve"] == "elastic":
            curve = s.elastic.setdefault(zeta, {"T": [], "D": [], "V": [], "A_g": []})
        elif row["curve"] in PAIR_CURVES:
            curve = s.pair.setdefault((row["curve"], zeta), {"T": [], "D": [], "V": [], "A_g": []})
        else:
            mu = number(row["ductility"])
            s.alpha = number(row["alpha"])
            curve = s.inelastic.setdefault((zeta, mu),
                                           {"T": [], "D": [], "V": [], "A_g": [], "fy": []})
            curve["fy"].append(number(row["fy_over_fo"]))
        curve["T"].append(number(row["period_s"]))
        curve["D"].append(number(row[d]))
        curve["V"].append(number(row[v]))
        curve["A_g"].append(number(row["A_g"]))
    return s


def read_hdf5(h5py, path):
    s = Spectra()
    with h5py.File(path, "r") as f:
        T = f["period"][:]
        zetas = f["damping"][:]
        first = "elastic" if "elastic" in f else "h1"
        units = f[first + "/D"].attrs.get("units", b"m")
        s.length = units.decode() if isinstance(units, bytes) else str(units)
        g = float(f.attrs["gravity"])
        for k, zeta in enumerate(zetas):
            if "elastic" in f:
                s.elastic[float(zeta)] = {"T": T, "D": f["elastic/D"][k],
                                          "V": f["elastic/V"][k], "A_g": f["elastic/A"][k] / g}
            for name in PAIR_CURVES:
                if name in f:
                    s.pair[(name, float(zeta))] = {"T": T, "D": f[name]["D"][k],
                                                   "V": f[name]["V"][k],
                                                   "A_g": f[name]["A"][k] / g}
        if "constant_ductility" in f:
            c = f["constant_ductility"]
            s.alpha = float(c.attrs["alpha"])
            for k, zeta in enumerate(zetas):
                for m, mu in enumerate(c["ductility"][:]):
                    s.inelastic[(float(zeta), float(mu))] = {
                        "T": T, "D": c["D_y"][k, m], "V": c["V_y"][k, m],
                        "A_g": c["A_y"][k, m] / g, "fy": c["strength_ratio"][k, m]}
    return s


def plot_quantity(plt, np, s, key, label, path, log, title, metadata):
    fig, ax = plt.subplots(figsize=(6.5, 4.2), layout="constrained")
    zetas = sorted(set(s.elastic) | {zeta for (zeta, _) in s.inelastic} |
                   {zeta for (_, zeta) in s.pair})
    for zeta, c in sorted(s.elastic.items()):
        ax.plot(c["T"], c[key], STYLES[zetas.index(zeta) % len(STYLES)], color="k", lw=1.2,
                label=f"elastic, zeta = {zeta:g}")
    for name, (curve_label, color) in PAIR_CURVES.items():
        for zeta in zetas:
            if (name, zeta) in s.pair:
                c = s.pair[(name, zeta)]
                ax.plot(c["T"], c[key], STYLES[zetas.index(zeta) % len(STYLES)], color=color,
                        lw=1.4 if name.startswith("rotd") else 1.0,
                        label=f"{curve_label}, zeta = {zeta:g}")
    ductilities = sorted({mu for (_, mu) in s.inelastic})
    for (zeta, mu), c in sorted(s.inelastic.items()):
        if key not in c:
            continue
        color = f"C{ductilities.index(mu) % 10}"
        ax.plot(c["T"], c[key], STYLES[zetas.index(zeta) % len(STYLES)], color=color, lw=1.0,
                label=f"mu = {mu:g}, zeta = {zeta:g}")
    if log:
        ax.set_xscale("log")
        ax.set_yscale("log")
    else:
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
    ax.set_xlabel("natural period T [s]")
    ax.set_ylabel(label)
    ax.grid(alpha=0.3, which="both")
    # Beside the axes: a spectrum's curves fill the plot where a legend inside would go.
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    ax.set_title(wrap_title(title, 4.8, 9.5))
    return save(plt, np, fig, path, metadata)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("spectrum", nargs="?", help="CSV or HDF5 file written by isolab spectrum")
    parser.add_argument("-o", "--output-dir", help="directory for the PNGs (default: the file's)")
    parser.add_argument("--velocity", action="store_true", help="also plot pseudo-velocity")
    parser.add_argument("--log", action="store_true", help="log-log axes")
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
    if not args.spectrum:
        parser.error("the spectrum file is required")
    if not os.path.isfile(args.spectrum):
        print(f"plot_spectrum.py: {args.spectrum}: no such file", file=sys.stderr)
        return 2
    extension = os.path.splitext(args.spectrum)[1].lower()
    s = read_csv(args.spectrum) if extension == ".csv" else read_hdf5(h5py, args.spectrum)
    directory = args.output_dir or os.path.dirname(args.spectrum) or "."
    os.makedirs(directory, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.spectrum))[0]
    title = short_name(args.spectrum)
    if s.inelastic:
        title += f" (constant ductility: alpha = {s.alpha:g}; yield values D_y, V_y, A_y)"
    L = s.length
    plots = [("D", "D", f"deformation D [{L}]")]
    if args.velocity:
        plots.append(("V", "V", f"pseudo-velocity V [{L}/s]"))
    plots.append(("A", "A_g", "pseudo-acceleration A [g]"))
    written = []
    for name, key, label in plots:
        path = os.path.join(directory, f"{stem}_{name}.png")
        written.append(plot_quantity(plt, np, s, key, label, path, args.log, title, args.metadata))
    if s.inelastic:
        path = os.path.join(directory, f"{stem}_strength.png")
        only_inelastic = Spectra()
        only_inelastic.inelastic = s.inelastic
        written.append(plot_quantity(plt, np, only_inelastic, "fy",
                                     "normalised yield strength f_y / f_o [1]", path, args.log,
                                     title, args.metadata))
    if not args.quiet:
        for path in written:
            print(f"plot: {path} (and .pdf)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
