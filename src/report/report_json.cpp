// SPDX-License-Identifier: MIT
// The report's data: model, road-map rows with their free-body diagrams, histories, motion.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "alembert/eom/readable_equation.hpp"
#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

using namespace report_detail;

// ---- a small JSON writer: objects keep the order keys are written in -----------------------

std::string num(double v) {
    if (!std::isfinite(v)) return "null";
    if (v == 0) return "0";  // no -0
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// inside the page's <script>: '<', '>' and '&' escaped too
std::string str(const std::string& s) { return "\"" + json_escape(s, true) + "\""; }

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

std::string ground_or(const System& sys, const Body* b) {
    return b ? b->name() : sys.newtonian().name();
}

// ---- numbers at the configuration ----------------------------------------------------------


}  // namespace

namespace report_detail {

std::vector<const Point*> placed_points(const System& sys, const Evaluation* ev) {
    std::vector<const Point*> out;
    for (const Point* p : sys.points()) {
        try {
            (void)p->pos_from(sys.origin());
            if (!ev || ev->places(p)) out.push_back(p);
        } catch (const Error&) {
            // a point with no path to the origin has no place in a drawing
        }
    }
    return out;
}

}  // namespace report_detail

namespace {

// ---- the parts of the page's data ----------------------------------------------------------

std::string unit_of(const ReportContent& c, const std::string& name) {
    auto it = c.units.find(name);
    return it == c.units.end() ? "" : it->second;
}

// a value of `name` in the unit it is shown in (its declared unit), from SI
double shown_value(const ReportContent& c, const std::string& name, double si) {
    auto it = c.unit_scales.find(name);
    return it == c.unit_scales.end() || !(it->second > 0) ? si : si / it->second;
}

}  // namespace

namespace report_detail {

std::vector<ConfigurationDatum> configuration_data(const ReportContent& c) {
    std::vector<ConfigurationDatum> out;
    const auto add = [&](const ex& x, const std::string& name, const std::string& unit, double scale) {
        auto it = c.configuration.find(x);
        if (it == c.configuration.end() || !GiNaC::is_a<GiNaC::numeric>(it->second)) return;
        const double si = GiNaC::ex_to<GiNaC::numeric>(it->second).to_double();
        out.push_back({name, si, scale > 0 ? si / scale : si, unit});
    };
    // the rates in the coordinates' units per second (qA' in deg/s where qA is in deg)
    for (const TimeVariable& q : c.coordinates)
        for (int k = 1; k <= q.order(); ++k) {
            const std::string unit = unit_of(c, q.name());
            auto scale = c.unit_scales.find(q.name());
            add(q.d(k), q.name() + std::string(static_cast<std::size_t>(k), '\''),
                unit.empty() ? "" : unit + (k == 1 ? "/s" : "/s^" + std::to_string(k)),
                scale == c.unit_scales.end() ? 1.0 : scale->second);
        }
    const SymbolTable& st = c.system->symbols();
    for (const ex& x : st.symbols(SymbolKind::specified)) {
        const std::string name = st.name(x);
        auto scale = c.unit_scales.find(name);
        add(x, name, unit_of(c, name), scale == c.unit_scales.end() ? 1.0 : scale->second);
    }
    return out;
}

// "qA = 60 deg, qB = -41.6 deg (the configuration solve found at line 31)"
std::string configuration_words(const ReportContent& c) {
    std::string out;
    for (const TimeVariable& q : c.coordinates) {
        auto it = c.configuration.find(q.symbol());
        const double si = it != c.configuration.end() && GiNaC::is_a<GiNaC::numeric>(it->second)
                              ? GiNaC::ex_to<GiNaC::numeric>(it->second).to_double()
                              : 0.0;
        const std::string unit = unit_of(c, q.name());
        out += (out.empty() ? "" : ", ") + q.name() + " = " + num(shown_value(c, q.name(), si)) +
               (unit.empty() ? "" : " " + unit);
    }
    if (out.empty()) out = "the model's configuration";
    std::string data;
    for (const ConfigurationDatum& d : configuration_data(c))
        data += (data.empty() ? "" : ", ") + d.name + " = " + num(d.shown) + (d.unit.empty() ? "" : " " + d.unit);
    if (!data.empty()) out += ", with " + data;
    if (!c.configuration_source.empty()) out += " (" + c.configuration_source + ")";
    return out;
}

}  // namespace report_detail

namespace {


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
                                .add("value", v ? num(shown_value(c, st.name(k), *v)) : "null")
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


}  // namespace

namespace report_detail {

// sticks: a point of a body located from another by a vector fixed in the body (constant in
// its frame) is a segment of that body; else a vector fixed in the other point's body is a
// segment of that one; else one of fixed length a segment of the located point's body, and
// one fixed in N of the ground. A vector that
// changes in length and in all of them is a position, not material (a hip placed at
// x Nx> + y Ny> from the origin, a rolling disk's contact point, a cart on its rail): no stick.
std::vector<Segment> segments_of(const System& sys, const std::vector<const Point*>& placed) {
    std::vector<Segment> out;
    const SymbolTable& st = sys.symbols();
    for (const Point* p : placed) {
        const Point* q = p->located_from();
        if (!q) continue;
        Vector r = p->pos_from(*q);
        if (r.is_zero()) continue;
        const auto fixed_in = [&](const Body* b) {
            const Frame& F = b && b->frame() ? *b->frame() : sys.newtonian();
            if (b && !b->frame()) return false;  // a particle has no frame to hold a vector
            try {
                return is_zero_at_random_states(st, r.dt_in(F), sys.newtonian());
            } catch (const Error&) {
                return false;
            }
        };
        // a point of a body at a fixed distance from the point it is placed from hangs there
        // on a rod or a string of that length (a simple pendulum written in N's axes, a
        // rolling disk's centre above its contact point)
        const auto fixed_length = [&] {
            try {
                return is_zero_at_random_states(st, dot(r, r.dt_in(sys.newtonian())));
            } catch (const Error&) {
                return false;
            }
        };
        if (p->owner() && fixed_in(p->owner()))
            out.push_back({p->owner()->name(), q->name(), p->name()});
        else if (q->owner() && fixed_in(q->owner()))
            out.push_back({q->owner()->name(), q->name(), p->name()});
        else if (p->owner() && fixed_length())
            out.push_back({p->owner()->name(), q->name(), p->name()});
        else if (fixed_in(nullptr))
            out.push_back({"", q->name(), p->name()});
    }
    return out;
}

// "up" in N: against gravity, else Ny for planar models and Nz for others
std::vector<double> view_up(const System& sys, const Evaluation& ev, bool planar) {
    if (sys.gravity().is_zero()) return {0, planar ? 1.0 : 0, planar ? 0 : 1.0};
    return ev.in_newtonian(-sys.gravity());
}

std::string geometry_json(const System& sys, const Evaluation& ev,
                          const std::vector<const Point*>& placed, bool* planar,
                          const std::vector<const Point*>& about_only) {
    std::vector<std::string> pts, segs;
    *planar = true;
    for (const Point* p : placed) {
        Col3 c = p->pos_from(sys.origin()).components_in(sys.newtonian());
        // decided at random states, never by expanding: the position of a long chain's tip
        // from the origin, measured in N, expands into exponentially many terms
        if (*planar && !is_zero_at_random_states(sys.symbols(), c[2])) *planar = false;
        pts.push_back(Obj().add("name", str(p->name())).add("at", num_arr(ev.position(p, c))).done());
    }
    for (const Point* p : about_only)
        pts.push_back(Obj()
                          .add("name", str(p->name()))
                          .add("at", num_arr(ev.position(p)))
                          .add("about_only", "true")
                          .done());
    for (const Segment& s : segments_of(sys, placed))
        segs.push_back(
            Obj().add("body", str(s.body)).add("from", str(s.from)).add("to", str(s.to)).done());
    // "up" in the 3D view: against gravity, else Ny for planar models and Nz for others
    std::vector<double> up = view_up(sys, ev, *planar);
    Obj o;
    o.add("planar", *planar ? "true" : "false").add("points", arr(pts)).add("segments", arr(segs));
    o.add("up", num_arr(up));
    // a planar model's rotation angles, each drawn where its body is in a row's S
    std::vector<std::string> angles;
    if (*planar)
        for (const DiagramAngle& a : planar_angles(sys, ev))
            angles.push_back(Obj()
                                 .add("body", str(a.body->name()))
                                 .add("name", str(a.name))
                                 .add("at", str(a.at->name()))
                                 .add("from", num_arr(a.from))
                                 .add("to", num_arr(a.to))
                                 .add("value", num(a.value))
                                 .done());
    o.add("angles", arr(angles));
    return o.done();
}

}  // namespace report_detail

namespace {

std::string diagram_json(const System& sys, const Evaluation& ev, const RoadmapRow& r) {
    std::vector<std::string> loads, points;
    const std::vector<DiagramLoad> drawn = diagram_loads(sys, ev, r);
    for (const DiagramLoad& l : drawn) {
        Obj o;
        o.add("kind", str(l.kind)).add("label", str(l.label)).add("at", str(l.at->name()));
        o.add("on", str(l.on ? l.on->name() : ""));
        o.add("vector", num_arr(l.vector)).add("unknown", l.unknown ? "true" : "false");
        o.add("role", str(role_word(l.role)));
        if (!l.sense.empty()) o.add("sense", num_arr(l.sense));
        if (!l.placed) o.add("placed", "false");
        if (!l.given) o.add("given", "false");
        loads.push_back(o.done());
    }
    for (const Point* p : diagram_points(sys, r, drawn)) points.push_back(p->name());
    std::vector<std::string> names;
    for (const Body* b : r.system) names.push_back(b->name());
    Obj o;
    o.add("system", str_arr(names)).add("about", str(r.about ? r.about->name() : ""));
    o.add("direction", num_arr(ev.in_newtonian(r.direction))).add("loads", arr(loads));
    o.add("points", str_arr(points));
    return o.done();
}

}  // namespace

namespace report_detail {

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

}  // namespace report_detail

namespace {

// the intermediates each intermediate's definition uses directly, found once per page: the
// rows and steps reach the same definitions again and again
class DefinitionUses {
public:
    explicit DefinitionUses(const SymbolTable& st) : st_(st) {}

    // the intermediates of `st` that `e` holds, in symbols_of's order
    std::vector<ex> in(const ex& e) const {
        std::vector<ex> out;
        for (const ex& s : symbols_of(e))
            if (st_.owns(s) && st_.kind(s) == SymbolKind::intermediate) out.push_back(s);
        return out;
    }

    // in(st.definition(z)), remembered
    const std::vector<ex>& of(const ex& z) {
        auto it = uses_.find(z);
        if (it == uses_.end()) it = uses_.emplace(z, in(st_.definition(z))).first;
        return it->second;
    }

private:
    const SymbolTable& st_;
    std::map<ex, std::vector<ex>, GiNaC::ex_is_less> uses_;
};

// the names of the intermediates `e` uses, with those their definitions use (at most 200)
std::set<std::string> intermediates_used(const SymbolTable& st, DefinitionUses& uses, const ex& e) {
    std::set<std::string> used;
    // each entry: the intermediates one expression holds (`e`'s, then definitions')
    std::vector<std::vector<ex>> todo{uses.in(e)};
    while (!todo.empty() && used.size() < 200) {
        const std::vector<ex> x = std::move(todo.back());
        todo.pop_back();
        for (const ex& s : x)
            if (used.insert(st.name(s)).second) todo.push_back(uses.of(s));
    }
    return used;
}


}  // namespace

namespace report_detail {

PageIntermediates page_intermediates(const System& sys, const std::vector<RoadmapRow>& rows,
                                     const std::vector<RowSteps>* steps) {
    const SymbolTable& st = sys.symbols();
    DefinitionUses uses(st);
    std::vector<std::set<std::string>> used, used_by_steps;
    std::set<std::string> all;
    for (const RoadmapRow& r : rows) {
        used.push_back(intermediates_used(st, uses, r.equation));
        all.insert(used.back().begin(), used.back().end());
    }
    if (steps)
        for (const RowSteps& s : *steps) {
            used_by_steps.emplace_back();
            for (const ex& q : s.quantities) {
                const std::set<std::string> u = intermediates_used(st, uses, q);
                used_by_steps.back().insert(u.begin(), u.end());
            }
            all.insert(used_by_steps.back().begin(), used_by_steps.back().end());
        }
    PageIntermediates p;
    std::map<std::string, std::size_t> position;
    for (const ex& z : st.intermediates())
        if (all.count(st.name(z))) {
            position[st.name(z)] = p.names.size();
            p.names.push_back(st.name(z));
            p.tex.push_back(breakable_tex(to_latex(z) + " = " + to_latex(st.definition(z))));
        }
    const auto positions = [&](const std::vector<std::set<std::string>>& from,
                               std::vector<std::vector<std::size_t>>& into) {
        for (const auto& u : from) {
            std::vector<std::size_t> idx;
            for (const std::string& n : u) idx.push_back(position.at(n));
            std::sort(idx.begin(), idx.end());
            into.push_back(std::move(idx));
        }
    };
    positions(used, p.of_row);
    positions(used_by_steps, p.of_steps);
    return p;
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

}  // namespace report_detail

namespace {

// an entry of the mass matrix or forcing as people read it: intermediates written out,
// simplified when small enough
ex readable_entry(const SymbolTable& st, const ex& e) {
    ex x = st.expand_intermediates(e);
    return count_ops(x) <= kReadableSimplifyOps ? simplify(x) : x;
}

}  // namespace

namespace report_detail {

// M q'' = f typeset: the matrix, the column of accelerations and the forcing
std::string matrices_tex(const SymbolTable& st, const LinearSystem& m) {
    const unsigned n = m.A.rows();
    std::vector<std::vector<std::string>> M(n);
    std::vector<std::string> f(n);
    std::vector<ex> wide;              // the entries with a piece too long for a line
    std::vector<std::string*> wide_at;  // and where each is written
    const auto entry = [&](const ex& e, std::string& tex) {
        const ex x = readable_entry(st, e);
        tex = to_latex(x);
        if (longest_unbreakable(breakable_tex(tex)) > kUnbreakableChars) {
            wide.push_back(x);
            wide_at.push_back(&tex);
        }
    };
    std::size_t widest = 0;  // the widest line of the matrix form: a row of M and f's entry
    for (unsigned i = 0; i < n; ++i) {
        std::size_t width = 0;
        M[i].resize(m.A.cols());
        for (unsigned j = 0; j < m.A.cols(); ++j) {
            entry(m.A(i, j), M[i][j]);
            width += M[i][j].size() + 3;
        }
        entry(m.b(i, 0), f[i]);
        widest = std::max(widest, width + f[i].size());
    }
    std::string x = "\\begin{bmatrix} ";
    for (std::size_t j = 0; j < m.unknowns.size(); ++j)
        x += to_latex(m.unknowns[j]) + (j + 1 < m.unknowns.size() ? " \\\\ " : " ");
    x += "\\end{bmatrix}";
    if (widest > kMatrixRowChars) {
        // too wide for a column: the equation, then each entry on a line of its own
        std::string t = "M \\, " + x + " = f \\text{, with}";
        const auto index = [](unsigned k) { return std::to_string(k + 1); };
        // entries with a piece too long for a line written as the rows' equations are: with
        // named parts w_k (shared among them), defined on the lines after the entries
        AbbreviatedForm parts;
        if (!wide.empty()) {
            parts = abbreviate_form(wide, 100, "w");
            for (std::size_t k = 0; k < wide.size(); ++k) *wide_at[k] = to_latex(parts.results[k]);
        }
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < M[i].size(); ++j)
                t += std::string(kTexLineBreak) + "M_{" + index(i) + (n > 9 ? "," : "") + index(j) +
                     "} = " + M[i][j];
        for (unsigned i = 0; i < n; ++i)
            t += std::string(kTexLineBreak) + "f_{" + index(i) + "} = " + f[i];
        for (std::size_t k = 0; k < parts.definitions.size(); ++k)
            t += std::string(kTexLineBreak) + (k == 0 ? "\\text{with } " : "") +
                 to_latex(parts.definitions[k].first) + " = " + to_latex(parts.definitions[k].second);
        return breakable_tex(t);
    }
    std::string A = "\\begin{bmatrix} ", b = "\\begin{bmatrix} ";
    for (unsigned i = 0; i < n; ++i) {
        const std::string end = i + 1 < n ? " \\\\ " : " ";
        for (unsigned j = 0; j < M[i].size(); ++j) A += (j ? " & " : "") + M[i][j];
        A += end;
        b += f[i] + end;
    }
    return breakable_tex(A + "\\end{bmatrix} " + x + " = " + b + "\\end{bmatrix}");
}

}  // namespace report_detail

namespace {

// the mass matrix and forcing: their entries as text (to read back) and all of it as TeX
std::string matrices_json(const System& sys, const LinearSystem& m) {
    const SymbolTable& st = sys.symbols();
    std::vector<std::string> unknowns, M, f;
    for (const ex& x : m.unknowns) unknowns.push_back(to_string(x));
    for (unsigned i = 0; i < m.A.rows(); ++i) {
        std::vector<std::string> row;
        for (unsigned j = 0; j < m.A.cols(); ++j) row.push_back(to_string(readable_entry(st, m.A(i, j))));
        M.push_back(str_arr(row));
        f.push_back(to_string(readable_entry(st, m.b(i, 0))));
    }
    return Obj()
        .add("unknowns", str_arr(unknowns))
        .add("M", arr(M))
        .add("f", str_arr(f))
        .add("tex", str(matrices_tex(st, m)))
        .done();
}

// a row's derivation, closed on the page until asked for
std::string steps_json(const RowSteps& steps, const std::vector<std::size_t>& intermediates) {
    std::vector<std::string> items;
    for (const DerivationStep& d : steps.steps)
        items.push_back(Obj().add("label", str(d.label)).add("text", str(d.text)).add("tex", str(d.tex)).done());
    std::string idx = "[";
    for (std::size_t i = 0; i < intermediates.size(); ++i) idx += (i ? "," : "") + std::to_string(intermediates[i]);
    return Obj().add("steps", arr(items)).add("intermediates", idx + "]").done();
}

std::string verdict_word(ReportUnitCheck::Verdict v) {
    switch (v) {
        case ReportUnitCheck::Verdict::consistent: return "consistent";
        case ReportUnitCheck::Verdict::inconsistent: return "inconsistent";
        case ReportUnitCheck::Verdict::unchecked: return "unchecked";
    }
    return "";
}

std::string units_json(const ReportUnitCheck& u) {
    return Obj()
        .add("verdict", str(verdict_word(u.verdict)))
        .add("unit", str(u.unit))
        .add("summary", str(u.summary))
        .add("terms", str_arr(u.terms))
        .done();
}

std::string row_json(const System& sys, const Evaluation& ev, const RoadmapRow& r,
                     const std::string& equation, const std::vector<std::size_t>& intermediates) {
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
    o.add("equation", str(equation));
    std::string idx = "[";
    for (std::size_t i = 0; i < intermediates.size(); ++i) idx += (i ? "," : "") + std::to_string(intermediates[i]);
    o.add("intermediates", idx + "]");
    o.add("additional_unknowns", str_arr(extra)).add("note", str(r.note));
    o.add("diagram", r.motion == Motion::constraint ? "null" : diagram_json(sys, ev, r));
    return o.done();
}

// long runs are thinned for plotting to about kMaxPlotRows rows that keep each series'
// extremes (calc_plot_rows)
constexpr std::size_t kMaxPlotRows = 2000;

bool plotted(const ReportContent& c, const std::string& name) {
    return c.plotted.empty() ||
           std::find(c.plotted.begin(), c.plotted.end(), name) != c.plotted.end();
}

std::string history_json(const ReportContent& c, const ReportHistory& h) {
    // the time and the series chosen for plotting
    Table shown;
    const Table& t = h.table;
    for (std::size_t k = 0; k < t.columns.size(); ++k)
        if (k == 0 || plotted(c, t.names[k])) {
            shown.names.push_back(t.names[k]);
            shown.units.push_back(t.units[k]);
            shown.columns.push_back(t.columns[k]);
        }
    if (shown.columns.size() < 2) return "";
    shown = calc_table_rows(shown, calc_plot_rows(shown, kMaxPlotRows));
    std::vector<std::string> series;
    for (std::size_t k = 1; k < shown.columns.size(); ++k)
        series.push_back(Obj()
                             .add("name", str(shown.names[k]))
                             .add("unit", str(shown.units[k]))
                             .add("values", num_arr(shown.columns[k]))
                             .done());
    Obj o;
    o.add("title", str(h.title)).add("line", std::to_string(h.line)).add("file", str(h.file));
    o.add("rows", num(static_cast<double>(t.row_count())));
    o.add("plotted_rows", num(static_cast<double>(shown.row_count())));
    o.add("time", num_arr(shown.columns[0]));
    o.add("time_unit", str(shown.units[0]));
    o.add("series", arr(series));
    return o.done();
}

// a result's sweep: the swept values and each series with its axis ("real part"), thinned as
// the histories are; "null" when there is nothing to plot
std::string sweep_json(const ReportSweep& w) {
    const Table& t = w.table;
    if (t.columns.size() < 2 || t.row_count() == 0 || w.axes.size() != t.columns.size() - 1) return "null";
    const Table shown = calc_table_rows(t, calc_plot_rows(t, kMaxPlotRows));
    std::vector<std::string> series;
    for (std::size_t k = 1; k < shown.columns.size(); ++k)
        series.push_back(Obj()
                             .add("name", str(shown.names[k]))
                             .add("axis", str(w.axes[k - 1]))
                             .add("unit", str(shown.units[k]))
                             .add("values", num_arr(shown.columns[k]))
                             .done());
    Obj o;
    o.add("title", str(w.title)).add("file", str(w.file));
    o.add("rows", num(static_cast<double>(t.row_count())));
    o.add("plotted_rows", num(static_cast<double>(shown.row_count())));
    o.add("parameter", str(shown.names[0])).add("unit", str(shown.units[0]));
    o.add("values", num_arr(shown.columns[0]));
    o.add("series", arr(series));
    return o.done();
}

// the body drawn in 3D as the ellipsoid of uniform density with its mass and central inertia:
// semi-axes a_i^2 = 5 (I_j + I_k - I_i) / (2 m) along the principal axes (a thin disk of radius
// r: a flat ellipse of radius 1.12 r; a slender rod of length L: a needle 0.65 L either side);
// "null" where the mass or inertia is missing or not a number
std::string inertia_ellipsoid_json(const System& sys, const Evaluation& ev, const Body& b) {
    const auto* rigid = dynamic_cast<const RigidBody*>(&b);
    if (!rigid || !rigid->has_inertia() || !rigid->has_mass() || !rigid->frame()) return "null";
    (void)sys;
    const double m = ev.at(rigid->mass());
    Mat3 I = rigid->inertia().components_in(*rigid->frame());
    Eigen::Matrix3d A;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(i, j) = ev.at(I(i, j));
    if (!(m > 0) || !A.allFinite()) return "null";
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (A + A.transpose()));
    const Eigen::Vector3d l = eig.eigenvalues();
    std::vector<double> axes, directions;
    for (int i = 0; i < 3; ++i)
        axes.push_back(std::sqrt(std::max(0.0, 2.5 * (l.sum() - 2 * l(i)) / m)));
    if (axes[0] + axes[1] + axes[2] <= 0) return "null";
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
            directions.push_back(eig.eigenvectors()(i, k));  // column k: axis k in B
    return Obj().add("axes", num_arr(axes)).add("directions", num_arr(directions)).done();
}

// the positions of the placed points at each sample of the first history with a motion,
// thinned to at most 400 frames, through one compiled tape; a point placed by more than the
// coordinates (a force plate's centre of pressure, read with the plate's data) is left out
std::string animation_json(const ReportContent& c, const std::vector<const Point*>& all_placed) {
    const System& sys = *c.system;
    for (const ReportHistory& h : c.histories) {
        if (h.motion.empty() || h.table.columns.empty()) continue;
        std::vector<ex> inputs, outputs;
        for (const TimeVariable& q : h.coordinates) inputs.push_back(q.symbol());
        std::vector<const Point*> placed;
        for (const Point* p : all_placed) {
            Col3 x = p->pos_from(sys.origin()).components_in(sys.newtonian());
            try {
                (void)CompiledExpressions(sys.symbols(), inputs, {x[0], x[1], x[2]});
            } catch (const Error&) {
                continue;
            }
            placed.push_back(p);
            for (int i = 0; i < 3; ++i) outputs.push_back(x[i]);
        }
        // then each rigid body's axes in N (the 3D view turns a triad with the body)
        std::vector<std::string> bodies;
        for (const Body* b : sys.bodies()) {
            if (!b->frame() || b->frame() == &sys.newtonian()) continue;
            std::vector<ex> axes;
            try {
                for (int k = 0; k < 3; ++k) {
                    Col3 e{0, 0, 0};
                    e[k] = 1;
                    Col3 x = Vector(*b->frame(), e).components_in(sys.newtonian());
                    for (int i = 0; i < 3; ++i) axes.push_back(x[i]);
                }
            } catch (const Error&) {
                continue;  // a frame with no path to N
            }
            Obj body;
            body.add("name", str(b->name())).add("cm", str(b->cm().name()));
            body.add("ellipsoid",
                     inertia_ellipsoid_json(sys, Evaluation(sys, c.configuration), *b));
            bodies.push_back(body.done());
            outputs.insert(outputs.end(), axes.begin(), axes.end());
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
        o.add("source", str(h.title)).add("points", str_arr(names)).add("bodies", arr(bodies));
        o.add("time", arr(times));
        o.add("frames", arr(frames));
        return o.done();
    }
    return "null";
}


}  // namespace



std::vector<ReportCheck> calc_report_checks(const ReportContent& c) {
    std::vector<ReportCheck> out;
    for (const ReportHistory& h : c.histories) {
        const Table& t = h.table;
        for (std::size_t k = 0; k < t.columns.size(); ++k) {
            const std::vector<double>& v = t.columns[k];
            if (v.empty()) continue;
            if (t.names[k] == "energy") {
                double scale = 0, change = 0;
                for (double e : v) scale = std::max(scale, std::abs(e));
                for (double e : v) change = std::max(change, std::abs(e - v.front()));
                ReportCheck r{"energy", "energy", h.title, scale > 0 ? change / scale : change,
                              "",       false,    ""};
                r.passed = r.value <= 1e-6;
                char buf[200];
                std::snprintf(buf, sizeof buf,
                              "energy %.6g %s at the start; its largest change is %.3g of its "
                              "largest magnitude",
                              v.front(), t.units[k].empty() ? "J" : t.units[k].c_str(), r.value);
                r.summary = buf;
                out.push_back(r);
            } else if (t.names[k].rfind("drift_", 0) == 0) {
                double worst = 0;
                for (double e : v) worst = std::max(worst, std::abs(e));
                ReportCheck r{"constraint", t.names[k],    h.title, worst,
                              t.units[k],   worst <= 1e-6, ""};
                char buf[200];
                std::snprintf(buf, sizeof buf, "constraint %s: largest residual %.3g%s%s",
                              t.names[k].substr(6).c_str(), worst, t.units[k].empty() ? "" : " ",
                              t.units[k].c_str());
                r.summary = buf;
                out.push_back(r);
            }
        }
    }
    auto compare = [&](const std::string& kind, const std::string& name, double d, int states,
                       const std::string& what) {
        ReportCheck r{kind, name, "random states", d, "", d <= 1e-8, ""};
        char buf[240];
        std::snprintf(buf, sizeof buf, "%s: largest scaled difference %.3g at %d random states",
                      what.c_str(), d, states);
        r.summary = buf;
        out.push_back(r);
    };
    if (c.methods)
        for (std::size_t k = 0; k < c.methods->methods.size() && k < c.methods->differences.size();
             ++k)
            if (k > 0 || c.methods->methods.size() == 1)
                compare("methods", c.methods->methods[k], c.methods->differences[k],
                        c.methods->states, c.methods->methods[k] + " vs the road-map (q'')");
    // each row's units, as the script declares them
    for (std::size_t i = 0; i < c.unit_checks.size() && i < c.rows.size(); ++i) {
        const ReportUnitCheck& u = c.unit_checks[i];
        ReportCheck r{"units", "E_" + to_string(c.rows[i].variable), "declared units",
                      static_cast<double>(u.terms.size()), "",
                      u.verdict == ReportUnitCheck::Verdict::consistent, u.summary};
        r.checked = u.verdict != ReportUnitCheck::Verdict::unchecked;
        r.measure = u.verdict == ReportUnitCheck::Verdict::consistent ? u.unit
                    : u.verdict == ReportUnitCheck::Verdict::inconsistent
                        ? std::to_string(u.terms.size()) + (u.terms.size() == 1 ? " term off" : " terms off")
                        : "-";
        out.push_back(r);
    }
    if (c.reactions)
        for (std::size_t k = 0;
             k < c.reactions->measures.size() && k < c.reactions->differences.size(); ++k)
            compare(
                "reactions", to_string(c.reactions->measures[k]), c.reactions->differences[k],
                c.reactions->states,
                "reaction " + to_string(c.reactions->measures[k]) + ": road-map vs Newton-Euler");
    return out;
}

namespace {

std::string checks_json(const ReportContent& c) {
    std::vector<std::string> items;
    for (const ReportCheck& r : calc_report_checks(c))
        items.push_back(Obj()
                            .add("kind", str(r.kind))
                            .add("name", str(r.name))
                            .add("source", str(r.source))
                            .add("value", num(r.value))
                            .add("unit", str(r.unit))
                            .add("passed", r.passed ? "true" : "false")
                            .add("checked", r.checked ? "true" : "false")
                            .add("measure", str(r.measure))
                            .add("summary", str(r.summary))
                            .done());
    return arr(items);
}

}  // namespace

std::string render_report_json(const ReportContent& c) {
    return report_detail::render_json(c, report_detail::typeset_equations(c));
}

std::string report_detail::render_json(const ReportContent& c,
                                       const std::vector<std::string>& equations,
                                       const std::vector<RowSteps>* given_steps,
                                       const BruteForceCount* given_count) {
    if (!c.system)
        throw ArgumentError(
            "render_report_json(): the report has no model; build one (newtonian N, ...) before "
            "report");
    const System& sys = *c.system;
    Evaluation ev(sys, c.configuration);
    std::vector<const Point*> placed = placed_points(sys, &ev);
    bool planar = true;
    std::string geometry = geometry_json(sys, ev, placed, &planar, row_about_points(c.rows, ev));
    std::vector<std::string> rows, histories, config;
    const std::vector<RowSteps> formed_steps =
        given_steps ? std::vector<RowSteps>{} : calc_rows_steps(c, equations);
    const std::vector<RowSteps>& steps = given_steps ? *given_steps : formed_steps;
    const PageIntermediates zs = page_intermediates(sys, c.rows, &steps);
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        std::string row = row_json(sys, ev, c.rows[i], equations.at(i), zs.of_row[i]);
        row.pop_back();  // the closing brace: the derivation and the unit check follow
        row += "," + str("derivation") + ":" + steps_json(steps.at(i), zs.of_steps.at(i));
        row += "," + str("units") + ":" +
               (i < c.unit_checks.size() ? units_json(c.unit_checks[i]) : std::string("null")) + "}";
        rows.push_back(row);
    }
    if (c.plot_histories)
        for (const ReportHistory& h : c.histories) {
            std::string one = history_json(c, h);
            if (!one.empty()) histories.push_back(one);
        }
    for (const TimeVariable& q : c.coordinates) {
        auto it = ev.values.find(q.symbol());
        double v =
            it == ev.values.end() ? 0.0 : GiNaC::ex_to<GiNaC::numeric>(it->second).to_double();
        config.push_back(Obj()
                             .add("name", str(q.name()))
                             .add("value", num(v))
                             .add("shown", num(shown_value(c, q.name(), v)))
                             .add("unit", str(unit_of(c, q.name())))
                             .done());
    }
    std::vector<std::string> config_data;
    for (const ConfigurationDatum& d : configuration_data(c))
        config_data.push_back(Obj()
                                  .add("name", str(d.name))
                                  .add("value", num(d.si))
                                  .add("shown", num(d.shown))
                                  .add("unit", str(d.unit))
                                  .done());
    // how far the drawn configuration is from closing each loop the model declares
    std::vector<std::string> closure;
    for (const Constraint& k : sys.constraints())
        if (k.kind == ConstraintKind::configuration)
            closure.push_back(Obj()
                                  .add("name", str(k.name))
                                  .add("residual", num(ev.at(k.residual)))
                                  .done());
    std::vector<std::string> results;
    for (const ReportResult& r : c.results) {
        Obj o;
        o.add("line", std::to_string(r.line)).add("statement", str(r.statement)).add("text", str(r.text));
        // a sweep's values, plotted under the text (none with the plots turned off)
        const std::string sweep = r.sweep && c.plot_histories ? sweep_json(*r.sweep) : "null";
        if (sweep != "null") o.add("sweep", sweep);
        results.push_back(o.done());
    }
    // the equations kane and lagrange formed, typeset after the rows'
    std::vector<std::string> sets;
    std::size_t next = c.rows.size();
    for (const ReportEquationSet& set : c.equation_sets) {
        std::vector<std::string> tex;
        for (std::size_t k = 0; k < set.equations.size(); ++k) tex.push_back(equations.at(next++));
        sets.push_back(Obj()
                           .add("name", str(set.name))
                           .add("method", str(set.method))
                           .add("line", std::to_string(set.line))
                           .add("equations", str_arr(tex))
                           .done());
    }
    Obj o;
    o.add("format", "1")
        .add("title", str(c.title))
        .add("notes", str_arr(c.notes))
        .add("model", model_json(c));
    o.add("configuration", arr(config))
        .add("configuration_source", str(c.configuration_source))
        .add("configuration_data", arr(config_data))
        .add("closure", arr(closure))
        .add("geometry", geometry)
        .add("roadmap", arr(rows));
    // free-body diagrams of every body separately, counted beside the road-map's rows
    const BruteForceCount bf = given_count ? *given_count : calc_brute_force_count(c);
    if (!c.rows.empty())
        o.add("brute_force", Obj()
                                 .add("formed", bf.formed ? "true" : "false")
                                 .add("planar", bf.count.planar ? "true" : "false")
                                 .add("equations", std::to_string(bf.count.equations + bf.constraint_rows))
                                 .add("unknowns", std::to_string(bf.count.unknowns))
                                 .add("reactions", std::to_string(bf.count.force_reactions + bf.count.torque_reactions))
                                 .add("asked", std::to_string(bf.asked.size()))
                                 .add("rows", std::to_string(c.rows.size() - bf.reaction_rows))
                                 .add("text", str(brute_force_words(bf, c.rows.size())))
                                 .done());
    o.add("equation_sets", arr(sets));
    o.add("results", arr(results));
    o.add("intermediates", str_arr(zs.tex));
    o.add("histories", arr(histories)).add("animation", animation_json(c, placed));
    o.add("checks", checks_json(c));
    if (c.matrices) o.add("matrices", matrices_json(sys, *c.matrices));
    return o.done();
}

}  // namespace alembert
