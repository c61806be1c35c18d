#!/usr/bin/python3
"""Prints docs/bncs.md's tables of the BNCS isolation layer identified from the ICA50 isolator
history (standard library only), as scripts/bncs_study.sh makes them, into a scratch folder:

    fits       `isolab fit` of the BHM2 and the THM1 assembly specifications (budgets 6,000 and
               20,000): parameters, e^2, evaluations and the fit's own wall time (about 80 s)
    diagnosis  `isolab diagnose` from the BHM2 (about 2.5 minutes): each effect named, its
               evidence against its threshold, the e^2 after it and the share of the base e^2
               it closed, the component added

The measurements are not in the repository (bncs_data.py), so scripts/check_docs.py runs this with
--opt-in only.

    bncs_isolator.py ISOLAB {fits,diagnosis} [DATA_DIR]
"""
import json
import os
import subprocess
import sys
import tempfile

from bncs_data import ROOT, isolator_history

FITS = (("BHM2 (`bhm2_spec.yaml`)", "bhm2_spec.yaml", 6000),
        ("Table 9-style THM1 assembly: 2 trilinear, 2 THM1, 1 elastoplastic (`thm1_spec.yaml`)",
         "thm1_spec.yaml", 20000))


def percent(e2):
    return f"{100 * e2:.3f} %"


def run_json(command):
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def print_fits(isolab, history, folder):
    print("| model family | parameters | e^2 | evaluations | wall time |")
    print("|---|---|---|---|---|")
    for label, spec, budget in FITS:
        fit = run_json([isolab, "fit", history, "--model",
                        os.path.join(ROOT, "models", "bncs", spec), "--budget", str(budget),
                        "-o", os.path.join(folder, spec), "-q", "--json"])
        parameters = sum(len(c["parameters"]) for c in fit["components"])
        seconds = fit["seconds"]
        wall = f"{seconds:.1f} s" if seconds < 10 else f"{seconds:.0f} s"
        print(f"| {label} | {parameters} | {percent(fit['e2'])} | {fit['evaluations']:,} "
              f"| {wall} |")


def print_diagnosis(isolab, history, folder):
    report = run_json([isolab, "diagnose", history, "--base",
                       os.path.join(ROOT, "models", "bncs", "bhm2_spec.yaml"), "--json", "-q",
                       "--no-plot", "--out", os.path.join(folder, "ica50_diagnosis")])
    base = report["base"]["e2"]
    print("| step | effect | evidence (threshold) | e^2 | share of the base e^2 closed | added |")
    print("|---|---|---|---|---|---|")
    print(f"| base | one BHM2 | | {percent(base)} | | |")
    for number, step in enumerate(report["steps"], start=1):
        evidence = step["evidence"]
        closed = (step["e2_before"] - step["e2_after"]) / base
        print(f"| {number} | {step['effect']} | {evidence['value']:.3f} "
              f"({evidence['threshold']:g}) | {percent(step['e2_after'])} | {100 * closed:.0f} % "
              f"| `{step['added']['type']}` |")


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[2] not in ("fits", "diagnosis"):
        sys.exit(__doc__)
    isolab = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="isolab_bncs_") as folder:
        history = isolator_history(isolab, "ica50", folder,
                                   sys.argv[3] if len(sys.argv) == 4 else None)
        (print_fits if sys.argv[2] == "fits" else print_diagnosis)(isolab, history, folder)
    return 0


if __name__ == "__main__":
    sys.exit(main())
