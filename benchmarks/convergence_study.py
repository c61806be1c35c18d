#!/usr/bin/python3
"""Newmark's error against its step, with IDA at rtol = 1e-10 as the reference, and the work
each integrator needs for a given accuracy.

For each case, isolab runs the model with Newmark (average acceleration, full Newton) at steps
from 0.02 s to 0.0005 s and with IDA at tolerances from 1e-3 to 1e-9; errors are of the
isolator (SDOF) displacement at the record's 0.02 s sample times, relative to its peak. Wall time
is the integrator's own (RunSummary.wall_seconds), the best of three runs. The table goes to
stdout and to docs/convergence.md.

Usage: benchmarks/convergence_study.py [--isolab build/isolab] [--out docs/convergence.md | -]
(`--out -`: the tables to stdout only, as scripts/doc_tables/convergence.py prints them for the
docs check)
Reads the bundled ground_motions/elcentro_1940_ns.at2; needs Debian's python3-h5py.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EL_CENTRO = os.path.join(ROOT, "ground_motions", "elcentro_1940_ns.at2")
CASES = [
    ("Control: linear SDOF (Tn = 1 s, 2 %, Chopra Case C), El Centro: no events",
     "models/chopra/case_c_el_centro_sdof.yaml", [], "in"),
    ("Elastoplastic SDOF (Tn = 0.5 s, 5 %, fy = 0.25 f0), El Centro",
     "models/chopra/elastoplastic_sdof_el_centro.yaml", [], "in"),
    ("Five-story building on the Table 9 THM1 system, El Centro",
     "models/buildings/five_story_table9.yaml", ["--record", EL_CENTRO, "--scale", "1"], "mm"),
]
STEPS = [0.02, 0.01, 0.005, 0.002, 0.001, 0.0005]
TOLERANCES = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9]
REFERENCE_RTOL = 1e-10
SAMPLE = 0.02  # the record's step: errors are measured at these times
REPEATS = 3


def run(isolab, model, extra, options):
    """Runs isolab; returns (isolator displacement at the sample times, summary JSON)."""
    with tempfile.TemporaryDirectory() as scratch:
        output = os.path.join(scratch, "run.h5")
        best = None
        for _ in range(REPEATS):
            # The record alone: the error is measured over it, not over free vibration after it.
            command = ([isolab, "run", model, "--json", "-o", output, "--free-vibration", "0"] +
                       extra + options)
            result = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit(f"{' '.join(command)} failed:\n{result.stderr}")
            summary = json.loads(result.stdout)
            if best is None or summary["wall_seconds"] < best["wall_seconds"]:
                best = summary
        with h5py.File(output, "r") as results:
            time = results["time"][:]
            displacement = results["isolator/displacement"][:]
    stride = int(round(SAMPLE / (time[1] - time[0])))
    return displacement[::stride], best


def errors(u, reference):
    n = min(len(u), len(reference))
    difference = u[:n] - reference[:n]
    scale = np.max(np.abs(reference[:n]))
    rms = math.sqrt(np.mean(difference**2)) / math.sqrt(np.mean(reference[:n] ** 2))
    return np.max(np.abs(difference)) / scale, rms


def matched_time(points, target):
    """Wall time at which an integrator reaches `target` error, interpolated in log-log between
    the runs that bracket it; None when no run reaches it."""
    points = sorted(points, key=lambda p: p[1])  # by wall time
    if all(e <= target for e, _ in points):
        return points[0][1], True  # the cheapest run is already that accurate: an upper bound
    for (e0, w0), (e1, w1) in zip(points, points[1:]):
        if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0))), False
    return None, False


# Each table says where it comes from (scripts/check_docs.py requires it of a table of numbers):
# the docs check compares the errors, orders and counts with what scripts/doc_tables/convergence.py
# prints (opt-in), not the wall times, which are one machine's.
def marker(number, columns):
    return (f"<!-- table from: scripts/doc_tables/convergence.py isolab | table: {number} | "
            f"columns: {columns} | opt-in: about a minute, needs python3-h5py; wall (ms) is one "
            "machine's -->")


WALL_MARKER = ("<!-- table from: benchmarks/convergence_study.py | not checked: wall times of one "
               "machine, interpolated -->")


def study(isolab, title, model, extra, unit, first_table):
    """The case's three tables, numbered from `first_table` among those the study prints."""
    lines = [f"### {title}", ""]
    reference, ref_summary = run(
        isolab, model, extra,
        ["--integrator", "ida", "--rtol", str(REFERENCE_RTOL), "--atol", "1e-13", "--dt",
         str(SAMPLE)])
    peak = np.max(np.abs(reference))
    lines.append(
        f"Reference: IDA, rtol = {REFERENCE_RTOL:g}: peak isolator displacement "
        f"{peak:.6g} {unit}, {ref_summary['ida']['steps']} steps, "
        f"{ref_summary['ida']['events']} phase-change events, energy balance error "
        f"{ref_summary['energy_balance_error']:.1e}.")
    lines += ["", marker(first_table, "1-5"),
              "| Newmark dt (s) | max error / peak | observed order | RMS error | "
              "Newton iterations | wall (ms) |", "|---|---|---|---|---|---|"]
    newmark_points, previous = [], None
    for dt in STEPS:
        u, summary = run(isolab, model, extra, ["--integrator", "newmark", "--dt", str(dt)])
        max_error, rms = errors(u, reference)
        order = "" if previous is None else \
            f"{math.log(previous[1] / max_error) / math.log(previous[0] / dt):.2f}"
        previous = (dt, max_error)
        wall = summary["wall_seconds"]
        newmark_points.append((max_error, wall))
        lines.append(f"| {dt:g} | {max_error:.2e} | {order} | {rms:.2e} | "
                     f"{summary['newton']['iterations']} | {1e3 * wall:.2f} |")
    dts = np.log([dt for dt in STEPS])
    errs = np.log([e for e, _ in newmark_points])
    fitted = np.polyfit(dts, errs, 1)[0]
    off = [f"{a:g} -> {b:g} s ({math.log(ea / eb) / math.log(a / b):.2f})"
           for (a, (ea, _)), (b, (eb, _)) in zip(zip(STEPS, newmark_points),
                                                 zip(STEPS[1:], newmark_points[1:]))
           if abs(math.log(ea / eb) / math.log(a / b) - 2.0) > 0.3]
    lines += ["", f"Least-squares order over 0.02-0.0005 s: **{fitted:.2f}**. "
              + (f"Step pairs off 2 by more than 0.3: {', '.join(off)}." if off
                 else "Every step pair is within 0.3 of 2.")]
    lines += ["", marker(first_table + 1, "1-6"),
              "| IDA rtol | max error / peak | RMS error | IDA steps | events | "
              "Jacobians | wall (ms) |", "|---|---|---|---|---|---|---|"]
    ida_points = []
    for rtol in TOLERANCES:
        u, summary = run(isolab, model, extra,
                         ["--integrator", "ida", "--rtol", str(rtol), "--atol", str(rtol * 1e-3),
                          "--dt", str(SAMPLE)])
        max_error, rms = errors(u, reference)
        wall = summary["wall_seconds"]
        ida_points.append((max_error, wall))
        ida = summary["ida"]
        lines.append(f"| {rtol:g} | {max_error:.2e} | {rms:.2e} | {ida['steps']} | "
                     f"{ida['events']} | {ida['jacobian_evaluations']} | {1e3 * wall:.2f} |")
    lines += ["", "Wall time for equal accuracy (interpolated between the runs above):", "",
              WALL_MARKER, "| max error / peak | Newmark (ms) | IDA (ms) | IDA / Newmark |",
              "|---|---|---|---|"]
    for target in [1e-2, 1e-3, 1e-4, 1e-5]:
        newmark, newmark_bound = matched_time(newmark_points, target)
        ida, ida_bound = matched_time(ida_points, target)
        cell = lambda w, bound: (("<= " if bound else "") + f"{1e3 * w:.2f}") if w else \
            "not reached in the runs above"
        ratio = f"{ida / newmark:.1f}" if newmark and ida and not (newmark_bound or ida_bound) \
            else ""
        lines.append(f"| {target:g} | {cell(newmark, newmark_bound)} | {cell(ida, ida_bound)} | "
                     f"{ratio} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--isolab", default=os.path.join(ROOT, "build", "isolab"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "convergence.md"))
    args = parser.parse_args()
    if not os.path.exists(EL_CENTRO):
        sys.exit(f"the study needs {EL_CENTRO}, which the repository bundles")
    lines = []
    for case, (title, model, extra, unit) in enumerate(CASES):
        lines += study(os.path.abspath(args.isolab), title, model, extra, unit, 3 * case + 1) + [""]
    table = "\n".join(lines)
    print(table)
    if args.out == "-":
        return
    with open(args.out) as existing:
        text = existing.read()
    begin, end = "<!-- convergence-study:begin -->", "<!-- convergence-study:end -->"
    head, rest = text.split(begin)
    _, tail = rest.split(end)
    with open(args.out, "w") as out:
        out.write(f"{head}{begin}\n{table}\n{end}{tail}")


if __name__ == "__main__":
    main()
