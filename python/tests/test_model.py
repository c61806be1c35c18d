"""Models from files and dicts, parameters changed, and bad input as located exceptions."""

import pytest

import isolab

FIVE_STORY = "models/buildings/five_story_table9.yaml"


def test_load_reads_the_file(repo):
    model = isolab.load_model(repo / FIVE_STORY)
    assert model.units == {"force": "kN", "length": "mm", "time": "s"}
    assert model.description.startswith("Five-story building")
    assert model.get("isolation.components[3].uyh") == 125.542
    assert model.get("isolation.components.c4.uyh") == 125.542  # by name
    assert model.get("structure.stories") == {"count": 5, "mass": "25 t", "stiffness": "76 kN/mm",
                                              "height": "3.2 m"}
    assert model.text == (repo / FIVE_STORY).read_text()


def test_missing_file_is_an_input_error(tmp_path):
    with pytest.raises(isolab.InputError, match="no_such.yaml.*cannot open"):
        isolab.load_model(tmp_path / "no_such.yaml")


def test_input_error_is_a_value_error():
    assert issubclass(isolab.InputError, ValueError)
    assert issubclass(isolab.RunError, RuntimeError)


def test_file_error_names_line_and_key(repo, tmp_path):
    text = (repo / FIVE_STORY).read_text().replace("k1: 0.402485", "k1: 1.3")
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    line = next(i for i, l in enumerate(text.splitlines(), 1) if "k1: 1.3" in l)
    with pytest.raises(isolab.InputError) as error:
        isolab.load_model(path)
    assert f"bad.yaml:{line}:" in str(error.value)
    assert "isolation.components[3].k1 = 1.3 (must be" in str(error.value)


def sdof(**spring):
    return {
        "units": {"force": "kN", "length": "m", "time": "s"},
        "structure": {"type": "sdof", "mass": 10.0, "damping": {"ratio": 0.05}},
        "isolation": {"components": [{"name": "spring", "type": "linear_spring", **spring}]},
    }


def test_dict_errors_are_the_readers(tmp_path):
    with pytest.raises(isolab.InputError, match=r"<dict>:\d+:\d+: .*isolation.components\[0\]"):
        isolab.Model.from_dict(sdof(k=400.0, kk=3))  # unknown key
    with pytest.raises(isolab.InputError, match=r"units.force"):
        isolab.Model.from_dict({**sdof(k=400.0), "units": {"force": "kg", "length": "m"}})
    with pytest.raises(TypeError, match="isolation.components"):
        isolab.Model.from_dict(sdof(k=object()))


def test_dict_round_trip(repo):
    model = isolab.load_model(repo / FIVE_STORY)
    again = isolab.Model.from_dict(model.to_dict(), name=str(repo / FIVE_STORY))
    assert again.to_dict() == model.to_dict()
    assert again.get("isolation.components.c9.k0") == 67.44507


def test_set_checks_and_keeps_the_model_on_error(repo):
    model = isolab.load_model(repo / FIVE_STORY)
    model.set("isolation.components.c4.k1", 0.5)
    assert model.get("isolation.components[3].k1") == 0.5
    with pytest.raises(isolab.InputError, match=r"isolation.components\[3\].k1 = 1.3"):
        model.set("isolation.components[3].k1", 1.3)
    assert model.get("isolation.components[3].k1") == 0.5  # unchanged
    model.set("analysis.duration", "12 s")  # a new key, with a unit
    assert model.get("analysis.duration") == "12 s"
    with pytest.raises(KeyError, match="no entry named 'c10'"):
        model.set("isolation.components.c10.k1", 1)
    with pytest.raises(KeyError, match="past the end"):
        model.get("isolation.components[9]")
    copy = model.copy()
    copy.set("analysis.dt", 0.0025)
    assert model.get("analysis.dt") == 0.005


def test_a_key_typo_through_set_names_the_key_path_not_a_line(repo):
    # The reader sees the YAML written for the changed tree, whose lines are not the file's: a
    # line of the original file would point at text that does not contain the typo.
    model = isolab.load_model(repo / FIVE_STORY)
    with pytest.raises(isolab.InputError) as error:
        model.set("isolation.components.c4.k11", 0.5)
    message = str(error.value)
    assert message.startswith(f'{repo / FIVE_STORY}, set("isolation.components.c4.k11"): '
                              "isolation.components[3].k11: unknown key"), message
    assert "yaml:" not in message  # no line or column
    assert model.get("isolation.components.c4.k1") == 0.402485  # unchanged


def test_a_dict_inside_itself_is_a_value_error():
    model = sdof(k=400.0)
    model["structure"]["again"] = model
    with pytest.raises(ValueError, match=r"^structure.again: refers back to the model"):
        isolab.Model.from_dict(model)
    components = [{"name": "spring", "type": "linear_spring", "k": 400.0}]
    components.append(components)
    with pytest.raises(ValueError, match=r"isolation.components\[1\]: refers back to "
                                         r"isolation.components"):
        isolab.Model.from_dict({**sdof(k=400.0), "isolation": {"components": components}})


def test_a_deep_nesting_is_a_value_error_not_a_crash():
    deep = inner = {}
    for _ in range(100_000):
        inner["a"] = {}
        inner = inner["a"]
    with pytest.raises(ValueError, match="nested deeper than 64"):
        isolab.Model.from_dict(deep)
    model = isolab.Model.from_dict(sdof(k=400.0))
    with pytest.raises(ValueError, match="nested deeper than 64"):
        model.set("analysis.note", deep)
