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

A Markdown table of numbers is checked the same way, cell by cell, against the table its
command prints (the first Markdown table of its stdout):

    <!-- table from: scripts/doc_tables/study_means.py isolab models/studies/x.yaml -->
    | variant | isolator [mm] | ...
    |---|---|...

The command is `isolab ...` or a script under `scripts/` or `benchmarks/` (run with /usr/bin/python3
or bash), every word `isolab` replaced by the binary. The two tables must have the same rows and columns; each
cell the same text and each number within half a unit of the page's last digit. `columns:`
(1-based, `2-6` or `1,3`) limits the check to those columns, for a column the command cannot
reproduce (wall times); `table: 2` compares with the second table the command prints, for a
command that prints two (its runs done once). Every table with a number in its body must carry a
marker: one the checker does not run says why, and the checker prints it:

    <!-- table from: scripts/doc_tables/bncs_predictions.py isolab lac100 | opt-in: needs ../shared -->
    <!-- table from: callgrind of ... | not checked: instruction counts of one machine -->

`opt-in:` tables run only with `--opt-in` (slow runs, or data a clone lacks); `not checked:` ones
never (measurements of one machine, reference values). A table a test measures is printed by the
test itself and read back by scripts/doc_tables/test_printout.py. `--update` rewrites the
checked cells of each page from what the commands print (then read the diff, and the prose).

Usage: check_docs.py --isolab BUILD/isolab [--root REPO] [--opt-in] [--update] [PAGE.md ...]
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


def tracked_top_level(root):
    """The top-level names git tracks, or None outside a git checkout."""
    try:
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True,
                                check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    return {path.split("/", 1)[0] for path in listed.decode().split("\0") if path}


# What isolab writes (results, tables, figures): outside a git checkout, such a file at the top
# level is taken for a command's output rather than a source.
RESULT_SUFFIXES = {".h5", ".csv", ".png", ".pdf", ".json"}


def link_repository(root, folder):
    """Links in `folder` to the repository's top-level files and folders: the sources only, not
    the results a command left in the checkout (the README's first command writes
    five_story_table9.h5 there; linked, the same command here would be refused its output)."""
    tracked = tracked_top_level(root)
    for entry in root.iterdir():
        if entry.name.startswith(".") or entry.name.startswith("build"):
            continue
        if tracked is None:
            if entry.is_file() and entry.suffix in RESULT_SUFFIXES:
                continue
        elif entry.name not in tracked:
            continue
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


TABLE_MARKER = re.compile(r"<!--\s*table from:\s*(?P<body>.+?)\s*-->")
SEPARATOR = re.compile(r"\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?")
KEYS = ("columns", "table", "opt-in", "not checked")


def cells(line):
    """The cells of a Markdown table row; `\\|` is a bar inside a cell."""
    inner = line.strip()
    inner = inner[1:] if inner.startswith("|") else inner
    inner = inner[:-1] if inner.endswith("|") and not inner.endswith("\\|") else inner
    return [c.strip() for c in re.split(r"(?<!\\)\|", inner)]


def markdown_tables(lines):
    """(first line index, [(line index, cells)] without the separator) of each table outside
    fenced blocks."""
    found, fenced, i = [], False, 0
    while i < len(lines):
        if lines[i].startswith("```"):
            fenced = not fenced
        elif (not fenced and lines[i].lstrip().startswith("|") and i + 1 < len(lines)
              and SEPARATOR.fullmatch(lines[i + 1].strip())):
            rows, j = [(i, cells(lines[i]))], i + 2
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                rows.append((j, cells(lines[j])))
                j += 1
            found.append((i, rows))
            i = j
            continue
        i += 1
    return found


def has_number(rows):
    """Whether a table quotes numbers: a body cell that starts with one once its code spans (keys,
    files, formulas) are dropped. A table of words that mentions "HDF5" or "ASCE 7" does not."""
    return any(re.match(r"[-+<>=~≈±−(]*\s*\.?\d", re.sub(r"`[^`]*`", "", cell).strip())
               for _, row in rows[1:] for cell in row)


def parse_columns(text, where):
    chosen = set()
    for part in text.split(","):
        bounds = part.strip().split("-")
        if not all(b.strip().isdigit() for b in bounds) or len(bounds) > 2:
            raise SystemExit(f"{where}: columns: '{text}' (must be like 2-6 or 1,3)")
        chosen.update(range(int(bounds[0]), int(bounds[-1]) + 1))
    return chosen


def table_markers(page):
    """(marker line, source, options, table start, rows) of each table; a table of numbers
    without a marker, or a marker before no table, is an error of the page."""
    lines = page.read_text(encoding="utf-8").splitlines()
    tables = {start: rows for start, rows in markdown_tables(lines)}
    found, errors, marked = [], [], set()
    for i, line in enumerate(lines):
        marker = TABLE_MARKER.fullmatch(line.strip())
        if not marker:
            continue
        start = i + 1
        while start < len(lines) and not lines[start].strip():
            start += 1
        if start not in tables:
            raise SystemExit(f"{page}:{i + 1}: a `table from:` marker must stand before a table")
        parts = [p.strip() for p in re.split(r"\s\|\s", marker.group("body"))]
        options = {}
        for part in parts[1:]:
            key, _, value = part.partition(":")
            if key.strip() not in KEYS or not value.strip():
                raise SystemExit(f"{page}:{i + 1}: '{part}' (a marker's options are "
                                 f"{', '.join(k + ': ...' for k in KEYS)})")
            options[key.strip()] = value.strip()
        marked.add(start)
        found.append((i + 1, parts[0], options, start, tables[start]))
    for start, rows in tables.items():
        for index, row in rows[1:]:  # a `|` inside a code span splits a cell unless escaped
            if len(row) != len(rows[0][1]):
                errors.append(f"{page}:{index + 1}: {len(row)} cells in a table of "
                              f"{len(rows[0][1])} columns (a bar inside a cell is written \\|)")
        if start not in marked and has_number(rows):
            errors.append(f"{page}:{start + 1}: a table of numbers without a `table from:` "
                          f"marker (scripts/check_docs.py says how): | {' | '.join(rows[0][1])} |")
    return found, errors


def run_source(source, binary, root, cache):
    """stdout, stderr and exit status of a table's command, run once per checker run."""
    if source not in cache:
        words = [str(binary) if w == "isolab" else w for w in shlex.split(source)]
        if words[0].startswith(("scripts/", "benchmarks/")):
            interpreter = "/usr/bin/python3" if words[0].endswith(".py") else "bash"
            words = [interpreter, str(root / words[0]), *words[1:]]
        elif words[0] != str(binary):
            raise SystemExit(f"`{source}`: a table's command starts with isolab, scripts/ or "
                             f"benchmarks/")
        with tempfile.TemporaryDirectory(prefix="isolab_docs_") as folder:
            link_repository(root, pathlib.Path(folder))
            done = subprocess.run(words, cwd=folder, capture_output=True, text=True)
        cache[source] = done
    return cache[source]


def printed_table(stdout, number):
    """The header and body rows of the `number`-th (from 1) Markdown table a command prints."""
    tables = markdown_tables(stdout.splitlines())
    return [row for _, row in tables[number - 1][1]] if len(tables) >= number else None


def check_table(page, marker_line, source, options, rows, binary, root, cache, update):
    """Differences between a page's table and the one its command prints; with `update`, the
    page's lines rewritten to the printed cells (returned as {line index: text})."""
    done = run_source(source, binary, root, cache)
    number = options.get("table", "1")
    if not number.isdigit() or int(number) < 1:
        raise SystemExit(f"{page}:{marker_line}: table: {number} (the printed table's number, "
                         f"from 1)")
    printed = printed_table(done.stdout, int(number))
    where = f"{page}:{rows[0][0] + 1}"
    if printed is None:
        return [f"{where}: `{source}` printed no Markdown table number {number} "
                f"(exit {done.returncode}; stderr: {done.stderr.strip()[-300:]})"], {}
    if len(printed) != len(rows) or any(len(p) != len(r) for p, (_, r) in zip(printed, rows)):
        return [f"{where}: the table has {len(rows) - 1} rows of {len(rows[0][1])} columns, "
                f"`{source}` prints {len(printed) - 1} of {len(printed[0])}"], {}
    columns = (parse_columns(options["columns"], f"{page}:{marker_line}")
               if "columns" in options else set(range(1, len(rows[0][1]) + 1)))
    differences, rewritten = [], {}
    lines = page.read_text(encoding="utf-8").splitlines()
    for (index, row), got in zip(rows, printed):
        new = list(row)
        for c, (cell, printed_cell) in enumerate(zip(row, got), start=1):
            if c in columns and not same(cell, printed_cell):
                differences.append(f"{page}:{index + 1}: row '{row[0]}', column {c} "
                                   f"('{rows[0][1][c - 1]}'): page {cell!r}, printed "
                                   f"{printed_cell!r} (the command of line {marker_line})")
                new[c - 1] = printed_cell
        if new != row:  # the row rebuilt, indented as it was (a table in a list item)
            line = lines[index]
            rewritten[index] = line[:len(line) - len(line.lstrip())] + "| " + " | ".join(new) + " |"
    return differences, rewritten if update else {}


def check_tables(page, binary, root, cache, opt_in, update):
    """(checked, differences, skipped) of a page's tables; the page rewritten with `update`."""
    found, problems = table_markers(page)
    checked, skipped, rewritten = 0, [], {}
    for marker_line, source, options, start, rows in found:
        if "not checked" in options or ("opt-in" in options and not opt_in):
            why = options.get("not checked") or "opt-in (--opt-in): " + options["opt-in"]
            skipped.append(f"{page}:{start + 1}: from {source}; {why}")
            continue
        differences, lines = check_table(page, marker_line, source, options, rows, binary, root,
                                         cache, update)
        checked += 1
        problems += differences
        rewritten.update(lines)
    if rewritten:
        text = page.read_text(encoding="utf-8").splitlines()
        for index, line in rewritten.items():
            text[index] = line
        page.write_text("\n".join(text) + "\n", encoding="utf-8")
        print(f"{page}: rewrote {len(rewritten)} table rows from what the commands print")
    return checked, problems, skipped


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--isolab", required=True, type=pathlib.Path)
    parser.add_argument("--root", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parents[1])
    parser.add_argument("--opt-in", action="store_true",
                        help="also check the tables marked opt-in (slow, or data a clone lacks)")
    parser.add_argument("--update", action="store_true",
                        help="rewrite the checked table cells that differ from what is printed")
    parser.add_argument("pages", nargs="*", type=pathlib.Path)
    args = parser.parse_args()
    root = args.root.resolve()
    pages = args.pages or [root / "README.md", *sorted((root / "docs").glob("*.md"))]
    binary = args.isolab.resolve()
    checked = sum(len(blocks(page)) for page in pages)
    failures = sum(check(page, binary, root) for page in pages)
    cache, tables, skipped, problems = {}, 0, [], []
    for page in pages:
        n, page_problems, page_skipped = check_tables(page, binary, root, cache, args.opt_in,
                                                      args.update)
        tables, problems, skipped = tables + n, problems + page_problems, skipped + page_skipped
    for problem in problems:
        print(problem)
    if skipped:
        print(f"{len(skipped)} tables not run here, with why:")
        for line in skipped:
            print("  " + line)
    print(f"{checked} quoted outputs checked in {len(pages)} pages, {failures} out of date")
    print(f"{tables} tables checked against their commands, {len(problems)} out of date or unmarked"
          f"{' (rewritten: read the diff and the prose)' if args.update and problems else ''}")
    return 1 if failures or problems or checked + tables == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
