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
