#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The sit-to-stand report as a user sees it: headless Chromium opens DIR/index.html, its
scripts run, and the DOM after them is checked (no errors, one free-body diagram per road-map
row with one arrow group per load on S, every equation typeset by KaTeX, plots, animation),
then a screenshot is taken and checked not to be blank.

usage: browser_test.py ALEMBERT_CLI SOURCE_DIR WORK_DIR     (exit 77: Chromium missing)"""
import html.parser
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

failures = []


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
        self.stack = []          # open elements: (tag, classes)
        self.status = None
        self.errors = ""
        self.fbds = []           # per svg.fbd: [data-loads, arrow groups counted]
        self.equations = 0       # .equation boxes
        self.katex = 0           # .katex inside them
        self.raw = 0             # .tex-raw boxes (TeX left untypeset)
        self.text_backslashes = 0  # backslashes in visible text (TeX not rendered)
        self.plots = 0
        self.series = 0
        self.legend_boxes = 0
        self.anim = 0
        self.anim_sticks = 0
        self.play = False
        self.slider = False
        self.in_errors = False

    def classes(self, attrs):
        return set((dict(attrs).get("class") or "").split())

    def inside(self, tag=None, cls=None):
        return any((tag is None or t == tag) and (cls is None or cls in c) for t, c in self.stack)

    def handle_starttag(self, tag, attrs):
        a, c = dict(attrs), self.classes(attrs)
        if a.get("id") == "alembert-status":
            self.status = a.get("data-status")
        if a.get("id") == "alembert-errors":
            self.in_errors = True
        if tag == "svg" and "fbd" in c:
            self.fbds.append([int(a.get("data-loads", "-1")), 0])
        if tag == "g" and "load" in c and self.inside("svg", "fbd"):
            self.fbds[-1][1] += 1
        if "equation" in c:
            self.equations += 1
        if "katex" in c and self.inside(cls="equation"):
            self.katex += 1
        if "tex-raw" in c:
            self.raw += 1
        if tag == "svg" and "plot-svg" in c:
            self.plots += 1
        if tag == "polyline" and "series" in c:
            self.series += 1
        if tag == "input" and a.get("type") == "checkbox" and a.get("data-series"):
            self.legend_boxes += 1
        if tag == "svg" and "anim" in c:
            self.anim += 1
        if tag == "line" and "stick" in c and self.inside("svg", "anim"):
            self.anim_sticks += 1
        if a.get("id") == "play":
            self.play = True
        if a.get("id") == "time-slider":
            self.slider = True
        if tag not in ("input", "br", "img", "meta", "link", "line", "circle", "path", "polyline"):
            self.stack.append((tag, c))

    def handle_endtag(self, tag):
        for i in range(len(self.stack) - 1, -1, -1):
            if self.stack[i][0] == tag:
                del self.stack[i:]
                break
        if tag == "pre":
            self.in_errors = False

    def handle_data(self, data):
        if self.in_errors:
            self.errors += data
        hidden = self.inside("annotation") or self.inside("script") or self.inside("style")
        if not hidden and "\\" in data:
            self.text_backslashes += 1


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


def spatial(cli, source, work, browser):
    """A spatial model: drawn in a projection the user turns, every equation typeset."""
    out = os.path.join(work, "spatial")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    script = os.path.join(source, "tests", "report", "spatial_double_pendulum.alb")
    r = subprocess.run([cli, "run", "-q", script, "--out", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "the spatial script writes its report (stderr: %s)" % r.stderr.strip())
    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    try:
        dump = subprocess.run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
                               "--virtual-time-budget=3000", "--dump-dom",
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


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    cli, source, work = sys.argv[1:]
    browser = chromium()
    if not browser:
        print("report.browser: skipped: Chromium is not installed (Debian: apt-get install chromium; "
              "scripts/install_deps.sh installs it)")
        return 77
    out = os.path.join(work, "sit_to_stand")
    shutil.rmtree(out, ignore_errors=True)
    model = os.path.join(source, "examples", "sit_to_stand", "model.alb")
    r = subprocess.run([cli, "report", model, "--out", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "alembert report exits 0 (stderr: %s)" % r.stderr.strip())
    index = os.path.join(out, "index.html")
    check(os.path.isfile(index), "index.html written")
    if failures:
        return 1
    with open(index, encoding="utf-8") as f:
        page = f.read()
    # same script, same bytes: nothing in the page depends on the clock or the directory
    again = os.path.join(work, "sit_to_stand_again")
    shutil.rmtree(again, ignore_errors=True)
    subprocess.run([cli, "report", model, "--out", again], capture_output=True, text=True, timeout=120)
    with open(os.path.join(again, "index.html"), encoding="utf-8") as f:
        check(f.read() == page, "a second run writes the same bytes")
    leftovers = [n for d, _, files in os.walk(out) for n in files if n.endswith(".tmp")]
    check(not leftovers, "no temporaries left (%s)" % leftovers)
    remote = [w for w in ('src="http', "src='http", 'href="http', "url(http", "url('http", 'url("http', "@import")
              if w in page]
    check(not remote, "the page loads nothing from the network (%s)" % remote)

    profile = tempfile.mkdtemp(prefix="alembert-chromium-")
    flags = [browser, "--headless", "--disable-gpu", "--no-sandbox", "--user-data-dir=" + profile,
             "--hide-scrollbars", "--enable-logging=stderr", "--v=0", "--virtual-time-budget=3000"]
    url = "file://" + os.path.abspath(index)
    try:
        dump = subprocess.run(flags + ["--dump-dom", url], capture_output=True, text=True, timeout=90)
        shot = os.path.join(out, "screenshot.png")
        subprocess.run(flags + ["--window-size=1280,2200", "--screenshot=" + shot, url],
                       capture_output=True, text=True, timeout=90)
        worked = subprocess.run(flags + ["--dump-dom", url + "#exercise"], capture_output=True, text=True, timeout=90)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    console = [l for l in dump.stderr.splitlines() if "CONSOLE" in l]
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
    check(dom.katex == dom.equations, "every equation typeset by KaTeX (%d of %d)" % (dom.katex, dom.equations))
    check(dom.raw == 0 and dom.text_backslashes == 0,
          "no raw TeX left (%d raw boxes, %d texts with backslashes)" % (dom.raw, dom.text_backslashes))
    check(dom.plots >= 1 and dom.series == 9 and dom.legend_boxes == 9,
          "the plot of the torques and the joints' force components with their toggles "
          "(%d plots, %d series)" % (dom.plots, dom.series))
    check(dom.anim == 1 and dom.anim_sticks >= 3 and dom.play and dom.slider,
          "the animation with its sticks, play button and time slider")

    # the controls, worked once in the page (#exercise): series toggles, the value readout,
    # the time slider, play and pause
    start = worked.stdout.find('<pre id="alembert-exercise">')
    steps = worked.stdout[start:worked.stdout.find("</pre>", start)].split(">", 1)[-1].splitlines() if start >= 0 else []
    check(len(steps) == 6, "the controls were exercised (%d steps)" % len(steps))
    for step in steps:
        check(step.startswith("ok "), "control: " + step)

    check(os.path.isfile(shot) and os.path.getsize(shot) > 20000, "a screenshot was taken")
    if os.path.isfile(shot):
        w, h, gray = png_pixels(shot)
        mean = sum(gray) / len(gray)
        var = sum((g - mean) ** 2 for g in gray) / len(gray)
        dark = sum(1 for g in gray if g < 128) / len(gray)
        check(w == 1280 and var > 100 and 0.002 < dark < 0.5,
              "the screenshot is not blank (%dx%d, variance %.0f, %.1f%% dark)" % (w, h, var, 100 * dark))
    spatial(cli, source, work, browser)
    print("report: %s" % index)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
