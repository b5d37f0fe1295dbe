// SPDX-License-Identifier: MIT
// Sample model: the Whipple bicycle with the benchmark parameters of Meijaard et al. (2007).
#include <cmath>

#include "alembert/mech/sample_models.hpp"

namespace alembert {

namespace {

// the central inertia of a body as a dyadic in the upright-aligned frame U (x forward, y left,
// z up); Meijaard's Table 1 gives it in x forward, y right, z down, which flips the sign of
// the xz product
Dyadic upright_inertia(const Frame& U, const ex& Ixx, const ex& Iyy, const ex& Izz,
                       const ex& Ixz_table) {
    Mat3 I;
    I(0, 0) = Ixx, I(1, 1) = Iyy, I(2, 2) = Izz;
    I(0, 2) = I(2, 0) = -Ixz_table;
    return Dyadic(U, U, I);
}

}  // namespace

SampleNonholonomicModel make_whipple_bicycle() {
    SampleNonholonomicModel m{System("N"), {}, {}, {}, {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();

    // ---- Table 1 of Meijaard et al. (2007)
    ex w = s.add_constant("w", 1.02), c = s.add_constant("c", 0.08);
    ex lambda = s.add_constant("lambda", M_PI / 10), g = s.add_constant("g", 9.81);
    ex rR = s.add_constant("r_R", 0.3), mR = s.add_constant("m_R", 2);
    ex IRxx = s.add_constant("I_Rxx", 0.0603), IRyy = s.add_constant("I_Ryy", 0.12);
    ex xB = s.add_constant("x_B", 0.3), zB = s.add_constant("z_B", -0.9);
    ex mB = s.add_constant("m_B", 85);
    ex IBxx = s.add_constant("I_Bxx", 9.2), IByy = s.add_constant("I_Byy", 11);
    ex IBzz = s.add_constant("I_Bzz", 2.8), IBxz = s.add_constant("I_Bxz", 2.4);
    ex xH = s.add_constant("x_H", 0.9), zH = s.add_constant("z_H", -0.7);
    ex mH = s.add_constant("m_H", 4);
    ex IHxx = s.add_constant("I_Hxx", 0.05892), IHyy = s.add_constant("I_Hyy", 0.06);
    ex IHzz = s.add_constant("I_Hzz", 0.00708), IHxz = s.add_constant("I_Hxz", -0.00756);
    ex rF = s.add_constant("r_F", 0.35), mF = s.add_constant("m_F", 3);
    ex IFxx = s.add_constant("I_Fxx", 0.1405), IFyy = s.add_constant("I_Fyy", 0.28);

    // ---- coordinates: yaw, lean (roll), rear wheel angle, pitch, steer, front wheel angle
    for (const char* n : {"q1", "q2", "q3", "q4", "q5", "q6"}) m.q.push_back(s.add_variable(n, 1));
    for (const char* n : {"u1", "u2", "u3", "u4", "u5", "u6"}) m.u.push_back(s.add_variable(n, 1));
    for (std::size_t i = 0; i < 6; ++i) m.kinematic_equations.push_back(m.u[i] - m.q[i].d(1));

    // ---- frames: yaw Y about Nz, lean L about Yx, rear frame B pitched about Ly; the steer
    // axis frame S fixed in B (Sz up along the steer axis, tilted back by lambda), the fork H
    // steered about Sz, and Hu fixed in H (upright-aligned at zero steer) for its inertia
    Frame& Y = sys.add_frame("Y");
    Y.orient_axis(N, Axis::z, m.q[0]);
    Frame& L = sys.add_frame("L");
    L.orient_axis(Y, Axis::x, m.q[1]);
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Bf = B.body_frame();
    Bf.orient_axis(L, Axis::y, m.q[3]);
    Frame& S = sys.add_frame("S");
    S.orient_axis(Bf, Axis::y, -lambda);
    RigidBody& H = sys.add_rigid_body("H");
    Frame& Hf = H.body_frame();
    Hf.orient_axis(S, Axis::z, m.q[4]);
    Frame& Hu = sys.add_frame("Hu");
    Hu.orient_axis(Hf, Axis::y, lambda);
    RigidBody& R = sys.add_rigid_body("R");
    R.body_frame().orient_axis(Bf, Axis::y, m.q[2]);
    RigidBody& F = sys.add_rigid_body("F");
    F.body_frame().orient_axis(Hf, Axis::y, m.q[5]);

    // ---- points. The rear wheel's point in contact P_R is at rest (rolling); the rear wheel
    // centre R_o is r_R above it along Lz. Upright, in (forward, up) from the rear contact:
    // R_o (0, r_R), B's mass centre (x_B, -z_B), H's (x_H, -z_H), F_o (w, r_F), and the steer
    // axis meets the ground at S_g (w + c, 0).
    Point& PR = sys.add_point("P_R", &R);
    PR.set_vel(N, Vector());
    Point& Ro = sys.point("R_o");
    Ro.set_pos(PR, rR * L.z());
    Ro.set_vel_two_point(N, PR, R.body_frame());
    R.cm().set_pos(Ro, Vector());
    B.cm().set_pos(Ro, xB * Bf.x() + (-zB - rR) * Bf.z());
    B.cm().set_vel_two_point(N, Ro, Bf);
    Point& Sg = sys.add_point("S_g", &B);
    Sg.set_pos(Ro, (w + c) * Bf.x() - rR * Bf.z());
    Sg.set_vel_two_point(N, Ro, Bf);
    H.cm().set_pos(Sg, (xH - w - c) * Hu.x() + (-zH) * Hu.z());
    H.cm().set_vel_two_point(N, Sg, Hf);
    Point& Fo = sys.point("F_o");
    Fo.set_pos(Sg, -c * Hu.x() + rF * Hu.z());
    Fo.set_vel_two_point(N, Sg, Hf);
    F.cm().set_pos(Fo, Vector());
    // the front wheel's point in contact: r_F from its centre, in the wheel plane, straight
    // down as far as the plane allows: along (Nz . Hy) Hy - Nz, of length sqrt(1 - (Nz . Hy)^2)
    ex k = dot(N.z(), Hf.y());
    Point& PF = sys.add_point("P_F", &F);
    PF.set_pos(Fo, rF * (k * Hf.y() - N.z()) / sqrt(1 - k * k));
    PF.set_vel_two_point(N, Fo, F.body_frame());

    // ---- masses and central inertias (the wheels' are symmetric about their axles)
    B.set_mass(mB);
    B.set_inertia(B.cm(), upright_inertia(Bf, IBxx, IByy, IBzz, IBxz));
    H.set_mass(mH);
    H.set_inertia(H.cm(), upright_inertia(Hu, IHxx, IHyy, IHzz, IHxz));
    Mat3 IR, IF;
    IR(0, 0) = IRxx, IR(1, 1) = IRyy, IR(2, 2) = IRxx;
    IF(0, 0) = IFxx, IF(1, 1) = IFyy, IF(2, 2) = IFxx;
    R.set_mass(mR);
    R.set_inertia(R.cm(), Dyadic(Bf, Bf, IR));
    F.set_mass(mF);
    F.set_inertia(F.cm(), Dyadic(Hf, Hf, IF));
    sys.set_gravity(-g * N.z());

    // ---- rolling of the front wheel: its contact point at rest, along Yx, Yy and Yz (the
    // last is the rate of the holonomic constraint that keeps it on the ground)
    Vector vPF = PF.vel_in(N);
    m.motion_constraints = {dot(vPF, Y.x()), dot(vPF, Y.y()), dot(vPF, Y.z())};
    m.dependent_speeds = {m.u[0], m.u[3], m.u[5]};
    m.links = {&B, &H, &R, &F};
    return m;
}

}  // namespace alembert
