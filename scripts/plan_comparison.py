#!/usr/bin/python3
"""The comparison of docs/bidirectional.md: peak resultant isolator displacement of the plan model
(models/plan/five_story_table9_plan.yaml) under both record components against the one-direction
model (models/buildings/five_story_table9.yaml) under each component alone and the codes'
100 %/30 % combination of those. Runs isolab (standard library only) and prints a Markdown table.

    scripts/plan_comparison.py [ISOLAB]        (default: build/isolab, from the repository root)
"""
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLAN = os.path.join(ROOT, "models/plan/five_story_table9_plan.yaml")
ONE_DIRECTION = os.path.join(ROOT, "models/buildings/five_story_table9.yaml")
H2 = os.path.join(ROOT, "ground_motions/h2_fwn_firm_seed3.at2")


def run(isolab, model, *options):
    with tempfile.TemporaryDirectory() as folder:
        out = subprocess.run([isolab, "run", model, "--json", "-o",
                              os.path.join(folder, "r.h5"), *options],
                             check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def plan_variant(text, centred, angle, folder, name, uncoupled=False):
    """The plan model with its centres of mass at the plan's centre (centred), H1 at `angle`, and
    each bearing's laws as uncoupled pairs (a square strength) when asked."""
    if uncoupled:
        text = text.replace("      components: &table9", "      coupling: uncoupled\n      components: &table9")
        text = text.replace("components: *table9", "coupling: uncoupled, components: *table9")
    if centred:
        text = text.replace("centre_of_mass: [13200, 8000]", "centre_of_mass: [12000, 8000]")
    text = text.replace("    angle: 0\n", f"    angle: {angle}\n")
    text = text.replace("../../ground_motions/", os.path.join(ROOT, "ground_motions") + "/")
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    isolab = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/isolab")
    d1 = run(isolab, ONE_DIRECTION)["peaks"]["isolator_displacement"]["value"]
    d2 = run(isolab, ONE_DIRECTION, "--record", H2, "--scale", "0.6")["peaks"][
        "isolator_displacement"]["value"]
    combined = max(math.hypot(d1, 0.3 * d2), math.hypot(d2, 0.3 * d1))
    print("| analysis | centre of mass [mm] | largest isolator [mm] | torsional amplification |")
    print("|---|---|---|---|")
    print(f"| one direction, H1 alone | {d1:.1f} | {d1:.1f} | |")
    print(f"| one direction, H2 alone | {d2:.1f} | {d2:.1f} | |")
    print(f"| 100 %/30 % of those (resultant, larger ordering) | {combined:.1f} | {combined:.1f} | |")
    with open(PLAN) as f:
        text = f.read()
    with tempfile.TemporaryDirectory() as folder:
        for centred, uncoupled, label in ((True, True, "no eccentricity, uncoupled bearings"),
                                          (True, False, "no eccentricity"),
                                          (False, False, "5 % eccentricity")):
            for angle in (0, 90):
                model = plan_variant(text, centred, angle, folder, "plan.yaml", uncoupled)
                r = run(isolab, model)
                largest = max(i["displacement"]["value"] for i in r["isolators"].values())
                centre = r["peaks"]["base_centre_displacement"]["value"]
                print(f"| plan, H1 at {angle} deg, {label} | {centre:.1f} | "
                      f"{largest:.1f} | {r['torsional_amplification']:.3f} |")


if __name__ == "__main__":
    main()
