#!/usr/bin/python3
"""Prints docs/convergence.md's tables as benchmarks/convergence_study.py makes them, without
rewriting the page: for `scripts/check_docs.py --opt-in`, which compares their errors, orders and
counts (about a minute; needs python3-h5py). The wall times are one machine's and are not
compared.

    convergence.py ISOLAB
"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    study = os.path.join(ROOT, "benchmarks", "convergence_study.py")
    sys.exit(subprocess.run(["/usr/bin/python3", study, "--isolab", sys.argv[1], "--out", "-"])
             .returncode)
