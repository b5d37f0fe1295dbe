// SPDX-License-Identifier: MIT
// The road-map planner: partial velocities decide S, the direction and the about point.
#include "alembert/eom/planner.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "accumulated_moment.hpp"
#include "free_body_rows.hpp"
#include "unknown_rows.hpp"
#include "alembert/eom/moving_bodies.hpp"
#include "alembert/eom/zero_test.hpp"

namespace alembert {

namespace {

// zero at random states, through the intermediates (a symbolic test misses cancellations
// inside them)
bool zero(const System& sys, const Vector& v) {
    return is_zero_at_random_states(sys.symbols(), v, sys.newtonian());
}

// the constant factors of `e` (symbols of constants, to their powers), by base
std::map<ex, GiNaC::numeric, GiNaC::ex_is_less> constant_factors(const SymbolTable& st, const ex& e) {
    std::map<ex, GiNaC::numeric, GiNaC::ex_is_less> out;
    const auto add = [&](const ex& f) {
        const bool power = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1));
        const ex base = power ? f.op(0) : f;
        if (GiNaC::is_a<GiNaC::symbol>(base) && st.owns(base) && st.kind(base) == SymbolKind::constant)
            out[base] += power ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)) : GiNaC::numeric(1);
    };
    if (GiNaC::is_a<GiNaC::mul>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) add(e.op(i));
    else
        add(e);
    return out;
}

// The unit vector along `v` (a partial velocity) for a row's direction: v without the product
// of constants all its measures share, so that a link's length L, which GiNaC does not know to
// be positive, leaves no L/sqrt(L^2) in it; signed as v is at the constants' values (any sign
// gives the row's equation, up to its sign).
Vector row_direction(const SymbolTable& st, const Vector& v) {
    const Vector s = v.simplify();
    std::map<ex, GiNaC::numeric, GiNaC::ex_is_less> common;
    bool first = true;
    for (const auto& [F, c] : s.components())
        for (int i = 0; i < 3; ++i) {
            if (c[i].is_zero()) continue;
            const auto here = constant_factors(st, c[i]);
            if (first) {
                common = here;
                first = false;
                continue;
            }
            for (auto it = common.begin(); it != common.end();) {
                const auto h = here.find(it->first);
                if (h == here.end() || (h->second > 0) != (it->second > 0)) {
                    it = common.erase(it);
                    continue;
                }
                it->second = it->second > 0 ? std::min(it->second, h->second) : std::max(it->second, h->second);
                ++it;
            }
        }
    ex factor = 1;
    for (const auto& [b, n] : common) factor *= GiNaC::pow(b, n);
    if (factor.is_equal(1)) return s.unit();
    double value = 1;
    try {
        value = st.evaluate(factor);
    } catch (const std::exception&) {  // a constant with no value: taken positive
    }
    return (value < 0 ? -1 : 1) * (s / factor).unit();
}

// the geometry of one coordinate's row
struct Plan {
    BodySet S;
    Motion motion = Motion::rotate;
    Vector u;
    const Point* O = nullptr;
    std::shared_ptr<Point> own;  // O when it is no point of the model
    std::string note;
};

// the position of P from N_o, or false when P was never located
bool position_of(const System& sys, const Point& P, Vector& r) {
    try {
        r = P.pos_from(sys.origin());
        return true;
    } catch (const ModelError&) {
        return false;
    }
}

// The instantaneous centre of S's motion when only q changes: the point whose partial
// velocity is zero, r^{IC/cm} = w x v / (w . w) for the partial angular velocity w and the
// mass centre's partial velocity v (planar motion: v normal to w). A point of the model on the
// axis through it along w stands for it (a point of S first: a rolling disk's contact point;
// then a fixed point such as a top's tip at N_o: the moments about any point of the axis have
// the same component along w); else a point IC_q.
void locate_instantaneous_centre(const System& sys, const TimeVariable& q, const Body& B,
                                 const Vector& w, const Vector& v, Plan& p) {
    Vector r_cm;
    if (!position_of(sys, B.cm(), r_cm) ||
        !is_zero_at_random_states(sys.symbols(), dot(w, v)))
        return;
    const Vector r = r_cm + cross(w, v) / dot(w, w);
    for (int pass = 0; pass < 2 && !p.O; ++pass)
        for (const Point* P : sys.points()) {
            const bool on_S = P->owner() && std::find(p.S.begin(), p.S.end(), P->owner()) != p.S.end();
            Vector rp;
            if (on_S != (pass == 0) || !position_of(sys, *P, rp) || !zero(sys, v + cross(w, rp - r_cm)))
                continue;
            p.O = P;
            break;
        }
    if (p.O) return;
    p.own = std::make_shared<Point>("IC_" + q.name());
    p.own->set_pos(sys.origin(), r);
    p.O = p.own.get();
}

// The model's kinematics as the planner tests it: which bodies each speed moves
// (MovingBodies), and each point's velocity and position, measured in N once (not once per
// coordinate), with their values at the zero tests' random states
class PlannerKinematics {
public:
    explicit PlannerKinematics(const System& sys) : sys_(sys), moving_(sys) {}

    MovingBodies& moving() { return moving_; }
    MeasuresAtRandomStates& at() { return moving_.at(); }
    const Col3& w(std::size_t body) const { return moving_.w(body); }
    const Col3& v(std::size_t body) const { return moving_.v(body); }

    /// P's velocity in N, measured in N; nothing for a point never located
    const std::optional<Col3>& velocity(const Point& P) {
        auto [it, added] = point_v_.try_emplace(&P);
        if (added) {
            try {
                it->second = P.vel_in(sys_.newtonian()).components_in(sys_.newtonian());
            } catch (const ModelError&) {
            }
        }
        return it->second;
    }

    /// P's position from N_o at the random states; nothing for a point never located
    const std::optional<MeasuresAtRandomStates::Values>& position(const Point& P) {
        auto [it, added] = point_r_.try_emplace(&P);
        if (added) {
            Vector r;
            if (position_of(sys_, P, r)) it->second = at().calc_values(r.components_in(sys_.newtonian()));
        }
        return it->second;
    }

private:
    const System& sys_;
    MovingBodies moving_;
    std::map<const Point*, std::optional<Col3>> point_v_;
    std::map<const Point*, std::optional<MeasuresAtRandomStates::Values>> point_r_;
};

MeasuresAtRandomStates::Values cross_at(const MeasuresAtRandomStates::Values& a,
                                        const MeasuresAtRandomStates::Values& b) {
    MeasuresAtRandomStates::Values c{};
    for (std::size_t k = 0; k < c.size(); ++k) {
        c[k][0] = a[k][1] * b[k][2] - a[k][2] * b[k][1];
        c[k][1] = a[k][2] * b[k][0] - a[k][0] * b[k][2];
        c[k][2] = a[k][0] * b[k][1] - a[k][1] * b[k][0];
    }
    return c;
}

MeasuresAtRandomStates::Values minus_at(MeasuresAtRandomStates::Values a,
                                        const MeasuresAtRandomStates::Values& b) {
    for (std::size_t k = 0; k < a.size(); ++k)
        for (std::size_t i = 0; i < 3; ++i) a[k][i] -= b[k][i];
    return a;
}

// The same plan as plan_coordinate below, its tests made on the kinematics' values at the
// random states: which bodies move and how, by the change of each velocity when q' alone moves
// by 1 (a partial velocity, one walk of the kinematics for all bodies), and S turning as one
// body about O by those partials and the points' positions, with no symbolic derivative but
// the direction's. Nothing where a measure cannot be evaluated at the states (the symbolic
// tests decide then).
std::optional<Plan> plan_coordinate_at_random_states(
    const System& sys, const TimeVariable& q, const std::function<bool()>& constraint_forces_are_loads,
    PlannerKinematics& kin) {
    using Values = MeasuresAtRandomStates::Values;
    const Frame& N = sys.newtonian();
    const ex& qd = q.d(1);
    MeasuresAtRandomStates& at = kin.at();
    try {
        Plan p;
        std::vector<std::size_t> index;  // each body of S's place in sys.bodies()
        std::vector<Values> pw, pv;      // their partial angular and mass centres' velocities
        std::vector<bool> turns;
        const std::vector<const Body*>& bodies = sys.bodies();
        const std::vector<BodyMotion>& moves = kin.moving().calc_motions(qd);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            const bool w_moves = moves[i].turns, v_moves = moves[i].slides;
            if (!w_moves && !v_moves) continue;
            p.S.push_back(bodies[i]);
            index.push_back(i);
            pw.push_back(w_moves ? at.calc_changes(kin.w(i), qd) : Values{});
            pv.push_back(v_moves ? at.calc_changes(kin.v(i), qd) : Values{});
            turns.push_back(w_moves);
        }
        if (p.S.empty()) {
            p.note = "nothing moves when only " + q.name() + " changes";
            return p;
        }
        // the direction: the first turning (else sliding) body's partial velocity, symbolic
        // and in the frames the model writes it in
        auto partial_w = [&](const Body& b) { return b.frame()->ang_vel_in(N).diff(qd).simplify(); };
        auto partial_v = [&](const Body& b) { return b.cm().vel_in(N).diff(qd).simplify(); };
        const auto turning = std::find(turns.begin(), turns.end(), true);
        if (turning == turns.end()) {
            p.motion = Motion::translate;
            p.u = row_direction(sys.symbols(), partial_v(*p.S.front()));
            for (std::size_t i = 0; i < p.S.size(); ++i)
                if (!MeasuresAtRandomStates::agree(pv[i], pv.front()))
                    p.note = "S does not slide as one body when only " + q.name() +
                             " changes; constraint forces may remain";
            return p;
        }
        const std::size_t t = static_cast<std::size_t>(turning - turns.begin());
        p.motion = Motion::rotate;
        const Vector w0 = partial_w(*p.S[t]);
        p.u = row_direction(sys.symbols(), w0);
        // the about point: a point of S that stays put when only q changes (the joint)
        for (const Point* P : sys.points()) {
            if (!P->owner() || std::find(p.S.begin(), p.S.end(), P->owner()) == p.S.end()) continue;
            const std::optional<Col3>& v = kin.velocity(*P);
            if (!v) continue;  // a point never located cannot serve as the about point
            if (!at.calc_changes_with(*v, qd)) {
                p.O = P;
                break;
            }
        }
        if (!p.O && constraint_forces_are_loads())
            locate_instantaneous_centre(sys, q, *p.S[t], w0, partial_v(*p.S[t]), p);
        if (!p.O) {
            p.note = "no point of S stays fixed when only " + q.name() +
                     " changes; no about point eliminates the constraint forces";
            return p;
        }
        // check: S turns as one body about O (partials w0 and w0 x r^{cm/O})
        const std::optional<Values>& r_O = kin.position(*p.O);
        for (std::size_t i = 0; i < p.S.size(); ++i) {
            const std::optional<Values>& r_cm = kin.position(p.S[i]->cm());
            if (!r_O || !r_cm) return std::nullopt;
            // (a particle has no orientation: only its velocity counts)
            const bool rigid = (!p.S[i]->frame() || MeasuresAtRandomStates::agree(pw[i], pw[t])) &&
                               MeasuresAtRandomStates::agree(pv[i], cross_at(pw[t], minus_at(*r_cm, *r_O)));
            if (!rigid) {
                p.note = "S does not turn as one body about " + p.O->name() + " when only " +
                         q.name() + " changes; constraint forces may remain";
                break;
            }
        }
        return p;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// `constraint_forces_are_loads` tells (when asked: it costs an evaluation of the generalized
// forces) whether declared loads supply every constraint's force
Plan plan_coordinate(const System& sys, const TimeVariable& q,
                     const std::function<bool()>& constraint_forces_are_loads) {
    const Frame& N = sys.newtonian();
    const ex& qd = q.d(1);
    Plan p;
    // what moves when only q changes
    std::vector<Vector> pw, pv;
    for (const Body* b : sys.bodies()) {
        Vector w = b->frame() ? b->frame()->ang_vel_in(N).diff(qd) : Vector();
        Vector v = b->cm().vel_in(N).diff(qd);
        if (zero(sys, w) && zero(sys, v)) continue;
        p.S.push_back(b);
        pw.push_back(w.simplify());
        pv.push_back(v.simplify());
    }
    if (p.S.empty()) {
        p.note = "nothing moves when only " + q.name() + " changes";
        return p;
    }
    auto turning = std::find_if(pw.begin(), pw.end(), [](const Vector& w) { return !w.is_zero(); });
    if (turning == pw.end()) {
        // translation: every body slides the same way
        p.motion = Motion::translate;
        p.u = row_direction(sys.symbols(), pv.front());
        for (std::size_t i = 0; i < p.S.size(); ++i)
            if (!zero(sys, pv[i] - pv.front()))
                p.note = "S does not slide as one body when only " + q.name() +
                         " changes; constraint forces may remain";
        return p;
    }
    p.motion = Motion::rotate;
    const Vector& w0 = *turning;
    p.u = row_direction(sys.symbols(), w0);
    // the about point: a point of S that stays put when only q changes (the joint)
    for (const Point* P : sys.points()) {
        if (!P->owner() || std::find(p.S.begin(), p.S.end(), P->owner()) == p.S.end()) continue;
        Vector v;
        try {
            v = P->vel_in(N);
        } catch (const ModelError&) {
            continue;  // a point never located cannot serve as the about point
        }
        if (zero(sys, v.diff(qd))) {
            p.O = P;
            break;
        }
    }
    // none: the instantaneous centre, where workless contact forces pass (with declared
    // constraints, only when declared loads supply their forces: the row keeps those loads,
    // as the other rows do; an undeclared constraint force would do work when q alone changes)
    if (!p.O && constraint_forces_are_loads())
        locate_instantaneous_centre(sys, q, *p.S[static_cast<std::size_t>(turning - pw.begin())],
                                    w0, pv[static_cast<std::size_t>(turning - pw.begin())], p);
    if (!p.O) {
        p.note = "no point of S stays fixed when only " + q.name() +
                 " changes; no about point eliminates the constraint forces";
        return p;
    }
    // check: S turns as one body about O (partials w0 and w0 x r^{cm/O})
    for (std::size_t i = 0; i < p.S.size(); ++i) {
        // (a particle has no orientation: only its velocity counts)
        bool rigid = (!p.S[i]->frame() || zero(sys, pw[i] - w0)) &&
                     zero(sys, pv[i] - cross(w0, p.S[i]->cm().pos_from(*p.O)));
        if (!rigid) {
            p.note = "S does not turn as one body about " + p.O->name() + " when only " +
                     q.name() + " changes; constraint forces may remain";
            break;
        }
    }
    return p;
}

// true if the placement of p (its chain of located-from points) passes through a point of b
bool placed_from(const Point* p, const Body& b) {
    for (const Point* x = p ? p->located_from() : nullptr; x; x = x->located_from())
        if (x->owner() == &b) return true;
    return false;
}

// true if frame F is oriented, through its chain of parents, from frame B
bool oriented_from(const Frame* F, const Frame* B) {
    for (const Frame* x = F ? F->parent() : nullptr; x && B; x = x->parent())
        if (x == B) return true;
    return false;
}

}  // namespace

BodySet calc_bodies_beyond(const System& sys, const JointReaction& reaction) {
    const Body& child = *reaction.child;
    BodySet S;
    for (const Body* b : sys.bodies()) {
        bool beyond =
            b == &child || placed_from(&b->cm(), child) || oriented_from(b->frame(), child.frame());
        if (!beyond) continue;
        if (b == reaction.parent)
            throw ModelError("plan_roadmap(): the joint reaction '" + reaction.name +
                             "' acts on '" + child.name() + "' from '" + b->name() + "', but '" +
                             b->name() + "' is placed from '" + child.name() +
                             "'; declare the reaction with its parent and child swapped");
        S.push_back(b);
    }
    return S;
}

namespace {

// the row of a reaction measure: translate along its direction (force) or rotate about it
// (torque) with S = what moves if the joint let that motion through, about the joint
RoadmapRow plan_reaction(const System& sys, const JointReaction& reaction,
                         const ReactionComponent& c, Analysis analysis) {
    RoadmapRow r{.variable = c.measure,
                 .motion = c.kind == LoadKind::force ? Motion::translate : Motion::rotate,
                 .direction = c.direction,
                 .system = calc_bodies_beyond(sys, reaction),
                 .about = reaction.at,
                 .analysis = analysis};
    // S should meet the rest only at this joint; other joints leave their forces in the row
    std::string elsewhere;
    for (const Point* p : sys.points()) {
        const Point* from = p->located_from();
        if (!p->owner() || !from || p == reaction.at) continue;
        if (std::find(r.system.begin(), r.system.end(), p->owner()) == r.system.end()) continue;
        if (from->owner() == reaction.parent ||
            std::find(r.system.begin(), r.system.end(), from->owner()) != r.system.end())
            continue;
        // a point placed through points of no body from the parent is the same joint
        const Point* up = from;
        while (up && !up->owner()) up = up->located_from();
        if (up ? up->owner() == reaction.parent : reaction.parent == nullptr) continue;
        elsewhere += (elsewhere.empty() ? "" : ", ") + p->name();
    }
    if (!elsewhere.empty())
        r.note = "S is joined to the rest at " + elsewhere +
                 " too; the constraint forces there "
                 "stay in this row";
    return r;
}

// The reaction measures among `unknowns` whose own rows (plan_reaction) would repeat one
// another: the same S, the same motion, parallel directions and, for rotations, the same
// about point. Such rows are one equation twice, and the measures they hold could not be
// told apart; both are returned.
GiNaC::exset calc_repeated_reaction_rows(const System& sys, const std::vector<ex>& unknowns,
                                         Analysis analysis) {
    GiNaC::exset out;
    std::vector<RoadmapRow> own;
    for (const ex& x : unknowns) {
        const JointReaction* jr = sys.reaction_of(x);
        if (!jr) continue;
        auto c = std::find_if(jr->components.begin(), jr->components.end(),
                              [&](const ReactionComponent& rc) { return rc.measure.is_equal(x); });
        RoadmapRow r = plan_reaction(sys, *jr, *c, analysis);
        r.variable = x;
        for (const RoadmapRow& o : own) {
            if (o.motion != r.motion || o.system.size() != r.system.size()) continue;
            if (r.motion == Motion::rotate && o.about != r.about) continue;
            if (!std::is_permutation(o.system.begin(), o.system.end(), r.system.begin())) continue;
            if (!zero(sys, cross(o.direction, r.direction))) continue;
            // both measures are planned together, so that their rows differ
            out.insert(o.variable);
            out.insert(x);
        }
        own.push_back(std::move(r));
    }
    return out;
}

// Minimum-cost assignment of each of n agents to a distinct one of m >= n tasks (Hungarian
// algorithm, Kuhn-Munkres with potentials); cost[i][j] = kInfeasible forbids a pair. Returns
// the task of each agent, or an empty vector when no complete assignment exists.
constexpr double kInfeasible = 1e9;
std::vector<int> assign_min_cost(const std::vector<std::vector<double>>& cost) {
    const std::size_t n = cost.size(), m = n ? cost[0].size() : 0;
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> u(n + 1, 0), v(m + 1, 0);
    std::vector<std::size_t> p(m + 1, 0), way(m + 1, 0);
    for (std::size_t i = 1; i <= n; ++i) {
        p[0] = i;
        std::size_t j0 = 0;
        std::vector<double> minv(m + 1, inf);
        std::vector<bool> used(m + 1, false);
        do {
            used[j0] = true;
            std::size_t i0 = p[j0], j1 = 0;
            double delta = inf;
            for (std::size_t j = 1; j <= m; ++j) {
                if (used[j]) continue;
                double cur = cost[i0 - 1][j - 1] - u[i0] - v[j];
                if (cur < minv[j]) minv[j] = cur, way[j] = j0;
                if (minv[j] < delta) delta = minv[j], j1 = j;
            }
            for (std::size_t j = 0; j <= m; ++j) {
                if (used[j]) u[p[j]] += delta, v[j] -= delta;
                else minv[j] -= delta;
            }
            j0 = j1;
        } while (p[j0] != 0);
        do {
            std::size_t j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
        } while (j0);
    }
    std::vector<int> task(n, -1);
    for (std::size_t j = 1; j <= m; ++j)
        if (p[j]) {
            if (cost[p[j] - 1][j - 1] >= kInfeasible) return {};
            task[p[j] - 1] = static_cast<int>(j - 1);
        }
    return task;
}

std::string list_text(const std::vector<ex>& xs) {
    std::string s;
    for (const ex& x : xs) s += (s.empty() ? "" : ", ") + to_string(x);
    return s;
}

}  // namespace

namespace {

// The blocks of rows that must be solved together (strongly connected components of "row i
// holds the unknown of row j"), in an order in which each block needs only the unknowns of
// blocks before it; ties keep the rows' order. Tarjan's algorithm, then a stable topological
// sort of the components.
std::vector<std::vector<std::size_t>> solve_order(
    const std::vector<std::vector<std::size_t>>& deps) {
    const std::size_t n = deps.size();
    std::vector<int> index(n, -1), low(n, 0), comp(n, -1);
    std::vector<bool> on_stack(n, false);
    std::vector<std::size_t> stack;
    int counter = 0, n_comp = 0;
    // iterative Tarjan: (node, next edge) frames
    for (std::size_t root = 0; root < n; ++root) {
        if (index[root] >= 0) continue;
        std::vector<std::pair<std::size_t, std::size_t>> frames{{root, 0}};
        index[root] = low[root] = counter++;
        stack.push_back(root);
        on_stack[root] = true;
        while (!frames.empty()) {
            auto& [v, e] = frames.back();
            if (e < deps[v].size()) {
                std::size_t w = deps[v][e++];
                if (index[w] < 0) {
                    index[w] = low[w] = counter++;
                    stack.push_back(w);
                    on_stack[w] = true;
                    frames.push_back({w, 0});
                } else if (on_stack[w]) {
                    low[v] = std::min(low[v], index[w]);
                }
                continue;
            }
            if (low[v] == index[v]) {
                std::size_t w;
                do {
                    w = stack.back();
                    stack.pop_back();
                    on_stack[w] = false;
                    comp[w] = n_comp;
                } while (w != v);
                ++n_comp;
            }
            std::size_t done = v;
            frames.pop_back();
            if (!frames.empty())
                low[frames.back().first] = std::min(low[frames.back().first], low[done]);
        }
    }
    std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(n_comp));
    for (std::size_t i = 0; i < n; ++i) members[static_cast<std::size_t>(comp[i])].push_back(i);
    std::vector<bool> placed(static_cast<std::size_t>(n_comp), false);
    std::vector<std::vector<std::size_t>> order;
    while (order.size() < members.size()) {
        // the ready block whose first row comes first
        std::size_t best = members.size();
        for (std::size_t c = 0; c < members.size(); ++c) {
            if (placed[c]) continue;
            bool ready = true;
            for (std::size_t i : members[c])
                for (std::size_t w : deps[i])
                    if (static_cast<std::size_t>(comp[w]) != c &&
                        !placed[static_cast<std::size_t>(comp[w])])
                        ready = false;
            if (ready && (best == members.size() || members[c].front() < members[best].front()))
                best = c;
        }
        placed[best] = true;
        order.push_back(members[best]);
    }
    return order;
}

}  // namespace

namespace {

// The accelerations that fill the rows the unknowns leave free (see plan_default_roadmap):
// agents are the free rows or the candidate accelerations, whichever are fewer; an
// acceleration takes its own coordinate's row at no cost, or a constraint row whose equation
// holds it (the later coordinates first, as the dependent ones). Without a complete
// assignment, only the accelerations whose own rows are free. In the coordinates' order.
std::vector<ex> calc_completing_accelerations(const System& sys,
                                              const std::vector<TimeVariable>& coordinates,
                                              const std::vector<ex>& unknowns,
                                              const std::vector<std::size_t>& free_rows,
                                              const std::vector<ex>& row_equations) {
    const std::size_t n_coordinates = coordinates.size();
    std::vector<std::size_t> own;  // the coordinate of each candidate
    std::vector<ex> candidates;
    for (std::size_t j = 0; j < n_coordinates; ++j) {
        const TimeVariable& q = coordinates[j];
        bool listed = false;
        for (int d = 0; d <= q.order() && !listed; ++d)
            for (const ex& x : unknowns) listed = listed || x.is_equal(q.d(d));
        if (listed) continue;
        own.push_back(j);
        candidates.push_back(q.d(std::min(2, q.order())));
    }
    if (candidates.empty() || free_rows.empty()) return {};
    // cost[row][candidate]
    const std::size_t m = free_rows.size(), p = candidates.size();
    std::vector<std::vector<double>> cost(m, std::vector<double>(p, kInfeasible));
    for (std::size_t a = 0; a < m; ++a) {
        const std::size_t i = free_rows[a];
        if (i < n_coordinates) {
            for (std::size_t b = 0; b < p; ++b)
                if (own[b] == i) cost[a][b] = 0;
            continue;
        }
        const std::vector<bool> changes =
            calc_changes_with_at_random_states(sys.symbols(), row_equations[i], candidates);
        for (std::size_t b = 0; b < p; ++b)
            if (changes[b])
                cost[a][b] = 1 + 0.5 * static_cast<double>(p - b) / static_cast<double>(p + 1);
    }
    std::vector<bool> chosen(p, false);
    if (m <= p) {
        for (int b : assign_min_cost(cost))
            if (b >= 0) chosen[static_cast<std::size_t>(b)] = true;
    } else {
        std::vector<std::vector<double>> by_candidate(p, std::vector<double>(m));
        for (std::size_t a = 0; a < m; ++a)
            for (std::size_t b = 0; b < p; ++b) by_candidate[b][a] = cost[a][b];
        if (!assign_min_cost(by_candidate).empty()) chosen.assign(p, true);
    }
    if (std::none_of(chosen.begin(), chosen.end(), [](bool c) { return c; }))
        for (std::size_t a = 0; a < m; ++a)
            for (std::size_t b = 0; b < p; ++b)
                if (cost[a][b] == 0) chosen[b] = true;
    std::vector<ex> out;
    for (std::size_t b = 0; b < p; ++b)
        if (chosen[b]) out.push_back(candidates[b]);
    return out;
}

// plan_roadmap; with `completion`, when the unknowns leave coordinate or constraint rows free
// (dynamics), it receives the accelerations that fill them and no rows are planned
std::vector<RoadmapRow> plan_rows(const System& sys, const std::vector<TimeVariable>& coordinates,
                                  const std::vector<ex>& unknowns, Analysis analysis,
                                  std::vector<ex>* completion) {
    // the constraint rows the model declares (motion constraints restrict speeds only, so
    // statics has none of them)
    std::vector<RoadmapRow> constraint_rows;
    for (const Constraint& c : sys.constraints()) {
        if (analysis == Analysis::statics && c.kind == ConstraintKind::motion) continue;
        RoadmapRow r;
        r.analysis = analysis;
        r.constraint = c.name;
        form_constraint_row(sys, r, unknowns);
        constraint_rows.push_back(std::move(r));
    }
    // the measures of declared joint reactions get rows of their own; the other unknowns
    // share the coordinate and constraint rows. A measure whose own row would repeat an
    // earlier measure's (a ladder's wall push and floor friction, both along Nx> on S = the
    // ladder) is planned like a contact force instead: its row is searched among the
    // coordinates' and the free-body rows
    std::vector<ex> shared;
    std::size_t n_reactions = 0;
    const GiNaC::exset repeated = calc_repeated_reaction_rows(sys, unknowns, analysis);
    const auto own_row = [&](const ex& x) { return sys.reaction_of(x) && !repeated.count(x); };
    for (const ex& x : unknowns) {
        if (own_row(x))
            ++n_reactions;
        else
            shared.push_back(x);
    }
    std::optional<bool> forces_declared;
    const std::function<bool()> constraint_forces_are_loads = [&] {
        if (!forces_declared)
            forces_declared = detail::constraint_forces_declared(sys, coordinates, unknowns);
        return *forces_declared;
    };
    // each coordinate's S, direction and about point, tested at random states, symbolically
    // where the kinematics cannot be evaluated there
    PlannerKinematics kinematics(sys);
    detail::InertiaLoadsMemo inertia_loads;  // the rows below meet the same bodies
    auto plan = [&](const TimeVariable& q) {
        std::optional<Plan> p = plan_coordinate_at_random_states(sys, q, constraint_forces_are_loads, kinematics);
        return p ? std::move(*p) : plan_coordinate(sys, q, constraint_forces_are_loads);
    };
    std::vector<Plan> plans;
    for (const TimeVariable& q : coordinates) plans.push_back(plan(q));
    // the rows of the specified motions something moves with, after the constraint rows: the
    // loads that drive them are found there (column 4: treat the specified quantity as a
    // coordinate and see what moves); plans[coordinates.size() + d] is the d-th one's
    std::vector<TimeVariable> driven;
    for (const TimeVariable& v : detail::calc_driven_quantities(sys, coordinates)) {
        Plan p = plan(v);
        if (p.S.empty() || (p.motion == Motion::rotate && !p.O)) continue;
        driven.push_back(v);
        plans.push_back(std::move(p));
    }
    const std::size_t n_coordinates = coordinates.size(), n_constraints = constraint_rows.size();
    const std::size_t n_rows = n_coordinates + n_constraints + driven.size();
    // the kind of row i and its plan (coordinate and driven rows)
    auto is_constraint = [&](std::size_t i) { return i >= n_coordinates && i < n_coordinates + n_constraints; };
    auto is_driven = [&](std::size_t i) { return i >= n_coordinates + n_constraints; };
    auto plan_of = [&](std::size_t i) -> const Plan& {
        return plans[is_driven(i) ? i - n_constraints : i];
    };
    // why the rows of the coordinates and constraints alone do not serve (then the free-body
    // rows of what carries the unknown loads are searched too)
    std::string refusal;
    if (shared.size() > n_rows)
        refusal = (
            "plan_roadmap(): " + std::to_string(shared.size()) + " unknowns but only " +
            std::to_string(coordinates.size()) + " coordinates and " +
            std::to_string(constraint_rows.size()) + " constraint rows" +
            (driven.empty() ? std::string()
                            : " and " + std::to_string(driven.size()) + " rows of specified motions") +
            (n_reactions ? " (besides " + std::to_string(n_reactions) +
                               " joint-reaction measures, which have rows of their own)"
                         : std::string()) +
            "; each row determines one unknown, so declare fewer unknowns, declare "
            "the model's constraints, or declare constraint forces as joint "
            "reactions (System::add_joint_reaction, the reaction statement)");

    const std::size_t n = shared.size();
    std::vector<int> row_of;
    if (refusal.empty()) {
        // a statics-style equation per coordinate, to see which load measures it holds
        std::vector<ex> probe(n_rows);
        for (std::size_t i = 0; i < n_rows; ++i) {
            if (is_constraint(i)) {
                probe[i] = constraint_rows[i - n_coordinates].equation;
                continue;
            }
            const Plan& p = plan_of(i);
            if (p.S.empty() || (p.motion == Motion::rotate && !p.O)) continue;
            RoadmapRow r{.variable = ex(), .motion = p.motion, .direction = p.u, .system = p.S,
                         .about = p.O, .analysis = Analysis::statics};
            probe[i] = form_roadmap_equation(sys, r);
        }

        // each unknown to its own row: a coordinate (or its derivative) to its coordinate's row,
        // else a row whose equation holds it, preferring rows with the fewest other unknowns,
        // and keeping earlier coordinates in their own rows when a constraint row must take one
        // (the constraint rows then read as the equations of the dependent coordinates)
        // which unknowns each probe holds: an index built once (one pass over each probe's DAG),
        // not a scan of the whole probe for every pair of unknown and row
        std::vector<GiNaC::exset> held(n_rows);
        std::vector<std::size_t> n_held(n_rows, 0);
        for (std::size_t i = 0; i < n_rows; ++i) {
            if (probe[i].is_zero()) continue;
            const GiNaC::exset syms = symbols_of(probe[i]);
            std::vector<ex> present;
            for (const ex& x : shared)
                if (syms.count(x)) present.push_back(x);
            // held by meaning: a measure whose coefficient cancels (a torque normal to u, in
            // measures that cancel only as numbers) drops out
            const std::vector<bool> changes = calc_changes_with_at_random_states(sys.symbols(), probe[i], present);
            for (std::size_t j = 0; j < present.size(); ++j)
                if (changes[j]) held[i].insert(present[j]), ++n_held[i];
        }
        // a speed unknown (q' of a coordinate q declared to order 2) goes to a row whose
        // equation (dynamics) holds it, preferring rows that still hold it with the other
        // speeds and all accelerations 0 (a steady precession rate: the row about the nodal
        // axis, not psi's own row, which holds psi' only times theta')
        std::vector<int> speed_of(n, -1);
        std::vector<std::vector<bool>> holds_speed(n), holds_speed_alone(n);
        if (analysis == Analysis::dynamics)
            for (std::size_t k = 0; k < n; ++k) speed_of[k] = detail::calc_speed_of(shared[k], coordinates);
        if (std::any_of(speed_of.begin(), speed_of.end(), [](int j) { return j >= 0; })) {
            for (std::size_t k = 0; k < n; ++k) holds_speed[k] = holds_speed_alone[k] = std::vector<bool>(n_rows, false);
            for (std::size_t i = 0; i < n_coordinates + n_constraints; ++i) {
                ex E;
                if (is_constraint(i)) {
                    E = constraint_rows[i - n_coordinates].equation;
                } else {
                    const Plan& p = plans[i];
                    if (p.S.empty() || (p.motion == Motion::rotate && !p.O)) continue;
                    RoadmapRow r{.variable = ex(), .motion = p.motion, .direction = p.u, .system = p.S,
                                 .about = p.O, .analysis = Analysis::dynamics};
                    E = form_roadmap_equation(sys, r);
                }
                std::vector<ex> speeds;
                for (std::size_t k = 0; k < n; ++k)
                    if (speed_of[k] >= 0) speeds.push_back(shared[k]);
                const std::vector<bool> changes = calc_changes_with_at_random_states(sys.symbols(), E, speeds);
                for (std::size_t k = 0, s = 0; k < n; ++k) {
                    if (speed_of[k] < 0) continue;
                    holds_speed[k][i] = changes[s++];
                    holds_speed_alone[k][i] =
                        holds_speed[k][i] &&
                        calc_changes_with_others_zero_at_random_states(
                            sys.symbols(), E, shared[k], detail::calc_other_rates(shared[k], coordinates));
                }
            }
        }
        std::vector<std::vector<double>> cost(n, std::vector<double>(n_rows, kInfeasible));
        for (std::size_t k = 0; k < n; ++k) {
            bool derivative = false;  // of a coordinate: never on a specified motion's row
            for (const TimeVariable& q : coordinates)
                for (int d = 0; d <= q.order(); ++d) derivative = derivative || shared[k].is_equal(q.d(d));
            for (std::size_t i = 0; i < n_rows; ++i) {
                if (speed_of[k] >= 0) {
                    if (!holds_speed[k][i]) continue;
                    cost[k][i] = 1 + static_cast<double>(n_held[i]) +
                                 (holds_speed_alone[k][i] ? 0 : static_cast<double>(n_rows + 1));
                    continue;
                }
                bool own = false;
                if (i < n_coordinates)
                    for (int d = 0; d <= coordinates[i].order(); ++d)
                        if (shared[k].is_equal(coordinates[i].d(d))) own = true;
                if (own) {
                    cost[k][i] = 0;
                    continue;
                }
                if (!held[i].count(shared[k]) || (derivative && is_driven(i))) continue;
                // the load drives the row's motion (a torque about its axis, a force along its
                // direction); a specified motion's row is complete only with the load that
                // drives it, so it takes no other (a contact force there would leave out an
                // actuator the model does not declare)
                const bool drives =
                    !is_constraint(i) && detail::acts_only_along(sys, shared[k], plan_of(i).motion, plan_of(i).u);
                if (is_driven(i) && !drives) continue;
                const double others = static_cast<double>(n_held[i] - 1);
                cost[k][i] = 1 + others + (is_constraint(i)
                                               ? 0.5 * static_cast<double>(n - k) / static_cast<double>(n + 1)
                                               : 0);
                // among rows that hold as many others, the row whose motion the load drives
                if (drives) cost[k][i] -= 0.25;
            }
        }
        row_of = n ? assign_min_cost(cost) : std::vector<int>{};
        if (n && row_of.empty()) {
            // name an unknown no row can hold, or say that they compete
            for (std::size_t k = 0; k < n && refusal.empty(); ++k)
                if (speed_of[k] >= 0 &&
                    std::all_of(cost[k].begin(), cost[k].end(), [](double c) { return c >= kInfeasible; }))
                    refusal = "plan_roadmap(): no road-map row holds the speed '" + to_string(shared[k]) +
                              "' (the equation of every coordinate's row and constraint row is the "
                              "same whatever its value); a speed is found only from a row that "
                              "depends on it, as a steady motion's rate is from the row its "
                              "gyroscopic or centripetal terms enter; solve for another unknown";
                else if (std::all_of(cost[k].begin(), cost[k].end(), [](double c) { return c >= kInfeasible; }))
                    refusal = "plan_roadmap(): no road-map row holds the unknown '" +
                              to_string(shared[k]) +
                              "'; check that it acts on a body that moves, or that it is not "
                              "internal to every system the planner found";
            if (refusal.empty())
                refusal = "plan_roadmap(): the unknowns " + list_text(shared) +
                          " cannot each be given a row of their own (too many of them appear "
                          "only in the same rows); declare the model's constraints or fewer "
                          "unknowns";
        }
        for (std::size_t k = 0; k < row_of.size() && refusal.empty(); ++k) {
            const std::size_t i = static_cast<std::size_t>(row_of[k]);
            if (!is_constraint(i) && plan_of(i).motion == Motion::rotate && !plan_of(i).O)
                refusal = "plan_roadmap(): " + plan_of(i).note + " (unknown '" + to_string(shared[k]) + "')";
        }
    }

    // the rows no unknown took (the coordinates' rows that can be formed, the constraint
    // rows): the degrees of freedom the unknown loads leave undetermined
    if (completion && refusal.empty() && analysis == Analysis::dynamics) {
        std::vector<bool> taken(n_rows, false);
        for (int i : row_of) taken[static_cast<std::size_t>(i)] = true;
        std::vector<std::size_t> free_rows;
        std::vector<ex> row_equations(n_coordinates + n_constraints);
        for (std::size_t i = 0; i < n_coordinates + n_constraints; ++i) {
            if (taken[i]) continue;
            if (is_constraint(i)) {
                row_equations[i] = constraint_rows[i - n_coordinates].equation;
            } else {
                const Plan& p = plans[i];
                if (p.S.empty() || (p.motion == Motion::rotate && !p.O)) continue;
            }
            free_rows.push_back(i);
        }
        *completion = calc_completing_accelerations(sys, coordinates, unknowns, free_rows, row_equations);
        if (!completion->empty()) return {};
    }

    // the free-body rows: contact forces as unknowns in minimal coordinates (the road-map's
    // column 4: release the contact along u, S is what would move), about points chosen so
    // that each row holds as few unknowns as possible
    // (a speed has no free-body row: refused as it is)
    if (refusal.find("holds the speed") != std::string::npos) throw ModelError(refusal);
    const bool free_body = !refusal.empty();
    std::vector<RoadmapRow> free_rows;
    if (free_body) {
        std::vector<detail::FixedRow> fixed;
        for (std::size_t i = 0; i < coordinates.size(); ++i) {
            const Plan& p = plans[i];
            if (p.S.empty() || (p.motion == Motion::rotate && !p.O) || !p.note.empty()) continue;
            RoadmapRow r{.variable = ex(), .motion = p.motion, .direction = p.u, .system = p.S,
                         .about = p.O, .analysis = analysis};
            r.about_owned = p.own;
            r.equation = form_roadmap_equation(sys, r);
            fixed.push_back({std::move(r), static_cast<int>(i)});
        }
        for (const RoadmapRow& r : constraint_rows)
            fixed.push_back({r, detail::FixedRow::kAnyCoordinate});
        try {
            free_rows = detail::plan_free_body_rows(sys, coordinates, fixed, shared, unknowns,
                                                    analysis, constraint_forces_are_loads());
        } catch (const ModelError& e) {
            // a constraint whose force no declared load supplies leaves its bodies without
            // free-body rows: that first, it is the fix
            std::string constraints;
            if (!constraint_forces_are_loads())
                for (const Constraint& c : sys.constraints())
                    constraints += (constraints.empty() ? "" : ", ") + c.name;
            std::string rest = refusal.substr(refusal.find(' ') + 1);  // without "plan_roadmap(): "
            rest[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(rest[0])));
            if (!constraints.empty())
                throw ModelError(
                    "plan_roadmap(): the forces of the constraints " + constraints +
                    " are no declared loads, so no body their coordinates move has a free-body "
                    "row; declare the force that holds each constraint (a loop's pin force as a "
                    "force pair), with its measures unknown. " + rest +
                    ". Free-body rows of the bodies the unknown loads act on: " + e.what());
            throw ModelError(refusal + ". Free-body rows of the bodies the unknown loads act on: " +
                             e.what() +
                             " (declare each contact force on the body it acts on, with its "
                             "measure an unknown, or fewer unknowns)");
        }
    }

    // the rows, in the order of the unknowns
    std::vector<RoadmapRow> rows;
    std::vector<bool> reaction_row;
    for (RoadmapRow& r : free_rows) {
        rows.push_back(std::move(r));
        reaction_row.push_back(false);
    }
    std::size_t k = 0;
    for (const ex& x : unknowns) {
        if (const JointReaction* jr = own_row(x) ? sys.reaction_of(x) : nullptr) {
            auto c =
                std::find_if(jr->components.begin(), jr->components.end(),
                             [&](const ReactionComponent& rc) { return rc.measure.is_equal(x); });
            RoadmapRow r = plan_reaction(sys, *jr, *c, analysis);
            form_roadmap_row(sys, r, unknowns);
            if (!symbols_of(r.equation).count(x))
                throw ModelError("plan_roadmap(): the row of the reaction measure '" +
                                 to_string(x) + "' of '" + jr->name +
                                 "' does not hold it (S = what moves beyond '" + jr->child->name() +
                                 "' does not feel it); check the reaction's "
                                 "direction and its parent and child");
            rows.push_back(std::move(r));
            reaction_row.push_back(true);
            continue;
        }
        if (free_body) continue;  // its row is among the free-body rows
        const std::size_t i = static_cast<std::size_t>(row_of[k++]);
        reaction_row.push_back(false);
        if (is_constraint(i)) {
            // formed already, with no variable: its additional unknowns are all those it
            // holds, so only the one it is now for leaves the list
            RoadmapRow r = constraint_rows[i - n_coordinates];
            r.variable = x;
            std::erase_if(r.additional_unknowns,
                          [&](const ex& y) { return y.is_equal(r.variable); });
            rows.push_back(std::move(r));
            continue;
        }
        const Plan& p = plan_of(i);
        if (p.motion == Motion::rotate && !p.O)
            throw ModelError("plan_roadmap(): " + p.note + " (unknown '" + to_string(x) + "')");
        RoadmapRow r{.variable = x,
                     .motion = p.motion,
                     .direction = p.u,
                     .system = p.S,
                     .about = p.O,
                     .analysis = analysis};
        r.about_owned = p.own;
        r.note = p.note;
        form_roadmap_row(sys, r, unknowns);
        rows.push_back(std::move(r));
    }

    // the order of solution: blocks of rows that share unknowns, each after those it needs
    std::vector<std::vector<std::size_t>> deps(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (const ex& x : rows[i].additional_unknowns)
            for (std::size_t j = 0; j < rows.size(); ++j)
                if (j != i && rows[j].variable.is_equal(x)) deps[i].push_back(j);
    std::vector<std::vector<std::size_t>> blocks = solve_order(deps);

    // say where constraint forces stay in a row, and what closes the system
    std::string closing;
    for (const RoadmapRow& r : rows)
        if (r.motion == Motion::constraint) closing += (closing.empty() ? "" : ", ") + r.constraint;
    const SymbolTable& st = sys.symbols();
    for (const std::vector<std::size_t>& block : blocks) {
        bool has_reaction = false;
        for (std::size_t i : block) has_reaction = has_reaction || reaction_row[i];
        for (std::size_t i : block) {
            RoadmapRow& r = rows[i];
            if (r.motion == Motion::constraint || !r.note.empty()) continue;
            if ((has_reaction || free_body) && block.size() > 1) {
                // a block of rows with reaction measures: name the rows it is solved with
                std::vector<ex> with;
                for (std::size_t j : block)
                    if (j != i) with.push_back(rows[j].variable);
                r.note = "solve together with the rows of " + list_text(with);
                continue;
            }
            if (reaction_row[i] || free_body) continue;  // the others are solved before
            // the load measures left (other accelerations in a row are expected: they couple)
            std::vector<ex> loads;
            for (const ex& x : r.additional_unknowns)
                if (st.owns(x) && st.kind(x) == SymbolKind::unknown && !sys.reaction_of(x))
                    loads.push_back(x);
            if (loads.empty()) continue;
            r.note = "no choice of S and O eliminates " + list_text(loads) +
                     (closing.empty() ? "; solve the rows together"
                                      : "; the constraint rows (" + closing + ") close the system");
        }
    }
    // with reaction measures, the rows in the order of solution; without, in the order of the
    // unknowns, as callers that pair row k with unknown k expect
    if (n_reactions == 0 && !free_body) return rows;
    std::vector<RoadmapRow> ordered;
    for (const std::vector<std::size_t>& block : blocks)
        for (std::size_t i : block) ordered.push_back(std::move(rows[i]));
    return ordered;
}

}  // namespace

std::vector<RoadmapRow> plan_roadmap(const System& sys,
                                     const std::vector<TimeVariable>& coordinates,
                                     const std::vector<ex>& unknowns, Analysis analysis) {
    return plan_rows(sys, coordinates, unknowns, analysis, nullptr);
}

std::vector<RoadmapRow> plan_default_roadmap(const System& sys,
                                             const std::vector<TimeVariable>& coordinates) {
    std::vector<ex> unknowns = sys.symbols().symbols(SymbolKind::unknown);
    if (unknowns.empty()) {
        for (const TimeVariable& q : coordinates) unknowns.push_back(q.d(std::min(2, q.order())));
        return plan_roadmap(sys, coordinates, unknowns);
    }
    std::vector<ex> completion;
    std::vector<RoadmapRow> rows = plan_rows(sys, coordinates, unknowns, Analysis::dynamics, &completion);
    if (completion.empty()) return rows;
    unknowns.insert(unknowns.end(), completion.begin(), completion.end());
    return plan_roadmap(sys, coordinates, unknowns);
}

}  // namespace alembert
