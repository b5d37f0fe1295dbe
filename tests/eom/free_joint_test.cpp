// SPDX-License-Identifier: MIT
// The free joint of the recursive formation (Euler parameters, body-frame angular velocity):
// a lone rigid body's rows against Newton-Euler written out by hand and against Kane's method
// in the same speeds, and a long torque-free tumble that keeps its energy, angular momentum
// and the quaternion's unit norm.
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace free_joint_test {

constexpr double kFreeExact = 1e-12;

// A lone rigid body B on a free joint: mass m, central inertia with products (in B), mass
// centre at c from B_o, a force F (measures Fx, Fy, Fz along N) at a point P of B and a torque
// T (measures Tx, Ty, Tz along B), gravity -g Nz.
struct FreeBody {
    System sys{"N"};
    FreeJoint joint;
    RigidBody* B = nullptr;
    std::vector<ex> loads;
    static constexpr double m = 2.5, g = 9.81;
    static constexpr double c[3] = {0.1, -0.2, 0.3}, p[3] = {-0.4, 0.25, 0.15};
    // central inertia in B (kg m^2): all three moments distinct, products non-zero
    static constexpr double I[3][3] = {{0.30, 0.02, -0.01}, {0.02, 0.45, 0.03}, {-0.01, 0.03, 0.60}};
    explicit FreeBody(double gravity = g) {
        SymbolTable& st = sys.symbols();
        B = &sys.add_rigid_body("B");
        joint = add_free_joint(sys, *B);
        const Frame& N = sys.newtonian();
        const Frame& F = B->body_frame();
        B->set_mass(m);
        B->cm().set_pos(sys.point("B_o"), c[0] * F.x() + c[1] * F.y() + c[2] * F.z());
        Mat3 I_BBcm;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) I_BBcm(i, j) = I[i][j];
        B->set_inertia(B->cm(), Dyadic(F, F, I_BBcm));
        Point& P = sys.add_point("P", B);
        P.set_pos(sys.point("B_o"), p[0] * F.x() + p[1] * F.y() + p[2] * F.z());
        for (const char* name : {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"}) loads.push_back(st.add_unknown(name));
        sys.add_force(P, loads[0] * N.x() + loads[1] * N.y() + loads[2] * N.z(), "F");
        sys.add_torque(*B, loads[3] * F.x() + loads[4] * F.y() + loads[5] * F.z(), "T");
        sys.set_gravity(-gravity * N.z());
    }
};

Eigen::Matrix3d rotation_of(const Eigen::Vector4d& e) {
    return Eigen::Quaterniond(e[0], e[1], e[2], e[3]).toRotationMatrix();
}

Eigen::Matrix3d inertia() {
    Eigen::Matrix3d I;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) I(i, j) = FreeBody::I[i][j];
    return I;
}

}  // namespace free_joint_test

using namespace free_joint_test;

// Newton-Euler by hand about B_o: with a_O the acceleration of B_o in N (N axes), w and alpha
// in B axes, ^N a^cm = a_O + R (alpha x c + w x (w x c)); the rows of the translational speeds
// are Nx_i . (F - m g Nz - m a_cm), those of w_i are Bx_i . (M^O - c x m a_cm - I alpha
// - w x I w), with M^O the applied moment about B_o (torque plus p x F).
TEST(FreeJoint, LoneBodyRowsAreNewtonEulerWrittenOutByHand) {
    FreeBody b;
    SymbolTable& st = b.sys.symbols();
    const std::vector<TimeVariable> q = b.joint.coordinates();
    TreeEquations tree = form_tree_equations(b.sys, q, b.joint.speeds());
    ASSERT_EQ(tree.residuals.size(), 6u);
    ASSERT_EQ(tree.joints.size(), 1u);
    EXPECT_EQ(tree.joints[0].coordinates, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> draw(-2, 2);
    const Eigen::Matrix3d I = inertia();
    const Eigen::Vector3d c(FreeBody::c[0], FreeBody::c[1], FreeBody::c[2]);
    const Eigen::Vector3d p(FreeBody::p[0], FreeBody::p[1], FreeBody::p[2]);
    for (int k = 0; k < 5; ++k) {
        Eigen::Vector4d e(draw(rng), draw(rng), draw(rng), draw(rng));
        e.normalize();
        Eigen::Vector3d x, v, a, w, al, F, T;
        for (int i = 0; i < 3; ++i)
            x[i] = draw(rng), v[i] = draw(rng), a[i] = draw(rng), w[i] = draw(rng),
            al[i] = draw(rng), F[i] = 10 * draw(rng), T[i] = draw(rng);
        exmap at;
        for (int i = 0; i < 3; ++i) {
            at[b.joint.position[i].d(0)] = x[i];
            at[b.joint.position[i].d(1)] = v[i];
            at[b.joint.position[i].d(2)] = a[i];
            at[b.joint.angular[i].d(0)] = w[i];
            at[b.joint.angular[i].d(1)] = al[i];
            at[b.loads[i]] = F[i];
            at[b.loads[3 + i]] = T[i];
        }
        for (int i = 0; i < 4; ++i) at[b.joint.quaternion[i].d(0)] = e[i];
        const Eigen::Matrix3d R = rotation_of(e);
        const Eigen::Vector3d a_cm = a + R * (al.cross(c) + w.cross(w.cross(c)));
        const Eigen::Vector3d force = F - FreeBody::m * FreeBody::g * Eigen::Vector3d::UnitZ() -
                                      FreeBody::m * a_cm;  // N axes
        const Eigen::Vector3d F_B = R.transpose() * F,
                              g_B = R.transpose() * (-FreeBody::g * Eigen::Vector3d::UnitZ());
        const Eigen::Vector3d moment = T + p.cross(F_B) + c.cross(FreeBody::m * g_B) -
                                       c.cross(FreeBody::m * (R.transpose() * a_cm)) - I * al -
                                       w.cross(I * w);  // B axes
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(st.evaluate(tree.residuals[i], at), force[i], kFreeExact * 100);
            EXPECT_NEAR(st.evaluate(tree.residuals[3 + i], at), moment[i], kFreeExact * 100);
        }
        // forward dynamics: at the accelerations the recursion gives, every row vanishes
        exmap fd = at;
        for (int i = 0; i < 3; ++i) {
            fd[b.joint.position[i].d(2)] = st.evaluate(tree.accelerations[i], at);
            fd[b.joint.angular[i].d(1)] = st.evaluate(tree.accelerations[3 + i], at);
        }
        for (const ex& r : tree.residuals) EXPECT_NEAR(st.evaluate(r, fd), 0, kFreeExact * 100);
    }
}

// Kane's method with speeds v1, v2, v3 (= x', y', z') and w1, w2, w3 and the kinematic
// equations e' = 1/2 Q(e) w gives the same rows.
TEST(FreeJoint, LoneBodyRowsAgreeWithKanesMethodInTheSameSpeeds) {
    FreeBody b;
    SymbolTable& st = b.sys.symbols();
    std::vector<TimeVariable> v;
    for (const char* name : {"v1", "v2", "v3"}) v.push_back(st.add_variable(name, 1));
    KaneOptions options;
    options.coordinates = b.joint.coordinates();
    const std::vector<ex> rates = b.joint.coordinate_rates();
    for (int i = 0; i < 3; ++i) {
        options.speeds.push_back(v[static_cast<std::size_t>(i)].d(0));
        options.kinematic_equations.push_back(v[static_cast<std::size_t>(i)].d(0) -
                                              b.joint.position[static_cast<std::size_t>(i)].d(1));
    }
    for (const TimeVariable& w : b.joint.angular) options.speeds.push_back(w.d(0));
    for (std::size_t i = 0; i < 4; ++i)
        options.kinematic_equations.push_back(b.joint.quaternion[i].d(1) - rates[3 + i]);
    options.simplify = false;
    KaneEquations kane = form_kane_equations(b.sys, options);
    TreeEquations tree = form_tree_equations(b.sys, b.joint.coordinates(), b.joint.speeds());
    ASSERT_EQ(kane.residuals.size(), 6u);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> draw(-2, 2);
    for (int k = 0; k < 5; ++k) {
        Eigen::Vector4d e(draw(rng), draw(rng), draw(rng), draw(rng));
        e.normalize();
        exmap tree_at, kane_at;
        for (std::size_t i = 0; i < 3; ++i) {
            const double x = draw(rng), xd = draw(rng), xdd = draw(rng);
            tree_at[b.joint.position[i].d(0)] = kane_at[b.joint.position[i].d(0)] = x;
            tree_at[b.joint.position[i].d(1)] = kane_at[v[i].d(0)] = xd;
            tree_at[b.joint.position[i].d(2)] = kane_at[v[i].d(1)] = xdd;
            const double w = draw(rng), wd = draw(rng);
            tree_at[b.joint.angular[i].d(0)] = kane_at[b.joint.angular[i].d(0)] = w;
            tree_at[b.joint.angular[i].d(1)] = kane_at[b.joint.angular[i].d(1)] = wd;
        }
        for (std::size_t i = 0; i < 4; ++i)
            tree_at[b.joint.quaternion[i].d(0)] = kane_at[b.joint.quaternion[i].d(0)] =
                e[static_cast<Eigen::Index>(i)];
        for (const ex& l : b.loads) tree_at[l] = kane_at[l] = 10 * draw(rng);
        for (std::size_t r = 0; r < 6; ++r)
            EXPECT_NEAR(st.evaluate(tree.residuals[r], tree_at),
                        st.evaluate(kane.residuals[r], kane_at), kFreeExact * 100)
                << "row " << r;
    }
}

// A torque-free tumble near the intermediate axis (zero gravity, so it flips over and back),
// 100 s by classical Runge-Kutta at 0.5 ms on the recursion's accelerations and
// e' = 1/2 Q(e) w. RK4's error per step is about (|w| h)^5 / 120, so over the 2e5 steps at
// |w| ~ 3 rad/s about 1e-11 relative: the kinetic energy and the angular momentum about N_o
// (in N) hold to 2e-10 relative, |e| to 1e-12, and the mass centre moves at constant velocity
// (measured: 2e-13, 6e-11, 1e-14).
TEST(FreeJoint, TorqueFreeTumbleConservesEnergyMomentumAndUnitQuaternion) {
    FreeBody b(0.0);
    SymbolTable& st = b.sys.symbols();
    TreeEquations tree = form_tree_equations(b.sys, b.joint.coordinates(), b.joint.speeds());
    // state y = (x, e, v, w): 3 + 4 + 3 + 3
    std::vector<ex> inputs, outputs = b.joint.coordinate_rates();
    for (const TimeVariable& x : b.joint.coordinates()) inputs.push_back(x.d(0));
    for (const ex& u : b.joint.speeds()) inputs.push_back(u);
    for (const ex& l : b.loads) inputs.push_back(l);
    outputs.insert(outputs.end(), tree.accelerations.begin(), tree.accelerations.end());
    CompiledExpressions f(st, inputs, outputs);
    using State = Eigen::Matrix<double, 13, 1>;
    auto rhs = [&](const State& y) {
        double in[19] = {}, out[13];
        for (int i = 0; i < 13; ++i) in[i] = y[i];
        f.evaluate(in, out);
        return State(Eigen::Map<State>(out));
    };
    const Eigen::Matrix3d I = inertia();
    const Eigen::Vector3d c(FreeBody::c[0], FreeBody::c[1], FreeBody::c[2]);
    struct Measures {
        double energy;
        Eigen::Vector3d momentum, v_cm;
    };
    auto measure = [&](const State& y) {
        const Eigen::Vector4d e = y.segment<4>(3);
        const Eigen::Matrix3d R = rotation_of(e / e.norm());
        const Eigen::Vector3d w = y.segment<3>(10);
        const Eigen::Vector3d r_cm = y.segment<3>(0) + R * c;
        const Eigen::Vector3d v_cm = y.segment<3>(7) + R * w.cross(c);
        return Measures{0.5 * FreeBody::m * v_cm.squaredNorm() + 0.5 * w.dot(I * w),
                        R * (I * w) + FreeBody::m * r_cm.cross(v_cm), v_cm};
    };
    State y;
    y << 0.1, -0.2, 0.3, 1, 0, 0, 0, 0.2, -0.1, 0.05, 0.4, 3.0, -0.7;
    const Measures start = measure(y);
    const double h = 5e-4;
    double wander = 0;
    double worst_energy = 0, worst_momentum = 0, worst_norm = 0;
    for (int k = 0; k < 200000; ++k) {
        const State k1 = rhs(y), k2 = rhs(y + h / 2 * k1), k3 = rhs(y + h / 2 * k2),
                    k4 = rhs(y + h * k3);
        y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        if (k % 200 != 199) continue;
        wander = std::max(wander, (y.segment<3>(10) - Eigen::Vector3d(0.4, 3.0, -0.7)).norm());
        const Measures now = measure(y);
        worst_energy = std::max(worst_energy, std::abs(now.energy - start.energy) / start.energy);
        worst_momentum = std::max(worst_momentum,
                                  (now.momentum - start.momentum).norm() / start.momentum.norm());
        worst_norm = std::max(worst_norm, std::abs(y.segment<4>(3).norm() - 1));
        ASSERT_LT((now.v_cm - start.v_cm).norm(), 1e-10);
    }
    // the body tumbles: its angular velocity in B wanders far from where it started
    EXPECT_GT(wander, 1.0);
    EXPECT_LT(worst_energy, 2e-10);
    EXPECT_LT(worst_momentum, 2e-10);
    EXPECT_LT(worst_norm, 1e-12);
}

TEST(FreeJoint, RefusesASpeedThatMovesNoBody) {
    FreeBody b;
    SymbolTable& st = b.sys.symbols();
    TimeVariable s = st.add_variable("s", 1);
    std::vector<ex> speeds = b.joint.speeds();
    speeds.push_back(s.d(0));
    EXPECT_THROW_MSG(form_tree_equations(b.sys, b.joint.coordinates(), speeds), ModelError,
                     "the speed 's' moves no body");
    EXPECT_THROW_MSG(add_free_joint(b.sys, *b.B), ModelError, "already oriented");
}
