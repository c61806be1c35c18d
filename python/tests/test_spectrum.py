"""isolab.spectrum against the command line's HDF5 spectra and the closed form of a sine."""

import math

import h5py
import numpy as np
import pytest

import isolab

PULSE = "ground_motions/pulse_tp2.at2"


def test_spectrum_equals_the_command_line(repo, tmp_path, isolab_cli):
    h5 = tmp_path / "spectrum.h5"
    isolab_cli("spectrum", PULSE, "--periods", "0.2,0.5,1,2,3", "--damping", "0,0.05",
               "--ductility", "2,4", "--scale", 0.5, "-o", h5, "-q")
    mine = isolab.spectrum(repo / PULSE, periods=[0.2, 0.5, 1, 2, 3], damping=[0, 0.05],
                           ductility=[2, 4], scale=0.5)
    with h5py.File(h5) as f:
        np.testing.assert_array_equal(mine["period"], f["period"][...])
        for name in ("D", "V", "A", "time_of_peak"):
            np.testing.assert_allclose(mine["elastic"][name], f["elastic"][name][...], rtol=1e-12)
        for name in ("strength_ratio", "D_y", "A_y", "u_m", "achieved_ductility"):
            np.testing.assert_allclose(mine["constant_ductility"][name],
                                       f["constant_ductility"][name][...], rtol=1e-12)
        assert mine["record"]["pga"] == pytest.approx(f.attrs["record_pga"], rel=1e-12)


def test_the_command_lines_list_syntax_and_units(repo, isolab_cli):
    # periods="0.05:5:0.05" crashed in float(); the same text gives the command line's numbers.
    cli = isolab_cli.json("spectrum", PULSE, "--periods", "0.1:1:0.3", "--damping", "0.02,0.05",
                          "--ductility", "2", "-q")
    mine = isolab.spectrum(repo / PULSE, periods="0.1:1:0.3", damping="0.02,0.05", ductility="2")
    assert mine["period"].tolist() == cli["periods"] == [0.1, 0.4, 0.7, 1.0]
    assert mine["damping"].tolist() == [0.02, 0.05]
    for d, curve in enumerate(cli["elastic"]):
        for name in ("D", "A", "A_g"):
            np.testing.assert_allclose(mine["elastic"][name][d], curve[name], rtol=1e-12)
    np.testing.assert_allclose(mine["constant_ductility"]["A_y_g"][0, 0],
                               cli["constant_ductility"][0]["A_y_g"], rtol=1e-12)
    # Units as the command line's table heads give them: A in m/s^2, A_g in g = A / 9.80665.
    assert mine["units"]["A"] == "m/s^2" and mine["units"]["A_g"] == "g"
    assert mine["units"]["D"] == "m" and mine["units"]["V"] == "m/s"
    assert mine["units"]["g"] == cli["units"]["g"] == 9.80665
    np.testing.assert_allclose(mine["elastic"]["A_g"], mine["elastic"]["A"] / 9.80665, rtol=1e-15)
    in_mm = isolab.spectrum(repo / PULSE, periods="0.5", length_unit="mm")
    assert in_mm["units"]["A"] == "mm/s^2" and in_mm["units"]["g"] == 9806.65
    with pytest.raises(isolab.InputError, match="^periods: '1:0.5:0.1': STOP = 0.5 must be >= "):
        isolab.spectrum(repo / PULSE, periods="1:0.5:0.1")
    with pytest.raises(isolab.InputError, match="^damping: 'x' is not a number"):
        isolab.spectrum(repo / PULSE, periods=[1.0], damping="0.05,x")


def test_undamped_sine_at_resonance_against_the_closed_form():
    # a_g = a0 sin(w t) on an undamped SDOF of the same w: u(t) = a0 / (2 w^2) (sin wt - wt cos wt)
    # (Chopra Eq. 3.1.13); its peak over 5 periods is at the last |cos| extreme, close to
    # a0 / (2 w^2) * w t_end.
    dt, w, a0 = 0.001, 2 * math.pi, 1.0
    t = np.arange(0, 5.0 + dt / 2, dt)
    result = isolab.spectrum(a0 * np.sin(w * t), record_dt=dt, units="m/s^2", periods=[1.0],
                             damping=0.0)
    exact = np.abs(a0 / (2 * w**2) * (np.sin(w * t) - w * t * np.cos(w * t))).max()
    assert result["elastic"]["D"][0, 0] == pytest.approx(exact, rel=1e-4)


def test_spectrum_bad_input():
    with pytest.raises(isolab.InputError, match="damping"):
        isolab.spectrum(np.ones(100), record_dt=0.01, units="g", damping=1.5)
    with pytest.raises(isolab.InputError, match="record_dt"):
        isolab.spectrum(np.ones(100), units="g")


def test_a_spectrum_beyond_max_steps_is_refused_before_it_starts(repo):
    record = repo / "ground_motions/fwn_firm_seed1.at2"
    with pytest.raises(isolab.InputError, match="max_steps: the spectrum would take about"):
        isolab.spectrum(record, periods=[1e-9])
    with pytest.raises(isolab.InputError, match="raise max_steps"):
        isolab.spectrum(record, periods=[1.0], max_steps=10)


def test_a_pair_equals_the_command_lines_and_refuses_ductility(repo, tmp_path, isolab_cli):
    h1, h2 = "ground_motions/fwn_firm_seed1.at2", "ground_motions/h2_fwn_firm_seed3.at2"
    h5 = tmp_path / "pair.h5"
    isolab_cli("spectrum", h1, h2, "--periods", "0.5,1,2.5", "--scale", 0.6, "-o", h5, "-q")
    mine = isolab.spectrum(repo / h1, repo / h2, periods=[0.5, 1, 2.5], scale=0.6)
    assert "elastic" not in mine
    with h5py.File(h5) as f:
        for curve in ("h1", "h2", "geometric_mean", "rotd50", "rotd100"):
            for name in ("D", "V", "A"):
                np.testing.assert_array_equal(mine[curve][name], f[curve][name][...])
        np.testing.assert_array_equal(mine["rotd100"]["angle"], f["rotd100/angle"][...])
        assert mine["record_h2"]["pga"] == f.attrs["record_h2_pga"]
    # The components' curves are each record's own spectrum.
    alone = isolab.spectrum(repo / h2, periods=[0.5, 1, 2.5], scale=0.6)
    np.testing.assert_array_equal(mine["h2"]["D"], alone["elastic"]["D"])
    assert (mine["rotd100"]["D"] >= np.maximum(mine["h1"]["D"], mine["h2"]["D"])).all()
    with pytest.raises(isolab.InputError, match="ductility"):
        isolab.spectrum(repo / h1, repo / h2, periods=[1.0], ductility=2)
    with pytest.raises(isolab.InputError, match="a pair has one length"):
        isolab.spectrum(repo / h1, repo / "ground_motions/pulse_tp2.at2", periods=[1.0])
