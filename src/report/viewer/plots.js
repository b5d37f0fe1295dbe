// SPDX-License-Identifier: MIT
// Alembert's report viewer: the plots of the time histories and of the results' sweeps. One
// unit per plot (its y axis labelled with it), at most ten series per plot in ten
// well-separated colours, the plots of one history stacked on a shared time axis, and one time
// cursor for the whole page; a sweep's plots (against the swept value) share a cursor of their
// own.
// Inlined before viewer.js, which calls alembertPlots(helpers).
var alembertPlots = function (helpers) {
  "use strict";
  var el = helpers.el, svg = helpers.svg, fmt = helpers.fmt;

  // ten hues far apart (the "category 10" colours); a plot holds at most as many series as
  // there are colours, so no two series of one plot share one
  var palette = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                 "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"];

  // a unit as the axis shows it: N*m as N·m; a series without one is said to have none
  function unitText(unit) { return unit ? unit.replace(/\*/g, "\u00b7") : "no unit"; }

  // a history's series as plots: one per unit (and per axis where the series name one: a
  // sweep's real and imaginary parts), in the order they first appear; a unit with more series
  // than colours over as few plots as hold them, the series shared evenly
  function plotGroups(series) {
    var keys = [], byKey = Object.create(null);
    series.forEach(function (ser, k) {
      var key = (ser.axis || "") + "\u0000" + ser.unit;
      if (!byKey[key]) { byKey[key] = []; keys.push(key); }
      byKey[key].push(k);
    });
    var groups = [];
    keys.forEach(function (key) {
      var ks = byKey[key], parts = Math.ceil(ks.length / palette.length), size = Math.ceil(ks.length / parts);
      for (var i = 0; i < parts; ++i)
        groups.push({unit: series[ks[0]].unit, axis: series[ks[0]].axis || "", series: ks.slice(i * size, (i + 1) * size),
                     part: i + 1, parts: parts});
    });
    return groups;
  }

  function niceTicks(lo, hi, n) {
    var span = hi - lo || 1, step = Math.pow(10, Math.floor(Math.log10(span / n)));
    [1, 2, 5, 10].some(function (m) { if (span / (step * m) <= n) { step *= m; return true; } return false; });
    var out = [];
    for (var v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) out.push(Math.abs(v) < 1e-12 * span ? 0 : v);
    return out;
  }

  // the row of sorted times `t` nearest to `v`
  function nearest(t, v) {
    var lo = 0, hi = t.length - 1;
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (t[mid] <= v) lo = mid; else hi = mid;
    }
    return Math.abs(t[hi] - v) < Math.abs(t[lo] - v) ? hi : lo;
  }

  var plots = [];        // every plot on the page: its setCursor(time)
  var onCursor = null;   // what else follows the cursor (the animation)
  // the cursor at time `v` on every plot, and the animation there unless it moved the cursor
  function cursorAt(v, fromAnimation) {
    plots.forEach(function (p) { p.setCursor(v); });
    if (onCursor && !fromAnimation) onCursor(v);
  }

  var plotCount = 0;
  // one plot of history `h`: its `group` of series (one unit) on the time axis `axis`, which
  // the history's plots share (zooming one zooms them all). A sweep's (h.sweep) is drawn
  // against the swept value h.x_name, its cursor axis.cursorAt, and its classes are its own
  // (figure.sweep-plot, svg.sweep-svg, polyline.sweep-series), apart from the time plots'.
  function plot(parent, h, group, axis) {
    ++plotCount;
    var W = 720, H = 240, ml = 76, mr = 20, mt = 12, mb = 36;
    var kind = h.sweep ? "sweep-" : "", xName = h.x_name || "t";
    var title = h.title + ": " + (group.axis ? group.axis + "s, " : "") + unitText(group.unit) +
                (group.parts > 1 ? ", " + group.part + " of " + group.parts : "");
    var fig = el("figure", {"class": h.sweep ? "sweep-plot" : "plot", "data-unit": group.unit, "data-title": title,
                            "data-axis": group.axis}, parent);
    el("figcaption", {}, fig, title + (h.plotted_rows < h.rows ? " (" + h.rows + " rows, " + h.plotted_rows +
       " plotted: each stretch of the run keeps its least and greatest values)" : ""));
    var s = svg("svg", {"class": kind + "plot-svg", viewBox: "0 0 " + W + " " + H, width: W, height: H}, fig);
    var series = group.series.map(function (k) { return h.series[k]; });
    var shown = series.map(function () { return true; });
    var readout = el("div", {"class": "readout"}, fig, "move over the plot to read values" +
                     (h.sweep ? "" : " (the animation follows)"));
    var legend = el("div", {"class": "legend"}, fig);
    series.forEach(function (ser, i) {
      var lab = el("label", {style: "color:" + palette[i]}, legend);
      var box = el("input", {type: "checkbox", checked: "checked", "data-series": ser.name}, lab);
      lab.appendChild(document.createTextNode(" " + ser.name));
      box.addEventListener("change", function () { shown[i] = box.checked; draw(); });
    });
    var t = h.time, cursor = null, band = null, row = -1;
    var zoomBar = el("div", {"class": "zoom"}, fig);
    var reset = el("button", {type: "button", "class": "zoom-reset", disabled: "disabled"}, zoomBar, "show all");
    el("span", {"class": "note"}, zoomBar, " drag across the plot to zoom into a " + (h.sweep ? "range of " + xName : "time range") +
       "; double-click or \u201cshow all\u201d to zoom out");
    reset.addEventListener("click", function () { axis.zoomTo(axis.full0, axis.full1); });
    function timeAt(e) {
      var r = s.getBoundingClientRect(), x = (e.clientX - r.left) * W / r.width;
      return axis.x0 + (x - ml) / (W - ml - mr) * (axis.x1 - axis.x0);
    }
    function draw() {
      var x0 = axis.x0, x1 = axis.x1;
      if (x0 === axis.full0 && x1 === axis.full1) reset.setAttribute("disabled", "disabled");
      else reset.removeAttribute("disabled");
      if (axis.zoomed) fig.setAttribute("data-range", fmt(x0) + " " + fmt(x1));
      while (s.firstChild) s.removeChild(s.firstChild);
      var lo = Infinity, hi = -Infinity;
      series.forEach(function (ser, i) {
        if (!shown[i]) return;
        ser.values.forEach(function (v, j) {
          if (v !== null && t[j] >= x0 && t[j] <= x1) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
        });
      });
      if (!isFinite(lo)) { lo = -1; hi = 1; }
      if (hi === lo) { hi += 1; lo -= 1; }
      var X = function (v) { return ml + (v - x0) / (x1 - x0) * (W - ml - mr); };
      var Y = function (v) { return mt + (hi - v) / (hi - lo) * (H - mt - mb); };
      var axes = svg("g", {"class": "axes"}, s);
      niceTicks(lo, hi, 5).forEach(function (v) {
        svg("line", {x1: ml, x2: W - mr, y1: Y(v), y2: Y(v), "class": "grid"}, axes);
        svg("text", {x: ml - 6, y: Y(v) + 4, "text-anchor": "end"}, axes, fmt(v));
      });
      niceTicks(x0, x1, 8).forEach(function (v) {
        svg("line", {x1: X(v), x2: X(v), y1: mt, y2: H - mb, "class": "grid"}, axes);
        svg("text", {x: X(v), y: H - mb + 16, "text-anchor": "middle"}, axes, fmt(v));
      });
      svg("text", {x: (W + ml) / 2, y: H - 4, "text-anchor": "middle", "class": "x-label"}, axes,
          xName + (h.time_unit ? " [" + unitText(h.time_unit) + "]" : ""));
      var ym = (mt + H - mb) / 2;
      svg("text", {x: 14, y: ym, "text-anchor": "middle", transform: "rotate(-90 14 " + ym + ")", "class": "y-label"},
          axes, unitText(group.unit));
      var clip = "clip-" + plotCount;
      svg("rect", {x: ml, y: mt, width: W - ml - mr, height: H - mt - mb}, svg("clipPath", {id: clip}, s));
      // a sweep's samples marked where they are few enough to be told apart
      var marks = h.sweep && t.length <= 200;
      series.forEach(function (ser, i) {
        if (!shown[i]) return;
        var pts = [];
        ser.values.forEach(function (v, j) {
          // the rows in view and one on either side, so lines reach the edges
          if (v !== null && (j + 1 < t.length ? t[j + 1] >= x0 : true) && (j > 0 ? t[j - 1] <= x1 : true))
            pts.push(X(t[j]).toFixed(2) + "," + Y(v).toFixed(2));
        });
        svg("polyline", {points: pts.join(" "), fill: "none", stroke: palette[i], "stroke-width": 1.8, "class": kind + "series",
                         "data-series": ser.name, "data-unit": ser.unit, "clip-path": "url(#" + clip + ")"}, s);
        if (marks)
          pts.forEach(function (p) {
            var xy = p.split(",");
            svg("circle", {cx: xy[0], cy: xy[1], r: 2.2, fill: palette[i], "class": "sample", "clip-path": "url(#" + clip + ")"}, s);
          });
      });
      cursor = svg("line", {x1: -10, x2: -10, y1: mt, y2: H - mb, "class": "cursor"}, s);
      band = svg("rect", {x: 0, y: mt, width: 0, height: H - mt - mb, "class": "zoom-band"}, s);
      s.X = X;
      if (row >= 0) place();
    }
    // the cursor on row `row`, and the values there
    function place() {
      cursor.setAttribute("x1", s.X(t[row])); cursor.setAttribute("x2", s.X(t[row]));
      fig.setAttribute("data-cursor", t[row]);
      readout.textContent = xName + " = " + fmt(t[row]) + (h.sweep && h.time_unit ? " " + h.time_unit : "") + series.filter(function (ser, i) { return shown[i]; }).map(function (ser) {
        return ", " + ser.name + " = " + fmt(ser.values[row]) + (ser.unit ? " " + ser.unit : ""); }).join("");
    }
    var dragFrom = null;
    s.addEventListener("mousedown", function (e) { dragFrom = timeAt(e); e.preventDefault(); });
    window.addEventListener("mouseup", function (e) {
      if (dragFrom === null) return;
      var a = dragFrom, b = timeAt(e);
      dragFrom = null;
      band.setAttribute("width", 0);
      if (Math.abs(b - a) > 0.01 * (axis.x1 - axis.x0)) axis.zoomTo(Math.min(a, b), Math.max(a, b));
    });
    s.addEventListener("dblclick", function () { axis.zoomTo(axis.full0, axis.full1); });
    s.addEventListener("mousemove", function (e) {
      var tv = timeAt(e);
      if (dragFrom !== null) {
        var xa = s.X(Math.max(axis.x0, Math.min(axis.x1, dragFrom))), xb = s.X(Math.max(axis.x0, Math.min(axis.x1, tv)));
        band.setAttribute("x", Math.min(xa, xb)); band.setAttribute("width", Math.abs(xb - xa));
      }
      (axis.cursorAt || cursorAt)(t[nearest(t, tv)]);
    });
    draw();
    return {draw: draw, setCursor: function (v) { row = nearest(t, v); place(); }};
  }

  // every history's plots, under a heading naming the statement that computed it
  function histories(main, data) {
    if (!data.histories.length) return;
    var sec = el("section", {id: "histories"}, main);
    el("h2", {}, sec, "Time histories");
    el("p", {"class": "note"}, sec, "One unit per plot. Moving over a plot moves the cursor on every plot and the " +
       "animation to that time; a unit with more than " + palette.length + " series is split over several plots.");
    data.histories.forEach(function (h) {
      var box = el("div", {"class": "history"}, sec);
      el("h3", {}, box, h.title);
      var t = h.time, full0 = t[0], full1 = t[t.length - 1] === full0 ? full0 + 1 : t[t.length - 1];
      var own = [];
      var axis = {full0: full0, full1: full1, x0: full0, x1: full1, zoomed: false,
                  zoomTo: function (a, b) {
                    if (!(b > a)) return;
                    axis.x0 = Math.max(full0, a); axis.x1 = Math.min(full1, b); axis.zoomed = true;
                    own.forEach(function (p) { p.draw(); });
                  }};
      plotGroups(h.series).forEach(function (g) {
        var p = plot(box, h, g, axis);
        own.push(p);
        plots.push(p);
      });
    });
  }

  // the plots of result `r`'s sweep under its text in `box`: against the swept value, one
  // plot per axis and unit (the real parts, the imaginary parts), with a cursor of their own
  function sweep(box, r) {
    var w = r.sweep;
    if (!w || !w.values.length) return;
    var h = {sweep: true, title: w.title, rows: w.rows, plotted_rows: w.plotted_rows, time: w.values, time_unit: w.unit,
             x_name: w.parameter, series: w.series};
    var div = el("div", {"class": "sweep", "data-parameter": w.parameter}, box);
    var x = w.values, full0 = x[0], full1 = x[x.length - 1] === full0 ? full0 + 1 : x[x.length - 1];
    var own = [];
    var axis = {full0: full0, full1: full1, x0: full0, x1: full1, zoomed: false,
                zoomTo: function (a, b) {
                  if (!(b > a)) return;
                  axis.x0 = Math.max(full0, a); axis.x1 = Math.min(full1, b); axis.zoomed = true;
                  own.forEach(function (p) { p.draw(); });
                },
                cursorAt: function (v) { own.forEach(function (p) { p.setCursor(v); }); }};
    plotGroups(w.series).forEach(function (g) { own.push(plot(div, h, g, axis)); });
  }

  return {palette: palette, sweep: sweep, unitText: unitText, plotGroups: plotGroups, histories: histories, cursorAt: cursorAt,
          follow: function (f) { onCursor = f; }};
};
