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
