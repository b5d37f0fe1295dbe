// SPDX-License-Identifier: MIT
// A row's derivation step by step: its quantities by hand for a pendulum, and its projection
// equal to the row's equation for the sit-to-stand and a spatial chain; the brute-force count.
#include "alembert/eom/row_derivation.hpp"

#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/zero_test.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/print.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;

namespace row_derivation_test {

namespace {

// every row's steps end in its equation: u . (M - d/dt H - v^O x L) (or u . (F - sum m a))
// minus the row's equation, formed as sum I alpha + w x I w + r x m a, is zero at random states
void expect_steps_give_each_row(const SampleModel& m, const std::vector<ex>& unknowns,
                                std::size_t* momentum_rows = nullptr) {
    const System& sys = m.system;
    const std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns);
    ASSERT_FALSE(rows.empty());
    for (const RoadmapRow& r : rows) {
        const RowDerivation d = calc_row_derivation(sys, r);
        EXPECT_FALSE(r.equation.is_zero());
        EXPECT_TRUE(is_zero_at_random_states(sys.symbols(), d.projected - r.equation))
            << "the row for " << to_string(r.variable);
        if (r.motion == Motion::rotate && !d.accumulated) {
            EXPECT_FALSE(d.angular_momentum.is_zero()) << to_string(r.variable);
            if (momentum_rows) ++*momentum_rows;
        }
    }
}

}  // namespace

TEST(RowDerivation, PendulumMomentumAboutThePivotIsTheHandDerivation) {
    // a rod A turning about Nz by q at the pivot N_o, mass centre d along -Ay, central inertia
    // I about z, torque T: about the pivot H = (I + m d^2) q' Nz, L = m d q' Ax,
    // d/dt H = (I + m d^2) q'' Nz, v^O x L = 0, M = (T - m g d sin q) Nz, so
    // E = T - m g d sin q - (I + m d^2) q''
    System sys("N");
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    const ex g = s.add_constant("g", 9.81), m = s.add_constant("m", 2), d = s.add_constant("d", 0.5),
             I = s.add_constant("I", 0.1);
    const TimeVariable q = s.add_variable("q", 2);
    const ex T = s.add_unknown("T");
    RigidBody& A = sys.add_rigid_body("A");
    A.body_frame().orient_axis(N, Axis::z, q);
    Point& Ao = sys.point("A_o");
    Ao.set_pos(sys.origin(), Vector());
    A.cm().set_pos(Ao, -d * A.body_frame().y());
    A.set_mass(m);
    A.set_inertia(A.cm(), 0, 0, I);
    sys.add_torque_pair(A, N, T * N.z(), "T");
    sys.set_gravity(-g * N.y());

    RoadmapRow row{.variable = q.d(2), .motion = Motion::rotate, .direction = N.z(),
                   .system = sys.bodies({"A"}), .about = &Ao};
    form_roadmap_row(sys, row, {q.d(2)});
    const RowDerivation D = calc_row_derivation(sys, row);
    EXPECT_TRUE(same(D.angular_momentum, (I + m * d * d) * q.d(1) * N.z(), N));
    EXPECT_TRUE(same(D.linear_momentum, m * d * q.d(1) * A.body_frame().x(), N));
    EXPECT_TRUE(same(D.angular_momentum_rate, (I + m * d * d) * q.d(2) * N.z(), N));
    EXPECT_TRUE(same(D.transport, Vector(), N));
    EXPECT_TRUE(same(D.moment, (T - m * g * d * GiNaC::sin(q)) * N.z(), N));
    EXPECT_TRUE(same(D.projected, T - m * g * d * GiNaC::sin(q) - (I + m * d * d) * q.d(2)));
    EXPECT_TRUE(same(D.projected, row.equation));
    EXPECT_EQ(D.moved_by, "q");
    EXPECT_NE(D.about_reason.find("the joint at A_o joins S to N"), std::string::npos) << D.about_reason;
}

TEST(RowDerivation, SitToStandStepsGiveEachRowsEquation) {
    const SampleModel m = make_triple_pendulum();
    std::size_t momentum_rows = 0;
    expect_steps_give_each_row(m, m.unknowns, &momentum_rows);  // the torques
    EXPECT_EQ(momentum_rows, 3u);
    std::vector<ex> accelerations;
    for (const TimeVariable& q : m.q) accelerations.push_back(q.d(2));
    expect_steps_give_each_row(m, accelerations);
    // the knee's row: S = {B, C}, what moves when qB alone changes, about the knee B_o
    const std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, m.unknowns);
    const RowDerivation knee = calc_row_derivation(m.system, rows.at(1));
    EXPECT_EQ(knee.moved_by, "qB");
    EXPECT_FALSE(knee.transport.is_zero());  // the knee moves: v^O x L counts
}

TEST(RowDerivation, SpatialChainStepsGiveEachRowsEquation) {
    const SampleModel m = make_n_link_pendulum(3, ChainKind::spatial);
    std::size_t momentum_rows = 0;
    expect_steps_give_each_row(m, m.unknowns, &momentum_rows);
    EXPECT_EQ(momentum_rows, 6u);  // two axes at each of three joints
}

TEST(RowDerivation, StaticsRowsProjectTheLoadsAlone) {
    const SampleModel m = make_triple_pendulum();
    const std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, m.unknowns, Analysis::statics);
    for (const RoadmapRow& r : rows) {
        const RowDerivation d = calc_row_derivation(m.system, r);
        EXPECT_TRUE(d.angular_momentum.is_zero());
        EXPECT_TRUE(is_zero_at_random_states(m.system.symbols(), d.projected - r.equation));
    }
}

TEST(BruteForceCount, SitToStandNineEquationsInNineUnknownsInThePlane) {
    // 3 bodies x 3 equations; 3 pins x 2 force components + the 3 torques
    const SampleModel m = make_triple_pendulum();
    const NewtonEulerCount c = count_newton_euler_equations(m.system, m.q, m.unknowns.size());
    EXPECT_TRUE(c.planar);
    EXPECT_EQ(c.equations, 9u);
    EXPECT_EQ(c.unknowns, 9u);
    EXPECT_EQ(c.force_reactions, 6u);
    EXPECT_EQ(c.torque_reactions, 0u);
    ASSERT_EQ(c.joints.size(), 3u);
    for (const NewtonEulerJointCount& j : c.joints) EXPECT_EQ(j.free_rotations, 1);
    // no symbol made: the table's unknowns are the model's three
    EXPECT_EQ(m.system.symbols().symbols(SymbolKind::unknown).size(), 3u);
}

TEST(BruteForceCount, SpatialChainOfTwoAxisJoints) {
    // by hand: 3 rods x 6 equations = 18; each two-axis joint forbids 3 slides and 1 rotation
    // (3 + 1 reaction components), 3 joints = 12, and the 6 joint torques asked: 18 unknowns
    const SampleModel m = make_n_link_pendulum(3, ChainKind::spatial);
    const NewtonEulerCount c = count_newton_euler_equations(m.system, m.q, m.unknowns.size());
    EXPECT_FALSE(c.planar);
    EXPECT_EQ(c.equations, 18u);
    EXPECT_EQ(c.force_reactions, 9u);
    EXPECT_EQ(c.torque_reactions, 3u);
    EXPECT_EQ(c.unknowns, 18u);
}

}  // namespace row_derivation_test
