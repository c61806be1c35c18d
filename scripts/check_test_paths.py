#!/usr/bin/env python3
"""Fails when a test names a fixed temporary path, or works outside its own folder.

A test reads only what the repository holds and what it wrote itself into a directory of its own
(tests/own_test_file.h; pytest's tmp_path). A fixed path under /tmp, or a file named directly in
GoogleTest's TempDir() or std::filesystem::temp_directory_path(), is shared by every process and
every checkout on the machine: a test that reads one may pass only where an earlier run left the
file, and two tests writing one race under `ctest -j`. A command a test runs from the
filesystem's root (`cd / && isolab run ...`) or the user's home writes its default outputs
there, outside the test's folder (and fails for a user who may not write there).

Usage: check_test_paths.py [ROOT]   (ROOT: the repository, default this script's parent's parent)
Prints each offending line as FILE:LINE: TEXT and exits 1; exits 0 when there is none.
"""
import pathlib
import re
import sys

# The one place allowed to ask for the temporary directory: it makes a folder per test process.
ALLOWED = {"tests/own_test_file.h"}
PATTERNS = [
    re.compile(r"""["']/tmp(/|["'])"""),        # a literal /tmp path
    re.compile(r"\bTempDir\s*\(\s*\)"),           # GoogleTest's shared temporary directory
    re.compile(r"\btemp_directory_path\s*\("),    # std::filesystem's
    re.compile(r"\btempfile\.gettempdir\s*\("),   # Python's
    re.compile(r"""\bcd\s+/(\s|&|;|["'])"""),       # a command run from the filesystem's root
    re.compile(r"""["']~/"""),                    # the user's home, by either name
    re.compile(r"""getenv\s*\(\s*["']HOME["']|environ\s*\[\s*["']HOME["']|expanduser"""),
]
SUFFIXES = {".cpp", ".h", ".py", ".sh"}
FOLDERS = ["tests", "python/tests"]


def offending_lines(root: pathlib.Path):
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            relative = path.relative_to(root).as_posix()
            if path.suffix not in SUFFIXES or not path.is_file() or relative in ALLOWED:
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                code = line.split("//")[0] if path.suffix in {".cpp", ".h"} else line
                if any(pattern.search(code) for pattern in PATTERNS):
                    yield f"{relative}:{number}: {line.strip()}"


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else __file__).resolve()
    if len(sys.argv) <= 1:
        root = root.parent.parent
    found = list(offending_lines(root))
    for line in found:
        print(line)
    if found:
        print(f"check_test_paths: {len(found)} line(s) name a fixed temporary path or work outside "
              "the test's folder; use "
              "tests/own_test_file.h (C++) or pytest's tmp_path", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
