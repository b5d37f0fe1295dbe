// SPDX-License-Identifier: MIT
// The integrators: a chaotic double pendulum against a converged reference, a stiff
// spring-damper against its closed form, energy, events and dense output with each method.
#include "alembert/sim/integrator.hpp"

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sim/simulation.hpp"
#include "support/constants.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using test::kPi;

const Integrator kEvery[] = {Integrator::dopri5, Integrator::rkf78, Integrator::bulirsch_stoer,
                             Integrator::bdf};

// a double pendulum of uniform rods released from a high, chaotic start: 10 s
SimulationResult run_double_pendulum(Integrator method, double tol, double dq1 = 0) {
    SampleModel m = make_n_link_pendulum(2);
    SimulationRequest r;
    r.model = "double_pendulum";
    r.coordinates = m.q;
    r.initial_values = {{m.q[0].symbol(), 1.1 + dq1}, {m.q[1].symbol(), 1.4}};
    r.outputs = {{"q1", m.q[0], "rad"}, {"q2", m.q[1], "rad"}};
    r.options = {.t_final = 10.0, .integrator = method, .output_step = 0.5, .abs_tol = tol,
                 .rel_tol = tol, .progress = false};
    return run_simulation(m.system, r);
}

double largest_difference(const SimulationResult& a, const SimulationResult& b) {
    double worst = 0;
    for (std::size_t i = 0; i < a.q_end.size(); ++i)
        worst = std::max(worst, std::abs(a.q_end[i] - b.q_end[i]));
    return worst;
}

TEST(Integrator, NamesRoundTripAndAnUnknownNameListsTheChoices) {
    for (Integrator m : kEvery) EXPECT_EQ(parse_integrator(to_string(m)), m);
    EXPECT_THROW_MSG(parse_integrator("rk4"), ArgumentError,
                     "no integrator named 'rk4'; choose one of dopri5, rkf78, bulirsch_stoer, bdf");
}

// The same double pendulum written by hand in absolute angles th1 = q1, th2 = q1 + q2 (uniform
// rods m = L = 1, I = m L^2/12 about the mass centre, gravity -g Ny; Lagrange's equations):
//   (4/3) th1'' + (1/2) cos(th1 - th2) th2'' + (1/2) sin(th1 - th2) th2'^2 + (3/2) g sin th1 = 0
//   (1/2) cos(th1 - th2) th1'' + (1/3) th2'' - (1/2) sin(th1 - th2) th1'^2 + (1/2) g sin th2 = 0
// integrated in long double (64-bit mantissa, 2^11 times finer than double) by Odeint's
// Fehlberg 7(8) at tolerance 1e-18: its error, amplified by the chaos, stays near 1e-14 rad, so it
// is a reference for runs in double that aim at 1e-10 rad. Rows every 0.5 s to 10 s: q1, q2.
std::vector<std::array<long double, 2>> hand_double_pendulum_reference() {
    using State = std::vector<long double>;  // th1, th2, th1', th2'
    const long double g = 9.81L;
    auto rhs = [g](const State& x, State& dx, long double) {
        const long double c = std::cos(x[0] - x[1]), s = std::sin(x[0] - x[1]);
        const long double a11 = 4.0L / 3, a12 = 0.5L * c, a22 = 1.0L / 3;
        const long double b1 = -(0.5L * s * x[3] * x[3] + 1.5L * g * std::sin(x[0]));
        const long double b2 = -(-0.5L * s * x[2] * x[2] + 0.5L * g * std::sin(x[1]));
        const long double det = a11 * a22 - a12 * a12;
        dx[0] = x[2];
        dx[1] = x[3];
        dx[2] = (b1 * a22 - a12 * b2) / det;
        dx[3] = (a11 * b2 - a12 * b1) / det;
    };
    namespace odeint = boost::numeric::odeint;
    auto stepper = odeint::make_controlled(1e-18L, 1e-18L, odeint::runge_kutta_fehlberg78<State, long double>());
    State x{1.1L, 1.1L + 1.4L, 0.0L, 0.0L};
    std::vector<std::array<long double, 2>> rows;
    odeint::integrate_const(stepper, rhs, x, 0.0L, 10.0L, 0.5L, [&](const State& y, long double) {
        rows.push_back({y[0], y[1] - y[0]});
    });
    return rows;
}

TEST(Integrator, Fehlberg78ReachesTenDigitsOnAChaoticDoublePendulumOverTenSeconds) {
    const std::vector<std::array<long double, 2>> ref = hand_double_pendulum_reference();
    ASSERT_EQ(ref.size(), 21u);
    // the model's equations are the hand ones: Alembert's run at a tight tolerance follows the
    // reference through the lower link's turning over (an error in the equations would be of
    // order one after the chaos)
    const SimulationResult tight = run_double_pendulum(Integrator::rkf78, 1e-15);
    // chaotic: a change of 1e-9 rad at the start grows more than a thousandfold in 10 s (the
    // lower link turns over), where a regular motion changes it by a small factor
    const SimulationResult moved = run_double_pendulum(Integrator::rkf78, 1e-15, 1e-9);
    const double amplification = largest_difference(moved, tight) / 1e-9;
    EXPECT_GT(amplification, 1e3);
    EXPECT_GT(std::abs(tight.q_end[1]), 4 * kPi);
    const SimulationResult rkf = run_double_pendulum(Integrator::rkf78, 1e-14);
    const SimulationResult dp = run_double_pendulum(Integrator::dopri5, 1e-14);
    auto error = [&](const SimulationResult& run) {
        double worst = 0;
        for (std::size_t r = 0; r < ref.size(); ++r)
            for (int c = 1; c <= 2; ++c)
                worst = std::max(worst, static_cast<double>(std::abs(run.table.columns[c][r] - ref[r][c - 1])));
        return worst;
    };
    std::printf("double pendulum at 10 s (amplification %.1e) against a long-double reference: "
                "rkf78 error %.2e rad at tolerance 1e-15, at 1e-14 %.2e rad in %zu steps; dopri5 at "
                "1e-14 %.2e rad in %zu steps\n",
                amplification, error(tight), error(rkf), rkf.steps, error(dp), dp.steps);
    ASSERT_EQ(rkf.table.row_count(), ref.size());
    EXPECT_LT(error(tight), 1e-10);
    // every output row of the high-order run, not only the end, is within 1e-10 rad
    for (std::size_t r = 0; r < ref.size(); ++r)
        for (int c = 1; c <= 2; ++c)
            EXPECT_NEAR(rkf.table.columns[c][r], static_cast<double>(ref[r][c - 1]), 1e-10)
                << "row " << r << " column " << c;
}

TEST(Integrator, EveryMethodConservesTheDoublePendulumsEnergy) {
    for (Integrator m : kEvery) {
        if (!integrator_available(m)) continue;  // bdf, in a build without SUNDIALS
        const SimulationResult res = run_double_pendulum(m, 1e-12);
        const std::vector<double>& E = res.table.columns[res.table.column_index("energy")];
        double worst = 0;
        for (double e : E) worst = std::max(worst, std::abs(e - E.front()));
        // local errors of 1e-12 per step over 1e2 to 1e4 steps: 1e-10 to 1e-8 of E
        std::printf("%-15s energy drift %.2e J over 10 s in %zu steps\n",
                    std::string(to_string(m)).c_str(), worst, res.steps);
        EXPECT_LT(worst, 1e-7 * std::abs(E.front())) << to_string(m);
    }
}

TEST(Integrator, BdfFollowsAStiffSpringDamperToItsClosedForm) {
    if (!integrator_available(Integrator::bdf)) GTEST_SKIP() << "built without SUNDIALS CVODE";
    // m x'' + c x' + k x = 0 with m = 1, k = 1e6, c = 1e6 + 1: s^2 + c s + k = (s + 1)(s + 1e6),
    // two time constants a million apart; from x = 1, x' = 0:
    //   x(t) = A e^-t + B e^-1e6 t,  A + B = 1,  A + 1e6 B = 0
    SampleModel m = make_mass_spring_damper();
    SymbolTable& s = m.system.symbols();
    s.set_value(s.symbol("k"), 1e6);
    s.set_value(s.symbol("c"), 1e6 + 1);
    const double A = 1 / (1 - 1e-6), B = 1 - A;
    auto run = [&](Integrator method, double t_final) {
        SimulationRequest r;
        r.model = "stiff_spring_damper";
        r.coordinates = m.q;
        r.initial_values = {{m.q[0].symbol(), 1.0}};
        r.outputs = {{"x", m.q[0], "m"}, {"v", m.q[0].d(1), "m/s"}};
        r.options = {.t_final = t_final, .integrator = method, .output_step = 0.25,
                     .abs_tol = 1e-10, .rel_tol = 1e-10, .progress = false};
        return run_simulation(m.system, r);
    };
    const SimulationResult bdf = run(Integrator::bdf, 10.0);
    const Table& t = bdf.table;
    ASSERT_EQ(t.row_count(), 41u);
    for (std::size_t r = 0; r < t.row_count(); ++r) {
        const double time = t.columns[0][r];
        EXPECT_NEAR(t.columns[1][r], A * std::exp(-time) + B * std::exp(-1e6 * time), 1e-8)
            << "t = " << time;
        EXPECT_NEAR(t.columns[2][r], -A * std::exp(-time) - 1e6 * B * std::exp(-1e6 * time),
                    1e-8)
            << "t = " << time;
    }
    // the explicit method's steps follow the fast time constant (stability, not accuracy):
    // it needs more steps for 0.25 s than the implicit one for the whole 10 s
    const SimulationResult dp = run(Integrator::dopri5, 0.25);
    std::printf("stiff spring-damper: bdf %zu steps for 10 s, dopri5 %zu steps for 0.25 s\n",
                bdf.steps, dp.steps);
    EXPECT_GT(dp.steps, bdf.steps);
    EXPECT_LT(bdf.steps, 3000u);
}

TEST(Integrator, EveryMethodFindsTheRodsEllipticIntegralFallTimeByAnEvent) {
    // a uniform rod pinned at its end, released from horizontal, reaches the bottom after a
    // quarter period of amplitude 90 deg: K(1/sqrt 2) sqrt(I_O / (m g d)), I_O = m L^2 / 3
    const double expected = 1.8540746773013719 * std::sqrt((1.0 / 3.0) / (9.81 * 0.5));
    for (Integrator method : kEvery) {
        if (!integrator_available(method)) continue;  // bdf, in a build without SUNDIALS
        SampleModel rod = make_planar_chain(1);
        ex q = rod.q[0];
        SimulationRequest r;
        r.model = "rod";
        r.coordinates = rod.q;
        r.initial_values = {{q, kPi / 2}};
        r.events = {{"bottom", q - kPi, EventDirection::rising}};
        r.outputs = {{"q", q, "rad"}};
        r.options = {.t_final = 2.0, .integrator = method, .output_step = 0.1, .abs_tol = 1e-12,
                     .rel_tol = 1e-12, .progress = false};
        const SimulationResult res = run_simulation(rod.system, r);
        // BDF's order is at most 5 and its interpolant that of the step: looser, as it is
        const double tol = method == Integrator::bdf ? 1e-7 : 1e-9;
        EXPECT_EQ(res.stopped_by, "bottom") << to_string(method);
        EXPECT_NEAR(res.t_end, expected, tol) << to_string(method);
        EXPECT_NEAR(res.q_end[0], kPi, tol) << to_string(method);
        // rows at 0, 0.1, ..., 0.4 exactly, then the event row
        const Table& t = res.table;
        ASSERT_EQ(t.row_count(), 6u) << to_string(method);
        for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(t.columns[0][k], 0.1 * static_cast<double>(k));
        // the start of the fall: q'' = 3 g / (2 L) at horizontal, so,
        // q = pi/2 + (3 g / 4 L) t^2 + O(t^6) with L = 1 m
        EXPECT_NEAR(t.columns[1][1], kPi / 2 + 0.75 * 9.81 * 0.01 * 1.0, 1e-4) << to_string(method);
    }
}

// A build without SUNDIALS (ALEMBERT_WITH_SUNDIALS=OFF, or AUTO where it is missing) keeps the
// name and says, when bdf is asked for, how to get it.
TEST(Integrator, BdfIsThereOrSaysHowToGetIt) {
    EXPECT_EQ(parse_integrator("bdf"), Integrator::bdf);
    for (Integrator m : {Integrator::dopri5, Integrator::rkf78, Integrator::bulirsch_stoer})
        EXPECT_TRUE(integrator_available(m)) << to_string(m);
    SampleModel m = make_mass_spring_damper();
    SimulationRequest r;
    r.model = "msd";
    r.coordinates = m.q;
    r.initial_values = {{m.q[0].symbol(), 1.0}};
    r.options = {.t_final = 0.1, .integrator = Integrator::bdf, .progress = false};
    if (integrator_available(Integrator::bdf))
        EXPECT_NO_THROW(run_simulation(m.system, r));
    else
        EXPECT_THROW_MSG(run_simulation(m.system, r), ArgumentError, "libsundials-dev");
}

TEST(Integrator, BdfReportsASingularModelWithTheModelAndTheTime) {
    if (!integrator_available(Integrator::bdf)) GTEST_SKIP() << "built without SUNDIALS CVODE";
    // a massless particle: the mass matrix is singular at once
    SampleModel m = make_mass_spring_damper();
    SymbolTable& s = m.system.symbols();
    s.set_value(s.symbol("m"), 0.0);
    SimulationRequest r;
    r.model = "massless";
    r.coordinates = m.q;
    r.initial_values = {{m.q[0].symbol(), 1.0}};
    r.options = {.t_final = 1.0, .integrator = Integrator::bdf, .progress = false};
    EXPECT_THROW_MSG(run_simulation(m.system, r), SolveError, "massless");
}

}  // namespace
}  // namespace alembert
