// SPDX-License-Identifier: MIT
// The floating-base humanoid (make_humanoid, src/mech/sample_humanoid.cpp): the recursive
// formation's inverse and forward dynamics against brute-force Newton-Euler at random states.
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"

using namespace alembert;

namespace humanoid_test {

// The coordinates in blocks: a quaternion's four (e0_<B>..e3_<B>, the free joint's and each
// ball joint's) with three speeds, or one coordinate whose rate is its speed.
struct Block {
    std::size_t q, u;
    bool quaternion;
};

std::vector<Block> blocks(const SampleModel& m) {
    std::vector<Block> out;
    for (std::size_t i = 0, k = 0; i < m.q.size(); ++i) {
        const bool quaternion = m.q[i].name().rfind("e0_", 0) == 0;
        out.push_back({i, k, quaternion});
        i += quaternion ? 3 : 0;
        k += quaternion ? 3 : 1;
    }
    return out;
}

// One random state: coordinates (unit quaternions), speeds, speed rates and loads.
struct State {
    std::vector<double> q, u, u_dot, loads;
};

State random_state(std::mt19937& rng, const SampleModel& m) {
    std::uniform_real_distribution<double> d(-1, 1);
    State s;
    for (std::size_t i = 0; i < m.q.size(); ++i) s.q.push_back(d(rng));
    for (const Block& b : blocks(m)) {
        if (!b.quaternion) continue;
        double norm = 0;
        for (std::size_t i = b.q; i < b.q + 4; ++i) norm += s.q[i] * s.q[i];
        for (std::size_t i = b.q; i < b.q + 4; ++i) s.q[i] /= std::sqrt(norm);
    }
    for (std::size_t i = 0; i < m.speeds.size(); ++i)
        s.u.push_back(d(rng)), s.u_dot.push_back(d(rng)), s.loads.push_back(20 * d(rng));
    return s;
}

// The Newton-Euler model: the same humanoid with the angular velocities of the pelvis (in N)
// and of each ball-jointed segment (in its parent) derived from their Euler parameters
// (orient_dcm again drops the ones set in the speeds), so that every velocity is in q and q'
// and the joints are inferred from them; e' = 1/2 Q(e) w and e'' = 1/2 (Q(e') w + Q(e) w')
// give the Euler parameters' rates at a state. Each R_PB is divided by e.e, the rotation of
// e/|e|: equal at unit e, and a rotation at the states off the unit sphere where Newton-Euler
// decides which directions each joint frees.
struct NewtonEulerModel {
    SampleModel m = make_humanoid();
    NewtonEulerEquations ne;
    LinearSystem linear;
    NewtonEulerModel() {
        for (const Block& b : blocks(m)) {
            if (!b.quaternion) continue;
            Frame& B = m.system.frame(m.q[b.q].name().substr(3));
            Mat3 R = B.rotation_from_parent();
            ex norm = 0;
            for (std::size_t i = b.q; i < b.q + 4; ++i) norm += m.q[i].d(0) * m.q[i].d(0);
            for (ex& r : R.m) r = r / norm;
            B.orient_dcm(*B.parent(), R);
        }
        NewtonEulerOptions options;
        options.mode = NewtonEulerMode::spatial;
        ne = form_newton_euler_equations(m.system, m.q, m.unknowns, options);
        linear = form_linear_system(ne.equations, ne.unknowns);
    }
    // the loads Newton-Euler gives at a state (reactions solved for with them)
    std::vector<double> loads(const State& s) const {
        const SymbolTable& st = m.system.symbols();
        exmap at;
        auto Q = [](const double* e4, const double* w3, double* out) {
            out[0] = -0.5 * (e4[1] * w3[0] + e4[2] * w3[1] + e4[3] * w3[2]);
            out[1] = 0.5 * (e4[0] * w3[0] + e4[2] * w3[2] - e4[3] * w3[1]);
            out[2] = 0.5 * (e4[0] * w3[1] + e4[3] * w3[0] - e4[1] * w3[2]);
            out[3] = 0.5 * (e4[0] * w3[2] + e4[1] * w3[1] - e4[2] * w3[0]);
        };
        for (std::size_t i = 0; i < m.q.size(); ++i) at[m.q[i].d(0)] = s.q[i];
        for (const Block& b : blocks(m)) {
            if (!b.quaternion) {
                at[m.q[b.q].d(1)] = s.u[b.u], at[m.q[b.q].d(2)] = s.u_dot[b.u];
                continue;
            }
            const double* e = &s.q[b.q];
            const double* w = &s.u[b.u];
            const double* wd = &s.u_dot[b.u];
            double ed[4], edd_a[4], edd_b[4];
            Q(e, w, ed);
            Q(ed, w, edd_a);
            Q(e, wd, edd_b);
            for (std::size_t i = 0; i < 4; ++i)
                at[m.q[b.q + i].d(1)] = ed[i], at[m.q[b.q + i].d(2)] = edd_a[i] + edd_b[i];
        }
        const Eigen::VectorXd x = solve_numeric(st, linear, at);
        return std::vector<double>(x.data(), x.data() + m.unknowns.size());
    }
};

}  // namespace humanoid_test

using namespace humanoid_test;

TEST(Humanoid, HasFifteenSegmentsAndThirtyTwoDegreesOfFreedom) {
    SampleModel m = make_humanoid();
    EXPECT_EQ(m.links.size(), 15u);
    EXPECT_EQ(m.q.size(), 39u);  // 7 of the free joint, 4 of each of 6 balls, 8 hinge angles
    EXPECT_EQ(m.speeds.size(), 32u);
    EXPECT_EQ(m.unknowns.size(), 32u);
    EXPECT_EQ(m.coordinate_rates.size(), 39u);
    // de Leva's fractions add up to the whole body
    double mass = 0;
    for (const RigidBody* B : m.links) mass += m.system.symbols().evaluate(B->mass());
    EXPECT_NEAR(mass, 73.0, 1e-12);
    TreeEquations tree = form_tree_equations(m.system, m.q, m.speeds);
    ASSERT_EQ(tree.joints.size(), 15u);  // one joint per segment, no gimbal stages
    EXPECT_EQ(tree.joints[0].coordinates, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
    // the lumbar ball joint owns the next three speeds, those of the torso
    EXPECT_EQ(tree.joints[1].coordinates, (std::vector<std::size_t>{6, 7, 8}));
}

// Inverse dynamics: the loads of the recursive rows at random states equal those of
// brute-force Newton-Euler (every body's free-body diagram, 90 equations with the joint
// reactions); forward dynamics: at the recursion's accelerations for random loads,
// Newton-Euler gives those loads back.
TEST(Humanoid, RecursiveInverseAndForwardDynamicsAgreeWithNewtonEuler) {
    SampleModel m = make_humanoid();
    const SymbolTable& st = m.system.symbols();
    TreeEquations tree = form_tree_equations(m.system, m.q, m.speeds);
    const std::size_t n = m.speeds.size();
    std::vector<ex> inputs;
    for (const TimeVariable& q : m.q) inputs.push_back(q.d(0));
    for (const ex& u : m.speeds) inputs.push_back(u);
    std::vector<ex> u_dot;
    for (const ex& u : m.speeds) u_dot.push_back(m.system.symbols().dt(u));
    std::vector<ex> id_inputs = inputs, fd_inputs = inputs;
    id_inputs.insert(id_inputs.end(), u_dot.begin(), u_dot.end());
    id_inputs.insert(id_inputs.end(), m.unknowns.begin(), m.unknowns.end());
    fd_inputs.insert(fd_inputs.end(), m.unknowns.begin(), m.unknowns.end());
    CompiledExpressions rows(st, id_inputs, tree.residuals);
    CompiledExpressions accelerations(st, fd_inputs, tree.accelerations);
    NewtonEulerModel ne;
    ASSERT_EQ(ne.linear.unknowns.size(), ne.linear.A.rows());
    std::mt19937 rng(17);
    for (int trial = 0; trial < 3; ++trial) {
        State s = random_state(rng, m);
        // the rows' loads: E = loads - (inertia terms), each load in its own row
        std::vector<double> in = s.q;
        in.insert(in.end(), s.u.begin(), s.u.end());
        in.insert(in.end(), s.u_dot.begin(), s.u_dot.end());
        in.insert(in.end(), n, 0.0);
        std::vector<double> minus_tau = rows.evaluate(in);
        const std::vector<double> tau_ne = ne.loads(s);
        double scale = 1;
        for (double t : tau_ne) scale = std::max(scale, std::abs(t));
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_NEAR(-minus_tau[i], tau_ne[i], 1e-12 * scale) << "inverse, " << to_string(m.unknowns[i]);
        // forward dynamics at random loads, back through Newton-Euler
        std::vector<double> fin = s.q;
        fin.insert(fin.end(), s.u.begin(), s.u.end());
        fin.insert(fin.end(), s.loads.begin(), s.loads.end());
        State back = s;
        back.u_dot = accelerations.evaluate(fin);
        const std::vector<double> tau_back = ne.loads(back);
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_NEAR(tau_back[i], s.loads[i], 1e-12 * 20) << "forward, " << to_string(m.unknowns[i]);
    }
}
