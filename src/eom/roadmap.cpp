// SPDX-License-Identifier: MIT
// Forming road-map rows, describing free-body diagrams, printing the road-map table.
#include "alembert/eom/roadmap.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "alembert/eom/inertia_forces.hpp"
#include "alembert/eom/readable_equation.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "accumulated_moment.hpp"
#include "free_body_rows.hpp"
#include "alembert/eom/zero_test.hpp"

namespace alembert {

namespace {

bool member(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

std::string body_or_ground(const System& sys, const Body* b) {
    return b ? b->name() : sys.newtonian().name();
}

std::string set_text(const BodySet& S) {
    std::string s = "{";
    for (std::size_t i = 0; i < S.size(); ++i) s += (i ? ", " : "") + S[i]->name();
    return s + "}";
}

}  // namespace

ex form_roadmap_equation(const System& sys, const RoadmapRow& row) {
    if (row.motion == Motion::constraint)
        throw ArgumentError("form_roadmap_equation(): the row for '" + to_string(row.variable) +
                            "' is a constraint row ('" + row.constraint +
                            "'); form it with form_constraint_row()");
    if (row.system.empty())
        throw ArgumentError("form_roadmap_equation(): the row for '" + to_string(row.variable) +
                            "' has an empty system S; list the bodies it moves");
    const Frame& N = sys.newtonian();
    if (row.motion == Motion::translate) {
        // u . (F^S - sum m a)
        Vector F = sys.calc_resultant(row.system, sys.origin()).force;
        if (row.analysis == Analysis::dynamics) F -= calc_inertial_force(row.system, N);
        return dot(row.direction, F);
    }
    if (!row.about)
        throw ArgumentError("form_roadmap_equation(): the rotate row for '" +
                            to_string(row.variable) + "' has no about point; give one");
    // large systems: the moments accumulated along the point tree (each row a few terms per
    // acceleration beyond the intermediates the rows share)
    if (row.system.size() > detail::kAccumulatedRowBodies)
        if (auto E = detail::form_accumulated_moment_row(sys, row)) return *E;
    // u . (M^{S/O} - d/dt H^{S/O} - v^O x L^S), the inertial part as sum I.alpha + w x I.w + r x m a
    Vector M = sys.calc_resultant(row.system, *row.about).moment;
    if (row.analysis == Analysis::dynamics) M -= calc_inertial_moment(row.system, *row.about, N);
    return dot(row.direction, M);
}

std::vector<std::string> describe_free_body_diagram(const System& sys, const BodySet& S) {
    return describe_free_body_diagram(sys, S, ex());
}

std::vector<std::string> describe_free_body_diagram(const System& sys, const BodySet& S,
                                                    const ex& equation) {
    std::vector<std::string> out;
    const SymbolTable& st = sys.symbols();
    const GiNaC::exset in_equation = symbols_of(equation);  // once, not a scan per measure
    // the unknown measures of each load external to S, then which of them the equation keeps,
    // decided for all of them by one evaluation of the equation
    std::vector<const Load*> external;
    std::vector<std::vector<ex>> measures;
    std::vector<ex> held;
    for (const Load& l : sys.loads()) {
        if (!member(S, l.on) || member(S, l.from)) continue;
        external.push_back(&l);
        measures.emplace_back();
        for (const auto& part : l.vector.components())
            for (int i = 0; i < 3; ++i)
                for (const ex& s : symbols_of(part.second[i]))
                    if (st.owns(s) && st.kind(s) == SymbolKind::unknown) {
                        measures.back().push_back(s);
                        if (in_equation.count(s)) held.push_back(s);
                    }
    }
    std::sort(held.begin(), held.end(), GiNaC::ex_is_less());
    held.erase(std::unique(held.begin(), held.end(),
                           [](const ex& a, const ex& b) { return a.is_equal(b); }),
               held.end());
    const std::vector<bool> changes =
        equation.is_zero() ? std::vector<bool>(held.size(), false)
                           : calc_changes_with_at_random_states(st, equation, held);
    auto kept_by_equation = [&](const ex& s) {
        if (equation.is_zero()) return true;
        for (std::size_t k = 0; k < held.size(); ++k)
            if (held[k].is_equal(s)) return static_cast<bool>(changes[k]);
        return false;
    };
    for (std::size_t n = 0; n < external.size(); ++n) {
        const Load& l = *external[n];
        std::string what = l.label.empty() ? (l.kind == LoadKind::force ? "force" : "torque")
                                           : l.label;
        // a load whose measures are unknowns is marked, like the joints' forces
        // (and, given the row's equation, those whose measures it does not keep)
        const bool unknown = !measures[n].empty();
        const bool kept = std::any_of(measures[n].begin(), measures[n].end(), kept_by_equation);
        const char* mark = !unknown ? "" : kept ? " (unknown)" : " (unknown, drops out)";
        if (l.kind == LoadKind::force)
            out.push_back(what + " at " + l.point->name() + " from " +
                          body_or_ground(sys, l.from) + mark);
        else
            out.push_back(what + " on " + l.on->name() + " from " + body_or_ground(sys, l.from) +
                          mark);
    }
    if (!sys.gravity().is_zero()) {
        std::string g = "gravity at";
        for (std::size_t i = 0; i < S.size(); ++i) g += (i ? ", " : " ") + S[i]->cm().name();
        out.push_back(g);
    }
    // joints: points of S that are points of a body outside S too (located from one at an
    // offset fixed in it: a pin, a weld) carry unknown contact loads; a point placed at an
    // offset that changes with the coordinates (a disk's centre, a cart on a rail, a rod's
    // foot on the floor) is no joint (a declared reaction's measures, listed above, stand for
    // a joint's force)
    for (const Point* p : sys.points()) {
        const Body* from = nullptr;
        if (!member(S, p->owner()) || !is_joint_point(sys, *p, &from)) continue;
        if (member(S, from) || sys.find_joint_reaction(*p, from, p->owner())) continue;
        out.push_back("joint force at " + p->name() + " from " + body_or_ground(sys, from) +
                      " (unknown)");
    }
    return out;
}

bool is_joint_point(const System& sys, const Point& P, const Body** other) {
    return detail::joined_at(sys, P, other);
}

namespace {
// the unknowns the equation holds; a load measure (never inside an intermediate) only where
// its coefficient is not zero at random states (a torque normal to the row's direction
// written in another frame has a coefficient that is zero but does not look it)
void list_additional_unknowns(const System& sys, RoadmapRow& row, const std::vector<ex>& unknowns) {
    const SymbolTable& st = sys.symbols();
    row.additional_unknowns.clear();
    const GiNaC::exset in_equation = symbols_of(row.equation);
    std::vector<ex> held, measures;  // the unknowns the equation holds; the load measures among them
    for (const ex& x : unknowns) {
        if (x.is_equal(row.variable) || !in_equation.count(x)) continue;
        held.push_back(x);
        if (st.owns(x) && st.kind(x) == SymbolKind::unknown) measures.push_back(x);
    }
    const std::vector<bool> changes = calc_changes_with_at_random_states(st, row.equation, measures);
    for (const ex& x : held) {
        auto it = std::find_if(measures.begin(), measures.end(),
                               [&](const ex& m) { return m.is_equal(x); });
        if (it != measures.end() && !changes[static_cast<std::size_t>(it - measures.begin())])
            continue;
        row.additional_unknowns.push_back(x);
    }
}
}  // namespace

void form_roadmap_row(const System& sys, RoadmapRow& row, const std::vector<ex>& unknowns) {
    if (row.motion == Motion::constraint) {
        form_constraint_row(sys, row, unknowns);
        return;
    }
    row.equation = form_roadmap_equation(sys, row);
    row.fbd = describe_free_body_diagram(sys, row.system, row.equation);
    list_additional_unknowns(sys, row, unknowns);
}

void form_constraint_row(const System& sys, RoadmapRow& row, const std::vector<ex>& unknowns) {
    const auto& cs = sys.constraints();
    auto it = std::find_if(cs.begin(), cs.end(),
                           [&](const Constraint& c) { return c.name == row.constraint; });
    if (it == cs.end()) {
        std::string declared;
        for (const Constraint& c : cs) declared += (declared.empty() ? "" : ", ") + c.name;
        throw ArgumentError("form_constraint_row(): no constraint named '" + row.constraint +
                            "' is declared (declared: " +
                            (declared.empty() ? std::string("none") : declared) + ")");
    }
    if (it->kind == ConstraintKind::motion && row.analysis == Analysis::statics)
        throw ArgumentError("form_constraint_row(): '" + it->name +
                            "' is a motion constraint; it restricts speeds only, so it has no "
                            "statics row");
    // the frames' table names z' intermediates as it differentiates; it is the model's own
    SymbolTable& st = sys.newtonian().symbols();
    ex e = it->residual;
    if (row.analysis == Analysis::dynamics) {
        e = st.dt(e);
        if (it->kind == ConstraintKind::configuration) e = st.dt(e);
    }
    row.motion = Motion::constraint;
    row.system.clear();
    row.about = nullptr;
    row.fbd.clear();
    row.equation = e;
    list_additional_unknowns(sys, row, unknowns);
}

namespace {

std::string direction_text(const System& sys, const Vector& u) {
    // prefer the Newtonian frame when the direction is constant there
    Col3 c = u.components_in(sys.newtonian());
    // values that differ between two random states: not constant, and no simplification of
    // a long chain's composed rotations to say so
    try {
        MeasuresAtRandomStates at(sys.symbols());
        const MeasuresAtRandomStates::Values v = at.calc_values(c);
        MeasuresAtRandomStates::Values first = v;
        for (auto& state : first) state = v[0];
        if (!MeasuresAtRandomStates::agree(v, first)) return u.to_string();
    } catch (const std::exception&) {
        // not evaluable there: simplify decides
    }
    bool constant = true;
    for (int i = 0; i < 3; ++i) {
        c[i] = simplify(c[i]);
        if (!GiNaC::is_a<GiNaC::numeric>(c[i])) constant = false;
    }
    return constant ? Vector(sys.newtonian(), c).to_string() : u.to_string();
}

struct Cells {
    std::vector<std::string> c;
};

std::string motion_text(Motion m) {
    switch (m) {
        case Motion::translate: return "translate";
        case Motion::rotate: return "rotate";
        case Motion::constraint: return "constraint";
    }
    return "?";
}

Cells row_cells(const System& sys, const RoadmapRow& r) {
    std::string extra;
    for (std::size_t i = 0; i < r.additional_unknowns.size(); ++i)
        extra += (i ? ", " : "") + to_string(r.additional_unknowns[i]);
    if (extra.empty()) extra = "none";
    if (!r.note.empty()) extra += " (" + r.note + ")";
    if (r.motion == Motion::constraint) {
        bool motion = false;
        for (const Constraint& c : sys.constraints())
            if (c.name == r.constraint) motion = c.kind == ConstraintKind::motion;
        std::string eq = r.analysis == Analysis::statics ? r.constraint + " = 0"
                         : motion                        ? "d/dt " + r.constraint + " = 0"
                                                         : "d2/dt2 " + r.constraint + " = 0";
        return {{to_string(r.variable), "constraint", "-", "-", "", "-", eq, extra}};
    }
    std::string eq = r.motion == Motion::translate
                         ? (r.analysis == Analysis::statics ? "u.F^S = 0" : "u.(F^S - m a^Scm) = 0")
                         : (r.analysis == Analysis::statics
                                ? "u.M^{S/O} = 0"
                                : "u.(M^{S/O} - dH^{S/O}/dt - v^O x L^S) = 0");
    std::string fbd;
    for (std::size_t i = 0; i < r.fbd.size(); ++i) fbd += (i ? "; " : "") + r.fbd[i];
    return {{to_string(r.variable), motion_text(r.motion),
             direction_text(sys, r.direction), set_text(r.system), fbd,
             r.about ? r.about->name() : "-", eq, extra}};
}

}  // namespace

std::string json_escape(const std::string& s, bool for_script) {
    std::string o;
    for (char ch : s) {
        switch (ch) {
            case '"': o += "\\\""; break;
            case '\\': o += "\\\\"; break;
            case '\n': o += "\\n"; break;
            case '\t': o += "\\t"; break;
            case '<': o += for_script ? "\\u003c" : "<"; break;
            case '>': o += for_script ? "\\u003e" : ">"; break;
            case '&': o += for_script ? "\\u0026" : "&"; break;
            default:
                if (static_cast<unsigned char>(ch) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", ch);
                    o += buf;
                } else {
                    o += ch;
                }
        }
    }
    return o;
}

std::string format_roadmap_table(const System& sys, const std::vector<RoadmapRow>& rows,
                                 bool with_equations) {
    const std::vector<std::string> head{"variable", "translate/rotate", "direction",
                                        "system S", "FBD of S", "about point", "equation",
                                        "additional unknowns"};
    std::vector<Cells> body;
    for (const RoadmapRow& r : rows) body.push_back(row_cells(sys, r));
    // the FBD column wraps: one load per line
    std::vector<std::size_t> width(head.size());
    for (std::size_t j = 0; j < head.size(); ++j) width[j] = head[j].size();
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t j = 0; j < head.size(); ++j) {
            if (j == 4) {
                for (const auto& line : rows[i].fbd) width[j] = std::max(width[j], line.size());
            } else {
                width[j] = std::max(width[j], body[i].c[j].size());
            }
        }
    auto line = [&](const std::vector<std::string>& cells) {
        std::string s = "|";
        for (std::size_t j = 0; j < cells.size(); ++j)
            s += " " + cells[j] + std::string(width[j] - cells[j].size(), ' ') + " |";
        return s + "\n";
    };
    std::string rule = "|";
    for (std::size_t w : width) rule += std::string(w + 2, '-') + "|";
    std::string out = line(head) + rule + "\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        std::size_t n = std::max<std::size_t>(1, rows[i].fbd.size());
        for (std::size_t k = 0; k < n; ++k) {
            std::vector<std::string> cells(head.size());
            for (std::size_t j = 0; j < head.size(); ++j) {
                if (j == 4) cells[j] = k < rows[i].fbd.size() ? rows[i].fbd[k] : "";
                else cells[j] = k == 0 ? body[i].c[j] : "";
            }
            out += line(cells);
        }
    }
    if (!with_equations) return out;
    out += "\n";
    Simplifier simplifier;
    for (const RoadmapRow& r : rows)
        out += "E_" + to_string(r.variable) + ": 0 = " +
               to_string(readable_equation(sys, r.equation, simplifier)) + "\n";
    return out;
}

std::string format_roadmap_json(const System& sys, const std::vector<RoadmapRow>& rows) {
    std::ostringstream os;
    os << "[";
    Simplifier simplifier;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const RoadmapRow& r = rows[i];
        Cells c = row_cells(sys, r);
        os << (i ? ",\n " : "\n ") << "{\"variable\": \"" << json_escape(c.c[0])
           << "\", \"motion\": \"" << c.c[1] << "\", \"direction\": \"" << json_escape(c.c[2])
           << "\", \"system\": [";
        for (std::size_t k = 0; k < r.system.size(); ++k)
            os << (k ? ", " : "") << "\"" << json_escape(r.system[k]->name()) << "\"";
        os << "], \"fbd\": [";
        for (std::size_t k = 0; k < r.fbd.size(); ++k)
            os << (k ? ", " : "") << "\"" << json_escape(r.fbd[k]) << "\"";
        os << "], \"about\": " << (r.about ? "\"" + json_escape(r.about->name()) + "\"" : "null")
           << ", \"analysis\": \"" << (r.analysis == Analysis::statics ? "statics" : "dynamics")
           << "\", \"equation\": \"" << json_escape(to_string(readable_equation(sys, r.equation, simplifier)))
           << "\", \"additional_unknowns\": [";
        for (std::size_t k = 0; k < r.additional_unknowns.size(); ++k)
            os << (k ? ", " : "") << "\"" << json_escape(to_string(r.additional_unknowns[k]))
               << "\"";
        os << "], \"note\": \"" << json_escape(r.note) << "\"}";
    }
    os << "\n]\n";
    return os.str();
}

}  // namespace alembert
