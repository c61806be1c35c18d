#!/usr/bin/python3
"""Prints docs/results.md's tables of the HDF5 results file as the files themselves have them
(needs Debian's python3-h5py): `isolab run` of bundled models that between them write every
dataset and attribute (an SDOF, the one-direction and the plan five-story buildings, and the plan
building on friction pendulums with axial loads and a vertical record), then, for each row of the
page's table, the names it documents that the files hold, with

    datasets    each dataset's units, in the page's symbols (L, F, T from the file's `units`)
    attributes  each root attribute's type (str, int, float, str array)

A name of the page that no file holds is printed with "(not written)", and a name that the files
hold and no row names is printed as a row of its own, "(not on the page)": either fails the page's
check. A row's names are backquoted and comma-separated; a name without a slash is a sibling of
the row's first (`/peaks/isolators/displacement`, `force`); `<name>` stands for every dataset of
its group that no other row names; `a`, ..., `b` for every name that starts as both do.

    results_layout.py ISOLAB {datasets,attributes}
"""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from page_rows import ROOT, first_cells

MODELS = ("models/sdof/table7_thm1_hard.yaml", "models/buildings/five_story_table9.yaml",
          "models/plan/five_story_table9_plan.yaml", "models/plan/five_story_fp_plan.yaml")
HEADERS = {"datasets": "| dataset | shape | units | meaning |",
           "attributes": "| attribute | type | meaning |"}
SUPERSCRIPTS = {"2": "²", "3": "³"}


def names_of(cell):
    """The names a row documents, as (exact names, prefix patterns, wildcard groups)."""
    items = re.findall(r"`([^`]+)`", cell)
    exact, prefixes, groups = [], [], []
    if "..." in cell:  # `a`, `b`, ..., `c`: the names that start as both ends do
        prefixes.append(os.path.commonprefix([items[0], items[-1]]).rstrip("_"))
        return exact, prefixes, groups
    parent = items[0].rsplit("/", 1)[0] if "/" in items[0] else ""
    for item in items:
        name = item if "/" in item or not parent else f"{parent}/{item}"
        if name.endswith("/<name>") or name.endswith("/<term>"):
            groups.append(name.rsplit("/", 1)[0])
        else:
            exact.append(name)
    return exact, prefixes, groups


def symbols(units, system):
    """A unit string of the file (kN*mm, mm/s^2) in the page's symbols (F·L, L/T²)."""
    names = dict(re.findall(r"(force|length|time) (\S+?)(?:,|$)", system))
    letters = {names["force"]: "F", names["length"]: "L", names["time"]: "T"}
    out = re.sub(r"[A-Za-z]+", lambda m: letters.get(m.group(0), m.group(0)), units)
    out = re.sub(r"\^(\d)", lambda m: SUPERSCRIPTS[m.group(1)], out)
    return out.replace("*", "·")


def type_of(value):
    if isinstance(value, (bytes, str)):
        return "str"
    if isinstance(value, np.ndarray) and value.dtype.kind in "OSU":
        return "str array"
    if isinstance(value, (int, np.integer)):
        return "int"
    return "float"


def written(isolab, folder):
    """{dataset path: its units in symbols} and {root attribute: type} over every model's file."""
    datasets, attributes = {}, {}
    for k, model in enumerate(MODELS):
        path = os.path.join(folder, f"r{k}.h5")
        subprocess.run([isolab, "run", os.path.join(ROOT, model), "-q", "-o", path,
                        "--free-vibration", "0"], check=True, stdout=subprocess.DEVNULL)
        with h5py.File(path, "r") as f:
            system = f.attrs["units"]
            system = system.decode() if isinstance(system, bytes) else system
            for name, value in f.attrs.items():
                attributes.setdefault(name, type_of(value))

            def visit(name, node):
                if isinstance(node, h5py.Dataset):
                    units = node.attrs.get("units", "")
                    units = units.decode() if isinstance(units, bytes) else units
                    datasets.setdefault("/" + name, symbols(units, system) if units else "")
            f.visititems(visit)
    return datasets, attributes


def described(values, groups):
    """A row's units or types in the page's form: one for the row when its names agree, else one
    per name ("L, F, L"); a `<name>` group's distinct ones ("L, F, L/T² or rad")."""
    if groups:
        values, last = list(dict.fromkeys(values)), " or "
    elif len(set(values)) <= 1:
        values, last = values[:1], ", "
    else:
        last = ", "
    return ", ".join(values[:-1]) + last + values[-1] if len(values) > 1 else "".join(values)


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in HEADERS:
        sys.exit(__doc__)
    which = sys.argv[2]
    with tempfile.TemporaryDirectory(prefix="isolab_layout_") as folder:
        datasets, attributes = written(os.path.abspath(sys.argv[1]), folder)
    held = datasets if which == "datasets" else attributes

    def row(name, value):  # the page's columns: name, (shape,) units or type, meaning
        return f"| {name} | | {value} | |" if which == "datasets" else f"| {name} | {value} | |"

    rows = [(cell, *names_of(cell)) for cell in first_cells("results.md", HEADERS[which])]
    named = {n for _, exact, _, _ in rows for n in exact}
    unclaimed = set(held) - named
    print(HEADERS[which])
    print("|" + "---|" * (HEADERS[which].count(" | ") + 1))
    for cell, exact, prefixes, groups in rows:
        found = [n for n in exact if n in held]
        found += sorted(n for n in unclaimed if any(n.startswith(p) for p in prefixes))
        found += sorted(n for n in unclaimed if any(n.rsplit("/", 1)[0] == g for g in groups))
        unclaimed -= set(found)
        missing = [n for n in exact if n not in held] or ([] if found else ["any"])
        label = cell + (f" (not written: {', '.join(missing)})" if missing else "")
        # a family (`a`, ..., `b`): the page gives its members' types with the first component's
        print(row(label, "" if prefixes else described([held[n] for n in found], groups)))
    for name in sorted(unclaimed):
        print(row(f"`{name}` (not on the page)", held[name]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
