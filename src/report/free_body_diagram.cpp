// SPDX-License-Identifier: MIT
// What a row's free-body diagram shows, for the page and the TikZ picture alike: the loads on
// S with the body each acts on and its part in the row's equation, the points named, the
// weights labelled with their masses, and the angles of a planar model's rotations.
#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

using namespace report_detail;

bool in_body_set(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

std::string body_name_or_ground(const System& sys, const Body* b) {
    return b ? b->name() : sys.newtonian().name();
}

// the point a torque on B is drawn at: where B is joined to what is outside B, else Bcm
const Point* torque_point(const System& sys, const Body* B) {
    for (const Point* p : sys.points())
        if (p->owner() == B && p->located_from() && p->located_from()->owner() != B) return p;
    return B ? &B->cm() : &sys.origin();
}

// the unknown measures a load's vector holds
std::vector<ex> unknown_measures(const System& sys, const Vector& v) {
    const SymbolTable& st = sys.symbols();
    std::vector<ex> out;
    for (const auto& part : v.components())
        for (int i = 0; i < 3; ++i)
            for (const ex& s : symbols_of(part.second[i]))
                if (st.owns(s) && st.kind(s) == SymbolKind::unknown) out.push_back(s);
    return out;
}

bool holds(const std::vector<ex>& xs, const ex& x) {
    return std::any_of(xs.begin(), xs.end(), [&](const ex& y) { return y.is_equal(x); });
}

double norm3(const std::vector<double>& v) {
    return v.size() < 3 ? 0 : std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// a known load's part in the row's equation: u . F (translate) or u . (r_OP x F) (rotate),
// u . T for a torque. Decided at the drawn configuration where it is clearly not zero there
// (most loads: no symbolic work), else at random states
bool known_load_appears(const System& sys, const Evaluation& ev, const RoadmapRow& r,
                        const std::vector<double>& u, bool torque, const Point* at, const Vector& v,
                        const std::vector<double>& numeric) {
    const bool rotate = r.motion == Motion::rotate && r.about && !torque;
    double c = 0, scale = norm3(numeric) * norm3(u);
    if (!rotate) {
        for (int k = 0; k < 3; ++k) c += u[k] * numeric[k];
    } else {
        const std::vector<double>& P = ev.position(at);
        const std::vector<double>& O = ev.position(r.about);
        const double d[3] = {P[0] - O[0], P[1] - O[1], P[2] - O[2]};
        const double m[3] = {d[1] * numeric[2] - d[2] * numeric[1],
                             d[2] * numeric[0] - d[0] * numeric[2],
                             d[0] * numeric[1] - d[1] * numeric[0]};
        for (int k = 0; k < 3; ++k) c += u[k] * m[k];
        scale *= 1 + std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    if (std::isfinite(c) && std::abs(c) > 1e-9 * std::max(scale, 1e-300)) return true;
    try {
        const ex e = rotate ? dot(r.direction, cross(at->pos_from(*r.about), v))
                            : dot(r.direction, v);
        return !is_zero_at_random_states(sys.symbols(), e);
    } catch (const Error&) {
        return true;  // cannot tell: drawn as a load the equation holds
    }
}

// a known load zero at the configuration: its vector in N with the rates (q', q'', ...) and
// the specified quantities that are 0 there taken as 1 (the coordinates kept); empty if that
// is zero or not finite too
std::vector<double> positive_sense(const System& sys, const Evaluation& ev, const Vector& v) {
    const SymbolTable& st = sys.symbols();
    exmap values = ev.values;
    for (auto& [x, value] : values)
        if (st.owns(x) && (st.kind(x) == SymbolKind::specified ||
             (st.kind(x) == SymbolKind::variable && st.derivative_order(x) > 0)) &&
            GiNaC::is_a<GiNaC::numeric>(value) && value.is_zero())
            value = 1;
    const Col3 c = v.components_in(sys.newtonian());
    std::vector<double> out(3);
    try {
        for (int k = 0; k < 3; ++k) out[k] = st.evaluate(c[k], values);
    } catch (const std::exception&) {
        return {};
    }
    const double n = norm3(out);
    return std::isfinite(n) && n > 0 ? out : std::vector<double>{};
}

}  // namespace

namespace report_detail {

bool Evaluation::places(const Point* p) const {
    auto it = places_.find(p);
    if (it != places_.end()) return it->second;
    bool placed = true;
    try {
        const SymbolTable& st = sys.symbols();
        const Col3 c = p->pos_from(sys.origin()).components_in(sys.newtonian());
        for (int k = 0; k < 3; ++k)
            for (const ex& s : symbols_of(c[k]))
                if (st.owns(s) && st.kind(s) == SymbolKind::specified && !given_.count(s)) placed = false;
    } catch (const Error&) {
        placed = false;  // no path to the origin
    }
    return places_.emplace(p, placed).first->second;
}

bool Evaluation::gives(const Load& l) const {
    auto it = gives_.find(&l);
    if (it != gives_.end()) return it->second;
    bool given = true;
    try {
        const SymbolTable& st = sys.symbols();
        const Col3 c = l.vector.components_in(sys.newtonian());
        for (int k = 0; k < 3 && given; ++k)
            for (const ex& s : symbols_of(c[k]))
                if (st.owns(s) && !given_.count(s) &&
                    (st.kind(s) == SymbolKind::specified ||
                     (st.kind(s) == SymbolKind::variable && st.derivative_order(s) > 0)))
                    given = false;
    } catch (const Error&) {
        given = false;  // not expressible in N
    }
    return gives_.emplace(&l, given).first->second;
}

WeightLabel weight_label(const System& sys, const Evaluation& ev, const Body& b) {
    // the gravity constant: gravity's one component in N (its sign made positive at the
    // configuration), else the one constant every component holds, else "g"
    const Col3 c = sys.gravity().components_in(sys.newtonian());
    std::vector<ex> nonzero;
    for (int k = 0; k < 3; ++k)
        if (!c[k].is_zero()) nonzero.push_back(c[k]);
    ex g = GiNaC::symbol("g");
    if (nonzero.size() == 1) {
        g = ev.at(nonzero[0]) < 0 ? ex(-nonzero[0]) : nonzero[0];
    } else if (!nonzero.empty()) {
        const SymbolTable& st = sys.symbols();
        std::vector<ex> common;
        for (const ex& s : symbols_of(nonzero[0]))
            if (st.owns(s) && st.kind(s) == SymbolKind::constant &&
                std::all_of(nonzero.begin(), nonzero.end(),
                            [&](const ex& x) { return symbols_of(x).count(s) > 0; }))
                common.push_back(s);
        if (common.size() == 1) g = common[0];
    }
    const ex m = b.mass();
    const bool sum = GiNaC::is_a<GiNaC::add>(m), number = GiNaC::is_a<GiNaC::numeric>(m);
    const bool g_sum = GiNaC::is_a<GiNaC::add>(g);
    const auto wrap = [](bool paren, const std::string& s) { return paren ? "(" + s + ")" : s; };
    WeightLabel w;
    w.text = wrap(sum, to_string(m)) + (number ? "*" : " ") + wrap(g_sum, to_string(g));
    w.tex = wrap(sum, to_latex(m)) + (number ? " \\cdot " : " \\, ") + wrap(g_sum, to_latex(g));
    return w;
}

std::vector<DiagramLoad> diagram_loads(const System& sys, const Evaluation& ev,
                                       const RoadmapRow& r) {
    std::vector<DiagramLoad> loads;
    const BodySet& S = r.system;
    // a load whose measures are unknowns: the row's own where one is the row's variable; held
    // by the equation where one is among its additional unknowns (those are listed where their
    // coefficient is not zero); else it drops out
    const auto unknown_role = [&](const std::vector<ex>& measures) {
        if (holds(measures, r.variable)) return LoadRole::own;
        for (const ex& x : measures)
            if (holds(r.additional_unknowns, x)) return LoadRole::held;
        return LoadRole::drops_out;
    };
    // the row's direction and gravity in N, evaluated once for all of S's loads
    const std::vector<double> u = ev.in_newtonian(r.direction);
    const std::vector<double> gravity = ev.in_newtonian(sys.gravity());
    for (const Load& l : sys.loads()) {
        if (!in_body_set(S, l.on) || in_body_set(S, l.from)) continue;
        const bool torque = l.kind != LoadKind::force;
        std::string label = l.label.empty() ? (torque ? "T" : "F") : l.label;
        DiagramLoad d;
        d.kind = torque ? "torque" : "force";
        d.label = label;
        d.at = torque ? torque_point(sys, l.on) : l.point;
        d.on = l.on;
        d.placed = ev.places(d.at);
        // the load's vector with what the configuration does not give taken as 0: shown only
        // where the configuration gives it; else it only tells that the load's part in the
        // equation is not zero everywhere
        const std::vector<double>& at_configuration = ev.load_vector(l);
        const std::vector<ex> measures = unknown_measures(sys, l.vector);
        d.unknown = !measures.empty();
        d.given = d.unknown || ev.gives(l);
        if (d.given) d.vector = at_configuration;
        if (!d.unknown && !(norm3(d.vector) > 0)) d.sense = positive_sense(sys, ev, l.vector);
        d.role = d.unknown ? unknown_role(measures)
                 : known_load_appears(sys, ev, r, u, torque, d.at, l.vector, at_configuration)
                     ? LoadRole::known
                     : LoadRole::drops_out;
        loads.push_back(std::move(d));
    }
    if (!sys.gravity().is_zero())
        for (const Body* b : S)
            if (b->has_mass()) {
                DiagramLoad d;
                const WeightLabel w = weight_label(sys, ev, *b);
                d.kind = "gravity";
                d.label = w.text;
                d.tex = w.tex;
                d.at = &b->cm();
                d.on = b;
                d.vector = gravity;
                d.role = known_load_appears(sys, ev, r, u, false, d.at, b->mass() * sys.gravity(),
                                            d.vector)
                             ? LoadRole::known
                             : LoadRole::drops_out;
                loads.push_back(std::move(d));
            }
    // joints where S meets the rest (a point placed at an offset that changes with the
    // coordinates is no joint: a cart on a rail, a rolling disk's centre); a declared
    // reaction's measures, drawn above, stand for the joint's force. The equation holds no
    // undeclared joint force: the planner chose S and O so that it drops out
    for (const Point* p : sys.points()) {
        const Body* from = nullptr;
        if (!in_body_set(S, p->owner()) || !is_joint_point(sys, *p, &from)) continue;
        if (in_body_set(S, from) || sys.find_joint_reaction(*p, from, p->owner())) continue;
        DiagramLoad d;
        d.kind = "joint";
        d.label = "from " + body_name_or_ground(sys, from);
        d.at = p;
        d.on = p->owner();
        d.unknown = true;
        d.role = LoadRole::drops_out;
        loads.push_back(std::move(d));
    }
    return loads;
}

std::string role_word(LoadRole r) {
    switch (r) {
        case LoadRole::own:
            return "own";
        case LoadRole::held:
            return "held";
        case LoadRole::known:
            return "known";
        case LoadRole::drops_out:
            return "drops";
    }
    return "";
}

std::vector<const Point*> diagram_points(const System& sys, const RoadmapRow& r,
                                         const std::vector<DiagramLoad>& loads) {
    std::vector<const Point*> out;
    const auto add = [&](const Point* p) {
        if (p && std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    };
    add(r.about);
    // the joints of S's bodies, with the outside and between them
    for (const Point* p : sys.points()) {
        const Body* from = nullptr;
        if (!is_joint_point(sys, *p, &from)) continue;
        if (in_body_set(r.system, p->owner()) || in_body_set(r.system, from)) add(p);
    }
    // where the loads act (the mass centres among them), where the configuration places it
    for (const DiagramLoad& l : loads)
        if (l.placed) add(l.at);
    return out;
}

const Point* row_about_point(const RoadmapRow& r, const Evaluation& ev) {
    const Point* p = r.about_owned.get();
    if (!p || !ev.places(p)) return nullptr;
    const std::vector<double>& at = ev.position(p);
    return std::all_of(at.begin(), at.end(), [](double x) { return std::isfinite(x); }) ? p : nullptr;
}

std::vector<const Point*> row_about_points(const std::vector<RoadmapRow>& rows,
                                           const Evaluation& ev) {
    std::vector<const Point*> out;
    for (const RoadmapRow& r : rows)
        if (const Point* p = row_about_point(r, ev))
            if (std::none_of(out.begin(), out.end(), [&](const Point* q) { return q->name() == p->name(); }))
                out.push_back(p);
    return out;
}

std::vector<DiagramAngle> planar_angles(const System& sys, const Evaluation& ev) {
    std::vector<DiagramAngle> out;
    for (const Body* b : sys.bodies()) {
        const Frame* F = b->frame();
        if (!F || !F->parent()) continue;
        const Mat3& R = F->rotation_from_parent();
        // a rotation about the shared z axis: R_PB(1,0) = sin(angle)
        if (!R(0, 2).is_zero() || !R(1, 2).is_zero() || !R(2, 0).is_zero() ||
            !R(2, 1).is_zero() || !(R(2, 2) - 1).is_zero())
            continue;
        ex s = R(1, 0), sign = 1;
        if (GiNaC::is_a<GiNaC::mul>(s) && s.nops() == 2 && s.op(1).is_equal(-1))
            s = s.op(0), sign = -1;
        if (GiNaC::is_a<GiNaC::mul>(s) && s.nops() == 2 && s.op(0).is_equal(-1))
            s = s.op(1), sign = -1;
        if (!GiNaC::is_a<GiNaC::function>(s) || !s.match(GiNaC::sin(GiNaC::wild())))
            continue;
        const ex angle = s.op(0);
        DiagramAngle a;
        a.body = b;
        a.name = to_string(angle);
        a.at = torque_point(sys, b);
        // the body's axis drawn: the one its first stick from that point lies along (x, else y)
        a.axis = 0;
        for (const Point* p : sys.points())
            if (p->located_from() == a.at && p->owner() == b) {
                try {
                    const Col3 c = p->pos_from(*a.at).components_in(*F);
                    if (c[0].is_zero() && !c[1].is_zero()) a.axis = 1;
                } catch (const Error&) {
                }
                break;
            }
        const Axis axis = a.axis == 0 ? Axis::x : Axis::y;
        a.from = ev.in_newtonian(F->parent()->unit(axis));
        a.to = ev.in_newtonian(F->unit(axis));
        a.value = ev.at(sign * angle);
        if (!std::isfinite(a.value) || !a.at) continue;
        out.push_back(a);
    }
    return out;
}

}  // namespace report_detail

}  // namespace alembert
