// SPDX-License-Identifier: MIT
// Numeric inverse dynamics: the hand-written recursion, statics by hand, solved and unsolved
// forms, and errors by name.
#include "alembert/sim/inverse_dynamics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "alembert/sim/inverse_analysis.hpp"
#include "alembert/mech/sample_models.hpp"
#include "planar_chain_reference.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

TEST(InverseDynamics, PlanarChainsMatchTheHandWrittenNewtonEulerRecursion) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-2.0, 2.0);
    for (int n : {1, 3, 7}) {
        SampleModel chain = make_planar_chain(n);
        InverseDynamics id =
            compile_inverse_dynamics(chain.system, chain.q, chain.unknowns, "chain");
        EXPECT_TRUE(id.solved()) << "a road-map row per torque leaves no solve for run time";
        bench::PlanarChainReference reference(n);
        const auto un = static_cast<std::size_t>(n);
        std::vector<double> q(un), qd(un), qdd(un), ours(un), theirs(un);
        for (int trial = 0; trial < 10; ++trial) {
            for (std::size_t i = 0; i < un; ++i)
                q[i] = angle(rng), qd[i] = rate(rng), qdd[i] = rate(rng);
            id.calc_loads(0.0, q.data(), qd.data(), qdd.data(), ours.data());
            reference.inverse_dynamics(q.data(), qd.data(), qdd.data(), theirs.data());
            for (std::size_t i = 0; i < un; ++i)
                EXPECT_NEAR(ours[i], theirs[i], 1e-12 * (1 + std::abs(theirs[i])))
                    << "n = " << n << ", joint " << i + 1;
        }
    }
}

TEST(InverseDynamics, TreesUseTheRecursiveRowsAndAgreeWithThePlannedRoadmap) {
    // a tree with one motor torque per coordinate takes form_tree_equations' rows; the loads
    // are those of the planned road-map's rows, compiled here as before, at random states
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-1.5, 1.5);
    struct Case {
        const char* name;
        SampleModel model;
    };
    Case cases[] = {{"arm", make_kuka_iiwa14()}, {"spatial chain", make_n_link_pendulum(4, ChainKind::spatial)}};
    for (Case& c : cases) {
        const System& sys = c.model.system;
        InverseDynamics tree = compile_inverse_dynamics(sys, c.model.q, c.model.unknowns, c.name);
        const std::vector<RoadmapRow> rows = plan_roadmap(sys, c.model.q, c.model.unknowns, Analysis::dynamics);
        InverseDynamics planned = compile_inverse_dynamics(
            sys.symbols(), form_linear_system(residuals_of(rows), c.model.unknowns), c.model.q, c.name);
        EXPECT_TRUE(tree.solved()) << c.name << ": each motor torque enters its own rows only";
        EXPECT_LT(tree.function().operation_count, planned.function().operation_count)
            << c.name << ": the recursive rows were not used";
        const std::size_t n = c.model.q.size();
        std::vector<double> q(n), qd(n), qdd(n), a(n), b(n);
        for (int trial = 0; trial < 10; ++trial) {
            for (std::size_t i = 0; i < n; ++i) q[i] = value(rng), qd[i] = value(rng), qdd[i] = value(rng);
            tree.calc_loads(0.0, q.data(), qd.data(), qdd.data(), a.data());
            planned.calc_loads(0.0, q.data(), qd.data(), qdd.data(), b.data());
            double scale = 1;
            for (double x : b) scale = std::max(scale, std::abs(x));
            for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(a[i], b[i], 1e-12 * scale) << c.name << ", load " << i;
        }
    }
}

TEST(InverseDynamics, TriplePendulumHoldsAStillPoseWithItsWeightMoments) {
    // at rest, each joint torque balances the weight of the segments above it:
    // T_j = -sum_{k >= j} m_k g (x_k - x_j), x horizontal positions (first principles)
    SampleModel m = make_triple_pendulum();
    InverseDynamics id = compile_inverse_dynamics(m.system, m.q, m.unknowns, "triple_pendulum");
    const double L[3] = {0.4182, 0.4165, 0.4896}, mass[3] = {6.51, 14.00, 47.46},
                 d[3] = {0.2371, 0.2362, 0.3065}, g = 9.81;
    const double q[3] = {-0.3, 1.4, -1.9}, zero[3] = {0, 0, 0};
    double T[3];
    id.calc_loads(0, q, zero, zero, T);
    double theta = 0, joint_x[3], cm_x[3], x = 0;
    for (int k = 0; k < 3; ++k) {
        theta += q[k];
        joint_x[k] = x;
        cm_x[k] = x - d[k] * std::sin(theta);  // a_y turned by theta points to (-sin, cos)
        x -= L[k] * std::sin(theta);
    }
    for (int j = 0; j < 3; ++j) {
        double moment = 0;
        for (int k = j; k < 3; ++k) moment += mass[k] * g * (cm_x[k] - joint_x[j]);
        EXPECT_NEAR(T[j], moment, 1e-10) << "joint " << j;
    }
    EXPECT_EQ(id.load_names(), (std::vector<std::string>{"T_A", "T_B", "T_C"}));
}

TEST(InverseDynamics, CoupledLoadMeasuresAreSolvedAtRunTime) {
    // the four-bar's crank torque and pin force share rows: the unsolved form, solved by LU;
    // at rest the crank torque equals the virtual-work holding torque dV/dqA along the loop
    SampleModel fb = make_four_bar();
    InverseDynamics id = compile_inverse_dynamics(fb.system, fb.q, fb.unknowns, "four_bar");
    EXPECT_FALSE(id.solved());
    const double LN = 1, LA = 0.4, LB = 1.2, LC = 0.8, g = 9.81;
    auto pose = [&](double qA, double* q) {
        const double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
        const double dx = LN - ax, dy = -ay, dd = std::hypot(dx, dy);
        const double along = (LB * LB - LC * LC + dd * dd) / (2 * dd);
        const double h = std::sqrt(LB * LB - along * along);
        const double px = ax + along * dx / dd - h * dy / dd,
                     py = ay + along * dy / dd + h * dx / dd;
        q[0] = qA, q[1] = std::atan2(py - ay, px - ax) - qA, q[2] = std::atan2(py, px - LN);
    };
    auto potential = [&](double qA) {
        double q[3];
        pose(qA, q);
        const double yA = LA / 2 * std::sin(q[0]);
        const double yB = LA * std::sin(q[0]) + LB / 2 * std::sin(q[0] + q[1]);
        const double yC = LC / 2 * std::sin(q[2]);
        return g * (1.0 * yA + 2.0 * yB + 1.5 * yC);
    };
    const double qA = 1.1, h = 1e-5;
    double q[3], zero[3] = {0, 0, 0}, loads[3];
    pose(qA, q);
    id.calc_loads(0, q, zero, zero, loads);
    const double holding = (potential(qA + h) - potential(qA - h)) / (2 * h);
    EXPECT_NEAR(loads[0], holding, 1e-6);
}

TEST(InverseDynamics, AMotionOffTheClosedLoopIsRefusedNamingTheConstraint) {
    // the four-bar's loop closes at the analytic pose; the same motion with the rocker turned
    // by 0.1 rad leaves the pin apart by about L_C * 0.1 = 8 cm
    SampleModel fb = make_four_bar();
    InverseDynamics id = compile_inverse_dynamics(fb.system, fb.q, fb.unknowns, "four_bar");
    ASSERT_EQ(id.constraint_names().size(), 2u);
    const double LN = 1, LA = 0.4, LB = 1.2, LC = 0.8, qA = 1.1;
    const double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
    const double dx = LN - ax, dy = -ay, dd = std::hypot(dx, dy);
    const double along = (LB * LB - LC * LC + dd * dd) / (2 * dd), h = std::sqrt(LB * LB - along * along);
    const double px = ax + along * dx / dd - h * dy / dd, py = ay + along * dy / dd + h * dx / dd;
    MotionSamples m;
    m.coordinates = {"qA", "qB", "qC"};
    m.t = {0, 0.1, 0.2};
    m.q = {{qA, qA, qA}, {0, 0, 0}, {0, 0, 0}};
    m.q[1].assign(3, std::atan2(py - ay, px - ax) - qA);
    m.q[2].assign(3, std::atan2(py, px - LN));
    m.qd.assign(3, std::vector<double>(3, 0.0));
    m.qdd = m.qd;
    EXPECT_EQ(calc_inverse_dynamics(id, m).row_count(), 3u);
    m.q[2][1] += 0.1;
    InverseAnalysisOptions o;
    o.constraint_units = {{"loop_x", "m"}, {"loop_y", "m"}};
    EXPECT_THROW_MSG(calc_inverse_dynamics(id, m, o), ArgumentError,
                     "calc_inverse_dynamics('four_bar'): the motion violates the configuration "
                     "constraint 'loop_x' at 1 of 3 samples: t = 0.1 s (sample 2); its largest "
                     "residual is ");
    EXPECT_THROW_MSG(calc_inverse_dynamics(id, m, o), ArgumentError, " m at t = 0.1 s, beyond the tolerance 1e-06 m");
}

TEST(InverseDynamics, TheFileIsNamedForWhatItHolds) {
    EXPECT_EQ(inverse_dynamics_file_stem({"N m", "N*m"}), "torques");
    EXPECT_EQ(inverse_dynamics_file_stem({"N", "kN"}), "forces");
    EXPECT_EQ(inverse_dynamics_file_stem({"N*m", "N", "N"}), "loads");
    EXPECT_EQ(inverse_dynamics_file_stem({"", ""}), "torques");
}

TEST(InverseDynamics, AMissingConstantValueIsNamed) {
    SampleModel rod = make_planar_chain(1);
    SymbolTable& s = rod.system.symbols();
    ex k = s.add_constant("k_spring");  // no value
    rod.system.add_torque(*rod.links[0], -k * rod.q[0] * rod.system.newtonian().z(), "spring");
    EXPECT_THROW_MSG(compile_inverse_dynamics(rod.system, rod.q, rod.unknowns, "rod"),
                     ArgumentError, "k_spring");
}

}  // namespace
}  // namespace alembert
