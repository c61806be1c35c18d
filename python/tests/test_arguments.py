"""Keyword arguments the module refuses as the command line refuses its options: a value of the
wrong kind is never read as something else (a string of digits as a list of digits, a dict as
its keys, 1.7 cycles as 1), an empty list is not a request for the default, an option of another
option is not ignored, and no output is written over the command's own input."""

import shutil

import numpy as np
import pytest

import isolab

SDOF = "models/paper/table7_thm1_hard.yaml"  # a bearing, for cyclic
SDOF_RUN = "models/sdof/table7_thm1_hard.yaml"  # the SDOF under its record, for run
PLAN = "models/plan/five_story_table9_plan.yaml"
BASE = "models/diagnosis/base_bhm2.yaml"
H1, H2 = "ground_motions/fwn_firm_seed1.at2", "ground_motions/h2_fwn_firm_seed3.at2"


def test_cyclic_never_writes_its_test_data_over_its_model(repo, tmp_path):
    model = tmp_path / "model.yaml"
    shutil.copy(repo / SDOF, model)
    text = model.read_text()
    for given in (model, isolab.load_model(model)):
        with pytest.raises(isolab.InputError, match="is an input of this command"):
            isolab.cyclic(given, 100, test_data=model)
        assert model.read_text() == text


@pytest.mark.parametrize("amplitude, message", [
    ("125", "amplitude: '125' is not a number or a list of numbers"),
    ([], "amplitude: an empty list"),
    ({"a": 1}, "is not a number or a list of numbers"),
    ([50, "100"], r"amplitude\[1\]: '100' is not a number"),
])
def test_cyclic_amplitudes_are_numbers(repo, amplitude, message):
    with pytest.raises(isolab.InputError, match=message):
        isolab.cyclic(repo / SDOF, amplitude)
    # A numpy array of numbers is a list of them.
    assert len(isolab.cyclic(repo / SDOF, np.array([50.0, 100.0]), cycles=1)) == 2


@pytest.fixture
def tests_csv(repo, tmp_path):
    data = tmp_path / "tests.csv"
    isolab.cyclic(repo / "models/diagnosis/null.yaml", [10, 20], period=2, cycles=2,
                  test_data=data)
    return data


@pytest.mark.parametrize("cycles", ["12", 1.7, [], True])
def test_fit_cycles_are_whole_numbers(repo, tests_csv, cycles):
    with pytest.raises(isolab.InputError, match="cycles: "):
        isolab.fit(tests_csv, repo / BASE, cycles=cycles, budget=300, quiet=True)


def test_a_dict_is_not_a_list_of_data_files(repo, tests_csv):
    with pytest.raises(TypeError, match="data: expected a path or a list of paths, not dict"):
        isolab.fit({str(tests_csv): "notes"}, repo / BASE, budget=300, quiet=True)


def test_run_seed_samples_and_angle_as_the_command_line_takes_them(repo):
    model = isolab.load_model(repo / SDOF_RUN)
    with pytest.raises(isolab.InputError, match="seed: seeds the parameter sets samples="):
        isolab.run(model, seed=5)
    with pytest.raises(isolab.InputError, match="samples: 2.5 is not a whole number"):
        isolab.run(model, samples=2.5)
    plan = isolab.load_model(repo / PLAN)
    for angle in (float("nan"), float("inf")):  # bad input, not a run that failed
        with pytest.raises(isolab.InputError, match="angle: "):
            isolab.run(plan, repo / H1, repo / H2, angle=angle)


def test_spectrum_needs_its_periods_and_damping_when_given(repo):
    record = repo / "ground_motions/elcentro_1940_ns.at2"
    with pytest.raises(isolab.InputError, match="periods: an empty list"):
        isolab.spectrum(record, periods=[])
    with pytest.raises(isolab.InputError, match="damping: None"):
        isolab.spectrum(record, damping=None)


@pytest.mark.parametrize("period", [-1.0, 0.0, float("nan"), float("inf"), 1e10])
def test_a_spectrums_periods_are_refused_by_name_not_blamed_on_the_record(repo, period):
    record = repo / "ground_motions/elcentro_1940_ns.at2"
    with pytest.raises(isolab.InputError) as refused:
        isolab.spectrum(record, periods=[0.5, period])
    assert str(refused.value).startswith("periods: periods[1] = ")
    assert "elcentro" not in str(refused.value)


@pytest.mark.parametrize("max_steps", [float("nan"), float("inf"), 0, -1])
def test_a_spectrums_step_limit_is_a_finite_count(repo, max_steps):
    with pytest.raises(isolab.InputError, match="max_steps: .* must be finite and >= 1"):
        isolab.spectrum(repo / "ground_motions/elcentro_1940_ns.at2", periods=[1.0],
                        max_steps=max_steps)


def test_worker_counts_are_bounded_as_on_the_command_line(repo, tmp_path):
    with pytest.raises(isolab.InputError, match=r"jobs: 1000000 workers on \d+ hardware threads"):
        isolab.compare(repo / "models/studies/five_story_bearings.yaml", output=tmp_path / "c",
                       jobs=10**6)
    assert not (tmp_path / "c").exists()


def test_compare_never_writes_over_files_an_earlier_compare_did_not_write(repo, tmp_path):
    folder = tmp_path / "study"
    folder.mkdir()
    (folder / "summary.csv").write_text("my notes\n")
    with pytest.raises(isolab.InputError, match="holds 'summary.csv', which an earlier compare"):
        isolab.compare(repo / "tests/study/data/small_study.yaml", output=folder, jobs=1,
                       quiet=True)
    assert (folder / "summary.csv").read_text() == "my notes\n"


def test_an_empty_path_or_word_is_refused_not_read_as_left_out(repo, tests_csv, tmp_path):
    with pytest.raises(isolab.InputError, match="test_data: an empty path"):
        isolab.cyclic(repo / SDOF, 100, test_data="")
    with pytest.raises(isolab.InputError, match="output: an empty path"):
        isolab.compare(repo / "tests/study/data/small_study.yaml", output="", jobs=1, quiet=True)
    with pytest.raises(isolab.InputError, match="specimen: '' \\(expected sequential or"):
        isolab.fit(tests_csv, repo / BASE, specimen="", budget=300, quiet=True)
    with pytest.raises(isolab.InputError, match="orbit: '' "):
        isolab.cyclic(repo / SDOF, 50, orbit="")


def test_messages_name_the_keywords_not_the_command_lines_options(repo):
    # The run's checks are shared with the command line; here they name the module's keywords.
    for keywords, message in [({"dt": 0}, "^dt: 0 must be > 0"),
                              ({"trial_displacement": 0}, "^trial_displacement: 0 must be > 0"),
                              ({"fixed_base": True}, "^fixed_base: applies to a building")]:
        with pytest.raises(isolab.InputError, match=message):
            isolab.run(repo / SDOF_RUN, **keywords)
    with pytest.raises(isolab.InputError, match="choose a larger dt or a shorter duration$"):
        isolab.run(repo / SDOF_RUN, dt=1e-9)  # no --max-steps to advise: the module has none


@pytest.mark.parametrize("keyword, value", [
    ("dt", "0.5"), ("dt", True), ("dt", float("nan")), ("record_dt", float("nan")),
    ("trial_displacement", float("inf")), ("trial_displacement", True), ("rtol", float("nan")),
    ("rtol", 1e-308), ("atol", 0.0), ("units", ""), ("samples", 0), ("samples", 1.5),
    ("scale", 1e308)])
def test_run_refuses_what_the_command_line_refuses_naming_the_keyword(repo, keyword, value):
    # Each was passed through: True as a step of 1, nan or 1e-308 as tolerances, "" as the
    # default units, samples=0 as no band, a string as the binding's TypeError.
    with pytest.raises(isolab.InputError, match=f"^{keyword}: "):
        isolab.run(repo / SDOF_RUN, **{keyword: value})


@pytest.mark.parametrize("keyword, value", [
    ("record_dt", float("nan")), ("record_dt", 0.0), ("units", ""), ("ductility", float("inf")),
    ("points_per_period", 1.5), ("points_per_period", True), ("scale", True), ("scale", 1e308)])
def test_spectrum_refuses_what_the_command_line_refuses_naming_the_keyword(repo, keyword, value):
    with pytest.raises(isolab.InputError, match=f"^{keyword}: "):
        isolab.spectrum(repo / H1, periods=[1.0], **{keyword: value})


@pytest.mark.parametrize("keyword, value", [
    ("cycles", 1.5), ("cycles", True), ("steps_per_cycle", float("nan")), ("noise", True),
    ("seed", -1), ("seed", 2**32)])
def test_cyclic_counts_and_seeds_are_whole_numbers_in_range(repo, tmp_path, keyword, value):
    extra = {"test_data": tmp_path / "t.csv"} if keyword in ("noise", "seed") else {}
    with pytest.raises(isolab.InputError, match=f"^{keyword}: "):
        isolab.cyclic(repo / SDOF, 10.0, period=2.0, **extra, **{keyword: value})


@pytest.mark.parametrize("jobs", [1.5, "2", float("nan"), -1])
def test_a_studys_worker_count_is_a_whole_number(repo, tmp_path, jobs):
    with pytest.raises(isolab.InputError, match="^jobs: "):
        isolab.compare(repo / "models/studies/five_story_bearings.yaml", output=tmp_path / "s",
                       jobs=jobs)
    assert not (tmp_path / "s").exists()


def test_a_results_file_is_never_saved_over_the_runs_record(repo, tmp_path):
    record = tmp_path / "rec.at2"
    shutil.copy(repo / H1, record)
    before = record.read_bytes()
    result = isolab.run(repo / SDOF_RUN, record=record)
    renamed = tmp_path / "rec.csv"
    record.rename(renamed)
    result = isolab.run(repo / SDOF_RUN, record=renamed)
    with pytest.raises(isolab.InputError, match="is an input of this command"):
        result.save(renamed)
    assert renamed.read_bytes() == before
