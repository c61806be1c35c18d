#!/usr/bin/env python3
"""Figures for `isolab shaketable`: the isolator's measured force-displacement loop from the
cyclic-test CSV that --isolator writes, and the measured-vs-predicted overlay from the CSV that
--comparison writes; each a 300 dpi PNG with a vector PDF beside it (and, with --metadata, a JSON
file of its axes' labels, units and data ranges).

Usage: plot_shaketable.py loop ISOLATOR.csv [MORE.csv ...] -o loop.png [--weight W] [--metadata]
       plot_shaketable.py overlay COMPARISON.csv [MORE.csv ...] -o overlay.png [--title TEXT]
(each further comparison adds its prediction, labelled by its file name)
"""
import argparse

from plot_common import import_modules, save, wrap_title


def read_isolator(np, path):
    with open(path, encoding="utf-8") as handle:
        lines = [line for line in handle if not line.startswith("#")]
    header = lines[0].strip().split(",")
    values = np.array([[float(x) for x in line.split(",")[1:]] for line in lines[1:]])
    return (values[:, header.index("displacement") - 1], values[:, header.index("force") - 1])


def loop(args, plt, np):
    figure, axes = plt.subplots(figsize=(6.0, 4.4), layout="constrained")
    for path in args.files:
        u, f = read_isolator(np, path)
        scale = 1.0 / args.weight if args.weight else 1.0
        axes.plot(u, f * scale, linewidth=0.5, label=path.split("/")[-1].replace(".csv", ""))
    axes.set_xlabel("isolator displacement (base slab relative to the table) [mm]")
    axes.set_ylabel("isolator force / weight [1]" if args.weight else "isolator force [kN]")
    axes.legend(loc="upper left")  # a loop through the origin leaves that corner empty
    axes.set_title(wrap_title(args.title or "Measured isolator loop: minus the sum of mass x "
                              "absolute acceleration", 5.6))
    save(plt, np, figure, args.output, args.metadata)


def overlay(args, plt, np):
    figure, axes = plt.subplots(2, 1, figsize=(7.2, 5.0), sharex=True, layout="constrained")
    colours = ["r", "b", "g"]
    for i, path in enumerate(args.files):
        data = np.genfromtxt(path, delimiter=",", names=True)
        t = data["time_s"]
        label = path.split("/")[-1].replace("_comparison.csv", "").replace(".csv", "")
        if i == 0:
            axes[0].plot(t, data["isolator_displacement_measured"], "k", linewidth=0.9,
                         label="measured")
            axes[1].plot(t, data["roof_acceleration_measured"] / 9806.65, "k", linewidth=0.7,
                         label="measured")
        colour = colours[i % len(colours)]
        if "isolator_displacement_p5" in data.dtype.names:  # a band from --samples
            axes[0].fill_between(t, data["isolator_displacement_p5"],
                                 data["isolator_displacement_p95"], color=colour, alpha=0.3,
                                 linewidth=0, label=f"5-95 % band: {label}")
            axes[1].fill_between(t, data["roof_acceleration_p5"] / 9806.65,
                                 data["roof_acceleration_p95"] / 9806.65, color=colour, alpha=0.3,
                                 linewidth=0)
        axes[0].plot(t, data["isolator_displacement_predicted"], colour, linewidth=0.7,
                     label=f"predicted: {label}")
        axes[1].plot(t, data["roof_acceleration_predicted"] / 9806.65, colour, linewidth=0.5,
                     label=f"predicted: {label}")
    axes[0].set_ylabel("isolator displacement [mm]")
    axes[1].set_ylabel("roof absolute\nacceleration [g]")
    axes[1].set_xlabel("time [s]")
    # One legend for both panels, above them: inside, it covered the histories' peaks.
    handles, labels = axes[0].get_legend_handles_labels()
    axes[0].legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 1.0),
                   ncol=min(3, len(labels)), frameon=False)
    figure.suptitle(wrap_title(args.title or "Measured vs predicted", 7.0))
    save(plt, np, figure, args.output, args.metadata)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["loop", "overlay"])
    parser.add_argument("files", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--weight", type=float, default=0.0,
                        help="divide the force by this weight (kN)")
    parser.add_argument("--title", default="")
    parser.add_argument("--metadata", action="store_true",
                        help="beside the figure, a JSON file of its axes: labels, units and the "
                        "range of the data drawn")
    args = parser.parse_args()
    _, plt, np = import_modules()
    (loop if args.kind == "loop" else overlay)(args, plt, np)


if __name__ == "__main__":
    main()
