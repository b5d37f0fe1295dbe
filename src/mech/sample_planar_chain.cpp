// SPDX-License-Identifier: MIT
// Sample model: the upright planar chain of the dynamics benchmarks.
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"

namespace alembert {

SampleModel make_planar_chain(int n) {
    if (n < 1)
        throw ArgumentError("make_planar_chain(): a chain needs at least one link, not " +
                            std::to_string(n));
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex g = s.add_constant("g", 9.81);

    // link B_i turns about z by q_i relative to B_{i-1} (N for the first); it stands along its
    // own +y axis, from its joint B_i_o to the next joint, L_i further on
    const Frame* parent = &N;
    const Point* joint = &sys.origin();
    ex previous_length = 0;
    for (int i = 1; i <= n; ++i) {
        std::string k = std::to_string(i);
        ex L = s.add_constant("L" + k, 1.0);
        ex mass = s.add_constant("m" + k, 1.0);
        RigidBody& B = sys.add_rigid_body("B" + k);
        Frame& F = B.body_frame();
        TimeVariable q = s.add_variable("q" + k, 2);
        F.orient_axis(*parent, Axis::z, q);
        ex T = s.add_unknown("T" + k);
        sys.add_torque_pair(B, *parent, T * N.z(), "T" + k);
        Point& Bo = sys.point("B" + k + "_o");
        Bo.set_pos(*joint, i == 1 ? Vector() : previous_length * parent->y());
        B.cm().set_pos(Bo, (L / 2) * F.y());
        B.set_mass(mass);
        ex I = mass * L * L / 12;
        B.set_inertia(B.cm(), I, 0, I);
        m.q.push_back(q);
        m.unknowns.push_back(T);
        m.links.push_back(&B);
        parent = &F;
        joint = &Bo;
        previous_length = L;
    }
    sys.set_gravity(-g * N.y());
    return m;
}

}  // namespace alembert
