// SPDX-License-Identifier: MIT
// Sample model: a thin disk rolling without slip, in generalized speeds.
#include "alembert/mech/sample_models.hpp"

namespace alembert {

SampleNonholonomicModel make_rolling_disk(double mass, double radius, double gravity,
                                          bool axle_torque) {
    SampleNonholonomicModel out{System("N"), {}, {}, {}, {}, {}, {}};
    System& sys = out.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    const ex m = s.add_constant("m", mass), r = s.add_constant("r", radius),
             g = s.add_constant("g", gravity);
    for (const char* n : {"q1", "q2", "q3", "x", "y"}) out.q.push_back(s.add_variable(n, 1));
    for (const char* n : {"u1", "u2", "u3", "u4", "u5"}) out.u.push_back(s.add_variable(n, 1));
    Frame& Y = sys.add_frame("Y");
    Frame& L = sys.add_frame("L");
    RigidBody& D = sys.add_rigid_body("D");
    Y.orient_axis(N, Axis::z, out.q[0].symbol());
    L.orient_axis(Y, Axis::x, out.q[1].symbol());
    D.body_frame().orient_axis(L, Axis::y, out.q[2].symbol());
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), out.q[3].symbol() * N.x() + out.q[4].symbol() * N.y());
    D.cm().set_pos(P, r * L.z());
    Point& D_P = sys.add_point("D_P", &D);
    D_P.set_pos(D.cm(), -r * L.z());
    D_P.set_vel_two_point(N, D.cm(), D.body_frame());
    D.set_mass(m);
    D.set_inertia(D.cm(), m * r * r / 4, m * r * r / 2, m * r * r / 4);
    sys.set_gravity(-g * N.z());
    if (axle_torque) sys.add_torque(D, s.add_unknown("T") * L.y(), "T");
    const Vector w_ND = D.body_frame().ang_vel_in(N);
    out.kinematic_equations = {out.u[0].symbol() - dot(w_ND, L.x()),
                               out.u[1].symbol() - dot(w_ND, L.y()),
                               out.u[2].symbol() - dot(w_ND, L.z()),
                               out.u[3].symbol() - out.q[3].d(1),
                               out.u[4].symbol() - out.q[4].d(1)};
    out.motion_constraints = {dot(D_P.vel_in(N), N.x()), dot(D_P.vel_in(N), N.y())};
    out.dependent_speeds = {out.u[3].symbol(), out.u[4].symbol()};
    out.links = {&D};
    return out;
}

}  // namespace alembert
