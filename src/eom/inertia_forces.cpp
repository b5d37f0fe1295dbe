// SPDX-License-Identifier: MIT
// Inertia forces and moments of bodies and systems.
#include "alembert/eom/inertia_forces.hpp"

namespace alembert {

InertiaLoads calc_inertia_loads(const Body& B, const Frame& N) {
    InertiaLoads r;
    r.force = -(B.mass() * B.cm().acc_in(N));
    if (const auto* rb = dynamic_cast<const RigidBody*>(&B)) {
        const Frame& F = *rb->frame();
        Vector w = F.ang_vel_in(N), alpha = F.ang_acc_in(N);
        const Dyadic& I = rb->inertia();
        r.torque = -(dot(I, alpha) + cross(w, dot(I, w)));
    }
    return r;
}

Vector calc_inertial_force(const BodySet& S, const Frame& N) {
    Vector f;
    for (const Body* b : S) f += b->mass() * b->cm().acc_in(N);
    return f;
}

Vector calc_inertial_moment(const BodySet& S, const Point& O, const Frame& N) {
    Vector m;
    for (const Body* b : S) {
        InertiaLoads r = calc_inertia_loads(*b, N);
        m -= r.torque;
        m -= cross(b->cm().pos_from(O), r.force);
    }
    return m;
}

}  // namespace alembert
