// SPDX-License-Identifier: MIT
// The road-map planner: partial velocities decide S, the direction and the about point.
#include "alembert/eom/planner.hpp"

#include <algorithm>
#include <limits>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

namespace {

bool zero(const Vector& v) { return v.simplify().is_zero(); }

// the geometry of one coordinate's row
struct Plan {
    BodySet S;
    Motion motion = Motion::rotate;
    Vector u;
    const Point* O = nullptr;
    std::string note;
};

Plan plan_coordinate(const System& sys, const TimeVariable& q) {
    const Frame& N = sys.newtonian();
    const ex& qd = q.d(1);
    Plan p;
    // what moves when only q changes
    std::vector<Vector> pw, pv;
    for (const Body* b : sys.bodies()) {
        Vector w = b->frame() ? b->frame()->ang_vel_in(N).diff(qd) : Vector();
        Vector v = b->cm().vel_in(N).diff(qd);
        if (zero(w) && zero(v)) continue;
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
        p.u = pv.front().unit();
        for (std::size_t i = 0; i < p.S.size(); ++i)
            if (!zero(pv[i] - pv.front()))
                p.note = "S does not slide as one body when only " + q.name() +
                         " changes; constraint forces may remain";
        return p;
    }
    p.motion = Motion::rotate;
    const Vector& w0 = *turning;
    p.u = w0.unit();
    // the about point: a point of S that stays put when only q changes (the joint)
    for (const Point* P : sys.points()) {
        if (!P->owner() || std::find(p.S.begin(), p.S.end(), P->owner()) == p.S.end()) continue;
        Vector v;
        try {
            v = P->vel_in(N);
        } catch (const ModelError&) {
            continue;  // a point never located cannot serve as the about point
        }
        if (zero(v.diff(qd))) {
            p.O = P;
            break;
        }
    }
    if (!p.O) {
        p.note = "no point of S stays fixed when only " + q.name() +
                 " changes; no about point eliminates the constraint forces";
        return p;
    }
    // check: S turns as one body about O (partials w0 and w0 x r^{cm/O})
    for (std::size_t i = 0; i < p.S.size(); ++i) {
        bool rigid = zero(pw[i] - w0) &&
                     zero(pv[i] - cross(w0, p.S[i]->cm().pos_from(*p.O)));
        if (!rigid) {
            p.note = "S does not turn as one body about " + p.O->name() + " when only " +
                     q.name() + " changes; constraint forces may remain";
            break;
        }
    }
    return p;
}

}  // namespace

std::vector<RoadmapRow> plan_roadmap(const System& sys,
                                     const std::vector<TimeVariable>& coordinates,
                                     const std::vector<ex>& unknowns, Analysis analysis) {
    if (unknowns.size() > coordinates.size())
        throw ModelError("plan_roadmap(): " + std::to_string(unknowns.size()) +
                         " unknowns but only " + std::to_string(coordinates.size()) +
                         " coordinates; each row eliminates one unknown, so declare fewer "
                         "unknowns or add constraint rows");
    std::vector<Plan> plans;
    for (const TimeVariable& q : coordinates) plans.push_back(plan_coordinate(sys, q));

    // a statics-style equation per coordinate, to see which load measures it holds
    std::vector<ex> probe(coordinates.size());
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
        if (plans[i].S.empty() || (plans[i].motion == Motion::rotate && !plans[i].O)) continue;
        RoadmapRow r{.variable = coordinates[i].symbol(), .motion = plans[i].motion,
                     .direction = plans[i].u, .system = plans[i].S, .about = plans[i].O,
                     .analysis = Analysis::statics};
        probe[i] = form_roadmap_equation(sys, r);
    }

    // assign each unknown to a row: its own coordinate, else the row holding it with the
    // fewest other unknowns
    std::vector<int> row_of(unknowns.size(), -1);
    std::vector<bool> taken(coordinates.size(), false);
    for (std::size_t k = 0; k < unknowns.size(); ++k)
        for (std::size_t i = 0; i < coordinates.size(); ++i)
            for (int d = 0; d <= coordinates[i].order(); ++d)
                if (unknowns[k].is_equal(coordinates[i].d(d)) && !taken[i]) {
                    row_of[k] = static_cast<int>(i);
                    taken[i] = true;
                }
    for (std::size_t k = 0; k < unknowns.size(); ++k) {
        if (row_of[k] >= 0) continue;
        int best = -1;
        std::size_t best_others = std::numeric_limits<std::size_t>::max();
        for (std::size_t i = 0; i < coordinates.size(); ++i) {
            if (taken[i] || probe[i].is_zero() || !probe[i].has(unknowns[k])) continue;
            std::size_t others = 0;
            for (const ex& x : unknowns)
                if (!x.is_equal(unknowns[k]) && probe[i].has(x)) ++others;
            if (others < best_others) best = static_cast<int>(i), best_others = others;
        }
        if (best < 0)
            throw ModelError("plan_roadmap(): no road-map row holds the unknown '" +
                             to_string(unknowns[k]) +
                             "'; check that it acts on a body that moves, or that it is not "
                             "internal to every system the planner found");
        row_of[k] = best;
        taken[static_cast<std::size_t>(best)] = true;
    }

    std::vector<RoadmapRow> rows;
    for (std::size_t k = 0; k < unknowns.size(); ++k) {
        const Plan& p = plans[static_cast<std::size_t>(row_of[k])];
        if (p.motion == Motion::rotate && !p.O)
            throw ModelError("plan_roadmap(): " + p.note + " (unknown '" +
                             to_string(unknowns[k]) + "')");
        RoadmapRow r{.variable = unknowns[k], .motion = p.motion, .direction = p.u,
                     .system = p.S, .about = p.O, .analysis = analysis};
        r.note = p.note;
        form_roadmap_row(sys, r, unknowns);
        rows.push_back(std::move(r));
    }
    return rows;
}

}  // namespace alembert
