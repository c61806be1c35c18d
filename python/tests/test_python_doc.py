"""docs/python.md's worked example runs as it stands, prints what the page shows, and agrees
with the command line on the same model.

The page's table is what isolab printed when the page was written: no closed form gives a
five-story building's nonlinear response to a record, so comparing with it is a regression check
(the page still tells the truth), named so. The Qd = 80 kN row is also checked against the
command line, a second path through the model reader and the results file."""

import os
import re
import subprocess
import sys

import pytest

import isolab

EXAMPLE = re.compile(r"<!-- python-example:begin -->\n```python\n(.*?)```\n"
                     r"<!-- python-example:end -->.*?It prints\n\n```\n(.*?)```", re.S)


def test_regression_the_qd_sweep_example_prints_the_pages_table(repo, tmp_path, isolab_cli):
    """Regression check: the printed table against the page's copy of an earlier run's output."""
    found = EXAMPLE.search((repo / "docs/python.md").read_text())
    assert found, "no example between the markers in docs/python.md"
    code, printed = found.groups()
    for folder in ("models", "ground_motions"):  # the page runs it from the repository's folder
        os.symlink(repo / folder, tmp_path / folder)
    (tmp_path / "example.py").write_text(code)
    package = os.path.dirname(os.path.dirname(os.path.abspath(isolab.__file__)))
    done = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True,
                          text=True, env=dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=package))
    assert done.returncode == 0, done.stderr
    assert done.stdout == printed
    assert (tmp_path / "qd_sweep.png").stat().st_size > 10000

    # The Qd = 80 kN row against `isolab run` of the same model, written out as a file.
    model = isolab.load_model(repo / "models/buildings/five_story_table9.yaml")
    model.set("isolation", {"components": [
        {"name": "lrb", "type": "lead_rubber", "qd": 80, "kd": 0.3391, "ku": 3.391}]})
    (tmp_path / "lrb80.yaml").write_text(model.text)
    cli = isolab_cli.json("run", tmp_path / "lrb80.yaml", "--record",
                          "ground_motions/fwn_firm_seed1.at2", "--scale", 0.6,
                          "-o", tmp_path / "lrb80.h5")
    row = next(line.split() for line in done.stdout.splitlines() if line.split()[0] == "80")
    assert float(row[1]) == pytest.approx(cli["peaks"]["isolator_displacement"]["value"], abs=0.05)
    assert float(row[2]) == pytest.approx(cli["peaks"]["base_shear"]["value"], abs=0.05)
