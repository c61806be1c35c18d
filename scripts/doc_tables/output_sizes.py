#!/usr/bin/python3
"""Prints docs/run.md's table of results-file size and peak memory against the output options
(standard library only): `isolab run MODEL -o FILE OPTIONS` in a scratch folder for each set of
options, the file's size in MB (10^6 bytes; kB below 1 MB) and the child's maximum resident set
in MiB. The memory depends on the machine and its libraries: the page checks the sizes only.

    output_sizes.py ISOLAB MODEL
"""
import os
import shlex
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# (the page's label, isolab run's options)
OPTIONS = (
    ("(every history, every step)", ""),
    ("`--quantities isolator,energy --levels 0,roof`",
     "--quantities isolator,energy --levels 0,roof"),
    ("`--every 10`", "--every 10"),
    ("`--summary-only`", "--summary-only"),
)


def size(n):
    """A file's size as the page writes it: three significant digits, in MB or kB."""
    if n >= 1e6:
        value, unit = n / 1e6, "MB"
    else:
        value, unit = n / 1e3, "kB"
    return f"{value:.{max(0, 2 - len(str(int(value))) + 1)}f} {unit}"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    isolab, model = sys.argv[1:]
    print("| options | file | peak memory |")
    print("|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="isolab_sizes_") as folder:
        for label, options in OPTIONS:
            path = os.path.join(folder, "run.h5")
            child = subprocess.Popen([isolab, "run", os.path.join(ROOT, model), "-o", path,
                                      *shlex.split(options)], stdout=subprocess.DEVNULL)
            _, status, usage = os.wait4(child.pid, 0)  # this child's own peak, not the largest
            child.returncode = os.waitstatus_to_exitcode(status)
            if child.returncode != 0:
                sys.exit(f"isolab run {model} {options}: exit {child.returncode}")
            print(f"| {label} | {size(os.path.getsize(path))} | {usage.ru_maxrss / 1024:.1f} MiB |")
            os.remove(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
