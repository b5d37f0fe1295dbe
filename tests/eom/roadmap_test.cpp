// SPDX-License-Identifier: MIT
// Road-map rows written by hand, the moving-point form, and the road-map table.
#include "alembert/eom/roadmap.hpp"

#include "alembert/eom/equations.hpp"
#include "alembert/eom/inertia_forces.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {
struct Triple {
    SampleModel m = make_triple_pendulum();
    SymbolTable& s = m.system.symbols();
    TimeVariable &qA = m.q[0], &qB = m.q[1], &qC = m.q[2];
    ex g = s.symbol("g"), L_A = s.symbol("L_A"), L_B = s.symbol("L_B");
    ex d_A = s.symbol("d_A"), d_B = s.symbol("d_B"), d_C = s.symbol("d_C");
    ex m_A = s.symbol("m_A"), m_B = s.symbol("m_B"), m_C = s.symbol("m_C");
    ex I_C = s.symbol("I_C"), T_C = s.symbol("T_C");
};
}  // namespace

TEST(Roadmap, HandWrittenRowForTheHipMatchesTheHandDerivation) {
    Triple t;
    System& sys = t.m.system;
    RoadmapRow row{.variable = t.T_C, .motion = Motion::rotate, .direction = sys.newtonian().z(),
                   .system = sys.bodies({"C"}), .about = &sys.point("C_o")};
    form_roadmap_row(sys, row, t.m.unknowns);
    // about the moving hip C_o, with theta = qA+qB+qC, phi = qA+qB, beta = qB+qC:
    // T_C + m_C g d_C sin(theta) - I_C theta'' - m_C d_C [d_C theta'' + L_A (qA'' cos(beta)
    //   + qA'^2 sin(beta)) + L_B (phi'' cos(qC) + phi'^2 sin(qC))] = 0
    const TimeVariable &qA = t.qA, &qB = t.qB, &qC = t.qC;
    ex th2 = qA.d(2) + qB.d(2) + qC.d(2), ph1 = qA.d(1) + qB.d(1), ph2 = qA.d(2) + qB.d(2);
    ex beta = qB + qC, theta = qA + qB + qC;
    ex expected = t.T_C + t.m_C * t.g * t.d_C * sin(theta) - t.I_C * th2 -
                  t.m_C * t.d_C *
                      (t.d_C * th2 + t.L_A * (qA.d(2) * cos(beta) + pow(qA.d(1), 2) * sin(beta)) +
                       t.L_B * (ph2 * cos(qC) + pow(ph1, 2) * sin(qC)));
    EXPECT_TRUE(same(row.equation, expected));
    EXPECT_TRUE(row.additional_unknowns.empty());
    ASSERT_EQ(row.fbd.size(), 3u);
    EXPECT_EQ(row.fbd[0], "T_C on C from B (unknown)");  // T_C is an unknown measure
    EXPECT_EQ(row.fbd[1], "gravity at Ccm");
    EXPECT_EQ(row.fbd[2], "joint force at C_o from B (unknown)");
}

TEST(Roadmap, InertialMomentEqualsMovingPointFormOfAngularMomentum) {
    // sum I.alpha + w x I.w + r x m a  ==  d/dt H^{S/O} + v^O x L^S, O moving (the knee)
    Triple t;
    System& sys = t.m.system;
    const Frame& N = sys.newtonian();
    BodySet S = sys.bodies({"B", "C"});
    const Point& O = sys.point("B_o");
    Vector lhs = calc_inertial_moment(S, O, N);
    Vector rhs = sys.calc_angular_momentum(S, O).dt_in(N) +
                 cross(O.vel_in(N), sys.calc_linear_momentum(S));
    EXPECT_TRUE(same(lhs, rhs, N));
    // and the translational counterpart: sum m a = d/dt L
    EXPECT_TRUE(same(calc_inertial_force(S, N), sys.calc_linear_momentum(S).dt_in(N), N));
}

TEST(Roadmap, TranslateRowOfAMassSpringDamper) {
    SampleModel m = make_mass_spring_damper();
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    const TimeVariable& x = m.q[0];
    RoadmapRow row{.variable = x.d(2), .motion = Motion::translate,
                   .direction = sys.newtonian().x(), .system = sys.bodies({"Q"})};
    form_roadmap_row(sys, row, {x.d(2)});
    ex k = s.symbol("k"), c = s.symbol("c"), mass = s.symbol("m");
    // -k x - c x' - m x'' = 0 (x > 0 keeps |x| = x in the spring's length)
    exmap abs_x{{pow(pow(x, 2), GiNaC::wild()), pow(x, 2 * GiNaC::wild())}};
    EXPECT_TRUE(same(row.equation.subs(abs_x), -k * x - c * x.d(1) - mass * x.d(2)));
    row.analysis = Analysis::statics;
    EXPECT_TRUE(same(form_roadmap_equation(sys, row).subs(abs_x), -k * x - c * x.d(1)));
}

TEST(Roadmap, RowsWithoutSystemOrAboutPointAreRejected) {
    Triple t;
    System& sys = t.m.system;
    RoadmapRow empty{.variable = t.T_C, .direction = sys.newtonian().z()};
    EXPECT_THROW_MSG(form_roadmap_equation(sys, empty), ArgumentError, "empty system S");
    RoadmapRow no_point{.variable = t.T_C, .motion = Motion::rotate,
                        .direction = sys.newtonian().z(), .system = sys.bodies({"C"})};
    EXPECT_THROW_MSG(form_roadmap_equation(sys, no_point), ArgumentError, "no about point");
}
