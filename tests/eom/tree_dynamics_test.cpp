// SPDX-License-Identifier: MIT
// Recursive formation on trees: a pendulum by hand, the tree found in the sit-to-stand model,
// models it refuses (with the reason), and sizes that grow linearly with the chain.
// (Agreement with the road-map, Kane, Lagrange and Newton–Euler on a dozen models is in
// cross_check_test.cpp.)
#include "alembert/eom/tree_dynamics.hpp"

#include <cmath>
#include <random>

#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

constexpr double kExact = 1e-12;

std::size_t tape_operations(const SymbolTable& st, const std::vector<ex>& inputs,
                            const std::vector<ex>& outputs) {
    return CompiledExpressions(st, inputs, outputs, CompileOptions{.parameters = {}})
        .operation_count();
}

}  // namespace

// A uniform rod pinned at one end (mass m, length L, hanging at angle q from the downward
// vertical, motor torque T): about the pin, (m L^2 / 3) q'' = T - m g (L/2) sin q.
TEST(TreeEquations, RodPendulumMatchesTheHandDerivedLaw) {
    test::Model m = test::make_rod_pendulum();
    SymbolTable& st = m.sys.symbols();
    TreeEquations tree = form_tree_equations(m.sys, m.q);
    ASSERT_EQ(tree.joints.size(), 1u);
    EXPECT_EQ(tree.joints[0].parent, nullptr);
    EXPECT_EQ(tree.joints[0].origin->name(), "B_o");
    const double mass = 1.3, L = 0.8, g = 9.81;
    const ex q = m.q[0].d(0), qp = m.q[0].d(1), qpp = m.q[0].d(2), T = m.loads[0];
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> draw(-2, 2);
    for (int k = 0; k < 5; ++k) {
        const double qv = draw(rng), qpv = draw(rng), Tv = draw(rng), qppv = draw(rng);
        const double hand = (Tv - mass * g * (L / 2) * std::sin(qv)) / (mass * L * L / 3);
        exmap at{{q, qv}, {qp, qpv}, {T, Tv}, {qpp, qppv}};
        EXPECT_NEAR(st.evaluate(tree.accelerations[0], at), hand, kExact * std::abs(hand) + kExact);
        // the residual is the row about the pin: T - m g (L/2) sin q - (m L^2/3) q''
        const double row = Tv - mass * g * (L / 2) * std::sin(qv) - mass * L * L / 3 * qppv;
        EXPECT_NEAR(st.evaluate(tree.residuals[0], at), row, kExact * 10);
    }
}

TEST(TreeEquations, FindsTheJointsOfTheSitToStandModel) {
    SampleModel m = make_triple_pendulum();
    TreeEquations tree = form_tree_equations(m.system, m.q);
    ASSERT_EQ(tree.joints.size(), 3u);
    const char* names[] = {"A", "B", "C"};
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(tree.joints[k].body->name(), names[k]);
        EXPECT_EQ(tree.joints[k].parent, k == 0 ? nullptr : tree.joints[k - 1].body);
        EXPECT_EQ(tree.joints[k].origin->name(), std::string(names[k]) + "_o");
        EXPECT_EQ(tree.joints[k].coordinates, std::vector<std::size_t>{k});
    }
}

// A rigid double pendulum in absolute angles: B's orientation from N holds qB, and its joint
// hangs from A, so B's motion relative to A depends on qA too.
TEST(TreeEquations, RefusesAbsoluteAnglesOfRigidBodiesAndNamesTheCoordinate) {
    System sys("N");
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable qA = s.add_variable("qA"), qB = s.add_variable("qB");
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    A.body_frame().orient_axis(N, Axis::z, qA);
    B.body_frame().orient_axis(N, Axis::z, qB);
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), -0.5 * A.body_frame().y());
    sys.point("B_o").set_pos(sys.point("A_o"), -1 * A.body_frame().y());
    B.cm().set_pos(sys.point("B_o"), -0.5 * B.body_frame().y());
    for (RigidBody* b : {&A, &B}) {
        b->set_mass(1);
        b->set_inertia(b->cm(), 0, 0, ex(1) / 12);
    }
    const std::string why = explain_not_tree(sys, {qA, qB});
    EXPECT_NE(why.find("'qA' moves both 'A' and 'B'"), std::string::npos) << why;
    EXPECT_THROW_MSG(form_tree_equations(sys, {qA, qB}), ModelError, "relative coordinates");
}

TEST(TreeEquations, RefusesConstrainedModelsAndNamesTheConstraint) {
    test::Model m = test::make_rod_pendulum();
    m.sys.add_configuration_constraint("held", m.q[0].d(0) - 0.3);
    EXPECT_NE(explain_not_tree(m.sys, m.q).find("'held'"), std::string::npos);
    EXPECT_THROW_MSG(form_tree_equations(m.sys, m.q), ModelError, "constraints");
}

// The point of the recursion: each link adds a fixed number of operations, where the closed
// forms grow as n^2 (inverse dynamics) and n^3 (mass matrix). With sizes 8, 16, 32 the growth
// from 16 to 32 links is twice that from 8 to 16 for a linear size (four times for n^2).
TEST(TreeEquations, SizeGrowsLinearlyWithTheChain) {
    std::vector<std::size_t> rows, acc;
    for (int n : {8, 16, 32}) {
        SampleModel m = make_planar_chain(n);
        const SymbolTable& st = m.system.symbols();
        TreeEquations tree = form_tree_equations(m.system, m.q);
        std::vector<ex> state{st.time()}, with_acc;
        for (const TimeVariable& q : m.q) state.push_back(q.d(0)), state.push_back(q.d(1));
        state.insert(state.end(), m.unknowns.begin(), m.unknowns.end());
        with_acc = state;
        for (const TimeVariable& q : m.q) with_acc.push_back(q.d(2));
        rows.push_back(tape_operations(st, with_acc, tree.residuals));
        acc.push_back(tape_operations(st, state, tree.accelerations));
    }
    EXPECT_LE(rows[2] - rows[1], 2.1 * double(rows[1] - rows[0]))
        << rows[0] << ", " << rows[1] << ", " << rows[2];
    EXPECT_LE(acc[2] - acc[1], 2.1 * double(acc[1] - acc[0]))
        << acc[0] << ", " << acc[1] << ", " << acc[2];
    // and neither is large: a few dozen operations per link for the rows, about a hundred
    // for the accelerations (the hand-written planar recursions take about 30 and 60)
    EXPECT_LT(rows[2], 50u * 32) << rows[2];
    EXPECT_LT(acc[2], 130u * 32) << acc[2];
}

// A joint's motor torque (a torque pair between the body and its parent) enters its own rows
// with the coefficient of its axis and no other row: in the spatial chain's two-axis joints,
// Tz about the parent's z and Tx about the body's x, the coefficients are exactly 1 and 0 (the
// pair's two halves cancel in the rows of the joints below, by construction rather than by
// simplification), so inverse dynamics needs no symbolic solve.
TEST(TreeEquations, MotorTorquesEnterTheirOwnRowsWithExactCoefficients) {
    SampleModel m = make_n_link_pendulum(4, ChainKind::spatial);
    TreeEquations tree = form_tree_equations(m.system, m.q);
    ASSERT_EQ(m.unknowns.size(), tree.residuals.size());
    for (std::size_t r = 0; r < tree.residuals.size(); ++r)
        for (std::size_t u = 0; u < m.unknowns.size(); ++u) {
            const ex coefficient = tree.residuals[r].diff(GiNaC::ex_to<GiNaC::symbol>(m.unknowns[u]));
            EXPECT_TRUE(coefficient.is_equal(r == u ? 1 : 0))
                << "row " << r << ", " << m.unknowns[u] << ": " << coefficient;
        }
}
