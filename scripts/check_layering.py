#!/usr/bin/env python3
"""Prints which area of isolab includes which, and fails on an include the layering forbids.

Areas depend one way (docs/architecture.md):

  core <- hysteresis <- structure <- integrators <- spectra
       <- identification <- diagnosis
       <- io (formats) <- model (schemas) <- analysis <- building         <- cli, python
                                       model <- cyclic <- building
                                   analysis, cyclic <- design <- study <- cli, python

An area may include its own headers and those of the areas listed for it in ALLOWED, nothing
else: a lower area never sees a higher one (hysteresis knows no YAML, no files, no integrator).
The table is what the code uses, no more: an allowance none of an area's files takes is refused,
and so is a table that lets an area reach itself.
A relative include ("../x/y.h") that leaves the area's folder is refused whatever it reaches: it
would pass another area's private header through the table unseen. Every source belongs to an
area: a file directly under src/ or include/isolab/ is refused.
Third-party headers are checked too where an area must not see them (yaml-cpp outside model,
HDF5 outside io and analysis, MPI outside study, SUNDIALS outside integrators).

Usage: check_layering.py [ROOT]   (ROOT: the repository; default this script's parent's parent)
Exit status 1 when an include breaks the rules, each printed as FILE:LINE: what and why.
"""
import pathlib
import re
import sys

ALLOWED = {
    "core": set(),
    "hysteresis": {"core"},
    "structure": {"hysteresis"},
    "integrators": {"core", "hysteresis", "structure"},
    "spectra": {"core", "hysteresis", "structure", "integrators"},
    "identification": {"core", "hysteresis"},
    "diagnosis": {"core", "hysteresis", "identification"},
    "io": {"core", "hysteresis", "spectra", "identification"},
    "model": {"core", "hysteresis", "structure", "integrators", "spectra", "identification", "io"},
    "analysis": {"core", "hysteresis", "structure", "integrators", "spectra", "identification",
                 "io", "model"},
    "cyclic": {"core", "hysteresis", "identification", "diagnosis", "io", "model"},
    "building": {"core", "hysteresis", "structure", "identification", "diagnosis", "io", "model",
                 "analysis", "cyclic"},
    "design": {"core", "hysteresis", "spectra", "io", "model", "analysis", "cyclic"},
    "study": {"core", "hysteresis", "integrators", "spectra", "identification", "io", "model",
              "analysis", "design"},
    "cli": {"core", "hysteresis", "integrators", "spectra", "identification", "diagnosis", "io",
            "model", "analysis", "cyclic", "building", "design", "study"},
    "python": {"core", "hysteresis", "spectra", "identification", "io", "model", "analysis",
               "cyclic", "building", "study"},
}


def cycle_in(table):
    """An area that reaches itself through the table, or None: the order must stay one way."""
    state = {}

    def visit(area):
        state[area] = "open"
        for below in table[area]:
            if state.get(below) == "open" or (below not in state and visit(below)):
                return True
        state[area] = "done"
        return False

    return next((area for area in table if area not in state and visit(area)), None)


# Third-party headers and the only areas that may include them.
THIRD_PARTY = [
    (re.compile(r"^yaml-cpp/"), {"model", "python"}),
    (re.compile(r"^(hdf5|H5)"), {"io", "analysis"}),
    (re.compile(r"^mpi\.h$"), {"study"}),
    (re.compile(r"^(ida|idas|sundials|sunlinsol|sunmatrix|nvector)/"), {"integrators"}),
    (re.compile(r"^(klu|suitesparse/)"), {"integrators"}),
    (re.compile(r"^pagmo/"), {"identification"}),
]
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')


def area_of(path: pathlib.Path, root: pathlib.Path):
    parts = path.relative_to(root).parts
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    if parts[:2] == ("include", "isolab") and len(parts) > 3:
        return parts[2]
    if parts[:2] == ("python", "src"):
        return "python"
    return None


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    root = root.resolve()
    uses = {}
    seen = set()
    problems = []
    looped = cycle_in(ALLOWED)
    if looped:
        problems.append(f"the layering table lets {looped} reach itself: areas depend one way")
    files = sorted(p for folder in ("src", "include/isolab", "python/src")
                   for p in (root / folder).rglob("*") if p.suffix in (".h", ".cpp"))
    for path in files:
        area = area_of(path, root)
        if area is None:
            problems.append(f"{path.relative_to(root)}: belongs to no area (sources live in "
                            "src/<area>/, public headers in include/isolab/<area>/)")
            continue
        if area not in ALLOWED:
            problems.append(f"{path.relative_to(root)}: area '{area}' is not in the layering table")
            continue
        seen.add(area)
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            header = match.group(1)
            where = f"{path.relative_to(root)}:{number}"
            if ".." in pathlib.PurePosixPath(header).parts:
                reached = (path.parent / header).resolve()
                folder = path.parent
                while folder.name != area and folder != root:
                    folder = folder.parent
                if folder not in reached.parents:
                    problems.append(f"{where}: {area} includes \"{header}\" by a relative path "
                                    f"out of its folder: include a public header as "
                                    f"isolab/<area>/..., or keep the header in {area}")
                continue
            if header.startswith("isolab/"):
                target = header.split("/")[1]
                if target == area:
                    continue
                uses.setdefault(area, set()).add(target)
                if target not in ALLOWED[area]:
                    problems.append(f"{where}: {area} includes {header}: {target} is above it "
                                    f"(or beside it); {area} may include "
                                    f"{', '.join(sorted(ALLOWED[area])) or 'nothing of isolab'}")
                continue
            for pattern, areas in THIRD_PARTY:
                if pattern.search(header) and area not in areas:
                    problems.append(f"{where}: {area} includes <{header}>, which only "
                                    f"{', '.join(sorted(areas))} may include")
    # The table is what the code uses: an allowance nothing takes is a door left open.
    for area in sorted(seen):
        unused = ALLOWED[area] - uses.get(area, set())
        if unused:
            problems.append(f"the layering table lets {area} include {', '.join(sorted(unused))}, "
                            f"which none of its files does: drop it from ALLOWED")
    for area in ALLOWED:
        print(f"{area:15} includes {', '.join(sorted(uses.get(area, ()))) or '-'}")
    for problem in problems:
        print(problem)
    if problems:
        print(f"check_layering: {len(problems)} problem(s) with the layering", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
