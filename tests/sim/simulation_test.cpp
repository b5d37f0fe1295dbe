// SPDX-License-Identifier: MIT
// Forward simulation: energy of the triple pendulum, an elliptic-integral fall time found by an
// event, the inverse/forward round trip, a closed loop's drift, outputs and units.
#include "alembert/sim/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sim/inverse_dynamics.hpp"
#include "alembert/sim/motion.hpp"
#include "support/constants.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using test::kPi;

TEST(Simulation, TriplePendulumReleasedFromRestConservesEnergy) {
    // acceptance: zero torques, 5 s at tolerance 1e-12, energy to 1e-9 relative
    SampleModel m = make_triple_pendulum();
    SimulationRequest r;
    r.model = "triple_pendulum";
    r.coordinates = m.q;
    r.initial_values = {{m.q[0].symbol(), 0.3}, {m.q[1].symbol(), -0.8}, {m.q[2].symbol(), 1.2}};
    r.outputs = {{"qA", m.q[0], "deg"}};
    r.options = {.t_final = 5.0, .output_step = 0.01, .abs_tol = 1e-12, .rel_tol = 1e-12};
    SimulationResult result = run_simulation(m.system, r);
    const Table& t = result.table;
    ASSERT_EQ(t.names, (std::vector<std::string>{"t", "qA", "energy"}));
    EXPECT_EQ(t.units[2], "J");
    ASSERT_EQ(t.row_count(), 501u);
    EXPECT_DOUBLE_EQ(t.columns[0].back(), 5.0);
    const std::vector<double>& E = t.columns[2];
    // energy at rest, by hand: potential of the three mass centres
    const double q[3] = {0.3, -0.8, 1.2}, L[3] = {0.4182, 0.4165, 0.4896},
                 mass[3] = {6.51, 14.00, 47.46}, d[3] = {0.2371, 0.2362, 0.3065};
    double theta = 0, y = 0, V = 0;
    for (int k = 0; k < 3; ++k) {
        theta += q[k];
        V += mass[k] * 9.81 * (y + d[k] * std::cos(theta));
        y += L[k] * std::cos(theta);
    }
    EXPECT_NEAR(E.front(), V, 1e-9 * V);
    double worst = 0;
    for (double e : E) worst = std::max(worst, std::abs(e - V) / std::abs(V));
    EXPECT_LT(worst, 1e-9);
    std::printf("energy: largest relative change %.2e over 5 s in %zu steps\n", worst,
                result.steps);
    // it moved: the pendulum falls
    EXPECT_GT(std::abs(t.columns[1].back() - 0.3 * 180 / kPi), 10.0);
}

TEST(Simulation, ATreeRunsOnTheRecursionAndAgreesWithTheMassMatrixEquations) {
    // the triple pendulum with a motor law at each joint (a spring-damper servo and a constant
    // torque): run_simulation takes the recursive formation; simulate on Kane's M q'' = f with
    // the same laws substituted must give the same motion
    SampleModel m = make_triple_pendulum();
    const SymbolTable& s = m.system.symbols();
    exmap laws;
    laws[m.unknowns[0]] = -300 * (m.q[0].symbol() - 0.1) - 20 * m.q[0].d(1);
    laws[m.unknowns[1]] = -150 * m.q[1].symbol() - 10 * m.q[1].d(1) + 5 * sin(s.time());
    laws[m.unknowns[2]] = ex(12);
    SimulationRequest r;
    r.model = "servo";
    r.coordinates = m.q;
    r.inputs = laws;
    r.initial_values = {{m.q[0].symbol(), 0.3}, {m.q[1].symbol(), -0.8}, {m.q[2].symbol(), 1.2}};
    r.outputs = {{"T_A", m.unknowns[0], "N*m"}};
    r.options = {.t_final = 2.0, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12,
                 .progress = false};
    const SimulationResult tree = run_simulation(m.system, r);
    EXPECT_TRUE(tree.recursive);
    LinearSystem eqs = form_forward_equations(m.system, m.q);
    eqs.A = GiNaC::ex_to<GiNaC::matrix>(eqs.A.subs(laws));
    eqs.b = GiNaC::ex_to<GiNaC::matrix>(eqs.b.subs(laws));
    ForwardDynamics dense = compile_forward_dynamics(s, eqs, m.q, {}, "servo");
    OutputFunction none = compile_outputs(s, dense.layout(), {});
    const SimulationResult ref =
        simulate(dense, {0.3, -0.8, 1.2}, {0, 0, 0}, r.options, none);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(tree.q_end[i], ref.q_end[i], 1e-9) << i;
        EXPECT_NEAR(tree.qd_end[i], ref.qd_end[i], 1e-8) << i;
    }
    // the servo torque column is the law at the state of each row
    const Table& t = tree.table;
    EXPECT_NEAR(t.columns[1][0], -300 * (0.3 - 0.1), 1e-12);
}

TEST(Simulation, ARodFallsFromHorizontalToTheBottomInTheEllipticIntegralTime) {
    // a uniform rod pinned at its end, released from horizontal: the time to the bottom is a
    // quarter period of a pendulum of amplitude 90 deg, K(sin 45 deg) sqrt(I_O / (m g d)),
    // I_O = m L^2 / 3, d = L / 2, K(1/sqrt 2) = 1.8540746773013719
    SampleModel rod = make_planar_chain(1);
    ex q = rod.q[0];
    SimulationRequest r;
    r.model = "rod";
    r.coordinates = rod.q;
    r.initial_values = {{q, kPi / 2}};
    r.events = {{"bottom", q - kPi, EventDirection::rising}};
    r.outputs = {{"q", q, "deg"}, {"q'", rod.q[0].d(1), "deg/s"}};
    r.options = {.t_final = 2.0, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12};
    SimulationResult result = run_simulation(rod.system, r);
    const double expected = 1.8540746773013719 * std::sqrt((1.0 / 3.0) / (9.81 * 0.5));
    EXPECT_EQ(result.stopped_by, "bottom");
    EXPECT_NEAR(result.t_end, expected, 1e-9);
    EXPECT_NEAR(result.q_end[0], kPi, 1e-9);
    // outputs at 0, 0.1, ..., 0.4, then the event row
    const Table& t = result.table;
    ASSERT_EQ(t.row_count(), 6u);
    EXPECT_NEAR(t.columns[0][5], expected, 1e-9);
    EXPECT_NEAR(t.columns[1][5], 180.0, 1e-7);
    // speed at the bottom from energy: (1/2) I_O w^2 = m g d
    EXPECT_NEAR(t.columns[2][5], std::sqrt(2 * 9.81 * 0.5 / (1.0 / 3.0)) * 180 / kPi, 1e-6);
}

TEST(Simulation, TorquesOfAPrescribedMotionReproduceItForward) {
    // round trip: inverse dynamics of a prescribed motion, fed to forward simulation as a
    // torque history, gives the motion back to the integrator's tolerance. The motion swings
    // about the hanging pose (qA = pi), which is stable, so integration errors are not
    // amplified exponentially as they would be about the upright pose.
    SampleModel m = make_triple_pendulum();
    const SymbolTable& s = m.system.symbols();
    const ex t = s.time();
    PrescribedMotion motion(s, m.q,
                            {GiNaC::Pi + 0.2 * GiNaC::sin(2 * t), 0.3 * GiNaC::sin(3 * t),
                             0.4 * GiNaC::sin(t) * GiNaC::sin(t)});
    InverseDynamics id = compile_inverse_dynamics(m.system, m.q, m.unknowns, "triple_pendulum");
    ForwardDynamics fd = compile_forward_dynamics(m.system, m.q, m.unknowns, "triple_pendulum");
    InputFunction torques = [&](double time, const double*, const double*, double* T) {
        double q[3], qd[3], qdd[3];
        motion.calc_state(time, q, qd, qdd);
        id.calc_loads(time, q, qd, qdd, T);
    };
    std::vector<OutputSpec> specs;
    for (const TimeVariable& q : m.q) specs.push_back({q.name(), q, "rad"});
    OutputFunction out = compile_outputs(s, fd.layout(), specs);
    double q0[3], qd0[3], qdd0[3];
    motion.calc_state(0, q0, qd0, qdd0);
    SimulationOptions opt{.t_final = 2.0, .output_step = 0.05, .abs_tol = 1e-11, .rel_tol = 1e-11};
    SimulationResult result = simulate(fd, {q0, q0 + 3}, {qd0, qd0 + 3}, opt, out, {}, torques);
    const Table& tab = result.table;
    double worst = 0;
    for (std::size_t row = 0; row < tab.row_count(); ++row) {
        double q[3], qd[3], qdd[3];
        motion.calc_state(tab.columns[0][row], q, qd, qdd);
        for (int i = 0; i < 3; ++i)
            worst =
                std::max(worst, std::abs(tab.columns[static_cast<std::size_t>(i) + 1][row] - q[i]));
    }
    EXPECT_LT(worst, 100 * opt.abs_tol);
    std::printf("round trip: largest coordinate error %.2e rad over 2 s\n", worst);
}

TEST(Simulation, AClosedLoopReportsItsConstraintDrift) {
    // the four-bar falling freely from a closed pose at rest: drift columns for both loop
    // equations, which stay near zero (the road-map holds the loop at the acceleration level)
    SampleModel fb = make_four_bar();
    const double LN = 1, LA = 0.4, LB = 1.2, LC = 0.8, qA = 1.0;
    const double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
    const double dx = LN - ax, dy = -ay, dd = std::hypot(dx, dy);
    const double along = (LB * LB - LC * LC + dd * dd) / (2 * dd),
                 h = std::sqrt(LB * LB - along * along);
    const double px = ax + along * dx / dd - h * dy / dd, py = ay + along * dy / dd + h * dx / dd;
    SimulationRequest r;
    r.model = "four_bar";
    r.coordinates = fb.q;
    r.constraint_forces = {fb.unknowns[1], fb.unknowns[2]};
    r.initial_values = {{fb.q[0].symbol(), qA},
                        {fb.q[1].symbol(), std::atan2(py - ay, px - ax) - qA},
                        {fb.q[2].symbol(), std::atan2(py, px - LN)}};
    r.outputs = {{"qA", fb.q[0], "deg"}};
    r.options = {.t_final = 1.0, .output_step = 0.05, .abs_tol = 1e-10, .rel_tol = 1e-10};
    SimulationResult result = run_simulation(fb.system, r);
    const Table& t = result.table;
    ASSERT_EQ(t.names.size(), 5u);  // t, qA, energy, drift_loop_x, drift_loop_y
    EXPECT_EQ(t.names[3], "drift_loop_x");
    EXPECT_EQ(t.names[4], "drift_loop_y");
    for (std::size_t c : {3u, 4u})
        for (double v : t.columns[c]) EXPECT_LT(std::abs(v), 1e-7);
    // the loop's pin force does no work: energy is kept too
    const std::vector<double>& E = t.columns[2];
    for (double e : E) EXPECT_NEAR(e, E.front(), 1e-6 * std::abs(E.front()) + 1e-8);
    EXPECT_GT(std::abs(t.columns[1].back() - t.columns[1].front()), 1.0);  // it moved
}

TEST(Simulation, AnInitialStateOffTheLoopIsRefusedNotMovedOntoIt) {
    // the four-bar at qA = 1 with the coupler and rocker at zero: the pin is apart by metres
    SampleModel fb = make_four_bar();
    SimulationRequest r;
    r.model = "four_bar";
    r.coordinates = fb.q;
    r.constraint_forces = {fb.unknowns[1], fb.unknowns[2]};
    r.initial_values = {{fb.q[0].symbol(), 1.0}};
    r.constraint_units = {{"loop_x", "m"}};
    // loop_x = x(B_tip) - x(C_tip) = LA cos 1 + LB cos 1 - LN - LC = 1.6 cos 1 - 1.8
    EXPECT_THROW_MSG(run_simulation(fb.system, r), ArgumentError,
                     "run_simulation('four_bar'): the initial state violates the configuration "
                     "constraint 'loop_x': its residual is -0.935516 m at t = 0 s, beyond the "
                     "tolerance 1e-06 m");
}

TEST(Simulation, TooManyOutputRowsAreRefusedBeforeTheRun) {
    SampleModel rod = make_planar_chain(1);
    SimulationRequest r;
    r.model = "rod";
    r.coordinates = rod.q;
    r.options = {.t_final = 10, .output_step = 1e-9};
    EXPECT_THROW_MSG(run_simulation(rod.system, r), ArgumentError,
                     "simulate('rod'): the output step 1e-09 s from t = 0 to 10 s asks for "
                     "10000000001 rows, more than the limit of 1000000 rows "
                     "(SimulationOptions::max_output_rows; in a script, output limit N)");
    r.options = {.t_final = 1, .output_step = 0.001, .max_output_rows = 500};
    EXPECT_THROW_MSG(run_simulation(rod.system, r), ArgumentError, "asks for 1001 rows");
    r.options.max_output_rows = 1001;
    EXPECT_EQ(run_simulation(rod.system, r).table.row_count(), 1001u);
}

TEST(Simulation, BadRequestsAreNamed) {
    SampleModel rod = make_planar_chain(1);
    SimulationRequest r;
    r.model = "rod";
    r.coordinates = rod.q;
    r.outputs = {{"q", rod.q[0], "furlong"}};
    EXPECT_THROW_MSG(run_simulation(rod.system, r), ArgumentError,
                     "compile_outputs(): output 'q': unknown unit 'furlong'");
    r.outputs = {};
    r.options.t_final = -1;
    EXPECT_THROW_MSG(run_simulation(rod.system, r), ArgumentError,
                     "simulate('rod'): the final time -1 s must follow the initial time 0 s");
    r.options.t_final = 1;
    r.initial_values = {{rod.unknowns[0], 1.0}};
    EXPECT_THROW_MSG(run_simulation(rod.system, r), ArgumentError,
                     "an initial value is given for 'T1', which is neither a coordinate");
}

}  // namespace
}  // namespace alembert
