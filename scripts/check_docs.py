#!/usr/bin/env python3
"""Checks that the printed outputs the docs quote are what the commands print today.

A block of a page is checked when a marker stands before it:

    <!-- output of: isolab run models/buildings/five_story_table9.yaml | ignore: Newton: -->
    ```
    ...what the page says the command prints...
    ```

The command runs in a scratch folder that sees the repository's files (so `models/...` and
`ground_motions/...` resolve and a default results file lands in the scratch folder), with
`isolab` replaced by the binary given. Every line of the block, except those starting with an
`ignore:` prefix (comma-separated; for wall times and file names), must appear in the command's
stdout, in order: the same text, and every number within half a unit of its last printed digit
(the value the page rounds to). A page whose numbers drift from the code fails, naming the page, the line and
what the command printed instead.

Usage: check_docs.py --isolab BUILD/isolab [--root REPO] [PAGE.md ...]
(default pages: README.md and docs/*.md)
"""

import argparse
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

MARKER = re.compile(r"<!--\s*output of:\s*(?P<command>.+?)(?:\s*\|\s*ignore:\s*(?P<ignore>.+?))?\s*-->")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def blocks(page):
    """(line number, command, ignored prefixes, expected lines) of each marked block."""
    lines = page.read_text(encoding="utf-8").splitlines()
    found = []
    for i, line in enumerate(lines):
        marker = MARKER.fullmatch(line.strip())  # a marker is a line of its own
        if not marker:
            continue
        start = i + 1
        while start < len(lines) and not lines[start].strip():
            start += 1
        if start >= len(lines) or not lines[start].startswith("```"):
            raise SystemExit(f"{page}:{i + 1}: a marker must stand before a fenced block")
        end = start + 1
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        ignore = [p.strip() for p in (marker.group("ignore") or "").split(",") if p.strip()]
        found.append((start + 2, marker.group("command"), ignore, lines[start + 1:end]))
    return found


def digit_half(text):
    """Half a unit of the last printed digit of a number as written."""
    mantissa = re.split(r"[eE]", text)[0]
    exponent = int(re.split(r"[eE]", text)[1]) if re.search(r"[eE]", text) else 0
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (exponent - decimals)


def same(expected, actual):
    """Whether a printed line matches the page's: equal text, each number the one the page
    rounds."""
    e_numbers, a_numbers = NUMBER.findall(expected), NUMBER.findall(actual)
    e_text = " ".join(NUMBER.sub("#", expected).split())
    a_text = " ".join(NUMBER.sub("#", actual).split())
    if e_text != a_text or len(e_numbers) != len(a_numbers):
        return False
    for e, a in zip(e_numbers, a_numbers):
        ev, av = float(e), float(a)
        if abs(ev - av) > 1.0001 * digit_half(e):
            return False
    return True


def link_repository(root, folder):
    """Links in `folder` to the repository's top-level files and folders."""
    for entry in root.iterdir():
        if not entry.name.startswith(".") and not entry.name.startswith("build"):
            (folder / entry.name).symlink_to(entry)


def check(page, binary, root):
    failures = 0
    for line_number, command, ignore, expected in blocks(page):
        words = shlex.split(command)
        if words[0] != "isolab":
            raise SystemExit(f"{page}:{line_number - 2}: the command must start with isolab")
        with tempfile.TemporaryDirectory(prefix="isolab_docs_") as folder:
            link_repository(root, pathlib.Path(folder))
            done = subprocess.run([str(binary), *words[1:]], cwd=folder, capture_output=True,
                                  text=True)
        printed = done.stdout.splitlines()
        at = 0
        for offset, line in enumerate(expected):
            if not line.strip() or any(line.lstrip().startswith(p) for p in ignore):
                continue
            match = next((k for k in range(at, len(printed)) if same(line, printed[k])), None)
            if match is None:
                shape = " ".join(NUMBER.sub("#", line).split())
                nearest = next((p for p in printed[at:]
                                if " ".join(NUMBER.sub("#", p).split()) == shape), "(no such line)")
                print(f"{page}:{line_number + offset}: `{command}` no longer prints\n"
                      f"  page:    {line}\n  printed: {nearest}\n  (exit {done.returncode}; "
                      f"stderr: {done.stderr.strip()[:300]})")
                failures += 1
                break
            at = match + 1
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--isolab", required=True, type=pathlib.Path)
    parser.add_argument("--root", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parents[1])
    parser.add_argument("pages", nargs="*", type=pathlib.Path)
    args = parser.parse_args()
    root = args.root.resolve()
    pages = args.pages or [root / "README.md", *sorted((root / "docs").glob("*.md"))]
    checked = sum(len(blocks(page)) for page in pages)
    failures = sum(check(page, args.isolab.resolve(), root) for page in pages)
    print(f"{checked} quoted outputs checked in {len(pages)} pages, {failures} out of date")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
