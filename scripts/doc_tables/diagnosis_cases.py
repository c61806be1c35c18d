#!/usr/bin/python3
"""Prints docs/diagnosis.md's tables of the hidden-effect cases (standard library only): writes the
cases' data with scripts/generate_diagnosis_cases.sh into a scratch folder, runs `isolab diagnose
CASE.csv --base models/diagnosis/base_bhm2.yaml --seed 1 --json` on each, and prints two tables
from the reports: every case (what was named, on what evidence, the e^2 before and after, the
noise floor, and the largest value/threshold of the candidates left), then the two campaigns on
one specimen. About a minute of fitting: scripts/check_docs.py runs it with --opt-in only.

    diagnosis_cases.py ISOLAB
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = ("null", "rate_dependence", "amplitude_dependent_dissipation",
         "large_amplitude_hardening", "cyclic_degradation", "two_effects", "asymmetric_strength",
         "backlash", "campaign_cyclic_degradation", "campaign_rate_dependence")


def significant(value, digits=4):
    """`value` to `digits` significant digits, as the diagnosis report prints e^2."""
    return f"{value:.{digits}g}" if abs(value) >= 10 ** (digits - 1) else \
        f"{value:#.{digits}g}".rstrip(".")


def percent(e2):
    return f"{significant(100 * e2)} %"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    isolab = os.path.abspath(sys.argv[1])
    reports = {}
    with tempfile.TemporaryDirectory(prefix="isolab_diagnosis_") as folder:
        subprocess.run(["bash", os.path.join(ROOT, "scripts/generate_diagnosis_cases.sh"),
                        folder], check=True, stdout=subprocess.DEVNULL,
                       env={**os.environ, "ISOLAB": isolab})
        for case in CASES:
            printed = subprocess.run(
                [isolab, "diagnose", os.path.join(folder, case + ".csv"), "--base",
                 os.path.join(ROOT, "models/diagnosis/base_bhm2.yaml"), "--seed", "1", "--json",
                 "-q", "--no-plot", "--out", os.path.join(folder, case)],
                check=True, capture_output=True, text=True).stdout
            reports[case] = json.loads(printed)
    print("| case | named | evidence | base e^2 | final e^2 | noise floor | final / floor "
          "| left (max value/threshold) | time |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case in CASES:
        r = reports[case]
        label = case + (" (one specimen)" if case.startswith("campaign_") else "")
        named = ", then ".join(r["effects"]) or "none"
        evidence = ", ".join(f"{s['evidence']['value']:#.3g}" for s in r["steps"]) or "-"
        left = max((c["value"] / c["threshold"] for c in r["last_candidates"]), default=0.0)
        print(f"| {label} | {named} | {evidence} | {percent(r['base']['e2'])} | "
              f"{percent(r['final']['e2'])} | {percent(r['noise_floor_e2'])} | "
              f"{r['verdict']['ratio']:.2f} | {left:.2f} | {r['seconds']:.1f} s |")
    print()
    print("| campaign | named | base e^2 | final e^2 | noise floor | final / floor |")
    print("|---|---|---|---|---|---|")
    for case in CASES:
        if case.startswith("campaign_"):
            r = reports[case]
            print(f"| {case[len('campaign_'):]} | {', then '.join(r['effects']) or 'none'} | "
                  f"{percent(r['base']['e2'])} | {percent(r['final']['e2'])} | "
                  f"{percent(r['noise_floor_e2'])} | {r['verdict']['ratio']:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
