#!/usr/bin/python3
"""Prints a study's summary as the Markdown table the docs quote (standard library only): for each
scale and variant the mean over the records of each quantity, with its ratio to the reference
variant's (the summary's own `mean` rows), or with --per-record one row per record of one variant
and a last row of mean / max. Runs `isolab compare STUDY --runs none` in a scratch folder and
reads its summary.csv, so the table is what the code computes today (scripts/check_docs.py
checks the pages against it).

    study_means.py ISOLAB STUDY [--scale S] [--quantities Q,...] [--no-scale-column]
                   [--label NAME=TEXT ...] [--per-record [--record-header TEXT]]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

# summary.csv's column stem -> the page's header (one direction, plan). A plan study's quantities
# are resultants in plan, which the header says.
HEADERS = {
    "isolator_displacement": ("isolator [mm]", "isolator \\|u\\| [mm]"),
    "base_shear": ("base shear [kN]", "base shear \\|V\\| [kN]"),
    "story_drift_ratio": ("drift [%]", "drift [%]"),
    "floor_acceleration": ("floor acc. [g]", "floor acc. [g]"),
    "residual_isolator_displacement": ("residual [mm]", "residual [mm]"),
    "floor_rotation": ("floor rotation [rad]", "floor rotation [rad]"),
    "torsional_amplification": ("torsional amplification", "torsional amplification"),
}


def significant(value, digits=4):
    """`value` to `digits` significant digits without an exponent (isolab's summaries print 4)."""
    if value == 0 or not math.isfinite(value):
        return f"{value:g}"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
    return f"{value:.{decimals}f}"


def ratio(value):
    """A ratio to the reference: three decimals, one from 10 up (a residual's can be 20)."""
    return f"{value:.3f}" if abs(value) < 10 else f"{value:.1f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("isolab")
    parser.add_argument("study")
    parser.add_argument("--scale", type=float, help="only this scale (default: every scale)")
    parser.add_argument("--quantities", help="summary columns, comma-separated (default: all)")
    parser.add_argument("--no-scale-column", action="store_true")
    parser.add_argument("--label", action="append", default=[],
                        help="NAME=TEXT: a variant's or record's name as the page writes it")
    parser.add_argument("--per-record", action="store_true",
                        help="one row per record of a one-variant study, then mean / max")
    parser.add_argument("--record-header", default="record",
                        help="the first column's header with --per-record")
    args = parser.parse_args()
    labels = dict(item.split("=", 1) for item in args.label)
    with tempfile.TemporaryDirectory(prefix="isolab_study_") as folder:
        subprocess.run([args.isolab, "compare", args.study, "-q", "-j", "1", "--runs", "none",
                        "-o", os.path.join(folder, "out")], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "out", "summary.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    failed = [r for r in rows if r["status"] != "completed"]
    if failed:
        sys.exit(f"{args.study}: {len(failed)} runs did not complete ({failed[0]['message']})")
    stems = {c.split(" [")[0]: c for c in rows[0] if c.split(" [")[0] in HEADERS}
    quantities = args.quantities.split(",") if args.quantities else list(stems)
    plan = "floor_rotation" in stems
    header = [HEADERS[q][plan] for q in quantities]

    def value(row, q):
        return float(row[stems[q]])

    def chosen(record=None):
        return [r for r in rows if (args.scale is None or float(r["scale"]) == args.scale)
                and (r["record"] == record if record else r["record"] not in ("mean", "max"))]

    if args.per_record:
        print(f"| {args.record_header} | " + " | ".join(header) + " |")
        print("|---" * (len(header) + 1) + "|")
        for r in chosen():
            cells = [significant(value(r, q)) for q in quantities]
            print(f"| {labels.get(r['record'], r['record'])} | " + " | ".join(cells) + " |")
        mean, peak = chosen("mean")[0], chosen("max")[0]
        cells = [f"{significant(value(mean, q))} / {significant(value(peak, q))}"
                 for q in quantities]
        print("| mean / max | " + " | ".join(cells) + " |")
        return 0
    show_scale = not args.no_scale_column
    print(("| scale " if show_scale else "") + "| variant | " + " | ".join(header) + " |")
    print("|---" * (len(header) + 1 + show_scale) + "|")
    reference = chosen("mean")[0]["variant"]
    for r in sorted(chosen("mean"), key=lambda r: float(r["scale"])):  # stable: study's order
        cells = [significant(value(r, q)) if r["variant"] == reference else
                 f"{significant(value(r, q))} ({ratio(float(r['ratio ' + q]))})"
                 for q in quantities]
        print((f"| {float(r['scale']):g} " if show_scale else "") +
              f"| {labels.get(r['variant'], r['variant'])} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
