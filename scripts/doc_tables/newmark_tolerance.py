#!/usr/bin/python3
"""Prints docs/bidirectional.md's table of Newton solves per step against Newmark's force
tolerance (standard library only): `isolab run --json` of a plan model at its own dt, the model's
text with `analysis.newmark.force_tolerance` set to each tolerance in a scratch folder (`default`:
the model as it is), and the peak resultant displacement of one bearing.

    newmark_tolerance.py ISOLAB MODEL BEARING TOLERANCE ...   (e.g. default 1e-8 1e-6)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    isolab, model, bearing, *tolerances = sys.argv[1:]
    with open(os.path.join(ROOT, model), encoding="utf-8") as f:
        text = f.read().replace("../../ground_motions/",
                                os.path.join(ROOT, "ground_motions") + "/")
    if not re.search(r"(?m)^analysis:\n  dt: ", text):
        sys.exit(f"{model}: expected an `analysis:` section opening with `dt:`")
    solves, peaks, headers = [], [], []
    with tempfile.TemporaryDirectory(prefix="isolab_tolerance_") as folder:
        for tolerance in tolerances:
            variant = text
            if tolerance != "default":
                variant = text.replace("\nanalysis:\n", "\nanalysis:\n  newmark: "
                                       f"{{force_tolerance: {tolerance}}}\n", 1)
            path = os.path.join(folder, "model.yaml")
            with open(path, "w", encoding="utf-8") as f:
                f.write(variant)
            r = json.loads(subprocess.run(
                [isolab, "run", path, "--json", "-o", os.path.join(folder, "r.h5")],
                check=True, capture_output=True, text=True).stdout)
            solves.append(f"{r['newton']['solves_per_step']:.3f}")
            peaks.append(f"{r['isolators'][bearing]['displacement']['value']:.4f}")
            headers.append("1e-10 (default)" if tolerance == "default" else tolerance)
    print("| `newmark.force_tolerance` | " + " | ".join(headers) + " |")
    print("|---" * (len(headers) + 1) + "|")
    print("| solves per step | " + " | ".join(solves) + " |")
    print(f"| peak resultant, {bearing.upper()} bearing (mm) | " + " | ".join(peaks) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
