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

namespace {

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

std::vector<RoadmapRow> plan_roadmap(const System& sys,
                                     const std::vector<TimeVariable>& coordinates,
                                     const std::vector<ex>& unknowns, Analysis analysis) {
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
    const std::size_t n_rows = coordinates.size() + constraint_rows.size();
    if (unknowns.size() > n_rows)
        throw ModelError("plan_roadmap(): " + std::to_string(unknowns.size()) +
                         " unknowns but only " + std::to_string(coordinates.size()) +
                         " coordinates and " + std::to_string(constraint_rows.size()) +
                         " constraint rows; each row determines one unknown, so declare fewer "
                         "unknowns or declare the model's constraints");
    std::vector<Plan> plans;
    for (const TimeVariable& q : coordinates) plans.push_back(plan_coordinate(sys, q));

    // a statics-style equation per coordinate, to see which load measures it holds
    std::vector<ex> probe(n_rows);
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
        if (plans[i].S.empty() || (plans[i].motion == Motion::rotate && !plans[i].O)) continue;
        RoadmapRow r{.variable = coordinates[i].symbol(), .motion = plans[i].motion,
                     .direction = plans[i].u, .system = plans[i].S, .about = plans[i].O,
                     .analysis = Analysis::statics};
        probe[i] = form_roadmap_equation(sys, r);
    }
    for (std::size_t c = 0; c < constraint_rows.size(); ++c)
        probe[coordinates.size() + c] = constraint_rows[c].equation;

    // each unknown to its own row: a coordinate (or its derivative) to its coordinate's row,
    // else a row whose equation holds it, preferring rows with the fewest other unknowns,
    // and keeping earlier coordinates in their own rows when a constraint row must take one
    // (the constraint rows then read as the equations of the dependent coordinates)
    const std::size_t n = unknowns.size();
    std::vector<std::vector<double>> cost(n, std::vector<double>(n_rows, kInfeasible));
    for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t i = 0; i < n_rows; ++i) {
            bool own = false;
            if (i < coordinates.size())
                for (int d = 0; d <= coordinates[i].order(); ++d)
                    if (unknowns[k].is_equal(coordinates[i].d(d))) own = true;
            if (own) {
                cost[k][i] = 0;
                continue;
            }
            if (probe[i].is_zero() || !probe[i].has(unknowns[k])) continue;
            double others = 0;
            for (const ex& x : unknowns)
                if (!x.is_equal(unknowns[k]) && probe[i].has(x)) others += 1;
            cost[k][i] = 1 + others + (i >= coordinates.size()
                                           ? 0.5 * static_cast<double>(n - k) / static_cast<double>(n + 1)
                                           : 0);
        }
    }
    std::vector<int> row_of = assign_min_cost(cost);
    if (row_of.empty()) {
        // name an unknown no row can hold, or say that they compete
        for (std::size_t k = 0; k < n; ++k)
            if (std::all_of(cost[k].begin(), cost[k].end(), [](double c) { return c >= kInfeasible; }))
                throw ModelError("plan_roadmap(): no road-map row holds the unknown '" +
                                 to_string(unknowns[k]) +
                                 "'; check that it acts on a body that moves, or that it is not "
                                 "internal to every system the planner found");
        throw ModelError("plan_roadmap(): the unknowns " + list_text(unknowns) +
                         " cannot each be given a row of their own (too many of them appear "
                         "only in the same rows); declare the model's constraints or fewer "
                         "unknowns");
    }

    std::vector<RoadmapRow> rows;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = static_cast<std::size_t>(row_of[k]);
        if (i >= coordinates.size()) {
            // formed already, with no variable: its additional unknowns are all those it
            // holds, so only the one it is now for leaves the list
            RoadmapRow r = constraint_rows[i - coordinates.size()];
            r.variable = unknowns[k];
            std::erase_if(r.additional_unknowns, [&](const ex& x) { return x.is_equal(r.variable); });
            rows.push_back(std::move(r));
            continue;
        }
        const Plan& p = plans[i];
        if (p.motion == Motion::rotate && !p.O)
            throw ModelError("plan_roadmap(): " + p.note + " (unknown '" +
                             to_string(unknowns[k]) + "')");
        RoadmapRow r{.variable = unknowns[k], .motion = p.motion, .direction = p.u,
                     .system = p.S, .about = p.O, .analysis = analysis};
        r.note = p.note;
        form_roadmap_row(sys, r, unknowns);
        rows.push_back(std::move(r));
    }
    // say where constraint forces stay in a row, and what closes the system
    std::string closing;
    for (const RoadmapRow& r : rows)
        if (r.motion == Motion::constraint) closing += (closing.empty() ? "" : ", ") + r.constraint;
    const SymbolTable& st = sys.symbols();
    for (RoadmapRow& r : rows) {
        if (r.motion == Motion::constraint || !r.note.empty()) continue;
        // the load measures left (other accelerations in a row are expected: they couple)
        std::vector<ex> loads;
        for (const ex& x : r.additional_unknowns)
            if (st.owns(x) && st.kind(x) == SymbolKind::unknown) loads.push_back(x);
        if (loads.empty()) continue;
        r.note = "no choice of S and O eliminates " + list_text(loads) +
                 (closing.empty() ? "; solve the rows together"
                                  : "; the constraint rows (" + closing + ") close the system");
    }
    return rows;
}

}  // namespace alembert
