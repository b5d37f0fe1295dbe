// SPDX-License-Identifier: MIT
// Sample model: a four-bar linkage, the classic closed kinematic loop.
#include "alembert/mech/sample_models.hpp"

namespace alembert {

SampleModel make_four_bar() {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex g = s.add_constant("g", 9.81);
    ex LN = s.add_constant("L_N", 1.0);

    struct Link {
        const char* name;
        double L, mass;
    };
    const Link data[3] = {{"A", 0.4, 1.0}, {"B", 1.2, 2.0}, {"C", 0.8, 1.5}};
    std::vector<RigidBody*> links;
    std::vector<ex> lengths;
    for (const Link& d : data) {
        std::string n = d.name;
        ex L = s.add_constant("L_" + n, d.L), mass = s.add_constant("m_" + n, d.mass);
        TimeVariable q = s.add_variable("q" + n, 2);
        RigidBody& B = sys.add_rigid_body(n);
        B.set_mass(mass);
        B.cm().set_pos(sys.point(n + "_o"), (L / 2) * B.body_frame().x());
        B.set_inertia(B.cm(), 0, 0, mass * L * L / 12);
        m.q.push_back(q);
        links.push_back(&B);
        lengths.push_back(L);
    }
    RigidBody &A = *links[0], &B = *links[1], &C = *links[2];
    // the open tree: crank and rocker on the ground, coupler on the crank's tip
    A.body_frame().orient_axis(N, Axis::z, m.q[0]);
    B.body_frame().orient_axis(A.body_frame(), Axis::z, m.q[1]);
    C.body_frame().orient_axis(N, Axis::z, m.q[2]);
    Point& Nc = sys.add_point("N_c");
    Nc.set_pos(sys.origin(), LN * N.x());
    sys.point("A_o").set_pos(sys.origin(), Vector());
    Point& A_tip = sys.add_point("A_tip", &A);
    A_tip.set_pos(sys.point("A_o"), lengths[0] * A.body_frame().x());
    sys.point("B_o").set_pos(A_tip, Vector());
    sys.point("C_o").set_pos(Nc, Vector());
    Point& B_tip = sys.add_point("B_tip", &B);
    B_tip.set_pos(sys.point("B_o"), lengths[1] * B.body_frame().x());
    Point& C_tip = sys.add_point("C_tip", &C);
    C_tip.set_pos(sys.point("C_o"), lengths[2] * C.body_frame().x());

    // closing the loop: the coupler's tip meets the rocker's, and the pin force between them
    sys.add_configuration_constraint("loop", B_tip.pos_from(C_tip), N);
    ex T = s.add_unknown("T"), Fx = s.add_unknown("F_x"), Fy = s.add_unknown("F_y");
    sys.add_torque(A, T * N.z(), "T");
    sys.add_force_pair(B_tip, C_tip, Fx * N.x() + Fy * N.y(), "F_BC");
    sys.set_gravity(-g * N.y());
    m.unknowns = {T, Fx, Fy};
    m.links = {&A, &B, &C};
    return m;
}

}  // namespace alembert
