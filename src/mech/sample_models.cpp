// SPDX-License-Identifier: MIT
// Sample models: the sit-to-stand triple pendulum, n-link chains, a mass-spring-damper.
#include "alembert/mech/sample_models.hpp"

#include "alembert/error.hpp"

namespace alembert {

SampleModel make_triple_pendulum() {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();

    // segment data: Winter, Table 4.1, for a 70 kg, 1.70 m person (both legs lumped)
    struct Segment {
        const char* name;
        double L, mass, d, I;
    };
    const Segment seg[3] = {{"A", 0.4182, 6.51, 0.2371, 0.1038},
                            {"B", 0.4165, 14.00, 0.2362, 0.2534},
                            {"C", 0.4896, 47.46, 0.3065, 2.799}};
    ex g = s.add_constant("g", 9.81);

    const Frame* parent_frame = &N;
    const Point* joint_from = &sys.origin();
    ex previous_length = 0;
    const Frame* previous_body_frame = nullptr;
    for (const Segment& sg : seg) {
        std::string n = sg.name;
        ex L = s.add_constant("L_" + n, sg.L);
        ex mass = s.add_constant("m_" + n, sg.mass);
        ex d = s.add_constant("d_" + n, sg.d);
        ex I = s.add_constant("I_" + n, sg.I);
        TimeVariable q = s.add_variable("q" + n, 2);
        ex T = s.add_unknown("T_" + n);

        RigidBody& B = sys.add_rigid_body(n);
        Frame& F = B.body_frame();
        F.orient_axis(*parent_frame, Axis::z, q);
        // the joint B_o: at N_o for the shank, else L along the previous body's y axis
        Point& Bo = sys.point(n + "_o");
        Bo.set_pos(*joint_from, previous_body_frame ? previous_length * previous_body_frame->y()
                                                    : Vector());
        B.cm().set_pos(Bo, d * F.y());
        B.set_mass(mass);
        B.set_inertia(B.cm(), 0, 0, I);
        sys.add_torque_pair(B, *parent_frame, T * N.z(), "T_" + n);

        m.q.push_back(q);
        m.unknowns.push_back(T);
        m.links.push_back(&B);
        parent_frame = &F;
        previous_body_frame = &F;
        joint_from = &Bo;
        previous_length = L;
    }
    sys.set_gravity(-g * N.y());
    return m;
}

namespace {

// n uniform rods, each lying along its own y axis: +y (standing, `up`) or -y (hanging)
SampleModel make_chain(const char* caller, int n, ChainKind kind, bool up) {
    if (n < 1)
        throw ArgumentError(std::string(caller) + ": a chain needs at least one link, not " +
                            std::to_string(n));
    const ex along = up ? 1 : -1;
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex g = s.add_constant("g", 9.81);

    const Frame* parent = &N;
    const Point* joint = &sys.origin();
    ex previous_length = 0;
    for (int i = 1; i <= n; ++i) {
        std::string k = std::to_string(i);
        ex L = s.add_constant("L" + k, 1.0);
        ex mass = s.add_constant("m" + k, 1.0);
        RigidBody& B = sys.add_rigid_body("B" + k);
        Frame& F = B.body_frame();
        if (kind == ChainKind::planar) {
            TimeVariable q = s.add_variable("q" + k, 2);
            F.orient_axis(*parent, Axis::z, q);
            ex T = s.add_unknown("T" + k);
            sys.add_torque_pair(B, *parent, T * F.z(), "T" + k);
            m.q.push_back(q);
            m.unknowns.push_back(T);
        } else {
            TimeVariable qz = s.add_variable("qz" + k, 2), qx = s.add_variable("qx" + k, 2);
            F.orient_body_fixed(*parent, RotationSequence::ZXY, qz, qx, 0);
            ex Tz = s.add_unknown("Tz" + k), Tx = s.add_unknown("Tx" + k);
            sys.add_torque_pair(B, *parent, Tz * parent->z() + Tx * F.x(), "T" + k);
            m.q.push_back(qz);
            m.q.push_back(qx);
            m.unknowns.push_back(Tz);
            m.unknowns.push_back(Tx);
        }
        Point& Bo = sys.point("B" + k + "_o");
        Bo.set_pos(*joint, i == 1 ? Vector() : along * previous_length * parent->y());
        B.cm().set_pos(Bo, along * (L / 2) * F.y());
        B.set_mass(mass);
        ex I = mass * L * L / 12;
        B.set_inertia(B.cm(), I, 0, I);
        m.links.push_back(&B);
        parent = &F;
        joint = &Bo;
        previous_length = L;
    }
    sys.set_gravity(-g * N.y());
    return m;
}

}  // namespace

SampleModel make_n_link_pendulum(int n, ChainKind kind) {
    return make_chain("make_n_link_pendulum()", n, kind, false);
}

SampleModel make_planar_chain(int n) {
    return make_chain("make_planar_chain()", n, ChainKind::planar, true);
}

SampleModel make_mass_spring_damper() {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex mass = s.add_constant("m", 1.0), k = s.add_constant("k", 4.0), c = s.add_constant("c", 0.4);
    TimeVariable x = s.add_variable("x", 2);
    Particle& Q = sys.add_particle("Q");
    Q.set_mass(mass);
    Point& P = sys.point("Q");
    P.set_pos(sys.origin(), x * N.x());
    sys.add_spring(P, sys.origin(), k, 0, "spring");
    sys.add_damper(P, sys.origin(), c, "damper");
    m.q.push_back(x);
    return m;
}

}  // namespace alembert
