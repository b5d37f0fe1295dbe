// SPDX-License-Identifier: MIT
// Tests of points: positions along the point tree, velocities and accelerations by
// differentiation and by the two-point and one-point theorems, and the errors of a bad tree.
#include "alembert/mech/point.hpp"

#include <gtest/gtest.h>

#include "alembert/error.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;
using alembert::test::same;

// A disk precessing on a fixed arm: frame A turns about Nz by psi, the disk frame D spins
// about Ay by phi; the disk centre O is R_ along Ax from N_o and P is on the rim, r along Dz.
class PointOnPrecessingDisk : public ::testing::Test {
protected:
    PointOnPrecessingDisk() {
        A.orient_axis(N, Axis::z, psi);
        D.orient_axis(A, Axis::y, phi);
        O.set_pos(sys.origin(), R_ * A.x());
        P.set_pos(O, r * D.z());
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable psi = s.add_variable("psi"), phi = s.add_variable("phi");
    ex R_ = s.add_constant("R_"), r = s.add_constant("r");
    Frame& A = sys.add_frame("A");
    Frame& D = sys.add_frame("D");
    Point& O = sys.add_point("O");
    Point& P = sys.add_point("P");
};

TEST_F(PointOnPrecessingDisk, RimAccelerationByDifferentiationMatchesRigidBodyFormula) {
    // w = psi' Az + phi' Ay and, differentiating Ay in N (Ay turns with A),
    // alpha = psi'' Az + phi'' Ay + psi' phi' (Az x Ay)
    Vector w_ND = psi.d(1) * A.z() + phi.d(1) * A.y();
    Vector alpha_ND =
        psi.d(2) * A.z() + phi.d(2) * A.y() + psi.d(1) * phi.d(1) * cross(A.z(), A.y());
    // O moves on a circle of radius R_ about Nz: a^O = -R_ psi'^2 Ax + R_ psi'' Ay
    Vector a_NO = -R_ * pow(psi.d(1), 2) * A.x() + R_ * psi.d(2) * A.y();
    Vector p_OP = r * D.z();
    Vector a_NP = a_NO + cross(alpha_ND, p_OP) + cross(w_ND, cross(w_ND, p_OP));

    EXPECT_TRUE(same(O.acc_in(N), a_NO, N));
    EXPECT_TRUE(same(P.acc_in(N), a_NP, N));
    EXPECT_TRUE(same(P.acc_in(N), a_NP, D));
}

TEST_F(PointOnPrecessingDisk, RimAccelerationMatchesCylindricalComponents) {
    // P is at rho = R_ + r sin(phi) from the Nz axis, at angle psi, and at height r cos(phi):
    // a = (rho'' - rho psi'^2) Ax + (rho psi'' + 2 rho' psi') Ay + (r cos phi)'' Az
    ex sp = sin(phi), cp = cos(phi);
    ex rho = R_ + r * sp;
    ex rho_d = r * cp * phi.d(1);
    ex rho_dd = r * cp * phi.d(2) - r * sp * pow(phi.d(1), 2);
    ex z_dd = -r * sp * phi.d(2) - r * cp * pow(phi.d(1), 2);
    Vector a_NP = (rho_dd - rho * pow(psi.d(1), 2)) * A.x() +
                  (rho * psi.d(2) + 2 * rho_d * psi.d(1)) * A.y() + z_dd * A.z();
    EXPECT_TRUE(same(P.acc_in(N), a_NP, A));
}

TEST_F(PointOnPrecessingDisk, RimVelocityMatchesCylindricalComponents) {
    // v = rho' Ax + rho psi' Ay + (r cos phi)' Az
    ex rho = R_ + r * sin(phi);
    Vector v_NP =
        r * cos(phi) * phi.d(1) * A.x() + rho * psi.d(1) * A.y() - r * sin(phi) * phi.d(1) * A.z();
    EXPECT_TRUE(same(P.vel_in(N), v_NP, A));
}

TEST_F(PointOnPrecessingDisk, TwoPointTheoryMatchesDirectDifferentiation) {
    Point& Q = sys.add_point("Q");
    Q.set_pos(O, r * D.z());
    Q.set_vel_two_point(N, O, D);
    Q.set_acc_two_point(N, O, D);
    EXPECT_TRUE(Q.has_vel_set(N));

    // the same hand formulas as above, and the point derived by differentiation
    Vector w_ND = psi.d(1) * A.z() + phi.d(1) * A.y();
    Vector alpha_ND = psi.d(2) * A.z() + phi.d(2) * A.y() - psi.d(1) * phi.d(1) * A.x();
    Vector v_NO = R_ * psi.d(1) * A.y();
    Vector a_NO = -R_ * pow(psi.d(1), 2) * A.x() + R_ * psi.d(2) * A.y();
    Vector p_OQ = r * D.z();
    EXPECT_TRUE(same(Q.vel_in(N), v_NO + cross(w_ND, p_OQ), N));
    EXPECT_TRUE(
        same(Q.acc_in(N), a_NO + cross(alpha_ND, p_OQ) + cross(w_ND, cross(w_ND, p_OQ)), N));
    EXPECT_TRUE(same(Q.vel_in(N), P.vel_in(N), N));
    EXPECT_TRUE(same(Q.acc_in(N), P.acc_in(N), N));
}

TEST(Point, PositionBetweenBranchesGoesThroughTheCommonAncestor) {
    System sys;
    Frame& N = sys.newtonian();
    SymbolTable& s = sys.symbols();
    ex a = s.add_constant("a"), b = s.add_constant("b"), c = s.add_constant("c"),
       d = s.add_constant("d");
    Point &O = sys.add_point("O"), &P1 = sys.add_point("P1"), &P2 = sys.add_point("P2"),
          &P3 = sys.add_point("P3");
    O.set_pos(sys.origin(), a * N.x());
    P1.set_pos(O, b * N.y());
    P2.set_pos(O, c * N.z());
    P3.set_pos(P1, d * N.x());

    EXPECT_EQ(P1.located_from(), &O);
    EXPECT_EQ(O.located_from(), &sys.origin());
    EXPECT_TRUE(P1.pos_from(P1).is_zero());
    EXPECT_TRUE(same(P1.pos_from(sys.origin()), a * N.x() + b * N.y(), N));
    EXPECT_TRUE(same(P1.pos_from(P2), b * N.y() - c * N.z(), N));
    EXPECT_TRUE(same(P2.pos_from(P1), c * N.z() - b * N.y(), N));
    EXPECT_TRUE(same(P3.pos_from(P2), b * N.y() + d * N.x() - c * N.z(), N));
    EXPECT_TRUE(same(sys.origin().pos_from(P3), -(a + d) * N.x() - b * N.y(), N));
}

TEST(Point, VelocityOfAPendulumBobIsTangentToItsCircle) {
    System sys;
    Frame& N = sys.newtonian();
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q");
    ex L = s.add_constant("L");
    Frame& A = sys.add_frame("A");
    A.orient_axis(N, Axis::z, q);
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), L * A.y());

    // r = L Ay = L (-sin q, cos q): v = L q' (-cos q, -sin q),
    // a = L q'' (-cos q, -sin q) + L q'^2 (sin q, -cos q)
    Vector v_NP = L * q.d(1) * (-cos(q) * N.x() - sin(q) * N.y());
    Vector a_NP = L * q.d(2) * (-cos(q) * N.x() - sin(q) * N.y()) +
                  L * pow(q.d(1), 2) * (sin(q) * N.x() - cos(q) * N.y());
    EXPECT_TRUE(same(P.vel_in(N), v_NP, N));
    EXPECT_TRUE(same(P.acc_in(N), a_NP, N));
}

TEST(Point, SetVelocityReplacesTheDerivedOneAndItsDerivativeIsTheAcceleration) {
    System sys;
    Frame& N = sys.newtonian();
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x"), u = s.add_variable("u");
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), x * N.x());
    P.set_vel(N, u * N.x());
    EXPECT_TRUE(P.has_vel_set(N));
    EXPECT_TRUE(same(P.vel_in(N), u * N.x(), N));
    EXPECT_TRUE(same(P.acc_in(N), u.d(1) * N.x(), N));

    ex a = s.add_constant("a");
    P.set_acc(N, a * N.y());
    EXPECT_TRUE(same(P.acc_in(N), a * N.y(), N));
}

TEST(Point, DerivedVelocitiesFollowChangesToTheModel) {
    // velocities are formed once and kept; every change of the model must show in them
    System sys;
    Frame& N = sys.newtonian();
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x"), th = s.add_variable("th"), u = s.add_variable("u");
    Frame& B = sys.add_frame("B");
    B.orient_axis(N, Axis::z, th);
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), x * N.x());
    EXPECT_TRUE(same(P.vel_in(N), x.d(1) * N.x(), N));
    P.set_pos(sys.origin(), x * B.x());  // relocated
    EXPECT_TRUE(same(P.vel_in(N), x.d(1) * B.x() + x * th.d(1) * B.y(), N));
    EXPECT_TRUE(same(B.ang_vel_in(N), th.d(1) * N.z(), N));
    B.orient_axis(N, Axis::x, th);  // re-oriented
    EXPECT_TRUE(same(B.ang_vel_in(N), th.d(1) * N.x(), N));
    EXPECT_TRUE(same(P.vel_in(N), x.d(1) * B.x(), N));
    P.set_vel(N, P.vel_in(N) + u * N.z());  // set from the derived one
    EXPECT_TRUE(same(P.vel_in(N), x.d(1) * B.x() + u * N.z(), N));
    EXPECT_TRUE(same(P.acc_in(N), x.d(2) * B.x() + u.d(1) * N.z(), N));
}

TEST(Point, LongChainVelocitiesAreCompactAndEqualTheRateOfThePosition) {
    // the tip of a 7-link chain with two-axis joints: its velocity is formed in one frame with
    // named measures; it must equal d/dt of the position, by central differences along
    // q(t) = q0 + t q'
    SampleModel m = make_n_link_pendulum(7, ChainKind::spatial);
    const Point& tip = m.links.back()->cm();
    const Frame& N = m.system.newtonian();
    SymbolTable& s = m.system.symbols();
    Vector v = tip.vel_in(N);
    ASSERT_EQ(v.components().size(), 1u);
    for (int i = 0; i < 3; ++i) EXPECT_LT(count_ops(v.components()[0].second[i]), 60u);
    std::vector<ex> inputs, outputs;
    for (const TimeVariable& q : m.q) inputs.push_back(q.symbol());
    for (const TimeVariable& q : m.q) inputs.push_back(q.d(1));
    Col3 vN = v.components_in(N), rN = tip.pos_from(m.system.origin()).components_in(N);
    for (int i = 0; i < 3; ++i) outputs.push_back(vN[i]);
    for (int i = 0; i < 3; ++i) outputs.push_back(rN[i]);
    CompiledExpressions f(s, inputs, outputs);
    const std::size_t n = m.q.size();
    std::vector<double> x(2 * n);
    for (std::size_t k = 0; k < 2 * n; ++k)
        x[k] = 0.3 + 0.17 * static_cast<double>(k % 5) - 0.4 * static_cast<double>(k % 2);
    const double h = 1e-5;
    auto at = [&](double t) {
        std::vector<double> y = x;
        for (std::size_t k = 0; k < n; ++k) y[k] += t * x[n + k];
        return f.evaluate(y);
    };
    std::vector<double> here = at(0), ahead = at(h), behind = at(-h);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(here[i], (ahead[3 + i] - behind[3 + i]) / (2 * h), 1e-7) << "component " << i;
}

TEST(Point, OnePointTheoryGivesTheVelocityOfABeadOnASpinningRod) {
    System sys;
    Frame& N = sys.newtonian();
    SymbolTable& s = sys.symbols();
    TimeVariable theta = s.add_variable("theta"), x = s.add_variable("x");
    Frame& B = sys.add_frame("B");
    B.orient_axis(N, Axis::z, theta);

    // the bead slides along the rod Bx at x from N_o (fixed on B, on the spin axis)
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), x * B.x());
    P.set_vel(B, x.d(1) * B.x());
    P.set_vel_one_point(N, sys.origin(), B);
    // ^N v^P = x' Bx + theta' Bz x x Bx = x' Bx + x theta' By
    Vector v_NP = x.d(1) * B.x() + x * theta.d(1) * B.y();
    EXPECT_TRUE(same(P.vel_in(N), v_NP, N));

    // a second bead whose velocity is derived by differentiation agrees
    Point& Q = sys.add_point("Q");
    Q.set_pos(sys.origin(), x * B.x());
    EXPECT_TRUE(same(Q.vel_in(N), v_NP, B));
}

// ---- errors --------------------------------------------------------------------------------

TEST(Point, VelocityOfAPointNeverLocatedIsAnErrorNamingPointAndFrame) {
    System sys;
    Point& P = sys.add_point("P");
    EXPECT_THROW_MSG(P.vel_in(sys.newtonian()), ModelError,
                     "velocity of 'P' in frame 'N' is not defined");
    EXPECT_THROW_MSG(P.vel_in(sys.newtonian()), ModelError, "P.set_vel(N, ...)");
    EXPECT_THROW_MSG(P.acc_in(sys.newtonian()), ModelError,
                     "velocity of 'P' in frame 'N' is not defined");
}

TEST(Point, PositionBetweenUnlinkedPointsIsAnErrorNamingBoth) {
    System sys;
    Point& P = sys.add_point("P");
    Point& Q = sys.add_point("Q");
    P.set_pos(sys.origin(), sys.newtonian().x());
    EXPECT_THROW_MSG(P.pos_from(Q), ModelError, "the position of 'P' from 'Q' is not defined");
}

TEST(Point, LocatingAPointFromItselfIsAnErrorNamingIt) {
    System sys;
    Point& P = sys.add_point("P");
    EXPECT_THROW_MSG(P.set_pos(P, sys.newtonian().x()), ModelError,
                     "point 'P' cannot be located from itself");
    EXPECT_EQ(P.located_from(), nullptr);
}

TEST(Point, LocatingAPointThatClosesACycleIsAnErrorNamingTheChain) {
    System sys;
    Frame& N = sys.newtonian();
    Point &P = sys.add_point("P"), &Q = sys.add_point("Q"), &R = sys.add_point("R");
    Q.set_pos(P, N.x());
    R.set_pos(Q, N.y());
    EXPECT_THROW_MSG(P.set_pos(R, N.z()), ModelError, "locating 'P' from 'R' would close a cycle");
    EXPECT_THROW_MSG(P.set_pos(R, N.z()), ModelError, "'R' -> 'Q' -> 'P'");
    // the failed call left P where it was: unlocated
    EXPECT_EQ(P.located_from(), nullptr);
}

}  // namespace
}  // namespace alembert
