#!/usr/bin/python3
"""A design's report as one self-contained HTML file: design.md of an `isolab design` output
folder, its figures embedded (base64 PNG), so a reviewer opens one file.

    scripts/design_html.py DIR

Writes DIR/design.html. plot_design.py calls it once the figures are drawn. The Markdown is the
subset design.md uses (headings, paragraphs, lists, tables, images, code blocks, `code` and
**bold**); anything else is kept as text.
"""

import argparse
import base64
import html
import os
import re
import sys

STYLE = """
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; max-width: 62em;
       margin: 2em auto; padding: 0 1.5em; line-height: 1.45; color: #222; }
h1 { font-size: 1.6em; border-bottom: 2px solid #444; padding-bottom: 0.2em; }
h2 { font-size: 1.25em; margin-top: 1.8em; border-bottom: 1px solid #bbb; }
h3 { font-size: 1.05em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.86em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.55em; text-align: left; vertical-align: top; }
th { background: #eee; }
td:not(:first-child) { font-variant-numeric: tabular-nums; }
code, pre { font-family: "DejaVu Sans Mono", monospace; font-size: 0.88em; background: #f4f4f4; }
pre { padding: 0.6em; overflow-x: auto; }
figure { margin: 1.2em 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.88em; color: #555; }
.exceeded { color: #b00; font-weight: bold; }
"""


def inline(text):
    """Escaped text with `code`, **bold** and the EXCEEDED verdict marked."""
    parts = re.split(r"(`[^`]*`)", text)
    out = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) > 1:
            out.append(f"<code>{html.escape(part[1:-1])}</code>")
            continue
        escaped = html.escape(part)
        escaped = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", escaped)
        escaped = escaped.replace("EXCEEDED", '<span class="exceeded">EXCEEDED</span>')
        out.append(escaped)
    return "".join(out)


def image(directory, alt, name):
    """A figure element with the PNG embedded; a note where the file is missing."""
    path = os.path.join(directory, name)
    if not os.path.isfile(path):
        return f"<p>(figure {html.escape(name)} not drawn)</p>"
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    return (f'<figure><img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{html.escape(alt)}</figcaption></figure>")


# The figures plot_design.py draws, as design.md names them.
FIGURES = (("design_spectra.png", "The scaled suite's spectra against the target"),
           ("design_loops.png", "The worst bearing's loops at the three bounds"),
           ("design_orbits.png", "The orbits of the bearings that move most and least"),
           ("design_drifts.png", "Peak story drift ratios"))


def drawn_afterwards(directory):
    """The figures drawn after a design that wrote its report without them (--no-figures, or
    Python's design()): design.md says they were not drawn, the folder now has them."""
    return [image(directory, alt, name) for name, alt in FIGURES
            if os.path.isfile(os.path.join(directory, name))]


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def convert(markdown, directory):
    lines = markdown.split("\n")
    body, paragraph = [], []

    def flush():
        if paragraph:
            body.append(f"<p>{inline(' '.join(paragraph))}</p>")
            paragraph.clear()

    i = 0
    while i < len(lines):
        line = lines[i]
        heading = re.match(r"(#{1,3}) (.*)", line)
        picture = re.match(r"!\[(.*)\]\((.*)\)\s*$", line)
        if heading:
            flush()
            level = len(heading.group(1))
            body.append(f"<h{level}>{inline(heading.group(2))}</h{level}>")
        elif picture:
            flush()
            body.append(image(directory, picture.group(1), picture.group(2)))
        elif line.startswith("```"):
            flush()
            block = []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                block.append(lines[i])
                i += 1
            body.append(f"<pre>{html.escape(chr(10).join(block))}</pre>")
        elif line.startswith("|"):
            flush()
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(cells(lines[i]))
                i += 1
            i -= 1
            head, rest = rows[0], [r for r in rows[1:] if not all(set(c) <= set("-:") for c in r)]
            table = ["<table><thead><tr>"] + [f"<th>{inline(c)}</th>" for c in head]
            table.append("</tr></thead><tbody>")
            for row in rest:
                table.append("<tr>" + "".join(f"<td>{inline(c)}</td>" for c in row) + "</tr>")
            table.append("</tbody></table>")
            body.append("".join(table))
        elif line.startswith("- "):
            flush()
            items = []
            while i < len(lines) and lines[i].startswith("- "):
                items.append(f"<li>{inline(lines[i][2:])}</li>")
                i += 1
            i -= 1
            body.append("<ul>" + "".join(items) + "</ul>")
        elif not line.strip():
            flush()
        elif line.startswith("Not drawn here:") and drawn_afterwards(directory):
            flush()
            body.extend(drawn_afterwards(directory))
        else:
            paragraph.append(line.strip())
        i += 1
    flush()
    title = next((re.sub(r"<[^>]+>", "", b) for b in body if b.startswith("<h1>")), "Design")
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{title}</title><style>{STYLE}</style></head><body>\n"
            + "\n".join(body) + "\n</body></html>\n")


def write_html(directory):
    """Writes DIR/design.html from DIR/design.md; returns its path."""
    source = os.path.join(directory, "design.md")
    with open(source, encoding="utf-8") as f:
        page = convert(f.read(), directory)
    target = os.path.join(directory, "design.html")
    partial = target + ".partial"
    with open(partial, "w", encoding="utf-8") as f:
        f.write(page)
    os.replace(partial, target)
    return target


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", help="the output folder of isolab design")
    arguments = parser.parse_args()
    if not os.path.isfile(os.path.join(arguments.directory, "design.md")):
        sys.exit(f"design_html.py: {arguments.directory} holds no design.md")
    print(write_html(arguments.directory))


if __name__ == "__main__":
    main()
