// SPDX-License-Identifier: MIT
// Simulation of Kane's equations in generalized speeds with motion constraints, against hand
// derivations: the rolling disk keeps its energy, turns steadily at the lean, spin and turn
// rates of Euler's equations about its mass centre and rolls straight at r w; the Chaplygin
// sled follows its closed-form speed and turn rate; a double pendulum in absolute angular
// speeds moves as the same model simulated in q''; the Whipple bicycle's weave grows at
// Meijaard et al.'s rate; the errors a user can meet.
#include "alembert/sim/speed_simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>

#include "alembert/error.hpp"
#include "alembert/mech/rigid_body.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"
#include "support/meijaard2007.hpp"

namespace alembert {
namespace {

constexpr double kDiskMass = 2.0, kDiskRadius = 0.3, kGravity = 9.81;

// The rolling disk of examples/rolling_disk/model.alb in speeds (make_rolling_disk) with its
// Kane equations; with `torque`, a torque T Ly on D about its axle (a load measure).
struct RollingDisk {
    SampleNonholonomicModel model{System("N"), {}, {}, {}, {}, {}, {}};
    KaneEquations kane{};
};

RollingDisk rolling_disk_with_kane(bool torque = false) {
    RollingDisk out{make_rolling_disk(kDiskMass, kDiskRadius, kGravity, torque)};
    SampleNonholonomicModel& d = out.model;
    System& sys = d.system;
    std::vector<ex> u;
    for (const TimeVariable& ui : d.u) u.push_back(ui.symbol());
    out.kane = form_kane_equations(sys, KaneOptions{.coordinates = d.q,
                                                    .speeds = u,
                                                    .kinematic_equations = d.kinematic_equations,
                                                    .motion_constraints = d.motion_constraints,
                                                    .dependent_speeds = d.dependent_speeds});
    return out;
}

std::size_t column(const Table& t, const std::string& name) { return t.column_index(name); }

double largest_change(const std::vector<double>& v) {
    double worst = 0;
    for (double x : v) worst = std::max(worst, std::abs(x - v.front()));
    return worst;
}

TEST(SpeedSimulation, RollingDiskKeepsItsEnergyAndItsContactAtRest) {
    RollingDisk disk = rolling_disk_with_kane();
    const auto& q = disk.model.q;
    const auto& u = disk.model.u;
    SimulationRequest r;
    r.model = "rolling_disk";
    // leaning and wobbling: lean 0.3 rad, lean rate 0.4, spin 6, turn 1 (rad/s)
    r.initial_values = {{q[1].symbol(), 0.3}, {u[0].symbol(), 0.4}, {u[1].symbol(), 6.0},
                        {u[2].symbol(), 1.0}};
    r.outputs = {{"q2", q[1].symbol(), ""}, {"u4", u[3].symbol(), ""}, {"u5", u[4].symbol(), ""}};
    r.options = {.t_final = 4.0, .output_step = 0.01, .abs_tol = 1e-11, .rel_tol = 1e-11};
    const SimulationResult res = run_speed_simulation(disk.model.system, disk.kane, r);
    const Table& t = res.table;
    ASSERT_EQ(t.names, (std::vector<std::string>{"t", "q2", "u4", "u5", "energy", "drift_motion_1",
                                                 "drift_motion_2"}));
    ASSERT_EQ(t.row_count(), 401u);
    // the energy at the start by hand: v_cm = w x (r Lz) with w = (u1, u2, u3) in L, so
    // |v_cm|^2 = r^2 (u1^2 + u2^2); T = m |v_cm|^2 / 2 + (A u1^2 + C u2^2 + A u3^2) / 2 with
    // A = m r^2/4, C = m r^2/2; V = m g r cos(q2)
    const double m = kDiskMass, rr = kDiskRadius, A = m * rr * rr / 4, C = m * rr * rr / 2;
    const double E0 = m * rr * rr * (0.16 + 36) / 2 + (A * 0.16 + C * 36 + A * 1) / 2 +
                      m * kGravity * rr * std::cos(0.3);
    const std::vector<double>& E = t.columns[column(t, "energy")];
    EXPECT_NEAR(E.front(), E0, 1e-12 * E0);
    EXPECT_LT(largest_change(E) / E0, 1e-9);
    std::printf("rolling disk: energy's largest relative change %.2e over 4 s in %zu steps\n",
                largest_change(E) / E0, res.steps);
    // the contact point of D at rest: the motion constraints' residuals at rounding
    for (const char* c : {"drift_motion_1", "drift_motion_2"})
        for (double v : t.columns[column(t, c)]) EXPECT_LT(std::abs(v), 1e-12) << c;
    // it moved: the lean changes and the contact travels
    double lean_range = 0;
    for (double v : t.columns[1]) lean_range = std::max(lean_range, std::abs(v - 0.3));
    EXPECT_GT(lean_range, 0.01);
    EXPECT_GT(std::hypot(res.q_end[3], res.q_end[4]), 0.5);
    EXPECT_EQ(res.u_end.size(), 3u);
    EXPECT_EQ(res.qd_end.size(), 5u);
}

TEST(SpeedSimulation, RollingDiskTurnsSteadilyAtTheRatesOfEulersEquations) {
    // Steady turning at lean theta and turn rate W (q1' = W, q2' = 0): w = (0, u2, W cos theta)
    // in L, and L turns at w_L = (0, W sin theta, W cos theta). The mass centre moves at
    // v = w x (r Lz) = r u2 Lx, so a = r u2 W (cos theta Ly - sin theta Lz). About the mass
    // centre, dH/dt = w_L x (I . w) = W (A u3 sin theta - C u2 cos theta) Lx must equal
    // (-r Lz) x F with F = m a + m g Nz, Nz = sin theta Ly + cos theta Lz: r F_y Lx. Hence
    //   W^2 cos(theta) sin(theta) - 6 W u2 cos(theta) - 4 g sin(theta) / r = 0
    // (A = m r^2/4, C = m r^2/2), u2 = (W^2 cos sin - 4 g sin / r) / (6 W cos). The ground
    // contact P moves at r (u2 - W sin theta) Lx: a circle of radius R = r (u2 - W sin) / W.
    RollingDisk disk = rolling_disk_with_kane();
    const auto& q = disk.model.q;
    const auto& u = disk.model.u;
    const double theta = 0.25, W = -4.0, s = std::sin(theta), c = std::cos(theta);
    const double u2 = (W * W * c * s - 4 * kGravity * s / kDiskRadius) / (6 * W * c);
    SimulationRequest r;
    r.model = "steady_turn";
    r.initial_values = {{q[1].symbol(), theta}, {u[1].symbol(), u2}, {u[2].symbol(), W * c}};
    r.outputs = {{"q1", q[0].symbol(), ""}, {"q2", q[1].symbol(), ""}, {"x", q[3].symbol(), ""},
                 {"y", q[4].symbol(), ""}, {"u2", u[1].symbol(), ""}, {"u3", u[2].symbol(), ""}};
    r.options = {.t_final = 2.0, .output_step = 0.05, .abs_tol = 1e-12, .rel_tol = 1e-12};
    const SimulationResult res = run_speed_simulation(disk.model.system, disk.kane, r);
    const Table& t = res.table;
    const double R = kDiskRadius * (u2 - W * s) / W;
    double worst = 0;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double tk = t.columns[0][k];
        worst = std::max({worst, std::abs(t.columns[1][k] - W * tk), std::abs(t.columns[2][k] - theta),
                          std::abs(t.columns[3][k] - R * std::sin(W * tk)),
                          std::abs(t.columns[4][k] - R * (1 - std::cos(W * tk))),
                          std::abs(t.columns[5][k] - u2), std::abs(t.columns[6][k] - W * c)});
    }
    EXPECT_LT(worst, 1e-8);
    std::printf("steady turn: largest departure from the closed form %.2e over 2 s\n", worst);
}

TEST(SpeedSimulation, UprightDiskRollsStraightAtItsRadiusTimesItsSpin) {
    // upright (q2 = 0) with spin w about the axle only: x = r w t, the spin angle w t
    RollingDisk disk = rolling_disk_with_kane();
    const auto& q = disk.model.q;
    const auto& u = disk.model.u;
    const double w = 7.0;
    SimulationRequest r;
    r.initial_values = {{u[1].symbol(), w}};
    r.outputs = {{"q3", q[2].symbol(), ""}, {"x", q[3].symbol(), ""}, {"y", q[4].symbol(), ""}};
    r.options = {.t_final = 1.5, .output_step = 0.5};
    const SimulationResult res = run_speed_simulation(disk.model.system, disk.kane, r);
    const Table& t = res.table;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double tk = t.columns[0][k];
        EXPECT_NEAR(t.columns[1][k], w * tk, 1e-9);
        EXPECT_NEAR(t.columns[2][k], kDiskRadius * w * tk, 1e-9);
        EXPECT_NEAR(t.columns[3][k], 0.0, 1e-12);
    }
}

// The Chaplygin sled: a body B on the plane, heading th about Nz, resting on a knife edge at
// P = x Nx + y Ny that cannot slide along By; its mass centre a ahead of P along Bx. Speeds
// u1 = v (P's speed along Bx), u2 = th', u3 (P's speed along By) made 0 by the constraint.
struct Sled {
    System system{"N"};
    std::vector<TimeVariable> q, u;
    KaneEquations kane{};
};

constexpr double kSledMass = 3.0, kSledInertia = 0.2, kSledOffset = 0.4;

std::unique_ptr<Sled> make_sled() {
    auto out = std::make_unique<Sled>();
    System& sys = out->system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex m = s.add_constant("m", kSledMass), I = s.add_constant("I", kSledInertia),
       a = s.add_constant("a", kSledOffset);
    for (const char* n : {"x", "y", "th"}) out->q.push_back(s.add_variable(n, 1));
    for (const char* n : {"u1", "u2", "u3"}) out->u.push_back(s.add_variable(n, 1));
    RigidBody& B = sys.add_rigid_body("B");
    B.body_frame().orient_axis(N, Axis::z, out->q[2].symbol());
    Point& P = sys.add_point("P", &B);
    P.set_pos(sys.origin(), out->q[0].symbol() * N.x() + out->q[1].symbol() * N.y());
    B.cm().set_pos(P, a * B.body_frame().x());
    B.set_mass(m);
    B.set_inertia(B.cm(), I, I, I);
    const Vector v = P.vel_in(N);
    const Frame& F = B.body_frame();
    std::vector<ex> u;
    for (const TimeVariable& ui : out->u) u.push_back(ui.symbol());
    out->kane = form_kane_equations(
        sys, KaneOptions{.coordinates = out->q,
                         .speeds = u,
                         .kinematic_equations = {u[0] - dot(v, F.x()), u[1] - out->q[2].d(1),
                                                 u[2] - dot(v, F.y())},
                         .motion_constraints = {dot(v, F.y())},
                         .dependent_speeds = {u[2]}});
    return out;
}

TEST(SpeedSimulation, ChaplyginSledFollowsItsClosedForm) {
    // With J = I + m a^2 (Neimark & Fufaev; by hand: m (v' - a w^2) = 0 along Bx, and about
    // the mass centre I w' = -a lambda with lambda = m (v w + a w') the knife's force):
    //   v' = a w^2,  J w' = -m a v w.
    // The energy m v^2 + J w^2 = m V^2 is kept, so v' = k (V^2 - v^2) with k = m a / J:
    //   v = V tanh(k V t + c0), c0 = atanh(v0 / V),  w = w0 cosh(c0) / cosh(k V t + c0).
    auto sled = make_sled();
    const double v0 = -0.5, w0 = 2.0, m = kSledMass, a = kSledOffset;
    const double J = kSledInertia + m * a * a, V = std::sqrt(v0 * v0 + J * w0 * w0 / m), k = m * a / J;
    const double c0 = std::atanh(v0 / V);
    SimulationRequest r;
    r.model = "sled";
    r.initial_values = {{sled->u[0].symbol(), v0}, {sled->u[1].symbol(), w0}};
    const ex u1 = sled->u[0].symbol(), u2 = sled->u[1].symbol();
    // u1' is the rate of an independent speed, u3' of the dependent one (0: it stays 0)
    r.outputs = {{"v", u1, ""}, {"w", u2, ""}, {"vdot", sled->u[0].d(1), ""},
                 {"u3dot", sled->u[2].d(1), ""}};
    r.options = {.t_final = 3.0, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12};
    const SimulationResult res = run_speed_simulation(sled->system, sled->kane, r);
    const Table& t = res.table;
    ASSERT_EQ(t.names, (std::vector<std::string>{"t", "v", "w", "vdot", "u3dot", "energy", "drift_motion_1"}));
    double worst = 0;
    for (std::size_t i = 0; i < t.row_count(); ++i) {
        const double ti = t.columns[0][i];
        const double v = V * std::tanh(k * V * ti + c0), w = w0 * std::cosh(c0) / std::cosh(k * V * ti + c0);
        worst = std::max({worst, std::abs(t.columns[1][i] - v), std::abs(t.columns[2][i] - w),
                          std::abs(t.columns[3][i] - a * w * w), std::abs(t.columns[4][i])});
    }
    EXPECT_LT(worst, 1e-9);
    std::printf("Chaplygin sled: largest departure from the closed form %.2e over 3 s\n", worst);
    // it ends moving forward (v -> V), turning ever slower
    EXPECT_GT(t.columns[1].back(), 0.9 * V);
    // the energy (m v^2 + J w^2)/2 is kept, and the constraint holds
    const std::vector<double>& E = t.columns[5];
    EXPECT_NEAR(E.front(), (m * v0 * v0 + J * w0 * w0) / 2, 1e-12);
    EXPECT_LT(largest_change(E), 1e-10);
}

TEST(SpeedSimulation, DoublePendulumInAbsoluteSpeedsMovesAsInTheCoordinatesRates) {
    // two rods in a vertical plane: A about N by qA, B about A by qB; speeds wA = qA' and
    // wB = qA' + qB' (B's angular velocity in N). The same model simulated in q'' is the
    // reference: the same end state to the tolerance of the integration.
    System sys("N");
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex L = s.add_constant("L", 0.7), m = s.add_constant("m", 1.3), g = s.add_constant("g", 9.81);
    TimeVariable qA = s.add_variable("qA", 2), qB = s.add_variable("qB", 2);
    TimeVariable wA = s.add_variable("wA", 1), wB = s.add_variable("wB", 1);
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    A.body_frame().orient_axis(N, Axis::z, qA.symbol());
    B.body_frame().orient_axis(A.body_frame(), Axis::z, qB.symbol());
    A.cm().set_pos(sys.origin(), -L / 2 * A.body_frame().y());
    Point& joint = sys.add_point("J", &A);
    joint.set_pos(sys.origin(), -L * A.body_frame().y());
    B.cm().set_pos(joint, -L / 2 * B.body_frame().y());
    for (RigidBody* b : {&A, &B}) {
        b->set_mass(m);
        b->set_inertia(b->cm(), m * L * L / 12, 0, m * L * L / 12);
    }
    sys.set_gravity(-g * N.y());
    const KaneEquations kane = form_kane_equations(
        sys, KaneOptions{.coordinates = {qA, qB},
                         .speeds = {wA.symbol(), wB.symbol()},
                         .kinematic_equations = {wA.symbol() - qA.d(1), wB.symbol() - qA.d(1) - qB.d(1)}});
    SimulationRequest r;
    r.model = "double_pendulum";
    r.coordinates = {qA, qB};
    r.options = {.t_final = 3.0, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12};
    r.outputs = {{"qA", qA.symbol(), ""}, {"qB", qB.symbol(), ""}};
    SimulationRequest in_rates = r;
    in_rates.initial_values = {{qA.symbol(), 1.0}, {qB.symbol(), -0.5}, {qA.d(1), 0.3}, {qB.d(1), 0.9}};
    r.initial_values = {{qA.symbol(), 1.0}, {qB.symbol(), -0.5}, {wA.symbol(), 0.3}, {wB.symbol(), 1.2}};
    const SimulationResult plain = run_simulation(sys, in_rates);
    const SimulationResult speeds = run_speed_simulation(sys, kane, r);
    ASSERT_EQ(plain.table.row_count(), speeds.table.row_count());
    double worst = 0;
    for (std::size_t c = 1; c < 3; ++c)
        for (std::size_t k = 0; k < plain.table.row_count(); ++k)
            worst = std::max(worst, std::abs(plain.table.columns[c][k] - speeds.table.columns[c][k]));
    EXPECT_LT(worst, 1e-8);
    EXPECT_NEAR(speeds.qd_end[0], plain.qd_end[0], 1e-8);
    EXPECT_NEAR(speeds.qd_end[1], plain.qd_end[1], 1e-8);
    EXPECT_NEAR(speeds.u_end[1], plain.qd_end[0] + plain.qd_end[1], 1e-8);
    // chaotic enough to mean something: the angles moved
    EXPECT_GT(std::abs(speeds.q_end[1] + 0.5), 0.1);
    // both runs keep the energy
    const Table& t = speeds.table;
    EXPECT_LT(largest_change(t.columns[t.column_index("energy")]), 1e-9);
}

TEST(SpeedSimulation, WhippleBicyclesWeaveGrowsAtTheBenchmarkRate) {
    // At 3 m/s the benchmark bicycle's weave is unstable, lambda = 1.70675605663975 +-
    // 2.31582447384325 i (Meijaard et al. 2007, Table 2); the capsize (-2.63) and castering
    // (-10.35) modes decay. Released upright with a tiny lean rate, the motion stays linear and
    // after 2.5 s is the weave alone (the others below 1e-4 of it), so one weave period
    // T = 2 pi / omega later every state scales by exp(sigma T).
    SampleNonholonomicModel bike = make_whipple_bicycle();
    std::vector<ex> u;
    for (const TimeVariable& ui : bike.u) u.push_back(ui.symbol());
    const KaneEquations kane = form_kane_equations(
        bike.system, KaneOptions{.coordinates = bike.q,
                                 .speeds = u,
                                 .kinematic_equations = bike.kinematic_equations,
                                 .motion_constraints = bike.motion_constraints,
                                 .dependent_speeds = bike.dependent_speeds,
                                 .simplify = false});
    const std::complex<double> weave = test::kMeijaardTable2[3].eig[2];
    ASSERT_EQ(test::kMeijaardTable2[3].v, 3.0);
    const double sigma = weave.real(), omega = std::abs(weave.imag()), T = 2 * std::acos(-1.0) / omega;
    SimulationRequest r;
    r.model = "bicycle";
    r.initial_values = {{u[2], 3.0 / 0.3}, {u[1], 1e-6}};  // rear wheel at v / r_R; lean rate
    r.outputs = {{"q2", bike.q[1].symbol(), ""}, {"q5", bike.q[4].symbol(), ""}, {"u2", u[1], ""},
                 {"u5", u[4], ""}};
    r.options = {.t_final = 2.5 + T, .output_times = {2.5, 2.5 + T}, .abs_tol = 1e-14, .rel_tol = 1e-12};
    const SimulationResult res = run_speed_simulation(bike.system, kane, r);
    const Table& t = res.table;
    ASSERT_EQ(t.row_count(), 2u);
    // the ratio of the largest state over the period
    std::size_t c = 1;
    for (std::size_t k = 2; k <= 4; ++k)
        if (std::abs(t.columns[k][0]) > std::abs(t.columns[c][0])) c = k;
    const double ratio = t.columns[c][1] / t.columns[c][0];
    EXPECT_NEAR(ratio / std::exp(sigma * T), 1.0, 1e-3) << t.names[c];
    std::printf("bicycle at 3 m/s: growth over a weave period %.6g, exp(sigma T) = %.6g\n", ratio,
                std::exp(sigma * T));
    // the motion stays small (linear): the lean below 0.01 rad at the end
    EXPECT_LT(std::abs(res.q_end[1]), 1e-2);
    EXPECT_GT(std::abs(res.q_end[1]), 1e-6);
}

TEST(SpeedSimulation, ATorqueThatDoesWorkLeavesTheEnergyColumnOut) {
    RollingDisk disk = rolling_disk_with_kane(/*torque=*/true);
    const SymbolTable& s = disk.model.system.symbols();
    SimulationRequest r;
    r.inputs = {{s.symbol("T"), ex(0.05)}};
    r.initial_values = {{disk.model.u[1].symbol(), 3.0}};
    r.outputs = {{"u2", disk.model.u[1].symbol(), ""}};
    r.options = {.t_final = 1.0, .output_step = 0.5};
    const SimulationResult res = run_speed_simulation(disk.model.system, disk.kane, r);
    EXPECT_EQ(res.table.names, (std::vector<std::string>{"t", "u2", "drift_motion_1", "drift_motion_2"}));
    // upright, the torque about the axle spins it up: (C + m r^2) u2' = T
    const double C = kDiskMass * kDiskRadius * kDiskRadius / 2;
    EXPECT_NEAR(res.table.columns[1].back(), 3.0 + 0.05 / (C + kDiskMass * kDiskRadius * kDiskRadius), 1e-9);
}

TEST(SpeedSimulation, RefusesWhatItCannotTakeByName) {
    RollingDisk disk = rolling_disk_with_kane(/*torque=*/true);
    const auto& u = disk.model.u;
    const SymbolTable& s = disk.model.system.symbols();
    SimulationRequest r;
    r.model = "disk";
    r.options = {.t_final = 0.1, .output_step = 0.05};
    // a dependent speed given that disagrees with the constraints: upright, spin 2, so u4 = 0.6
    r.initial_values = {{u[1].symbol(), 2.0}, {u[3].symbol(), 1.0}};
    EXPECT_THROW_MSG(run_speed_simulation(disk.model.system, disk.kane, r), ArgumentError,
                     "the initial value 1 of 'u4' disagrees with 0.6, its value from the motion constraints");
    // the value it has is accepted
    r.initial_values = {{u[1].symbol(), 2.0}, {u[3].symbol(), 0.6}};
    EXPECT_NO_THROW(run_speed_simulation(disk.model.system, disk.kane, r));
    // a load measure without an input read by an output
    r.outputs = {{"T", s.symbol("T"), ""}};
    EXPECT_THROW_MSG(run_speed_simulation(disk.model.system, disk.kane, r), ArgumentError,
                     "reads the load measure 'T', which Kane's equations in generalized speeds do not determine");
    r.outputs.clear();
    // equations without chosen speeds
    KaneEquations plain = disk.kane;
    plain.kinematic_equations.clear();
    EXPECT_THROW(run_speed_simulation(disk.model.system, plain, r), ArgumentError);
    KaneEquations aux = disk.kane;
    aux.auxiliary_speeds = {u[0].symbol()};
    EXPECT_THROW_MSG(run_speed_simulation(disk.model.system, aux, r), ArgumentError,
                     "auxiliary speeds must each have their auxiliary equation and be none of the speeds");
}

TEST(SpeedSimulation, DeclaredConfigurationConstraintIsReportedCheckedAtTheStartAndWatched) {
    // A particle on a rod of length L about N_o in Cartesian coordinates x, y with speeds
    // ux = x', uy = y' and the rod's rate x ux + y uy = 0 solved for uy; the rod itself
    // declared as a configuration constraint: its drift is a column, and an initial state off
    // the rod is refused.
    System sys("N");
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex L = s.add_constant("L", 1.2), m = s.add_constant("m", 0.5), g = s.add_constant("g", 9.81);
    TimeVariable x = s.add_variable("x", 1), y = s.add_variable("y", 1);
    TimeVariable ux = s.add_variable("ux", 1), uy = s.add_variable("uy", 1);
    Particle& P = sys.add_particle("P");
    P.point().set_pos(sys.origin(), x.symbol() * N.x() + y.symbol() * N.y());
    P.set_mass(m);
    sys.set_gravity(-g * N.y());
    sys.add_configuration_constraint("rod", x.symbol() * x.symbol() + y.symbol() * y.symbol() - L * L);
    const KaneEquations kane = form_kane_equations(
        sys, KaneOptions{.coordinates = {x, y},
                         .speeds = {ux.symbol(), uy.symbol()},
                         .kinematic_equations = {ux.symbol() - x.d(1), uy.symbol() - y.d(1)},
                         .motion_constraints = {x.symbol() * ux.symbol() + y.symbol() * uy.symbol()},
                         .dependent_speeds = {uy.symbol()}});
    SimulationRequest r;
    r.model = "rod";
    const double th = 0.6;  // from the downward vertical
    r.initial_values = {{x.symbol(), 1.2 * std::sin(th)}, {y.symbol(), -1.2 * std::cos(th)}};
    r.options = {.t_final = 1.0, .output_step = 0.1, .abs_tol = 1e-11, .rel_tol = 1e-11};
    r.outputs = {{"x", x.symbol(), ""}};
    const SimulationResult res = run_speed_simulation(sys, kane, r);
    const Table& t = res.table;
    ASSERT_EQ(t.names, (std::vector<std::string>{"t", "x", "energy", "drift_motion_1", "drift_rod"}));
    EXPECT_LT(largest_change(t.columns[4]), 1e-7);
    // the pendulum's period: released at 0.6 rad it swings back to x = 1.2 sin(0.6) after
    // T = 4 sqrt(L/g) K(sin(th/2)) = 2.2798... s; at 1 s (before half a period, 1.14 s) it is
    // on the other side
    EXPECT_LT(t.columns[1].back(), 0.0);
    // loose error tolerances let the rod's length drift (only its rate is enforced): with a
    // tight constraint tolerance the run stops, naming the constraint
    r.options.abs_tol = r.options.rel_tol = 1e-4;
    r.options.constraint_tolerance = 1e-9;
    EXPECT_THROW_MSG(run_speed_simulation(sys, kane, r), SolveError,
                     "the residual of the configuration constraint 'rod' grew to");
    // off the rod at the start
    r.initial_values[x.symbol()] = 1.0;
    EXPECT_THROW_MSG(run_speed_simulation(sys, kane, r), ArgumentError,
                     "the initial state violates the configuration constraint 'rod'");
}

}  // namespace
}  // namespace alembert
