#!/usr/bin/python3
"""Prints docs/diagnosis.md's catalogue of effects as `isolab diagnose` reports it (standard
library only): the bilinear base alone (models/diagnosis/null.yaml, as
scripts/generate_diagnosis_cases.sh draws it) diagnosed from models/diagnosis/base_bhm2.yaml, whose
report lists every detector among its last candidates with its threshold, and names `none`.
Rows follow the page's; a detector the report has and the page lacks is a row of its own, "(not on
the page)", and one the page lists and the report lacks is marked "(not a detector)".

    detectors.py ISOLAB
"""
import json
import os
import subprocess
import sys
import tempfile

from page_rows import ROOT, first_cells

HEADER = "| effect | detector (reads the fitted model and the data only) | threshold | component added |"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    isolab = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="isolab_detectors_") as folder:
        data = os.path.join(folder, "null.csv")
        subprocess.run([isolab, "cyclic", os.path.join(ROOT, "models/diagnosis/null.yaml"), "-a",
                        "10,25,50,100,150,200", "-T", "2,0.5", "-n", "3", "--steps-per-cycle",
                        "200", "--test-data", data, "--noise", "0.01", "--seed", "11"],
                       check=True, stdout=subprocess.DEVNULL)
        report = json.loads(subprocess.run(
            [isolab, "diagnose", data, "--base",
             os.path.join(ROOT, "models/diagnosis/base_bhm2.yaml"), "--json", "-q", "--no-plot",
             "--out", os.path.join(folder, "null")], check=True, capture_output=True,
            text=True).stdout)
    thresholds = {c["effect"]: c["threshold"] for c in report["last_candidates"]}
    verdicts = set(report["effects"])  # the null case's: `none`
    print(HEADER)
    print("|---|---|---|---|")
    for cell in first_cells("diagnosis.md", HEADER):
        effect = cell.strip("`")
        if effect in thresholds:
            print(f"| {cell} | | {thresholds.pop(effect):g} | |")
        elif effect in verdicts:
            print(f"| {cell} | | | |")
        else:
            print(f"| {cell} (not a detector) | | | |")
    for effect, threshold in thresholds.items():
        print(f"| `{effect}` (not on the page) | | {threshold:g} | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
