#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The sit-to-stand report as a user sees it: headless Chromium opens DIR/index.html, its
scripts run, and the DOM after them is checked (no errors, one free-body diagram per road-map
row with one arrow group per load on S, every equation typeset by KaTeX and no wider than its
column on the screen at 1280 px and in print, plots, animation), then a screenshot is taken and
checked not to be blank.

Then every example's report (examples/*/ with a model script, report_examples.py), checked
alike. PART: "main" (the sit-to-stand page, the options, the spatial, 3D and motion-file
scripts), or examples by name (bicycle,kuka_iiwa); all of them when left out. CMake runs
the parts as ctest entries report.browser.<part> that ctest -j balances.

usage: browser_test.py ALEMBERT_CLI SOURCE_DIR WORK_DIR [PART]     (exit 77: Chromium missing)"""
import collections
import html.parser
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

from report_examples import example_models

failures = []
# headless Chromium draws WebGL (the 3D view) in software; saying so keeps its console quiet
WEBGL = ["--enable-unsafe-swiftshader"]
# what the page's #exercise mode does with the controls, by the words of each step
EXERCISE = ["unticking a series hides it", "ticking it shows it again", "the cursor reads values",
            "dragging zooms into a time range", "show all zooms out again", "the 3D view is drawn",
            "dragging turns the 3D view", "the time slider moves the model", "the time slider moves the 3D view",
            "play starts the animation", "pause stops it", "the cursor moves the animation", "the speed control offers",
            "play at 1\u00d7", "play at 0.5\u00d7", "play at 2\u00d7", "play at 0.25\u00d7"]
# what it does with the teaching aids on every page with road-map rows: each row's derivation
# opened and typeset, the brute-force Newton-Euler count and each row's unit check shown
EXERCISE_TEACHING = ["derivations are closed until opened", "each derivation opens and typesets its steps",
                     "no derivation formula wider than its column", "the brute-force count is shown",
                     "each row shows its unit check"]
# what it does with the plots and the animation on every example's page
EXERCISE_PLOTS = ["the cursor reads values", "dragging zooms into a time range", "show all zooms out again"]
# what it does with a result's sweep on the pages that have one
EXERCISE_SWEEP = ["a sweep's cursor reads its values on its own plots"]
EXERCISE_MOTION = ["the time slider moves the model", "play starts the animation", "the speed control offers",
                   "play at 1\u00d7", "play at 0.5\u00d7", "play at 2\u00d7", "play at 0.25\u00d7"]


SPENT = {}  # wall time per kind of run: [runs, seconds]


def run(cmd, **kw):
    """subprocess.run, its wall time added to SPENT under the program run (alembert, Chromium)."""
    import time
    start = time.monotonic()
    try:
        return subprocess.run(cmd, **kw)
    finally:
        kind = "Chromium" if cmd[1:2] == ["--headless"] else "alembert"
        spent = SPENT.setdefault(kind, [0, 0.0])
        spent[0] += 1
        spent[1] += time.monotonic() - start


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Dom(html.parser.HTMLParser):
    """Collects what the checks need from the DOM Chromium dumps."""

    def __init__(self):
        super().__init__()
        self.stack = []          # open elements: (tag, classes, keys counted in self.open)
        self.open = collections.Counter()  # open elements by tag, by class and by (tag, class)
        self.status = None
        self.errors = ""
        self.fbds = []           # per svg.fbd: [data-loads, arrow groups counted]
        self.gravity_shafts = []  # per gravity arrow in a diagram: (dx, dy) of its shaft, page axes
        self.equations = 0       # .equation boxes
        self.folded = 0          # long equations folded, typeset when opened
        self.shown = 0           # .equation boxes outside the derivations (rows', equation sets')
        self.folded_shown = 0    # folded equations outside the derivations
        self.katex = 0           # .katex inside them
        self.raw = 0             # .tex-raw boxes (TeX left untypeset)
        self.text_backslashes = 0  # backslashes in visible text (TeX not rendered)
        self.plots = 0
        self.view_controls = 0   # div#view-controls: the sliders that turn a spatial model's diagrams
        self.series = 0
        self.legend_boxes = 0
        self.anim = 0
        self.anim_sticks = 0
        self.play = False
        self.slider = False
        self.in_errors = False
        self.rows = 0            # road-map rows (div.row)
        self.pending = 0         # rows not drawn yet (div.row[data-pending]: drawn when scrolled near)
        self.drawn_rows = []     # the numbers of the rows drawn (N of div.row#row-N)
        self.constraint_rows = 0  # rows without a diagram (constraint rows)
        self.canvas = None       # the 3D view's attributes
        self.checks = []         # (kind, passed) per row of the checks panel
        self.exercise = ""
        self.image3d = ""
        self.in_pre = None
        self.matrices = 0        # section#matrices (the mass matrix and forcing)
        self.matrices_katex = 0  # KaTeX renderings inside it
        self.matrices_tables = 0  # matrices KaTeX laid out inside it (span.mtable)
        self.results = []        # per div.result: [statement line, output text]
        self.configuration = ""  # the note saying where the diagrams are drawn
        self.equation_sets = 0   # div.equation-set: the equations of a kane or lagrange
        self.title = ""          # the page's <title>
        self.h1 = ""
        self.figures = []        # per figure.plot: its unit, title, y axis label and series (unit, colour)
        # per figure.sweep-plot (a result's sweep): the line of the result it is under, its
        # unit, axis, title, axis labels and series (unit, colour, points drawn)
        self.sweeps = []
        self.result_line = None  # data-line of the div.result last opened

    def classes(self, attrs):
        return set((dict(attrs).get("class") or "").split())

    def inside(self, tag=None, cls=None):
        # a count of the open elements per key, not a scan of the stack: the arm's page has
        # hundreds of thousands of text nodes, each asking several times
        if tag is not None and cls is not None:
            return self.open[("tag-class", tag, cls)] > 0
        if tag is not None:
            return self.open[("tag", tag)] > 0
        if cls is not None:
            return self.open[("class", cls)] > 0
        return bool(self.stack)

    def handle_starttag(self, tag, attrs):
        a, c = dict(attrs), self.classes(attrs)
        if a.get("id") == "matrices":
            self.matrices += 1
            c.add("#matrices")
        if "katex" in c and self.inside(cls="#matrices"):
            self.matrices_katex += 1
        if tag == "span" and "mtable" in c and self.inside(cls="#matrices"):
            self.matrices_tables += 1
        if a.get("id") == "alembert-status":
            self.status = a.get("data-status")
        if a.get("id") == "alembert-errors":
            self.in_errors = True
        if tag == "pre" and a.get("id") in ("alembert-exercise", "alembert-3d"):
            self.in_pre = a.get("id")
        if tag == "div" and "row" in c:
            self.rows += 1
            self.pending += "data-pending" in a
            if "data-pending" not in a:
                self.drawn_rows.append(int(a.get("id", "row-0")[4:]))
        if tag == "div" and "equation-set" in c:
            self.equation_sets += 1
        if tag == "div" and "result" in c:
            self.results.append(["", ""])
            self.result_line = a.get("data-line")
        if tag == "figure" and "sweep-plot" in c:
            self.sweeps.append({"line": self.result_line if self.inside("div", "result") else None,
                                "unit": a.get("data-unit"), "axis": a.get("data-axis"), "title": a.get("data-title"),
                                "label": "", "x_label": "", "series": []})
        if tag == "polyline" and "sweep-series" in c and self.inside("figure", "sweep-plot"):
            self.sweeps[-1]["series"].append((a.get("data-unit"), a.get("stroke"), len(a.get("points", "").split())))
        if tag == "pre" and self.inside("div", "result"):
            c.add("statement" in c and "#statement" or "#output")
        if tag == "p" and a.get("id") == "configuration":
            c.add("#configuration")
        if tag == "canvas" and "view3d" in c:
            self.canvas = a
        if tag == "tr" and a.get("data-kind"):
            self.checks.append((a.get("data-kind"), "passed" in c))
        if tag == "svg" and "fbd" in c:
            self.fbds.append([int(a.get("data-loads", "-1")), 0])
        if tag == "g" and "load" in c and self.inside("svg", "fbd"):
            self.fbds[-1][1] += 1
        if tag == "line" and "shaft" in c and self.inside("g", "gravity") and self.inside("svg", "fbd"):
            self.gravity_shafts.append((float(a["x2"]) - float(a["x1"]), float(a["y2"]) - float(a["y1"])))
        if "equation" in c:
            self.equations += 1
            self.shown += not self.inside("details", "derivation")
        if tag == "details" and "equation-folded" in c:
            self.folded += 1
            self.folded_shown += not self.inside("details", "derivation")
        if "katex" in c and self.inside(cls="equation"):
            self.katex += 1
        if "tex-raw" in c:
            self.raw += 1
        if tag == "svg" and "plot-svg" in c:
            self.plots += 1
        if tag == "figure" and "plot" in c:
            self.figures.append({"unit": a.get("data-unit"), "title": a.get("data-title"), "label": "", "series": []})
        if tag == "polyline" and "series" in c:
            self.series += 1
            if self.inside("figure", "plot"):
                self.figures[-1]["series"].append((a.get("data-unit"), a.get("stroke")))
        if tag == "input" and a.get("type") == "checkbox" and a.get("data-series"):
            self.legend_boxes += 1
        if tag == "svg" and "anim" in c:
            self.anim += 1
        if tag == "line" and "stick" in c and self.inside("svg", "anim"):
            self.anim_sticks += 1
        if a.get("id") == "view-controls":
            self.view_controls += 1
        if a.get("id") == "play":
            self.play = True
        if a.get("id") == "time-slider":
            self.slider = True
        if tag not in ("input", "br", "img", "meta", "link", "line", "circle", "path", "polyline"):
            keys = [("tag", tag)] + [("class", k) for k in c] + [("tag-class", tag, k) for k in c]
            self.open.update(keys)
            self.stack.append((tag, c, keys))

    def handle_endtag(self, tag):
        for i in range(len(self.stack) - 1, -1, -1):
            if self.stack[i][0] == tag:
                for _, _, keys in self.stack[i:]:
                    self.open.subtract(keys)
                del self.stack[i:]
                break
        if tag == "pre":
            self.in_errors = False
            self.in_pre = None

    def handle_data(self, data):
        if self.in_errors:
            self.errors += data
        if self.in_pre == "alembert-exercise":
            self.exercise += data
        if self.in_pre == "alembert-3d":
            self.image3d += data

        if self.inside("pre", "#statement"):
            self.results[-1][0] += data
        if self.inside("pre", "#output"):
            self.results[-1][1] += data
        if self.inside("p", "#configuration"):
            self.configuration += data
        if self.inside("title") and not self.inside("svg"):
            self.title += data
        if self.inside("h1"):
            self.h1 += data
        if self.inside("text", "y-label") and self.inside("figure", "plot"):
            self.figures[-1]["label"] += data
        if self.inside("text", "y-label") and self.inside("figure", "sweep-plot"):
            self.sweeps[-1]["label"] += data
        if self.inside("text", "x-label") and self.inside("figure", "sweep-plot"):
            self.sweeps[-1]["x_label"] += data

        hidden = self.inside("annotation") or self.inside("script") or self.inside("style")
        if not hidden and "\\" in data:
            self.text_backslashes += 1
        if not hidden and "no free-body diagram" in data:
            self.constraint_rows += 1


def png_pixels(path):
    """Width, height and the gray level of every pixel of an 8-bit RGB(A) PNG."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and color in (2, 6), "unexpected PNG format"
            channels = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up, ul = prev[x], prev[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 255
            elif kind == 2:
                line[x] = (line[x] + up) & 255
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - ul
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - ul)
                line[x] = (line[x] + (left if pa <= pb and pa <= pc else up if pb <= pc else ul)) & 255
        rows.append(line)
        prev = line
    gray = []
    for line in rows[::4]:  # every fourth row is plenty for a variance
        gray.extend((line[x] + line[x + 1] + line[x + 2]) // 3 for x in range(0, stride, channels))
    return width, height, gray



def unit_text(unit):
    """A unit as the plots' axes show it: N*m as N·m, none said."""
    return unit.replace("*", "\u00b7") if unit else "no unit"


def check_plots(dom, data, who, model):
    """The page is titled with the model's name; one unit per plot, named on its y axis; no
    two series of a plot in one colour; every series plotted once; no two plots titled alike
    (each names the statement, line and table behind it, and its unit)."""
    check(dom.title.strip() == model and dom.h1.strip() == model,
          "%s: the page's title and heading are the model's name %r (%r, %r)" % (who, model, dom.title, dom.h1))
    # expected: per history, per unit in order, as many plots as hold its series ten at a time
    expected = []
    for h in data["histories"]:
        units = []
        for ser in h["series"]:
            if ser["unit"] not in units:
                units.append(ser["unit"])
        for u in units:
            n = sum(1 for ser in h["series"] if ser["unit"] == u)
            expected += [u] * math.ceil(n / 10)
    figures = dom.figures
    check([f["unit"] for f in figures] == expected,
          "%s: a plot per unit of each history (%s, expected %s)" % (who, [f["unit"] for f in figures], expected))
    check(sum(len(f["series"]) for f in figures) == sum(len(h["series"]) for h in data["histories"]),
          "%s: every series plotted once (%d)" % (who, sum(len(f["series"]) for f in figures)))
    for f in figures:
        units = set(u for u, _ in f["series"])
        colours = [c for _, c in f["series"]]
        check(units <= {f["unit"]} and f["label"] == unit_text(f["unit"]),
              "%s: %s: its series share its unit %r, shown on its axis (%s, label %r)"
              % (who, f["title"], f["unit"], sorted(units), f["label"]))
        check(len(set(colours)) == len(colours) and all(colours),
              "%s: %s: no two of its %d series in one colour (%s)" % (who, f["title"], len(colours), colours))
    titles = [f["title"] for f in figures]
    check(len(set(titles)) == len(titles), "%s: no two plots titled alike (%s)" % (who, titles))
    check(all(re.match(r"(simulate|inverse) at line \d+ \(.+\.csv\): ", t) for t in titles),
          "%s: each plot titled with its statement, line and table (%s)" % (who, titles[:2]))


def check_sweeps(dom, data, who):
    """Each result's sweep (a linearize ... for c = a to b step h) plotted under the result
    against the swept value: the real parts on one plot and the imaginary parts on another
    (ten series at most each), each titled with its statement, line and table and its axis,
    its unit on the y axis and the swept value's name and unit on the x axis, every series
    drawn through every sample, no two series of a plot in one colour."""
    expected = []
    for r in data["results"]:
        w = r.get("sweep")
        if not w:
            continue
        for axis in ("real part", "imaginary part"):
            n = sum(1 for ser in w["series"] if ser["axis"] == axis)
            expected += [(str(r["line"]), axis, "1/s", w["title"], w["parameter"], w["unit"], len(w["values"]))] \
                * math.ceil(n / 10)
    check([(f["line"], f["axis"], f["unit"]) for f in dom.sweeps] == [e[:3] for e in expected],
          "%s: each sweep's real and imaginary parts plotted under its result (%s, expected %s)"
          % (who, [(f["line"], f["axis"]) for f in dom.sweeps], [e[:2] for e in expected]))
    for f, (line, axis, unit, title, parameter, parameter_unit, samples) in zip(dom.sweeps, expected):
        colours = [c for _, c, _ in f["series"]]
        x_label = parameter + (" [%s]" % unit_text(parameter_unit) if parameter_unit else "")
        check(f["title"].startswith(title + ": " + axis + "s, ") and re.match(r"linearize at line \d+", title)
              and f["label"] == unit_text(unit) and f["x_label"] == x_label,
              "%s: %s: titled with its statement and axis, %r on its y axis and %r on its x axis (%r, %r)"
              % (who, f["title"], unit_text(unit), x_label, f["label"], f["x_label"]))
        check(f["series"] and all(u == unit and n == samples for u, _, n in f["series"])
              and len(set(colours)) == len(colours) and all(colours),
              "%s: %s: its %d series each drawn through the %d samples in colours of their own (%s)"
              % (who, f["title"], len(f["series"]), samples, [n for _, _, n in f["series"]]))


def console_lines(stderr):
    """The page's console messages in Chromium's log, without the notes of its software GL
    driver about its own speed ("GL Driver Message ... GPU stall due to ReadPixels"), which
    are Chromium's, not the page's."""
    return [l for l in stderr.splitlines() if "CONSOLE" in l and "GL Driver Message" not in l]


def check_exercise(steps, expected, who):
    """Every expected control was worked and did what it should."""
    for want in expected:
        found = [s for s in steps if want in s]
        check(bool(found) and all(s.startswith("ok ") for s in found), "%s: control: %s (%s)" % (who, want, found))
    for step in steps:
        if not step.startswith("ok "):
            check(False, "%s: control: %s" % (who, step))


def page_data(index):
    """The report's data as the page embeds it."""
    import json
    with open(index, encoding="utf-8") as f:
        page = f.read()
    start = page.index('id="alembert-data">') + len('id="alembert-data">')
    return json.loads(page[start:page.index("</script>", start)])


def open_page(browser, url, extra=()):
    """Chromium's DOM of the page after its scripts, and its console lines."""
    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    try:
        r = run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
                 "--hide-scrollbars", "--enable-logging=stderr", "--v=0", "--virtual-time-budget=3000"]
                + WEBGL + list(extra) + ["--dump-dom", url], capture_output=True, text=True, timeout=120)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    dom = Dom()
    dom.feed(r.stdout)
    return dom, console_lines(r.stderr)


def not_blank(png, who, min_dark=0.002):
    w, h, gray = png_pixels(png)
    mean = sum(gray) / len(gray)
    var = sum((g - mean) ** 2 for g in gray) / len(gray)
    dark = sum(1 for g in gray if g < 200) / len(gray)
    check(var > 30 and min_dark < dark < 0.7, "%s: the picture is not blank (%dx%d, variance %.0f, %.1f%% drawn)"
          % (who, w, h, var, 100 * dark))


def three_d(cli, source, work, browser):
    """Models in the 3D view: the four-bar swinging, a rolling disk, a spatial chain. Each is
    drawn (sticks, bodies as their inertia ellipsoids), turns when dragged, follows the time
    slider, and its checks pass: energy kept, constraints held, the methods agree."""
    import base64
    for name, kinds_expected in (("four_bar_motion", ["energy", "constraint", "methods"]),
                                 ("rolling_disk_motion", ["energy", "constraint"]),
                                 ("spatial_chain_motion", ["energy", "methods"])):
        out = os.path.join(work, name)
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        script = os.path.join(source, "tests", "report", name + ".alb")
        r = run([cli, "run", "-q", script, "--out", out], capture_output=True, text=True, timeout=300)
        check(r.returncode == 0, "%s: the script writes its report (stderr: %s)" % (name, r.stderr.strip()[:300]))
        index = os.path.join(out, "index.html")
        if r.returncode != 0:
            continue
        data = page_data(index)
        dom, console = open_page(browser, "file://" + os.path.abspath(index) + "#exercise")
        check(dom.status == "ready" and not dom.errors.strip() and not console,
              "%s: the viewer finished without errors (%r %s)" % (name, dom.errors.strip()[:200], console[:2]))
        check(dom.canvas is not None, "%s: the 3D view is on the page" % name)
        if dom.canvas is None:
            continue
        bodies = [b for b in data["animation"]["bodies"] if b["ellipsoid"]]
        check(dom.canvas.get("data-sticks") == str(len(data["geometry"]["segments"])) and
              dom.canvas.get("data-shells") == str(len(bodies)) and len(bodies) >= 1,
              "%s: a stick per segment and an ellipsoid per rigid body (%s, %s)"
              % (name, dom.canvas.get("data-sticks"), dom.canvas.get("data-shells")))
        check_exercise(dom.exercise.strip().splitlines(),
                       ["the 3D view is drawn", "dragging turns the 3D view", "the time slider moves the 3D view",
                        "dragging zooms into a time range", "play starts the animation", "the cursor moves the animation",
                        "play at 1\u00d7"], name)
        check_plots(dom, data, name, name)
        if dom.image3d.startswith("data:image/png;base64,"):
            png = os.path.join(out, "view3d.png")
            with open(png, "wb") as f:
                f.write(base64.b64decode(dom.image3d.split(",", 1)[1]))
            not_blank(png, name + ": 3D view")
        else:
            check(False, "%s: the 3D view's picture was written" % name)
        kinds = [k for k, _ in dom.checks]
        kinds_expected = kinds_expected + (["units"] if data["roadmap"] else [])
        check(set(kinds) == set(kinds_expected), "%s: the checks shown are %s (%s)" % (name, kinds_expected, kinds))
        check(all(ok for _, ok in dom.checks) and len(dom.checks) > 0, "%s: every check passes (%s)" % (name, dom.checks))
        if "methods" in kinds_expected:
            check(kinds.count("methods") >= 3, "%s: Kane, Lagrange and Newton-Euler compared (%s)" % (name, kinds))


def motion_from_file(cli, source, work, browser):
    """A script whose inverse reads its motion from a file (tests/report/motion_file_inverse.alb
    over motion_file_inverse.csv, unfiltered): the report animates that motion as it does a
    simulated one, the animation plays, and the diagrams are drawn at the file's first row."""
    import csv
    name = "motion_file_inverse"
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    script = os.path.join(source, "tests", "report", name + ".alb")
    r = run([cli, "run", "-q", script, "--out", out], capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, "%s: the script writes its report (stderr: %s)" % (name, r.stderr.strip()[:300]))
    index = os.path.join(out, "index.html")
    if r.returncode != 0 or not os.path.isfile(index):
        return
    with open(os.path.join(source, "tests", "report", name + ".csv"), newline="") as f:
        table = list(csv.reader(f))
    times = [float(row[0]) for row in table[1:]]
    q1, q2 = (math.radians(float(v)) for v in table[1][1:3])
    # the arm by hand at the first row: links along their x axes, L_A = 0.4 m, L_B = 0.3 m
    a_tip = [0.4 * math.cos(q1), 0.4 * math.sin(q1), 0]
    b_tip = [a_tip[0] + 0.3 * math.cos(q1 + q2), a_tip[1] + 0.3 * math.sin(q1 + q2), 0]
    want = {"A_o": [0, 0, 0], "Acm": [v / 2 for v in a_tip], "A_tip": a_tip, "B_o": a_tip,
            "Bcm": [(a + b) / 2 for a, b in zip(a_tip, b_tip)], "B_tip": b_tip}
    data = page_data(index)
    anim = data["animation"]
    check(anim is not None and anim["source"].startswith("inverse"),
          "%s: the motion read from the file is animated (%s)" % (name, anim and anim["source"]))
    if anim is None:
        return
    check(len(anim["time"]) == len(times) and abs(anim["time"][0] - times[0]) <= 1e-9
          and abs(anim["time"][-1] - times[-1]) <= 1e-9,
          "%s: a frame per row of the file, t = %g to %g s (%d frames)" % (name, times[0], times[-1], len(anim["time"])))

    def gap(at):
        return max(math.dist(at[n], p) for n, p in want.items())
    first = {n: anim["frames"][0][3 * i:3 * i + 3] for i, n in enumerate(anim["points"])}
    drawn = {p["name"]: p["at"] for p in data["geometry"]["points"]}
    check(gap(first) <= 1e-5, "%s: the animation's first frame is the file's first row (off by %.3g m)"
          % (name, gap(first)))
    check(gap(drawn) <= 1e-5 and "first sample" in data["configuration_source"],
          "%s: the diagrams are drawn at the file's first row (off by %.3g m; %r)"
          % (name, gap(drawn), data["configuration_source"]))
    dom, console = open_page(browser, "file://" + os.path.abspath(index) + "#exercise")
    check(dom.status == "ready" and not dom.errors.strip() and not console,
          "%s: the viewer finished without errors (%r %s)" % (name, dom.errors.strip()[:200], console[:2]))
    check(dom.anim == 1 and dom.play and dom.slider and dom.anim_sticks >= 2,
          "%s: the animation with its sticks, play and the time slider" % name)
    check(data["configuration_source"] in dom.configuration,
          "%s: the page says where the diagrams are drawn (%r)" % (name, dom.configuration[-120:]))
    check_exercise(dom.exercise.strip().splitlines(), EXERCISE_MOTION + ["the cursor moves the animation"], name)


# appended to a copy of a report's page: once the viewer has drawn and KaTeX's fonts are in,
# opens the folded equations as printing does (the viewer's beforeprint), then writes on
# <body> how many .equation boxes there are and those whose content is wider than the box
MEASURE = """<script>
window.addEventListener("load", function () {
  // #print: the page's @media print rules applied as printing applies them
  if (location.hash === "#print")
    Array.prototype.forEach.call(document.styleSheets, function (sheet) {
      Array.prototype.forEach.call(sheet.cssRules, function (rule) {
        if (rule.media && /print/.test(rule.media.mediaText))
          Array.prototype.forEach.call(rule.cssRules, function (r) { sheet.insertRule(r.cssText, sheet.cssRules.length); });
      });
    });
  document.fonts.ready.then(function () {
    window.dispatchEvent(new Event("beforeprint"));
    setTimeout(function () {
      var boxes = document.querySelectorAll("div.equation"), wide = [];
      boxes.forEach(function (b, i) {
        if (b.scrollWidth > b.clientWidth + 1) wide.push(i + ":" + b.scrollWidth + ">" + b.clientWidth);
      });
      var row = document.querySelector(".row-body");
      document.body.setAttribute("data-measured", boxes.length + "|" + wide.join(",") + "|" +
                                 (row ? getComputedStyle(row).display : ""));
    }, 100);
  });
});
</script>"""


# appended to a copy of a report's page: once the viewer has drawn, and has drawn the rows it
# leaves until they are scrolled to as printing has it draw them, writes what each free-body
# diagram drew into <pre id="fbd-measure"> as JSON: its viewBox, every label's text and laid
# out box, each load arrow's data attributes, lines, arrowhead tips, arcs and computed stroke,
# the points' drawn places and the u arrow's lines
FBD_MEASURE = """<script>
window.addEventListener("load", function () {
  document.fonts.ready.then(function () {
    window.dispatchEvent(new Event("beforeprint"));
    setTimeout(function () {
      function box(n) { var b = n.getBBox(); return [b.x, b.y, b.width, b.height]; }
      function lines(g) {
        return Array.prototype.map.call(g.querySelectorAll("line.shaft"), function (l) {
          return ["x1", "y1", "x2", "y2"].map(function (c) { return Number(l.getAttribute(c)); }); });
      }
      function tips(g) {
        return Array.prototype.map.call(g.querySelectorAll("path.head"), function (h) {
          return h.getAttribute("d").slice(1).split(" ")[0].split(",").map(Number); });
      }
      var out = Array.prototype.map.call(document.querySelectorAll("svg.fbd"), function (s) {
        var points = {};
        s.querySelectorAll("circle[data-point]").forEach(function (c) {
          points[c.getAttribute("data-point")] = [Number(c.getAttribute("cx")), Number(c.getAttribute("cy"))]; });
        var dir = s.querySelector("g.direction");
        return {
          view: s.getAttribute("viewBox").split(" ").map(Number),
          points: points,
          labels: Array.prototype.map.call(s.querySelectorAll("text.label"), function (t) {
            return {text: t.textContent, cls: t.getAttribute("class"), box: box(t)}; }),
          loads: Array.prototype.map.call(s.querySelectorAll("g.load"), function (g) {
            var shaft = g.querySelector(".shaft"), st = shaft ? getComputedStyle(shaft) : null;
            return {kind: g.classList[1], label: g.getAttribute("data-label"), on: g.getAttribute("data-on"),
                    at: g.getAttribute("data-at"), role: g.getAttribute("data-role"), lines: lines(g), tips: tips(g),
                    arcs: Array.prototype.map.call(g.querySelectorAll("polyline.shaft"), function (p) {
                      return p.getAttribute("points").split(" ").map(function (q) { return q.split(",").map(Number); }); }),
                    stroke: st ? st.stroke : "", width: st ? parseFloat(st.strokeWidth) : 0,
                    dash: st ? st.strokeDasharray : "", halo: g.querySelector(".halo") !== null}; }),
          direction: {lines: lines(dir), tips: tips(dir), circles: Array.prototype.map.call(dir.querySelectorAll("circle"), box),
                      label: box(dir.querySelector("text"))},
          legend: Array.prototype.map.call(s.parentNode.querySelectorAll(".fbd-legend li"), function (li) { return li.className; })
        };
      });
      var pre = document.createElement("pre");
      pre.id = "fbd-measure";
      pre.textContent = JSON.stringify(out);
      document.body.appendChild(pre);
    }, 100);
  });
});
</script>"""


MEASURED = {}  # (page, media, width): the DOM of the page measured (measured_page)


def measured_page(browser, index, media, width):
    """The DOM of a copy of the page (measure.html) with MEASURE and FBD_MEASURE appended, as
    Chromium lays it out `width` px wide for `media` (screen, print): each equation box's
    width against its column's and each free-body diagram as drawn, from one start of
    Chromium (each start costs seconds); loaded once per page, media and width."""
    key = (os.path.abspath(index), media, width)
    if key not in MEASURED:
        with open(index, encoding="utf-8") as f:
            page = f.read()
        at = page.rindex("</body>")
        measure = os.path.join(os.path.dirname(index), "measure.html")
        with open(measure, "w", encoding="utf-8") as f:
            f.write(page[:at] + MEASURE + FBD_MEASURE + page[at:])
        profile = tempfile.mkdtemp(prefix="alembert-chromium-")
        try:
            r = run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
                     "--hide-scrollbars", "--virtual-time-budget=10000", "--window-size=%d,1600" % width] + WEBGL +
                    ["--dump-dom", "file://" + os.path.abspath(measure) + "#" + media],
                    capture_output=True, text=True, timeout=300)
        finally:
            shutil.rmtree(profile, ignore_errors=True)
        MEASURED[key] = r.stdout
    return MEASURED[key]


def segment_meets_box(a, b, box):
    """Whether the segment a-b passes through the box [x, y, w, h] (sampled finely)."""
    for k in range(201):
        x, y = a[0] + (b[0] - a[0]) * k / 200, a[1] + (b[1] - a[1]) * k / 200
        if box[0] < x < box[0] + box[2] and box[1] < y < box[1] + box[3]:
            return True
    return False


def data_symbols(vector, data):
    """The names a load's vector (as the page's model table writes it) holds that are no
    constant, unknown, coordinate, unit vector (Nx>) or function (sqrt): its rates (x') and
    specified quantities (a push F, a plate's chair_Tz), whose values the configuration may
    not give."""
    model = data["model"]
    fixed = set(c["name"] for c in model["constants"] + model["unknowns"] + model["coordinates"])
    out = []
    for m in re.finditer(r"(?<![A-Za-z0-9_.])([A-Za-z_][A-Za-z0-9_]*)('*)(>|\()?", vector):
        name, primes, after = m.group(1), m.group(2), m.group(3)
        if after or (not primes and name in fixed):
            continue
        out.append(name + primes)
    return out


def diagram_checks(browser, index, who):
    """Each free-body diagram as drawn, against the page's data: every load arrow acts on a body
    of S (its data attributes, checked against the model's tables) and starts or ends at its
    point's drawn place (a torque's arc is centred there); no two labels overlap, nor does a
    label lie on a load arrow's shaft, arc or head; the u arrow
    lies inside the picture and its label clear of its shaft; the points of S and a planar
    model's angles of S are named; a weight is labelled with its mass times g; the row's own
    unknown is drawn apart (thicker, highlighted); a load whose part in the row's equation (u . F,
    or u . (r_OP x F) about O) is clearly not zero at the drawn configuration is never dashed,
    a dashed one's is zero there, and the unknown loads the road-map's list says drop out are
    dashed."""
    import html
    import json
    data = page_data(index)
    m = re.search(r'<pre id="fbd-measure">(.*?)</pre>', measured_page(browser, index, "screen", 1280), re.S)
    check(m is not None, "%s: the diagrams were measured" % who)
    if not m:
        return
    drawn = json.loads(html.unescape(m.group(1)))
    rows = [row for row in data["roadmap"] if row["diagram"]]
    check(len(drawn) == len(rows), "%s: a measured diagram per row with one (%d of %d)" % (who, len(drawn), len(rows)))
    geo = data["geometry"]
    place = {p["name"]: p["at"] for p in geo["points"]}
    owner = {p["name"]: p["on"] for p in data["model"]["points"]}
    load_on = {}  # a load's label: (on, from) of each load so labelled (a reaction's two)
    for l in data["model"]["loads"]:
        if l["kind"] != "gravity":
            load_on.setdefault(l["label"], []).append((l["on"], l["from"]))
    load_vector = {l["label"]: l["vector"] for l in data["model"]["loads"]}
    bodies = {b["name"]: b for b in data["model"]["bodies"]}
    unknowns = set(u["name"] for u in data["model"]["unknowns"])
    bad = {"on": [], "at": [], "overlap": [], "on_arrow": [], "direction": [], "named": [], "weight": [], "own": [], "drops": [],
           "zero": [], "given": []}
    # what the configuration gives: its coordinates, and the rates and data it lists
    given = set(c["name"] for c in data["configuration"] + data.get("configuration_data", []))
    for row, d in zip(rows, drawn):
        dia, S, var = row["diagram"], set(row["diagram"]["system"]), row["variable"]
        vb = d["view"]
        L = max(vb[2], vb[3])
        tol = 1e-6 * L
        # the drawn points where the data puts them (planar: the page's plane, up the page)
        if geo["planar"] and d["points"]:
            up = geo["up"][:2]
            n = math.hypot(*up) or 1
            ux, uy = up[0] / n, up[1] / n
            proj = {k: (uy * p[0] - ux * p[1], -(ux * p[0] + uy * p[1])) for k, p in place.items()}
            ref = next(iter(d["points"]))
            off = (d["points"][ref][0] - proj[ref][0], d["points"][ref][1] - proj[ref][1])
            for k, q in d["points"].items():
                if math.dist(q, (proj[k][0] + off[0], proj[k][1] + off[1])) > 1e-4 * L:
                    bad["at"].append("%s: point %s drawn off its place" % (var, k))
        for load in d["loads"]:
            # acts on a body of S, the body the model says it acts on
            if load["on"] not in S:
                bad["on"].append("%s: %s on %s, not in S %s" % (var, load["label"], load["on"], sorted(S)))
            if load["kind"] == "gravity":
                want = [b for b in S if bodies[b]["cm"] == load["at"]]
            elif load["kind"] == "joint":
                want = [owner.get(load["at"])]
            else:
                want = [on for on, frm in load_on.get(load["label"], []) if frm not in S]
            if load["on"] not in want:
                bad["on"].append("%s: %s drawn on %s, the model's %s" % (var, load["label"], load["on"], want))
            # starts or ends at its point
            p = d["points"].get(load["at"])
            if p is None:
                bad["at"].append("%s: %s at %s, a point not drawn" % (var, load["label"], load["at"]))
                continue
            ends = [q for l in load["lines"] for q in ((l[0], l[1]), (l[2], l[3]))] + [tuple(t) for t in load["tips"]]
            if load["arcs"]:
                radii = [math.dist(q, p) for q in load["arcs"][0]]
                ok = max(radii) - min(radii) <= 1e-4 * L
            else:
                ok = any(math.dist(q, p) <= tol for q in ends)
            if not ok:
                bad["at"].append("%s: %s not drawn at %s" % (var, load["label"], load["at"]))
        # no two labels overlap
        boxes = [(l["text"], l["box"]) for l in d["labels"]]
        for i in range(len(boxes)):
            for j in range(i + 1, len(boxes)):
                a, b = boxes[i][1], boxes[j][1]
                e = 1e-3 * L
                if a[0] + e < b[0] + b[2] and b[0] + e < a[0] + a[2] and a[1] + e < b[1] + b[3] and b[1] + e < a[1] + a[3]:
                    bad["overlap"].append("%s: %r over %r" % (var, boxes[i][0], boxes[j][0]))
        # no label on a load arrow: its shaft, its arc or its head
        for text, b in boxes:
            e = 1e-3 * L
            inner = [b[0] + e, b[1] + e, b[2] - 2 * e, b[3] - 2 * e]
            for load in d["loads"]:
                segments = [((l[0], l[1]), (l[2], l[3])) for l in load["lines"]] + \
                    [(a[k - 1], a[k]) for a in load["arcs"] for k in range(1, len(a))]
                if any(segment_meets_box(p, q, inner) for p, q in segments) or \
                        any(inner[0] < t[0] < inner[0] + inner[2] and inner[1] < t[1] < inner[1] + inner[3] for t in load["tips"]):
                    bad["on_arrow"].append("%s: %r on %s's arrow" % (var, text, load["label"]))
        # the u arrow inside the picture, its label clear of its shaft
        u = d["direction"]
        xs = [c for l in u["lines"] for c in (l[0], l[2])] + [t[0] for t in u["tips"]] + [c[0] for c in u["circles"]] + \
             [c[0] + c[2] for c in u["circles"]]
        ys = [c for l in u["lines"] for c in (l[1], l[3])] + [t[1] for t in u["tips"]] + [c[1] for c in u["circles"]] + \
             [c[1] + c[3] for c in u["circles"]]
        lb = u["label"]
        if not (xs and min(xs) >= vb[0] and max(xs) <= vb[0] + vb[2] and min(ys) >= vb[1] and max(ys) <= vb[1] + vb[3]
                and lb[0] >= vb[0] and lb[0] + lb[2] <= vb[0] + vb[2] and lb[1] >= vb[1] and lb[1] + lb[3] <= vb[1] + vb[3]):
            bad["direction"].append("%s: u outside the viewBox %s (x %s, y %s)" % (var, vb, xs, ys))
        for l in u["lines"]:
            if segment_meets_box((l[0], l[1]), (l[2], l[3]), lb):
                bad["direction"].append("%s: u's label on its shaft" % var)
        # S's points and angles named
        texts = set(l["text"] for l in d["labels"])
        if "points" not in dia:
            bad["named"].append("%s: the data lists no points to name" % var)
        for name in dia.get("points", []):
            if name not in texts and "O = " + name not in texts:
                bad["named"].append("%s: %s" % (var, name))
        if dia["about"] and "O = " + dia["about"] not in texts:
            bad["named"].append("%s: O = %s" % (var, dia["about"]))
        for an in geo.get("angles", []):
            if an["body"] in S and an["name"] not in texts:
                bad["named"].append("%s: angle %s" % (var, an["name"]))
        # a weight: its mass times g
        for load in d["loads"]:
            if load["kind"] == "gravity":
                mass = bodies.get(load["on"], {}).get("mass", "(no body)")
                if mass not in load["label"] or load["label"] == load["on"] + " g":
                    bad["weight"].append("%s: %r for mass %r" % (var, load["label"], mass))
        # the row's own unknown apart: the loads whose vector holds the row's variable, a load
        # measure (a statics row's coordinate in a spring's force is no load's own)
        word = re.compile(r"(?<![A-Za-z0-9_])" + re.escape(var) + r"(?![A-Za-z0-9_'])")
        for load in d["loads"]:
            own = load["kind"] in ("force", "torque") and var in unknowns and \
                bool(word.search(load_vector.get(load["label"], "")))
            if own != (load["role"] == "own"):
                bad["own"].append("%s: %s role %s" % (var, load["label"], load["role"]))
        owns = [l for l in d["loads"] if l["role"] == "own"]
        others = [l for l in d["loads"] if l["role"] != "own"]
        for o in owns:
            if not o["halo"] or any(o["width"] <= x["width"] for x in others) or "own" not in d["legend"]:
                bad["own"].append("%s: %s not drawn apart (width %s, halo %s, legend %s)"
                                  % (var, o["label"], o["width"], o["halo"], d["legend"]))
        # dashed exactly where the load's part in the equation is zero
        U = dia["direction"]
        O = place.get(dia["about"]) if row["motion"] == "rotate" else None
        # a load at a point the configuration does not place is not drawn, and the legend says so
        placed = [l for l in dia["loads"] if l.get("placed", True)]
        if len(placed) < len(dia["loads"]) and "unplaced" not in d["legend"]:
            bad["at"].append("%s: loads left undrawn and the legend silent" % var)
        # a known load zero here: drawn along its positive sense, labelled as zero, said in the legend
        texts_drawn = [l["text"] for l in d["labels"]]
        for spec in placed:
            if spec["kind"] in ("force", "torque") and not spec["unknown"] and spec.get("given", True) \
                    and not any(spec["vector"]):
                if (spec["label"] + " = 0") not in texts_drawn or "zero" not in d["legend"]:
                    bad["zero"].append("%s: %s, zero here, not labelled so (%s)" % (var, spec["label"], d["legend"]))
        # a known load whose value the configuration does not give (a specified quantity or a
        # rate it leaves out): no value in the data, none in its label, and the legend says so;
        # every other known load's vector is the model's at the configuration's values
        for spec in dia["loads"]:
            if spec["kind"] not in ("force", "torque") or spec["unknown"]:
                continue
            needs = [x for x in data_symbols(load_vector.get(spec["label"], ""), data) if x not in given]
            if spec.get("given", True) == bool(needs):
                bad["given"].append("%s: %s holds %s the configuration does not give, marked given %s"
                                    % (var, spec["label"], needs, spec.get("given", True)))
            if spec.get("given", True):
                continue
            valued = [t for t in texts_drawn if t.startswith(spec["label"] + " =")]
            if spec["vector"] or (spec.get("placed", True) and (valued or spec["label"] not in texts_drawn
                                                                 or "not-given" not in d["legend"])):
                bad["given"].append("%s: %s, not given here, drawn with %s labelled %s (legend %s)"
                                    % (var, spec["label"], spec["vector"], valued, d["legend"]))
        for load, spec in zip(d["loads"], placed):
            dashed = load["dash"] not in ("", "none")
            if (load["role"] == "drops") != dashed or (dashed and "drops" not in d["legend"]):
                bad["drops"].append("%s: %s role %s, dash %r" % (var, load["label"], load["role"], load["dash"]))
            if spec["kind"] == "joint":
                if load["role"] != "drops" or (O is not None and spec["at"] != dia["about"]):
                    bad["drops"].append("%s: joint at %s (O %s) role %s" % (var, spec["at"], dia["about"], load["role"]))
                continue
            F = spec["vector"] if row["motion"] == "rotate" or spec["kind"] != "torque" else [0, 0, 0]
            if O is not None and spec["kind"] != "torque":
                rr = [a - b for a, b in zip(place[spec["at"]], O)]
                F = [rr[1] * F[2] - rr[2] * F[1], rr[2] * F[0] - rr[0] * F[2], rr[0] * F[1] - rr[1] * F[0]]
            part = sum(a * b for a, b in zip(U, F))
            size = math.sqrt(sum(a * a for a in spec["vector"])) * (1 + (L if O is not None else 0))
            if load["role"] == "drops" and abs(part) > 1e-6 * size:
                bad["drops"].append("%s: %s dashed, its part %.3g" % (var, load["label"], part))
            if load["role"] != "drops" and abs(part) > 1e-6 * size:
                continue
            # zero here: the road-map's own list says whether it drops out at every state
            listed = [f for f in row["fbd"] if f.startswith(spec["label"] + " ")]
            if listed and "drops out" in listed[0] and load["role"] != "drops":
                bad["drops"].append("%s: %s listed as dropping out, not dashed" % (var, spec["label"]))
    for what, text in (("on", "every load arrow on a body of S, the one the model says it acts on"),
                       ("at", "every load arrow at its point's drawn place"),
                       ("overlap", "no two labels overlap"),
                       ("on_arrow", "no label on a load arrow's shaft, arc or head"),
                       ("direction", "the u arrow inside the picture, its label clear of its shaft"),
                       ("named", "S's points, O and S's angles named"),
                       ("weight", "each weight labelled with its mass times g"),
                       ("own", "the row's own unknown drawn apart"),
                       ("drops", "loads the equation does not hold dashed, others not"),
                       ("zero", "a known load zero at the configuration labelled = 0, the legend saying so"),
                       ("given", "a known load the configuration gives no value of labelled with none, the legend saying so")):
        check(not bad[what], "%s: %s (%d diagrams; %s)" % (who, text, len(drawn), bad[what][:3]))


WIDTHS = (("screen", 1280), ("print", 720))


def lazy_rows(browser, url, rows, who):
    """A page whose rows hold more than the viewer's EAGER_TEX (40,000 characters of TeX) draws
    its first rows on opening and each other when it is scrolled near: opened in a window of
    800 x 600 px, rows past the first are left to draw and the page is ready without errors;
    opened at its last row, that row is drawn and the rows between are not."""
    data = page_data(url[len("file://"):])
    tex = [len(row["equation"]) for row in data["roadmap"]]
    if sum(tex) <= 40000:
        return
    first = next(i + 1 for i in range(len(tex)) if sum(tex[:i + 1]) >= 40000)
    dom, console = open_page(browser, url, ["--window-size=800,600"])
    check(dom.status == "ready" and not dom.errors.strip() and not console,
          "%s: opened without #exercise, the viewer finished without errors (%r)" % (who, dom.errors.strip()[:200]))
    drawn = sum(1 for row in data["roadmap"][:rows - dom.pending] if row["diagram"])
    check(dom.rows == rows and 0 < dom.pending <= rows - first and len(dom.fbds) == drawn,
          "%s: the first %d rows drawn on opening, %d of %d left until scrolled to (%d diagrams)"
          % (who, first, dom.pending, rows, len(dom.fbds)))
    # opened at the last row (the address's #row-N): it is drawn, the first rows too, the rows
    # between are left
    dom, console = open_page(browser, url + "#row-%d" % rows, ["--window-size=800,600"])
    check(dom.status == "ready" and not dom.errors.strip() and not console and dom.rows == rows
          and 0 < dom.pending < rows - first and dom.drawn_rows[:first] == list(range(1, first + 1))
          and rows in dom.drawn_rows,
          "%s: opened at row %d, it is drawn (rows drawn %s)" % (who, rows, dom.drawn_rows))


def equation_widths(browser, index, who, print_pdf=False, widths=WIDTHS):
    """Every .equation box no wider than its column: at 1280 px on the screen, and with the
    page's @media print rules applied (measure.html#print) at an A4 page's width (about 720 px
    within its margins), where the row's diagram and equation stack. With `print_pdf`, the page
    printed to PDF by Chromium too (minutes for the arm's 200 pages, so for one page only)."""
    rows = len(page_data(index)["roadmap"])
    url = "file://" + os.path.abspath(os.path.join(os.path.dirname(index), "measure.html"))
    for media, width in widths:
        m = re.search(r'data-measured="(\d+)\|([^|"]*)\|([a-z]*)"', measured_page(browser, index, media, width))
        check(m is not None and int(m.group(1)) >= rows and not m.group(2),
              "%s (%s, %d px): no equation wider than its column (%s)"
              % (who, media, width, m.group(0)[:200] if m else "not measured"))
        if media == "print" and rows:
            check(m is not None and m.group(3) == "block",
                  "%s: the print stylesheet applies (a row's diagram above its equation: %s)"
                  % (who, m.group(3) if m else "not measured"))
    if not print_pdf:
        return
    pdf = os.path.join(os.path.dirname(index), "printed.pdf")
    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    try:
        run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
             "--virtual-time-budget=10000", "--no-pdf-header-footer", "--print-to-pdf=" + pdf, url] + WEBGL,
            capture_output=True, text=True, timeout=300)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    pages = 0
    if os.path.isfile(pdf):
        with open(pdf, "rb") as f:
            pages = len(re.findall(rb"/Type\s*/Page[^s]", f.read()))
    check(pages > 0, "%s: printed to PDF (%d pages)" % (who, pages))


def examples(cli, source, work, browser, names):
    """The reports of the examples `names` (report_examples.example_models; main_page opens the
    sit-to-stand page): written, drawn without errors, one free-body diagram per road-map row
    with an arrow per load on S, every equation typeset, plots and animation where the script
    computed histories; a planar and a spatial example's screenshot not blank."""
    import time
    for name, model in example_models(source):
        if name not in names:
            continue
        out = os.path.join(work, "examples", name)
        shutil.rmtree(out, ignore_errors=True)
        start = time.monotonic()
        r = run([cli, "report", model, "--out", out], capture_output=True, text=True, timeout=600)
        seconds = time.monotonic() - start
        check(r.returncode == 0, "%s: alembert report exits 0 in %.2f s (stderr: %s)" % (name, seconds, r.stderr.strip()[:300]))
        index = os.path.join(out, "index.html")
        if r.returncode != 0 or not os.path.isfile(index):
            continue
        data = page_data(index)
        url = "file://" + os.path.abspath(index)
        dom, console = open_page(browser, url + "#exercise")
        check(dom.status == "ready" and not dom.errors.strip(), "%s: the viewer finished without errors (%r)"
              % (name, dom.errors.strip()[:300]))
        check(not console, "%s: no console messages (%s)" % (name, console[:2]))
        rows = len(data["roadmap"])
        drawn = [f for f in dom.fbds]
        with_diagram = sum(1 for row in data["roadmap"] if row["diagram"])
        # the sliders that turn the diagrams only where a spatial model has diagrams to turn
        check(dom.view_controls == (1 if with_diagram and not data["geometry"]["planar"] else 0),
              "%s: sliders to turn the diagrams where there are spatial diagrams (%d sliders' boxes, %d diagrams)"
              % (name, dom.view_controls, with_diagram))
        check(dom.rows == rows and len(drawn) == with_diagram and dom.constraint_rows == rows - with_diagram,
              "%s: one free-body diagram per road-map row (%d rows, %d diagrams, %d constraint rows)"
              % (name, rows, len(drawn), dom.constraint_rows))
        expected = [len([l for l in row["diagram"]["loads"] if l.get("placed", True)])
                    for row in data["roadmap"] if row["diagram"]]
        check([f[1] for f in drawn] == expected and all(n > 0 for n in expected),
              "%s: an arrow per load on S %s" % (name, [f[1] for f in drawn]))
        # each row's equation and each equation a kane or lagrange formed (a model may have
        # either alone: the bicycle's Kane equations with no road-map) typeset, or folded when
        # longer than the viewer's LONG_TEX, to be typeset when opened
        shown = [row["equation"] for row in data["roadmap"]] + [e for s in data["equation_sets"] for e in s["equations"]]
        long_ones = sum(1 for e in shown if len(e) > 12000)
        check(dom.shown == len(shown) - long_ones and dom.folded_shown == long_ones and dom.katex == dom.equations
              and dom.raw == 0 and dom.text_backslashes == 0,
              "%s: every equation of the rows and equation sets typeset by KaTeX (%d of %d) or folded when long "
              "(%d of %d; %d typeset in all)" % (name, dom.shown, len(shown) - long_ones, dom.folded_shown, long_ones,
                                                 dom.katex))
        # the intermediates are on the page once, each row naming those it uses
        check(all(0 <= k < len(data["intermediates"]) for row in data["roadmap"] for k in row["intermediates"]),
              "%s: the rows' intermediates are in the page's table (%d)" % (name, len(data["intermediates"])))
        # gravity down the page in every diagram, whichever N axis is up (SVG's y points down)
        down = [dx == 0 and dy > 0 or abs(dx) <= 1e-9 * abs(dy) and dy > 0 for dx, dy in dom.gravity_shafts]
        gravity = sum(1 for row in data["roadmap"] if row["diagram"]
                      for load in row["diagram"]["loads"] if load["kind"] == "gravity")
        check(len(down) == gravity and all(down),
              "%s: gravity points down the page in every diagram (%d arrows of %d, shafts %s)"
              % (name, len(down), gravity, dom.gravity_shafts[:3]))
        # every result the script printed is on the page, under its statement
        with open(model) as f:
            lines = f.read().split("\n")
        printing = [i + 1 for i, l in enumerate(lines) if re.match(r"(solve|evaluate|linearize)\b", l)]
        check([int(r[0].split(":")[0].split()[1]) for r in dom.results] == printing
              and all(r[1].strip() for r in dom.results),
              "%s: every solve, evaluate and linearize result shown under its statement (lines %s, page %s)"
              % (name, printing, [r[0][:40] for r in dom.results]))
        # the equations kane and lagrange formed, each statement's under its name
        formed = [i + 1 for i, l in enumerate(lines) if re.match(r"(kane|lagrange)\b", l)]
        check([s["line"] for s in data["equation_sets"]] == formed and dom.equation_sets == len(formed),
              "%s: the equations of every kane and lagrange statement on the page (lines %s, %d sections)"
              % (name, formed, dom.equation_sets))
        # drawn at a configuration the model takes: its loops closed, and the page says where
        closure = [abs(k["residual"]) for k in data["closure"]]
        check(all(r <= 1e-9 for r in closure) and data["configuration_source"]
              and (data["configuration_source"] in dom.configuration or not data["roadmap"]),
              "%s: the diagrams' configuration closes every loop (residuals %s) and is named (%r)"
              % (name, closure, dom.configuration[-120:]))
        if name == "four_bar_linkage":
            # the coupler's tip is the rocker's: the loop is drawn closed, every link its length
            at = {p["name"]: p["at"] for p in data["geometry"]["points"]}
            gap = math.dist(at["B_tip"], at["C_tip"])
            coupler, rocker = math.dist(at["B_o"], at["B_tip"]), math.dist(at["C_o"], at["C_tip"])
            check(gap <= 1e-5 and abs(coupler - 1.2) <= 1e-5 and abs(rocker - 0.8) <= 1e-5,
                  "four_bar_linkage: drawn closed (gap %.3g m, coupler %.6g m, rocker %.6g m)" % (gap, coupler, rocker))
        if name == "sit_to_stand_lab":
            chair_by_hand(source, data)
            chair_unplaced(cli, source, work, browser)
        check_plots(dom, data, name, name)
        check_sweeps(dom, data, name)
        if name in ("rolling_disk", "bicycle"):
            check(len(dom.sweeps) >= 2, "%s: the eigenvalues of its sweep are drawn (%d plots)" % (name, len(dom.sweeps)))
        # the controls worked: the plots' cursor and zoom, the animation's slider, play and speed
        want = (EXERCISE_PLOTS if data["histories"] else []) + (EXERCISE_MOTION if data["animation"] else [])
        want += EXERCISE_TEACHING if data["roadmap"] else []
        want += EXERCISE_SWEEP if any(r.get("sweep") for r in data["results"]) else []
        if data["histories"] and data["animation"]:
            want.append("the cursor moves the animation")
        check_exercise(dom.exercise.strip().splitlines(), want, name)
        if not data["geometry"]["planar"]:
            check(dom.canvas is not None, "%s: a spatial model is shown in the 3D view" % name)
        if data["animation"]:
            check(dom.anim == 1 and dom.play and dom.slider and (dom.canvas is not None or data["geometry"]["planar"]),
                  "%s: the animation with play and the time slider" % name)
        lazy_rows(browser, url, dom.rows, name)
        diagram_checks(browser, index, name)
        # in print too where the rows are longest (the arm); the sit-to-stand page and the
        # mass matrix's are measured in print below
        equation_widths(browser, index, name, widths=WIDTHS if name == "kuka_iiwa" else WIDTHS[:1])
        # a picture of a planar page and of a spatial one (the DOM checks above hold for every
        # page; the sit-to-stand page's picture is checked in main())
        if name not in ("four_bar_linkage", "rolling_disk"):
            continue
        profile = tempfile.mkdtemp(prefix="alembert-chromium-")
        shot = os.path.join(out, "screenshot.png")
        try:
            run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
                 "--hide-scrollbars", "--virtual-time-budget=3000", "--window-size=1280,1600",
                 "--screenshot=" + shot, url] + WEBGL, capture_output=True, text=True, timeout=120)
        finally:
            shutil.rmtree(profile, ignore_errors=True)
        if os.path.isfile(shot):
            not_blank(shot, name + ": screenshot")
        else:
            check(False, "%s: a screenshot was taken" % name)


def chair_by_hand(source, data):
    """The lab sit-to-stand's chair plate where its record puts it at the motion's first row,
    which the diagrams are drawn at: its force (rise.mot's 1_ground_force at the first time)
    and its centre of pressure from the model's N_o, the ankle marker LMAL (rise.trc, in mm;
    the plates' CoP are taken from the lab's origin to N_o)."""
    lab = os.path.join(source, "examples", "sit_to_stand", "lab")
    with open(os.path.join(lab, "rise.mot")) as f:
        lines = f.read().split("\n")
    head = lines.index("endheader") + 1
    names, first = lines[head].split("\t"), [float(v) for v in lines[head + 1].split("\t")]
    record = dict(zip(names, first))
    with open(os.path.join(lab, "rise.trc")) as f:
        frames = [l.split("\t") for l in f.read().split("\n")[5:] if l.strip()]
    lmal = [(float(r[2]) / 1000, float(r[3]) / 1000) for r in frames]
    origin = (sum(h for h, _ in lmal) / len(lmal), sum(v for _, v in lmal) / len(lmal))
    want = (record["1_ground_force_px"] - origin[0], record["1_ground_force_py"] - origin[1])
    place = {p["name"]: p["at"] for p in data["geometry"]["points"]}
    at = place.get("chair_CoP")
    check(at is not None and math.dist(at[:2], want) <= 1e-6 and abs(data["animation"]["time"][0] - first[0]) <= 1e-9,
          "sit_to_stand_lab: the chair's centre of pressure drawn where the plate's record has it at t = %g s "
          "(%s, by hand %s)" % (first[0], at, want))
    force = (record["1_ground_force_vx"], record["1_ground_force_vy"], 0)
    drawn = [l for row in data["roadmap"] if row["diagram"] for l in row["diagram"]["loads"] if l["label"] == "chair"]
    check(drawn and all(l["at"] == "chair_CoP" and l.get("placed", True) and math.dist(l["vector"], force) <= 1e-6
                        for l in drawn),
          "sit_to_stand_lab: the chair's force drawn at chair_CoP as the record has it, %s N (%s)"
          % (force, [l["vector"] for l in drawn][:1]))


def chair_unplaced(cli, source, work, browser):
    """The lab sit-to-stand drawn at angles `report at` gives, at no row of the plate's record:
    the chair's centre of pressure has no place there, so neither it nor the chair's force is
    drawn, and each diagram's legend says so (diagram_checks, as drawn)."""
    folder = os.path.abspath(os.path.join(source, "examples", "sit_to_stand"))
    with open(os.path.join(folder, "model_lab.alb")) as f:
        script = f.read().replace('"lab/', '"' + os.path.join(folder, "lab") + "/")
    out = os.path.join(work, "lab_report_at")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    path = os.path.join(out, "lab_report_at.alb")
    with open(path, "w") as f:
        f.write(script + '\nreport at qA = -20 deg, qB = 100 deg, qC = -120 deg to "page"\n')
    r = run([cli, "run", "-q", path, "--out", out], capture_output=True, text=True, timeout=300)
    index = os.path.join(out, "page", "index.html")
    check(r.returncode == 0 and os.path.isfile(index),
          "sit_to_stand_lab at report at: the page is written (stderr: %s)" % r.stderr.strip()[:300])
    if not os.path.isfile(index):
        return
    data = page_data(index)
    chair = [l for row in data["roadmap"] if row["diagram"] for l in row["diagram"]["loads"] if l["label"] == "chair"]
    names = [p["name"] for p in data["geometry"]["points"]]
    check(chair and all(l.get("placed") is False for l in chair) and "chair_CoP" not in names,
          "sit_to_stand_lab at report at: chair_CoP has no place and the chair's force is not drawn (%s)"
          % [(l["at"], l.get("placed")) for l in chair][:1])
    # the free moment acts on B wherever it is drawn, but its value (chair_Tz) is the record's
    # at its own rows: drawn with no value (diagram_checks: no "= 0", the legend says so)
    moment = [l for row in data["roadmap"] if row["diagram"] for l in row["diagram"]["loads"]
              if l["label"] == "chair free moment"]
    check(moment and all(l.get("placed", True) and l.get("given") is False and not l["vector"] for l in moment)
          and not data.get("configuration_data"),
          "sit_to_stand_lab at report at: the chair's free moment drawn with no value, none given (%s; data %s)"
          % ([(l.get("given"), l["vector"]) for l in moment][:1], data.get("configuration_data")))
    diagram_checks(browser, index, "sit_to_stand_lab at report at")


def options(cli, source, work, browser):
    """alembert report's options: --plot chooses the series, --no-plots drops them, --check
    adds the methods and the joint reactions compared, each check passing, --matrices the
    mass matrix and forcing typeset (absent without it)."""
    model = os.path.join(source, "examples", "sit_to_stand", "model.alb")
    for args, series, checked in ((["--plot", "T_A,T_B", "--check", "--matrices"], 2, True), (["--no-plots"], 0, False)):
        out = os.path.join(work, "options" + "".join(a.strip("-").replace(",", "_") for a in args))
        shutil.rmtree(out, ignore_errors=True)
        r = run([cli, "report", model, "--out", out] + args, capture_output=True, text=True, timeout=600)
        check(r.returncode == 0, "report %s exits 0 (stderr: %s)" % (" ".join(args), r.stderr.strip()[:300]))
        dom, console = open_page(browser, "file://" + os.path.abspath(os.path.join(out, "index.html")))
        check(dom.status == "ready" and not dom.errors.strip() and not console,
              "report %s: the viewer finished without errors" % " ".join(args))
        check(dom.series == series and dom.plots == (1 if series else 0),
              "report %s: %d series plotted (%d)" % (" ".join(args), series, dom.series))
        kinds = [k for k, _ in dom.checks]
        if checked:
            check(kinds.count("methods") >= 3 and kinds.count("reactions") == 6 and all(ok for _, ok in dom.checks),
                  "report %s: the methods and the six reaction measures compared, all passing (%s)"
                  % (" ".join(args), dom.checks))
        else:
            check("methods" not in kinds, "report %s: no methods compared unless asked" % " ".join(args))
        if "--matrices" in args:
            # M, the accelerations and f: three matrices in one display; or, too wide for the
            # column (the sit-to-stand's), the accelerations' column and each entry on a line
            # of its own (M_{ij} = ..., f_{i} = ...); typeset, no TeX left
            tex = page_data(os.path.join(out, "index.html"))["matrices"]["tex"]
            matrices = 1 if "\\newline M_{" in tex else 3
            check(dom.matrices == 1 and dom.matrices_katex == 1 and dom.matrices_tables == matrices
                  and dom.raw == 0 and dom.text_backslashes == 0,
                  "report %s: the mass matrix and forcing typeset by KaTeX (%d sections, %d renderings, %d matrices)"
                  % (" ".join(args), dom.matrices, dom.matrices_katex, dom.matrices_tables))
            equation_widths(browser, os.path.join(out, "index.html"), "report " + " ".join(args))
        else:
            check(dom.matrices == 0, "report %s: no mass matrix and forcing unless asked" % " ".join(args))

def spatial(cli, source, work, browser):
    """A spatial model: drawn in a projection the user turns, every equation typeset."""
    out = os.path.join(work, "spatial")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    script = os.path.join(source, "tests", "report", "spatial_double_pendulum.alb")
    r = run([cli, "run", "-q", script, "--out", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "the spatial script writes its report (stderr: %s)" % r.stderr.strip())
    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    try:
        dump = run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
                    "--virtual-time-budget=3000"] + WEBGL + ["--dump-dom",
                    "file://" + os.path.abspath(os.path.join(out, "index.html"))],
                   capture_output=True, text=True, timeout=90)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    dom = Dom()
    dom.feed(dump.stdout)
    check(dom.status == "ready" and not dom.errors.strip(), "spatial: the viewer finished without errors (%r)"
          % dom.errors.strip()[:300])
    # four rows: T1 and T2 with S = {A, B} (2 torques, 2 weights, the joint at A_o), T3 and T4
    # with S = {B} (2 torques, B's weight, the joint at B_o)
    check([f[1] for f in dom.fbds] == [5, 5, 4, 4], "spatial: arrows per diagram %s" % dom.fbds)
    check(dom.equations >= 4 and dom.katex == dom.equations and dom.raw == 0, "spatial: every equation typeset")
    check('id="view-turn"' in dump.stdout and 'id="view-tilt"' in dump.stdout, "spatial: the view can be turned")
    # by hand: 2 rods x 6 equations; each two-axis joint forbids 3 slides and 1 turn (4
    # reaction components each) and the 4 torques asked: 12 equations in 12 unknowns, 4 rows
    bf = page_data(os.path.join(out, "index.html"))["brute_force"]
    check((bf["equations"], bf["unknowns"], bf["reactions"], bf["rows"]) == (12, 12, 8, 4) and not bf["planar"],
          "spatial: brute force takes 12 equations in 12 unknowns beside 4 road-map rows (%s)" % bf["text"])
    dom, console = open_page(browser, "file://" + os.path.abspath(os.path.join(out, "index.html")) + "#exercise")
    check(dom.status == "ready" and not dom.errors.strip() and not console,
          "spatial: the derivations open without errors (%r %s)" % (dom.errors.strip()[:200], console[:2]))
    check_exercise(dom.exercise.strip().splitlines(), EXERCISE_TEACHING, "spatial")


def main():
    import time
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        return 2
    cli, source, work = sys.argv[1:4]
    part = sys.argv[4] if len(sys.argv) == 5 else "all"
    names = [n for n, _ in example_models(source)]
    chosen = names if part == "all" else [] if part == "main" else part.split(",")
    if any(n not in names for n in chosen):
        print("browser_test.py: %r: no such example (examples with a model script: %s)" % (part, ", ".join(names)))
        return 2
    browser = chromium()
    if not browser:
        print("report.browser: skipped: Chromium is not installed (Debian: apt-get install chromium; "
              "scripts/install_deps.sh installs it)")
        return 77
    start = time.monotonic()
    if part in ("all", "main"):
        main_page(cli, source, work, browser)
        options(cli, source, work, browser)
        spatial(cli, source, work, browser)
        three_d(cli, source, work, browser)
        motion_from_file(cli, source, work, browser)
    examples(cli, source, work, browser, [n for n in chosen if n != "sit_to_stand"])
    print("time: %.1f s in all; " % (time.monotonic() - start) +
          "; ".join("%s %d runs %.1f s" % (k, n, t) for k, (n, t) in sorted(SPENT.items())))
    return 1 if failures else 0


def main_page(cli, source, work, browser):
    """The sit-to-stand report: the same bytes run to run, nothing from the network, nine
    diagrams with the loads on S, every equation typeset, the plots, the animation, every
    control worked once, the count and the unit checks, a screenshot that is not blank."""
    out = os.path.join(work, "sit_to_stand")
    shutil.rmtree(out, ignore_errors=True)
    model = os.path.join(source, "examples", "sit_to_stand", "model.alb")
    r = run([cli, "report", model, "--out", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "alembert report exits 0 (stderr: %s)" % r.stderr.strip())
    index = os.path.join(out, "index.html")
    check(os.path.isfile(index), "index.html written")
    if failures:
        return
    with open(index, encoding="utf-8") as f:
        page = f.read()
    # same script, same bytes: nothing in the page depends on the clock or the directory
    again = os.path.join(work, "sit_to_stand_again")
    shutil.rmtree(again, ignore_errors=True)
    run([cli, "report", model, "--out", again], capture_output=True, text=True, timeout=120)
    with open(os.path.join(again, "index.html"), encoding="utf-8") as f:
        check(f.read() == page, "a second run writes the same bytes")
    leftovers = [n for d, _, files in os.walk(out) for n in files if n.endswith(".tmp")]
    check(not leftovers, "no temporaries left (%s)" % leftovers)
    remote = [w for w in ('src="http', "src='http", 'href="http', "url(http", "url('http", 'url("http', "@import")
              if w in page]
    check(not remote, "the page loads nothing from the network (%s)" % remote)

    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    flags = [browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
             "--hide-scrollbars", "--enable-logging=stderr", "--v=0", "--virtual-time-budget=3000"] + WEBGL
    url = "file://" + os.path.abspath(index)
    try:
        dump = run(flags + ["--dump-dom", url], capture_output=True, text=True, timeout=90)
        shot = os.path.join(out, "screenshot.png")
        run(flags + ["--window-size=1280,2200", "--screenshot=" + shot, url],
            capture_output=True, text=True, timeout=90)
        worked = run(flags + ["--dump-dom", url + "#exercise"], capture_output=True, text=True, timeout=90)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    console = console_lines(dump.stderr)
    check(not console, "no console messages (%s)" % " | ".join(console[:3]))

    dom = Dom()
    dom.feed(dump.stdout)
    check(dom.status == "ready", "the viewer finished (data-status %r)" % dom.status)
    check(dom.errors.strip() == "", "the viewer reports no errors (%r)" % dom.errors.strip()[:300])
    # the seed's three rows, then a row per declared reaction measure (compressive and shear at
    # the ankle, knee and hip). Loads on S: {A,B,C} (rows T_A, F_Ac, F_As): T_A, gravity at
    # Acm, Bcm, Ccm and the ankle's two components at A_o (they stand for the joint's force);
    # {B,C} (T_B, F_Kc, F_Ks): T_B, 2 x gravity, the knee's two; {C} (T_C, F_Hc, F_Hs): T_C,
    # gravity, the hip's two
    check(len(dom.fbds) == 9, "one free-body diagram per road-map row (%d)" % len(dom.fbds))
    check([f[1] for f in dom.fbds] == [6, 5, 4, 6, 6, 5, 5, 4, 4],
          "arrows per diagram are the loads on S: %s" % dom.fbds)
    check(all(f[0] == f[1] for f in dom.fbds), "every load of the data is drawn")
    check(dom.equations == 9, "one equation per row (%d)" % dom.equations)
    equation_widths(browser, index, "sit_to_stand", print_pdf=True)
    diagram_checks(browser, index, "sit_to_stand")
    check(dom.katex == dom.equations, "every equation typeset by KaTeX (%d of %d)" % (dom.katex, dom.equations))
    check(dom.raw == 0 and dom.text_backslashes == 0,
          "no raw TeX left (%d raw boxes, %d texts with backslashes)" % (dom.raw, dom.text_backslashes))
    check(dom.plots >= 1 and dom.series == 9 and dom.legend_boxes == 9,
          "the plot of the torques and the joints' force components with their toggles "
          "(%d plots, %d series)" % (dom.plots, dom.series))
    check(dom.anim == 1 and dom.anim_sticks >= 3 and dom.play and dom.slider,
          "the animation with its sticks, play button and time slider")
    # the torques (N*m) and the joints' forces (N) on two plots
    check(sorted(f["unit"] for f in dom.figures) == ["N", "N*m"],
          "the torques and the joint forces on plots of their own (%s)" % [f["unit"] for f in dom.figures])
    check_plots(dom, page_data(index), "sit-to-stand", "sit_to_stand")

    # the controls, worked once in the page (#exercise): series toggles, the value readout,
    # the time slider, play and pause
    start = worked.stdout.find('<pre id="alembert-exercise">')
    steps = worked.stdout[start:worked.stdout.find("</pre>", start)].split(">", 1)[-1].splitlines() if start >= 0 else []
    check_exercise(steps, EXERCISE + EXERCISE_TEACHING, "sit-to-stand")
    # the seed's count: 3 bodies x 3 equations in the plane, in 6 joint-force components and the
    # 3 torques, beside the road-map's 3 rows for the torques; every row's units consistent
    # (torques in N*m, joint forces in N)
    bf = page_data(index)["brute_force"]
    check((bf["equations"], bf["unknowns"], bf["reactions"], bf["rows"]) == (9, 9, 6, 3) and bf["planar"]
          and "9 equations" in bf["text"] and "9 unknowns" in bf["text"] and "3 rows for T_A, T_B, T_C" in bf["text"],
          "sit-to-stand: brute force takes 9 equations in 9 unknowns beside 3 road-map rows (%s)" % bf["text"])
    units = [ok for k, ok in dom.checks if k == "units"]
    check(len(units) == 9 and all(units), "sit-to-stand: every row's units consistent in the checks (%s)" % units)
    check('class="unit-check consistent"' in dump.stdout and "units: N\u00b7m \u2713" in dump.stdout,
          "sit-to-stand: each row marked with its units")

    check(os.path.isfile(shot) and os.path.getsize(shot) > 20000, "a screenshot was taken")
    if os.path.isfile(shot):
        w, h, gray = png_pixels(shot)
        mean = sum(gray) / len(gray)
        var = sum((g - mean) ** 2 for g in gray) / len(gray)
        dark = sum(1 for g in gray if g < 128) / len(gray)
        check(w == 1280 and var > 100 and 0.002 < dark < 0.5,
              "the screenshot is not blank (%dx%d, variance %.0f, %.1f%% dark)" % (w, h, var, 100 * dark))
    print("report: %s" % index)


if __name__ == "__main__":
    sys.exit(main())
