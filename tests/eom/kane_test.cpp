// SPDX-License-Identifier: MIT
// Kane's method against equations derived by hand.
#include "alembert/eom/kane.hpp"

#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::pow;
using GiNaC::sin;

TEST(Kane, RodPendulumMatchesHandDerivation) {
    // a uniform rod about its end: T1 - (m L^2/3) q'' - m g (L/2) sin q = 0
    SampleModel m = make_n_link_pendulum(1);
    SymbolTable& s = m.system.symbols();
    ex L = s.symbol("L1"), mass = s.symbol("m1"), g = s.symbol("g"), T = s.symbol("T1");
    const TimeVariable& q = m.q[0];
    std::vector<ex> E = form_kane_equations(m.system, m.q);
    ASSERT_EQ(E.size(), 1u);
    EXPECT_TRUE(same(E[0], T - mass * L * L / 3 * q.d(2) - mass * g * L / 2 * sin(q)));
    // F_r alone: the torque and gravity
    EXPECT_TRUE(same(form_generalized_active_forces(m.system, m.q)[0],
                     T - mass * g * L / 2 * sin(q)));
}

TEST(Kane, ParticleInARotatingTubeMatchesHandDerivation) {
    // tube T turns about Nz by theta (inertia J about Nz); particle P of mass m at r along Tx,
    // tied to N_o by a spring (k, natural length L0); motor torque tau on T.
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th = s.add_variable("theta"), r = s.add_variable("r");
    ex J = s.add_constant("J"), mass = s.add_constant("m"), k = s.add_constant("k"),
       L0 = s.add_constant("L0"), tau = s.add_unknown("tau");
    RigidBody& T = sys.add_rigid_body("T");
    T.body_frame().orient_axis(N, Axis::z, th);
    sys.point("T_o").set_pos(sys.origin(), Vector());
    T.cm().set_pos(sys.point("T_o"), Vector());
    T.set_mass(s.add_constant("M"));
    T.set_inertia(T.cm(), 0, 0, J);
    Particle& P = sys.add_particle("P");
    P.set_mass(mass);
    sys.point("P").set_pos(sys.point("T_o"), r * T.body_frame().x());
    sys.add_spring(sys.point("P"), sys.origin(), k, L0);
    sys.add_torque_pair(T, N, tau * N.z());
    std::vector<ex> E = form_kane_equations(sys, {th, r});
    // r > 0: |r| = r.  theta: tau - (J + m r^2) theta'' - 2 m r r' theta' = 0
    //                  r:     -k (r - L0) - m (r'' - r theta'^2) = 0
    exmap abs_r{{pow(pow(r, 2), GiNaC::wild()), pow(r, 2 * GiNaC::wild())}};
    EXPECT_TRUE(same(E[0].subs(abs_r), tau - (J + mass * r * r) * th.d(2) -
                                           2 * mass * r * r.d(1) * th.d(1)));
    EXPECT_TRUE(same(E[1].subs(abs_r),
                     -k * (r - L0) - mass * (r.d(2) - r * pow(th.d(1), 2))));
}
