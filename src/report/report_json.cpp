// SPDX-License-Identifier: MIT
// The report's data: model, road-map rows with their free-body diagrams, histories, motion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <set>
#include <string>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

// ---- a small JSON writer: objects keep the order keys are written in -----------------------

std::string num(double v) {
    if (!std::isfinite(v)) return "null";
    if (v == 0) return "0";  // no -0
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string str(const std::string& s) { return "\"" + report_detail::json_escape(s) + "\""; }

struct Obj {
    std::string s = "{";
    Obj& add(const std::string& key, const std::string& raw) {
        s += (s.size() > 1 ? "," : "") + str(key) + ":" + raw;
        return *this;
    }
    std::string done() const { return s + "}"; }
};

std::string arr(const std::vector<std::string>& items) {
    std::string s = "[";
    for (std::size_t i = 0; i < items.size(); ++i) s += (i ? "," : "") + items[i];
    return s + "]";
}

std::string str_arr(const std::vector<std::string>& items) {
    std::vector<std::string> q;
    for (const std::string& i : items) q.push_back(str(i));
    return arr(q);
}

std::string num_arr(const std::vector<double>& v) {
    std::vector<std::string> q;
    for (double x : v) q.push_back(num(x));
    return arr(q);
}

bool member(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

std::string ground_or(const System& sys, const Body* b) {
    return b ? b->name() : sys.newtonian().name();
}

// ---- numbers at the configuration ----------------------------------------------------------

/// Values for evaluating the model's geometry: the configuration, every other variable and
/// rate 0, unknowns and specified quantities 1 (so a load's arrow shows its positive sense).
struct Evaluation {
    const System& sys;
    exmap values;

    Evaluation(const System& s, const exmap& configuration) : sys(s) {
        const SymbolTable& st = sys.symbols();
        for (SymbolKind k : {SymbolKind::variable, SymbolKind::specified})
            for (const ex& x : st.symbols(k)) values[x] = 0;
        for (const ex& x : st.symbols(SymbolKind::unknown)) values[x] = 1;
        for (const auto& [x, v] : configuration) values[x] = v;
    }
    /// The value of `e`, or NaN if it needs what is not known.
    double at(const ex& e) const {
        try {
            return sys.symbols().evaluate(e, values);
        } catch (const std::exception&) {
            return std::nan("");  // a library error, or GiNaC's (a spring of length 0 at rest)
        }
    }
    std::vector<double> in_newtonian(const Vector& v) const {
        Col3 c = v.components_in(sys.newtonian());
        return {at(c[0]), at(c[1]), at(c[2])};
    }
};

std::vector<const Point*> placed_points(const System& sys) {
    std::vector<const Point*> out;
    for (const Point* p : sys.points()) {
        try {
            (void)p->pos_from(sys.origin());
            out.push_back(p);
        } catch (const Error&) {
            // a point with no path to the origin has no place in a drawing
        }
    }
    return out;
}

// the point a torque on B is drawn at: where B is joined to what is outside B, else Bcm
const Point* torque_point(const System& sys, const Body* B) {
    for (const Point* p : sys.points())
        if (p->owner() == B && p->located_from() && p->located_from()->owner() != B) return p;
    return B ? &B->cm() : &sys.origin();
}

bool has_unknown(const System& sys, const Vector& v) {
    const SymbolTable& st = sys.symbols();
    for (const auto& part : v.components())
        for (int i = 0; i < 3; ++i)
            for (const ex& s : symbols_of(part.second[i]))
                if (st.owns(s) && st.kind(s) == SymbolKind::unknown) return true;
    return false;
}

// ---- the parts of the page's data ----------------------------------------------------------

std::string unit_of(const ReportContent& c, const std::string& name) {
    auto it = c.units.find(name);
    return it == c.units.end() ? "" : it->second;
}

std::string model_json(const ReportContent& c) {
    const System& sys = *c.system;
    const SymbolTable& st = sys.symbols();
    std::vector<std::string> frames{str(sys.newtonian().name())}, bodies, points, loads, coords,
        constants, unknowns;
    for (const Body* b : sys.bodies()) {
        if (b->frame() && b->frame() != &sys.newtonian()) frames.push_back(str(b->frame()->name()));
        Obj o;
        o.add("name", str(b->name())).add("cm", str(b->cm().name()));
        o.add("kind", str(b->frame() ? "rigid body" : "particle"));
        o.add("mass", str(b->has_mass() ? to_string(b->mass()) : ""));
        bodies.push_back(o.done());
    }
    for (const Point* p : sys.points()) {
        Obj o;
        o.add("name", str(p->name())).add("on", str(p->owner() ? p->owner()->name() : ""));
        const Point* from = p->located_from();
        o.add("from", str(from ? from->name() : ""));
        o.add("position", str(from ? p->pos_from(*from).to_string() : ""));
        points.push_back(o.done());
    }
    for (const Load& l : sys.loads()) {
        Obj o;
        o.add("label", str(l.label))
            .add("kind", str(l.kind == LoadKind::force ? "force" : "torque"));
        o.add("at", str(l.point ? l.point->name() : "")).add("on", str(l.on ? l.on->name() : ""));
        o.add("from", str(ground_or(sys, l.from))).add("vector", str(l.vector.to_string()));
        loads.push_back(o.done());
    }
    if (!sys.gravity().is_zero()) {
        Obj o;
        o.add("label", str("gravity")).add("kind", str("gravity")).add("at", str("mass centres"));
        o.add("on", str("")).add("from", str(sys.newtonian().name()));
        o.add("vector", str(sys.gravity().to_string()));
        loads.push_back(o.done());
    }
    for (const TimeVariable& q : c.coordinates)
        coords.push_back(
            Obj().add("name", str(q.name())).add("unit", str(unit_of(c, q.name()))).done());
    for (const ex& k : st.symbols(SymbolKind::constant)) {
        std::optional<double> v = st.value(k);
        constants.push_back(Obj()
                                .add("name", str(st.name(k)))
                                .add("value", v ? num(*v) : "null")
                                .add("unit", str(unit_of(c, st.name(k))))
                                .done());
    }
    for (const ex& k : st.symbols(SymbolKind::unknown))
        unknowns.push_back(
            Obj().add("name", str(st.name(k))).add("unit", str(unit_of(c, st.name(k)))).done());
    Obj o;
    o.add("frames", arr(frames)).add("bodies", arr(bodies)).add("points", arr(points));
    o.add("loads", arr(loads)).add("coordinates", arr(coords)).add("constants", arr(constants));
    o.add("unknowns", arr(unknowns));
    return o.done();
}

struct Segment {
    std::string body, from, to;
};

// sticks: a point located from another by a vector fixed in one body's frame is a segment of
// that body; other nonzero links belong to the owner of the located point
std::vector<Segment> segments_of(const System& sys, const std::vector<const Point*>& placed) {
    std::vector<Segment> out;
    for (const Point* p : placed) {
        const Point* q = p->located_from();
        if (!q) continue;
        Vector r = p->pos_from(*q);
        if (r.is_zero()) continue;
        std::set<const Frame*> frames;
        for (const auto& part : r.components()) frames.insert(part.first);
        const Body* owner = frames.size() == 1 ? sys.body_of(**frames.begin()) : nullptr;
        if (!owner) owner = p->owner();
        out.push_back({owner ? owner->name() : "", q->name(), p->name()});
    }
    return out;
}

std::string geometry_json(const System& sys, const Evaluation& ev,
                          const std::vector<const Point*>& placed, bool* planar) {
    std::vector<std::string> pts, segs;
    *planar = true;
    for (const Point* p : placed) {
        Col3 c = p->pos_from(sys.origin()).components_in(sys.newtonian());
        if (!simplify(sys.symbols().expand_intermediates(c[2])).is_zero()) *planar = false;
        std::vector<double> x = ev.in_newtonian(p->pos_from(sys.origin()));
        pts.push_back(Obj().add("name", str(p->name())).add("at", num_arr(x)).done());
    }
    for (const Segment& s : segments_of(sys, placed))
        segs.push_back(
            Obj().add("body", str(s.body)).add("from", str(s.from)).add("to", str(s.to)).done());
    Obj o;
    o.add("planar", *planar ? "true" : "false").add("points", arr(pts)).add("segments", arr(segs));
    return o.done();
}

/// The loads of one free-body diagram, as the viewer draws them.
std::string diagram_json(const System& sys, const Evaluation& ev, const RoadmapRow& r) {
    std::vector<std::string> loads;
    auto load = [&](const std::string& kind, const std::string& label, const Point* at,
                    const std::vector<double>& dir, bool unknown) {
        Obj o;
        o.add("kind", str(kind)).add("label", str(label)).add("at", str(at->name()));
        o.add("vector", num_arr(dir)).add("unknown", unknown ? "true" : "false");
        loads.push_back(o.done());
    };
    const BodySet& S = r.system;
    for (const Load& l : sys.loads()) {
        if (!member(S, l.on) || member(S, l.from)) continue;
        std::string label = l.label.empty() ? (l.kind == LoadKind::force ? "F" : "T") : l.label;
        if (l.kind == LoadKind::force)
            load("force", label, l.point, ev.in_newtonian(l.vector), has_unknown(sys, l.vector));
        else
            load("torque", label, torque_point(sys, l.on), ev.in_newtonian(l.vector),
                 has_unknown(sys, l.vector));
    }
    if (!sys.gravity().is_zero())
        for (const Body* b : S)
            if (b->has_mass())
                load("gravity", b->name() + " g", &b->cm(), ev.in_newtonian(sys.gravity()), false);
    for (const Point* p : sys.points()) {
        if (!member(S, p->owner()) || !p->located_from()) continue;
        const Point* from = p->located_from();
        // a declared reaction's measures, drawn above, stand for the joint's force
        if (member(S, from->owner()) || sys.find_joint_reaction(*p, from->owner(), p->owner()))
            continue;
        load("joint", "from " + ground_or(sys, from->owner()), p, {}, true);
    }
    std::vector<std::string> names;
    for (const Body* b : S) names.push_back(b->name());
    Obj o;
    o.add("system", str_arr(names)).add("about", str(r.about ? r.about->name() : ""));
    o.add("direction", num_arr(ev.in_newtonian(r.direction))).add("loads", arr(loads));
    return o.done();
}

std::string motion_word(Motion m) {
    switch (m) {
        case Motion::translate:
            return "translate";
        case Motion::rotate:
            return "rotate";
        case Motion::constraint:
            return "constraint";
    }
    return "";
}

// an equation as people read it: collected in the accelerations when small enough
ex readable_equation(const System& sys, const ex& e) {
    if (count_ops(e) > 4000) return e;
    std::vector<ex> acc;
    const SymbolTable& st = sys.symbols();
    for (const ex& s : symbols_of(e))
        if (st.owns(s) && st.kind(s) == SymbolKind::variable && st.derivative_order(s) == 2)
            acc.push_back(s);
    std::sort(acc.begin(), acc.end(),
              [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    return acc.empty() ? simplify(e) : collect_in(simplify(e), acc);
}

// "0 = t1 + t2 ...": the terms holding the row's variable first, the others in the order of
// their printed form; one line per few terms, so long equations wrap
std::string equation_tex(const ex& e, const ex& variable) {
    std::vector<std::string> terms;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        std::vector<std::pair<std::string, ex>> keyed;
        for (std::size_t i = 0; i < e.nops(); ++i) keyed.emplace_back(to_string(e.op(i)), e.op(i));
        std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
            const bool va = a.second.has(variable), vb = b.second.has(variable);
            return va != vb ? va : a.first < b.first;
        });
        for (const auto& k : keyed) terms.push_back(to_latex(k.second));
    } else {
        terms.push_back(to_latex(e));
    }
    std::string out = "\\begin{aligned} 0 ={} & ";
    std::size_t line = 0;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        std::string t = terms[i];
        bool neg = !t.empty() && t[0] == '-';
        if (i > 0 && line + t.size() > 110) {
            out += " \\\\ & ";
            line = 0;
        }
        if (i > 0 || neg)
            out += neg ? " - " + t.substr(1) : " + " + t;
        else
            out += t;
        line += t.size();
    }
    return out + " \\end{aligned}";
}

// the intermediates `e` uses, with those their definitions use, in dependency order, as TeX
std::vector<std::string> intermediate_definitions(const System& sys, const ex& e) {
    const SymbolTable& st = sys.symbols();
    std::set<std::string> used;
    std::vector<ex> todo{e};
    while (!todo.empty() && used.size() < 200) {
        ex x = todo.back();
        todo.pop_back();
        for (const ex& s : symbols_of(x))
            if (st.owns(s) && st.kind(s) == SymbolKind::intermediate &&
                used.insert(st.name(s)).second)
                todo.push_back(st.definition(s));
    }
    std::vector<std::string> defs;
    for (const ex& z : st.intermediates())
        if (used.count(st.name(z)))
            defs.push_back(to_latex(z) + " = " + to_latex(st.definition(z)));
    return defs;
}

// the direction as the road-map table writes it: in N when it is constant there
std::string direction_words(const System& sys, const Vector& u) {
    Col3 c = u.components_in(sys.newtonian());
    for (int i = 0; i < 3; ++i) {
        c[i] = simplify(c[i]);
        if (!GiNaC::is_a<GiNaC::numeric>(c[i])) return u.to_string();
    }
    return Vector(sys.newtonian(), c).to_string();
}

std::string row_json(const System& sys, const Evaluation& ev, const RoadmapRow& r) {
    std::vector<std::string> extra, names;
    for (const ex& x : r.additional_unknowns) extra.push_back(to_string(x));
    for (const Body* b : r.system) names.push_back(b->name());
    Obj o;
    o.add("variable", str(to_string(r.variable))).add("variable_tex", str(to_latex(r.variable)));
    o.add("motion", str(motion_word(r.motion)));
    o.add("analysis", str(r.analysis == Analysis::statics ? "statics" : "dynamics"));
    o.add("direction",
          str(r.motion == Motion::constraint ? "" : direction_words(sys, r.direction)));
    o.add("system", str_arr(names)).add("fbd", str_arr(r.fbd));
    o.add("about", str(r.about ? r.about->name() : "")).add("constraint", str(r.constraint));
    o.add("equation", str(equation_tex(readable_equation(sys, r.equation), r.variable)));
    o.add("intermediates", str_arr(intermediate_definitions(sys, r.equation)));
    o.add("additional_unknowns", str_arr(extra)).add("note", str(r.note));
    o.add("diagram", r.motion == Motion::constraint ? "null" : diagram_json(sys, ev, r));
    return o.done();
}

// every k-th row (and the last), so that long runs plot quickly: at most kMaxPlotRows
constexpr std::size_t kMaxPlotRows = 2000;

std::vector<double> thinned(const std::vector<double>& v) {
    const std::size_t step = std::max<std::size_t>(1, (v.size() + kMaxPlotRows - 1) / kMaxPlotRows);
    if (step == 1) return v;
    std::vector<double> out;
    for (std::size_t k = 0; k < v.size(); k += step) out.push_back(v[k]);
    if ((v.size() - 1) % step != 0) out.push_back(v.back());
    return out;
}

std::string history_json(const ReportHistory& h) {
    std::vector<std::string> series;
    const Table& t = h.table;
    for (std::size_t c = 1; c < t.columns.size(); ++c)
        series.push_back(Obj()
                             .add("name", str(t.names[c]))
                             .add("unit", str(t.units[c]))
                             .add("values", num_arr(thinned(t.columns[c])))
                             .done());
    Obj o;
    o.add("title", str(h.title)).add("rows", num(static_cast<double>(t.row_count())));
    o.add("time", t.columns.empty() ? "[]" : num_arr(thinned(t.columns[0])));
    o.add("time_unit", str(t.units.empty() ? "" : t.units[0]));
    o.add("series", arr(series));
    return o.done();
}

// the positions of the placed points at each sample of the first history with a motion,
// thinned to at most 400 frames, through one compiled tape
std::string animation_json(const ReportContent& c, const std::vector<const Point*>& placed) {
    const System& sys = *c.system;
    for (const ReportHistory& h : c.histories) {
        if (h.motion.empty() || h.table.columns.empty()) continue;
        std::vector<ex> inputs, outputs;
        for (const TimeVariable& q : h.coordinates) inputs.push_back(q.symbol());
        for (const Point* p : placed) {
            Col3 x = p->pos_from(sys.origin()).components_in(sys.newtonian());
            for (int i = 0; i < 3; ++i) outputs.push_back(x[i]);
        }
        CompiledExpressions tape;
        try {
            tape = CompiledExpressions(sys.symbols(), inputs, outputs);
        } catch (const Error&) {
            return "null";  // positions need more than the coordinates (rates, inputs)
        }
        const std::vector<double>& t = h.table.columns[0];
        const std::size_t n = t.size(), step = std::max<std::size_t>(1, (n + 399) / 400);
        std::vector<std::string> times, frames;
        std::vector<double> in(inputs.size()), out(outputs.size());
        for (std::size_t k = 0; k < n; k += step) {
            for (std::size_t j = 0; j < inputs.size(); ++j) in[j] = h.motion[j][k];
            tape.evaluate(in.data(), out.data());
            times.push_back(num(t[k]));
            frames.push_back(num_arr(out));
        }
        std::vector<std::string> names;
        for (const Point* p : placed) names.push_back(p->name());
        Obj o;
        o.add("source", str(h.title)).add("points", str_arr(names)).add("time", arr(times));
        o.add("frames", arr(frames));
        return o.done();
    }
    return "null";
}

// text for LaTeX's text mode
std::string tex_text(const std::string& s) {
    std::string o;
    for (char ch : s) {
        switch (ch) {
            case '_':
                o += "\\_";
                break;
            case '&':
                o += "\\&";
                break;
            case '%':
                o += "\\%";
                break;
            case '#':
                o += "\\#";
                break;
            case '$':
                o += "\\$";
                break;
            case '{':
                o += "\\{";
                break;
            case '}':
                o += "\\}";
                break;
            case '>':
                o += "\\textgreater{}";
                break;
            case '<':
                o += "\\textless{}";
                break;
            case '^':
                o += "\\textasciicircum{}";
                break;
            case '~':
                o += "\\textasciitilde{}";
                break;
            case '\\':
                o += "\\textbackslash{}";
                break;
            default:
                o += ch;
        }
    }
    return o;
}

std::string set_words(const BodySet& S) {
    std::string s = "\\{";
    for (std::size_t i = 0; i < S.size(); ++i) s += (i ? ", " : "") + tex_text(S[i]->name());
    return s + "\\}";
}

}  // namespace

std::string render_report_latex(const ReportContent& c) {
    if (!c.system)
        throw ArgumentError(
            "render_report_latex(): the report has no model; build one (newtonian N, ...) before "
            "report");
    const System& sys = *c.system;
    std::string t;
    t += "% Generated by Alembert from the model '" + c.title + "'; regenerate rather than edit.\n";
    t += "\\documentclass[a4paper]{article}\n\\usepackage{amsmath}\n\\usepackage[margin=2cm]{"
         "geometry}\n";
    t += "\\begin{document}\n\\section*{MG road-map of " + tex_text(c.title) + "}\n\n";
    t += "Each equation is $E = \\text{applied} - \\text{inertial} = 0$; the free-body diagram of "
         "$S$ lists the loads "
         "external to $S$.\n\n";
    t += "\\begin{tabular}{llllll}\n\\hline\nvariable & translate/rotate & direction & system $S$ "
         "& about point & "
         "additional unknowns \\\\\n\\hline\n";
    for (const RoadmapRow& r : c.rows) {
        std::string extra;
        for (std::size_t i = 0; i < r.additional_unknowns.size(); ++i)
            extra += (i ? ", " : "") + std::string("$") + to_latex(r.additional_unknowns[i]) + "$";
        const bool constraint = r.motion == Motion::constraint;
        t += "$" + to_latex(r.variable) + "$ & " + motion_word(r.motion) + " & " +
             (constraint ? "--" : tex_text(direction_words(sys, r.direction))) + " & " +
             (constraint ? "--" : "$" + set_words(r.system) + "$") + " & " +
             (r.about ? tex_text(r.about->name()) : "--") + " & " +
             (extra.empty() ? "none" : extra) + " \\\\\n";
    }
    t += "\\hline\n\\end{tabular}\n\n\\subsection*{Free-body diagrams}\n\\begin{itemize}\n";
    for (const RoadmapRow& r : c.rows) {
        if (r.motion == Motion::constraint) continue;
        t += "\\item $S = " + set_words(r.system) + "$ (for $" + to_latex(r.variable) + "$):";
        for (std::size_t i = 0; i < r.fbd.size(); ++i) t += (i ? "; " : " ") + tex_text(r.fbd[i]);
        t += ".\n";
    }
    t += "\\end{itemize}\n\n\\subsection*{Equations}\n";
    for (const RoadmapRow& r : c.rows) {
        t += "\\[ E_{" + to_latex(r.variable) + "}: \\quad " +
             equation_tex(readable_equation(sys, r.equation), r.variable) + " \\]\n";
        std::vector<std::string> defs = intermediate_definitions(sys, r.equation);
        if (!defs.empty()) {
            t += "where\n";
            for (const std::string& d : defs) t += "\\[ " + d + " \\]\n";
        }
    }
    t += "\\end{document}\n";
    return t;
}

std::string render_report_json(const ReportContent& c) {
    if (!c.system)
        throw ArgumentError(
            "render_report_json(): the report has no model; build one (newtonian N, ...) before "
            "report");
    const System& sys = *c.system;
    Evaluation ev(sys, c.configuration);
    std::vector<const Point*> placed = placed_points(sys);
    bool planar = true;
    std::string geometry = geometry_json(sys, ev, placed, &planar);
    std::vector<std::string> rows, histories, config;
    for (const RoadmapRow& r : c.rows) rows.push_back(row_json(sys, ev, r));
    for (const ReportHistory& h : c.histories) histories.push_back(history_json(h));
    for (const TimeVariable& q : c.coordinates) {
        auto it = ev.values.find(q.symbol());
        double v =
            it == ev.values.end() ? 0.0 : GiNaC::ex_to<GiNaC::numeric>(it->second).to_double();
        config.push_back(Obj().add("name", str(q.name())).add("value", num(v)).done());
    }
    Obj o;
    o.add("format", "1")
        .add("title", str(c.title))
        .add("notes", str_arr(c.notes))
        .add("model", model_json(c));
    o.add("configuration", arr(config)).add("geometry", geometry).add("roadmap", arr(rows));
    o.add("histories", arr(histories)).add("animation", animation_json(c, placed));
    return o.done();
}

}  // namespace alembert
