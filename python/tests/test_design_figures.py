"""The design report's figures checked by what they plot (scripts/plot_design.py --metadata),
against the numbers the design wrote: not only that a PNG exists; and design.html, the report as
one file with the figures in it."""

import csv
import json
import re
import shutil
import subprocess

import pytest

PLOT = ["/usr/bin/python3", "scripts/plot_design.py"]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def design(repo, tmp_path_factory, isolab_cli):
    """An EN 1998-1 design of the four-story triple-pendulum building on three pairs, its figures
    drawn with their metadata."""
    folder = tmp_path_factory.mktemp("figures")
    path = folder / "design.yaml"
    path.write_text(f"model: {repo / 'models' / 'design' / 'four_story_tfp_plan.yaml'}\n"
                    "target: {eurocode8: {agr: 0.3 g, ground: C, type: 1}}\n"
                    "suite:\n  synthetic: {count: 3, seed: 2, duration: 30 s, tolerance: 0.12}\n"
                    "  orientations: [0]\n"
                    "eccentricity: 0.05\n")
    out = folder / "out"
    isolab_cli("design", path, "-q", "--no-figures", "-o", out)
    subprocess.run(PLOT + [str(out), "--metadata"], cwd=repo, check=True, capture_output=True)
    values = {(r["bound"], r["quantity"], r["statistic"]): float(r["value"])
              for r in rows(out / "design_values.csv")}
    return out, values


def metadata(out, name):
    with open(out / f"design_{name}.json") as f:
        return json.load(f)


def test_the_spectra_show_the_codes_threshold_and_every_bounds_period(design):
    out, values = design
    spectra, ratio = metadata(out, "spectra")["axes"]
    # EN 1998-1's suite: each component a time history, so the components' spectra.
    assert spectra["ylabel"].startswith("components' Sa [g]")
    for bound in ("nominal", "upper", "lower"):
        assert f"T_M {bound} {values[(bound, 'T_M', 'elf')]:.2f} s" in spectra["legend"]
    assert "0.9 x target" in spectra["legend"]
    # The ratio is drawn inside the scaling range only, and stays above EN 1998-1's 0.9 there.
    assert ratio["ylabel"] == "mean / target [-]"
    assert "threshold 0.9" in ratio["legend"]
    assert ratio["y_range"][0] >= 0.9 * (1 - 1e-9)
    inside = [float(r["period_s"]) for r in rows(out / "design_spectra.csv") if r["in_range"] == "1"]
    assert ratio["x_range"] == pytest.approx([min(inside), max(inside)], rel=1e-9)


def test_the_loops_show_both_directions_and_each_bounds_secant(design):
    out, _ = design
    figure = metadata(out, "loops")
    assert [a["title"] for a in figure["axes"]] == ["along x", "along y"]
    bearing = figure["title"].split()[1]
    secants = {r["bound"]: float(r["D_M [mm]"]) for r in rows(out / "design_bearings.csv")
               if r["bearing"] == bearing}
    assert len(secants) == 3
    for d_m in secants.values():
        assert f"ELF secant to D_M {d_m:.0f} mm" in figure["axes"][1]["legend"]
    assert "eccentricity" in figure["title"]


def test_the_orbits_keep_each_bearing_and_draw_d_tm_and_the_capacity(design):
    out, values = design
    figure = metadata(out, "orbits")
    assert [a["title"] for a in figure["axes"]] == ["lower bound", "nominal bound", "upper bound"]
    legend = figure["legend"]
    assert any(label.endswith("(moves most)") for label in legend)
    assert any(label.endswith("(moves least)") for label in legend)
    assert f"design D_TM {values[('design', 'D_TM', 'design')]:.0f} mm" in legend
    assert "capacity 880 mm" in legend


def test_the_drifts_are_the_design_values_of_every_bound(design):
    out, _ = design
    [axes] = metadata(out, "drifts")["axes"]
    drifts = [float(r["value"]) for r in rows(out / "design_parts.csv")
              if r["quantity"] == "story_drift_ratio" and r["statistic"] == "max"]
    assert len(drifts) == 3 * 4
    assert axes["x_range"] == pytest.approx([min(drifts), max(drifts)], rel=1e-9)
    assert axes["xlabel"] == "design story drift ratio, maximum of 3 records [%]"


def test_the_html_report_is_one_file_with_the_figures_in_it(design):
    out, _ = design
    page = (out / "design.html").read_text()
    markdown = (out / "design.md").read_text()
    # Self-contained: every image is embedded, nothing else is fetched.
    sources = re.findall(r'(?:src|href)="([^"]*)"', page)
    assert sources and all(s.startswith("data:image/png;base64,") for s in sources)
    # The design ran without figures; drawn afterwards, they take the place of the note.
    assert "Not drawn here" in markdown and "Not drawn here" not in page
    assert len(sources) == 4
    tables = sum(1 for block in re.split(r"\n\s*\n", markdown) if block.lstrip().startswith("|"))
    assert page.count("<table>") == tables
    assert "<h2>Summary</h2>" in page and "<h2>Checks</h2>" in page


def test_a_folder_with_the_figures_and_the_html_drawn_afterwards_is_still_the_designs(
        design, isolab_cli, tmp_path):
    out, _ = design
    copy = tmp_path / "out"
    shutil.copytree(out, copy)  # the other tests' folder stays as it is
    assert (copy / "design_spectra.json").is_file() and (copy / "design.html").is_file()
    isolab_cli("design", out.parent / "design.yaml", "-q", "--no-figures", "-o", copy)
    assert not (copy / "design.html").exists()  # the new design replaced the folder
    # Anything else beside the figures' names is the engineer's: refused, untouched.
    (copy / "design_notes.json").write_text("{}")
    isolab_cli("design", out.parent / "design.yaml", "-q", "--no-figures", "-o", copy, expect=2)
    assert (copy / "design_notes.json").read_text() == "{}"
