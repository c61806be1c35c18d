"""isolab.diagnose against the command line's JSON report, on tests generated from a known
truth (a degrading bearing) that it must name: both render the one report the library builds,
candidates, verdict and identifiability included."""

import pytest

import isolab

TRUTH = "models/diagnosis/cyclic_degradation.yaml"
BASE = "models/diagnosis/base_bhm2.yaml"


def test_diagnose_equals_the_command_line(repo, tmp_path, isolab_cli):
    data = tmp_path / "tests.csv"
    isolab_cli("cyclic", TRUTH, "-a", "25,100,200", "-T", 2, "-n", 3, "--steps-per-cycle", 100,
               "--noise", 0.01, "--seed", 15, "--test-data", data)
    cli = isolab_cli.json("diagnose", data, "--base", BASE, "--budget", 1500, "-q", "--no-plot",
                          "--out", tmp_path / "report")
    mine = isolab.diagnose(data, repo / BASE, budget=1500, quiet=True)
    assert mine["effects"] == cli["effects"] == ["cyclic_degradation"]  # the data's truth
    assert mine["stop_reason"] == cli["stop_reason"]
    assert mine["head"] == cli["head"]
    assert mine["head"][0].startswith("Verdict: ")
    assert mine["verdict"]["kind"] == cli["verdict"]["kind"]
    assert mine["identifiability"]["findings"] == cli["identifiability"]["findings"]
    assert [c["effect"] for c in mine["steps"][0]["candidates"]] == \
        [c["effect"] for c in cli["steps"][0]["candidates"]]
    assert mine["noise_floor_e2"] == pytest.approx(cli["noise_floor_e2"], rel=1e-9)
    for which in ("base", "final"):
        assert mine[which]["e2"] == pytest.approx(cli[which]["e2"], rel=1e-9)
        for a, b in zip(mine[which]["components"], cli[which]["components"]):
            assert a["parameters"] == pytest.approx(b["parameters"], rel=1e-9, abs=1e-12)
    for a, b in zip(mine["steps"], cli["steps"]):
        assert a["evidence"]["value"] == pytest.approx(b["evidence"]["value"], rel=1e-9)
        assert a["e2_after"] == pytest.approx(b["e2_after"], rel=1e-9)
        assert a["added"]["parameters"] == pytest.approx(b["added"]["parameters"], rel=1e-9)


def test_diagnose_bad_input(repo, tmp_path):
    with pytest.raises(isolab.InputError, match="no_such.csv"):
        isolab.diagnose(tmp_path / "no_such.csv", repo / BASE, quiet=True)
    bare = tmp_path / "bare.csv"
    bare.write_text("test,time,displacement,force\n" +
                    "".join(f"u,{k},{[0, 1, 0, -1][k % 4]},{[0, 1, 0, -1][k % 4]}\n"
                            for k in range(20)))
    with pytest.raises(isolab.InputError, match="force_unit= and length_unit="):
        isolab.diagnose(bare, repo / BASE, quiet=True)


def test_building_diagnosis_equals_the_command_line(tmp_path, isolab_cli, shake_table):
    """isolab.diagnose(building=) returns the report `isolab diagnose --building --json` prints,
    its head opening with the building's lines and its "building" object the same (one library
    function builds both); the files stay with the command line."""
    data, spec = shake_table
    cli = isolab_cli.json("diagnose", data, "--building", spec, "--budget", 300, "--threads", 1,
                          "--offsets", "none", "--no-plot", "-q", "--out", tmp_path / "report")
    mine = isolab.diagnose(data, building=spec, budget=300, threads=1, offsets="none",
                           quiet=True)
    assert mine["head"] == cli["head"]
    assert mine["effects"] == cli["effects"]
    assert mine["building"] == cli["building"]
    assert mine["building"]["base"]["parameters"][0]["name"] == "isolation.iso.k1"
    assert mine["head"][-1].startswith("Note: Building: ")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["motion.csv", "spec.yaml", "start.yaml", "truth.yaml", "report.json", "report.md",
         "report.model.yaml", "report.residual.csv"])  # the command line's files, none of mine


def test_building_diagnosis_refuses_what_does_not_apply(repo, tmp_path, shake_table):
    data, spec = shake_table
    cases = [
        (dict(base=repo / BASE, building=spec), "building= excludes base="),
        (dict(), r"give base= \(cyclic tests\) or building= \(a building's shake-table"),
        (dict(building=spec, force_unit="kN", length_unit="mm"),
         "force_unit= and length_unit= apply to cyclic tests, not to building="),
        (dict(building=spec, force=True), "force= applies to cyclic tests, not to building="),
        (dict(base=repo / BASE, offsets="none"), "offsets= applies to building=, not to cyclic"),
    ]
    for kwargs, message in cases:
        with pytest.raises(isolab.InputError, match=message):
            isolab.diagnose(data, budget=300, quiet=True, **kwargs)
