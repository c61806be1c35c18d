"""isolab.design against `isolab design`: the same design values, to the CSV's 12 digits, from
the same design file."""

import csv

import pytest

import isolab


def write_design(repo, folder):
    motions = repo / "ground_motions"
    records = ", ".join(str(motions / name) for name in
                        ("fwn_firm_seed1.at2", "fwn_soft_seed2.at2", "elcentro_1940_ns.at2"))
    design = folder / "design.yaml"
    building = repo / "tests" / "study" / "data" / "two_story_lrb.yaml"
    design.write_text(f"model: {building}\ntarget: {{asce7: {{sms: 1.2 g, sm1: 0.6 g}}}}\n"
                      f"suite:\n  records: [{records}]\n")
    return design


def read_values(path):
    with open(path, newline="") as f:
        return {(r["bound"], r["quantity"], r["statistic"]): float(r["value"])
                for r in csv.DictReader(f)}


def test_the_design_equals_the_command_lines(repo, tmp_path, isolab_cli):
    design = write_design(repo, tmp_path)
    isolab_cli("design", design, "-q", "--no-figures", "-o", tmp_path / "cli")
    result = isolab.design(design, output=tmp_path / "py", jobs=1, quiet=True)
    values = read_values(tmp_path / "cli" / "design_values.csv")
    assert result["statistic"] == "max"  # 3 records
    assert set(result["bounds"]) == {"nominal", "upper", "lower"}
    for bound, data in result["bounds"].items():
        assert data["elf"]["D_M"] == pytest.approx(values[(bound, "D_M", "elf")], rel=1e-11)
        assert data["elf"]["V_b"] == pytest.approx(values[(bound, "V_b", "elf")], rel=1e-11)
        for key in ("D_M", "D_TM", "V_b", "story_drift_ratio"):
            assert data["values"][key] == pytest.approx(values[(bound, key, "max")], rel=1e-11)
    assert result["governing"]["D_TM"] == "lower"
    assert [r["name"] for r in result["records"]] == ["fwn_firm_seed1", "fwn_soft_seed2",
                                                      "elcentro_1940_ns"]
    assert (tmp_path / "py" / "design.md").is_file()


def test_the_runs_warnings_come_back_as_data_and_as_isolab_warnings(repo, tmp_path):
    """A building on pendulums given 40 % of its weight: each bound's runs warn, naming both
    weights; design() returns them and issues each as an IsolabWarning."""
    model = tmp_path / "pendulums.yaml"
    model.write_text(
        "units: {force: kN, length: mm, time: s}\n"
        "isolation:\n  count: 4\n"
        "  components: [{name: fp, type: friction_pendulum, w: 500, r: 2235, mu: 0.06, uy: 0.5}]\n"
        "  modification: {fp: {mu: {min: 0.8, max: 1.3}}}\n"
        "structure: {type: shear_building, base_mass: 110 t,\n"
        "  stories: {count: 4, mass: 100 t, stiffness: 800 kN/mm, height: 3500}}\n"
        "analysis: {dt: 0.01}\n")
    motions = repo / "ground_motions"
    design = tmp_path / "design.yaml"
    design.write_text(f"model: {model}\ntarget: {{asce7: {{sms: 1.2 g, sm1: 0.6 g}}}}\n"
                      f"suite:\n  records: [{motions / 'fwn_firm_seed1.at2'}, "
                      f"{motions / 'fwn_soft_seed2.at2'}, {motions / 'elcentro_1940_ns.at2'}]\n")
    with pytest.warns(isolab.IsolabWarning, match=r"weights w sum to 2000 kN, the structure "
                                                  r"weighs 5001.4 kN"):
        result = isolab.design(design, output=tmp_path / "out", jobs=1, quiet=True)
    weights = [w for w in result["warnings"] if "weights w sum to" in w["text"]]
    assert sorted(w["bound"] for w in weights) == ["lower", "nominal", "upper"]
    assert all(w["runs"] == 3 for w in weights)
    assert result["summary"].startswith("WARNING: the runs gave ")
    # A single pendulum's law states no displacement capacity: the check says so, as data.
    [check] = [c for c in result["checks"] if c["check"].startswith("D_TM <= displacement")]
    assert check["isolators"] == ["every bearing of the layer"]
    assert check["limit"] is None and check["verdict"] == "not checked"
    assert check["demand"] == result["design_values"]["D_TM"]["value"] > 0


@pytest.mark.parametrize("output", [b"out", 42, {"folder": "out"}, 3.5])
def test_a_path_argument_is_a_path(repo, tmp_path, monkeypatch, output):
    """bytes are a path (decoded as the file system does); numbers and dicts are refused, naming
    the argument, and never become a folder's name."""
    monkeypatch.chdir(tmp_path)
    design = write_design(repo, tmp_path)
    if isinstance(output, bytes):
        result = isolab.design(design, output=output, jobs=1, quiet=True)
        assert result["output"] == "out"
        assert (tmp_path / "out" / "design.md").is_file()
        return
    with pytest.raises(TypeError, match="output: expected a path"):
        isolab.design(design, output=output, jobs=1, quiet=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["design.yaml"]


def test_a_suite_inside_the_earlier_design_it_replaces_is_refused_and_that_design_kept(
        repo, tmp_path, monkeypatch):
    """A synthetic design's pairs taken as the suite of a design into the same folder would be
    moved aside with that earlier design before the runs read them: refused at the entry, naming
    the folder and the argument, as `isolab design -o` is."""
    monkeypatch.chdir(tmp_path)
    building = repo / "tests" / "study" / "data" / "two_story_lrb.yaml"
    head = f"model: {building}\ntarget: {{asce7: {{sms: 1.2 g, sm1: 0.6 g}}}}\n"
    synthetic = tmp_path / "synthetic.yaml"
    synthetic.write_text(head + "suite: {synthetic: {count: 3}}\n")
    isolab.design(synthetic, output="out", jobs=1, quiet=True)
    before = {p: p.read_bytes() for p in (tmp_path / "out").rglob("*") if p.is_file()}
    again = tmp_path / "again.yaml"
    again.write_text(head + "suite:\n  records: [out/records/pair1_h1.at2, "
                     "out/records/pair2_h1.at2, out/records/pair3_h1.at2]\n")
    with pytest.raises(isolab.InputError, match=r"suite.records\[0\]: '\S*/out/records/"
                       r"pair1_h1.at2' is inside 'out', the earlier design this design replaces "
                       r"\(output\)"):
        isolab.design(again, output="out", jobs=1, quiet=True)
    assert {p: p.read_bytes() for p in (tmp_path / "out").rglob("*") if p.is_file()} == before
