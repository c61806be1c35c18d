#!/usr/bin/python3
"""Prints the pseudo-acceleration spectra of a record pair as the Markdown table
docs/bidirectional.md quotes (standard library only): per period, A in g of H1, H2, their
geometric mean, RotD50 and RotD100, and RotD100's direction, at the first damping ratio, from
`isolab spectrum H1 H2 ARGS --json`.

    spectrum_pair.py ISOLAB H1 H2 [isolab spectrum's options ...]
"""
import json
import math
import subprocess
import sys


def significant(value, digits=4):
    """`value` to `digits` significant digits without an exponent."""
    if value == 0 or not math.isfinite(value):
        return f"{value:g}"
    return f"{value:.{max(0, digits - 1 - math.floor(math.log10(abs(value))))}f}"


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    isolab, *arguments = sys.argv[1:]
    printed = subprocess.run([isolab, "spectrum", *arguments, "--json"], check=True,
                             capture_output=True, text=True).stdout
    spectra = json.loads(printed)
    pair = spectra["pair"][0]
    print("| T [s] | H1 | H2 | geometric mean | RotD50 | RotD100 | RotD100 direction |")
    print("|---|---|---|---|---|---|---|")
    for i, period in enumerate(spectra["periods"]):
        cells = [significant(pair[k]["A_g"][i])
                 for k in ("h1", "h2", "geometric_mean", "rotd50", "rotd100")]
        print(f"| {period:g} | " + " | ".join(cells) + f" | {pair['rotd100']['angle'][i]:.1f}° |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
