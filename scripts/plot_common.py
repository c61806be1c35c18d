"""What the isolab plot scripts share: the plotting stack, imported without a display or an
install hint when missing; HDF5 strings as text; and figures fit for a report: 300 dpi PNG with a
vector PDF beside it, titles that fit their figure, units on every axis, accelerations in g, and
(with --metadata) a JSON sidecar per figure that says what each axis shows, in which unit, over
which range of data, so that tests can check a figure's content and not only that it exists."""
import json
import math
import os
import sys
import textwrap

NEEDS = ("matplotlib, h5py and numpy (Debian: sudo apt-get install python3-matplotlib "
         "python3-h5py)")

DPI = 300  # print resolution; the PDF beside each PNG is vector
STANDARD_GRAVITY = 9.80665  # m/s^2
# Metres per length unit, for accelerations in g.
METRES = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048, "km": 1000.0}


def import_modules():
    """Imports the plotting stack, or exits 3 saying what to install."""
    try:
        import matplotlib
        matplotlib.use("Agg")  # files only: no display needed
        import h5py
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as error:
        print(f"{os.path.basename(sys.argv[0])}: {error}; needs {NEEDS}", file=sys.stderr)
        sys.exit(3)
    style(plt)
    return h5py, plt, np


def style(plt):
    """One look for every figure: readable type at print size, light grids."""
    plt.rcParams.update({
        "font.size": 9, "axes.titlesize": 9.5, "axes.labelsize": 9, "legend.fontsize": 8,
        "xtick.labelsize": 8, "ytick.labelsize": 8, "figure.titlesize": 10.5,
        "axes.grid": True, "grid.alpha": 0.3, "grid.linewidth": 0.5,
        "savefig.dpi": DPI, "pdf.fonttype": 42,  # TrueType in the PDF: editable text
    })


def text(value):
    """HDF5 fixed-length strings come back as bytes."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return str(value)


def short_name(path, limit=36):
    """A file's base name, its middle elided past `limit` characters (titles must fit)."""
    name = os.path.basename(str(path))
    if len(name) <= limit:
        return name
    keep = limit - 1
    return name[:math.ceil(keep / 2)] + "\u2026" + name[len(name) - keep // 2:]


def wrap_title(title, width_inches, fontsize=10.5):
    """Breaks a title into lines that fit `width_inches` at `fontsize` points (an average glyph
    is about 0.55 em wide), so that a long model or record name is never cut at the edge."""
    characters = max(20, int(width_inches * 72 / (0.55 * fontsize)))
    return "\n".join(textwrap.wrap(title, characters, break_long_words=True))


def g_per(unit):
    """How many of `unit` (a length per s^2: "mm/s^2") make one g; None for another unit."""
    length = unit.replace(" ", "").split("/")[0]
    if not unit.replace(" ", "").endswith(("/s^2", "/s2", "/s\u00b2")) or length not in METRES:
        return None
    return STANDARD_GRAVITY / METRES[length]


def unit_of(label):
    """The unit in a label's last brackets: "isolator force [kN]" -> "kN"; "" when none."""
    if "[" in label and label.rstrip().endswith("]"):
        return label[label.rindex("[") + 1:label.rstrip().rindex("]")]
    return ""


def mark_reference(*artists):
    """Zero lines, spans and markers of a threshold are not data: left out of the ranges."""
    for artist in artists:
        artist.set_gid("reference")


def data_range(np, ax):
    """The x and y ranges of the data drawn on `ax` (lines, bars, filled areas), reference
    artists left out; None for an axis with no finite data."""
    from matplotlib.patches import Rectangle

    xs, ys = [], []
    for line in ax.get_lines():
        if line.get_gid() != "reference":
            xs.append(np.asarray(line.get_xdata(), dtype=float).ravel())
            ys.append(np.asarray(line.get_ydata(), dtype=float).ravel())
    for patch in ax.patches:
        if patch.get_gid() != "reference" and isinstance(patch, Rectangle):
            x, y, w, h = patch.get_x(), patch.get_y(), patch.get_width(), patch.get_height()
            xs.append(np.array([x, x + w]))
            ys.append(np.array([y, y + h]))
    for collection in ax.collections:
        if collection.get_gid() != "reference":
            for path in collection.get_paths():
                xs.append(path.vertices[:, 0])
                ys.append(path.vertices[:, 1])

    def bounds(parts):
        values = np.concatenate(parts) if parts else np.array([])
        values = values[np.isfinite(values)]
        return [float(values.min()), float(values.max())] if values.size else None

    return bounds(xs), bounds(ys)


def describe(np, fig):
    """Every visible axes of `fig`: title, labels, units, data ranges, legend entries."""
    axes = []
    for ax in fig.get_axes():
        if not ax.get_visible() or not ax.axison:  # hidden panels, a legend's own row
            continue
        x_range, y_range = data_range(np, ax)
        legend = ax.get_legend()
        axes.append({
            "title": ax.get_title(), "xlabel": ax.get_xlabel(), "ylabel": ax.get_ylabel(),
            "x_unit": unit_of(ax.get_xlabel()), "y_unit": unit_of(ax.get_ylabel()),
            "x_range": x_range, "y_range": y_range,
            "legend": [t.get_text() for t in legend.get_texts()] if legend else [],
        })
    return axes


def save(plt, np, fig, path, metadata=False):
    """Writes `path` (PNG, 300 dpi) and the same figure as a vector PDF beside it; with
    `metadata`, a JSON sidecar beside them (describe()). Closes the figure; returns the PNG's
    path."""
    stem = os.path.splitext(path)[0]
    fig.savefig(stem + ".png", dpi=DPI)
    fig.savefig(stem + ".pdf")
    if metadata:
        width, height = fig.get_size_inches()
        title = fig._suptitle.get_text() if fig._suptitle is not None else ""
        sidecar = {
            "figure": os.path.basename(stem + ".png"), "pdf": os.path.basename(stem + ".pdf"),
            "dpi": DPI, "size_px": [round(width * DPI), round(height * DPI)],
            "title": title, "axes": describe(np, fig),
            "legend": [t.get_text() for legend in fig.legends for t in legend.get_texts()],
        }
        with open(stem + ".json", "w", encoding="utf-8") as stream:
            json.dump(sidecar, stream, indent=1)
    plt.close(fig)
    return stem + ".png"
