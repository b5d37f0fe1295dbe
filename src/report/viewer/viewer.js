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
  function tex(parent, source, display) {
    var box = el(display ? "div" : "span", {"class": "equation"}, parent);
    if (window.katex) {
      try {
        window.katex.render(source, box, {displayMode: !!display, throwOnError: true, maxExpand: 1000000});
        return box;
      } catch (e) {
        fail("KaTeX could not typeset: " + source.slice(0, 80) + "...: " + e.message);
      }
    }
    box.className = "equation tex-raw";
    box.textContent = source;
    return box;
  }

  // ---- geometry: the plane of planar models, an oblique view of spatial ones ----------------
  // spatial models: turned about Ny by view.turn, then tilted by view.tilt (radians)
  var view = {turn: 0.6, tilt: 0.35};
  function projector(planar) {
    if (planar) return function (p) { return [p[0], -p[1]]; };
    var ct = Math.cos(view.turn), st = Math.sin(view.turn), ce = Math.cos(view.tilt), se = Math.sin(view.tilt);
    return function (p) {
      var x = ct * p[0] + st * p[2], z = -st * p[0] + ct * p[2];
      return [x, -(ce * p[1] + se * z)];
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
    svg("line", {x1: from[0], y1: from[1], x2: b[0], y2: b[1], "class": "shaft " + (cls || "")}, g);
    svg("path", {d: "M" + to[0] + "," + to[1] + " L" + (b[0] - u[1] * w) + "," + (b[1] + u[0] * w) +
                 " L" + (b[0] + u[1] * w) + "," + (b[1] - u[0] * w) + " Z", "class": "head " + (cls || "")}, g);
  }

  // one free-body diagram: the model faded, S in ink, each load on S as an arrow
  function drawDiagram(parent, data, row) {
    var geo = data.geometry, project = projector(geo.planar);
    var at = {};
    geo.points.forEach(function (p) { at[p.name] = p.at; });
    var box = bounds(geo.points.map(function (p) { return p.at; }), project);
    var L = box.size, pad = 0.45 * L;
    var view = [box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad];
    var s = svg("svg", {"class": "fbd", viewBox: view.join(" "), width: 340, height: 340 * view[3] / view[2],
                        "data-variable": row.variable, "data-loads": row.diagram.loads.length}, parent);
    var g = svg("g", {"class": "scene", "font-size": 0.055 * L}, s);
    g.head = 0.06 * L;
    var inS = {};
    row.diagram.system.forEach(function (b) { inS[b] = true; });
    geo.segments.forEach(function (seg) {
      var a = project(at[seg.from]), b = project(at[seg.to]);
      svg("line", {x1: a[0], y1: a[1], x2: b[0], y2: b[1],
                   "class": inS[seg.body] ? "stick in-system" : "stick faded"}, g);
    });
    geo.points.forEach(function (p) {
      var q = project(p.at);
      svg("circle", {cx: q[0], cy: q[1], r: 0.012 * L, "class": "point"}, g);
    });
    var arrowLength = 0.28 * L;
    row.diagram.loads.forEach(function (load) {
      var lg = svg("g", {"class": "load " + load.kind + (load.unknown ? " unknown" : " known"),
                         "data-label": load.label}, g);
      lg.head = g.head;
      var p = project(at[load.at] || [0, 0, 0]);
      var labelAt = [p[0] + 0.05 * L, p[1] - 0.05 * L];
      if (load.kind === "torque" && !geo.planar) {
        // in space: a double-headed arrow along the torque
        var tu = unit2(project(load.vector.length ? load.vector : [0, 0, 1]));
        if (tu) {
          var tip = [p[0] + tu[0] * arrowLength, p[1] + tu[1] * arrowLength];
          arrow(lg, p, tip);
          arrow(lg, p, [tip[0] - tu[0] * g.head, tip[1] - tu[1] * g.head]);
          labelAt = [tip[0] + 0.03 * L, tip[1]];
        }
      } else if (load.kind === "torque") {
        // an arc about the point, counterclockwise in the plane for a +z torque
        var z = load.vector.length ? load.vector[2] : 1, r = 0.11 * L, sense = z >= 0 ? 1 : -1;
        var th0 = sense > 0 ? -2.1 : 2.6, th1 = sense > 0 ? 2.6 : -2.1, pts = [];
        for (var k = 0; k <= 24; ++k) {
          var th = th0 + (th1 - th0) * k / 24;
          pts.push([p[0] + r * Math.cos(th), p[1] - r * Math.sin(th)]);
        }
        svg("polyline", {points: pts.map(function (q) { return q.join(","); }).join(" "), "class": "shaft arc", fill: "none"}, lg);
        var end1 = pts[24], tan = [-Math.sin(th1) * sense, -Math.cos(th1) * sense];
        arrow(lg, [end1[0] - tan[0] * 0.9 * g.head, end1[1] - tan[1] * 0.9 * g.head], end1);
        labelAt = [p[0] + r, p[1] - r];
      } else if (load.kind === "joint") {
        // a joint's force: unknown components along Nx and Ny
        (geo.planar ? [[1, 0, 0], [0, 1, 0]] : [[1, 0, 0], [0, 1, 0], [0, 0, 1]]).forEach(function (axis) {
          var a = project(axis);
          arrow(lg, p, [p[0] + 0.6 * arrowLength * a[0], p[1] + 0.6 * arrowLength * a[1]]);
        });
        labelAt = [p[0] + 0.62 * arrowLength, p[1] + 0.06 * L];
      } else {
        var u = unit2(project(load.vector));
        if (u) {
          var tail = load.kind === "gravity" ? p : [p[0] - u[0] * arrowLength, p[1] - u[1] * arrowLength];
          var head = load.kind === "gravity" ? [p[0] + u[0] * arrowLength, p[1] + u[1] * arrowLength] : p;
          arrow(lg, tail, head);
          labelAt = load.kind === "gravity" ? [head[0] + 0.03 * L, head[1]] : [tail[0], tail[1] - 0.03 * L];
        } else {
          svg("circle", {cx: p[0], cy: p[1], r: 0.04 * L, "class": "shaft", fill: "none"}, lg);
        }
      }
      svg("text", {x: labelAt[0], y: labelAt[1], "class": "label"}, lg, load.label);
    });
    // the about point O and the direction u
    if (row.diagram.about && at[row.diagram.about]) {
      var o = project(at[row.diagram.about]);
      var og = svg("g", {"class": "about"}, g);
      svg("circle", {cx: o[0], cy: o[1], r: 0.03 * L, fill: "none"}, og);
      svg("line", {x1: o[0] - 0.045 * L, y1: o[1], x2: o[0] + 0.045 * L, y2: o[1]}, og);
      svg("line", {x1: o[0], y1: o[1] - 0.045 * L, x2: o[0], y2: o[1] + 0.045 * L}, og);
      svg("text", {x: o[0] - 0.05 * L, y: o[1] + 0.1 * L, "text-anchor": "end", "class": "label"}, og,
          "O = " + row.diagram.about);
    }
    var dir = row.diagram.direction;
    var dg = svg("g", {"class": "direction"}, g);
    dg.head = g.head;
    var du = unit2(project(dir));
    var inPlane = du && (!geo.planar || Math.hypot(dir[0], dir[1]) > 0.2);
    var base = [box.x - 0.3 * L, box.y + box.h + 0.3 * L];
    if (inPlane) {
      arrow(dg, base, [base[0] + du[0] * 0.25 * L, base[1] + du[1] * 0.25 * L]);
    } else {
      svg("circle", {cx: base[0], cy: base[1], r: 0.04 * L, fill: "none"}, dg);
      svg("circle", {cx: base[0], cy: base[1], r: 0.01 * L, "class": "dot"}, dg);
    }
    svg("text", {x: base[0] + 0.07 * L, y: base[1] + 0.02 * L, "class": "label"}, dg,
        "\u00fb = " + row.direction + (inPlane ? "" : " (out of the page)"));
    return s;
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
    table(sec, ["constant", "value (SI)", "unit"], m.constants.map(function (c) {
      return [c.name, c.value === null ? "" : fmt(c.value), c.unit]; }));
    if (m.unknowns.length)
      table(sec, ["unknown", "unit"], m.unknowns.map(function (u) { return [u.name, u.unit]; }));
  }

  function roadmap(main, data) {
    var sec = el("section", {id: "roadmap"}, main);
    el("h2", {}, sec, "MG road-map");
    el("p", {"class": "note"}, sec, "Free-body diagrams at " + data.configuration.map(function (c) {
      return c.name + " = " + fmt(c.value); }).join(", ") + " (SI). Unknown loads in red, known in blue, gravity in green; " +
      "each equation is E = applied \u2212 inertial = 0.");
    var head = ["variable", "translate/rotate", "direction", "system S", "FBD of S", "about point", "additional unknowns"];
    data.roadmap.forEach(function (row, i) {
      var card = el("div", {"class": "row", id: "row-" + (i + 1)}, sec);
      var cells = [row.variable, row.motion, row.direction || "-", row.system.length ? "{" + row.system.join(", ") + "}" : "-",
                   row.fbd.join("; ") || "-", row.about || "-",
                   row.additional_unknowns.length ? row.additional_unknowns.join(", ") : "none"];
      table(card, head, [cells], "data roadmap-row");
      var body = el("div", {"class": "row-body"}, card);
      var pic = el("div", {"class": "fbd-box"}, body);
      if (row.diagram) drawDiagram(pic, data, row);
      else el("p", {"class": "note"}, pic, "constraint " + row.constraint + ": no free-body diagram");
      var eq = el("div", {"class": "eq-box"}, body);
      el("div", {"class": "eq-name"}, eq, "E_" + row.variable + ":");
      tex(eq, row.equation, true);
      if (row.intermediates.length) {
        var d = el("details", {}, eq);
        el("summary", {}, d, row.intermediates.length + " named intermediates");
        row.intermediates.forEach(function (z) { tex(d, z, true); });
      }
      if (row.note) el("p", {"class": "note"}, eq, row.note);
    });
  }

  var palette = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"];
  function niceTicks(lo, hi, n) {
    var span = hi - lo || 1, step = Math.pow(10, Math.floor(Math.log10(span / n)));
    [1, 2, 5, 10].some(function (m) { if (span / (step * m) <= n) { step *= m; return true; } return false; });
    var out = [];
    for (var v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) out.push(Math.abs(v) < 1e-12 * span ? 0 : v);
    return out;
  }
  function plot(parent, h) {
    var W = 720, H = 300, ml = 60, mr = 20, mt = 16, mb = 40;
    var fig = el("figure", {"class": "plot"}, parent);
    el("figcaption", {}, fig, h.title);
    var s = svg("svg", {"class": "plot-svg", viewBox: "0 0 " + W + " " + H, width: W, height: H}, fig);
    var shown = h.series.map(function () { return true; });
    var readout = el("div", {"class": "readout"}, fig, "move over the plot to read values");
    var legend = el("div", {"class": "legend"}, fig);
    h.series.forEach(function (ser, k) {
      var lab = el("label", {style: "color:" + palette[k % palette.length]}, legend);
      var box = el("input", {type: "checkbox", checked: "checked", "data-series": ser.name}, lab);
      lab.appendChild(document.createTextNode(" " + ser.name + (ser.unit ? " [" + ser.unit + "]" : "")));
      box.addEventListener("change", function () { shown[k] = box.checked; draw(); });
    });
    var t = h.time, x0 = t[0], x1 = t[t.length - 1] === x0 ? x0 + 1 : t[t.length - 1];
    var cursor = null;
    function draw() {
      while (s.firstChild) s.removeChild(s.firstChild);
      var lo = Infinity, hi = -Infinity;
      h.series.forEach(function (ser, k) {
        if (!shown[k]) return;
        ser.values.forEach(function (v) { if (v !== null) { lo = Math.min(lo, v); hi = Math.max(hi, v); } });
      });
      if (!isFinite(lo)) { lo = -1; hi = 1; }
      if (hi === lo) { hi += 1; lo -= 1; }
      var X = function (v) { return ml + (v - x0) / (x1 - x0) * (W - ml - mr); };
      var Y = function (v) { return mt + (hi - v) / (hi - lo) * (H - mt - mb); };
      var axes = svg("g", {"class": "axes"}, s);
      niceTicks(lo, hi, 6).forEach(function (v) {
        svg("line", {x1: ml, x2: W - mr, y1: Y(v), y2: Y(v), "class": "grid"}, axes);
        svg("text", {x: ml - 6, y: Y(v) + 4, "text-anchor": "end"}, axes, fmt(v));
      });
      niceTicks(x0, x1, 8).forEach(function (v) {
        svg("line", {x1: X(v), x2: X(v), y1: mt, y2: H - mb, "class": "grid"}, axes);
        svg("text", {x: X(v), y: H - mb + 16, "text-anchor": "middle"}, axes, fmt(v));
      });
      svg("text", {x: (W + ml) / 2, y: H - 6, "text-anchor": "middle"}, axes, "t" + (h.time_unit ? " [" + h.time_unit + "]" : ""));
      h.series.forEach(function (ser, k) {
        if (!shown[k]) return;
        var pts = [];
        ser.values.forEach(function (v, i) { if (v !== null) pts.push(X(t[i]).toFixed(2) + "," + Y(v).toFixed(2)); });
        svg("polyline", {points: pts.join(" "), fill: "none", stroke: palette[k % palette.length], "stroke-width": 1.8,
                         "class": "series", "data-series": ser.name}, s);
      });
      cursor = svg("line", {x1: -10, x2: -10, y1: mt, y2: H - mb, "class": "cursor"}, s);
      s.X = X;
    }
    s.addEventListener("mousemove", function (e) {
      var r = s.getBoundingClientRect(), x = (e.clientX - r.left) * W / r.width;
      var tv = x0 + (x - ml) / (W - ml - mr) * (x1 - x0), best = 0;
      t.forEach(function (v, i) { if (Math.abs(v - tv) < Math.abs(t[best] - tv)) best = i; });
      cursor.setAttribute("x1", s.X(t[best])); cursor.setAttribute("x2", s.X(t[best]));
      readout.textContent = "t = " + fmt(t[best]) + h.series.filter(function (ser, k) { return shown[k]; }).map(function (ser) {
        return ", " + ser.name + " = " + fmt(ser.values[best]) + (ser.unit ? " " + ser.unit : ""); }).join("");
    });
    draw();
  }
  function histories(main, data) {
    if (!data.histories.length) return;
    var sec = el("section", {id: "histories"}, main);
    el("h2", {}, sec, "Time histories");
    data.histories.forEach(function (h) { plot(sec, h); });
  }

  function animation(main, data) {
    var a = data.animation;
    if (!a) return;
    var sec = el("section", {id: "animation"}, main);
    el("h2", {}, sec, "Motion (" + a.source + ")");
    var geo = data.geometry, project = projector(geo.planar), index = {};
    a.points.forEach(function (n, i) { index[n] = i; });
    var pointAt = function (frame, name) { var i = 3 * index[name]; return [frame[i], frame[i + 1], frame[i + 2]]; };
    var all = [];
    a.frames.forEach(function (f) { a.points.forEach(function (n) { all.push(pointAt(f, n)); }); });
    var box = bounds(all, project), pad = 0.15 * box.size;
    var view = [box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad];
    var k = 420 / Math.max(view[2], view[3]);
    var s = svg("svg", {"class": "anim", viewBox: view.join(" "), width: k * view[2], height: k * view[3]}, sec);
    var g = svg("g", {}, s);
    svg("line", {x1: view[0], x2: view[0] + view[2], y1: project([0, 0, 0])[1], y2: project([0, 0, 0])[1], "class": "ground"}, g);
    var lines = geo.segments.map(function (seg, k) {
      return svg("line", {"class": "stick", stroke: palette[k % palette.length], "data-body": seg.body}, g);
    });
    var controls = el("div", {"class": "controls"}, sec);
    var button = el("button", {type: "button", id: "play"}, controls, "play");
    var slider = el("input", {type: "range", min: 0, max: a.frames.length - 1, value: 0, step: 1, id: "time-slider"}, controls);
    var label = el("span", {"class": "time"}, controls);
    function show(k) {
      var f = a.frames[k];
      geo.segments.forEach(function (seg, j) {
        var p = project(pointAt(f, seg.from)), q = project(pointAt(f, seg.to));
        lines[j].setAttribute("x1", p[0]); lines[j].setAttribute("y1", p[1]);
        lines[j].setAttribute("x2", q[0]); lines[j].setAttribute("y2", q[1]);
      });
      label.textContent = "t = " + fmt(a.time[k]) + " s";
      slider.value = k;
    }
    var playing = false, start = 0, t0 = 0;
    function tick(now) {
      if (!playing) return;
      var t = a.time[0] + t0 + (now - start) / 1000, k = 0;
      while (k + 1 < a.time.length && a.time[k + 1] <= t) ++k;
      show(k);
      if (k + 1 >= a.time.length) { playing = false; button.textContent = "play"; return; }
      window.requestAnimationFrame(tick);
    }
    button.addEventListener("click", function () {
      playing = !playing;
      button.textContent = playing ? "pause" : "play";
      if (playing) {
        var k = Number(slider.value);
        if (k + 1 >= a.time.length) k = 0;
        t0 = a.time[k] - a.time[0];
        start = performance.now();
        window.requestAnimationFrame(tick);
      }
    });
    slider.addEventListener("input", function () { playing = false; button.textContent = "play"; show(Number(slider.value)); });
    show(0);
  }

  // ---- the page ---------------------------------------------------------------------------
  function render(data, main) {
    while (main.firstChild) main.removeChild(main.firstChild);
    el("h1", {}, main, data.title + ": Alembert report");
    if (!data.geometry.planar) {
      // a spatial model: sliders turn the drawings
      var turn = el("div", {"class": "controls", id: "view-controls"}, main);
      [["turn", -3.1416, 3.1416], ["tilt", -1.5, 1.5]].forEach(function (c) {
        var lab = el("label", {}, turn, c[0] + " ");
        var input = el("input", {type: "range", min: c[1], max: c[2], step: 0.01, value: view[c[0]], id: "view-" + c[0]}, lab);
        input.addEventListener("change", function () { view[c[0]] = Number(input.value); render(data, main); });
      });
    }
    if (!window.katex)
      el("p", {"class": "warning"}, main, "KaTeX was not found when this report was written, so equations show as TeX; " +
         "install Debian's libjs-katex (or set ALEMBERT_KATEX_DIR) and write the report again.");
    data.notes.forEach(function (n) { el("p", {"class": "warning"}, main, n); });
    if (data.roadmap.length) roadmap(main, data);
    animation(main, data);
    histories(main, data);
    model(main, data);
  }
  try {
    render(JSON.parse(document.getElementById("alembert-data").textContent), document.getElementById("report"));
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
    }
    var slider = document.getElementById("time-slider");
    if (slider) {
      var stick = document.querySelector("svg.anim line.stick"), x0 = stick.getAttribute("x2");
      slider.value = slider.max;
      slider.dispatchEvent(new Event("input"));
      expect(stick.getAttribute("x2") !== x0, "the time slider moves the model");
      var play = document.getElementById("play");
      slider.value = 0;
      slider.dispatchEvent(new Event("input"));
      play.click();
      expect(play.textContent === "pause", "play starts the animation");
      play.click();
      expect(play.textContent === "play", "pause stops it");
    }
    el("pre", {id: "alembert-exercise"}, document.body, out.join("\n"));
  }
  if (!failed && window.location.hash === "#exercise") {
    try { exercise(); } catch (e) { fail("exercising the controls failed: " + e); }
  }
  status.setAttribute("data-status", failed ? "error" : "ready");
  status.textContent = failed ? "the report has errors (below)" : "";
})();
