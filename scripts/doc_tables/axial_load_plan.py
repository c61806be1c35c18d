#!/usr/bin/python3
"""Prints docs/axial_load.md's table of the five-story friction-pendulum building in plan
(models/plan/five_story_fp_plan.yaml) with its axial loads taken five ways, from `isolab run
--json` of each variant (standard library only). The variants are the model's own text with its
`axial_load` section and vertical component changed, written to a scratch folder.

    axial_load_plan.py ISOLAB [--scale S] [--short-labels]
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "models/plan/five_story_fp_plan.yaml")
ORDER = ("sw", "se", "nw", "ne")  # the page's order of the least N
# (long label, short label, axial_load section or None, whether the vertical component stays)
VARIANTS = (
    ("constant `w` (no `axial_load`)", "constant `w`", None, False),
    ("static share (`{}`)", "static share", "{}", False),
    ("static + vertical", "static + vertical", "{vertical: true}", True),
    ("static + overturning", "static + overturning", "{overturning: true, base_height: 600}",
     False),
    ("static + vertical + overturning", "static + vertical + overturning",
     "{vertical: true, overturning: true, base_height: 600}", True),
)


def significant(value, digits=4):
    """`value` to `digits` significant digits without an exponent."""
    return f"{value:.{max(0, digits - 1 - math.floor(math.log10(abs(value))))}f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("isolab")
    parser.add_argument("--scale", help="isolab run's --scale (every component)")
    parser.add_argument("--short-labels", action="store_true")
    args = parser.parse_args()
    with open(MODEL, encoding="utf-8") as f:
        text = f.read().replace("../../ground_motions/",
                                os.path.join(ROOT, "ground_motions") + "/")
    w = re.search(r"\bw: (\d+) kN", text).group(1)  # every bearing's constant axial load
    print("| axial load | isolator displacement | isolator force | base shear | story drift "
          "| torsional amplification | least N (sw, se, nw, ne) |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="isolab_axial_") as folder:
        for long_label, short_label, section, vertical in VARIANTS:
            variant = re.sub(r"(?m)^axial_load: .*\n", "" if section is None else
                             f"axial_load: {section}\n", text)
            if not vertical:
                variant = re.sub(r"(?m)^    v: .*\n", "", variant)
            model = os.path.join(folder, "model.yaml")
            with open(model, "w", encoding="utf-8") as f:
                f.write(variant)
            command = [args.isolab, "run", model, "--json", "-o", os.path.join(folder, "r.h5")]
            if args.scale:
                command += ["--scale", args.scale]
            r = json.loads(subprocess.run(command, check=True, capture_output=True,
                                          text=True).stdout)
            peaks = r["peaks"]
            if section is None:
                least = f"{w} each"
            else:
                least = ", ".join(f"{r['axial_loads'][b]['minimum']['value']:.0f}"
                                  for b in ORDER) + " kN"
            cells = [f"{peaks['isolator_displacement']['value']:.2f} mm",
                     f"{significant(peaks['isolator_force']['value'])} kN",
                     f"{significant(peaks['base_shear']['value'])} kN",
                     f"{significant(peaks['story_drift']['value'])} mm",
                     f"{r['torsional_amplification']:.3f}", least]
            label = short_label if args.short_labels else long_label
            print(f"| {label} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
