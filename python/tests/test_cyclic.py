"""isolab.cyclic against the command line and the bilinear loop's closed-form energy."""

import numpy as np
import pytest

import isolab

TABLE9 = "models/paper/table9_thm1_system.yaml"


def test_cyclic_equals_the_command_line(repo, tmp_path, isolab_cli):
    cli = isolab_cli.json("cyclic", TABLE9, "-a", 150, "-n", 3, "--csv", tmp_path / "loop.csv")
    result = isolab.cyclic(repo / TABLE9, 150, cycles=3)
    run = cli["runs"][0]
    assert result.protocol == run["protocol"]
    assert len(result.cycles) == 3
    for mine, theirs in zip(result.cycles, run["cycles"]):
        assert mine["dissipated"] == pytest.approx(theirs["dissipated"], rel=1e-12)
        assert mine["peak_force"] == pytest.approx(theirs["peak_force"], rel=1e-12)
        for a, b in zip(mine["components"], theirs["components"]):
            assert a["name"] == b["name"]
            assert a["slider_at_peak"] == pytest.approx(b["slider_at_peak"], rel=1e-12, abs=1e-12)
    loop = np.loadtxt(tmp_path / "loop.csv", delimiter=",", skiprows=1)
    np.testing.assert_allclose(result.time, loop[:, 0], rtol=1e-9)
    np.testing.assert_allclose(result.displacement, loop[:, 1], rtol=1e-9, atol=1e-9 * 150)
    np.testing.assert_allclose(result.force, loop[:, 2], rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(result.component_force, loop[:, 3:], rtol=1e-9, atol=1e-6)
    assert result.components == [f"c{i}" for i in range(1, 10)]
    assert not result.force.flags.writeable


BILINEAR = {
    "units": {"force": "kN", "length": "mm", "time": "s"},
    "isolation": {"components": [
        {"name": "bilinear", "type": "bhm2", "ke": 8.0653, "kh": 0.80653, "fs": 18.146}]},
}


def test_bilinear_loop_energy_is_the_closed_form():
    # A bilinear bearing (BHM2: ke, kh, fs): every cycle after the first encloses the
    # parallelogram W_d = 4 Qd (D - Dy), Dy = Qd / (Ku - Kd) (Naeim & Kelly, Eq. 4.5).
    result = isolab.cyclic(isolab.Model.from_dict(BILINEAR), 150, cycles=2)
    dy = 18.146 / (8.0653 - 0.80653)
    assert result.cycles[1]["dissipated"] == pytest.approx(4 * 18.146 * (150 - dy), rel=1e-9)
    assert result.cycles[1]["peak_force"] == pytest.approx(18.146 + 0.80653 * 150, rel=1e-9)


def test_cyclic_needs_an_amplitude(repo):
    with pytest.raises(isolab.InputError, match="no amplitude"):
        isolab.cyclic(isolab.Model.from_dict(BILINEAR))
    with pytest.raises(isolab.InputError, match="steps_per_cycle"):
        isolab.cyclic(repo / TABLE9, 100, steps_per_cycle=6)


DEGRADING = "models/diagnosis/cyclic_degradation.yaml"


def test_a_sequential_campaign_writes_the_command_lines_test_data(repo, tmp_path, isolab_cli,
                                                                   monkeypatch):
    monkeypatch.chdir(repo)
    options = ["-a", "50,100,150", "-T", "1,2", "-n", "2", "--noise", "0.01", "--seed", "7"]
    isolab_cli("cyclic", DEGRADING, *options, "--sequential", "--test-data", tmp_path / "cli.csv")
    runs = isolab.cyclic(DEGRADING, [50, 100, 150], period=[1, 2], cycles=2, sequential=True,
                         test_data=tmp_path / "py.csv", noise=0.01, seed=7)
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    assert "# specimen: one" in (tmp_path / "py.csv").read_text()
    assert [(r.protocol["period"], r.protocol["amplitude"]) for r in runs] == \
        [(t, a) for t in (1.0, 2.0) for a in (50.0, 100.0, 150.0)]
    # One specimen: a scragged bearing dissipates less in its second test at 50 mm than a
    # fresh one does in its first (the test at T = 2 follows the three at T = 1).
    fresh = isolab.cyclic(DEGRADING, 50, period=2, cycles=2)
    assert runs[3].cycles[0]["dissipated"] < 0.99 * fresh.cycles[0]["dissipated"]
    assert isolab.cyclic(DEGRADING, [50], period=2, cycles=2)[0].cycles[0]["dissipated"] == \
        fresh.cycles[0]["dissipated"]


def test_a_path_and_an_orbit_as_the_command_line_drives_them(repo, tmp_path, isolab_cli):
    # A measured test, replayed blind: the command line's JSON and the module's dict agree, and
    # the module's arrays hold the histories behind them.
    data = tmp_path / "tests.csv"
    isolab_cli("cyclic", DEGRADING, "-a", "25,100", "-T", 2, "-n", 2, "--steps-per-cycle", 200,
               "--noise", 0.01, "--seed", 3, "--test-data", data)
    cli = isolab_cli.json("cyclic", DEGRADING, "--path", data)["runs"]
    mine = isolab.cyclic(repo / DEGRADING, path=data)
    assert [r["path"] for r in mine] == [r["path"] for r in cli] == ["u=25", "u=100"]
    for a, b in zip(mine, cli):
        assert a["comparison"]["e2"] == pytest.approx(b["comparison"]["e2"], rel=1e-12)
        assert a["dissipated"][-1] == pytest.approx(b["dissipated"], rel=1e-12)
        assert a["force"].shape == a["measured"].shape == a["time"].shape
        error = np.sum((a["measured"] - a["force"]) ** 2) / np.sum(a["measured"] ** 2)
        assert a["comparison"]["e2"] == pytest.approx(error, rel=1e-12)
    # The truth itself against its own noisy data: the 1 % noise is what is left.
    assert mine[1]["comparison"]["e2"] == pytest.approx(1e-4, rel=0.2)
    # Round a circle, a bilinear bearing's coupled slider carries fs exactly while it slips.
    orbit = isolab.cyclic(isolab.Model.from_dict(BILINEAR), 150, orbit="circle", cycles=2,
                          steps_per_cycle=1000)[0]
    assert orbit["force"].shape[1] == 2
    slider = orbit["component_force"][0]  # the one component: spring kh u plus the slider
    u_end = orbit["displacement"][-1]
    assert np.linalg.norm(slider[-1] - 0.80653 * u_end) == pytest.approx(18.146, rel=1e-9)


def test_arguments_of_the_other_mode_are_refused_by_name(repo):
    """As the command line does: path and orbit, or the sinusoidal test, each with its own
    arguments; one of the other mode is an InputError naming it, never ignored."""
    bilinear = isolab.Model.from_dict(BILINEAR)
    for name, value in [("test_data", repo / "unused.csv"), ("noise", 0.1), ("seed", 3),
                        ("sequential", True)]:
        with pytest.raises(isolab.InputError, match=f"^{name}: "):
            isolab.cyclic(bilinear, 150, orbit="circle", **{name: value})
    for name, value in [("isolator", "ne"), ("uncoupled", True), ("force_unit", "kN")]:
        with pytest.raises(isolab.InputError, match=f"^{name}: "):
            isolab.cyclic(bilinear, 150, **{name: value})
    with pytest.raises(isolab.InputError, match="^isolator: .* is not a building in plan"):
        isolab.cyclic(bilinear, 150, orbit="circle", isolator="ne")
    plan = repo / "models/plan/five_story_table9_plan.yaml"
    with pytest.raises(isolab.InputError, match="^uncoupled: .* is a building in plan"):
        isolab.cyclic(plan, 100, orbit="circle", uncoupled=True)
    with pytest.raises(isolab.InputError, match="a building in plan: its isolators are driven"):
        isolab.cyclic(plan, 100)
    assert len(isolab.cyclic(plan, 100, orbit="circle", cycles=1, isolator="ne")) == 1
