#!/usr/bin/python3
"""Prints docs/errors.md's table of exit codes with each code as isolab returns it (standard
library only): for each code the page lists, one of the page's examples is run in a scratch
folder (a run that completes; a run that blows up, its isolator softening without bound; a model
with an unknown key; a run whose results file grows past the process's file size limit, which
the kernel refuses as "File too large"), and the row is the page's own with the code isolab
exited with, and its stderr checked to say why. A page that gives an example another code than
isolab's then differs in that cell; a code no probe here provokes prints "(not probed)".

    exit_codes.py ISOLAB
"""
import os
import resource
import signal
import subprocess
import sys
import tempfile

from page_rows import ROOT, body_rows

HEADER = "| code | meaning | examples |"
SDOF = os.path.join(ROOT, "models", "sdof", "table7_thm1_hard.yaml")
PULSE = os.path.join(ROOT, "ground_motions", "pulse_tp2.at2")

# An isolator whose stiffness turns negative after yield pushes the mass away ever faster.
SOFTENING = f"""units: {{force: kN, length: mm, time: s}}
structure: {{type: sdof, mass: 31.7 t, damping: {{ratio: 0.02}}}}
isolation:
  components:
    - {{name: bearing, type: thm1, k0: 1.0, k1: -0.2, k2: -0.45, uy: 20, uyh: 120}}
excitation:
  ground_motion: {{file: {PULSE}}}
analysis: {{dt: 0.01}}
"""


def small_files_only():
    """In the child: files past 64 KiB refused with EFBIG instead of killing it (SIGXFSZ)."""
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (64 * 1024, 64 * 1024))


def exit_code(folder, command, says, limit_files=False):
    """isolab's exit code for `command`, its stderr required to contain `says`."""
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True,
                          preexec_fn=small_files_only if limit_files else None)
    if says not in done.stderr:
        sys.exit(f"{' '.join(command)}: exit {done.returncode} without '{says}' on stderr: "
                 f"{done.stderr.strip()[-300:]}")
    return done.returncode


def probes(isolab, folder):
    """{the page's code: the code isolab exits with on one of that row's examples}."""
    with open(os.path.join(folder, "softening.yaml"), "w") as f:
        f.write(SOFTENING)
    with open(os.path.join(folder, "unknown_key.yaml"), "w") as f:
        f.write(open(SDOF, encoding="utf-8").read().replace("analysis:", "analysis_:", 1))
    return {
        "0": exit_code(folder, [isolab, "run", SDOF, "-q", "-o", "ok.h5"], ""),
        "1": exit_code(folder, [isolab, "run", "softening.yaml", "-q", "-o", "up.h5"],
                       "blow-up at t = "),
        "2": exit_code(folder, [isolab, "run", "unknown_key.yaml", "-q", "-o", "bad.h5"],
                       "unknown_key.yaml:"),
        "3": exit_code(folder, [isolab, "run", SDOF, "-q", "-o", "big.h5"], "File too large",
                       limit_files=True),
    }


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-1].strip())
    isolab = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="isolab_exit_codes_") as folder:
        codes = probes(isolab, folder)
        left = sorted(os.listdir(folder))
    if "big.h5" in left or "bad.h5" in left:
        sys.exit(f"a refused run left its results file: {left}")
    print(HEADER)
    print("|---|---|---|")
    for code, meaning, examples in body_rows("errors.md", HEADER):
        probed = codes.get(code)
        print(f"| {probed if probed is not None else code + ' (not probed)'} | {meaning} | "
              f"{examples} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
