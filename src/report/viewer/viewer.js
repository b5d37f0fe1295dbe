// SPDX-License-Identifier: MIT
// Alembert's report viewer: draws the data of #alembert-data (written by write_report) as the
// model, the road-map with its free-body diagrams, KaTeX equations, plots and an animation.
// Static code shipped once with Alembert; a report is its data plus this file.
(function () {
  "use strict";
  var SVG = "http://www.w3.org/2000/svg";
  var errors = document.getElementById("alembert-errors");
  var status = document.getElementById("alembert-status");
  var failed = false;
  function fail(message) {
    failed = true;
    errors.textContent += message + "\n";
  }
  window.addEventListener("error", function (e) { fail("script error: " + e.message); });
  // console errors and warnings (KaTeX warns there) are shown on the page, where tests read them
  ["error", "warn"].forEach(function (level) {
    var original = console[level];
    console[level] = function () {
      fail("console." + level + ": " + Array.prototype.slice.call(arguments).join(" "));
      original.apply(console, arguments);
    };
  });

  // ---- small DOM helpers ------------------------------------------------------------------
  function el(tag, attrs, parent, text) {
    var n = document.createElement(tag);
    for (var k in attrs || {}) n.setAttribute(k, attrs[k]);
    if (text !== undefined) n.textContent = text;
    if (parent) parent.appendChild(n);
    return n;
  }
  function svg(tag, attrs, parent, text) {
    var n = document.createElementNS(SVG, tag);
    for (var k in attrs || {}) n.setAttribute(k, attrs[k]);
    if (text !== undefined) n.textContent = text;
    if (parent) parent.appendChild(n);
    return n;
  }
  function fmt(v) {
    if (v === null || v === undefined) return "";
    if (v === 0) return "0";
    var a = Math.abs(v);
    return (a >= 1e5 || a < 1e-3) ? v.toExponential(3) : String(Number(v.toPrecision(4)));
  }
  function table(parent, head, rows, cls) {
    var t = el("table", {"class": cls || "data"}, parent);
    var tr = el("tr", {}, el("thead", {}, t));
    head.forEach(function (h) { el("th", {}, tr, h); });
    var body = el("tbody", {}, t);
    rows.forEach(function (r) {
      var row = el("tr", {}, body);
      r.forEach(function (c) { el("td", {}, row, c); });
    });
    return t;
  }

  // ---- equations --------------------------------------------------------------------------
  // An equation on lines of its own (display) is typeset in KaTeX's text style, which breaks a
  // line after a + - or = at the formula's outer level wherever the column is full (the report
  // writes sums in plain parentheses, which do not stop that): no equation is wider than its
  // column on the screen or in print. Continuation lines are indented.
  function tex(parent, source, display) {
    var box = el(display ? "div" : "span", {"class": display ? "equation broken" : "equation"}, parent);
    if (window.katex) {
      try {
        window.katex.render(source, box, {displayMode: false, throwOnError: true, maxExpand: 1000000});
        return box;
      } catch (e) {
        fail("KaTeX could not typeset: " + source.slice(0, 80) + "...: " + e.message);
      }
    }
    box.className = "equation tex-raw";
    box.textContent = source;
    return box;
  }

  // equations longer than this (TeX characters) are folded, and typeset when opened
  var LONG_TEX = 12000;

  // a <details> whose content fill() writes the first time it is opened
  function folded(parent, cls, summary, fill) {
    var d = el("details", cls ? {"class": cls} : {}, parent);
    el("summary", {}, d, summary);
    var done = false;
    d.addEventListener("toggle", function () {
      if (d.open && !done) { done = true; fill(d); }
    });
    return d;
  }
  // the road-map's first rows, up to EAGER_TEX characters of their equations' TeX, are drawn
  // on opening; the others (diagram, equation, derivation) when scrolled near: laying out a
  // large model's every row at once (the arm's 42 rows, 8 MB of DOM) kept its page from
  // showing for seconds. Printing, the #exercise mode and a browser without
  // IntersectionObserver draw them all; an address ending in #row-N draws row N on opening.
  var EAGER_TEX = 40000, pendingRows = [], rowObserver = null;
  function drawPendingRows() {
    var rows = pendingRows;
    pendingRows = [];
    rows.forEach(function (draw) { draw(); });
  }
  // printing draws the rows not yet drawn and opens the folded equations, so that the paper
  // holds every one
  window.addEventListener("beforeprint", function () {
    drawPendingRows();
    Array.prototype.forEach.call(document.querySelectorAll("details.equation-folded"), function (d) {
      if (!d.open) { d.open = true; d.dispatchEvent(new Event("toggle")); }
    });
  });

  // ---- geometry: the plane of planar models, an oblique view of spatial ones ----------------
  // "up" (against gravity: geo.up) is up the page. Planar models: their plane, up the page.
  // Spatial models: in axes (h, up, h x up), h the N axis least along up made square to it,
  // turned about up by view.turn, then tilted by view.tilt (radians)
  var view = {turn: 0.6, tilt: 0.35};
  function dot3(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function upOf(geo, planar) {
    var u = (geo.up || [0, 1, 0]).slice(0, 3);
    if (planar) u[2] = 0;
    var n = Math.hypot(u[0], u[1], u[2]);
    return n > 1e-12 ? [u[0] / n, u[1] / n, u[2] / n] : [0, 1, 0];
  }
  function projector(geo) {
    var u = upOf(geo, geo.planar);
    if (geo.planar) return function (p) { return [u[1] * p[0] - u[0] * p[1], -(u[0] * p[0] + u[1] * p[1])]; };
    var axes = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    axes.sort(function (a, b) { return Math.abs(dot3(a, u)) - Math.abs(dot3(b, u)); });
    var a = axes[0], k = dot3(a, u), h = [a[0] - k * u[0], a[1] - k * u[1], a[2] - k * u[2]];
    var hn = Math.hypot(h[0], h[1], h[2]);
    h = [h[0] / hn, h[1] / hn, h[2] / hn];
    var w = [h[1] * u[2] - h[2] * u[1], h[2] * u[0] - h[0] * u[2], h[0] * u[1] - h[1] * u[0]];  // h x up
    var ct = Math.cos(view.turn), st = Math.sin(view.turn), ce = Math.cos(view.tilt), se = Math.sin(view.tilt);
    return function (p) {
      var X = dot3(p, h), Y = dot3(p, u), Z = dot3(p, w);
      var x = ct * X + st * Z, z = -st * X + ct * Z;
      return [x, -(ce * Y + se * z)];
    };
  }
  function bounds(points, project) {
    var b = [Infinity, Infinity, -Infinity, -Infinity];
    points.forEach(function (p) {
      var q = project(p);
      if (!isFinite(q[0]) || !isFinite(q[1])) return;
      b[0] = Math.min(b[0], q[0]); b[1] = Math.min(b[1], q[1]);
      b[2] = Math.max(b[2], q[0]); b[3] = Math.max(b[3], q[1]);
    });
    if (!isFinite(b[0])) b = [-1, -1, 1, 1];
    var size = Math.max(b[2] - b[0], b[3] - b[1], 1e-9);
    return {x: b[0], y: b[1], w: b[2] - b[0], h: b[3] - b[1], size: size};
  }
  function unit2(v) {
    var n = Math.hypot(v[0], v[1]);
    return n > 1e-12 ? [v[0] / n, v[1] / n] : null;
  }
  function arrow(g, from, to, cls) {
    var d = [to[0] - from[0], to[1] - from[1]], n = Math.hypot(d[0], d[1]);
    if (n < 1e-12) return;
    var u = [d[0] / n, d[1] / n], h = Math.min(0.35 * n, g.head), w = 0.45 * h;
    var b = [to[0] - u[0] * h, to[1] - u[1] * h];
    // the row's own unknown: a highlight under its arrow
    if (g.halo) svg("line", {x1: from[0], y1: from[1], x2: to[0], y2: to[1], "class": "halo"}, g);
    svg("line", {x1: from[0], y1: from[1], x2: b[0], y2: b[1], "class": "shaft " + (cls || "")}, g);
    svg("path", {d: "M" + to[0] + "," + to[1] + " L" + (b[0] - u[1] * w) + "," + (b[1] + u[0] * w) +
                 " L" + (b[0] + u[1] * w) + "," + (b[1] - u[0] * w) + " Z", "class": "head " + (cls || "")}, g);
  }

  // ---- labels placed so that none covers another, nor an arrow -----------------------------
  // Each label is tried at offsets around its anchor, nearest first, in the eight directions
  // starting with the one it prefers. The first place kept is, of the ones that meet no label
  // placed before: one that also meets no point, arrowhead, load arrow's shaft or arc and no
  // line of S, near its anchor; else one clear of the points, heads and load arrows; else one
  // clear of the points and heads. Deterministic: the same diagram places its labels alike
  // every time.
  var DIRECTIONS = [[1, 0], [1, -1], [0, -1], [-1, -1], [-1, 0], [-1, 1], [0, 1], [1, 1]];
  function overlaps(a, b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
  }
  // whether the segment a-b passes through the box {x, y, w, h} (Liang-Barsky clipping)
  function segmentMeetsBox(a, b, r) {
    var t0 = 0, t1 = 1, dx = b[0] - a[0], dy = b[1] - a[1];
    var p = [-dx, dx, -dy, dy], q = [a[0] - r.x, r.x + r.w - a[0], a[1] - r.y, r.y + r.h - a[1]];
    for (var i = 0; i < 4; ++i) {
      if (Math.abs(p[i]) < 1e-12) { if (q[i] < 0) return false; continue; }
      var t = q[i] / p[i];
      if (p[i] < 0) { if (t > t1) return false; if (t > t0) t0 = t; }
      else { if (t < t0) return false; if (t < t1) t1 = t; }
    }
    return true;
  }
  function labelPlacer(L, fontSize) {
    // obstacles: boxes (points, heads); arrows: load shafts and arcs; lines: S's sticks, angles' arcs
    var placed = [], obstacles = [], arrows = [], lines = [];
    function size(t) {
      var bb = null;
      try { bb = t.getBBox(); } catch (e) { bb = null; }
      // not laid out (a hidden box): sized from its characters
      if (!bb || !(bb.width > 0)) {
        var w = 0.6 * fontSize * t.textContent.length, h = 1.2 * fontSize;
        bb = {x: Number(t.getAttribute("x")), y: Number(t.getAttribute("y")) - 0.9 * fontSize, width: w, height: h};
      }
      return bb;
    }
    return {
      obstacle: function (x, y, w, h) { obstacles.push({x: x, y: y, w: w, h: h}); },
      // a segment a-b drawn: a load arrow's (kind "arrow") or another line's
      segment: function (a, b, kind) { (kind === "arrow" ? arrows : lines).push([a, b]); },
      boxes: placed,
      // a text at a fixed place (the u label)
      fix: function (t) {
        var bb = size(t);
        placed.push({x: bb.x, y: bb.y, w: bb.width, h: bb.height});
      },
      // moves text t near anchor, preferring direction prefer ([dx, dy], page axes)
      place: function (t, anchor, prefer) {
        t.setAttribute("x", 0);
        t.setAttribute("y", 0);
        var bb = size(t), w = bb.width, h = bb.height, ox = bb.x, oy = bb.y;
        var start = 0, best = -Infinity;
        DIRECTIONS.forEach(function (d, i) {
          var c = ((d[0] * prefer[0] + d[1] * prefer[1]) / Math.hypot(d[0], d[1])) || 0;
          if (c > best + 1e-9) { best = c; start = i; }
        });
        var pad = 0.004 * L;
        function at(ring, k) {
          var d = DIRECTIONS[(start + k) % 8], gap = ring;
          var cx = anchor[0] + d[0] * (gap + w / 2), cy = anchor[1] + d[1] * (gap + h / 2);
          return {x: cx - w / 2, y: cy - h / 2, w: w, h: h};
        }
        function crosses(b, segments) {
          for (var i = 0; i < segments.length; ++i) if (segmentMeetsBox(segments[i][0], segments[i][1], b)) return true;
          return false;
        }
        // level 3: clear of everything; 2: of labels, points, heads and load arrows; 1: of
        // labels, points and heads; 0: of labels
        function free(b, level) {
          var grown = {x: b.x - pad, y: b.y - pad, w: b.w + 2 * pad, h: b.h + 2 * pad};
          for (var i = 0; i < placed.length; ++i) if (overlaps(grown, placed[i])) return false;
          if (level >= 1) for (var j = 0; j < obstacles.length; ++j) if (overlaps(b, obstacles[j])) return false;
          if (level >= 2 && crosses(b, arrows)) return false;
          if (level >= 3 && crosses(b, lines)) return false;
          return true;
        }
        var chosen = null;
        [3, 2, 1, 0].forEach(function (level) {
          // clear of everything only near the anchor: farther, a label is better on a line of S
          for (var r = 0; !chosen && r < (level === 3 ? 8 : 40); ++r) {
            var ring = L * (0.012 + 0.03 * r);
            for (var k = 0; k < 8 && !chosen; ++k) {
              var b = at(ring, k);
              if (free(b, level)) chosen = b;
            }
          }
        });
        if (!chosen) chosen = at(L * 1.3, 0);
        t.setAttribute("x", chosen.x - ox);
        t.setAttribute("y", chosen.y - oy);
        placed.push(chosen);
      }
    };
  }

  // one free-body diagram: the model faded, S in ink, each load on S as an arrow (the row's
  // own unknown highlighted, loads its equation does not hold dashed), S's points named, a
  // planar model's angles of S marked, then a legend
  function drawDiagram(parent, data, row) {
    var geo = data.geometry, project = projector(geo), dia = row.diagram;
    var at = {};
    geo.points.forEach(function (p) { at[p.name] = p.at; });
    // the model's points, and the row's about point where the planner located it off them (an
    // instantaneous centre IC_q): that one is drawn in the diagrams of the rows about it only
    var shown = geo.points.filter(function (p) { return !p.about_only || p.name === dia.about; });
    var box = bounds(shown.map(function (p) { return p.at; }), project);
    var L = box.size, pad = 0.45 * L, fontSize = 0.055 * L;
    var figure = el("div", {"class": "fbd-figure"}, parent);
    var view0 = [box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad];
    // a load at a point the configuration does not place is not drawn (the legend says so)
    var drawnLoads = dia.loads.filter(function (l) { return l.placed !== false; });
    var s = svg("svg", {"class": "fbd", viewBox: view0.join(" "), width: 340, height: 340 * view0[3] / view0[2],
                        "data-variable": row.variable, "data-loads": drawnLoads.length}, figure);
    var g = svg("g", {"class": "scene", "font-size": fontSize}, s);
    g.head = 0.06 * L;
    // the labels are drawn over everything else, each with a halo of the background
    var labelLayer = svg("g", {"class": "labels"}, g);
    var labels = labelPlacer(L, fontSize), pending = [];  // [text, anchor, preferred direction]
    function label(text, anchor, prefer, cls, attrs) {
      var t = svg("text", {x: anchor[0], y: anchor[1], "class": "label" + (cls ? " " + cls : "")}, labelLayer, text);
      for (var k in attrs || {}) t.setAttribute(k, attrs[k]);
      pending.push([t, anchor, prefer]);
      return t;
    }
    var inS = {};
    dia.system.forEach(function (b) { inS[b] = true; });
    geo.segments.forEach(function (seg) {
      var a = project(at[seg.from]), b = project(at[seg.to]);
      svg("line", {x1: a[0], y1: a[1], x2: b[0], y2: b[1],
                   "class": inS[seg.body] ? "stick in-system" : "stick faded"}, g);
    });
    shown.forEach(function (p) {
      var q = project(p.at);
      svg("circle", {cx: q[0], cy: q[1], r: 0.012 * L, "class": "point", "data-point": p.name}, g);
      labels.obstacle(q[0] - 0.015 * L, q[1] - 0.015 * L, 0.03 * L, 0.03 * L);
    });
    // the row's own unknown: a load measure, or the acceleration of a coordinate
    var ownName = row.variable.replace(/'+$/, "");
    // the angles of S's rotations (planar models): from the parent's axis to the body's
    var ownAngle = false;
    if (geo.planar) (geo.angles || []).forEach(function (an) {
      if (!inS[an.body] || !at[an.at]) return;
      var p = project(at[an.at]), f = unit2(project(an.from)), t2 = unit2(project(an.to));
      if (!f || !t2) return;
      var own = an.name === ownName;
      ownAngle = ownAngle || own;
      var ag = svg("g", {"class": "angle" + (own ? " own" : ""), "data-angle": an.name, "data-at": an.at}, g);
      var r = 0.075 * L;
      svg("line", {x1: p[0], y1: p[1], x2: p[0] + 0.15 * L * f[0], y2: p[1] + 0.15 * L * f[1], "class": "reference"}, ag);
      // a turn about +z seen on the page: which way from the parent's axis
      var f90 = unit2(project([-an.from[1], an.from[0], 0])), sense = f90 ? (f[0] * f90[1] - f[1] * f90[0] >= 0 ? 1 : -1) : 1;
      var a0 = Math.atan2(f[1], f[0]), sweep = Math.atan2(Math.sin(an.value), Math.cos(an.value)) * sense, pts = [];
      for (var k = 0; k <= 24; ++k) {
        var th = a0 + sweep * k / 24;
        pts.push([p[0] + r * Math.cos(th), p[1] + r * Math.sin(th)]);
      }
      svg("polyline", {points: pts.map(function (q) { return q.join(","); }).join(" "), fill: "none", "class": "arc"}, ag);
      var mid = a0 + sweep / 2, m = [p[0] + r * Math.cos(mid), p[1] + r * Math.sin(mid)];
      label(an.name, m, [Math.cos(mid), Math.sin(mid)], "angle-name" + (own ? " own" : ""), {"data-angle": an.name});
    });
    var arrowLength = 0.28 * L;
    drawnLoads.forEach(function (load) {
      var role = load.role || (load.unknown ? "held" : "known");
      var lg = svg("g", {"class": "load " + load.kind + (load.unknown ? " unknown" : " known") + " role-" + role,
                         "data-label": load.label, "data-on": load.on, "data-at": load.at, "data-role": role}, g);
      lg.head = g.head;
      lg.halo = role === "own";
      var p = project(at[load.at] || [0, 0, 0]);
      var anchor = [p[0], p[1]], prefer = [1, -1];
      function head(q) { labels.obstacle(q[0] - 0.4 * g.head, q[1] - 0.4 * g.head, 0.8 * g.head, 0.8 * g.head); }
      if (load.kind === "torque" && !geo.planar) {
        // in space: a double-headed arrow along the torque
        var tu = unit2(project(load.sense || (load.vector.length ? load.vector : [0, 0, 1])));
        if (tu) {
          var tip = [p[0] + tu[0] * arrowLength, p[1] + tu[1] * arrowLength];
          arrow(lg, p, tip);
          lg.halo = false;
          arrow(lg, p, [tip[0] - tu[0] * g.head, tip[1] - tu[1] * g.head]);
          head(tip);
          anchor = tip; prefer = tu;
        }
      } else if (load.kind === "torque") {
        // an arc about the point, counterclockwise in the plane for a +z torque
        var z = load.sense ? load.sense[2] : load.vector.length ? load.vector[2] : 1, r = 0.11 * L, sense = z >= 0 ? 1 : -1;
        var th0 = sense > 0 ? -2.1 : 2.6, th1 = sense > 0 ? 2.6 : -2.1, pts = [];
        for (var k = 0; k <= 24; ++k) {
          var th = th0 + (th1 - th0) * k / 24;
          pts.push([p[0] + r * Math.cos(th), p[1] - r * Math.sin(th)]);
        }
        var line = pts.map(function (q) { return q.join(","); }).join(" ");
        if (lg.halo) svg("polyline", {points: line, "class": "halo", fill: "none"}, lg);
        svg("polyline", {points: line, "class": "shaft arc", fill: "none"}, lg);
        var end1 = pts[24], tan = [-Math.sin(th1) * sense, -Math.cos(th1) * sense];
        lg.halo = false;
        arrow(lg, [end1[0] - tan[0] * 0.9 * g.head, end1[1] - tan[1] * 0.9 * g.head], end1);
        head(end1);
        anchor = [p[0] + 0.72 * r, p[1] - 0.72 * r];
      } else if (load.kind === "joint") {
        // a joint's force: unknown components along Nx and Ny
        (geo.planar ? [[1, 0, 0], [0, 1, 0]] : [[1, 0, 0], [0, 1, 0], [0, 0, 1]]).forEach(function (axis) {
          var a = project(axis), q = [p[0] + 0.6 * arrowLength * a[0], p[1] + 0.6 * arrowLength * a[1]];
          arrow(lg, p, q);
          head(q);
        });
        anchor = [p[0] + 0.3 * arrowLength, p[1] + 0.03 * L];
        prefer = [1, 1];
      } else {
        // a known load zero here (a damper at rest), or whose value this configuration does
        // not give, along its positive sense, labelled zero (or with no value)
        var u = (load.vector.length ? unit2(project(load.vector)) : null) || (load.sense && unit2(project(load.sense)));
        if (u) {
          var tail = load.kind === "gravity" ? p : [p[0] - u[0] * arrowLength, p[1] - u[1] * arrowLength];
          var tipp = load.kind === "gravity" ? [p[0] + u[0] * arrowLength, p[1] + u[1] * arrowLength] : p;
          arrow(lg, tail, tipp);
          head(tipp);
          anchor = load.kind === "gravity" ? [p[0] + 0.6 * u[0] * arrowLength, p[1] + 0.6 * u[1] * arrowLength] : tail;
          prefer = load.kind === "gravity" ? [1, 0] : [-u[0], -u[1]];
        } else {
          svg("circle", {cx: p[0], cy: p[1], r: 0.04 * L, "class": "shaft", fill: "none"}, lg);
        }
      }
      label(load.label + (load.sense && load.given !== false ? " = 0" : ""), anchor, prefer, "load-label " + load.kind + (load.unknown ? " unknown" : " known") + " role-" + role,
            {"data-label": load.label, "data-at": load.at});
    });
    // the about point O
    if (dia.about && at[dia.about]) {
      var o = project(at[dia.about]);
      var og = svg("g", {"class": "about", "data-at": dia.about}, g);
      svg("circle", {cx: o[0], cy: o[1], r: 0.03 * L, fill: "none"}, og);
      svg("line", {x1: o[0] - 0.045 * L, y1: o[1], x2: o[0] + 0.045 * L, y2: o[1]}, og);
      svg("line", {x1: o[0], y1: o[1] - 0.045 * L, x2: o[0], y2: o[1] + 0.045 * L}, og);
      label("O = " + dia.about, o, [-1, 1], "point-name about-name", {"data-point": dia.about});
    }
    // S's points named (O's already is)
    (dia.points || []).forEach(function (name) {
      if (name === dia.about || !at[name]) return;
      label(name, project(at[name]), [-1, 1], "point-name", {"data-point": name});
    });
    // the direction u, below all that is drawn, wholly inside the picture, its label beside it
    var drawn;
    pending.forEach(function (p) { p[0].style.display = "none"; });
    try { drawn = g.getBBox(); } catch (e) { drawn = null; }
    pending.forEach(function (p) { p[0].style.display = ""; });
    if (!drawn || !(drawn.width > 0)) drawn = {x: box.x - 0.3 * L, y: box.y - 0.3 * L, width: box.w + 0.6 * L, height: box.h + 0.6 * L};
    var dir = dia.direction;
    var dg = svg("g", {"class": "direction"}, g);
    dg.head = g.head;
    var du = unit2(project(dir));
    var inPlane = du && (!geo.planar || Math.hypot(dir[0], dir[1]) > 0.2);
    var ulen = 0.22 * L, corner = [Math.min(drawn.x, box.x - 0.3 * L), drawn.y + drawn.height + 0.08 * L];
    var right, middle;
    if (inPlane) {
      var ax = Math.abs(du[0]) * ulen, ay = Math.abs(du[1]) * ulen, w = 0.5 * g.head;
      var from = [corner[0] + w + (du[0] < 0 ? ax : 0), corner[1] + w + (du[1] < 0 ? ay : 0)];
      arrow(dg, from, [from[0] + du[0] * ulen, from[1] + du[1] * ulen]);
      right = corner[0] + ax + 2 * w;
      middle = corner[1] + w + ay / 2;
      labels.obstacle(corner[0], corner[1], ax + 2 * w, ay + 2 * w);
    } else {
      var c = [corner[0] + 0.04 * L, corner[1] + 0.04 * L];
      svg("circle", {cx: c[0], cy: c[1], r: 0.04 * L, fill: "none"}, dg);
      svg("circle", {cx: c[0], cy: c[1], r: 0.01 * L, "class": "dot"}, dg);
      right = c[0] + 0.04 * L;
      middle = c[1];
      labels.obstacle(corner[0], corner[1], 0.08 * L, 0.08 * L);
    }
    var ut = svg("text", {x: right + 0.04 * L, y: middle + 0.35 * fontSize, "class": "label"}, dg,
                 "\u00fb = " + row.direction + (inPlane ? "" : " (out of the page)"));
    labels.fix(ut);
    // the labels, in the order they matter: the loads' (the row's own first), O's, the angles', the points'
    function rank(t) {
      var cls = t.getAttribute("class");
      return /role-own/.test(cls) ? 0 : /load-label/.test(cls) ? 1 : /about-name/.test(cls) ? 2 :
             /angle-name/.test(cls) ? 3 : 4;
    }
    // what the labels keep off: the load arrows' shafts and arcs, S's sticks and the angles' arcs
    function polyline(n) {
      return n.getAttribute("points").split(" ").map(function (q) { return q.split(",").map(Number); });
    }
    function segmentsOf(selector, kind) {
      g.querySelectorAll(selector).forEach(function (n) {
        if (n.tagName === "line") {
          labels.segment([Number(n.getAttribute("x1")), Number(n.getAttribute("y1"))],
                         [Number(n.getAttribute("x2")), Number(n.getAttribute("y2"))], kind);
        } else {
          var pts = polyline(n);
          for (var k = 1; k < pts.length; ++k) labels.segment(pts[k - 1], pts[k], kind);
        }
      });
    }
    segmentsOf("g.load line.shaft, g.load polyline.shaft", "arrow");
    segmentsOf("line.stick.in-system, g.angle polyline.arc", "line");
    pending.forEach(function (p, i) { p.push(rank(p[0]), i); });
    pending.sort(function (a, b) { return a[3] - b[3] || a[4] - b[4]; });
    pending.forEach(function (p) { labels.place(p[0], p[1], p[2]); });
    g.appendChild(labelLayer);
    // the picture holds everything drawn, with a margin
    var all;
    try { all = g.getBBox(); } catch (e) { all = null; }
    if (all && all.width > 0) {
      var m = 0.04 * L, v = [all.x - m, all.y - m, all.width + 2 * m, all.height + 2 * m];
      s.setAttribute("viewBox", v.join(" "));
      s.setAttribute("height", 340 * v[3] / v[2]);
    }
    legend(figure, row, dia, ownAngle);
    return s;
  }

  // what the diagram's styles mean, for the styles it uses
  function legend(parent, row, dia, ownAngle) {
    var roles = {};
    dia.loads.forEach(function (l) { roles[l.role] = true; });
    var ul = el("ul", {"class": "fbd-legend"}, parent);
    if (roles.own || ownAngle) {
      var li = el("li", {"class": "own"}, ul);
      el("span", {"class": "swatch own"}, li);
      el("span", {}, li, "solved for in this row: " + row.variable);
    }
    if (roles.held) {
      var lh = el("li", {"class": "held"}, ul);
      el("span", {"class": "swatch held"}, lh);
      el("span", {}, lh, "unknown the equation also holds: " + row.additional_unknowns.join(", "));
    }
    var zero = dia.loads.filter(function (l) { return l.sense && l.given !== false && l.placed !== false; });
    if (zero.length) {
      var lz = el("li", {"class": "zero"}, ul);
      el("span", {}, lz, "zero at this configuration, drawn in its positive sense: " +
         zero.map(function (l) { return l.label; }).join(", "));
    }
    var unknownHere = dia.loads.filter(function (l) { return l.given === false && l.placed !== false; });
    if (unknownHere.length) {
      var lg = el("li", {"class": "not-given"}, ul);
      el("span", {}, lg, "value not given at this configuration, drawn in its positive sense: " +
         unknownHere.map(function (l) { return l.label; }).join(", "));
    }
    var unplaced = dia.loads.filter(function (l) { return l.placed === false; });
    if (unplaced.length) {
      var lu = el("li", {"class": "unplaced"}, ul);
      el("span", {}, lu, "not drawn, acting where this configuration does not say: " +
         unplaced.map(function (l) { return l.label + " at " + l.at; }).join(", "));
    }
    if (roles.drops) {
      var ld = el("li", {"class": "drops"}, ul);
      el("span", {"class": "swatch drops"}, ld);
      el("span", {}, ld, "not in E_" + row.variable + (row.motion === "rotate" ? ": through O, or its moment about O square to \u00fb" :
                                                     ": square to \u00fb"));
    }
  }

  // ---- sections ---------------------------------------------------------------------------
  function model(main, data) {
    var m = data.model, sec = el("section", {id: "model"}, main);
    el("h2", {}, sec, "Model");
    el("p", {}, sec, "Frames: " + m.frames.join(", ") + ". Coordinates: " +
       m.coordinates.map(function (c) { return c.name + (c.unit ? " [" + c.unit + "]" : ""); }).join(", ") + ".");
    table(sec, ["body", "kind", "mass centre", "mass"], m.bodies.map(function (b) {
      return [b.name, b.kind, b.cm, b.mass]; }));
    table(sec, ["point", "on", "located from", "by"], m.points.map(function (p) {
      return [p.name, p.on, p.from, p.position]; }));
    table(sec, ["load", "kind", "at", "on", "from", "vector"], m.loads.map(function (l) {
      return [l.label, l.kind, l.at, l.on, l.from, l.vector]; }));
    table(sec, ["constant", "value", "unit"], m.constants.map(function (c) {
      return [c.name, c.value === null ? "" : fmt(c.value), c.unit]; }));
    if (m.unknowns.length)
      table(sec, ["unknown", "unit"], m.unknowns.map(function (u) { return [u.name, u.unit]; }));
  }

  // the drawn free-body diagrams, [box, row]; a spatial model's turn when dragged
  var diagrams = [];
  function redrawDiagrams(data) {
    diagrams.forEach(function (d) {
      var old = d[0].querySelector(".fbd-figure");
      if (old) d[0].removeChild(old);
      drawDiagram(d[0], data, d[1]);
    });
    ["turn", "tilt"].forEach(function (c) {
      var input = document.getElementById("view-" + c);
      if (input) input.value = view[c];
    });
  }
  function turnable(data) {
    if (data.geometry.planar) return;
    var drag = null;
    document.addEventListener("mousedown", function (e) {
      if (e.target.closest && e.target.closest("svg.fbd")) { drag = [e.clientX, e.clientY]; e.preventDefault(); }
    });
    window.addEventListener("mouseup", function () { drag = null; });
    window.addEventListener("mousemove", function (e) {
      if (!drag) return;
      view.turn -= 0.01 * (e.clientX - drag[0]);
      view.tilt = Math.max(-1.5, Math.min(1.5, view.tilt + 0.01 * (e.clientY - drag[1])));
      drag = [e.clientX, e.clientY];
      redrawDiagrams(data);
    });
  }

  // ---- checks: energy, constraint drift, methods compared ---------------------------------
  function checks(main, data) {
    if (!data.checks || !data.checks.length) return;
    var sec = el("section", {id: "checks"}, main);
    el("h2", {}, sec, "Checks");
    var t = table(sec, ["check", "of", "from", "measure", "verdict"], [], "data checks");
    var body = t.querySelector("tbody");
    data.checks.forEach(function (c) {
      var unchecked = c.checked === false;
      var tr = el("tr", {"class": unchecked ? "unchecked" : c.passed ? "passed" : "failed", "data-kind": c.kind}, body);
      el("td", {}, tr, c.kind);
      el("td", {}, tr, c.name);
      el("td", {}, tr, c.source);
      el("td", {}, tr, c.measure ? c.measure : fmt(c.value) + (c.unit ? " " + c.unit : ""));
      el("td", {title: c.summary}, tr, (unchecked ? "\u2013 " : c.passed ? "\u2713 " : "\u2717 ") + c.summary);
    });
  }

  function roadmap(main, data) {
    var sec = el("section", {id: "roadmap"}, main);
    el("h2", {}, sec, "MG road-map");
    el("p", {"class": "note", id: "configuration"}, sec, "Free-body diagrams at " + data.configuration.map(function (c) {
      return c.name + " = " + fmt(c.shown) + (c.unit ? " " + c.unit : ""); }).join(", ") +
      ((data.configuration_data || []).length ? ", with " + data.configuration_data.map(function (c) {
        return c.name + " = " + fmt(c.shown) + (c.unit ? " " + c.unit : ""); }).join(", ") : "") +
      (data.configuration_source ? " (" + data.configuration_source + ")" : "") +
      ". Unknown loads in red, known in blue, gravity in green; each equation is E = applied \u2212 inertial = 0, " +
      "shown solved for the row's unknown where it holds it linearly with a constant coefficient.");
    bruteForce(sec, data);
    var head = ["variable", "translate/rotate", "direction", "system S", "FBD of S", "about point", "additional unknowns"];
    var eager = window.location.hash === "#exercise" || !("IntersectionObserver" in window);
    var texTotal = 0;
    data.roadmap.forEach(function (row) { texTotal += row.equation.length; });
    if (!eager && texTotal > EAGER_TEX)
      rowObserver = new IntersectionObserver(function (entries) {
        entries.forEach(function (e) {
          if (e.isIntersecting) e.target.drawRow();
        });
      }, {rootMargin: "100% 0px"});
    var texDrawn = 0;
    data.roadmap.forEach(function (row, i) {
      var card = el("div", {"class": "row", id: "row-" + (i + 1)}, sec);
      var cells = [row.variable, row.motion, row.direction || "-", row.system.length ? "{" + row.system.join(", ") + "}" : "-",
                   row.fbd.join("; ") || "-", row.about || "-",
                   row.additional_unknowns.length ? row.additional_unknowns.join(", ") : "none"];
      table(card, head, [cells], "data roadmap-row");
      // (the row the address names, #row-N, is drawn at once: the page opens there)
      if (!rowObserver || texDrawn < EAGER_TEX || window.location.hash === "#row-" + (i + 1)) {
        texDrawn += row.equation.length;
        drawRow(card, data, row);
        return;
      }
      var wait = el("p", {"class": "note row-waiting"}, card, "E_" + row.variable + ": drawn when scrolled to");
      card.setAttribute("data-pending", "");
      card.drawRow = function () {
        if (!card.hasAttribute("data-pending")) return;
        card.removeAttribute("data-pending");
        card.removeChild(wait);
        rowObserver.unobserve(card);
        drawRow(card, data, row);
      };
      pendingRows.push(card.drawRow);
      rowObserver.observe(card);
    });
  }

  // a row's free-body diagram, its equation and its derivation, under its table
  function drawRow(card, data, row) {
    var body = el("div", {"class": "row-body"}, card);
    var pic = el("div", {"class": "fbd-box"}, body);
    if (row.diagram) { drawDiagram(pic, data, row); diagrams.push([pic, row]); }
    else el("p", {"class": "note"}, pic, "constraint " + row.constraint + ": no free-body diagram");
    var eq = el("div", {"class": "eq-box"}, body);
    el("div", {"class": "eq-name"}, eq, "E_" + row.variable + ":");
    if (row.equation.length <= LONG_TEX) {
      tex(eq, row.equation, true);
    } else {
      // a long equation is typeset when asked for: typesetting every one of a large model's
      // rows on opening made the page take a minute to show
      folded(eq, "equation-folded", "the equation, " + Math.round(row.equation.length / 1000) +
             "k characters of TeX: open to typeset it", function (d) { tex(d, row.equation, true); });
    }
    if (row.intermediates.length) {
      folded(eq, "", row.intermediates.length + " named intermediates", function (d) {
        row.intermediates.forEach(function (k) { tex(d, data.intermediates[k], true); });
      });
    }
    if (row.note) el("p", {"class": "note"}, eq, row.note);
    unitMark(eq, row);
    derivation(card, data, row);
  }

  // ---- teaching aids: a row's derivation, its unit check, the brute-force count -----------
  // the row's derivation step by step, closed until asked for: each step's name, a sentence
  // and its formula (long ones folded, as long equations are)
  function derivation(card, data, row) {
    if (!row.derivation || !row.derivation.steps.length) return;
    folded(card, "derivation", "Derivation of E_" + row.variable + ", step by step", function (d) {
      var list = el("ol", {"class": "derivation-steps"}, d);
      row.derivation.steps.forEach(function (step) {
        var li = el("li", {"data-step": step.label}, list);
        el("span", {"class": "step-label"}, li, step.label);
        if (step.text) el("span", {"class": "step-text"}, li, ": " + step.text);
        if (!step.tex) return;
        if (step.tex.length <= LONG_TEX) tex(li, step.tex, true);
        else folded(li, "equation-folded", Math.round(step.tex.length / 1000) +
                    "k characters of TeX: open to typeset it", function (f) { tex(f, step.tex, true); });
      });
      if (row.derivation.intermediates.length)
        folded(d, "", row.derivation.intermediates.length + " named intermediates the steps use", function (f) {
          row.derivation.intermediates.forEach(function (k) { tex(f, data.intermediates[k], true); });
        });
    });
  }

  // the row's units: every term in N (translate) or N*m (rotate), from the declared units
  function unitMark(eq, row) {
    if (!row.units) return;
    var mark = row.units.verdict === "consistent" ? " \u2713" : row.units.verdict === "inconsistent" ? " \u2717" : "";
    el("p", {"class": "unit-check " + row.units.verdict}, eq, row.units.summary + mark);
  }

  // free-body diagrams of every body separately, counted beside the road-map's rows
  function bruteForce(sec, data) {
    if (!data.brute_force || !data.brute_force.text) return;
    el("p", {"class": "note", id: "brute-force", "data-equations": data.brute_force.equations,
             "data-unknowns": data.brute_force.unknowns, "data-rows": data.brute_force.rows}, sec, data.brute_force.text);
  }

  // the mass matrix and forcing, when the report was asked for them
  function matrices(main, data) {
    var sec = el("section", {id: "matrices"}, main);
    el("h2", {}, sec, "Mass matrix and forcing");
    el("p", {"class": "note"}, sec, "M(q) q\u2033 = f(q, q\u2032, t), as simulate forms them for forward dynamics.");
    tex(sec, data.matrices.tex, true);
  }

  // the plots of the time histories (plots.js)
  var plots = alembertPlots({el: el, svg: svg, fmt: fmt}), palette = plots.palette;

  // ---- the 3D view (three.js, when the report inlines it) ------------------------------------
  // frames: arrays of the points' positions (x, y, z each) then the bodies' axes (9 each);
  // the camera circles the model: view.turn about "up", view.tilt above the ground plane
  function view3d(parent, data, points, bodies, frames) {
    if (!window.THREE) return null;
    var THREE = window.THREE, W = 560, H = 420;
    var renderer;
    try {
      renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
    } catch (e) {
      el("p", {"class": "note"}, parent, "The 3D view needs WebGL, which this browser does not offer.");
      return null;
    }
    renderer.setPixelRatio(1);
    renderer.setSize(W, H);
    renderer.setClearColor(0xffffff, 1);
    var canvas = renderer.domElement;
    canvas.className = "view3d";
    canvas.setAttribute("title", "drag to turn the view");
    parent.appendChild(canvas);
    var geo = data.geometry, index = {};
    points.forEach(function (n, i) { index[n] = i; });
    var V = function (a) { return new THREE.Vector3(a[0], a[1], a[2]); };
    var at = function (f, name) { var i = 3 * index[name]; return new THREE.Vector3(f[i], f[i + 1], f[i + 2]); };
    // where the model goes over the whole motion
    var box = new THREE.Box3();
    frames.forEach(function (f) { for (var i = 0; i < 3 * points.length; i += 3)
      if (isFinite(f[i]) && isFinite(f[i + 1]) && isFinite(f[i + 2])) box.expandByPoint(new THREE.Vector3(f[i], f[i + 1], f[i + 2])); });
    if (box.isEmpty()) box.expandByPoint(new THREE.Vector3(0, 0, 0));
    var centre = box.getCenter(new THREE.Vector3()), size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-3);
    var up = V(geo.up || [0, 1, 0]);
    if (up.length() < 1e-12) up.set(0, 1, 0);
    up.normalize();
    // two directions across "up": the N axis least along it, made square to it, and their cross
    var axes = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)];
    axes.sort(function (a, b) { return Math.abs(a.dot(up)) - Math.abs(b.dot(up)); });
    var e1 = axes[0].clone().addScaledVector(up, -axes[0].dot(up)).normalize(), e2 = new THREE.Vector3().crossVectors(up, e1);
    if (geo.planar) { e1 = new THREE.Vector3(0, 0, 1).addScaledVector(up, -up.z).normalize(); e2 = new THREE.Vector3().crossVectors(up, e1); }

    var scene = new THREE.Scene();
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    var sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.copy(up).multiplyScalar(3 * size).addScaledVector(e1, size);
    scene.add(sun);
    // the ground: a grid across "up" through the lowest point, and N's axes at N_o
    var low = Infinity;
    frames.forEach(function (f) { for (var i = 0; i < 3 * points.length; i += 3) {
      var d = f[i] * up.x + f[i + 1] * up.y + f[i + 2] * up.z;
      if (isFinite(d)) low = Math.min(low, d); } });
    if (!isFinite(low)) low = 0;
    var grid = new THREE.GridHelper(2 * size, 10, 0xbbbbbb, 0xe2e2e2);
    grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
    grid.position.copy(centre).addScaledVector(up, low - centre.dot(up));
    scene.add(grid);
    var triadN = new THREE.AxesHelper(0.25 * size);
    scene.add(triadN);
    // the points that move, and how large the model is in one frame
    var moving = points.map(function (n, i) {
      return frames.some(function (f) { return Math.abs(f[3 * i] - frames[0][3 * i]) + Math.abs(f[3 * i + 1] - frames[0][3 * i + 1]) +
                                                Math.abs(f[3 * i + 2] - frames[0][3 * i + 2]) > 1e-9 * size; });
    });
    var extent = 0;
    frames.forEach(function (f) {
      var b = new THREE.Box3();
      points.forEach(function (n, i) { if (moving[i]) b.expandByPoint(at(f, n)); });
      if (!b.isEmpty()) extent = Math.max(extent, b.getSize(new THREE.Vector3()).length());
    });
    // a body's drawn ellipsoid counts in its size (a disk is wider than its points)
    bodies.forEach(function (b) {
      if (b.ellipsoid && extent > 0) extent = Math.max(extent, 2 * Math.max.apply(null, b.ellipsoid.axes));
    });
    var modelSize = extent > 0 ? Math.min(size, 1.6 * extent) : size;
    // the sticks as thin cylinders, the points as beads, each body's axes as a small triad
    var radius = 0.012 * modelSize, unitY = new THREE.Vector3(0, 1, 0);
    var sticks = geo.segments.map(function (seg, k) {
      var m = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, 1, 12),
                             new THREE.MeshLambertMaterial({color: palette[k % palette.length]}));
      m.userData = seg;
      scene.add(m);
      return m;
    });
    var beads = points.map(function () {
      var m = new THREE.Mesh(new THREE.SphereGeometry(1.6 * radius, 12, 8), new THREE.MeshLambertMaterial({color: 0x333333}));
      scene.add(m);
      return m;
    });
    // a body's triad as long as the body (its points' reach from its mass centre)
    var reach = bodies.map(function (b) {
      var c = at(frames[0], b.cm), r = 0;
      geo.segments.forEach(function (seg) {
        if (seg.body !== b.name || !(seg.from in index) || !(seg.to in index)) return;
        r = Math.max(r, at(frames[0], seg.from).distanceTo(c), at(frames[0], seg.to).distanceTo(c));
      });
      return Math.max(r, 0.06 * (extent || size));
    });
    var triads = bodies.map(function (b, i) {
      var t = new THREE.AxesHelper(reach[i]);
      t.matrixAutoUpdate = false;
      scene.add(t);
      return t;
    });
    // each rigid body as its inertia ellipsoid (uniform density, same mass and central inertia),
    // translucent, turning with the body: a disk shows as a disk, a rod as a needle
    var shells = bodies.map(function (b, i) {
      if (!b.ellipsoid) return null;
      var e = b.ellipsoid, d = e.directions, thin = 0.02 * modelSize;
      var m = new THREE.Mesh(new THREE.SphereGeometry(1, 32, 16),
                             new THREE.MeshLambertMaterial({color: palette[i % palette.length], transparent: true, opacity: 0.35}));
      m.matrixAutoUpdate = false;
      // principal axes (columns of d, in the body's frame) scaled by the semi-axes
      m.userData.shape = new THREE.Matrix4().set(
        d[0] * Math.max(e.axes[0], thin), d[3] * Math.max(e.axes[1], thin), d[6] * Math.max(e.axes[2], thin), 0,
        d[1] * Math.max(e.axes[0], thin), d[4] * Math.max(e.axes[1], thin), d[7] * Math.max(e.axes[2], thin), 0,
        d[2] * Math.max(e.axes[0], thin), d[5] * Math.max(e.axes[1], thin), d[8] * Math.max(e.axes[2], thin), 0,
        0, 0, 0, 1);
      m.userData.body = b.name;
      scene.add(m);
      return m;
    });
    // where each mass centre goes: a faint trace over the whole motion
    if (frames.length > 1)
      bodies.forEach(function (b, i) {
        var g = new THREE.BufferGeometry().setFromPoints(frames.map(function (f) { return at(f, b.cm); }));
        scene.add(new THREE.Line(g, new THREE.LineBasicMaterial({color: palette[i % palette.length], transparent: true, opacity: 0.45})));
      });
    // a model that travels far (a rolling disk) is followed by the camera
    var follow = null;
    if (extent > 0 && extent < size / 3) {
      var lab = el("label", {"class": "follow"}, parent, " follow the model");
      follow = el("input", {type: "checkbox", checked: "checked", id: "view-follow"});
      lab.insertBefore(follow, lab.firstChild);
      follow.addEventListener("change", function () { show(current); });
    }
    var camera = new THREE.PerspectiveCamera(35, W / H, size / 100, size * 100);
    function place(f) {
      var ct = Math.cos(view.turn), st = Math.sin(view.turn), ce = Math.cos(view.tilt), se = Math.sin(view.tilt);
      var d = new THREE.Vector3().addScaledVector(e1, ce * ct).addScaledVector(e2, ce * st).addScaledVector(up, se);
      var c = centre, r = size;
      if (follow && follow.checked) {
        var b = new THREE.Box3();
        points.forEach(function (n, i) { if (moving[i]) b.expandByPoint(at(f, n)); });
        c = b.getCenter(new THREE.Vector3());
        r = modelSize;
      }
      camera.position.copy(c).addScaledVector(d, 2.2 * r);
      camera.up.copy(up);
      camera.lookAt(c);
    }
    var current = 0;
    function show(k) {
      current = k;
      var f = frames[k];
      geo.segments.forEach(function (seg, j) {
        var a = at(f, seg.from), b = at(f, seg.to), d = b.clone().sub(a), n = d.length();
        var m = sticks[j];
        m.visible = isFinite(n) && n > 1e-12;
        if (!m.visible) return;
        m.position.copy(a).addScaledVector(d, 0.5);
        m.quaternion.setFromUnitVectors(unitY, d.divideScalar(n));
        m.scale.set(1, n, 1);
      });
      points.forEach(function (n, i) { beads[i].position.copy(at(f, n)); });
      bodies.forEach(function (b, i) {
        var o = 3 * points.length + 9 * i, c = at(f, b.cm);
        // columns: the body's x, y, z axes in N
        triads[i].matrix.set(f[o], f[o + 3], f[o + 6], c.x, f[o + 1], f[o + 4], f[o + 7], c.y,
                             f[o + 2], f[o + 5], f[o + 8], c.z, 0, 0, 0, 1);
        if (shells[i]) shells[i].matrix.multiplyMatrices(triads[i].matrix, shells[i].userData.shape);
      });
      place(f);
      renderer.render(scene, camera);
      canvas.setAttribute("data-frame", k);
      canvas.setAttribute("data-view", view.turn.toFixed(2) + " " + view.tilt.toFixed(2));
    }
    // dragging turns the view
    var drag = null;
    canvas.addEventListener("mousedown", function (e) { drag = [e.clientX, e.clientY]; e.preventDefault(); });
    window.addEventListener("mouseup", function () { drag = null; });
    canvas.addEventListener("mousemove", function (e) {
      if (!drag) return;
      view.turn -= 0.01 * (e.clientX - drag[0]);
      view.tilt = Math.max(-1.5, Math.min(1.5, view.tilt + 0.01 * (e.clientY - drag[1])));
      drag = [e.clientX, e.clientY];
      show(current);
    });
    // how much of the canvas is drawn on (the browser test reads it)
    function ink() {
      var gl = renderer.getContext(), px = new Uint8Array(W * H * 4), n = 0;
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, px);
      for (var i = 0; i < px.length; i += 4) if (px[i] < 200 || px[i + 1] < 200 || px[i + 2] < 200) ++n;
      return n / (W * H);
    }
    canvas.alembertInk = ink;
    canvas.setAttribute("data-sticks", sticks.length);
    canvas.setAttribute("data-bodies", bodies.length);
    canvas.setAttribute("data-shells", shells.filter(function (x) { return x; }).length);
    return {show: show, canvas: canvas};
  }

  // ---- the animation -----------------------------------------------------------------------
  // the speeds offered (seconds of motion per second of wall time)
  var SPEEDS = [0.25, 0.5, 1, 2, 4];
  // the motion's time `elapsed` ms after play started at motion time `from`, at `rate`
  function playedTime(from, elapsed, rate) { return from + rate * Math.max(0, elapsed) / 1000; }
  // the frame due at time t: the last whose time is not after t (the first before them all)
  function frameAt(times, t) {
    var lo = 0, hi = times.length - 1;
    if (t >= times[hi]) return hi;
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid;
    }
    return lo;
  }
  var animator = null;  // the animation's player, when there is a motion

  function animation(main, data) {
    var a = data.animation, geo = data.geometry;
    if (!a) {
      // a spatial model without a motion: its configuration in 3D
      if (geo.planar || !window.THREE) return;
      var still = el("section", {id: "animation"}, main);
      el("h2", {}, still, "The model in 3D (drag to turn)");
      var model = geo.points.filter(function (p) { return !p.about_only; });
      var v = view3d(still, data, model.map(function (p) { return p.name; }), [],
                     [[].concat.apply([], model.map(function (p) { return p.at; }))]);
      if (v) v.show(0);
      return;
    }
    var sec = el("section", {id: "animation"}, main);
    el("h2", {}, sec, "Motion: " + a.source);
    var project = projector(geo), index = {};
    a.points.forEach(function (n, i) { index[n] = i; });
    var pointAt = function (frame, name) { var i = 3 * index[name]; return [frame[i], frame[i + 1], frame[i + 2]]; };
    var all = [];
    a.frames.forEach(function (f) { a.points.forEach(function (n) { all.push(pointAt(f, n)); }); });
    var box = bounds(all, project), pad = 0.15 * box.size;
    var view = [box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad];
    var k = 420 / Math.max(view[2], view[3]);
    var stage = el("div", {"class": "stage"}, sec);
    var s = svg("svg", {"class": "anim", viewBox: view.join(" "), width: k * view[2], height: k * view[3]}, stage);
    var three = view3d(stage, data, a.points, a.bodies || [], a.frames);
    // a spatial model is shown in 3D alone when three.js is there
    if (three && !geo.planar) s.style.display = "none";
    var g = svg("g", {}, s);
    svg("line", {x1: view[0], x2: view[0] + view[2], y1: project([0, 0, 0])[1], y2: project([0, 0, 0])[1], "class": "ground"}, g);
    var lines = geo.segments.map(function (seg, k) {
      return svg("line", {"class": "stick", stroke: palette[k % palette.length], "data-body": seg.body}, g);
    });
    var controls = el("div", {"class": "controls"}, sec);
    var button = el("button", {type: "button", id: "play"}, controls, "play");
    var slider = el("input", {type: "range", min: 0, max: a.frames.length - 1, value: 0, step: 1, id: "time-slider"}, controls);
    var label = el("span", {"class": "time"}, controls);
    var speedLabel = el("label", {}, controls, "speed ");
    var speed = el("select", {id: "speed", title: "seconds of motion played per second"}, speedLabel);
    SPEEDS.forEach(function (v) {
      var o = el("option", {value: v}, speed, v + "\u00d7" + (v === 1 ? " (real time)" : ""));
      if (v === 1) o.selected = true;
    });
    // a segment with an end the motion does not place (a plate's centre of pressure) is not drawn
    geo.segments.forEach(function (seg, j) {
      if (!(seg.from in index) || !(seg.to in index)) lines[j].style.display = "none";
    });
    function show(k, fromCursor) {
      var f = a.frames[k];
      geo.segments.forEach(function (seg, j) {
        if (!(seg.from in index) || !(seg.to in index)) return;
        var p = project(pointAt(f, seg.from)), q = project(pointAt(f, seg.to));
        lines[j].setAttribute("x1", p[0]); lines[j].setAttribute("y1", p[1]);
        lines[j].setAttribute("x2", q[0]); lines[j].setAttribute("y2", q[1]);
      });
      label.textContent = "t = " + fmt(a.time[k]) + " s";
      slider.value = k;
      if (three) three.show(k);
      if (!fromCursor) plots.cursorAt(a.time[k], true);
    }
    // playing: the frame shown is the one due at the motion's time, which runs `rate` times
    // the wall clock from where play started (frames are skipped or held, never one per tick)
    var player = {playing: false, rate: 1, wall0: 0, time0: 0, frame: 0};
    function stop() { player.playing = false; button.textContent = "play"; }
    player.stop = stop;
    // what is shown at wall-clock instant `now` (ms, performance.now()); false at the end
    player.advance = function (now) {
      var k = frameAt(a.time, playedTime(player.time0, now - player.wall0, player.rate));
      if (k !== player.frame) { player.frame = k; show(k); }
      return k + 1 < a.time.length;
    };
    function tick() {
      if (!player.playing) return;
      if (player.advance(performance.now())) window.requestAnimationFrame(tick);
      else stop();
    }
    // play from frame k, now
    player.start = function (k) {
      if (k + 1 >= a.time.length) k = 0;
      player.frame = k;
      show(k);
      player.time0 = a.time[k];
      player.wall0 = performance.now();
      player.playing = true;
      button.textContent = "pause";
      window.requestAnimationFrame(tick);
    };
    button.addEventListener("click", function () {
      if (player.playing) stop(); else player.start(Number(slider.value));
    });
    speed.addEventListener("change", function () {
      // the new rate from the time shown now
      var now = performance.now();
      if (player.playing) {
        player.time0 = playedTime(player.time0, now - player.wall0, player.rate);
        player.wall0 = now;
      }
      player.rate = Number(speed.value);
    });
    slider.addEventListener("input", function () { stop(); player.frame = Number(slider.value); show(player.frame); });
    // the plots' cursor moves the motion to the frame nearest its time
    plots.follow(function (t) {
      stop();
      var k = 0;
      a.time.forEach(function (v, i) { if (Math.abs(v - t) < Math.abs(a.time[k] - t)) k = i; });
      player.frame = k;
      show(k, true);
    });
    show(0);
    animator = player;
  }

  // ---- the page ---------------------------------------------------------------------------
  // ---- the equations of motion kane and lagrange formed -----------------------------------
  function equationSets(main, data) {
    if (!data.equation_sets || !data.equation_sets.length) return;
    var sec = el("section", {id: "equations"}, main);
    el("h2", {}, sec, "Equations of motion");
    data.equation_sets.forEach(function (set) {
      var box = el("div", {"class": "equation-set", "data-line": set.line}, sec);
      el("h3", {}, box, set.method + ": " + set.name + " (line " + set.line + ")");
      set.equations.forEach(function (eq, k) {
        el("div", {"class": "eq-name"}, box, set.name + "[" + (k + 1) + "]");
        if (eq.length > LONG_TEX)
          folded(box, "equation-folded", "0 = ... (" + eq.length + " characters of TeX: open to typeset)",
                 function (d) { tex(d, eq, true); });
        else
          tex(box, eq, true);
      });
    });
  }

  // ---- what the script printed: solve, evaluate, linearize (a sweep's plots under it) -----
  function results(main, data) {
    if (!data.results || !data.results.length) return;
    var sec = el("section", {id: "results"}, main);
    el("h2", {}, sec, "Results");
    data.results.forEach(function (r) {
      var box = el("div", {"class": "result", "data-line": r.line}, sec);
      el("pre", {"class": "statement"}, box, "line " + r.line + ": " + r.statement);
      el("pre", {"class": "output"}, box, r.text.replace(/\n+$/, ""));
      plots.sweep(box, r);
    });
  }

  function render(data, main) {
    while (main.firstChild) main.removeChild(main.firstChild);
    el("h1", {}, main, data.title);
    el("p", {"class": "note subtitle"}, main, "Alembert report");
    if (!data.geometry.planar && data.roadmap.some(function (row) { return row.diagram; })) {
      // a spatial model's free-body diagrams: sliders turn them (none where there are none:
      // the 3D view is turned by dragging)
      var turn = el("div", {"class": "controls", id: "view-controls"}, main);
      [["turn", -3.1416, 3.1416], ["tilt", -1.5, 1.5]].forEach(function (c) {
        var lab = el("label", {}, turn, c[0] + " the diagrams ");
        var input = el("input", {type: "range", min: c[1], max: c[2], step: 0.01, value: view[c[0]], id: "view-" + c[0]}, lab);
        input.addEventListener("input", function () { view[c[0]] = Number(input.value); redrawDiagrams(data); });
      });
    }
    if (!window.katex)
      el("p", {"class": "warning"}, main, "KaTeX was not found when this report was written, so equations show as TeX; " +
         "install Debian's libjs-katex (or set ALEMBERT_KATEX_DIR) and write the report again.");
    data.notes.forEach(function (n) { el("p", {"class": "warning"}, main, n); });
    diagrams = [];
    if (data.roadmap.length) roadmap(main, data);
    equationSets(main, data);
    results(main, data);
    if (data.matrices) matrices(main, data);
    animation(main, data);
    plots.histories(main, data);
    checks(main, data);
    model(main, data);
  }
  try {
    var data = JSON.parse(document.getElementById("alembert-data").textContent);
    render(data, document.getElementById("report"));
    turnable(data);
  } catch (e) {
    fail("the report could not be drawn: " + (e && e.stack ? e.stack : e));
  }
  // with #exercise in the address, the controls are worked once as a user would and what they
  // did is written into #alembert-exercise (the browser test reads it)
  function exercise() {
    var out = [];
    function expect(ok, what) { out.push((ok ? "ok " : "FAIL ") + what); }
    var fig = document.querySelector("figure.plot");
    if (fig) {
      var lines = function () { return fig.querySelectorAll("polyline.series").length; };
      var before = lines(), box = fig.querySelector("input[type=checkbox]");
      box.checked = false;
      box.dispatchEvent(new Event("change"));
      expect(lines() === before - 1, "unticking a series hides it");
      box.checked = true;
      box.dispatchEvent(new Event("change"));
      expect(lines() === before, "ticking it shows it again");
      var plotSvg = fig.querySelector("svg"), r = plotSvg.getBoundingClientRect();
      plotSvg.dispatchEvent(new MouseEvent("mousemove", {clientX: r.left + r.width / 2, clientY: r.top + r.height / 2}));
      expect(/^t = .+, .+ = /.test(fig.querySelector(".readout").textContent), "the cursor reads values");
      // zoom: drag from a quarter to a half of the plot's width; the time axis then starts later
      var ticks = function () { return Array.prototype.map.call(fig.querySelectorAll("g.axes text[text-anchor=middle]"),
                                                                 function (n) { return n.textContent; }).join(" "); };
      var before = ticks();
      r = plotSvg.getBoundingClientRect();
      plotSvg.dispatchEvent(new MouseEvent("mousedown", {clientX: r.left + 0.3 * r.width, clientY: r.top + 0.5 * r.height, bubbles: true}));
      plotSvg.dispatchEvent(new MouseEvent("mousemove", {clientX: r.left + 0.6 * r.width, clientY: r.top + 0.5 * r.height, bubbles: true}));
      window.dispatchEvent(new MouseEvent("mouseup", {clientX: r.left + 0.6 * r.width, clientY: r.top + 0.5 * r.height}));
      var range = (fig.getAttribute("data-range") || "").split(" ").map(Number);
      expect(ticks() !== before && range.length === 2 && range[0] > 0 && range[1] > range[0], "dragging zooms into a time range (" +
             fig.getAttribute("data-range") + ")");
      fig.querySelector("button.zoom-reset").click();
      expect(ticks() === before, "show all zooms out again");
    }
    // a sweep's cursor: its values read against the swept value on its own plots, the time
    // plots and the animation left where they are
    var sweepFig = document.querySelector("figure.sweep-plot");
    if (sweepFig) {
      var sweepBox = sweepFig.parentNode, name = sweepBox.getAttribute("data-parameter");
      var timeFig = document.querySelector("figure.plot"), timeSlider = document.getElementById("time-slider");
      var timeBefore = timeFig ? timeFig.getAttribute("data-cursor") : null, frameBefore = timeSlider ? timeSlider.value : null;
      var ss = sweepFig.querySelector("svg"), sr = ss.getBoundingClientRect();
      ss.dispatchEvent(new MouseEvent("mousemove", {clientX: sr.left + 0.7 * sr.width, clientY: sr.top + sr.height / 2}));
      var at = sweepFig.getAttribute("data-cursor"), others = sweepBox.querySelectorAll("figure.sweep-plot"), same = true;
      Array.prototype.forEach.call(others, function (f) { same = same && f.getAttribute("data-cursor") === at; });
      expect(at !== null && same && sweepFig.querySelector(".readout").textContent.indexOf(name + " = ") === 0 &&
             (!timeFig || timeFig.getAttribute("data-cursor") === timeBefore) &&
             (!timeSlider || timeSlider.value === frameBefore),
             "a sweep's cursor reads its values on its own plots (" + name + " = " + at + " on " + others.length +
             " plots; time cursor " + (timeFig ? timeFig.getAttribute("data-cursor") : "none") + ", was " + timeBefore + ")");
    }
    var canvas = document.querySelector("canvas.view3d");
    if (canvas) {
      var inkBefore = canvas.alembertInk(), viewBefore = canvas.getAttribute("data-view");
      expect(inkBefore > 0.002 && inkBefore < 0.6, "the 3D view is drawn (" + (100 * inkBefore).toFixed(1) + "% ink)");
      var cr = canvas.getBoundingClientRect();
      canvas.dispatchEvent(new MouseEvent("mousedown", {clientX: cr.left + 100, clientY: cr.top + 100}));
      canvas.dispatchEvent(new MouseEvent("mousemove", {clientX: cr.left + 160, clientY: cr.top + 130}));
      window.dispatchEvent(new MouseEvent("mouseup", {}));
      expect(canvas.getAttribute("data-view") !== viewBefore && canvas.alembertInk() > 0.002, "dragging turns the 3D view (" +
             viewBefore + " to " + canvas.getAttribute("data-view") + ")");
    }
    var fbd = document.querySelector("svg.fbd");
    if (fbd && document.getElementById("view-turn")) {
      var turnBefore = document.getElementById("view-turn").value, fr = fbd.getBoundingClientRect();
      fbd.dispatchEvent(new MouseEvent("mousedown", {clientX: fr.left + 50, clientY: fr.top + 50, bubbles: true}));
      window.dispatchEvent(new MouseEvent("mousemove", {clientX: fr.left + 90, clientY: fr.top + 60}));
      window.dispatchEvent(new MouseEvent("mouseup", {}));
      expect(document.getElementById("view-turn").value !== turnBefore && document.querySelectorAll("svg.fbd").length === diagrams.length,
             "dragging a free-body diagram turns every diagram");
    }
    var slider = document.getElementById("time-slider");
    if (slider) {
      // where the sticks are (a model's first stick may be fixed to the ground: an arm's base)
      var sticks = document.querySelectorAll("svg.anim line.stick"), stick = sticks.length > 0;
      var placed = function () { return Array.prototype.map.call(sticks, function (l) {
        return ["x1", "y1", "x2", "y2"].map(function (c) { return l.getAttribute(c); }).join(" "); }).join(";"); };
      var x0 = placed();
      var frame0 = canvas ? canvas.getAttribute("data-frame") : null;
      slider.value = slider.max;
      slider.dispatchEvent(new Event("input"));
      if (stick) expect(placed() !== x0, "the time slider moves the model");
      if (canvas) expect(canvas.getAttribute("data-frame") !== frame0, "the time slider moves the 3D view");
      var play = document.getElementById("play");
      slider.value = 0;
      slider.dispatchEvent(new Event("input"));
      play.click();
      expect(play.textContent === "pause", "play starts the animation");
      play.click();
      expect(play.textContent === "play", "pause stops it");
      var times = data.animation.time, span = times[times.length - 1] - times[0];
      // the plots' cursor moves the motion to the frame nearest the time under it
      var plotFig = document.querySelector("figure.plot");
      if (plotFig) {
        slider.value = 0;
        slider.dispatchEvent(new Event("input"));
        var ps = plotFig.querySelector("svg"), pr = ps.getBoundingClientRect();
        ps.dispatchEvent(new MouseEvent("mousemove", {clientX: pr.left + 0.8 * pr.width, clientY: pr.top + 0.5 * pr.height}));
        var tc = Number(plotFig.getAttribute("data-cursor")), want = 0;
        times.forEach(function (v, i) { if (Math.abs(v - tc) < Math.abs(times[want] - tc)) want = i; });
        expect(want > 0 && Number(slider.value) === want && (!canvas || canvas.getAttribute("data-frame") === String(want)),
               "the cursor moves the animation (t = " + fmt(tc) + " s: frame " + slider.value + ", nearest " + want + ")");
      }
      // play at each speed: after a wall time w the frame shown is the last at or before
      // t0 + speed * w (the player's own clock, driven here with chosen instants)
      var speed = document.getElementById("speed"), step = 0;
      for (var i = 1; i < times.length; ++i) step = Math.max(step, times[i] - times[i - 1]);
      expect(speed && speed.options.length >= 4 && speed.value === "1",
             "the speed control offers " + (speed ? speed.options.length : 0) + " speeds, 1\u00d7 (real time) first");
      [1, 0.5, 2, 0.25].forEach(function (rate) {
        speed.value = String(rate);
        speed.dispatchEvent(new Event("change"));
        animator.start(0);
        var wall = 0.4 * span / rate;  // seconds of wall time for 40 % of the motion
        animator.advance(animator.wall0 + 1000 * wall);
        var due = times[0] + 0.4 * span, shown = times[animator.frame];
        expect(shown <= due + 1e-9 * span && due - shown <= step + 1e-9 * span && Number(slider.value) === animator.frame,
               "play at " + rate + "\u00d7: " + fmt(wall) + " s of wall time shows t = " + fmt(shown) + " s (due " + fmt(due) + " s)");
        animator.stop();
      });
      speed.value = "1";
      speed.dispatchEvent(new Event("change"));
    }
    exerciseTeaching(expect);
    el("pre", {id: "alembert-exercise"}, document.body, out.join("\n"));
    // the 3D view as drawn at the start (the browser test saves and checks it)
    if (canvas) {
      var slider0 = document.getElementById("time-slider");
      if (slider0) { slider0.value = 0; slider0.dispatchEvent(new Event("input")); }
      el("pre", {id: "alembert-3d"}, document.body, canvas.toDataURL("image/png"));
    }
  }
  // the teaching aids worked as a reader would: every row's derivation opened (closed until
  // then), its formulas typeset by KaTeX and none wider than its column; the brute-force count
  // and each row's unit check shown
  function exerciseTeaching(expect) {
    if (!data.roadmap.length) return;
    var all = document.querySelectorAll("details.derivation"), closed = 0, formulas = 0, typeset = 0, wide = [];
    Array.prototype.forEach.call(all, function (d) {
      if (!d.open) closed++;
      d.open = true;
      d.dispatchEvent(new Event("toggle"));
    });
    Array.prototype.forEach.call(all, function (d) {
      Array.prototype.forEach.call(d.querySelectorAll("ol.derivation-steps div.equation"), function (b) {
        formulas++;
        if (b.querySelector(".katex") && !b.querySelector(".katex-error")) typeset++;
        if (b.scrollWidth > b.clientWidth + 1) wide.push(b.scrollWidth + ">" + b.clientWidth);
      });
    });
    expect(all.length === data.roadmap.length && closed === all.length,
           "derivations are closed until opened (" + closed + " of " + all.length + " rows)");
    expect(formulas > 0 && typeset === formulas && !failed,
           "each derivation opens and typesets its steps (" + all.length + " rows, " + typeset + " of " + formulas + " formulas by KaTeX)");
    expect(wide.length === 0, "no derivation formula wider than its column (" + wide.slice(0, 3).join(", ") + ")");
    var bf = document.getElementById("brute-force");
    expect(bf && Number(bf.getAttribute("data-equations")) > 0 && /equations? .* in \d+ unknowns?/.test(bf.textContent),
           "the brute-force count is shown (" + (bf ? bf.getAttribute("data-equations") + " equations, " +
           bf.getAttribute("data-unknowns") + " unknowns, " + bf.getAttribute("data-rows") + " rows" : "none") + ")");
    var marks = document.querySelectorAll("p.unit-check"), kinds = document.querySelectorAll("tr[data-kind=units]");
    expect(marks.length === data.roadmap.length && kinds.length === data.roadmap.length,
           "each row shows its unit check (" + marks.length + " marks, " + kinds.length + " lines in the checks)");
    Array.prototype.forEach.call(all, function (d) { d.open = false; });
  }
  if (!failed && window.location.hash === "#exercise") {
    try { exercise(); } catch (e) { fail("exercising the controls failed: " + e); }
  }
  status.setAttribute("data-status", failed ? "error" : "ready");
  status.textContent = failed ? "the report has errors (below)" : "";
})();
