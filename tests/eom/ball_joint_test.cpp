// SPDX-License-Identifier: MIT
// The ball joint (Euler parameters, body-frame angular velocity relative to the parent) on a
// double spherical pendulum: its angular velocity against the rate of its rotation matrix, the
// recursive rows against Kane's method in the same speeds, its motor torques as generalized
// forces, and a long swing under gravity that keeps its energy and unit quaternions.
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/ball_joint.hpp"
#include "alembert/sym/evaluator.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace ball_joint_test {

constexpr double kBallExact = 1e-12;

// Two rigid bodies in a chain of ball joints: A to N at A_o = N_o, B to A at B_o, fixed in A at
// p from A_o. Each has a mass, a central inertia with products and a mass centre off its
// origin; the motor torques TA (on A from N, along A's axes) and TB (on B from A, along B's
// axes), a force F (along N) at a point P of B; gravity -g Nz.
struct SphericalPendulum {
    System sys{"N"};
    BallJoint a, b;
    RigidBody* A = nullptr;
    RigidBody* B = nullptr;
    std::vector<ex> loads;  // TA1..3, TB1..3, Fx, Fy, Fz
    static constexpr double mA = 1.5, mB = 0.8, g = 9.81;
    static constexpr double cA[3] = {0.05, -0.02, -0.3}, cB[3] = {-0.03, 0.04, -0.25};
    static constexpr double p[3] = {0.02, 0.01, -0.6}, r_BP[3] = {0.1, -0.05, -0.4};
    static constexpr double IA[3][3] = {
        {0.05, 0.004, -0.002}, {0.004, 0.06, 0.003}, {-0.002, 0.003, 0.02}};
    static constexpr double IB[3][3] = {
        {0.03, -0.002, 0.001}, {-0.002, 0.025, 0.002}, {0.001, 0.002, 0.01}};
    explicit SphericalPendulum(double gravity = g) {
        SymbolTable& st = sys.symbols();
        const Frame& N = sys.newtonian();
        A = &sys.add_rigid_body("A");
        B = &sys.add_rigid_body("B");
        a = add_ball_joint(sys, *A, N);
        b = add_ball_joint(sys, *B, A->body_frame());
        const Frame& FA = A->body_frame();
        const Frame& FB = B->body_frame();
        sys.point("A_o").set_pos(sys.origin(), Vector());
        sys.point("B_o").set_pos(sys.point("A_o"), p[0] * FA.x() + p[1] * FA.y() + p[2] * FA.z());
        A->set_mass(mA);
        B->set_mass(mB);
        A->cm().set_pos(sys.point("A_o"), cA[0] * FA.x() + cA[1] * FA.y() + cA[2] * FA.z());
        B->cm().set_pos(sys.point("B_o"), cB[0] * FB.x() + cB[1] * FB.y() + cB[2] * FB.z());
        Mat3 I_AAcm, I_BBcm;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) I_AAcm(i, j) = IA[i][j], I_BBcm(i, j) = IB[i][j];
        A->set_inertia(A->cm(), Dyadic(FA, FA, I_AAcm));
        B->set_inertia(B->cm(), Dyadic(FB, FB, I_BBcm));
        for (const char* name : {"TA1", "TA2", "TA3", "TB1", "TB2", "TB3", "Fx", "Fy", "Fz"})
            loads.push_back(st.add_unknown(name));
        sys.add_torque_pair(*A, N, loads[0] * FA.x() + loads[1] * FA.y() + loads[2] * FA.z(), "TA");
        sys.add_torque_pair(*B, FA, loads[3] * FB.x() + loads[4] * FB.y() + loads[5] * FB.z(),
                            "TB");
        Point& P = sys.add_point("P", B);
        P.set_pos(sys.point("B_o"), r_BP[0] * FB.x() + r_BP[1] * FB.y() + r_BP[2] * FB.z());
        sys.add_force(P, loads[6] * N.x() + loads[7] * N.y() + loads[8] * N.z(), "F");
        sys.set_gravity(-gravity * N.z());
    }
    std::vector<TimeVariable> coordinates() const {
        std::vector<TimeVariable> q = a.coordinates();
        q.insert(q.end(), b.quaternion.begin(), b.quaternion.end());
        return q;
    }
    std::vector<ex> speeds() const {
        std::vector<ex> u = a.speeds(), ub = b.speeds();
        u.insert(u.end(), ub.begin(), ub.end());
        return u;
    }
    std::vector<ex> coordinate_rates() const {
        std::vector<ex> r = a.coordinate_rates(), rb = b.coordinate_rates();
        r.insert(r.end(), rb.begin(), rb.end());
        return r;
    }
};

Eigen::Vector4d random_quaternion(std::mt19937& rng) {
    std::uniform_real_distribution<double> draw(-1, 1);
    Eigen::Vector4d e(draw(rng), draw(rng), draw(rng), draw(rng));
    return e.normalized();
}

Eigen::Matrix3d rotation_of(const Eigen::Vector4d& e) {
    return Eigen::Quaterniond(e[0], e[1], e[2], e[3]).normalized().toRotationMatrix();
}

Eigen::Matrix3d matrix(const double (&I)[3][3]) {
    Eigen::Matrix3d M;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M(i, j) = I[i][j];
    return M;
}

Eigen::Vector3d vector(const double (&v)[3]) { return Eigen::Vector3d(v[0], v[1], v[2]); }

// the coordinates (unit quaternions) and speeds of a random state
exmap random_state(std::mt19937& rng, const SphericalPendulum& s) {
    std::uniform_real_distribution<double> draw(-2, 2);
    exmap at;
    const Eigen::Vector4d ea = random_quaternion(rng), eb = random_quaternion(rng);
    for (std::size_t i = 0; i < 4; ++i) {
        at[s.a.quaternion[i].d(0)] = ea[static_cast<Eigen::Index>(i)];
        at[s.b.quaternion[i].d(0)] = eb[static_cast<Eigen::Index>(i)];
    }
    for (const ex& u : s.speeds()) at[u] = draw(rng);
    return at;
}

}  // namespace ball_joint_test

using namespace ball_joint_test;

// ^N w^B = ^N w^A + ^A w^B with each set in body-frame speeds agrees with the rate of the
// rotation matrix: [w_NB]x = R_NB^T R_NB' in B's axes, R_NB' by the chain rule over the Euler
// parameters with e' = 1/2 Q(e) w.
TEST(BallJoint, AngularVelocityIsTheRateOfTheEulerParameterRotation) {
    SphericalPendulum s;
    SymbolTable& st = s.sys.symbols();
    const Frame& N = s.sys.newtonian();
    const Frame& FB = s.B->body_frame();
    const Mat3 R_NB = rotation_matrix(N, FB);
    const Col3 w_NB_B = FB.ang_vel_in(N).components_in(FB);
    const std::vector<TimeVariable> q = s.coordinates();
    const std::vector<ex> rates = s.coordinate_rates();
    std::mt19937 rng(3);
    for (int k = 0; k < 5; ++k) {
        const exmap at = random_state(rng, s);
        Eigen::Matrix3d R, R_dot;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                R(i, j) = st.evaluate(R_NB(i, j), at);
                ex rate = 0;
                for (std::size_t r = 0; r < q.size(); ++r)
                    rate += R_NB(i, j).diff(GiNaC::ex_to<GiNaC::symbol>(q[r].d(0))) * rates[r];
                R_dot(i, j) = st.evaluate(rate, at);
            }
        EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), kBallExact);
        const Eigen::Matrix3d W = R.transpose() * R_dot;
        EXPECT_LT((W + W.transpose()).norm(), kBallExact * 10);
        const Eigen::Vector3d w(W(2, 1), W(0, 2), W(1, 0));
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(w[i], st.evaluate(w_NB_B[i], at), kBallExact * 10);
    }
}

// Kane's method with the speeds w1..w3 of both joints and e' = 1/2 Q(e) w as kinematic
// equations gives the recursion's rows, at random states, rates and loads.
TEST(BallJoint, DoubleSphericalPendulumRowsAgreeWithKanesMethodInTheSameSpeeds) {
    SphericalPendulum s;
    SymbolTable& st = s.sys.symbols();
    KaneOptions options;
    options.coordinates = s.coordinates();
    options.speeds = s.speeds();
    const std::vector<ex> rates = s.coordinate_rates();
    for (std::size_t i = 0; i < rates.size(); ++i)
        options.kinematic_equations.push_back(options.coordinates[i].d(1) - rates[i]);
    options.simplify = false;
    KaneEquations kane = form_kane_equations(s.sys, options);
    TreeEquations tree = form_tree_equations(s.sys, s.coordinates(), s.speeds());
    ASSERT_EQ(tree.joints.size(), 2u);
    EXPECT_EQ(tree.joints[0].coordinates, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(tree.joints[1].coordinates, (std::vector<std::size_t>{3, 4, 5}));
    ASSERT_EQ(kane.residuals.size(), 6u);
    ASSERT_EQ(tree.residuals.size(), 6u);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> draw(-2, 2);
    for (int k = 0; k < 5; ++k) {
        exmap at = random_state(rng, s);
        for (const ex& u : s.speeds()) at[st.dt(u)] = draw(rng);
        for (const ex& l : s.loads) at[l] = 10 * draw(rng);
        for (std::size_t r = 0; r < 6; ++r) {
            const double expected = st.evaluate(kane.residuals[r], at);
            EXPECT_NEAR(st.evaluate(tree.residuals[r], at), expected,
                        kBallExact * std::max(1.0, std::abs(expected)))
                << "row " << r;
        }
        // forward dynamics: at the recursion's accelerations Kane's rows vanish
        exmap fd = at;
        const std::vector<ex> u = s.speeds();
        for (std::size_t r = 0; r < 6; ++r)
            fd[st.dt(u[r])] = st.evaluate(tree.accelerations[r], at);
        for (const ex& e : kane.residuals) EXPECT_NEAR(st.evaluate(e, fd), 0, kBallExact * 100);
    }
}

// The joint's partial angular velocities relative to the parent are the body's axes: a motor
// torque component along B's axis i changes row i by itself and no other row.
TEST(BallJoint, MotorTorqueComponentsAreTheGeneralizedForcesOfTheirSpeeds) {
    SphericalPendulum s;
    SymbolTable& st = s.sys.symbols();
    TreeEquations tree = form_tree_equations(s.sys, s.coordinates(), s.speeds());
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> draw(-2, 2);
    for (int k = 0; k < 3; ++k) {
        exmap at = random_state(rng, s);
        for (const ex& u : s.speeds()) at[st.dt(u)] = draw(rng);
        for (const ex& l : s.loads) at[l] = 0;
        std::vector<double> base;
        for (const ex& r : tree.residuals) base.push_back(st.evaluate(r, at));
        for (std::size_t j = 0; j < 6; ++j) {
            exmap loaded = at;
            loaded[s.loads[j]] = 1;
            for (std::size_t r = 0; r < 6; ++r)
                EXPECT_NEAR(st.evaluate(tree.residuals[r], loaded) - base[r], r == j ? 1 : 0,
                            kBallExact * 100)
                    << "torque " << j << ", row " << r;
        }
    }
}

// Swinging under gravity with no loads for 20 s, by classical Runge-Kutta at 0.25 ms on the
// recursion's accelerations and e' = 1/2 Q(e) w: the energy (kinetic, from the bodies' mass
// centre velocities and angular velocities worked out by hand, plus gravity's potential)
// holds to 1e-10 relative to the kinetic energy at the start and |e| of both joints to 1e-12
// (measured: 1.5e-11 and 2.9e-13; at 2, 1 and 0.5 ms 6.5e-8, 4.0e-9 and 2.5e-10, falling 16x
// per halving of the step: Runge-Kutta's truncation error, not the equations').
TEST(BallJoint, UnloadedDoubleSphericalPendulumConservesEnergyAndUnitQuaternions) {
    SphericalPendulum s;
    SymbolTable& st = s.sys.symbols();
    TreeEquations tree = form_tree_equations(s.sys, s.coordinates(), s.speeds());
    // state y = (eA, eB, wA, wB): 4 + 4 + 3 + 3
    std::vector<ex> inputs, outputs = s.coordinate_rates();
    for (const TimeVariable& x : s.coordinates()) inputs.push_back(x.d(0));
    for (const ex& u : s.speeds()) inputs.push_back(u);
    for (const ex& l : s.loads) inputs.push_back(l);
    outputs.insert(outputs.end(), tree.accelerations.begin(), tree.accelerations.end());
    CompiledExpressions f(st, inputs, outputs);
    using State = Eigen::Matrix<double, 14, 1>;
    auto rhs = [&](const State& y) {
        double in[23] = {}, out[14];
        for (int i = 0; i < 14; ++i) in[i] = y[i];
        f.evaluate(in, out);
        return State(Eigen::Map<State>(out));
    };
    const Eigen::Matrix3d IA = matrix(SphericalPendulum::IA), IB = matrix(SphericalPendulum::IB);
    const Eigen::Vector3d cA = vector(SphericalPendulum::cA), cB = vector(SphericalPendulum::cB),
                          p = vector(SphericalPendulum::p);
    struct Energy {
        double kinetic, total;
    };
    auto energy = [&](const State& y) {
        const Eigen::Matrix3d R_NA = rotation_of(y.segment<4>(0)),
                              R_AB = rotation_of(y.segment<4>(4));
        const Eigen::Matrix3d R_NB = R_NA * R_AB;
        const Eigen::Vector3d w_NA_A = y.segment<3>(8);
        const Eigen::Vector3d w_NB_B = R_AB.transpose() * w_NA_A + y.segment<3>(11);
        const Eigen::Vector3d v_Acm = R_NA * w_NA_A.cross(cA);
        const Eigen::Vector3d v_Bcm = R_NA * w_NA_A.cross(p) + R_NB * w_NB_B.cross(cB);
        const double z_A = (R_NA * cA)[2], z_B = (R_NA * p + R_NB * cB)[2];
        const double kinetic =
            0.5 * SphericalPendulum::mA * v_Acm.squaredNorm() + 0.5 * w_NA_A.dot(IA * w_NA_A) +
            0.5 * SphericalPendulum::mB * v_Bcm.squaredNorm() + 0.5 * w_NB_B.dot(IB * w_NB_B);
        return Energy{kinetic, kinetic + SphericalPendulum::g * (SphericalPendulum::mA * z_A +
                                                                 SphericalPendulum::mB * z_B)};
    };
    State y;
    const Eigen::Vector4d ea = Eigen::Vector4d(0.9, 0.3, -0.2, 0.1).normalized();
    const Eigen::Vector4d eb = Eigen::Vector4d(0.8, -0.4, 0.3, 0.2).normalized();
    y << ea, eb, 1.0, -2.0, 0.5, -1.5, 2.5, 1.0;
    const Energy start = energy(y);
    const double h = 2.5e-4;
    double worst_energy = 0, worst_norm = 0, lowest_kinetic = start.kinetic;
    for (int k = 0; k < 80000; ++k) {
        const State k1 = rhs(y), k2 = rhs(y + h / 2 * k1), k3 = rhs(y + h / 2 * k2),
                    k4 = rhs(y + h * k3);
        y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        if (k % 400 != 399) continue;
        const Energy now = energy(y);
        lowest_kinetic = std::min(lowest_kinetic, now.kinetic);
        worst_energy = std::max(worst_energy, std::abs(now.total - start.total) / start.kinetic);
        worst_norm = std::max({worst_norm, std::abs(y.segment<4>(0).norm() - 1),
                               std::abs(y.segment<4>(4).norm() - 1)});
    }
    // energy moves between kinetic and potential: it swings
    EXPECT_LT(lowest_kinetic, 0.5 * start.kinetic);
    EXPECT_LT(worst_energy, 1e-10);
    EXPECT_LT(worst_norm, 1e-12);
}

TEST(BallJoint, RefusesAnOrientedFrameAndItsOwnFrame) {
    SphericalPendulum s;
    EXPECT_THROW_MSG(add_ball_joint(s.sys, *s.B, s.sys.newtonian()), ModelError,
                     "add_ball_joint(): the frame of 'B' is already oriented in 'A'");
    RigidBody& C = s.sys.add_rigid_body("C");
    EXPECT_THROW_MSG(add_ball_joint(s.sys, C, C.body_frame()), ModelError,
                     "cannot be joined to its own frame");
    EXPECT_THROW_MSG(euler_parameter_rates({1, 0, 0}, {0, 0, 0}), ArgumentError,
                     "got 3 Euler parameters");
}
