#!/usr/bin/python3
"""What recording every step costs in `isolab run`, per step, against a summary-only run.

Issue #27's method: per-step CPU time = (10,000-step run - 1-step run) / 9,999, the run's CPU
time being user + system of the whole process (the kernel's share of writing the file counts).
Models: the five-story Table 9 building (models/buildings/five_story_table9.yaml, analysis step
0.005 s) and a 1000-story building on a linear isolator (as benchmarks/process_costs.sh), under
isolab's seeded noise; every history streamed to a file in FOLDER (default: /dev/shm, tmpfs, so
that the disk does not count) or only the summary (--summary-only) written there. The configurations run REPEAT times (default
11), interleaved, so that a slow spell of a shared machine hits all of them; prints the minimum
and the median per step. Also prints what the kernel alone takes to write as many bytes to a
new file in the same folder (dd, less its own start), the floor of any file. Then issue #48's
measure: the five-story run at 60,000 steps, every history less summary-only, against dd of the
file's bytes. Every file, isolab's and dd's, is new: one that replaced the last would be charged
with freeing the old one's pages.

Run by hand on a quiet machine; never in CI:
    benchmarks/output_cost.py [ISOLAB] [REPEAT] [FOLDER]
"""
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ISOLAB = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/isolab"))
REPEAT = int(sys.argv[2]) if len(sys.argv) > 2 else 11
FOLDER = sys.argv[3] if len(sys.argv) > 3 else ("/dev/shm" if os.path.isdir("/dev/shm") else None)
STEPS = 10_000

ONE_STEP = """PEER STRONG MOTION DATABASE RECORD
one step
ACCELERATION TIME SERIES IN UNITS OF G
NPTS=   2, DT=   {dt:.4f} SEC
0.0 0.01
"""

STORIES_1000 = """units: {{force: kN, length: mm, time: s}}
structure:
  type: shear_building
  base_mass: 25 t
  stories: {{count: 1000, mass: 25 t, stiffness: 76 kN/mm, height: 3.2 m}}
  damping: {{type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}}
isolation:
  components:
    - {{name: spring, type: linear_spring, k: 158.07}}
    - {{name: dashpot, type: dashpot, c: 12.579}}
excitation:
  ground_motion: {{file: {record}}}
analysis: {{dt: 0.01}}
"""


def cpu_seconds(command):
    """User + system time of a command and its children, seconds."""
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        sys.exit(f"failed: {' '.join(command)}\n{process.stderr.read().decode()}")
    return usage.ru_utime + usage.ru_stime


def new_file_cpu(command, target):
    """cpu_seconds of a command that writes `target`, made new: a run that replaced the last
    one's file would also be charged with freeing its pages (at 30 MB on tmpfs, some 4 ms)."""
    if os.path.exists(target):
        os.remove(target)
    return cpu_seconds(command)


def new_file_dd(folder, size):
    """dd of `size` bytes to a new file in `folder` in blocks of 64 KiB, and an empty dd (its own
    start): (full, empty) CPU seconds. The kernel's write is the difference of their minima (or
    medians), as the recording is the difference of the runs'."""
    target = os.path.join(folder, "dd")
    blocks = (size + 65535) // 65536
    full = new_file_cpu(["dd", "if=/dev/zero", f"of={target}", "bs=64K", f"count={blocks}"],
                        target)
    return full, new_file_cpu(["dd", "if=/dev/zero", f"of={target}", "bs=64K", "count=0"], target)


def recording_against_dd(five, out):
    """Issue #48's measure: the five-story run at 60,000 steps (--dt 0.000715), the CPU of the run
    with every history less the run summary-only, against dd of the file's bytes; every file new,
    minima and medians of REPEAT interleaved rounds."""
    run = [ISOLAB, "run", five, "--dt", "0.000715", "-q", "-o"]
    every, summary, full, empty = [], [], [], []
    for _ in range(REPEAT):
        every.append(new_file_cpu(run + [os.path.join(out, "every.h5")],
                                  os.path.join(out, "every.h5")))
        summary.append(new_file_cpu(run + [os.path.join(out, "summary.h5"), "--summary-only"],
                                    os.path.join(out, "summary.h5")))
        dd = new_file_dd(out, os.path.getsize(os.path.join(out, "every.h5")))
        full.append(dd[0])
        empty.append(dd[1])
    size = os.path.getsize(os.path.join(out, "every.h5"))
    least = min(every) - min(summary)
    middle = statistics.median(every) - statistics.median(summary)
    kernel_least = min(full) - min(empty)
    kernel_middle = statistics.median(full) - statistics.median(empty)
    print(f"5 stories at 60,000 steps, {size / 1e6:.1f} MB: recording (every history less "
          f"summary-only) min {least * 1e3:.1f} ms, median {middle * 1e3:.1f} ms; dd of the "
          f"bytes to a new file min {kernel_least * 1e3:.1f} ms, median "
          f"{kernel_middle * 1e3:.1f} ms; {least / kernel_least:.2f} times dd at the minima, "
          f"{middle / kernel_middle:.2f} at the medians")


def main():
    work = tempfile.mkdtemp(prefix="isolab_output_cost.")
    out = tempfile.mkdtemp(prefix="isolab_output_cost.", dir=FOLDER)
    try:
        # 10,000 analysis steps for both models: 50 s at the five-story model's 0.005 s, 100 s at
        # the 1000-story model's 0.01 s (records sampled at 0.01 s).
        noise = {}
        for seconds in (50, 100):
            noise[seconds] = os.path.join(work, f"noise_{seconds}s.at2")
            subprocess.run([ISOLAB, "synth", "noise", "--duration", str(seconds), "--pga", "0.35",
                            "-o", noise[seconds]], check=True, stdout=subprocess.DEVNULL)
        one = os.path.join(work, "one_step.at2")
        with open(one, "w") as f:
            f.write(ONE_STEP.format(dt=0.01))
        tall = {}
        for name, record in (("long", noise[100]), ("one", one)):
            tall[name] = os.path.join(work, f"stories_1000_{name}.yaml")
            with open(tall[name], "w") as f:
                f.write(STORIES_1000.format(record=record))
        five = os.path.join(ROOT, "models/buildings/five_story_table9.yaml")
        cases = {
            "5 stories": {"long": [five, "--record", noise[50]], "one": [five, "--record", one]},
            "1000 stories": {"long": [tall["long"]], "one": [tall["one"]]},
        }
        outputs = {"summary only": ["--summary-only"], "every history": []}
        times = {}
        for _ in range(REPEAT):
            for case, runs in cases.items():
                for output, flags in outputs.items():
                    for length, model in runs.items():
                        target = os.path.join(out, f"{length}.h5")
                        command = [ISOLAB, "run", *model, "--free-vibration", "0", "-q", "-o",
                                   target, *flags]
                        times.setdefault((case, output, length), []).append(
                            new_file_cpu(command, target))
        print(f"isolab: {ISOLAB}; files in {out}; {REPEAT} repeats; per step, us "
              "(10,000-step run - 1-step run) / 9,999, user + system")
        for case, runs in cases.items():
            # The bytes of the 10,000-step file, and the kernel's time to write as many.
            subprocess.run([ISOLAB, "run", *runs["long"], "--free-vibration", "0", "-q", "-o",
                            os.path.join(out, "size.h5")], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
            size = os.path.getsize(os.path.join(out, "size.h5"))

            full, empty = zip(*(new_file_dd(out, size) for _ in range(REPEAT)))
            dd = min(full) - min(empty)
            line = f"{case}:"
            per_step = {}
            for output in outputs:
                long, one_step = times[(case, output, "long")], times[(case, output, "one")]
                per_step[output] = (min(long) - min(one_step)) / (STEPS - 1) * 1e6
                median = (statistics.median(long) - statistics.median(one_step)) / (STEPS - 1) * 1e6
                line += f"  {output}: min {per_step[output]:.3f}, median {median:.3f}"
            extra = per_step["every history"] / per_step["summary only"] - 1
            print(f"{line}  (+{100 * extra:.0f} % at the minima); file {size / 2**20:.1f} MiB, "
                  f"dd of as many bytes {dd * 1e6 / (STEPS - 1):.3f} us a step")
        recording_against_dd(five, out)
    finally:
        shutil.rmtree(work, ignore_errors=True)
        shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
