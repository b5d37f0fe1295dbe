#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""LaTeX out for every example (examples/*/ with a model script, report_examples.py): `alembert report MODEL
--matrices` writes roadmap.tex beside the page, with the road-map table (a line per row), a TikZ
free-body diagram per row that has one (an arrow per load on S, as many as the HTML report
draws) kept in one box with its caption and its row's equation, every row's equation, the mass
matrix, each result's sweep (a plot per axis, its table's numbers the page's) and the
document's end; a model without rows gets a document that says so. Where
pdflatex is installed (Debian's texlive-latex-base and texlive-pictures; scripts/install_deps.sh
installs them) each document is compiled and must give a PDF with no line more than 10 pt
wider than the text (no "Overfull \\hbox" over 10 pt in the log) and no page's content over
10 pt taller than the page (no "Overfull \\vbox" over 10 pt: what passes the foot is lost).
`alembert report MODEL --latex` writes that roadmap.tex alone, byte for byte (checked on the
sit-to-stand: each report runs its whole script, which for the larger examples is most of the time).

usage: latex_test.py ALEMBERT_CLI SOURCE_DIR WORK_DIR"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

import time

from report_examples import example_models

failures = []


def segment_meets_box(a, b, box):
    """Whether the segment a-b passes through the box [x, y, w, h] (sampled finely)."""
    for k in range(201):
        x, y = a[0] + (b[0] - a[0]) * k / 200, a[1] + (b[1] - a[1]) * k / 200
        if box[0] < x < box[0] + box[2] and box[1] < y < box[1] + box[3]:
            return True
    return False


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def tex_number(cell):
    """A table cell's number: $-5.11468$, $1.5\\cdot 10^{-5}$ (None: not a number)."""
    m = re.fullmatch(r"\$(-?[0-9.]+)(?:\\cdot 10\^\{(-?[0-9]+)\})?\$", cell.strip())
    if not m:
        return None
    return float(m.group(1)) * (10.0 ** int(m.group(2)) if m.group(2) else 1.0)


def tex_tables(part):
    """The numbers of each tabular in `part`: a list of (header names, rows of numbers)."""
    out = []
    for m in re.finditer(r"\\begin\{tabular\}\{[^\n]*\}\n(.*?)\\end\{tabular\}", part, re.S):
        lines = [l for l in m.group(1).split("\\\\\n") if l.strip()]
        lines = [l.replace("\\hline\n", "").replace("\\hline", "").strip() for l in lines]
        lines = [l for l in lines if l]
        head = [re.sub(r"\s*\[.*\]$", "", c.strip()).replace("\\_", "_") for c in lines[0].split("&")]
        out.append((head, [[tex_number(c) for c in l.split("&")] for l in lines[1:]]))
    return out


def check_sweeps(name, tex, data):
    """Each result's sweep in the document under its text, as the page's data holds it: its
    table's numbers those of the page (6 digits) at each sample listed (all, or at most 25), the
    series left out 0 at every sample, a plot for each axis with a series not 0 throughout."""
    for result in data.get("results", []):
        w = result.get("sweep")
        if not w:
            continue
        start = tex.find("Line %d:\n\\begin{verbatim}" % result["line"])
        end = tex.find("\nLine ", start + 1)
        part = tex[start:end if end >= 0 else len(tex)]
        what = "%s: the sweep at line %d" % (name, result["line"])
        values = w["values"]
        series = {s["name"]: s["values"] for s in w["series"]}
        largest = max([abs(v) for s in w["series"] for v in s["values"] if v is not None] + [0])
        tables = tex_tables(part)
        check(tables and all(h[0] == w["parameter"] for h, _ in tables),
              "%s: tabulated against %s (%s)" % (what, w["parameter"], [h for h, _ in tables]))
        if not tables:
            continue
        shown = [r[0] for r in tables[0][1]]
        check(set(shown) <= set(values) and (shown == values if len(values) <= 25 else len(shown) <= 25)
              and shown[:1] == values[:1] and shown[-1:] == values[-1:],
              "%s: the samples listed, all or at most 25 with the first and the last (%d of %d)"
              % (what, len(shown), len(values)))
        listed, wrong = set(), []
        for head, rows in tables:
            for k, column in enumerate(head[1:], 1):
                listed.add(column)
                for row in rows:
                    page = series[column][values.index(row[0])]
                    if not (row[k] == page or row[k] == 0 and abs(page) <= 1e-12 * largest):
                        wrong.append("%s at %s: %s, the page %s" % (column, row[0], row[k], page))
        check(not wrong, "%s: the table's numbers are the page's (%s)" % (what, wrong[:3]))
        silent = [n for n in series if n not in listed and any(abs(v) > 1e-12 * largest for v in series[n])]
        check(not silent, "%s: each series left out of the table is 0 at every sample (%s)" % (what, silent))
        axes = set(s["axis"] for s in w["series"] if s["name"] in listed)
        check(part.count("\\begin{axis}") == len(axes) and part.count("\\addlegendentry{") >= len(listed),
              "%s: a plot per axis (%s), a legend entry per series" % (what, sorted(axes)))


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    cli, source, work = sys.argv[1:]
    pdflatex = shutil.which("pdflatex")
    if not pdflatex:
        print("latex: pdflatex is not installed (Debian: apt-get install texlive-latex-base texlive-pictures); "
              "checking the documents' structure only")
    alone_checked = False
    began = time.monotonic()
    for name, model in example_models(source):
        out = os.path.join(work, name)
        shutil.rmtree(out, ignore_errors=True)
        # the mass matrix too, written entry by entry where it is wide (the arm's, 180 pages
        # and most of this test's time, adds no layout case the others lack)
        matrices = ["--matrices"] if name != "kuka_iiwa" else []
        r = subprocess.run([cli, "report", model] + matrices + ["--out", out], capture_output=True, text=True,
                           timeout=600)
        check(r.returncode == 0, "%s: alembert report exits 0 (stderr: %s)" % (name, r.stderr.strip()[:300]))
        tex_path = os.path.join(out, "roadmap.tex")
        check(os.path.isfile(tex_path), "%s: roadmap.tex written beside the page" % name)
        if not os.path.isfile(tex_path):
            continue
        with open(tex_path, encoding="utf-8") as f:
            tex = f.read()
        if not alone_checked and name == "sit_to_stand":  # a quick one: each report runs its script
            alone_checked = True
            alone = os.path.join(work, name + "_alone")
            shutil.rmtree(alone, ignore_errors=True)
            r = subprocess.run([cli, "report", model, "--matrices", "--latex", "--out", alone], capture_output=True, text=True,
                               timeout=600)
            alone_tex = os.path.join(alone, "roadmap.tex")
            check(r.returncode == 0 and os.path.isfile(alone_tex) and
                  not os.path.exists(os.path.join(alone, "index.html")),
                  "%s: --latex writes roadmap.tex alone, and no page (stderr: %s)" % (name, r.stderr.strip()[:300]))
            if os.path.isfile(alone_tex):
                with open(alone_tex, encoding="utf-8") as f:
                    check(f.read() == tex, "%s: --latex writes the report's roadmap.tex byte for byte" % name)
        # the road-map's part, checked below: the results (with their sweeps' plots and tables)
        # come last
        whole, tex = tex, tex.split("\\subsection*{Results}")[0]
        # the same model's data, as the HTML report holds it, says what the document must hold
        with open(os.path.join(out, "index.html"), encoding="utf-8") as f:
            page = f.read()
        start = page.index('id="alembert-data">') + len('id="alembert-data">')
        data = json.loads(page[start:page.index("</script>", start)])
        rows = data["roadmap"]
        if not rows:
            check("\\begin{tabular}" not in tex and "no MG road-map rows" in tex,
                  "%s: no rows, and the document says so instead of an empty table" % name)
        else:
            table = tex[tex.find("\\begin{tabular}"):tex.find("\\end{tabular}")]
            check(table.count("\\tabularnewline\n") == len(rows),
                  "%s: the table has a line per row (%d rows)" % (name, len(rows)))
        equations = re.findall(r"\\eqline\{E_\{(.*?)\}\\colon", tex)
        check(len(equations) == len(rows), "%s: every row's equation is there (%d of %d)" % (name, len(equations), len(rows)))
        check([e for e in equations] == [r["variable_tex"] for r in rows],
              "%s: the equations in the rows' order" % name)
        pictures = [tex[a:tex.find("\\end{tikzpicture}", a)] for a in
                    [m.start() for m in re.finditer(r"\\begin\{tikzpicture\}", tex)]]
        # the loads at points the configuration places (the others the caption names)
        loads = [len([l for l in r["diagram"]["loads"] if l.get("placed", True)]) for r in rows if r["diagram"]]
        check([p.count("% load: ") for p in pictures] == loads,
              "%s: a TikZ diagram per row with an arrow per load on S %s" % (name, loads))
        # no label on a load arrow: each label's box (its size as the placer estimates it for
        # \scriptsize: 0.13 cm a character and 0.1 cm, 0.32 cm high, about its node's place)
        # met by no load's shaft or arc
        on_arrow = []
        for p in pictures:
            segments = []
            for block in p.split("% load: ")[1:]:
                load_name = block.split("\n")[0]
                for m in re.finditer(r"\\draw\[->[^\n]*?\] \(([-\d.]+),([-\d.]+)\) -- (\+\+)?\(([-\d.]+),([-\d.]+)\);", block):
                    a = (float(m.group(1)), float(m.group(2)))
                    d = (float(m.group(4)), float(m.group(5)))
                    segments.append((load_name, a, (a[0] + d[0], a[1] + d[1]) if m.group(3) else d))
                for m in re.finditer(r"\\draw\[->[^\n]*?\] \(([-\d.]+),([-\d.]+)\) arc\[start angle=([-\d.]+), "
                                     r"end angle=([-\d.]+), radius=([\d.]+)\];", block):
                    x, y, a0, a1, r = (float(g) for g in m.groups())
                    a0, a1 = math.radians(a0), math.radians(a1)
                    c = (x - r * math.cos(a0), y - r * math.sin(a0))
                    arc = [(c[0] + r * math.cos(a0 + (a1 - a0) * k / 40), c[1] + r * math.sin(a0 + (a1 - a0) * k / 40))
                           for k in range(41)]
                    segments += [(load_name, arc[k - 1], arc[k]) for k in range(1, 41)]
            for m in re.finditer(r"% label: (.*)\n\\node\[[^\n]*?\] at \(([-\d.]+),([-\d.]+)\)", p):
                text = re.sub(r"\\(.)", r"\1", m.group(1))
                x, y, w, h = float(m.group(2)), float(m.group(3)), 0.13 * len(text) + 0.1, 0.32
                box = (x - w / 2 + 0.01, y - h / 2 + 0.01, w - 0.02, h - 0.02)
                hit = sorted(set(n for n, a, b in segments if segment_meets_box(a, b, box)))
                if hit:
                    on_arrow.append("%r on %s" % (text, hit))
        check(pictures and "% label: " in tex and not on_arrow or not pictures,
              "%s: no diagram label on a load arrow (%d: %s)" % (name, len(on_arrow), on_arrow[:3]))
        # each row's box (a minipage, which never floats or breaks) holds its diagram, the
        # diagram's caption and the start of the row's equation; or, where the equation's first
        # line is too long for a box that must fit a page, is held to that line's start (no
        # page break between them nor after the line's first printed line)
        held = "\\end{minipage}\n\\par\\nobreak\n\\begin{eqlines}\\clubpenalty=10000\n\\eqline{"
        boxes = []
        for m in re.finditer(r"\\begin\{minipage\}", tex):
            end = tex.find("\\end{minipage}", m.start())
            boxes.append(tex[m.start():end + len(held) + 100] if tex.startswith(held, end) else tex[m.start():end])
        together = len(boxes) == len(rows) and all(
            ("\\eqline{E_{%s}\\colon" % r["variable_tex"]) in b and
            (not r["diagram"] or ("\\begin{tikzpicture}" in b and ": free-body diagram of" in b))
            for r, b in zip(rows, boxes))
        check(together, "%s: each row's diagram, caption and equation in one box" % name)
        if rows:
            # each row's derivation, enumerated after the rows; the brute-force count after the
            # table; each row's unit check under its equation
            part = tex[tex.find("\\subsection*{Derivations, row by row}"):]
            derived = re.findall(r"\\paragraph\{Row \d+: \$E_\{(.*?)\}\$\.\}\n\\begin\{enumerate\}", part)
            check(derived == [r["variable_tex"] for r in rows] and part.count("\\end{enumerate}") == len(rows)
                  and part.count("\\item \\textbf{equation}") == len(rows),
                  "%s: each row's derivation enumerated, ending in its equation (%d of %d)" % (name, len(derived), len(rows)))
            after_table = tex[tex.find("\\end{tabular}"):tex.find("\\subsection*{Rows")]
            check("Free-body diagrams of every body separately" in after_table
                  and ("%d equations" % data["brute_force"]["equations"]) in after_table,
                  "%s: the brute-force Newton--Euler count beside the table" % name)
            check(tex.count("\\small units: ") == len(rows), "%s: each row's unit check (%d of %d)"
                  % (name, tex.count("\\small units: "), len(rows)))
        if "matrices" in data:
            check("\\subsection*{Mass matrix and forcing}" in tex and "\\eqline{" in
                  tex[tex.find("\\subsection*{Mass matrix and forcing}"):],
                  "%s: the mass matrix and forcing typeset" % name)
        check_sweeps(name, whole, data)
        check(whole.rstrip().endswith("\\end{document}"), "%s: the document ends" % name)
        if pdflatex:
            r = subprocess.run([pdflatex, "-interaction=nonstopmode", "-halt-on-error", "roadmap.tex"], cwd=out,
                               capture_output=True, text=True, timeout=300)
            errors = [l for l in r.stdout.splitlines() if l.startswith("!")]
            check(r.returncode == 0 and os.path.isfile(os.path.join(out, "roadmap.pdf")),
                  "%s: pdflatex compiles it (%s)" % (name, errors[:3]))
            with open(os.path.join(out, "roadmap.log"), encoding="latin-1") as f:
                log = f.read()
            over = [float(x) for x in re.findall(r"Overfull \\hbox \(([0-9.]+)pt too wide\)", log)]
            check(not over or max(over) <= 10,
                  "%s: no line over 10 pt wider than the text (%d overfull boxes, the widest %.1f pt)"
                  % (name, len(over), max(over) if over else 0))
            # a box taller than the page (a diagram kept with too much of its equation) runs
            # off its foot: what is past the foot is lost
            tall = [float(x) for x in re.findall(r"Overfull \\vbox \(([0-9.]+)pt too high\)", log)]
            check(not tall or max(tall) <= 10,
                  "%s: no page over 10 pt taller than the text (%d overfull pages, the tallest by %.1f pt)"
                  % (name, len(tall), max(tall) if tall else 0))
    print("time: %.1f s" % (time.monotonic() - began))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
