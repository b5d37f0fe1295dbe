// SPDX-License-Identifier: MIT
// Momentum and kinetic energy of particles and rigid bodies; inertia and its transfer.
#include "alembert/error.hpp"
#include "alembert/mech/inertia.hpp"
#include "alembert/mech/particle.hpp"
#include "alembert/mech/rigid_body.hpp"

namespace alembert {

const ex& Body::mass() const {
    if (!mass_)
        throw ModelError("Body::mass(): the mass of '" + name_ + "' is not set; call " + name_ +
                         ".set_mass(...) first");
    return *mass_;
}

Vector Body::calc_linear_momentum(const Frame& N) const { return mass() * cm().vel_in(N); }

Vector Body::calc_angular_momentum(const Point& O, const Frame& N) const {
    return cross(cm().pos_from(O), calc_linear_momentum(N));
}

ex Body::calc_kinetic_energy(const Frame& N) const {
    Vector v = cm().vel_in(N);
    return mass() * dot(v, v) / 2;
}

Dyadic inertia_dyadic(const Frame& B, const ex& Ixx, const ex& Iyy, const ex& Izz,
                      const ex& Ixy, const ex& Iyz, const ex& Izx) {
    Mat3 m;
    m(0, 0) = Ixx, m(1, 1) = Iyy, m(2, 2) = Izz;
    m(0, 1) = m(1, 0) = Ixy;
    m(1, 2) = m(2, 1) = Iyz;
    m(2, 0) = m(0, 2) = Izx;
    return Dyadic(B, B, m);
}

Dyadic point_mass_inertia(const ex& m, const Vector& r, const Frame& U_frame) {
    return m * (dot(r, r) * Dyadic::unit(U_frame) - outer(r, r));
}

void RigidBody::set_inertia(const Point& about, const ex& Ixx, const ex& Iyy, const ex& Izz,
                            const ex& Ixy, const ex& Iyz, const ex& Izx) {
    set_inertia(about, inertia_dyadic(*frame_, Ixx, Iyy, Izz, Ixy, Iyz, Izx));
}

void RigidBody::set_inertia(const Point& about, const Dyadic& I) {
    if (&about == &cm()) {
        I_cm_ = I;
        return;
    }
    if (!has_mass())
        throw ModelError("RigidBody::set_inertia(): the inertia of '" + name() +
                         "' is given about '" + about.name() +
                         "', not its mass centre, so transferring it needs the mass; call " +
                         name() + ".set_mass(...) first");
    // I^{B/Bcm} = I^{B/O} - m ((r.r) U - r r), r = r^{Bcm/O}
    I_cm_ = I - point_mass_inertia(mass(), cm().pos_from(about), *frame_);
}

const Dyadic& RigidBody::inertia() const {
    if (!I_cm_)
        throw ModelError("RigidBody::inertia(): the inertia of '" + name() +
                         "' is not set; call " + name() + ".set_inertia(...) first");
    return *I_cm_;
}

Dyadic RigidBody::calc_inertia_about(const Point& O) const {
    if (&O == &cm()) return inertia();
    return inertia() + point_mass_inertia(mass(), cm().pos_from(O), *frame_);
}

Vector RigidBody::calc_angular_momentum(const Point& O, const Frame& N) const {
    Vector H = dot(inertia(), frame_->ang_vel_in(N));
    if (&O != &cm()) H += Body::calc_angular_momentum(O, N);
    return H;
}

ex RigidBody::calc_kinetic_energy(const Frame& N) const {
    // the body's own inertia first, so that a missing one is the error reported whatever
    // order the compiler evaluates the sum's operands in
    const Dyadic I = inertia();
    const Vector w = frame_->ang_vel_in(N);
    return Body::calc_kinetic_energy(N) + dot(w, dot(I, w)) / 2;
}

}  // namespace alembert
