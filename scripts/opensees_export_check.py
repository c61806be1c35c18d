#!/usr/bin/python3
"""isolab's OpenSees export run against isolab: each bound's bearings, as `isolab bounds --opensees`
writes them, driven along the same displacement paths in OpenSees 3.8 and in `isolab cyclic
--path`, their forces compared.

Never a test: it needs OpenSees, which a clone does not have. The packed build in
../shared/peers/opensees (README there) is used when it is present, or --opensees PROGRAM.
docs/bearings.md's table of the agreement is its output (scripts/check_docs.py --opt-in).

    /usr/bin/python3 scripts/opensees_export_check.py --isolab build/isolab \
        [--model scripts/opensees_export/bearings.yaml ...] [--bounds nominal ...] \
        [--opensees PATH]

Paths, 2 s a cycle, dt 0.002 s (one bearing at a time, the ground node fixed, the top node's x and
y imposed, its rotations held, the pendulums' weight W applied first as a vertical load):
  x      along x, the amplitude growing from 0 to 600 mm over four cycles (every regime of the
         triple pendulum up to IV), then down to 150 mm over the fifth and one cycle at 150 mm
  orbit  a circle of radius 250 mm about (0, 250 mm), starting at the origin, its radius reached
         over the first cycle, three cycles
Both paths start at rest, so that OpenSees' Newmark velocity of the imposed motion (what its
velocity-dependent friction reads; the Penalty handler makes the imposed dofs carry one) follows the
path's. For each bearing and path: the peak force and the largest force difference over the
history, relative to the peak, and the work the motion did on the bearing (what it dissipated,
less what it stores at the end) in both; differences below 1e-9 (round-off, which varies from
machine to machine) print as "< 1e-9".
"""
import argparse
import os
import re
import subprocess
import sys
import tarfile
import tempfile

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PACKED = os.path.join(ROOT, "..", "shared", "peers", "opensees", "opensees-3.8-debian12.tar.xz")
DT = 0.002
PERIOD = 2.0


def paths():
    """The displacement paths (time, x, y), in mm and s."""
    t = np.arange(0.0, 6 * PERIOD + DT / 2, DT)
    cycles = t / PERIOD
    amplitude = np.where(cycles < 4, 600 * cycles / 4, 150.0)
    # Changed only where the sine is zero (whole cycles), so that the velocity stays continuous.
    amplitude = np.where((cycles >= 4) & (cycles < 5), 600 + (150 - 600) * (cycles - 4),
                         amplitude)
    x = amplitude * np.sin(2 * np.pi * cycles)
    t2 = np.arange(0.0, 3 * PERIOD + DT / 2, DT)
    ramp = np.minimum(1.0, t2 / PERIOD)
    phase = 2 * np.pi * t2 / PERIOD
    return {"x": (t, x, np.zeros_like(t)),
            "orbit": (t2, 250 * ramp * np.sin(phase), 250 * ramp * (1 - np.cos(phase)))}


def opensees_program(given, work):
    if given:
        return given
    if not os.path.exists(PACKED):
        sys.exit("no OpenSees: give --opensees PROGRAM (or keep ../shared/peers/opensees)")
    with tarfile.open(PACKED) as tar:
        tar.extractall(work)
    return os.path.join(work, "opensees-3.8-debian12", "opensees")


def sites(tcl):
    """Each bearing type's first site: (name, W) from the export's isolab_sites."""
    block = re.search(r"set isolab_sites \{\n(.*?)\n\}", open(tcl).read(), re.S).group(1)
    first = {}
    for line in block.splitlines():
        name, _x, _y, weight, procedure = line.strip().strip("{}").split()
        first.setdefault(procedure, (name, float(weight)))
    return list(first.values())


DRIVER = """wipe
model BasicBuilder -ndm 3 -ndf 6
node 1 0 0 0
node 2 0 0 0
fix 1 1 1 1 1 1 1
fix 2 0 0 0 1 1 1
set isolab_next_tag 1
source {{{export}}}
isolab_bearing {name} 1 2
constraints Penalty 1e14 1e14
numberer Plain
system FullGeneral
test NormDispIncr 1e-12 100
algorithm Newton
if {{{weight} > 0}} {{
  timeSeries Constant 90
  pattern Plain 90 90 {{ load 2 0 0 -{weight} 0 0 0 }}
  integrator LoadControl 1.0
  analysis Static
  if {{[analyze 1] != 0}} {{ puts "FAILED gravity"; exit 1 }}
  loadConst -time 0.0
  wipeAnalysis
}}
timeSeries Path 91 -dt {dt} -filePath {{{ux}}}
timeSeries Path 92 -dt {dt} -filePath {{{uy}}}
pattern Plain 91 91 {{ sp 2 1 1.0 }}
pattern Plain 92 92 {{ sp 2 2 1.0 }}
constraints Penalty 1e14 1e14
numberer Plain
system FullGeneral
test NormDispIncr 1e-12 100
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set out [open {{{forces}}} w]
puts $out "0 0 0"
for {{set i 1}} {{$i <= {steps}}} {{incr i}} {{
  if {{[analyze 1 {dt}] != 0}} {{ puts "FAILED at step $i"; exit 1 }}
  reactions
  puts $out "[getTime] [nodeReaction 2 1] [nodeReaction 2 2]"
}}
close $out
"""


def run_opensees(program, export, name, weight, path, work):
    t, x, y = path
    ux, uy, forces = (os.path.join(work, f) for f in ("ux.txt", "uy.txt", "forces.txt"))
    np.savetxt(ux, x, fmt="%.17g")
    np.savetxt(uy, y, fmt="%.17g")
    driver = os.path.join(work, "driver.tcl")
    with open(driver, "w") as f:
        f.write(DRIVER.format(export=export, name=name, weight=weight, dt=DT, ux=ux, uy=uy,
                              forces=forces, steps=len(t) - 1))
    run = subprocess.run([program, driver, "-noHeader"], capture_output=True, text=True)
    if run.returncode != 0 or "FAILED" in run.stdout:
        sys.exit(f"OpenSees failed on {name}: {run.stdout[-2000:]}{run.stderr[-2000:]}")
    return np.loadtxt(forces)[:, 1:3]


def bearings_at_their_weight(model):
    """The model without its axial_load section: `isolab cyclic` drives bearings at their own W,
    as the OpenSees driver loads them, and refuses a model that asks for time-history loads."""
    text = yaml.safe_load(open(model))
    if "axial_load" not in text:
        return model
    text.pop("axial_load")
    at_weight = os.path.splitext(model)[0] + "_at_w.yaml"
    with open(at_weight, "w") as f:
        yaml.safe_dump(text, f)
    return at_weight


def run_isolab(isolab, model, name, path, work):
    t, x, y = path
    csv = os.path.join(work, "path.csv")
    with open(csv, "w") as f:
        f.write("# units: kN, mm\ntime,displacement_x,displacement_y\n")
        for row in zip(t, x, y):
            f.write(",".join(f"{v:.17g}" for v in row) + "\n")
    loop = os.path.join(work, "loop.csv")
    subprocess.run([isolab, "cyclic", model, "--path", csv, "--isolator", name, "--csv", loop,
                    "-q"], check=True, capture_output=True)
    data = np.genfromtxt(loop, delimiter=",", names=True)
    return np.column_stack([data["force_x_kN"], data["force_y_kN"]])


def relative(difference):
    return "< 1e-9" if difference < 1e-9 else f"{difference:.2e}"


def work_done(path, force):
    """The work the imposed motion did on the bearing over the path (trapezoidal rule)."""
    _t, x, y = path
    mid = 0.5 * (force[1:] + force[:-1])
    return float(np.sum(mid[:, 0] * np.diff(x) + mid[:, 1] * np.diff(y)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--isolab", default=os.path.join(ROOT, "build", "isolab"))
    parser.add_argument("--opensees", help="the OpenSees program (default: the packed build)")
    parser.add_argument("--model", nargs="+",
                        default=[os.path.join(HERE, "opensees_export", "bearings.yaml"),
                                 os.path.join(ROOT, "models", "design", "five_story_lrb_plan.yaml"),
                                 os.path.join(ROOT, "models", "design", "four_story_tfp_plan.yaml")])
    parser.add_argument("--bounds", nargs="+", default=["nominal", "upper", "lower"],
                        choices=["nominal", "upper", "lower"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        program = opensees_program(args.opensees, work)
        print("| model | bound | bearing | path | peak force (kN) | max force difference / peak | "
              "work (kN mm) | work difference |")
        print("|---|---|---|---|---|---|---|---|")
        for model in args.model:
            stem = os.path.splitext(os.path.basename(model))[0]
            bounds = os.path.join(work, stem)
            subprocess.run([args.isolab, "bounds", model, "-o", bounds, "--opensees", "-q"],
                           check=True)
            for bound in args.bounds:
                export = os.path.join(bounds, f"{stem}_{bound}.tcl")
                model_file = bearings_at_their_weight(os.path.join(bounds, f"{stem}_{bound}.yaml"))
                for name, weight in sites(export):
                    for label, path in paths().items():
                        ours = run_isolab(args.isolab, model_file, name, path, work)
                        theirs = run_opensees(program, export, name, weight, path, work)
                        peak = np.max(np.hypot(ours[:, 0], ours[:, 1]))
                        gap = np.max(np.hypot(*(ours - theirs).T))
                        work_ours, work_theirs = work_done(path, ours), work_done(path, theirs)
                        print(f"| {stem} | {bound} | {name} | {label} | {peak:.2f} | "
                              f"{relative(gap / peak)} | {work_ours:.0f} | "
                              f"{relative(abs(work_theirs / work_ours - 1))} |", flush=True)


if __name__ == "__main__":
    main()
