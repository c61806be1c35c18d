#!/usr/bin/python3
"""Runs an isolab command on the BNCS motions as docs/bncs.md writes it (standard library only):
each word `ica50.csv` or `lac100.csv` of the command becomes that motion, unpacked under that name
into a scratch folder from the measurements (bncs_data.py), and the command's stdout is printed as
it is. The
measurements are not in the repository, so scripts/check_docs.py runs this with --opt-in only.

    bncs_motions.py ISOLAB COMMAND...   e.g. bncs_motions.py isolab fit ica50.csv lac100.csv ...
"""
import os
import subprocess
import sys
import tempfile

from bncs_data import unpack_motion

MOTIONS = {"ica50.csv": "ica50", "lac100.csv": "lac100"}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    isolab = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="isolab_bncs_") as folder:
        words = [unpack_motion(MOTIONS[w], folder, name=w) if w in MOTIONS else w
                 for w in sys.argv[2:]]
        return subprocess.run([isolab, *words]).returncode


if __name__ == "__main__":
    sys.exit(main())
