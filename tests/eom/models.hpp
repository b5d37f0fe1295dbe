// SPDX-License-Identifier: MIT
// Models built by hand for the eom tests (beside the library's sample models), and random states.
#pragma once

#include <random>
#include <vector>

#include "alembert/mech/sample_models.hpp"
#include "alembert/mech/system.hpp"

namespace alembert::test {

/// The relative difference below which two methods' equations agree.
inline constexpr double kAgree = 1e-12;

/// A model with its coordinates and its unknown load measures (motor torques, forces).
struct Model {
    System sys;
    std::vector<TimeVariable> q;
    std::vector<ex> loads;
};

/// The accelerations q'' of the coordinates.
inline std::vector<ex> accelerations(const std::vector<TimeVariable>& q) {
    std::vector<ex> a;
    for (const TimeVariable& qi : q) a.push_back(qi.d(2));
    return a;
}

/// A uniform rod B (mass m, length L) pinned at N_o about Nz, hanging along -By, angle q from
/// the downward vertical; gravity -g Ny; a motor torque T on B from N about Nz.
inline Model make_rod_pendulum() {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    const Frame& N = m.sys.newtonian();
    TimeVariable q = s.add_variable("q");
    ex mass = s.add_constant("m", 1.3), L = s.add_constant("L", 0.8), g = s.add_constant("g", 9.81);
    ex T = s.add_unknown("T");
    RigidBody& B = m.sys.add_rigid_body("B");
    B.body_frame().orient_axis(N, Axis::z, q);
    m.sys.point("B_o").set_pos(m.sys.origin(), Vector());
    B.cm().set_pos(m.sys.point("B_o"), -(L / 2) * B.body_frame().y());
    B.set_mass(mass);
    B.set_inertia(B.cm(), mass * L * L / 12, 0, mass * L * L / 12);
    m.sys.set_gravity(-g * N.y());
    m.sys.add_torque_pair(B, N, T * N.z(), "T");
    m.q = {q};
    m.loads = {T};
    return m;
}

/// Two particles on massless rods: Q1 at L1 along -Ay from N_o, Q2 at L2 along -By from Q1;
/// A and B are frames of no body turning about Nz by the absolute angles q1, q2; gravity -g Ny.
inline Model make_particle_double_pendulum() {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    Frame& N = m.sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    ex L1 = s.add_constant("L1", 1.1), L2 = s.add_constant("L2", 0.7);
    Frame& A = m.sys.add_frame("A");
    Frame& B = m.sys.add_frame("B");
    A.orient_axis(N, Axis::z, q1);
    B.orient_axis(N, Axis::z, q2);
    Particle& Q1 = m.sys.add_particle("Q1");
    Particle& Q2 = m.sys.add_particle("Q2");
    Q1.point().set_pos(m.sys.origin(), -L1 * A.y());
    Q2.point().set_pos(Q1.point(), -L2 * B.y());
    Q1.set_mass(s.add_constant("m1", 2.0));
    Q2.set_mass(s.add_constant("m2", 0.6));
    m.sys.set_gravity(-s.add_constant("g", 9.81) * N.y());
    m.q = {q1, q2};
    return m;
}

/// A free rigid body: B_o at x Nx> + y Ny> + z Nz> from N_o, B oriented by body-fixed XYZ
/// angles q1, q2, q3, mass centre off B_o, full central inertia; gravity -g Nz; a force
/// F Nx> at B_o and a torque Tq Bz> on B, both unknown load measures.
inline Model make_free_rigid_body() {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    Frame& N = m.sys.newtonian();
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y"), z = s.add_variable("z");
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2"), q3 = s.add_variable("q3");
    RigidBody& B = m.sys.add_rigid_body("B");
    const Frame& F = B.body_frame();
    B.body_frame().orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    Point& Bo = m.sys.point("B_o");
    Bo.set_pos(m.sys.origin(), x * N.x() + y * N.y() + z * N.z());
    B.cm().set_pos(Bo, 0.2 * F.x() - 0.1 * F.y() + 0.3 * F.z());
    B.set_mass(s.add_constant("mB", 2.5));
    B.set_inertia(B.cm(), 1.0, 2.0, 3.5, 0.1, -0.2, 0.15);
    m.sys.set_gravity(-s.add_constant("g", 9.81) * N.z());
    ex Fx = s.add_unknown("Fx"), Tq = s.add_unknown("Tq");
    m.sys.add_force(Bo, Fx * N.x(), "Fx");
    m.sys.add_torque(B, Tq * F.z(), "Tq");
    m.q = {x, y, z, q1, q2, q3};
    m.loads = {Fx, Tq};
    return m;
}

/// A tube T turning about Nz (the vertical plane's normal) at N_o, by the coordinate th driven
/// by a motor torque Tm (free rate), or by the specified function th(t) (specified rate); a
/// particle Q slides in it at x along Tx>, tied to T_o by a spring (stiffness k, natural length
/// L0); gravity -g Ny; the tube's mass centre lies c along Tx>.
inline Model make_spinning_tube(bool specified_rate) {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    Frame& N = m.sys.newtonian();
    TimeVariable x = s.add_variable("x");
    TimeVariable th = specified_rate ? s.add_specified("th") : s.add_variable("th");
    RigidBody& T = m.sys.add_rigid_body("T");
    T.body_frame().orient_axis(N, Axis::z, th);
    Point& To = m.sys.point("T_o");
    To.set_pos(m.sys.origin(), Vector());
    T.cm().set_pos(To, s.add_constant("c", 0.4) * T.body_frame().x());
    T.set_mass(s.add_constant("mT", 1.5));
    T.set_inertia(T.cm(), 0.01, 0.3, 0.3);
    Particle& Q = m.sys.add_particle("Q");
    Q.point().set_pos(To, x * T.body_frame().x());
    Q.set_mass(s.add_constant("mQ", 0.5));
    m.sys.add_spring(Q.point(), To, s.add_constant("k", 20.0), s.add_constant("L0", 0.3),
                     "spring");
    m.sys.set_gravity(-s.add_constant("g", 9.81) * N.y());
    m.q = {x};
    if (!specified_rate) {
        ex Tm = s.add_unknown("Tm");
        m.sys.add_torque_pair(T, N, Tm * N.z(), "Tm");
        m.q.push_back(th);
        m.loads = {Tm};
    }
    return m;
}

/// A body in a two-axis gimbal: ring A turns about Nz by q1, body B about Ax by q2, B's mass
/// centre e along Bz> from the common centre; full central inertias; gravity -g Nz; motor
/// torques T1 (A from N) and T2 (B from A).
inline Model make_gimbal() {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    Frame& N = m.sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    RigidBody& A = m.sys.add_rigid_body("A");
    RigidBody& B = m.sys.add_rigid_body("B");
    A.body_frame().orient_axis(N, Axis::z, q1);
    B.body_frame().orient_axis(A.body_frame(), Axis::x, q2);
    m.sys.point("A_o").set_pos(m.sys.origin(), Vector());
    A.cm().set_pos(m.sys.point("A_o"), Vector());
    m.sys.point("B_o").set_pos(m.sys.point("A_o"), Vector());
    B.cm().set_pos(m.sys.point("B_o"), s.add_constant("e", 0.1) * B.body_frame().z());
    A.set_mass(s.add_constant("mA", 1.0));
    B.set_mass(s.add_constant("mB", 3.0));
    A.set_inertia(A.cm(), 0.4, 0.5, 0.6, 0.01, 0.02, 0.03);
    B.set_inertia(B.cm(), 1.1, 1.3, 0.7, -0.05, 0.04, 0.02);
    m.sys.set_gravity(-s.add_constant("g", 9.81) * N.z());
    ex T1 = s.add_unknown("T1"), T2 = s.add_unknown("T2");
    m.sys.add_torque_pair(A, N, T1 * N.z(), "T1");
    m.sys.add_torque_pair(B, A.body_frame(), T2 * A.body_frame().x(), "T2");
    m.q = {q1, q2};
    m.loads = {T1, T2};
    return m;
}

/// A thin uniform disk D (mass m, radius r) rolling without slip on the plane of Nx>, Ny>
/// (Nz> up): heading Y (q1 about Nz>), lean L (q2 about Yx>), spin D (q3 about Ly>); the mass
/// centre at x Nx> + y Ny> + z Nz>, its height held by the configuration constraint
/// z - r cos q2 = 0 ("height"), D_P the disk's own point at the contact (-r Lz> from Dcm)
/// with no slip, the motion constraints roll_x, roll_y (v^{D_P} . Nx>, . Ny> = 0). The ground's
/// force on D at D_P, F_x Nx> + F_y Ny> + F_z Nz>, is held by those constraints (unknowns
/// F_x, F_y, F_z, in `loads`); gravity -g Nz>.
inline Model make_rolling_disk_with_contact() {
    Model m{System("N"), {}, {}};
    System& sys = m.sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2"), q3 = s.add_variable("q3"),
                 x = s.add_variable("x"), y = s.add_variable("y"), z = s.add_variable("z");
    ex mass = s.add_constant("m", 2.0), r = s.add_constant("r", 0.3), g = s.add_constant("g", 9.81);
    Frame& Y = sys.add_frame("Y");
    Frame& L = sys.add_frame("L");
    RigidBody& D = sys.add_rigid_body("D");
    Y.orient_axis(N, Axis::z, q1);
    L.orient_axis(Y, Axis::x, q2);
    D.body_frame().orient_axis(L, Axis::y, q3);
    D.cm().set_pos(sys.origin(), x * N.x() + y * N.y() + z * N.z());
    Point& DP = sys.add_point("D_P", &D);
    DP.set_pos(D.cm(), -r * L.z());
    DP.set_vel_two_point(N, D.cm(), D.body_frame());
    D.set_mass(mass);
    D.set_inertia(D.cm(), mass * r * r / 4, mass * r * r / 2, mass * r * r / 4);
    sys.set_gravity(-g * N.z());
    sys.add_configuration_constraint("height", z.symbol() - r * cos(q2.symbol()));
    sys.add_motion_constraint("roll_x", dot(DP.vel_in(N), N.x()));
    sys.add_motion_constraint("roll_y", dot(DP.vel_in(N), N.y()));
    ex Fx = s.add_unknown("F_x"), Fy = s.add_unknown("F_y"), Fz = s.add_unknown("F_z");
    sys.add_force(DP, Fx * N.x() + Fy * N.y() + Fz * N.z(), "contact");
    m.q = {q1, q2, q3, x, y, z};
    m.loads = {Fx, Fy, Fz};
    return m;
}

/// A 3D double pendulum: rod A hinged to N at N_o about Nz; square plate B hinged at the rod's
/// end about Ay, its mass centre off the hinge line; gravity -g Ny.
inline Model make_rod_and_plate() {
    Model m{System("N"), {}, {}};
    SymbolTable& s = m.sys.symbols();
    Frame& N = m.sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    RigidBody& A = m.sys.add_rigid_body("A");
    RigidBody& B = m.sys.add_rigid_body("B");
    ex L = s.add_constant("L", 1.2), w = s.add_constant("w", 0.5), mA = s.add_constant("mA", 1.0),
       mB = s.add_constant("mB", 2.0);
    A.body_frame().orient_axis(N, Axis::z, q1);
    B.body_frame().orient_axis(A.body_frame(), Axis::y, q2);
    m.sys.point("A_o").set_pos(m.sys.origin(), Vector());
    A.cm().set_pos(m.sys.point("A_o"), -(L / 2) * A.body_frame().y());
    m.sys.point("B_o").set_pos(m.sys.point("A_o"), -L * A.body_frame().y());
    B.cm().set_pos(m.sys.point("B_o"),
                   -(w / 2) * B.body_frame().y() + (w / 2) * B.body_frame().x());
    A.set_mass(mA);
    B.set_mass(mB);
    A.set_inertia(A.cm(), mA * L * L / 12, 0, mA * L * L / 12);
    B.set_inertia(B.cm(), mB * w * w / 12, mB * w * w / 12, mB * w * w / 6);
    m.sys.set_gravity(-s.add_constant("g", 9.81) * N.y());
    m.q = {q1, q2};
    return m;
}

/// Declares a joint reaction at each link of a chain sample model (make_triple_pendulum,
/// make_n_link_pendulum): on link L from its parent (N for the first) at L_o, forces R_L_x,
/// R_L_y along L's x and y axes (and R_L_z along z when `spatial`); spatial, also a torque
/// M_L about P.z x L.x, normal to both axes of the two-axis joint (P the parent's frame).
/// Returns the measures, reaction by reaction.
inline std::vector<ex> declare_chain_reactions(SampleModel& m, bool spatial) {
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    std::vector<ex> measures;
    for (std::size_t i = 0; i < m.links.size(); ++i) {
        RigidBody& L = *m.links[i];
        const Frame& F = L.body_frame();
        const Frame& P = i ? m.links[i - 1]->body_frame() : sys.newtonian();
        const std::string n = L.name();
        std::vector<ReactionComponent> forces{{s.add_unknown("R_" + n + "_x"), F.x()},
                                              {s.add_unknown("R_" + n + "_y"), F.y()}};
        std::vector<ReactionComponent> torques;
        if (spatial) {
            forces.push_back({s.add_unknown("R_" + n + "_z"), F.z()});
            torques.push_back({s.add_unknown("M_" + n), cross(P.z(), F.x())});
        }
        const JointReaction& r = sys.add_joint_reaction("joint " + n, i ? m.links[i - 1] : nullptr,
                                                        L, sys.point(n + "_o"), forces, torques);
        for (const ReactionComponent& c : r.components) measures.push_back(c.measure);
    }
    return measures;
}

/// A random state: every coordinate, speed, acceleration, specified input and unknown not in
/// `solve_for` from [-1, 1], every constant without a value from [0.5, 1.5], and the time.
inline exmap random_state(const SymbolTable& st, std::mt19937& rng,
                          const std::vector<ex>& solve_for) {
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
    auto solved = [&](const ex& s) {
        for (const ex& x : solve_for)
            if (x.is_equal(s)) return true;
        return false;
    };
    exmap values;
    for (SymbolKind kind : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
        for (const ex& s : st.symbols(kind))
            if (!solved(s)) values[s] = unit(rng);
    for (const ex& c : st.symbols(SymbolKind::constant))
        if (!st.value(c)) values[c] = positive(rng);
    values[st.time()] = positive(rng);
    return values;
}

}  // namespace alembert::test
