"""isolab.compare against `isolab compare`: the same summary, to the last bit."""

import csv
import math

import numpy as np
import pytest

import isolab

SMALL = "tests/study/data/small_study.yaml"
FAILING = "tests/study/data/failing_study.yaml"


def read_summary(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def number(text):
    return math.nan if text == "" else float(text)


def test_the_summary_equals_the_command_lines(repo, tmp_path, isolab_cli, monkeypatch):
    # From the repository, as the command line runs, so both summaries name the same study path.
    monkeypatch.chdir(repo)
    isolab_cli("compare", SMALL, "-q", "-j", "1", "-o", tmp_path / "cli")
    result = isolab.compare(SMALL, output=tmp_path / "py", jobs=2, quiet=True)
    rows = read_summary(tmp_path / "cli" / "summary.csv")
    runs = [row for row in rows if row["record"] not in ("mean", "max")]
    assert len(runs) == len(result["runs"]["variant"]) == 4 * 3 * 2
    quantities = list(result["units"])
    assert "isolator_displacement" in quantities and "base_shear" in quantities
    for i, row in enumerate(runs):
        assert result["runs"]["variant"][i] == row["variant"]
        assert result["runs"]["record"][i] == row["record"]
        assert result["runs"]["scale"][i] == float(row["scale"])
        assert bool(result["runs"]["completed"][i]) == (row["status"] == "completed")
        for key in quantities:
            column = f"{key} [{result['units'][key]}]"
            np.testing.assert_equal(result["runs"][key][i], number(row[column]), err_msg=column)
            np.testing.assert_equal(result["runs"][f"ratio {key}"][i],
                                    number(row[f"ratio {key}"]))
    means = [row for row in rows if row["record"] == "mean"]
    assert len(means) == len(result["statistics"]["variant"]) == 4 * 2
    for i, row in enumerate(means):
        assert result["statistics"]["variant"][i] == row["variant"]
        key = "isolator_displacement"
        np.testing.assert_equal(result["statistics"][f"mean {key}"][i],
                                number(row[f"{key} [{result['units'][key]}]"]))
    # The same files as the command line's: the HDF5 summary is byte for byte the same.
    assert (tmp_path / "py" / "summary.h5").read_bytes() == \
        (tmp_path / "cli" / "summary.h5").read_bytes()
    assert result["failed"] == 0 and result["reference"] == "thm1"


def test_failed_runs_are_reported_with_nan_quantities(repo, tmp_path):
    result = isolab.compare(repo / FAILING, output=tmp_path, jobs=1, quiet=True)
    runs = result["runs"]
    assert result["failed"] == sum(not c for c in runs["completed"]) > 0
    for completed, message, value in zip(runs["completed"], runs["message"],
                                         runs["base_shear"]):
        assert completed == (message == "")
        assert completed or math.isnan(value)


def test_runs_chooses_the_per_run_files_and_keeps_the_quantities(repo, tmp_path):
    full = isolab.compare(repo / SMALL, output=tmp_path / "full", jobs=2, quiet=True)
    none = isolab.compare(repo / SMALL, output=tmp_path / "none", jobs=2, quiet=True, runs="none")
    summary = isolab.compare(repo / SMALL, output=tmp_path / "summary", jobs=1, quiet=True,
                             runs="summary")
    assert not (tmp_path / "none" / "runs").exists()
    assert all(f == "" for f in none["runs"]["file"])
    assert list(summary["runs"]["file"]) == list(full["runs"]["file"])
    for key in full["units"]:
        np.testing.assert_equal(none["runs"][key], full["runs"][key])
        np.testing.assert_equal(summary["runs"][key], full["runs"][key])
    one = "runs/thm1/pulse_tp2_x1.h5"
    assert (tmp_path / "summary" / one).stat().st_size * 4 < (tmp_path / "full" / one).stat().st_size
    with pytest.raises(isolab.InputError, match="runs"):
        isolab.compare(repo / SMALL, output=tmp_path / "bad", runs="all")


def test_bad_input_raises_input_error_with_its_location(repo, tmp_path):
    with pytest.raises(isolab.InputError, match=r"bad_study_key.yaml:5:1: refrence: unknown key"):
        isolab.compare(repo / "tests/study/data/bad_study_key.yaml", output=tmp_path)
    with pytest.raises(isolab.InputError, match="free_vibration"):
        isolab.compare(repo / SMALL, output=tmp_path, free_vibration="soon")
    # The small study's building fixes its runs' duration: refused before any run.
    folder = tmp_path / "fixed_duration"
    with pytest.raises(isolab.InputError,
                       match=r"^free_vibration: variant 'thm1' fixes the run's duration"):
        isolab.compare(repo / SMALL, output=folder, free_vibration=3)
    assert not folder.exists()


def test_a_plan_study_has_the_plan_quantities_of_the_command_line(repo, tmp_path, isolab_cli,
                                                                   monkeypatch):
    monkeypatch.chdir(repo)
    plan = "models/studies/five_story_plan_angles.yaml"
    isolab_cli("compare", plan, "-q", "-j", "1", "-o", tmp_path / "cli")
    result = isolab.compare(plan, output=tmp_path / "py", jobs=2, quiet=True)
    assert list(result["units"]) == ["isolator_displacement", "base_shear", "story_drift_ratio",
                                     "floor_acceleration", "residual_isolator_displacement",
                                     "floor_rotation", "torsional_amplification"]
    assert (tmp_path / "py" / "summary.h5").read_bytes() == \
        (tmp_path / "cli" / "summary.h5").read_bytes()
    runs = [row for row in read_summary(tmp_path / "cli" / "summary.csv")
            if row["record"] not in ("mean", "max")]
    assert [row["record"] for row in runs] == list(result["runs"]["record"]) == \
        ["firm_at0", "firm_at45", "firm_at90", "firm_at135"]
    for key, unit in result["units"].items():
        for i, row in enumerate(runs):
            np.testing.assert_equal(result["runs"][key][i], number(row[f"{key} [{unit}]"]))
    assert all(a > 1.0 for a in result["runs"]["torsional_amplification"])
