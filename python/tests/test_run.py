"""isolab.run against the command line (same numbers to round-off), a closed form, and the GIL."""

import math
import sys
import threading
import time
import warnings

import h5py
import numpy as np
import pytest

import isolab

FIVE_STORY = "models/buildings/five_story_table9.yaml"


@pytest.fixture(scope="module")
def five_story_scaled():
    """The five-story model at a smaller scale and a coarser output, for a quick run."""
    return {"scale": 0.3, "free_vibration": 2.0}


def test_run_equals_the_command_line(repo, tmp_path, isolab_cli, five_story_scaled):
    h5 = tmp_path / "cli.h5"
    cli = isolab_cli.json("run", FIVE_STORY, "--scale", 0.3, "--free-vibration", 2, "-o", h5)
    result = isolab.run(repo / FIVE_STORY, **five_story_scaled)
    with h5py.File(h5) as f:
        compared = 0
        for name in result.names:
            assert name in f, name
            np.testing.assert_allclose(result[name], f[name][...], rtol=1e-12, atol=0, err_msg=name)
            assert result.units[name] == f[name].attrs["units"], name
            compared += 1
        assert compared >= 15
        columns = [c.decode() if isinstance(c, bytes) else c
                   for c in f["displacement"].attrs["columns"]]
        floors = [f"floor {i}" for i in range(1, 6)]
        assert result.columns["displacement"] == columns == ["base"] + floors
    for key in ("isolator_displacement", "base_shear", "roof_absolute_acceleration", "story_drift"):
        assert result.peaks[key]["value"] == pytest.approx(cli["peaks"][key]["value"], rel=1e-12)
        assert result.peaks[key]["time"] == cli["peaks"][key]["time"]
        assert result.peaks[key].get("index") == cli["peaks"][key].get("index"), key
    # Where a peak occurred, from 0: the isolator (the one isolation layer), the story of the
    # largest drift and the roof's level.
    assert result.peaks["isolator_displacement"]["index"] == 0
    assert 0 <= result.peaks["story_drift"]["index"] < 5
    assert result.peaks["roof_absolute_acceleration"]["index"] == 5
    assert result.warnings == cli["warnings"]
    # The summary is the command line's JSON, key for key, except what names this process's
    # files and time: the model's and record's paths as given, the results file (none here) and
    # the wall time.
    summary = dict(result.summary)
    assert summary["model"].endswith(FIVE_STORY) and "results" not in summary
    assert summary["record"].endswith(cli["record"].lstrip("./"))
    for key in ("model", "record", "results", "wall_seconds"):
        summary.pop(key, None)
        cli.pop(key)
    assert summary.keys() == cli.keys()
    for key in summary:
        assert summary[key] == pytest.approx(cli[key], rel=1e-12) if isinstance(
            cli[key], float) else summary[key] == cli[key], key


PLAN = "models/plan/five_story_table9_plan.yaml"
H1, H2 = "ground_motions/fwn_firm_seed1.at2", "ground_motions/h2_fwn_firm_seed3.at2"


@pytest.mark.parametrize("pair", [(), (H2, H1, 30.0)], ids=["own_pair", "given_pair_at_30"])
def test_a_plan_run_equals_the_command_line(repo, tmp_path, isolab_cli, pair):
    """A building in plan, under its own pair and under a pair given with its angle (H1 and H2
    swapped, turned 30 degrees): the histories and the summary are the command line's."""
    h5 = tmp_path / "cli.h5"
    options = ["--record", pair[0], "--record-h2", pair[1], "--angle", pair[2]] if pair else []
    cli = isolab_cli.json("run", PLAN, "--free-vibration", 2, "-o", h5, *options)
    given = {"record": repo / pair[0], "h2": repo / pair[1], "angle": pair[2]} if pair else {}
    result = isolab.run(repo / PLAN, free_vibration=2.0, **given)
    with h5py.File(h5) as f:
        for name in result.names:
            np.testing.assert_allclose(result[name], f[name][...], rtol=1e-12, atol=0, err_msg=name)
        assert "rotation" in result.names and "isolator/resultant" in result.names
    assert cli["angle"] == (pair[2] if pair else 0.0)
    assert cli["h2"]["record"].endswith(pair[1] if pair else H2)
    for key, peak in cli["peaks"].items():
        expected = peak["value"] if isinstance(peak, dict) else peak
        mine = result.peaks[key]["value"] if isinstance(peak, dict) else result.peaks[key]
        assert mine == pytest.approx(expected, rel=1e-12), key
    assert result.summary["torsional_amplification"] == pytest.approx(
        cli["torsional_amplification"], rel=1e-12)


FP_PLAN = "models/plan/five_story_fp_plan.yaml"


def test_axial_load_histories_are_the_command_lines(repo, tmp_path, isolab_cli):
    """A model with axial_load: each bearing's axial load history is the command line's
    /isolator/axial_load, its least value the file's /peaks/axial_loads and the summary's, and
    save() writes it; a model without axial_load has none."""
    h5 = tmp_path / "cli.h5"
    cli = isolab_cli.json("run", FP_PLAN, "--free-vibration", 2, "-o", h5)
    result = isolab.run(repo / FP_PLAN, free_vibration=2.0)
    saved = tmp_path / "saved.h5"
    result.save(saved)
    axial = result["isolator/axial_load"]
    with h5py.File(h5) as f, h5py.File(saved) as g:
        written = f["isolator/axial_load"]
        assert axial.shape == written.shape == (f["time"].shape[0], 4)
        np.testing.assert_array_equal(axial, written[...])
        np.testing.assert_array_equal(g["isolator/axial_load"][...], written[...])
        columns = [c.decode() if isinstance(c, bytes) else c for c in written.attrs["columns"]]
        assert result.columns["isolator/axial_load"] == columns == ["sw", "se", "nw", "ne"]
        assert result.units["isolator/axial_load"] == written.attrs["units"] == "kN"
        for key, units in (("static", "kN"), ("minimum", "kN"), ("minimum_time", "s"),
                           ("uplift_duration", "s"), ("first_uplift", "s")):
            assert f[f"peaks/axial_loads/{key}"].attrs["units"] == units, key
        for j, name in enumerate(columns):
            least = int(np.argmin(axial[:, j]))
            assert f["peaks/axial_loads/minimum"][j] == axial[least, j]
            assert f["peaks/axial_loads/minimum_time"][j] == result["time"][least]
            assert cli["axial_loads"][name]["minimum"]["value"] == axial[least, j]
            assert f["peaks/axial_loads/first_uplift"][j] == -1.0  # no uplift at this level
    # The static shares sum to the weight (600 t), and the loads vary about them.
    assert sum(cli["axial_loads"][n]["static"] for n in columns) == pytest.approx(600 * 9.80665)
    assert np.ptp(axial, axis=0).min() > 100.0
    assert "isolator/axial_load" not in isolab.run(repo / PLAN, free_vibration=2.0)


def test_a_second_component_or_an_angle_needs_a_record_and_a_building_in_plan(repo):
    with pytest.raises(isolab.InputError, match="h2: needs record"):
        isolab.run(repo / PLAN, h2=repo / H2)
    with pytest.raises(isolab.InputError, match="angle: needs record"):
        isolab.run(repo / PLAN, angle=30)
    with pytest.raises(isolab.InputError, match="h2: the structure moves along x only"):
        isolab.run(repo / FIVE_STORY, repo / H1, repo / H2)


def test_save_writes_the_command_lines_file(repo, tmp_path, isolab_cli, five_story_scaled):
    isolab_cli("run", FIVE_STORY, "--scale", 0.3, "--free-vibration", 2, "-o", tmp_path / "cli.csv")
    result = isolab.run(repo / FIVE_STORY, **five_story_scaled)
    result.save(tmp_path / "py.csv")
    cli = [l for l in (tmp_path / "cli.csv").read_text().splitlines() if "wall" not in l]
    py = [l for l in (tmp_path / "py.csv").read_text().splitlines() if "wall" not in l]
    assert len(py) == len(cli) and py[-1] == cli[-1] and py[-100] == cli[-100]


def test_arrays_are_read_only_views_with_names_and_units(repo, five_story_scaled):
    result = isolab.run(repo / FIVE_STORY, **five_story_scaled)
    displacement = result["displacement"]
    assert displacement.shape == (len(result["time"]), 6)
    assert np.shares_memory(displacement, result["displacement"])  # a view, not a copy
    assert displacement.base is not None and not displacement.flags.writeable
    with pytest.raises(ValueError):
        displacement[0, 0] = 1.0
    assert result.units["displacement"] == "mm"
    assert result.units["isolator/force"] == "kN"
    del result  # the arrays keep the result alive
    assert np.isfinite(displacement).all() and displacement[:, 0].max() > 1.0


def test_to_pandas(repo, five_story_scaled):
    result = isolab.run(repo / FIVE_STORY, **five_story_scaled)
    frame = result.to_pandas()
    assert frame.index.name == "time"
    np.testing.assert_array_equal(frame["displacement/floor 5"].to_numpy(),
                                  result["displacement"][:, 5])
    np.testing.assert_array_equal(frame["isolator/force"].to_numpy(), result["isolator/force"])
    assert frame.attrs["units"]["story/drift/story1"] == "mm"


def test_array_record_against_the_closed_form():
    # A linear SDOF (m = 10 t, k = 400 kN/m, 5 %) under a ground acceleration stepping to 1 m/s^2
    # at t = 0: u(t) = -(a/w^2) [1 - exp(-z w t) (cos wd t + z/sqrt(1-z^2) sin wd t)] (Chopra 4.3).
    model = isolab.Model.from_dict({
        "units": {"force": "kN", "length": "m", "time": "s"},
        "structure": {"type": "sdof", "mass": 10.0, "damping": {"ratio": 0.05}},
        "isolation": {"components": [{"name": "spring", "type": "linear_spring", "k": 400.0}]},
    })
    dt, a = 0.001, 1.0
    result = model.run(np.full(2001, a), record_dt=dt, units="m/s^2", free_vibration=0)
    t = result["time"]
    w, z = math.sqrt(40.0), 0.05
    wd = w * math.sqrt(1 - z * z)
    exact = -(a / w**2) * (1 - np.exp(-z * w * t) * (np.cos(wd * t) + z / math.sqrt(1 - z * z) *
                                                      np.sin(wd * t)))
    assert t[-1] == pytest.approx(2.0)
    # Newmark's period error, (w dt)^2 / 12, leaves about 1e-5 of the peak.
    np.testing.assert_allclose(result["displacement"][:, 0], exact,
                               atol=3e-5 * np.abs(exact).max())
    assert result.summary["record"] == "<array>"


def test_bad_run_input_raises_input_error(repo):
    with pytest.raises(isolab.InputError, match="record_dt"):
        isolab.run(repo / FIVE_STORY, np.zeros(10), units="g")
    with pytest.raises(isolab.InputError, match="units"):
        isolab.run(repo / FIVE_STORY, np.zeros(10), record_dt=0.01)
    with pytest.raises(isolab.InputError, match="coarser than the record"):
        isolab.run(repo / FIVE_STORY, dt=0.05)
    with pytest.raises(isolab.InputError, match="no_such.at2"):
        isolab.run(repo / FIVE_STORY, "no_such.at2")
    with pytest.raises(isolab.InputError, match="integrator"):
        isolab.run(repo / FIVE_STORY, integrator="rk4")


def test_a_scale_that_is_not_a_positive_finite_number_is_refused_before_the_run(repo):
    # nan went through to the run and failed in Newton; 0 and -1 ran records of zeros or flipped.
    for scale in (math.nan, math.inf, 0, -1.0):
        with pytest.raises(isolab.InputError, match=r"^scale: .* \(must be a finite number > 0\)"):
            isolab.run(repo / "models/sdof/table7_thm1_hard.yaml", scale=scale)
    with pytest.raises(isolab.InputError, match="^scale: '2' is not a number"):
        isolab.run(repo / "models/sdof/table7_thm1_hard.yaml", scale="2")


def test_plausibility_warnings_are_issued_as_isolab_warnings(repo, tmp_path, isolab_cli):
    # The Table 7 SDOF's record at 10 times its scale has a PGA of 3.5 g (0.35 g x 10): the command
    # line warns, and so must Python, where a list in result.warnings went unseen.
    model = repo / "models/sdof/table7_thm1_hard.yaml"
    with pytest.warns(isolab.IsolabWarning, match="peak ground acceleration, 3.5 g, exceeds 3 g"):
        result = isolab.run(model, scale=10, check=False)
    cli = isolab_cli.json("run", model, "--scale", 10, "-o", tmp_path / "run.h5")
    assert result.warnings == cli["warnings"] and len(cli["warnings"]) == 1
    assert issubclass(isolab.IsolabWarning, UserWarning)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a run within plausible ranges warns about nothing
        isolab.run(model, check=False)


def test_a_failed_run_raises_run_error_with_the_partial_result(repo):
    model = isolab.load_model(repo / FIVE_STORY)
    model.set("analysis.newmark", {"max_iterations": 1, "max_step_cuts": 0})
    with pytest.raises(isolab.RunError, match="stopped early") as error:
        isolab.run(model, scale=0.3, free_vibration=0)
    partial = error.value.result
    assert not partial.ok and 0 < len(partial["time"]) < 5000
    assert not isolab.run(model, scale=0.3, free_vibration=0, check=False).ok


def test_runs_release_the_gil(repo):
    # With a switch interval of 100 s the interpreter never takes the GIL from a thread: this
    # thread runs only when the run's thread lets it go. A run that keeps the GIL leaves count at
    # 0 (this thread waits in start() until the run's thread ends); a run that releases it lets
    # this thread count, a millisecond at a time, until the run ends.
    model = isolab.load_model(repo / FIVE_STORY)
    results = []
    worker = threading.Thread(target=lambda: results.append(isolab.run(model)))
    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    try:
        worker.start()
        count = 0
        while worker.is_alive():
            count += 1
            time.sleep(0.001)  # lets the run's thread take the GIL back when it is done
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert results[0].ok
    assert count >= 2, count


def test_a_run_beyond_the_identified_range_warns(repo, tmp_path, isolab_cli):
    # The BNCS BHM2 was identified on ICA50's isolator history, up to 108.5 mm (the range its
    # fitted file carries): under twice the ICA50 table motion of the bundled excerpt the run goes
    # far beyond it, and Python warns with the command line's words.
    record = tmp_path / "table.csv"
    isolab_cli("shaketable", "tests/cli/data/bncs/bncs_ica50_excerpt.csv", "--model",
               "models/bncs/bncs.yaml", "--record", record, "-q")
    model = repo / "models/bncs/bncs.yaml"
    identified = r"the isolation was identified up to 108.5 mm and 338.7 mm/s over 69.5 cycles"
    with pytest.warns(isolab.IsolabWarning, match=identified + r" \(bncs_ica50\); this run reaches"):
        result = isolab.run(model, record, scale=2)
    cli = isolab_cli.json("run", model, "--record", record, "--scale", 2, "-o", tmp_path / "cli.h5")
    assert result.warnings == cli["warnings"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # inside the range: nothing to say
        isolab.run(model, record, scale=0.75)


def test_samples_give_the_command_lines_band(repo, tmp_path, isolab_cli):
    """run(samples=, seed=) is `isolab run --samples --seed`: the same drawn sets, the same band;
    a model without a fit's uncertainty is refused."""
    model = tmp_path / "fitted.yaml"
    model.write_text(
        "units: {force: kN, length: mm, time: s}\n"
        "structure: {type: sdof, mass: 30 t}\n"
        "isolation:\n  components:\n    - {name: iso, type: bhm2, k0: 3, k1: 0.4, uy: 5}\n"
        f"excitation:\n  ground_motion: {{file: {repo / 'ground_motions/pulse_tp2.at2'}}}\n"
        "uncertainty:\n  parameters: [{name: isolation.iso.k1, value: 0.4, log: true}]\n"
        "  covariance: [[0.01]]\n")
    cli = isolab_cli.json("run", model, "--samples", 6, "--seed", 4, "-o", tmp_path / "r.h5")
    result = isolab.run(model, samples=6, seed=4)
    assert result.summary["band"] == cli["band"]
    assert cli["band"]["samples"] == 6
    with pytest.raises(isolab.InputError, match="no uncertainty"):
        isolab.run(repo / FIVE_STORY, samples=4)
    with pytest.raises(isolab.InputError, match="2 or more"):
        isolab.run(model, samples=1)
