#!/usr/bin/python3
"""The Python module's costs (docs/python.md, "Costs"): a run from Python against the executable
on the five-story model, and two records on two threads against one after the other.

Times are medians of REPEAT repetitions, wall and CPU (process user + system time; less sensitive
to other load). Run by hand, on a quiet machine, after building; never in CI:

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_module.py [--isolab build/isolab]
        [--repeat 9]
"""

import argparse
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

import isolab

REPO = pathlib.Path(__file__).resolve().parents[1]
MODEL = REPO / "models/buildings/five_story_table9.yaml"
RECORDS = [REPO / "ground_motions/fwn_firm_seed1.at2", REPO / "ground_motions/fwn_soft_seed2.at2"]


def cpu_seconds():
    """User + system time of this process (all its threads) and of its finished children."""
    total = 0.0
    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN):
        usage = resource.getrusage(who)
        total += usage.ru_utime + usage.ru_stime
    return total


def measure(action, repeat):
    """Median wall and CPU seconds of `action`."""
    walls, cpus = [], []
    for _ in range(repeat):
        cpu = cpu_seconds()
        start = time.perf_counter()
        action()
        walls.append(time.perf_counter() - start)
        cpus.append(cpu_seconds() - cpu)
    return statistics.median(walls), statistics.median(cpus)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--isolab", default=str(REPO / "build/isolab"))
    parser.add_argument("--repeat", type=int, default=9)
    options = parser.parse_args()
    model = isolab.load_model(MODEL)
    steps = isolab.run(model).summary["steps"]
    print(f"five-story model ({MODEL.name}), {steps} steps; medians of {options.repeat}")

    with tempfile.TemporaryDirectory() as folder:
        h5 = os.path.join(folder, "run.h5")
        cli = [options.isolab, "run", str(MODEL), "-o", h5, "--json"]
        rows = [
            ("executable: isolab run -o run.h5",
             lambda: subprocess.run(cli, check=True, capture_output=True)),
            ("python: isolab.run(path).save(run.h5)", lambda: isolab.run(MODEL).save(h5)),
            ("python: isolab.run(model)", lambda: isolab.run(model)),
        ]
        times = {}
        for name, action in rows:
            times[name] = measure(action, options.repeat)
            print(f"  {name:<42} wall {times[name][0] * 1e3:8.1f} ms, CPU "
                  f"{times[name][1] * 1e3:8.1f} ms")
        integrator = statistics.median(
            isolab.run(model).summary["wall_seconds"] for _ in range(options.repeat))
        name = "the integrator alone (summary wall_seconds)"
        print(f"  {name:<42} wall {integrator * 1e3:8.1f} ms")
        for what, index in (("wall", 0), ("CPU", 1)):
            print(f"  python / executable, the same work from a file to a file ({what}): "
                  f"{times[rows[1][0]][index] / times[rows[0][0]][index]:.3f}")

    # The pool is made once, as a script running many records would; each run is short (tens of
    # milliseconds), so a batch of eight runs shows the scaling without fixed costs on top.
    pool = ThreadPoolExecutor(2)

    def run(record):
        return isolab.run(model, str(record), scale=0.6)

    list(pool.map(run, RECORDS))
    for label, batch in (("two records", RECORDS), ("eight runs", RECORDS * 4)):
        sequential = measure(lambda: [run(record) for record in batch], options.repeat)
        threaded = measure(lambda: list(pool.map(run, batch)), options.repeat)
        print(f"{label}, one after the other: wall {sequential[0] * 1e3:8.1f} ms, CPU "
              f"{sequential[1] * 1e3:8.1f} ms")
        print(f"{label} on two threads:       wall {threaded[0] * 1e3:8.1f} ms, CPU "
              f"{threaded[1] * 1e3:8.1f} ms ({threaded[0] / sequential[0]:.2f} of the time, "
              f"{os.cpu_count()} cores)")
    pool.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
