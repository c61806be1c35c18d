"""isolab.fit against the command line's fit of the same generated tests."""

import pytest

import isolab

THREE_LAWS = "tests/cli/data/fit/three_laws.yaml"
SPEC = "tests/cli/data/fit/three_laws_spec.yaml"


def test_fit_equals_the_command_line(repo, tmp_path, isolab_cli):
    data = tmp_path / "tests.csv"
    isolab_cli("cyclic", THREE_LAWS, "-a", "5,50,100,150", "-T", 2, "-n", 3, "--steps-per-cycle",
               200, "--test-data", data)
    cli = isolab_cli.json("fit", data, "--model", SPEC, "--budget", 3000, "--seed", 5,
                          "--cycles", 3, "-q", "-o", tmp_path / "fitted.yaml")
    mine = isolab.fit(data, repo / SPEC, budget=3000, seed=5, cycles=3, quiet=True)
    assert mine["e2"] == pytest.approx(cli["e2"], rel=1e-9, abs=1e-15)
    assert mine["e2_per_test"] == pytest.approx(cli["e2_per_test"], rel=1e-9, abs=1e-15)
    assert mine["evaluations"] == cli["evaluations"]
    assert mine["e2_mean"] == pytest.approx(cli["e2_mean"], rel=1e-9, abs=1e-15)
    assert mine["stop_reason"] == cli["stop_reason"]
    # The thread count changes the speed, never the result.
    again = isolab.fit(data, repo / SPEC, budget=3000, seed=5, cycles=3, quiet=True, threads=1)
    assert again["e2"] == mine["e2"]
    for a, b in zip(mine["components"], cli["components"]):
        assert (a["name"], a["type"]) == (b["name"], b["type"])
        assert a["parameters"] == pytest.approx(b["parameters"], rel=1e-9, abs=1e-12)
    # The data came from the trilinear spring of three_laws.yaml: it comes back (its k1, k2, uyh).
    assert mine["components"][2]["parameters"]["k1"] == pytest.approx(0.2, abs=1e-3)
    assert mine["e2"] < 1e-4


def test_fit_bad_input(repo, tmp_path):
    with pytest.raises(isolab.InputError, match="no_such.csv"):
        isolab.fit(tmp_path / "no_such.csv", repo / SPEC, quiet=True)
