// SPDX-License-Identifier: MIT
// Numeric forward dynamics: hand formulas, the hand-written recursion, GiNaC's own numbers,
// a plugged-in C function, and singular or non-finite configurations reported by name.
#include "alembert/sim/forward_dynamics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "planar_chain_reference.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

TEST(ForwardDynamics, OneUprightRodFallsAsTheHandFormulaSays) {
    // (m L^2 / 3) q'' = T + m g (L/2) sin q
    SampleModel rod = make_planar_chain(1);
    ForwardDynamics fd = compile_forward_dynamics(rod.system, rod.q, rod.unknowns, "rod");
    const double q = 0.4, qd = 1.7, T = 0.3;
    double qdd = 0;
    fd.calc_accelerations(0.0, &q, &qd, &T, &qdd);
    EXPECT_NEAR(qdd, 3 * (T + 9.81 * 0.5 * std::sin(q)), 1e-13);
    EXPECT_TRUE(fd.last_solve_was_ldlt());
}

TEST(ForwardDynamics, PlanarChainsMatchTheHandWrittenArticulatedBodyRecursion) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-2.0, 2.0);
    for (int n : {2, 3, 6}) {
        SampleModel chain = make_planar_chain(n);
        ForwardDynamics fd =
            compile_forward_dynamics(chain.system, chain.q, chain.unknowns, "chain");
        bench::PlanarChainReference reference(n);
        const auto un = static_cast<std::size_t>(n);
        std::vector<double> q(un), qd(un), tau(un), ours(un), theirs(un);
        for (int trial = 0; trial < 10; ++trial) {
            for (std::size_t i = 0; i < un; ++i)
                q[i] = angle(rng), qd[i] = rate(rng), tau[i] = 10 * rate(rng);
            fd.calc_accelerations(0.0, q.data(), qd.data(), tau.data(), ours.data());
            reference.forward_dynamics(q.data(), qd.data(), tau.data(), theirs.data());
            for (std::size_t i = 0; i < un; ++i)
                EXPECT_NEAR(ours[i], theirs[i], 1e-10 * (1 + std::abs(theirs[i])))
                    << "n = " << n << ", joint " << i + 1;
            EXPECT_TRUE(fd.last_solve_was_ldlt());
        }
    }
}

TEST(ForwardDynamics, TapeAgreesWithGiNaCsOwnNumericEvaluation) {
    // M and f of the triple pendulum, evaluated by the tape and by GiNaC (subs + evalf)
    SampleModel m = make_triple_pendulum();
    const SymbolTable& s = m.system.symbols();
    LinearSystem eqs = form_forward_equations(m.system, m.q);
    ForwardDynamics fd = compile_forward_dynamics(s, eqs, m.q, m.unknowns, "triple_pendulum");
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<double> in(1 + 6 + 3);
        exmap at{{s.time(), in[0] = value(rng)}};
        for (std::size_t i = 0; i < 3; ++i) {
            at[m.q[i].symbol()] = in[1 + i] = value(rng);
            at[m.q[i].d(1)] = in[4 + i] = value(rng);
            at[m.unknowns[i]] = in[7 + i] = 50 * value(rng);
        }
        std::vector<double> out(12);
        fd.function().evaluate(in.data(), out.data());
        for (unsigned r = 0; r < 3; ++r) {
            for (unsigned c = 0; c < 3; ++c) {
                const double ginac = s.evaluate(eqs.A(r, c), at);
                EXPECT_NEAR(out[3 * r + c], ginac, 1e-12 * std::max(1.0, std::abs(ginac)));
            }
            const double ginac = s.evaluate(eqs.b(r, 0), at);
            EXPECT_NEAR(out[9 + r], ginac, 1e-12 * std::max(1.0, std::abs(ginac)));
        }
    }
}

// one upright rod written by hand in C: inputs [t, q, q', T], outputs [M, f]
void rod_by_hand(const double* in, double* out) {
    out[0] = 1.0 / 3.0;
    out[1] = in[3] + 9.81 * 0.5 * std::sin(in[1]);
}

TEST(ForwardDynamics, ACompiledFunctionCanReplaceTheTape) {
    SampleModel rod = make_planar_chain(1);
    ForwardDynamics from_tape = compile_forward_dynamics(rod.system, rod.q, rod.unknowns, "rod");
    ForwardDynamics from_c("rod", from_tape.layout(), make_c_function(rod_by_hand, 4, 2));
    const double q = -2.2, qd = 0.5, T = -1.1;
    double a = 0, b = 0;
    from_tape.calc_accelerations(0, &q, &qd, &T, &a);
    from_c.calc_accelerations(0, &q, &qd, &T, &b);
    EXPECT_NEAR(a, b, 1e-14);
    EXPECT_THROW_MSG(ForwardDynamics("rod", from_tape.layout(), make_c_function(rod_by_hand, 3, 2)),
                     ArgumentError, "the layout needs 4 inputs [t, q, q', inputs] and 2 outputs");
}

TEST(ForwardDynamics, ASingularMassMatrixIsReportedWithTheModelAndTheState) {
    // massless links: M = 0
    SampleModel chain = make_planar_chain(2);
    SymbolTable& s = chain.system.symbols();
    s.set_value(s.symbol("m1"), 0.0);
    s.set_value(s.symbol("m2"), 0.0);
    ForwardDynamics fd =
        compile_forward_dynamics(chain.system, chain.q, chain.unknowns, "massless");
    const double q[2] = {0.1, 0.2}, qd[2] = {0, 0}, T[2] = {0, 0};
    double qdd[2];
    EXPECT_THROW_MSG(fd.calc_accelerations(0.5, q, qd, T, qdd), SolveError,
                     "forward dynamics of 'massless': the mass matrix is singular or "
                     "ill-conditioned");
    EXPECT_THROW_MSG(fd.calc_accelerations(0.5, q, qd, T, qdd), SolveError,
                     "at t = 0.5, q1 = 0.1, q2 = 0.2, q1' = 0, q2' = 0");
}

TEST(ForwardDynamics, ANonFiniteForceIsReportedNotReturnedAsNaN) {
    SampleModel rod = make_planar_chain(1);
    SymbolTable& s = rod.system.symbols();
    s.set_value(s.symbol("g"), std::numeric_limits<double>::quiet_NaN());
    ForwardDynamics fd = compile_forward_dynamics(rod.system, rod.q, rod.unknowns, "rod");
    const double q = 0.3, qd = 0, T = 0;
    double qdd = 0;
    EXPECT_THROW_MSG(fd.calc_accelerations(0, &q, &qd, &T, &qdd), SolveError,
                     "forward dynamics of 'rod': the right-hand side of equation 1 is nan");
}

TEST(ForwardDynamics, ALoadMeasureLeftOutOfTheInputsIsNamed) {
    SampleModel rod = make_planar_chain(1);
    EXPECT_THROW_MSG(compile_forward_dynamics(rod.system, rod.q, {}, "rod"), ArgumentError,
                     "compile_forward_dynamics('rod'): ");
    EXPECT_THROW_MSG(compile_forward_dynamics(rod.system, rod.q, {}, "rod"), ArgumentError, "T1");
}

TEST(ForwardDynamics, AClosedLoopIsSolvedWithItsConstraintForcesByLU) {
    // the four-bar held still by its crank torque: zero accelerations at rest, and the pin
    // force balances the coupler and rocker
    SampleModel fb = make_four_bar();
    ForwardDynamics fd = compile_forward_dynamics(fb.system, fb.q, {fb.unknowns[0]}, "four_bar",
                                                  {fb.unknowns[1], fb.unknowns[2]});
    EXPECT_EQ(fd.unknown_count(), 5u);
    // a closed pose: crank at 60 degrees, coupler and rocker solved by hand
    const double LN = 1, LA = 0.4, LB = 1.2, LC = 0.8, qA = std::numbers::pi / 3;
    const double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
    const double dx = LN - ax, dy = -ay, d = std::hypot(dx, dy);
    const double along = (LB * LB - LC * LC + d * d) / (2 * d),
                 h = std::sqrt(LB * LB - along * along);
    const double px = ax + along * dx / d - h * dy / d, py = ay + along * dy / d + h * dx / d;
    const double thB = std::atan2(py - ay, px - ax);
    const double q[3] = {qA, thB - qA, std::atan2(py, px - LN)}, qd[3] = {0, 0, 0};
    ASSERT_NEAR(std::hypot(LN + LC * std::cos(q[2]) - px, LC * std::sin(q[2]) - py), 0, 1e-12);
    // with the crank free (T = 0) the linkage falls: the accelerations keep the loop closed
    // to first order, d^2/dt^2 loop = J q'' = 0 at rest
    const double T = 0;
    double qdd[3];
    fd.calc_accelerations(0, q, qd, &T, qdd);
    const double thA = q[0], thBa = q[0] + q[1], thC = q[2];
    const double loop_x = -LA * std::sin(thA) * qdd[0] - LB * std::sin(thBa) * (qdd[0] + qdd[1]) +
                          LC * std::sin(thC) * qdd[2];
    const double loop_y = LA * std::cos(thA) * qdd[0] + LB * std::cos(thBa) * (qdd[0] + qdd[1]) -
                          LC * std::cos(thC) * qdd[2];
    EXPECT_NEAR(loop_x, 0, 1e-10);
    EXPECT_NEAR(loop_y, 0, 1e-10);
    EXPECT_GT(std::abs(qdd[0]), 1e-3);  // it does fall
    EXPECT_FALSE(fd.last_solve_was_ldlt());
}

}  // namespace
}  // namespace alembert
