#!/usr/bin/python3
"""Prints docs/bncs.md's table of one BNCS motion measured against its prediction by the three
identified isolation models (standard library only): `isolab shaketable DATA --model M --predict
--json` for the BHM2 fit (models/bncs/bncs.yaml), the THM1 assembly and the diagnosed model, with
each peak's difference from the measured and the NRMSE of the two histories. The measurements are
not in the repository (bncs_data.py), so scripts/check_docs.py runs this with --opt-in only.

    bncs_predictions.py ISOLAB {lac100,ica50} [DATA_DIR]
(DATA_DIR: else $ISOLAB_BNCS_DATA, else ../shared/measured/bncs beside the repository)
"""
import json
import os
import subprocess
import sys
import tempfile

from bncs_data import ROOT, unpack_motion

MODELS = ("models/bncs/bncs.yaml", "models/bncs/bncs_thm1.yaml", "models/bncs/bncs_isolation_diagnosed.yaml")
# the page's first and last headers per motion (LAC100 predicted, ICA50 refitted in-sample)
HEADERS = {"lac100": ("LAC100", "diagnosed (below)"), "ica50": ("ICA50 (in-sample)", "diagnosed")}
G = 9806.65  # mm/s^2: the page gives accelerations in g


def change(predicted, measured):
    """The page's relative difference: whole percent, one decimal below 1 %."""
    p = 100 * (predicted / measured - 1)
    return f"({p:+.1f} %)" if abs(p) < 1 else f"({p:+.0f} %)"


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[2] not in HEADERS:
        sys.exit(__doc__)
    isolab, motion = os.path.abspath(sys.argv[1]), sys.argv[2]
    data = sys.argv[3] if len(sys.argv) == 4 else None
    reports = []
    with tempfile.TemporaryDirectory(prefix="isolab_bncs_") as folder:
        csv = unpack_motion(motion, folder, data)
        for model in MODELS:
            printed = subprocess.run(
                [isolab, "shaketable", csv, "--model", os.path.join(ROOT, model), "--predict",
                 "-q", "--json", "--results", os.path.join(folder, "p.h5")],
                check=True, capture_output=True, text=True).stdout
            reports.append(json.loads(printed))
    first, last = HEADERS[motion]
    print(f"| {first} | measured | BHM2 | THM1 assembly | {last} |")
    print("|---|---|---|---|---|")
    weight = reports[0]["weight"]
    for i, (label, unit, scale) in enumerate((("peak isolator displacement", "mm", 1),
                                              ("peak base shear", "kN", 1),
                                              ("peak roof absolute acceleration", "g", 1 / G))):
        measured = reports[0]["comparison"][i]["measured"]
        if reports[0]["comparison"][i]["quantity"] != label:
            sys.exit(f"shaketable's comparison[{i}] is "
                     f"'{reports[0]['comparison'][i]['quantity']}', not '{label}'")
        digits = 3 if unit == "g" else 1
        cells = [f"{measured * scale:.{digits}f} {unit}"]
        if unit == "kN":
            cells[0] += f" ({measured / weight:.3f} W)" if motion == "lac100" else ""
        for r in reports:
            predicted = r["comparison"][i]["predicted"]
            cells.append(f"{predicted * scale:.{digits}f} {unit} {change(predicted, measured)}")
        print(f"| {label} | " + " | ".join(cells) + " |")
    for key, label in (("isolator_displacement", "NRMSE isolator displacement"),
                       ("roof_acceleration", "NRMSE roof absolute acceleration")):
        print(f"| {label} | | " + " | ".join(f"{r['nrmse'][key]:.3f}" for r in reports) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
