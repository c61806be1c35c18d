"""The thread count changes the speed, never the result (issue 44): the building fit, the
building diagnosis, the cyclic-test diagnosis and the design give the same answer on 1, 2 and 4
threads (worker processes for the design), to the last digit. Each result is compared whole,
every number exactly; only the wall time, which no two runs share, is left out, by name.

Where the threads act: every fit searches with CMA-ES islands (2 by default) run side by side on
min(threads, islands) threads, then polishes on one (identification/unit_cube_search.cpp); a
cyclic fit whose tests are long (samples x law runs >= 200000) also shares each evaluation's law
runs among threads / islands threads, and its final solve among all of them
(identification/fit.cpp, parametrisation.cpp). The budgets below are, but where said, the
smallest at which the search as it stands runs at least one CMA-ES chunk of 20 generations on
both islands (0.9 budget >= 2 x population x 20), so the threaded part is exercised, not only
the serial polish; the tests assert the equality whatever the search does with its budget. The
design's runs go to 1, 2 or 4 worker processes (study/scheduler.h)."""

import json
import math
import re

import pytest

import isolab

THREADS = (1, 2, 4)

# The wall time of a fit or a diagnosis ("seconds": building_fit_report.cpp,
# diagnosis/report.cpp): a measurement of this run on this machine, the one value that is
# legitimately different on every run whatever the thread count. Nothing else is left out.
TIMING = {"seconds"}

TRUTH = "models/diagnosis/cyclic_degradation.yaml"
BASE = "models/diagnosis/base_bhm2.yaml"


def without_timing(value):
    """value with every key named in TIMING removed, at any depth."""
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in TIMING}
    if isinstance(value, (list, tuple)):
        return type(value)(without_timing(v) for v in value)
    return value


def differences(a, b, path="result"):
    """Where a and b differ, as key paths: the same structure, the same types (a float never
    equals an int here) and every number and string exactly equal (NaN equal to NaN)."""
    if type(a) is not type(b):
        return [f"{path}: {a!r} ({type(a).__name__}) != {b!r} ({type(b).__name__})"]
    if isinstance(a, dict):
        found = [f"{path}: key {k!r} in one only" for k in sorted(a.keys() ^ b.keys(), key=str)]
        for k in sorted(a.keys() & b.keys(), key=str):
            found += differences(a[k], b[k], f"{path}[{k!r}]")
        return found
    if isinstance(a, (list, tuple)):
        if len(a) != len(b):
            return [f"{path}: length {len(a)} != {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}[{i}]")]
    if isinstance(a, float) and math.isnan(a) and math.isnan(b):
        return []
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


def assert_same(results):
    """results: {threads: result}; each equal to the one thread's, but for TIMING."""
    one = without_timing(results[THREADS[0]])
    for threads, result in results.items():
        found = differences(one, without_timing(result))
        assert not found, f"{THREADS[0]} thread(s) against {threads}:\n" + "\n".join(found[:20])


def files_of(folder, replace=None):
    """{relative path: bytes} of every file under folder; replace: (old, new) bytes substituted
    in each (a folder's own name, written into what it holds)."""
    files = {}
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        data = path.read_bytes()
        if replace:
            data = data.replace(*replace)
        files[str(path.relative_to(folder))] = data
    return files


def assert_same_files(trees):
    """trees: {threads: files_of(...)}; the same files, byte for byte."""
    one = trees[THREADS[0]]
    assert one
    for threads, files in trees.items():
        assert sorted(files) == sorted(one), threads
        differing = [name for name in one if files[name] != one[name]]
        assert not differing, f"{THREADS[0]} thread(s) against {threads}: {differing}"


# --- the building fit ---------------------------------------------------------------------------

def test_building_fit(tmp_path, shake_table, capfd):
    """isolab.fit(building=): the whole result, the fitted model file's bytes and the search's
    progress on stderr (each stage's best so far) alike on 1, 2 and 4 threads."""
    data, spec = shake_table
    results, files, progress = {}, {}, {}
    for threads in THREADS:
        output = tmp_path / f"fitted_{threads}.yaml"
        capfd.readouterr()
        results[threads] = isolab.fit(data, building=spec, budget=600, seed=3, threads=threads,
                                      offsets="none", output=output)
        progress[threads] = capfd.readouterr().err
        files[threads] = output.read_bytes()
        # Each writes its own file: the one key whose value is the run's own path.
        assert results[threads].pop("output") == str(output)
    # 2 parameters: a population of 12 on each of 2 islands for 20 generations (with the first
    # populations and the start) is 505 simulations, the global stage's default where half the
    # budget is less; then least squares. The progress says what ran (building_fit_report.cpp).
    assert "CMA-ES generation    20," in progress[1]
    assert "least squares   1," in progress[1]
    assert_same(results)
    assert len(set(files.values())) == 1, "the fitted model files differ"
    assert len(set(progress.values())) == 1, progress
    assert results[1]["seconds"] > 0  # the one key left out is there, and is a time
    assert [p["name"] for p in results[1]["parameters"]] == ["isolation.iso.k1",
                                                             "stories.stiffness"]


# --- the building diagnosis ---------------------------------------------------------------------

@pytest.fixture
def viscous_shake_table(tmp_path, monkeypatch, request):
    """The shake_table fixture's building with a dashpot (c = 0.03 kN s/mm) beside its isolator,
    measured as that fixture measures it, and a specification from the fixture's start model
    (without the dashpot) freeing the isolator and the stories, as
    tests/cli/shaketable_command_test.cpp's DiagnoseBuildingNamesTheViscousPartTheModelLacks:
    the diagnosis names rate dependence and refits the building with it."""
    import conftest

    plain = conftest.BUILDING
    isolator = "    - {name: iso, type: bhm2, k0: 3, k1: K1, uy: 5}\n"
    assert isolator in plain
    monkeypatch.setattr(conftest, "BUILDING", plain.replace(
        isolator, isolator + "    - {name: visc, type: dashpot, c: 0.03}\n"))
    data, spec = request.getfixturevalue("shake_table")
    monkeypatch.undo()
    (tmp_path / "start.yaml").write_text(plain.replace("STIFFNESS", "80").replace("K1", "0.6") +
                                         "analysis: {dt: 0.01}\n")
    spec.write_text("model: start.yaml\nparameters:\n  - isolation.iso.k0\n"
                    "  - isolation.iso.k1\n  - isolation.iso.uy\n"
                    "  - {name: stories.stiffness, range: [30, 150]}\n")
    assert "dashpot" in (tmp_path / "truth.yaml").read_text()
    return data, spec


@pytest.mark.parametrize("motions, effects, budget", [
    # The building as its model describes it: nothing is named, the base fit is the answer.
    ("shake_table", ["none"], 600),
    # A dashpot the model lacks: named, added, and the building refitted with it (4 and then 5
    # parameters: populations of 16, a chunk of 640 of the 648 CMA-ES gets).
    ("viscous_shake_table", ["rate_dependence"], 720),
])
def test_building_diagnosis(request, motions, effects, budget):
    """isolab.diagnose(building=): the whole report (head, loops, steps with their candidates,
    verdict, the building's base fit and refit with their parameters, sigmas and channels) alike
    on 1, 2 and 4 threads."""
    data, spec = request.getfixturevalue(motions)
    results = {threads: isolab.diagnose(data, building=spec, budget=budget, seed=2,
                                        threads=threads, offsets="none", quiet=True)
               for threads in THREADS}
    assert_same(results)
    assert results[1]["effects"] == effects
    assert ("refit" in results[1]["building"]) == (effects != ["none"])


# --- the cyclic-test diagnosis ------------------------------------------------------------------

@pytest.mark.parametrize("steps_per_cycle, budget", [
    # 3 tests of 3 cycles: the islands on threads, each evaluation on one.
    (100, 1500),
    # Long tests: 3 x 3 x 7500 = 67500 samples, times the 3 law runs of the candidate fit
    # (bhm2 and degrading_bhm2) over fit.cpp's 200000, so that fit shares each evaluation's law
    # runs too, on threads / islands threads (4 threads work otherwise than 2). The smallest
    # budget keeps it to a few seconds: the polish alone, on the shared evaluations.
    (7500, 100),
], ids=["short_tests", "long_tests"])
def test_cyclic_diagnosis(repo, tmp_path, steps_per_cycle, budget):
    """isolab.diagnose(data, base): the whole report (head, every step with the candidates
    weighed and their evidence, base and final fits, verdict, identifiability, loops) alike on
    1, 2 and 4 threads, on tests of a degrading bearing it must name."""
    data = tmp_path / "tests.csv"
    isolab.cyclic(str(repo / TRUTH), [25, 100, 200], period=2, cycles=3,
                  steps_per_cycle=steps_per_cycle, noise=0.01, seed=15, test_data=data)
    results = {threads: isolab.diagnose(data, repo / BASE, budget=budget, seed=4,
                                        threads=threads, quiet=True)
               for threads in THREADS}
    assert_same(results)
    assert results[1]["effects"] == ["cyclic_degradation"]
    assert results[1]["samples"] >= 3 * 3 * steps_per_cycle
    assert [s["effect"] for s in results[1]["steps"]] == ["cyclic_degradation"]
    assert [c["type"] for c in results[1]["final"]["components"]] == ["bhm2", "degrading_bhm2"]


# --- the design ---------------------------------------------------------------------------------

def write_design(repo, folder):
    """The design of python/tests/test_design.py: a two-story building on lead-rubber bearings
    under three records (3 bounds x 3 records = 9 runs, well under a second)."""
    motions = repo / "ground_motions"
    records = ", ".join(str(motions / name) for name in
                        ("fwn_firm_seed1.at2", "fwn_soft_seed2.at2", "elcentro_1940_ns.at2"))
    design = folder / "design.yaml"
    building = repo / "tests" / "study" / "data" / "two_story_lrb.yaml"
    design.write_text(f"model: {building}\ntarget: {{asce7: {{sms: 1.2 g, sm1: 0.6 g}}}}\n"
                      f"suite:\n  records: [{records}]\n")
    return design


def test_design(repo, tmp_path, monkeypatch):
    """isolab.design on 1, 2 and 4 worker processes: the whole result (ELF and design values per
    bound, governing bounds, records and factors, the summary text, capacity checks) and every
    file it writes (design.md, the CSV files, the bound models, each run's HDF5 results, the
    histories and the manifest), byte for byte. None carries a time: a run file's wall_seconds
    is written as NaN (study/run_job.cpp), so nothing is left out. Each design runs in a folder
    of its own into "design", so that the paths it writes are the same too."""
    design = write_design(repo, tmp_path)
    results, trees = {}, {}
    for jobs in THREADS:
        folder = tmp_path / f"jobs{jobs}"
        folder.mkdir()
        monkeypatch.chdir(folder)
        results[jobs] = isolab.design(design, output="design", jobs=jobs, quiet=True)
        trees[jobs] = files_of(folder / "design")
    assert_same(results)
    assert_same_files(trees)
    assert "design_values.csv" in trees[1] and "runs/lower/elcentro_1940_ns_x1.h5" in trees[1]
    assert results[1]["governing"]["D_TM"] == "lower"


# --- the command line ---------------------------------------------------------------------------
# `isolab diagnose --threads` and `isolab design -j`, 1 against 4. The command line runs in the
# repository (the isolab_cli fixture), so each writes into tmp_path/j1 or tmp_path/j4, folders of
# equal length, and what names its folder is read with j4's name put in j1's place.

def test_cli_diagnose(repo, tmp_path, isolab_cli):
    """`isolab diagnose --threads 1` and `--threads 4`: the JSON printed and every file written
    (the report in JSON and Markdown, the final model, the residual), alike but for the wall
    time: "seconds" in the JSON and the Markdown's closing "Seed 4; 0.1 s." (report.cpp)."""
    data = tmp_path / "tests.csv"
    isolab.cyclic(str(repo / TRUTH), [25, 100, 200], period=2, cycles=3, steps_per_cycle=100,
                  noise=0.01, seed=15, test_data=data)
    printed, trees = {}, {}
    for threads in (1, 4):
        folder = tmp_path / f"j{threads}"
        folder.mkdir()
        done = isolab_cli("diagnose", data, "--base", BASE, "--budget", 1500, "--seed", 4,
                          "--threads", threads, "-q", "--no-plot", "--json",
                          "--out", folder / "report")
        rename = (str(folder).encode(), str(tmp_path / "j4").encode())
        printed[threads] = json.loads(done.stdout.replace(*map(bytes.decode, rename)))
        files = files_of(folder, rename)
        files["report.json"] = json.loads(files["report.json"])
        files["report.md"] = re.sub(rb"\nSeed 4; [0-9.]+ s\.\n", b"\nSeed 4; (time) s.\n",
                                    files["report.md"])
        assert b"(time)" in files["report.md"]
        trees[threads] = files
    assert_same(printed)
    assert printed[1]["effects"] == ["cyclic_degradation"]
    assert sorted(trees[1]) == sorted(trees[4]) == ["report.json", "report.md",
                                                    "report.model.yaml", "report.residual.csv"]
    assert_same({threads: files["report.json"] for threads, files in trees.items()})
    for name in ("report.md", "report.model.yaml", "report.residual.csv"):
        assert trees[1][name] == trees[4][name], name


def test_cli_design(repo, tmp_path, isolab_cli):
    """`isolab design -j 1` and `-j 4`: every file written (the runs' HDF5 files name their
    model by its path in the folder, so the folder's name is put right there too, at equal
    length) and the summary printed, alike."""
    design = write_design(repo, tmp_path)
    printed, trees = {}, {}
    for jobs in (1, 4):
        folder = tmp_path / f"j{jobs}"
        done = isolab_cli("design", design, "-q", "--no-figures", "-j", jobs, "-o", folder)
        rename = (str(folder).encode(), str(tmp_path / "j4").encode())
        printed[jobs] = done.stdout.replace(*map(bytes.decode, rename))
        trees[jobs] = files_of(folder, rename)
    assert printed[1] == printed[4]
    assert printed[1].startswith("design values")
    assert "runs/upper/fwn_soft_seed2_x1.h5" in trees[1]
    assert_same_files(trees)
