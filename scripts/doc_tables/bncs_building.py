#!/usr/bin/python3
"""Prints docs/bncs.md's tables of the BNCS building identified as a whole (standard library
only), from what scripts/bncs_building_study.sh left in build/bncs_building: each motion
predicted by the model it started from (the nominal building on the diagnosed isolation) and by
the building fits, in-sample and on the motion each fit did not see (nrmse); the bands of the
fits of one motion on the other (band); each motion's band without and with the model form
(model-form); each fit's search, from its printed summary (searches).

    bncs_building.py {nrmse,band,model-form,searches} [STUDY_DIR]   (default build/bncs_building)
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Each fit, its label and the motions it saw; a prediction of a motion it did not see is bold.
FITS = (("ica50", "ICA50", {"ica50"}), ("lac100", "LAC100", {"lac100"}),
        ("ica50_lac100", "both, ICA50 first", {"ica50", "lac100"}),
        ("lac100_ica50", "both, LAC100 first", {"ica50", "lac100"}))
MOTIONS = ("ica50", "lac100")
MODES = ("nrmse", "band", "model-form", "searches")


def load(study, name):
    with open(os.path.join(study, name)) as f:
        return json.load(f)


def start_model(study, motion):
    """The nominal building on the diagnosed isolation, the fits' starting point, run on `motion`."""
    out = subprocess.run([os.path.join(ROOT, "build", "isolab"), "shaketable",
                          os.path.join(study, f"{motion}.csv"), "--model",
                          os.path.join(ROOT, "models", "bncs", "bncs_isolation_diagnosed.yaml"),
                          "--predict", "--json", "-q", "--results",
                          os.path.join(study, f"start_on_{motion}.h5")],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def print_model_form(study):
    """Each motion predicted by the fit of both with its model form, and with it taken out."""
    print("| motion | measured peak: isolator, roof | band of the peaks without the model form "
          "| coverage of the histories (isolator, roof), peaks inside | with the model form "
          "| coverage, peaks inside |")
    print("|---|---|---|---|---|---|")
    for motion in MOTIONS:
        cells = []
        for fit in ("covariance_only", "model_form"):
            band = load(study, f"fit_{fit}_on_{motion}.json")["band"]
            d, a = band["peak_isolator_displacement"], band["peak_roof_acceleration"]
            cover, inside = band["coverage"], band["peak_inside"]
            cells.append(f"{d['p5']:.1f}-{d['p95']:.1f} mm, {a['p5']:.0f}-{a['p95']:.0f} mm/s^2")
            cells.append(f"{100 * cover['isolator_displacement']:.0f} %, "
                         f"{100 * cover['roof_acceleration']:.0f} %; "
                         + ", ".join("yes" if inside[k] else "no"
                                     for k in ("isolator_displacement", "roof_acceleration")))
        measured = load(study, f"fit_model_form_on_{motion}.json")["comparison"]
        peaks = {m["quantity"]: m["measured"] for m in measured}
        print(f"| {motion.upper()} | {peaks['peak isolator displacement']:.1f} mm, "
              f"{peaks['peak roof absolute acceleration']:.0f} mm/s^2 | " + " | ".join(cells)
              + " |")


def print_searches(study):
    """Each fit's simulations (the global search's, then the refinement's from both starts), its
    wall time (the study's own clock), objective and stop, from `isolab fit`'s summary line."""
    print("| fit | simulations | wall time | mean NRMSE^2 | stop |")
    print("|---|---|---|---|---|")
    for fit, label, _ in FITS:
        with open(os.path.join(study, f"fit_{fit}.txt")) as f:
            summary = f.read()
        found = re.search(r"global search: (\d+) simulations.*?least squares from [^:]*: (\w+) "
                          r"\(\d+ iterations, (\d+) simulations, mean NRMSE\^2 = ([0-9.e-]+)\)"
                          r".*?after (\d+) simulations", summary)
        if not found:
            sys.exit(f"{study}/fit_{fit}.txt: no two-stage search summary")
        simulations = sum(int(found.group(k)) for k in (1, 3, 5))
        with open(os.path.join(study, f"fit_{fit}.time")) as f:
            wall = f.read().split()[0]
        print(f"| {label} | {simulations:,} ({int(found.group(1)):,} global) | {wall} s "
              f"| {found.group(4)} | {found.group(2)} |")


def main():
    if len(sys.argv) not in (2, 3) or sys.argv[1] not in MODES:
        sys.exit(__doc__)
    study = sys.argv[2] if len(sys.argv) == 3 else os.path.join(ROOT, "build", "bncs_building")
    if sys.argv[1] == "nrmse":
        print("| fitted to | ICA50 isolator displacement | ICA50 roof acceleration "
              "| LAC100 isolator displacement | LAC100 roof acceleration |")
        print("|---|---|---|---|---|")
        rows = [("none (the starting model)", {m: start_model(study, m) for m in MOTIONS}, set())]
        for fit, label, seen in FITS:
            rows.append((label, {m: load(study, f"fit_{fit}_on_{m}.json") for m in MOTIONS}, seen))
        for label, runs, seen in rows:
            cells = []
            for motion in MOTIONS:
                for key in ("isolator_displacement", "roof_acceleration"):
                    value = f"{runs[motion]['nrmse'][key]:.3f}"
                    cells.append(value if motion in seen or not seen else f"**{value}**")
            print(f"| {label} | " + " | ".join(cells) + " |")
        return
    if sys.argv[1] == "model-form":
        print_model_form(study)
        return
    if sys.argv[1] == "searches":
        print_searches(study)
        return
    print("| prediction | peak isolator displacement: measured | predicted | 5-95 % band "
          "| NRMSE isolator displacement, 5-95 % |")
    print("|---|---|---|---|---|")
    for fit, motion in (("ica50", "lac100"), ("lac100", "ica50")):
        run = load(study, f"fit_{fit}_on_{motion}.json")
        peak = next(r for r in run["comparison"] if r["quantity"] == "peak isolator displacement")
        band = run["band"]
        p = band["peak_isolator_displacement"]
        n = band["nrmse_isolator_displacement"]
        print(f"| {fit.upper()} -> {motion.upper()} | {peak['measured']:.1f} mm | "
              f"{peak['predicted']:.1f} mm | {p['p5']:.1f} to {p['p95']:.1f} mm | "
              f"{n['p5']:.3f} to {n['p95']:.3f} |")


if __name__ == "__main__":
    main()
