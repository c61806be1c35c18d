"""Shared fixtures: the repository, the isolab executable the module is compared with."""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def isolab_cli():
    """Runs the isolab executable (ctest names it in ISOLAB_BINARY) and returns its result."""
    binary = os.environ.get("ISOLAB_BINARY", str(REPO / "build" / "isolab"))
    assert os.path.exists(binary), f"no isolab executable at {binary} (set ISOLAB_BINARY)"

    def run(*args, expect=0):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              cwd=REPO)
        assert done.returncode == expect, done.stdout + done.stderr
        return done

    def run_json(*args):
        return json.loads(run(*args, "--json").stdout)

    run.json = run_json
    return run


# A four-level isolated building (base slab and three floors, 30 t each) on a BHM2 isolator, and
# the model a building fit starts from (stories 80 instead of 60 kN/mm, k1 0.6 instead of 0.4),
# as tests/cli/shaketable_command_test.cpp has them.
BUILDING = """units: {force: kN, length: mm, time: s}
structure:
  type: shear_building
  base_mass: 30 t
  stories: {count: 3, mass: 30 t, stiffness: STIFFNESS kN/mm}
  damping: {type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}
isolation:
  components:
    - {name: iso, type: bhm2, k0: 3, k1: K1, uy: 5}
"""


@pytest.fixture
def shake_table(tmp_path):
    """A synthetic shake-table CSV of the building under isolab's filtered white noise (as
    WriteShakeTable of the C++ tests: roof first, accelerations in mm/s^2 in brackets,
    displacements in metres by suffix, the table in m/s^2) and a building fit specification
    starting off the truth; returns (data, spec)."""
    import numpy
    import isolab

    truth = tmp_path / "truth.yaml"
    truth.write_text(BUILDING.replace("STIFFNESS", "60").replace("K1", "0.4") +
                     f"excitation:\n  ground_motion: {{file: {REPO}/ground_motions/"
                     "fwn_firm_seed1.at2}\nanalysis: {dt: 0.01}\n")
    result = isolab.run(str(truth))
    time, u = result["time"], result["displacement"]
    a, relative = result["absolute_acceleration"], result["acceleration"]
    columns = [time, (a[:, 0] - relative[:, 0]) / 1000, numpy.zeros_like(time)]
    columns += [a[:, level] for level in range(3, -1, -1)]
    columns += [u[:, level] / 1000 for level in range(3, -1, -1)]
    data = tmp_path / "motion.csv"
    header = ("time_s,table_acceleration_m_s2,table_displacement_m," +
              ",".join(f"a{c} [mm/s^2]" for c in range(1, 5)) + "," +
              ",".join(f"d{c}_m" for c in range(1, 5)))
    numpy.savetxt(data, numpy.column_stack(columns), delimiter=",", header=header, comments="",
                  fmt="%.12g")
    start = tmp_path / "start.yaml"
    start.write_text(BUILDING.replace("STIFFNESS", "80").replace("K1", "0.6") +
                     "analysis: {dt: 0.01}\n")
    spec = tmp_path / "spec.yaml"
    spec.write_text("model: start.yaml\nparameters:\n  - isolation.iso.k1\n"
                    "  - {name: stories.stiffness, range: [30, 150]}\nchannels: [d1, a4]\n")
    return data, spec
