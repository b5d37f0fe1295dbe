// SPDX-License-Identifier: MIT
// Lagrange's method against equations derived by hand.
#include "alembert/eom/lagrange.hpp"

#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

TEST(Lagrange, RodPendulumMatchesHandDerivation) {
    SampleModel m = make_n_link_pendulum(1);
    SymbolTable& s = m.system.symbols();
    ex L = s.symbol("L1"), mass = s.symbol("m1"), g = s.symbol("g"), T = s.symbol("T1");
    const TimeVariable& q = m.q[0];
    std::vector<ex> E = form_lagrange_equations(m.system, m.q);
    EXPECT_TRUE(same(E[0], T - mass * L * L / 3 * q.d(2) - mass * g * L / 2 * sin(q)));
}

TEST(Lagrange, MassSpringDamperTakesTheSpringThroughThePotential) {
    // the spring is conservative (in V), the damper a generalized force: -k x - c x' - m x''
    SampleModel m = make_mass_spring_damper();
    SymbolTable& s = m.system.symbols();
    const TimeVariable& x = m.q[0];
    std::vector<ex> E = form_lagrange_equations(m.system, m.q);
    exmap abs_x{{pow(pow(x, 2), GiNaC::wild()), pow(x, 2 * GiNaC::wild())}};
    EXPECT_TRUE(same(E[0].subs(abs_x),
                     -s.symbol("k") * x - s.symbol("c") * x.d(1) - s.symbol("m") * x.d(2)));
}

TEST(Lagrange, DoublePendulumOfPointMassesMatchesTextbook) {
    // point masses m1, m2 on massless rods l1, l2, absolute angles from the downward vertical:
    // (m1+m2) l1 a1'' + m2 l2 a2'' cos(a1-a2) + m2 l2 a2'^2 sin(a1-a2) + (m1+m2) g sin a1 = 0
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable a1 = s.add_variable("a1"), a2 = s.add_variable("a2");
    ex m1 = s.add_constant("m1"), m2 = s.add_constant("m2"), l1 = s.add_constant("l1"),
       l2 = s.add_constant("l2"), g = s.add_constant("g");
    Frame& A = sys.add_frame("A");
    Frame& B = sys.add_frame("B");
    A.orient_axis(N, Axis::z, a1);
    B.orient_axis(N, Axis::z, a2);
    Particle& P1 = sys.add_particle("P1");
    Particle& P2 = sys.add_particle("P2");
    P1.set_mass(m1), P2.set_mass(m2);
    sys.point("P1").set_pos(sys.origin(), -l1 * A.y());
    sys.point("P2").set_pos(sys.point("P1"), -l2 * B.y());
    sys.set_gravity(-g * N.y());
    std::vector<ex> E = form_lagrange_equations(sys, {a1, a2});
    ex e1 = (m1 + m2) * l1 * a1.d(2) + m2 * l2 * a2.d(2) * cos(a1 - a2) +
            m2 * l2 * pow(a2.d(1), 2) * sin(a1 - a2) + (m1 + m2) * g * sin(a1);
    ex e2 = l2 * a2.d(2) + l1 * a1.d(2) * cos(a1 - a2) - l1 * pow(a1.d(1), 2) * sin(a1 - a2) +
            g * sin(a2);
    EXPECT_TRUE(same(E[0], -l1 * e1));
    EXPECT_TRUE(same(E[1], -m2 * l2 * e2));
}
