#!/usr/bin/python3
"""Prints the Markdown table a test prints as it runs (standard library only), for a page that
quotes a test's measured differences: the test executable of the build that holds ISOLAB
(`BUILD/tests/EXECUTABLE`, built by `scripts/setup.sh --tests`) runs the tests FILTER selects,
from the repository's root as ctest runs it, and every line of its output that is a table row
(starts with `|`) is printed in order. Such a test prints its table's header once and a row
per case, the page's words and the digits its own checks bound. A test that fails prints no
table here: its numbers are not the ones a page may quote.

    test_printout.py ISOLAB EXECUTABLE FILTER
"""
import os
import subprocess
import sys

from page_rows import ROOT


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__.strip().splitlines()[-1].strip())
    isolab, executable, test_filter = sys.argv[1:]
    path = os.path.join(os.path.dirname(os.path.abspath(isolab)), "tests", executable)
    if not os.access(path, os.X_OK):
        sys.exit(f"{path}: no such test executable (scripts/setup.sh --tests builds it)")
    done = subprocess.run([path, f"--gtest_filter={test_filter}"], cwd=ROOT, capture_output=True,
                          text=True)
    if done.returncode != 0 or "[  PASSED  ]" not in done.stdout:
        sys.exit(f"{executable} --gtest_filter={test_filter}: exit {done.returncode}\n"
                 f"{done.stdout[-2000:]}{done.stderr[-1000:]}")
    rows = [line for line in done.stdout.splitlines() if line.startswith("|")]
    if not rows:
        sys.exit(f"{executable} --gtest_filter={test_filter} printed no table row")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
