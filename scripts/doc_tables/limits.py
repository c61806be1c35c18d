#!/usr/bin/python3
"""Prints docs/errors.md's table of isolab's limits as isolab enforces them (standard library only):
each limit is crossed once in a scratch folder (a run of 10^8 steps, a spectrum of 3 x 10^10 SDOF
steps, `compare -j` of 10^5 workers, a fit specification of 101 and of 110 components, a record
line of 70,000 characters and a header line of 5,000, a specification file of 65 MiB, a fit of
2.4 x 10^12 units of work), and the limit is read from isolab's refusal. Each row is the page's
own, with the numbers that open its default cell replaced by those the refusals name, written as
the page writes them (10^7, 65536); a page that quotes another limit than isolab's then differs
in that cell, and a limit the page lists but no probe here crosses prints "(not probed)".

    limits.py ISOLAB
"""
import math
import os
import re
import subprocess
import sys
import tempfile

from page_rows import ROOT, body_rows

HEADER = "| limit | default | raise it with |"
RECORD = os.path.join(ROOT, "ground_motions", "fwn_firm_seed1.at2")
SDOF = os.path.join(ROOT, "models", "sdof", "table7_thm1_hard.yaml")


def refusal(folder, *command):
    """isolab's message refusing `command`: its stderr, which must say why (exit 2)."""
    done = subprocess.run(list(command), cwd=folder, capture_output=True, text=True)
    if done.returncode != 2:
        sys.exit(f"{' '.join(command)}: exit {done.returncode}, expected a refusal (2): "
                 f"{done.stderr.strip()[-300:]}")
    return done.stderr


def number(pattern, text):
    found = re.search(pattern, text)
    if not found:
        sys.exit(f"no limit matching {pattern!r} in: {text.strip()[-300:]}")
    return float(found.group(1))


def write(folder, name, text):
    with open(os.path.join(folder, name), "w") as f:
        f.write(text)
    return name


def probes(isolab, folder):
    """{the page's first words of a row: the limits isolab's refusals name, in the cell's order}."""
    specification = "units: {force: kN, length: mm}\ncomponents:\n"
    subprocess.run([isolab, "cyclic", os.path.join(ROOT, "models/diagnosis/null.yaml"), "-a", "10",
                    "-T", "2", "-n", "1", "--test-data", "test.csv"], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL)
    many = write(folder, "many.yaml", specification + "".join(
        f"  - {{type: bhm2, count: 10, name: g{k}}}\n" for k in range(11)))
    one = write(folder, "one.yaml", specification + "  - {type: bhm2, count: 101}\n")
    write(folder, "long.at2", "x" * 70000 + "\n")
    write(folder, "header.at2", "x" * 5000 + "\n")
    with open(os.path.join(folder, "large.yaml"), "w") as f:
        f.write(specification)
        f.write(("  - {type: bhm2, count: 1}  # " + "x" * 1000 + "\n") * (65 * 1024))
    fit = [isolab, "fit", "test.csv", "-q", "--model"]
    return {
        "analysis steps of a run": [number(r"limit of (\d+) steps", refusal(
            folder, isolab, "run", SDOF, "--dt", "1e-7", "-o", "r.h5"))],
        "SDOF steps of a spectrum": [number(r"more than the ([0-9.e+]+) allowed", refusal(
            folder, isolab, "spectrum", RECORD, "--periods", "0.1", "--points-per-period",
            "100000000", "-o", "s.csv"))],
        "`compare -j` worker processes": [number(r"\((\d+) per hardware thread\)", refusal(
            folder, isolab, "compare", os.path.join(ROOT, "models/studies/five_story_bearings.yaml"),
            "-j", "100000", "-o", "study"))],
        "components of a fit specification": [
            number(r"at most (\d+):", refusal(folder, *fit, many)),
            *(float(n) for n in re.search(r"must be (\d+) to (\d+)",
                                          refusal(folder, *fit, one)).groups())],
        "a line of any text input": [
            number(r"more than (\d+) characters", refusal(
                folder, isolab, "run", SDOF, "--record", "long.at2", "-o", "r.h5")),
            number(r"header lines have at most (\d+)", refusal(
                folder, isolab, "run", SDOF, "--record", "header.at2", "-o", "r.h5"))],
        "a YAML file": [number(r"more than the (\d+) MiB", refusal(folder, *fit, "large.yaml"))],
        "work of a fit": [number(r"\(limit ([0-9.e+]+)\)", refusal(
            folder, *fit, os.path.join(ROOT, "models/fit/nine_thm1.yaml"), "--budget",
            "1000000000"))],
    }


NUMBER = re.compile(r"\d+\^\d+|\d[\d,]*")


def as_page_writes(value, token):
    """`value` as the page's `token` is written: 10^k, or a whole number."""
    if "^" in token:
        power = round(math.log10(value))
        return f"10^{power}" if value == 10 ** power else f"{value:g}"
    return f"{value:,.0f}" if "," in token else f"{value:.0f}"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    isolab = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="isolab_limits_") as folder:
        limits = probes(isolab, folder)
    print(HEADER)
    print("|---|---|---|")
    for limit, default, _ in body_rows("errors.md", HEADER):
        probed = next((v for k, v in limits.items() if limit.startswith(k)), None)
        if probed is None:
            print(f"| {limit} | {default} (not probed) | |")
            continue
        tokens = NUMBER.findall(default)[:len(probed)]
        pieces = NUMBER.split(default, maxsplit=len(tokens))
        cell = pieces[0] + "".join(as_page_writes(v, t) + p
                                   for v, t, p in zip(probed, tokens, pieces[1:]))
        print(f"| {limit} | {cell} | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
