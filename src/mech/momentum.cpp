// SPDX-License-Identifier: MIT
// Mass, momentum, energy and load resultants of a system of bodies.
#include <algorithm>

#include "alembert/mech/system.hpp"

namespace alembert {

namespace {
bool member(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}
}  // namespace

ex System::calc_mass(const BodySet& S) const {
    ex m = 0;
    for (const Body* b : S) m += b->mass();
    return m;
}

Vector System::calc_cm_pos(const BodySet& S, const Point& O) const {
    Vector r;
    for (const Body* b : S) r += b->mass() * b->cm().pos_from(O);
    return r / calc_mass(S);
}

Vector System::calc_linear_momentum(const BodySet& S) const {
    Vector L;
    for (const Body* b : S) L += b->calc_linear_momentum(newtonian());
    return L;
}

Vector System::calc_angular_momentum(const BodySet& S, const Point& O) const {
    Vector H;
    for (const Body* b : S) H += b->calc_angular_momentum(O, newtonian());
    return H;
}

ex System::calc_kinetic_energy(const BodySet& S) const {
    ex K = 0;
    for (const Body* b : S) K += b->calc_kinetic_energy(newtonian());
    return K;
}

ex System::calc_potential_energy() const {
    ex V = 0;
    if (!gravity_.is_zero())
        for (const auto& b : bodies_) V -= b->mass() * dot(gravity_, b->cm().pos_from(origin()));
    for (const Potential& p : potentials_) V += p.energy;
    return V;
}

LoadResultant System::calc_resultant(const BodySet& S, const Point& O) const {
    LoadResultant r;
    for (const Load& l : loads_) {
        if (!member(S, l.on) || member(S, l.from)) continue;  // not on S, or internal to S
        if (l.kind == LoadKind::force) {
            r.force += l.vector;
            r.moment += cross(l.point->pos_from(O), l.vector);
        } else {
            r.moment += l.vector;
        }
    }
    if (!gravity_.is_zero())
        for (const Body* b : S) {
            Vector W = b->mass() * gravity_;
            r.force += W;
            r.moment += cross(b->cm().pos_from(O), W);
        }
    return r;
}

}  // namespace alembert
