// SPDX-License-Identifier: MIT
// Road-map, Kane and Lagrange agree at random states on a range of models; Euler's equations.
#include "alembert/eom/cross_check.hpp"

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {
constexpr double kAgree = 1e-12;

// a body pivoting about its mass centre, oriented by body-fixed XYZ angles
struct FreeBody {
    System sys;
    std::vector<TimeVariable> q;
    RigidBody* B = nullptr;
    FreeBody() {
        SymbolTable& s = sys.symbols();
        q = {s.add_variable("q1"), s.add_variable("q2"), s.add_variable("q3")};
        B = &sys.add_rigid_body("B");
        B->body_frame().orient_body_fixed(sys.newtonian(), RotationSequence::XYZ, q[0], q[1], q[2]);
        B->cm().set_pos(sys.origin(), Vector());
        B->set_mass(s.add_constant("m", 2.0));
        B->set_inertia(B->cm(), s.add_constant("Ixx", 1.0), s.add_constant("Iyy", 2.0),
                       s.add_constant("Izz", 3.5), s.add_constant("Ixy", 0.1));
    }
};
}  // namespace

TEST(CompareMethods, TriplePendulumAgrees) {
    SampleModel m = make_triple_pendulum();
    MethodComparison c = compare_methods(m.system, m.q, 4);
    EXPECT_EQ(c.methods.size(), 3u);
    EXPECT_LT(c.max_difference, kAgree);
}

TEST(CompareMethods, PlanarChainsAgreeUpToEightLinks) {
    for (int n = 1; n <= 8; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::planar);
        EXPECT_LT(compare_methods(m.system, m.q, 2).max_difference, kAgree) << n << " links";
    }
}

TEST(CompareMethods, SpatialChainsAgree) {
    for (int n = 1; n <= 3; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::spatial);
        EXPECT_LT(compare_methods(m.system, m.q, 2).max_difference, kAgree) << n << " links";
    }
}

TEST(CompareMethods, MassSpringDamperAgrees) {
    SampleModel m = make_mass_spring_damper();
    EXPECT_LT(compare_methods(m.system, m.q, 3).max_difference, kAgree);
}

TEST(CompareMethods, GimbalAgrees) {
    // outer gimbal A about Nz, inner body B about Ax, both with full central inertia
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    A.body_frame().orient_axis(sys.newtonian(), Axis::z, q1);
    B.body_frame().orient_axis(A.body_frame(), Axis::x, q2);
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), Vector());
    sys.point("B_o").set_pos(sys.point("A_o"), Vector());
    B.cm().set_pos(sys.point("B_o"), s.add_constant("e", 0.1) * B.body_frame().z());
    A.set_mass(s.add_constant("mA", 1.0));
    B.set_mass(s.add_constant("mB", 3.0));
    A.set_inertia(A.cm(), 0.4, 0.5, 0.6, 0.01, 0.02, 0.03);
    B.set_inertia(B.cm(), 1.1, 1.3, 0.7, -0.05, 0.04, 0.02);
    sys.set_gravity(-s.add_constant("g", 9.81) * sys.newtonian().z());
    sys.add_torque_pair(A, sys.newtonian(), s.add_unknown("T1") * sys.newtonian().z());
    sys.add_torque_pair(B, A.body_frame(), s.add_unknown("T2") * A.body_frame().x());
    EXPECT_LT(compare_methods(sys, {q1, q2}, 3).max_difference, kAgree);
}

TEST(CompareMethods, RodAndPlateDoublePendulumAgrees) {
    // rod A hinged to N about Nz; plate B hinged to the rod's end about Ay
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    ex L = s.add_constant("L", 1.2), w = s.add_constant("w", 0.5), mA = s.add_constant("mA", 1.0),
       mB = s.add_constant("mB", 2.0);
    A.body_frame().orient_axis(sys.newtonian(), Axis::z, q1);
    B.body_frame().orient_axis(A.body_frame(), Axis::y, q2);
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), -(L / 2) * A.body_frame().y());
    sys.point("B_o").set_pos(sys.point("A_o"), -L * A.body_frame().y());
    B.cm().set_pos(sys.point("B_o"), -(w / 2) * B.body_frame().y() + (w / 2) * B.body_frame().x());
    A.set_mass(mA), B.set_mass(mB);
    A.set_inertia(A.cm(), mA * L * L / 12, 0, mA * L * L / 12);
    B.set_inertia(B.cm(), mB * w * w / 12, mB * w * w / 12, mB * w * w / 6);  // square plate
    sys.set_gravity(-s.add_constant("g", 9.81) * sys.newtonian().y());
    EXPECT_LT(compare_methods(sys, {q1, q2}, 3).max_difference, kAgree);
}

TEST(CompareMethods, FreeRigidBodyAgreesAndSatisfiesEulersEquations) {
    FreeBody f;
    EXPECT_LT(compare_methods(f.sys, f.q, 3).max_difference, kAgree);
    // with no loads, the solved accelerations make I.alpha + w x I.w vanish
    const Frame& N = f.sys.newtonian();
    const Frame& Bf = f.B->body_frame();
    std::vector<ex> acc{f.q[0].d(2), f.q[1].d(2), f.q[2].d(2)};
    LinearSystem L = form_linear_system(form_kane_equations(f.sys, f.q), acc);
    exmap state{{f.q[0], 0.3}, {f.q[1], -0.4}, {f.q[2], 1.2},
                {f.q[0].d(1), 0.7}, {f.q[1].d(1), -1.1}, {f.q[2].d(1), 0.5}};
    Eigen::VectorXd qdd = solve_numeric(f.sys.symbols(), L, state);
    for (int i = 0; i < 3; ++i) state[acc[static_cast<std::size_t>(i)]] = qdd(i);
    Vector w = Bf.ang_vel_in(N), alpha = Bf.ang_acc_in(N);
    const Dyadic& I = f.B->inertia();
    Col3 euler = (dot(I, alpha) + cross(w, dot(I, w))).components_in(Bf);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f.sys.symbols().evaluate(euler[i], state), 0.0, 1e-12);
}
