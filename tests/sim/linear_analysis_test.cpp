// SPDX-License-Identifier: MIT
// Eigenvalues and stability verdicts, Ackermann's pole placement and stability changes along a
// parameter, against cases worked by hand.
#include "alembert/sim/linear_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using cd = std::complex<double>;

TEST(LinearAnalysis, EigenvaluesOfAnOscillatorAreOrderedAndVectorsNormalised) {
    // x'' = -4 x: lambda = +-2i, +2i first; its eigenvector (1, 2i)/sqrt(5) scaled so the
    // largest component (2i) becomes real positive: (-i, 2)/sqrt(5)
    Eigen::Matrix2d A;
    A << 0, 1, -4, 0;
    EigenAnalysis e = calc_eigen(A);
    ASSERT_EQ(e.values.size(), 2u);
    EXPECT_NEAR(e.values[0].real(), 0, 1e-14);
    EXPECT_NEAR(e.values[0].imag(), 2, 1e-14);
    EXPECT_NEAR(e.values[1].imag(), -2, 1e-14);
    EXPECT_NEAR(e.vectors(1, 0).real(), 2 / std::sqrt(5.0), 1e-14);
    EXPECT_NEAR(e.vectors(1, 0).imag(), 0, 1e-14);
    EXPECT_NEAR(e.vectors(0, 0).imag(), -1 / std::sqrt(5.0), 1e-14);
    // A v = lambda v for each
    for (int k = 0; k < 2; ++k)
        EXPECT_LT((A.cast<cd>() * e.vectors.col(k) -
                   e.values[static_cast<std::size_t>(k)] * e.vectors.col(k))
                      .norm(),
                  1e-13);
    EXPECT_EQ(classify_stability(e.values, zero_real_part_tolerance(A)), Stability::marginal);
    // an inverted pendulum x'' = 9 x: +3, -3, unstable; with damping x'' = -x - 2 x': double -1
    A << 0, 1, 9, 0;
    e = calc_eigen(A);
    EXPECT_NEAR(e.values[0].real(), 3, 1e-13);
    EXPECT_NEAR(e.values[1].real(), -3, 1e-13);
    EXPECT_EQ(classify_stability(e.values, zero_real_part_tolerance(A)), Stability::unstable);
    A << 0, 1, -1, -2;
    EXPECT_EQ(classify_stability(calc_eigen(A).values, zero_real_part_tolerance(A)),
              Stability::asymptotically_stable);
    EXPECT_THROW_MSG(calc_eigen(Eigen::MatrixXd::Zero(2, 3)), ArgumentError, "2 x 3");
}

TEST(LinearAnalysis, IgnorableStatesGiveExactZerosWithoutBlurringTheRest) {
    // a chain y' = q, q' = u, with u in an oscillator u'' = -9 u (states u, v = u'): a zero
    // eigenvalue of multiplicity 3 in a Jordan chain (y, q, and the oscillator's feed) would
    // come out of floating point near eps^(1/3) = 6e-6; the states y (zero column) and q (then
    // a zero column) are taken out exactly, leaving +-3i
    Eigen::Matrix4d A;  // states (y, q, u, v)
    A << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -9, 0;
    EigenAnalysis e = calc_eigen(A);
    ASSERT_EQ(e.values.size(), 4u);
    int zeros = 0;
    for (const cd& l : e.values) zeros += (l == cd(0, 0)) ? 1 : 0;
    EXPECT_EQ(zeros, 2);
    EXPECT_NEAR(e.values[0].imag(), 3, 1e-14);
    EXPECT_NEAR(e.values[3].imag(), -3, 1e-14);
    EXPECT_EQ(classify_stability(e.values, zero_real_part_tolerance(A)), Stability::marginal);
}

TEST(LinearAnalysis, AckermannGainOfTheDoubleIntegratorMatchesHandDerivation) {
    // x'' = r with r = -k1 x - k2 x': s^2 + k2 s + k1 = (s + 1)(s + 2) gives k = (2, 3)
    Eigen::Matrix2d A;
    A << 0, 1, 0, 0;
    Eigen::Vector2d b(0, 1);
    Eigen::RowVectorXd k = place_poles(A, b, {-1.0, -2.0});
    EXPECT_NEAR(k(0), 2, 1e-12);
    EXPECT_NEAR(k(1), 3, 1e-12);
    // poles -1 +- 2i: s^2 + 2 s + 5, k = (5, 2)
    k = place_poles(A, b, {cd(-1, 2), cd(-1, -2)});
    EXPECT_NEAR(k(0), 5, 1e-12);
    EXPECT_NEAR(k(1), 2, 1e-12);
    EXPECT_THROW_MSG(place_poles(A, b, {cd(-1, 2), -1.0}), ArgumentError, "has no conjugate");
    EXPECT_THROW_MSG(place_poles(A, b, {-1.0}), ArgumentError, "1 poles for 2 states");
    // a force on the position alone cannot steer the velocity of x'' = 0 with x' = r
    EXPECT_THROW_MSG(place_poles(A, Eigen::Vector2d(1, 0), {-1.0, -2.0}), SolveError,
                     "cannot steer every state");
}

TEST(LinearAnalysis, UncontrollableSystemIsReportedWithItsTrueConditionNumberZero) {
    // two double integrators, the input on the first: [b, A b, A^2 b, A^3 b] has columns
    // (0, 1, 0, 0), (1, 0, 0, 0), 0, 0: rank 2 of 4, singular values 1, 1, 0, 0, condition 0
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
    A(0, 1) = 1;
    A(2, 3) = 1;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(4);
    b(1) = 1;
    EXPECT_THROW_MSG(place_poles(A, b, {-1.0, -2.0, -3.0, -4.0}), SolveError,
                     "reaches 2 of the 4 states (reciprocal condition number 0, below 1e-12)");
}

TEST(LinearAnalysis, LqrGainOfAScalarSystemMatchesTheQuadraticFormula) {
    // x' = a x + b r, cost q x^2 + r0 r^2: the Riccati equation 2 a P - b^2 P^2/r0 + q = 0 has
    // the stabilising root P = r0 (a + sqrt(a^2 + b^2 q/r0))/b^2 and K = b P/r0
    const double a = 1, b = 2, q = 3, r0 = 0.5;
    Eigen::MatrixXd A(1, 1), B(1, 1), Q(1, 1), R(1, 1);
    A << a, B << b, Q << q, R << r0;
    LqrSolution s = solve_lqr(A, B, Q, R);
    const double P = r0 * (a + std::sqrt(a * a + b * b * q / r0)) / (b * b);
    EXPECT_NEAR(s.P(0, 0), P, 1e-13);
    EXPECT_NEAR(s.K(0, 0), b * P / r0, 1e-13);
    EXPECT_LT(a - b * s.K(0, 0), 0);
}

TEST(LinearAnalysis, LqrGainOfTheDoubleIntegratorMatchesHandDerivation) {
    // x'' = r, Q = 1, R = 1: P = [sqrt 3, 1; 1, sqrt 3], K = (1, sqrt 3) (the Riccati
    // equation's entries: p12^2 = 1, 2 p12 = p22^2 - 1, p11 = p12 p22)
    Eigen::MatrixXd A(2, 2), B(2, 1);
    A << 0, 1, 0, 0;
    B << 0, 1;
    LqrSolution s = solve_lqr(A, B, Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(1, 1));
    EXPECT_NEAR(s.P(0, 0), std::sqrt(3.0), 1e-13);
    EXPECT_NEAR(s.P(0, 1), 1, 1e-13);
    EXPECT_NEAR(s.P(1, 1), std::sqrt(3.0), 1e-13);
    EXPECT_NEAR(s.K(0, 0), 1, 1e-13);
    EXPECT_NEAR(s.K(0, 1), std::sqrt(3.0), 1e-13);
    EXPECT_LT(s.relative_residual, 1e-14);
    // an input that cannot reach an unstable mode, a weight that is not positive
    Eigen::MatrixXd one = Eigen::MatrixXd::Identity(1, 1);
    EXPECT_THROW_MSG(solve_lqr(one, Eigen::MatrixXd::Zero(1, 1), one, one), SolveError, "not stabilisable");
    // an undamped oscillator no input reaches: the Hamiltonian's eigenvalues +-i
    Eigen::MatrixXd W(2, 2);
    W << 0, 1, -1, 0;
    EXPECT_THROW_MSG(solve_lqr(W, Eigen::MatrixXd::Zero(2, 1), Eigen::MatrixXd::Identity(2, 2), one), SolveError,
                     "imaginary axis");
    EXPECT_THROW_MSG(solve_lqr(A, B, Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Zero(1, 1)), ArgumentError,
                     "positive definite");
    EXPECT_THROW_MSG(solve_lqr(A, B, -Eigen::MatrixXd::Identity(2, 2), one), ArgumentError, "negative eigenvalue");
}

TEST(LinearAnalysis, LqrOfACartPendulumSolvesRiccatiAndStabilises) {
    // the cart-pendulum below, two inputs (a force on the cart and a torque at the hinge):
    // the residual of the Riccati equation, recomputed here, is at round-off and A - B K is
    // stable; P is symmetric positive definite
    const double M = 1.5, m = 0.3, l = 0.6, g = 9.81;
    Eigen::MatrixXd A(4, 4), B(4, 2);
    A << 0, 0, 1, 0, 0, 0, 0, 1, 0, -m * g / M, 0, 0, 0, (M + m) * g / (M * l), 0, 0;
    B << 0, 0, 0, 0, 1 / M, -1 / (M * l), -1 / (M * l), (M + m) / (M * m * l * l);
    Eigen::MatrixXd Q = Eigen::Vector4d(10, 100, 1, 1).asDiagonal();
    Eigen::MatrixXd R = Eigen::Vector2d(0.1, 1).asDiagonal();
    LqrSolution s = solve_lqr(A, B, Q, R);
    Eigen::MatrixXd res = A.transpose() * s.P + s.P * A - s.P * B * R.inverse() * B.transpose() * s.P + Q;
    EXPECT_LT(res.norm(), 1e-9 * s.P.norm());
    EXPECT_LT((s.K - R.inverse() * B.transpose() * s.P).norm(), 1e-12 * s.K.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s.P).eigenvalues().minCoeff(), 0);
    for (const cd& z : calc_eigen(A - B * s.K).values) EXPECT_LT(z.real(), 0);
}

TEST(LinearAnalysis, PlacedPolesAreTheClosedLoopEigenvaluesOfACartPendulum) {
    // point-mass pendulum (m, l) on a cart (M), x = (x, th, x', th'), force F on the cart:
    // x'' = (F - m g th)/M, th'' = ((M + m) g th - F)/(M l)
    const double M = 1.5, m = 0.3, l = 0.6, g = 9.81;
    Eigen::Matrix4d A;
    A << 0, 0, 1, 0, 0, 0, 0, 1, 0, -m * g / M, 0, 0, 0, (M + m) * g / (M * l), 0, 0;
    Eigen::Vector4d b(0, 0, 1 / M, -1 / (M * l));
    std::vector<cd> poles = {cd(-2, 1), cd(-2, -1), -3.0, -4.0};
    Eigen::RowVectorXd k = place_poles(A, b, poles);
    EigenAnalysis e = calc_eigen(A - b * k);
    // sorted: -2 + i, -2 - i, -3, -4
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(e.values[i].real(), poles[i].real(), 1e-9) << i;
        EXPECT_NEAR(e.values[i].imag(), poles[i].imag(), 1e-9) << i;
    }
}

TEST(LinearAnalysis, StabilityChangesAreFoundByBisection) {
    // A(p) = diag(p - 1, -1): unstable above p = 1
    auto linear = [](double p) {
        Eigen::MatrixXd A(2, 2);
        A << p - 1, 0, 0, -1;
        return A;
    };
    std::vector<double> grid;
    for (int i = 0; i <= 6; ++i) grid.push_back(0.3 * i);
    std::vector<StabilityChange> c = find_stability_changes(linear, grid);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_TRUE(c[0].becomes_unstable);
    // the mode crosses the axis: the zero of its real part, not where it passes the
    // verdict's tolerance band (1e-6 here, which put the change at 1 + 1e-6)
    EXPECT_NEAR(c[0].at, 1.0, 1e-12);
    // x'' = (1 - p) x: lambda = +-sqrt(1 - p), unstable below p = 1 and marginal above; the
    // real part vanishes like sqrt, so the band 1e-6 moves the boundary by only 1e-12
    auto spring = [](double p) {
        Eigen::MatrixXd A(2, 2);
        A << 0, 1, 1 - p, 0;
        return A;
    };
    c = find_stability_changes(spring, grid);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_FALSE(c[0].becomes_unstable);
    EXPECT_NEAR(c[0].at, 1.0, 1e-10);
}

TEST(LinearAnalysis, ADampedOscillatorLosesStabilityExactlyWhereItsDampingChangesSign) {
    // m x'' + c x' + k x = 0 with k/m = 10000 s^-2: real parts -c/(2m), zero at c = 0. The
    // verdict's tolerance (1e-6 of the largest entry of A, 1e-2 here) put the change at
    // c = -0.02 when the sweep bisected on the verdict.
    auto damped = [](double c) {
        Eigen::MatrixXd A(2, 2);
        A << 0, 1, -10000, -c;
        return A;
    };
    std::vector<double> grid{-1, -0.5, 0.25, 0.5, 1};
    std::vector<StabilityChange> ch = find_stability_changes(damped, grid);
    ASSERT_EQ(ch.size(), 1u);
    EXPECT_FALSE(ch[0].becomes_unstable);  // unstable for negative damping, stable above
    EXPECT_NEAR(ch[0].at, 0.0, 1e-12);
}

}  // namespace
}  // namespace alembert
