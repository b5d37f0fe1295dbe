// SPDX-License-Identifier: MIT
// The default road-map gives every degree of freedom a row: an under-actuated model's
// undriven coordinates get rows of their own beside the unknown loads'.
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::Model;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::sin;

namespace {

// A cart (particle, mass M) sliding along Nx pushed by F Nx> (unknown) and a bob (particle,
// mass m) at l Ry> from it, the rod frame R turned by th about Nz from N (upright at th = 0,
// Ny up); gravity -g Ny, as examples/inverted_pendulum_cart/model.alb.
Model make_cart_pole() {
    Model md{System("N"), {}, {}};
    SymbolTable& s = md.sys.symbols();
    Frame& N = md.sys.newtonian();
    TimeVariable x = s.add_variable("x"), th = s.add_variable("th");
    ex M = s.add_constant("M"), m = s.add_constant("m"), l = s.add_constant("l"), g = s.add_constant("g");
    ex F = s.add_unknown("F");
    Frame& R = md.sys.add_frame("R");
    R.orient_axis(N, Axis::z, th);
    Particle& Cart = md.sys.add_particle("Cart");
    Particle& P = md.sys.add_particle("P");
    Cart.point().set_pos(md.sys.origin(), x * N.x());
    P.point().set_pos(Cart.point(), l * R.y());
    Cart.set_mass(M);
    P.set_mass(m);
    md.sys.set_gravity(-g * N.y());
    md.sys.add_force(Cart.point(), F * N.x(), "push");
    md.q = {x, th};
    md.loads = {F};
    return md;
}

// An acrobot: uniform rods A (mass m_A, length L_A) pinned at N_o and B (m_B, L_B) pinned at
// A's tip, hanging along -Ay> and -By>; A turns by q1 about Nz from N, B by q2 from A; gravity
// -g Ny; the only motor is at the elbow, T Nz> on B from A (unknown).
Model make_acrobot() {
    Model md{System("N"), {}, {}};
    SymbolTable& s = md.sys.symbols();
    Frame& N = md.sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    ex m_A = s.add_constant("m_A"), L_A = s.add_constant("L_A");
    ex m_B = s.add_constant("m_B"), L_B = s.add_constant("L_B"), g = s.add_constant("g");
    ex T = s.add_unknown("T");
    RigidBody& A = md.sys.add_rigid_body("A");
    RigidBody& B = md.sys.add_rigid_body("B");
    A.body_frame().orient_axis(N, Axis::z, q1);
    B.body_frame().orient_axis(A.body_frame(), Axis::z, q2);
    md.sys.point("A_o").set_pos(md.sys.origin(), Vector());
    A.cm().set_pos(md.sys.point("A_o"), -(L_A / 2) * A.body_frame().y());
    md.sys.point("B_o").set_pos(md.sys.point("A_o"), -L_A * A.body_frame().y());
    B.cm().set_pos(md.sys.point("B_o"), -(L_B / 2) * B.body_frame().y());
    A.set_mass(m_A);
    B.set_mass(m_B);
    A.set_inertia(A.cm(), m_A * L_A * L_A / 12, 0, m_A * L_A * L_A / 12);
    B.set_inertia(B.cm(), m_B * L_B * L_B / 12, 0, m_B * L_B * L_B / 12);
    md.sys.set_gravity(-g * N.y());
    md.sys.add_torque_pair(B, A.body_frame(), T * N.z(), "T");
    md.q = {q1, q2};
    md.loads = {T};
    return md;
}

std::vector<ex> equations_of(const std::vector<RoadmapRow>& rows) {
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    return E;
}

std::vector<std::string> names_of(const BodySet& S) {
    std::vector<std::string> n;
    for (const Body* b : S) n.push_back(b->name());
    return n;
}

// the largest difference, relative to max(1, |q''|), between the accelerations the road-map
// rows and Kane's and Lagrange's equations give with the loads drawn at random states
double largest_difference_from_kane_and_lagrange(const Model& md, const std::vector<ex>& rows) {
    const SymbolTable& st = md.sys.symbols();
    const std::vector<ex> acc = test::accelerations(md.q);
    const LinearSystem roadmap = form_linear_system(rows, acc);
    const LinearSystem kane = form_linear_system(form_kane_equations(md.sys, md.q), acc);
    const LinearSystem lagrange = form_linear_system(form_lagrange_equations(md.sys, md.q), acc);
    std::mt19937 rng(7);
    double worst = 0;
    for (int k = 0; k < 5; ++k) {
        const exmap state = test::random_state(st, rng, acc);
        const Eigen::VectorXd a = solve_numeric(st, roadmap, state);
        for (const LinearSystem* other : {&kane, &lagrange}) {
            const Eigen::VectorXd b = solve_numeric(st, *other, state);
            for (Eigen::Index i = 0; i < a.size(); ++i)
                worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(1.0, std::abs(b[i])));
        }
    }
    return worst;
}

}  // namespace

TEST(DefaultRoadmap, CartPoleGetsTheRowOfItsPendulumBesideThePush) {
    Model md = make_cart_pole();
    const SymbolTable& st = md.sys.symbols();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(md.sys, md.q);
    ASSERT_EQ(rows.size(), 2u);
    // the push's row: S = {Cart, P} sliding along Nx>, where the rod's force is internal
    EXPECT_TRUE(rows[0].variable.is_equal(md.loads[0]));
    EXPECT_EQ(rows[0].motion, Motion::translate);
    EXPECT_TRUE(same(dot(rows[0].direction, md.sys.newtonian().x()), 1));
    EXPECT_EQ(names_of(rows[0].system), (std::vector<std::string>{"Cart", "P"}));
    // the pendulum's row: S = {P}, what moves when only th changes; the push is not in it
    EXPECT_TRUE(rows[1].variable.is_equal(md.q[1].d(2)));
    EXPECT_EQ(names_of(rows[1].system), std::vector<std::string>{"P"});
    EXPECT_FALSE(rows[1].equation.has(md.loads[0]));

    // by hand (P at x Nx> + l Ry>, Ry> = -sin th Nx> + cos th Ny>):
    //   x:  (M + m) x'' - m l cos(th) th'' + m l sin(th) th'^2 - F = 0
    //   th: m l^2 th'' - m l cos(th) x'' - m g l sin(th) = 0 (moments about the cart's point)
    const ex M = st.symbol("M"), m = st.symbol("m"), l = st.symbol("l"), g = st.symbol("g");
    const ex x2 = md.q[0].d(2), th = md.q[1], th1 = md.q[1].d(1), th2 = md.q[1].d(2), F = md.loads[0];
    const ex hand_x = (M + m) * x2 - m * l * cos(th) * th2 + m * l * sin(th) * th1 * th1 - F;
    const ex hand_th = m * l * l * th2 - m * l * cos(th) * x2 - m * g * l * sin(th);
    // each row, solved for its own unknown with the other quantities drawn at random, gives the
    // value the hand equation gives: the rows are the hand equations up to a factor
    std::mt19937 rng(3);
    for (int k = 0; k < 5; ++k) {
        exmap state = test::random_state(st, rng, {F});
        const double F_hand = st.evaluate(solve_symbolic(form_linear_system({hand_x}, {F}))[0], state);
        const double F_row = st.evaluate(solve_symbolic(form_linear_system({rows[0].equation}, {F}))[0], state);
        EXPECT_NEAR(F_row, F_hand, 1e-12 * std::max(1.0, std::abs(F_hand)));
        state.erase(th2);
        const double th2_hand = st.evaluate(solve_symbolic(form_linear_system({hand_th}, {th2}))[0], state);
        const double th2_row =
            st.evaluate(solve_symbolic(form_linear_system({rows[1].equation}, {th2}))[0], state);
        EXPECT_NEAR(th2_row, th2_hand, 1e-12 * std::max(1.0, std::abs(th2_hand)));
    }
    // together, solved for the accelerations at a random push, they agree with Kane's and
    // Lagrange's equations
    EXPECT_LT(largest_difference_from_kane_and_lagrange(md, equations_of(rows)), test::kAgree);
}

TEST(DefaultRoadmap, ListedUnknownsKeepExactlyTheirRows) {
    Model md = make_cart_pole();
    const std::vector<RoadmapRow> rows = plan_roadmap(md.sys, md.q, md.loads);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_TRUE(rows[0].variable.is_equal(md.loads[0]));
}

TEST(DefaultRoadmap, AcrobotGetsTheShoulderRowBesideTheElbowTorque) {
    Model md = make_acrobot();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(md.sys, md.q);
    ASSERT_EQ(rows.size(), 2u);
    // the elbow torque: S = {B} about the elbow; the shoulder: S = {A, B} about the pin,
    // where the elbow torque is internal
    EXPECT_TRUE(rows[0].variable.is_equal(md.loads[0]));
    EXPECT_EQ(names_of(rows[0].system), std::vector<std::string>{"B"});
    ASSERT_NE(rows[0].about, nullptr);
    EXPECT_EQ(rows[0].about->name(), "B_o");
    EXPECT_TRUE(rows[1].variable.is_equal(md.q[0].d(2)));
    EXPECT_EQ(rows[1].motion, Motion::rotate);
    EXPECT_EQ(names_of(rows[1].system), (std::vector<std::string>{"A", "B"}));
    ASSERT_NE(rows[1].about, nullptr);
    EXPECT_EQ(rows[1].about->name(), "A_o");
    EXPECT_FALSE(rows[1].equation.has(md.loads[0]));
    EXPECT_LT(largest_difference_from_kane_and_lagrange(md, equations_of(rows)), test::kAgree);
}

TEST(DefaultRoadmap, AMotorAtEveryJointLeavesNoRowToAdd) {
    SampleModel m = make_triple_pendulum();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(m.system, m.q);
    ASSERT_EQ(rows.size(), m.unknowns.size());
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_TRUE(rows[i].variable.is_equal(m.unknowns[i]));
}

TEST(DefaultRoadmap, WithoutUnknownLoadsTheRowsAreTheAccelerations) {
    Model md = test::make_particle_double_pendulum();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(md.sys, md.q);
    ASSERT_EQ(rows.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(rows[i].variable.is_equal(md.q[i].d(2)));
}

TEST(DefaultRoadmap, ALoopsFreeConstraintRowsTakeTheDependentAccelerations) {
    // the four-bar's crank torque and pin force take the three coordinates' rows; its two
    // loop rows (at the acceleration level) are the equations of the rocker's and coupler's
    // accelerations, the crank's being the one degree of freedom the torque drives
    SampleModel m = make_four_bar();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(m.system, m.q);
    ASSERT_EQ(rows.size(), 5u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(rows[i].variable.is_equal(m.unknowns[i]));
    EXPECT_TRUE(rows[3].variable.is_equal(m.q[1].d(2)));
    EXPECT_TRUE(rows[4].variable.is_equal(m.q[2].d(2)));
    EXPECT_EQ(rows[3].motion, Motion::constraint);
    EXPECT_EQ(rows[4].motion, Motion::constraint);
}
