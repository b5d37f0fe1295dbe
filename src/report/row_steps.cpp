// SPDX-License-Identifier: MIT
// Each road-map row's derivation step by step, typeset, and the brute-force Newton–Euler count
// the road-map is compared with.
#include <algorithm>
#include <string>
#include <vector>

#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/row_derivation.hpp"
#include "alembert/error.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

using namespace report_detail;

// a quantity of more operations than this (all its measures together) is typeset abbreviated,
// with named parts on the lines below it, as long equations are
constexpr std::size_t kStepAbbreviateOps = 600;
// measures of at most this many operations are simplified for the reader
constexpr std::size_t kStepSimplifyOps = 200;
// a quantity whose TeX (abbreviated) is longer than this is named, not written out: a wall
// of named parts teaches nothing (a 7-link arm's rate of angular momentum takes 14,000)
constexpr std::size_t kStepTexChars = 6000;
// the row's equation is repeated as the last step when at most this long (else: see above)
constexpr std::size_t kStepEquationChars = 3000;

std::string frame_tex(const std::string& name) {
    std::string n;
    for (char ch : name) n += ch == '_' ? std::string("\\_") : std::string(1, ch);
    return n.size() == 1 ? "\\hat{" + n + "}" : "\\widehat{\\mathrm{" + n + "}}";
}

const char* const kAxis[3] = {"x", "y", "z"};

// "a (b) \hat{A}_x + ...": the measure TeX of each non-zero part, in the frames the vector is
// written in
std::string parts_tex(const std::vector<std::pair<ex, std::string>>& parts) {
    std::string out;
    for (const auto& [c, unit] : parts) {
        std::string t;
        if (c.is_equal(1)) t = unit;
        else if (c.is_equal(-1)) t = "-" + unit;
        else if (GiNaC::is_a<GiNaC::add>(c)) t = "(" + to_latex(c) + ")\\," + unit;
        else t = to_latex(c) + "\\," + unit;
        const bool neg = !t.empty() && t[0] == '-';
        if (out.empty()) out = t;
        else out += neg ? " - " + t.substr(1) : " + " + t;
    }
    return out.empty() ? "\\vec{0}" : out;
}

// the measures of `v` with their unit vectors' TeX, in the frames it is written in
void measures_of(const Vector& v, std::vector<ex>& measures, std::vector<std::string>& units) {
    for (const auto& [F, c] : v.components())
        for (int i = 0; i < 3; ++i) {
            if (c[i].is_zero()) continue;
            measures.push_back(c[i]);
            units.push_back(frame_tex(F->name()) + "_{" + kAxis[i] + "}");
        }
}

std::size_t ops_of(const std::vector<ex>& measures) {
    std::size_t ops = 0;
    for (const ex& m : measures) ops += count_ops(m);
    return ops;
}

// the vector typeset: each measure simplified when small; written in `prefer` (the frame of
// the row's direction) when that is no longer, so that a planar row's momenta, written body
// by body, read as one term; abbreviated with named parts (stem_1 = ...) on the lines below
// when the whole is large or holds a piece too long for a line
std::string vector_tex(const Vector& v, const std::string& stem, Simplifier& simplifier,
                       TextPrinter& printer, const Frame* prefer = nullptr) {
    std::vector<ex> measures;
    std::vector<std::string> units;
    measures_of(v, measures, units);
    std::size_t ops = ops_of(measures);
    auto simplified = [&](std::vector<ex> ms) {
        for (ex& m : ms)
            if (count_ops(m) <= kStepSimplifyOps) m = simplifier(m);
        return ms;
    };
    if (ops <= kStepAbbreviateOps) {
        measures = simplified(measures);
        ops = ops_of(measures);
        if (prefer && v.components().size() > 1) {
            const Col3 c = v.components_in(*prefer);
            std::vector<ex> in_one;
            std::vector<std::string> one_units;
            measures_of(Vector(*prefer, c), in_one, one_units);
            std::size_t raw = ops_of(in_one);
            if (raw <= kStepAbbreviateOps) {
                in_one = simplified(in_one);
                // no longer than the parts and the sums that join them
                if (ops_of(in_one) <= ops + 2 * measures.size()) {
                    measures = in_one;
                    units = one_units;
                }
            }
        }
    }
    std::vector<std::pair<ex, std::string>> parts;
    if (ops_of(measures) <= kStepAbbreviateOps) {
        for (std::size_t k = 0; k < measures.size(); ++k)
            if (!measures[k].is_zero()) parts.emplace_back(measures[k], units[k]);
        const std::string whole = parts_tex(parts);
        // a piece too long for a line (a fraction over a long root) is named instead
        if (longest_unbreakable(breakable_tex(whole)) <= kUnbreakableChars) return whole;
        parts.clear();
    }
    const AbbreviatedForm f = abbreviate_form(measures, printer, 100, stem);
    for (std::size_t k = 0; k < measures.size(); ++k) parts.emplace_back(f.results.at(k), units[k]);
    std::string out = parts_tex(parts);
    for (std::size_t i = 0; i < f.definitions.size(); ++i)
        out += std::string(kTexLineBreak) + (i == 0 ? "\\text{with } " : "") +
               to_latex(f.definitions[i].first) + " = " + to_latex(f.definitions[i].second);
    return out;
}

std::string set_tex(const BodySet& S) {
    std::string s = "\\{";
    for (std::size_t i = 0; i < S.size(); ++i) s += (i ? ", " : "") + to_latex(GiNaC::symbol(S[i]->name()));
    return s + "\\}";
}

std::string point_tex(const Point& p) { return to_latex(GiNaC::symbol(p.name())); }

void add_measures(std::vector<ex>& into, const Vector& v) {
    for (const auto& [F, c] : v.components())
        for (int i = 0; i < 3; ++i)
            if (!c[i].is_zero()) into.push_back(c[i]);
}

}  // namespace

namespace report_detail {

RowSteps calc_row_steps(const System& sys, const RoadmapRow& r, const std::string& equation,
                        Simplifier& simplifier, MovingBodies& moving, TextPrinter& printer) {
    RowSteps out;
    auto step = [&](const std::string& label, const std::string& text, const std::string& tex) {
        out.steps.push_back({label, text, tex.empty() ? tex : breakable_tex(tex)});
    };
    // a quantity: "name = value", or the name alone when the value is too long to read
    auto quantity = [&](const std::string& label, const std::string& text, const std::string& name,
                        const std::string& value) {
        if (value.size() <= kStepTexChars) return step(label, text, name + " = " + value);
        step(label, text + " (written out, " + std::to_string(value.size() / 1000) +
                        "k characters of TeX with named parts: left out)",
             name);
    };
    const RowDerivation d = calc_row_derivation(sys, r, moving);
    const std::string E = "E_{" + to_latex(r.variable) + "}";
    step("variable", "the unknown this row is solved for", to_latex(r.variable));
    if (r.motion == Motion::constraint) {
        bool motion = false;
        for (const Constraint& k : sys.constraints())
            if (k.name == r.constraint) motion = k.kind == ConstraintKind::motion;
        step("constraint", "the model declares " + r.constraint + " = 0" +
                               (motion ? " (a motion constraint, on the speeds)" : " (a configuration constraint)"),
             "0 = " + to_latex(d.constraint_residual));
        step("level",
             d.constraint_derivatives == 0 ? "used as declared (statics)"
             : d.constraint_derivatives == 1 ? "differentiated once in time: the accelerations' level"
                                             : "differentiated twice in time: the accelerations' level",
             "");
        if (equation.size() <= kStepEquationChars) step("equation", "the row's equation", equation);
        else step("equation", "the row's equation, above", "");
        return out;
    }
    const bool rotate = r.motion == Motion::rotate;
    const Frame* prefer = r.direction.components().empty() ? nullptr : r.direction.components().front().first;
    const bool dynamics = r.analysis == Analysis::dynamics;
    step(rotate ? "rotate" : "translate",
         rotate ? "a balance of moments about a line through O along \u00fb"
                : "a balance of forces along \u00fb",
         "");
    step("direction", "\u00fb, the direction the balance is projected on",
         "\\hat{u} = " + vector_tex(r.direction, "wu", simplifier, printer));
    step("system S",
         d.moved_by.empty() ? "the bodies whose free-body diagram is drawn"
                            : "what moves when only " + d.moved_by + " changes",
         "S = " + set_tex(r.system));
    std::string fbd;
    for (std::size_t k = 0; k < r.fbd.size(); ++k) fbd += (k ? "; " : "") + r.fbd[k];
    step("free-body diagram", fbd.empty() ? "no load from outside S" : fbd, "");
    if (rotate) step("about point O", d.about_reason, "O = " + point_tex(*r.about));
    const std::string O = r.about ? point_tex(*r.about) : "";
    if (!rotate) {
        quantity("resultant force", "the loads external to S, gravity included", "\\vec{F}^{S}",
                 vector_tex(d.force, "wf", simplifier, printer, prefer));
        add_measures(out.quantities, d.force);
        if (dynamics) {
            step("mass", "m^S, the mass of S", "m^{S} = " + to_latex(d.mass));
            quantity("mass times acceleration",
                     "each body's mass times its mass centre's acceleration in N",
                     "m^{S}\\,{}^{N}\\vec{a}^{S_{cm}} = \\sum_{B \\in S} "
                     "m^{B}\\,{}^{N}\\vec{a}^{B_{cm}}",
                     vector_tex(d.mass_acceleration, "wa", simplifier, printer, prefer));
            add_measures(out.quantities, d.mass_acceleration);
            step("projection", "the balance along \u00fb",
                 E + " = \\hat{u} \\cdot (\\vec{F}^{S} - m^{S}\\,{}^{N}\\vec{a}^{S_{cm}})");
        } else {
            step("projection", "the balance along \u00fb (statics)", E + " = \\hat{u} \\cdot \\vec{F}^{S}");
        }
    } else if (!dynamics || d.accumulated) {
        quantity("moment", "the moment about O of the loads external to S",
                 "\\vec{M}^{S/" + O + "}", vector_tex(d.moment, "wm", simplifier, printer, prefer));
        add_measures(out.quantities, d.moment);
        if (d.accumulated)
            step("projection",
                 "S has " + std::to_string(r.system.size()) +
                     " bodies: the moments of their weights, inertia forces and torques are "
                     "accumulated along the tree of points towards O, each sum named once",
                 E + " = \\hat{u} \\cdot (\\vec{M}^{S/" + O + "} - \\vec{M}^{*\\,S/" + O + "})");
        else
            step("projection", "the balance about O along \u00fb (statics)",
                 E + " = \\hat{u} \\cdot \\vec{M}^{S/" + O + "}");
    } else {
        quantity("angular momentum",
                 "about O, each body's central inertia times its angular velocity plus the moment "
                 "of its momentum",
                 "{}^{N}\\vec{H}^{S/" + O +
                     "} = \\sum_{B \\in S} (I^{B/B_{cm}} \\cdot {}^{N}\\vec{\\omega}^{B} + "
                     "\\vec{r}^{B_{cm}/" +
                     O + "} \\times m^{B}\\,{}^{N}\\vec{v}^{B_{cm}})",
                 vector_tex(d.angular_momentum, "wh", simplifier, printer, prefer));
        quantity("linear momentum", "the sum of the bodies' momenta",
                 "{}^{N}\\vec{L}^{S} = \\sum_{B \\in S} m^{B}\\,{}^{N}\\vec{v}^{B_{cm}}",
                 vector_tex(d.linear_momentum, "wl", simplifier, printer, prefer));
        quantity("rate of angular momentum", "the time derivative of H in N",
                 "\\frac{{}^{N}d}{dt}\\,{}^{N}\\vec{H}^{S/" + O + "}",
                 vector_tex(d.angular_momentum_rate, "wk", simplifier, printer, prefer));
        quantity("moving point",
                 d.transport.is_zero() ? "O is fixed in N: no term"
                                       : "O moves in N: this term corrects the rate of H",
                 "{}^{N}\\vec{v}^{" + O + "} \\times {}^{N}\\vec{L}^{S}",
                 vector_tex(d.transport, "wp", simplifier, printer, prefer));
        quantity("moment", "the moment about O of the loads external to S",
                 "\\vec{M}^{S/" + O + "}", vector_tex(d.moment, "wm", simplifier, printer, prefer));
        for (const Vector* v : {&d.angular_momentum, &d.linear_momentum, &d.angular_momentum_rate,
                                &d.transport, &d.moment})
            add_measures(out.quantities, *v);
        step("projection", "the balance of moments about O along \u00fb",
             E + " = \\hat{u} \\cdot (\\vec{M}^{S/" + O + "} - \\frac{{}^{N}d}{dt}\\,{}^{N}\\vec{H}^{S/" + O +
                 "} - {}^{N}\\vec{v}^{" + O + "} \\times {}^{N}\\vec{L}^{S})");
    }
    if (equation.size() <= kStepEquationChars)
        step("equation", "the dot product written out and solved for the row's unknown where it can be", equation);
    else
        step("equation", "the dot product written out: the row's equation above", "");
    return out;
}

std::vector<RowSteps> calc_rows_steps(const ReportContent& c, const std::vector<std::string>& equations) {
    std::vector<RowSteps> out;
    if (!c.system) return out;
    Simplifier simplifier;  // the rows share their kinematics: each node simplified once
    MovingBodies moving(*c.system);  // and which bodies each speed moves
    TextPrinter printer;             // and the texts that measure their abbreviated lines
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        try {
            out.push_back(
                calc_row_steps(*c.system, c.rows[i], equations.at(i), simplifier, moving, printer));
        } catch (const Error& e) {
            RowSteps s;
            s.steps.push_back({"derivation", std::string("not available: ") + e.what(), ""});
            out.push_back(std::move(s));
        }
    }
    return out;
}

BruteForceCount calc_brute_force_count(const ReportContent& c) {
    BruteForceCount b;
    if (!c.system || c.rows.empty()) return b;
    const System& sys = *c.system;
    // the unknowns asked for besides the measures of declared joint reactions, which brute
    // force counts as the joints' own components
    for (const RoadmapRow& r : c.rows) {
        if (r.motion == Motion::constraint) ++b.constraint_rows;
        if (sys.reaction_of(r.variable)) {
            ++b.reaction_rows;
            continue;
        }
        b.asked.push_back(to_string(r.variable));
    }
    try {
        b.count = count_newton_euler_equations(sys, c.coordinates, b.asked.size());
        b.formed = true;
    } catch (const Error& e) {
        b.why = e.what();
    }
    b.constraints = sys.constraints().size();
    return b;
}

std::string brute_force_words(const BruteForceCount& b, std::size_t rows) {
    if (!b.formed) return b.why.empty() ? "" : "Brute-force Newton\u2013Euler count not available: " + b.why;
    const NewtonEulerCount& n = b.count;
    auto count = [](std::size_t k, const std::string& one, const std::string& many) {
        return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    std::string bodies, rule;
    if (n.rigid_bodies) {
        bodies = count(n.rigid_bodies, "rigid body", "rigid bodies");
        rule = n.planar ? "3 per rigid body" : "6 per rigid body";
    }
    if (n.particles) {
        bodies += (bodies.empty() ? "" : " and ") + count(n.particles, "particle", "particles");
        rule += std::string(rule.empty() ? "" : ", ") + (n.planar ? "2 per particle" : "3 per particle");
    }
    if (b.constraint_rows)
        rule += ", and the " + count(b.constraint_rows, "constraint equation", "constraint equations") +
                " the road-map uses too";
    std::string asked;
    for (std::size_t k = 0; k < b.asked.size(); ++k) asked += (k ? ", " : "") + b.asked[k];
    std::string s = std::string("Free-body diagrams of every body separately (brute-force Newton\u2013Euler, ") +
                    (n.planar ? "planar" : "spatial") + "): " + bodies +
                    (n.rigid_bodies + n.particles == 1 ? " gives " : " give ") +
                    count(n.equations + b.constraint_rows, "equation", "equations") + " (" + rule + ") in " +
                    count(n.unknowns, "unknown", "unknowns") + ": " +
                    count(n.force_reactions + n.torque_reactions, "joint-reaction component",
                          "joint-reaction components") +
                    " (" + std::to_string(n.force_reactions) + " force, " +
                    std::to_string(n.torque_reactions) + " torque) and the " +
                    std::to_string(b.asked.size()) + " asked for" +
                    (asked.empty() ? "" : " (" + asked + ")") + ". The road-map: " +
                    count(rows - b.reaction_rows, "row", "rows") + (asked.empty() ? "" : " for " + asked);
    if (b.reaction_rows)
        s += ", and " + count(b.reaction_rows, "row", "rows") + " for the declared joint reactions' measures";
    s += ".";
    if (b.constraints && !b.constraint_rows)
        s += " The model's " + count(b.constraints, "constraint", "constraints") +
             " (loops, rolling) add equations and forces of their own to the brute-force count.";
    return s;
}

}  // namespace report_detail

}  // namespace alembert
