// SPDX-License-Identifier: MIT
// Kane's method: partial velocities, generalized active and inertia forces.
#include "alembert/eom/kane.hpp"

#include <map>

#include "alembert/eom/inertia_forces.hpp"

namespace alembert {

namespace {

// generalized forces of the loads (all of them, or only those without a potential)
std::vector<ex> active_forces(const System& sys, const std::vector<TimeVariable>& q,
                              bool include_gravity, bool include_conservative) {
    const Frame& N = sys.newtonian();
    std::vector<ex> F(q.size(), 0);
    std::map<const Point*, Vector> v;
    std::map<const Frame*, Vector> w;
    auto vel = [&](const Point* P) -> const Vector& {
        auto it = v.find(P);
        return it != v.end() ? it->second : v.emplace(P, P->vel_in(N)).first->second;
    };
    auto angvel = [&](const Frame* B) -> const Vector& {
        auto it = w.find(B);
        return it != w.end() ? it->second : w.emplace(B, B->ang_vel_in(N)).first->second;
    };
    for (const Load& l : sys.loads()) {
        if (l.conservative && !include_conservative) continue;
        for (std::size_t r = 0; r < q.size(); ++r) {
            const ex& u = q[r].d(1);
            if (l.kind == LoadKind::force) {
                F[r] += dot(vel(l.point).diff(u), l.vector);
            } else if (l.on->frame()) {
                F[r] += dot(angvel(l.on->frame()).diff(u), l.vector);
            }
        }
    }
    if (include_gravity && !sys.gravity().is_zero())
        for (const Body* b : sys.bodies())
            for (std::size_t r = 0; r < q.size(); ++r)
                F[r] += dot(vel(&b->cm()).diff(q[r].d(1)), b->mass() * sys.gravity());
    return F;
}

}  // namespace

std::vector<ex> form_generalized_active_forces(const System& sys,
                                               const std::vector<TimeVariable>& q,
                                               LoadSelection which) {
    bool all = which == LoadSelection::all;
    return active_forces(sys, q, all, all);
}

std::vector<ex> form_kane_equations(const System& sys, const std::vector<TimeVariable>& q) {
    const Frame& N = sys.newtonian();
    std::vector<ex> E = active_forces(sys, q, true, true);
    for (const Body* b : sys.bodies()) {
        InertiaLoads star = calc_inertia_loads(*b, N);
        Vector v = b->cm().vel_in(N);
        Vector w = b->frame() ? b->frame()->ang_vel_in(N) : Vector();
        for (std::size_t r = 0; r < q.size(); ++r) {
            const ex& u = q[r].d(1);
            E[r] += dot(v.diff(u), star.force);
            if (!star.torque.is_zero()) E[r] += dot(w.diff(u), star.torque);
        }
    }
    return E;
}

}  // namespace alembert
