"""Every bearing law and preset through Python, on a one-direction building and on a building in
plan: isolab.run, isolab.cyclic (a sinusoid, or an orbit round a plan isolator) and, for one
law of each family, isolab.design; each compared with the command line on the same files (the
C++ matrix, tests/cli/law_command_matrix_test.cpp, checks each command's numbers)."""

import csv
import json
import math

import pytest

import isolab

# One bearing of four under a 510 t building, as the C++ matrix has them: (type, components, the
# key the bounds scale, whether the law has a coupled form in plan).
LAWS = [
    ("bhm1", "{name: b, type: bhm1, k0: 3.4, k1: 0.34, uy: 28.9}", "k1", True),
    ("bhm2", "{name: b, type: bhm2, k0: 3.4, k1: 0.34, uy: 28.9}", "k1", True),
    ("thm1", "{name: b, type: thm1, k0: 3.4, k1: 0.34, k2: 1.0, uy: 28.9, uyh: 250}", "k1", True),
    ("thm2", "{name: b, type: thm2, k0: 3.4, k1: 0.34, k2: 1.0, uy: 28.9, uyh: 250}", "k1", True),
    ("bouc_wen", "{name: b, type: bouc_wen, alpha: 3.4, beta: 0.0385, gamma: 0.5, delta: 0.5, "
     "nu: 1}, {name: k, type: linear_spring, k: 0.34}", "alpha", True),
    ("degrading_bhm2", "{name: b, type: degrading_bhm2, k0: 3.4, k1: 0.34, uy: 28.9, loss: 0.3, "
     "slip_scale: 500}", "k1", False),
    ("lead_rubber", "{name: b, type: lead_rubber, qd: 88.26, kd: 0.3391, ku: 3.391, "
     "lead_diameter: 106, lead_height: 127, lead_heat_capacity: 1.456e-3, "
     "steel_conductivity: 0.05, steel_diffusivity: 14.1, shim_thickness: 27}", "qd", True),
    ("friction_pendulum", "{name: b, type: friction_pendulum, w: 1250, r: 2235, uy: 0.5, "
     "mu_slow: 0.03, mu_fast: 0.06, a: 0.02}", "mu_fast", True),
    ("hdr_bearing", "{name: b, type: hdr_bearing, g: 4.0e-4, area: 231875, tr: 100, "
     "damping: 0.089, strain: 1.5}", "g", True),
    ("double_friction_pendulum", "{name: b, type: double_friction_pendulum, w: 1250, r1: 1500, "
     "r2: 1500, mu1: 0.04, mu2: 0.07, d1: 300, d2: 300, uy: 0.5}", "mu1", True),
    ("triple_friction_pendulum", "{name: b, type: triple_friction_pendulum, w: 1250, r1: 2100, "
     "r2: 280, r3: 280, r4: 2100, mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 400, d2: 50, "
     "d3: 50, d4: 400, uy: 0.5}", "mu1", True),
    ("asymmetric_elastoplastic", "{name: b, type: asymmetric_elastoplastic, k0: 3.4, "
     "uy_pos: 28.9, uy_neg: 20}, {name: k, type: linear_spring, k: 0.34}", "k0", False),
    ("backlash_elastoplastic", "{name: b, type: backlash_elastoplastic, k0: 3.4, uy: 28.9, "
     "gap: 5}, {name: k, type: linear_spring, k: 0.34}", "k0", False),
]


def model_text(repo, law, plan):
    _, components, key, coupled = law
    motions = repo / "ground_motions"
    modification = f"{{b: {{{key}: {{min: 0.9, max: 1.1}}}}}}"
    if not plan:
        return ("units: {force: kN, length: mm, time: s}\n"
                f"isolation:\n  count: 4\n  components: [{components}]\n"
                f"  modification: {modification}\n"
                "structure: {type: shear_building, base_mass: 110 t,\n"
                "  stories: {count: 2, mass: 200 t, stiffness: 800 kN/mm, height: 3500}}\n"
                f"excitation: {{ground_motion: {{file: {motions / 'fwn_firm_seed1.at2'}}}}}\n"
                "analysis: {dt: 0.01}\n")
    return ("units: {force: kN, length: mm, time: s}\n"
            "plan:\n  footprint: [[0, 0], [20000, 10000]]\n  base: {mass: 110 t}\n"
            "  stories: {count: 2, mass: 200 t, height: 3500,\n"
            "            stiffness: {x: 800 kN/mm, y: 800 kN/mm, torsion: 3.33e10}}\n"
            "  isolators:\n    - name: b\n"
            "      positions: [[0, 0], [20000, 0], [0, 10000], [20000, 10000]]\n"
            + ("" if coupled else "      coupling: uncoupled\n")
            + f"      components: [{components}]\n      modification: {modification}\n"
            "excitation:\n  ground_motion:\n"
            f"    h1: {{file: {motions / 'fwn_firm_seed1.at2'}}}\n"
            f"    h2: {{file: {motions / 'h2_fwn_firm_seed3.at2'}}}\n"
            "analysis: {dt: 0.01}\n")


@pytest.mark.parametrize("plan", [False, True], ids=["one_direction", "plan"])
@pytest.mark.parametrize("law", LAWS, ids=[law[0] for law in LAWS])
def test_run_and_cyclic_are_the_command_lines(repo, tmp_path, isolab_cli, law, plan):
    model = tmp_path / "m.yaml"
    model.write_text(model_text(repo, law, plan))

    result = isolab.run(model)
    cli = isolab_cli.json("run", model, "-q", "-o", tmp_path / "r.h5")
    assert result.peaks["isolator_displacement"]["value"] == pytest.approx(
        cli["peaks"]["isolator_displacement"]["value"], rel=1e-12)
    assert result.summary["energy_balance_error"] < 1e-2
    assert 1.0 < result.peaks["isolator_displacement"]["value"] < 1000.0

    if plan:
        [loop] = isolab.cyclic(model, 100, orbit="circle", cycles=2, isolator="b_1")
        [expected] = isolab_cli.json("cyclic", model, "--isolator", "b_1", "--orbit", "circle",
                                     "-a", "100", "-n", "2")["runs"]
        dissipated = loop["dissipated"][-1]  # the history's last: the orbit's energy
        assert dissipated == pytest.approx(expected["dissipated"], rel=1e-12)
    else:
        loop = isolab.cyclic(model, 100, cycles=2)
        [expected] = isolab_cli.json("cyclic", model, "-a", "100", "-n", "2")["runs"]
        dissipated = loop.cycles[1]["dissipated"]
        assert dissipated == pytest.approx(expected["cycles"][1]["dissipated"], rel=1e-12)
    assert math.isfinite(dissipated) and dissipated > 0


# One law of each family (bilinear, rubber with heating, pendulum of several surfaces) designed
# through Python on each kind of model: the command line's design values, to its 12 digits.
@pytest.mark.parametrize("plan", [False, True], ids=["one_direction", "plan"])
@pytest.mark.parametrize("law", [LAWS[1], LAWS[6], LAWS[10]], ids=["bhm2", "lead_rubber",
                                                                   "triple_friction_pendulum"])
def test_design_is_the_command_lines(repo, tmp_path, isolab_cli, law, plan):
    (tmp_path / "m.yaml").write_text(model_text(repo, law, plan))
    motions = repo / "ground_motions"
    files = [motions / name for name in ("fwn_firm_seed1.at2", "fwn_soft_seed2.at2",
                                         "h2_fwn_firm_seed3.at2")]
    if plan:
        records = ", ".join(f"{{h1: {{file: {a}}}, h2: {{file: {b}}}}}"
                            for a, b in zip(files, files[1:] + files[:1]))
    else:
        records = ", ".join(str(f) for f in files)
    design = tmp_path / "design.yaml"
    design.write_text("model: m.yaml\ntarget: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\n"
                      f"suite:\n  records: [{records}]\neccentricity: 0\n")
    isolab_cli("design", design, "-q", "--no-figures", "-o", tmp_path / "cli")
    result = isolab.design(design, output=tmp_path / "py", jobs=1, quiet=True)
    with open(tmp_path / "cli" / "design_values.csv", newline="") as f:
        values = {(r["bound"], r["quantity"], r["statistic"]): float(r["value"])
                  for r in csv.DictReader(f)}
    for bound, data in result["bounds"].items():
        assert data["elf"]["D_M"] == pytest.approx(values[(bound, "D_M", "elf")], rel=1e-11)
        assert data["values"]["D_TM"] == pytest.approx(values[(bound, "D_TM", "max")], rel=1e-11)
        # The bearings as OpenSees elements, the command line's file; none for a lead core that
        # heats (no OpenSees element reproduces it), and the design says why.
        written = tmp_path / "cli" / "models" / f"m_{bound}.tcl"
        if law[0] == "lead_rubber":
            assert data["opensees"] is None and not written.exists()
        else:
            with open(data["opensees"]) as ours, open(written) as theirs:
                assert ours.read() == theirs.read()
    if law[0] == "lead_rubber":
        assert "lead_rubber with the lead core's heating" in result["opensees_refused"]
        assert result["opensees_refused"] in (tmp_path / "cli" / "design.md").read_text()
    else:
        assert result["opensees_refused"] is None
    assert json.dumps(result["checks"])  # data, not text
