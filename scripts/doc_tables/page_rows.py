"""The rows a page's own table lists, for the doc-table scripts that check a table of names
(datasets, attributes, detectors, limits) against what isolab writes or enforces: the script
prints, row by row, what isolab says of each name the page lists, and a row of its own for each
name the page lacks."""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def body_rows(page, header):
    """The cells of each body row of the table of docs/`page` headed by the line `header`."""
    with open(os.path.join(ROOT, "docs", page), encoding="utf-8") as f:
        lines = f.read().splitlines()
    start = lines.index(header) + 2
    rows = []
    while start < len(lines) and lines[start].startswith("|"):
        rows.append([cell.strip() for cell in lines[start].strip().strip("|").split(" | ")])
        start += 1
    return rows


def first_cells(page, header):
    """The first cell of each body row of that table."""
    return [row[0] for row in body_rows(page, header)]
