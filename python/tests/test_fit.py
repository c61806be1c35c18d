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
    # One workflow and one rendering (cyclic/cyclic_fit.h): every key the command line prints
    # but the model file it wrote, with the same values.
    assert set(mine) == set(cli) - {"output"}
    for key in ("units", "identified_range", "identifiability", "one_specimen", "stop", "seed"):
        assert mine[key] == cli[key], key
    assert [(r["test"], r["cycle"]) for r in mine["energy_per_cycle"]] == \
        [(r["test"], r["cycle"]) for r in cli["energy_per_cycle"]]
    for a, b in zip(mine["energy_per_cycle"], cli["energy_per_cycle"]):
        assert a["fitted"] == pytest.approx(b["fitted"], rel=1e-9)
        assert a["measured"] == b["measured"]
    assert mine["testing_factors"]["qd"] == cli["testing_factors"]["qd"]
    # The data came from the trilinear spring of three_laws.yaml: it comes back (its k1, k2, uyh).
    assert mine["components"][2]["parameters"]["k1"] == pytest.approx(0.2, abs=1e-3)
    assert mine["e2"] < 1e-4


def test_fit_bad_input(repo, tmp_path):
    with pytest.raises(isolab.InputError, match="no_such.csv"):
        isolab.fit(tmp_path / "no_such.csv", repo / SPEC, quiet=True)


def test_building_fit_equals_the_command_line(tmp_path, isolab_cli, shake_table):
    """isolab.fit(building=) returns what `isolab fit --building --json` prints (one library
    function builds both) and writes the fitted model where it is told, as the command line does."""
    data, spec = shake_table
    cli = isolab_cli.json("fit", data, "--building", spec, "--budget", 600, "--threads", 1,
                          "--offsets", "none", "-q", "-o", tmp_path / "cli.fitted.yaml")
    mine = isolab.fit(data, building=spec, budget=600, threads=1, offsets="none", quiet=True,
                      output=tmp_path / "mine.fitted.yaml")
    assert mine["output"] == str(tmp_path / "mine.fitted.yaml")
    assert (tmp_path / "mine.fitted.yaml").exists()
    for key in ("seconds", "output"):  # the run's own
        del mine[key], cli[key]
    assert mine == cli
    # The data came from the building the spec starts 50 % and 33 % off: it comes back.
    assert [p["name"] for p in mine["parameters"]] == ["isolation.iso.k1", "stories.stiffness"]
    assert mine["parameters"][0]["value"] == pytest.approx(0.4, rel=1e-3)
    assert mine["parameters"][1]["value"] == pytest.approx(60.0, rel=1e-3)
    fitted = isolab.load_model(str(tmp_path / "mine.fitted.yaml"))
    assert fitted.get("isolation.components[0].k1") == pytest.approx(0.4, rel=1e-3)


def test_building_model_form_equals_the_command_line(tmp_path, isolab_cli, shake_table):
    """isolab.fit(building=, model_form=True) returns what `isolab fit --building --model-form
    --json` prints, and both write the model with the fits to each motion as its model form and
    the spec's prior."""
    data, spec = shake_table
    other = tmp_path / "other.csv"
    other.write_text(data.read_text())
    # With a prior too: the isolator's yield displacement held at the model's 5 mm.
    spec.write_text(spec.read_text() +
                    "priors:\n  - {name: isolation.iso.uy, sigma: 0.1, source: design data}\n")
    common = ["--budget", 400, "--threads", 1, "--offsets", "none", "-q"]
    cli = isolab_cli.json("fit", data, other, "--building", spec, "--model-form", *common,
                          "-o", tmp_path / "cli.fitted.yaml")
    mine = isolab.fit([data, other], building=spec, model_form=True, budget=400, threads=1,
                      offsets="none", quiet=True, output=tmp_path / "mine.fitted.yaml")
    for key in ("seconds", "output"):  # the run's own
        del mine[key], cli[key]
    assert mine == cli
    assert mine["priors"] == [{"name": "isolation.iso.uy", "value": 5.0, "sigma": 0.1,
                               "source": "design data"}]
    fits = mine["model_form"]["fits"]
    assert [f["fitted_on"] for f in fits] == [["other"], ["motion"]]
    assert [p["name"] for p in mine["model_form"]["parameters"]] == \
        ["isolation.iso.k1", "stories.stiffness"]
    for name in ("cli", "mine"):
        text = (tmp_path / f"{name}.fitted.yaml").read_text()
        assert "model_form:" in text and "fitted_on: [other]" in text, name
        assert "priors:" in text and "source: design data" in text, name


def test_building_fit_refuses_what_does_not_apply(repo, tmp_path, shake_table):
    data, spec = shake_table
    output = tmp_path / "refused.yaml"
    cases = [
        (dict(model=repo / SPEC, building=spec), "building= excludes model="),
        (dict(), r"give model= \(cyclic tests\) or building= \(shake-table motions\)"),
        (dict(building=spec, cycles=3), "cycles= applies to cyclic tests, not to building="),
        (dict(building=spec, force=True), "force= applies to cyclic tests, not to building="),
        (dict(building=spec, force_unit="kN"), "force_unit= applies to force-driven tests"),
        (dict(building=spec, offsets="sometimes"), "offsets= sometimes: expected pre-event or none"),
        (dict(building=spec, specimen="one"),
         r"specimen: 'one' \(expected sequential or independent\)"),
        (dict(model=repo / SPEC, offsets="none"), "offsets= applies to building=, not to cyclic"),
        (dict(model=repo / SPEC, global_budget=500), "global_budget= applies to building="),
        (dict(building=spec, global_budget=50), "global_budget"),
        (dict(model=repo / SPEC, cross_validate=True), "cross_validate= applies to building="),
        (dict(model=repo / SPEC, model_form=True), "model_form= applies to building="),
        (dict(building=spec, cross_validate=True, model_form=True),
         "cross_validate=True and model_form=True"),
        (dict(building=spec, model_form=True),
         "the model form holds one motion out and fits the others"),
        (dict(building=spec, cross_validate=True), "output= with cross_validate=True"),
        (dict(model=repo / SPEC, output=output), "output= applies to building="),
    ]
    # A pause between one specimen's motions of ten million seconds (a billion samples) is not a
    # rest but a run out of memory: refused before any simulation.
    paused = tmp_path / "paused.yaml"
    paused.write_text(spec.read_text() + "pause: 1.0e7\n")
    cases.append((dict(building=paused, specimen="sequential"),
                  r"pause: 1e\+07 is 1e\+09 samples of motion's step; at most 1e\+06"))
    # A band above the data's Nyquist frequency (50 Hz at 0.01 s) and substeps beyond a run's
    # steps are the specification's, and named so (not the model's, nor --dt's).
    for name, extra, message in [
            ("nyquist", "band: [60, 100]\n",
             r"band: \[60, 100\] lies above motion's Nyquist frequency \(50, sampled every 0.01\)"),
            ("substeps", "substeps: 10000\n", r"substeps: 10000 makes 4.5e\+07 steps a simulation")]:
        variant = tmp_path / f"{name}.yaml"
        variant.write_text(spec.read_text() + extra)
        cases.append((dict(building=variant), f"{variant}: " + message))
    for kwargs, message in cases:
        kwargs.setdefault("output", output) if "building" in kwargs else None
        with pytest.raises(isolab.InputError, match=message):
            isolab.fit(data, budget=300, quiet=True, **kwargs)
        assert not output.exists(), message
    # Cross-validation holds one motion out and fits the others: one motion is not enough.
    with pytest.raises(isolab.InputError, match="it needs two motions or more"):
        isolab.fit(data, building=spec, cross_validate=True, budget=300, quiet=True)
