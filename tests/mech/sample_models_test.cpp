// SPDX-License-Identifier: MIT
// Tests of the sample models: the sit-to-stand triple pendulum, n-link chains and the
// mass-spring-damper, against kinematics, momenta, loads and energies derived by hand.
#include "alembert/mech/sample_models.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "alembert/error.hpp"
#include "support/expect.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;
using alembert::test::same;

using alembert::test::near;

// ---- the sit-to-stand triple pendulum --------------------------------------------------------

// The model and its symbols. Each segment i turns by the absolute angle th_i about Nz
// (th_A = qA, th_B = qA + qB, th_C = qA + qB + qC) and lies along its own y axis,
// e_i = (-sin th_i, cos th_i), so a point at distance l along it moves at l th_i' f_i with
// f_i = (-cos th_i, -sin th_i).
class SampleModelTriplePendulum : public ::testing::Test {
protected:
    Vector e(const ex& th) const { return -sin(th) * N.x() + cos(th) * N.y(); }
    Vector f(const ex& th) const { return -cos(th) * N.x() - sin(th) * N.y(); }

    SampleModel model = make_triple_pendulum();
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex qA = model.q.at(0), qB = model.q.at(1), qC = model.q.at(2);
    ex dqA = model.q.at(0).d(1), dqB = model.q.at(1).d(1), dqC = model.q.at(2).d(1);
    ex thB = qA + qB, thC = qA + qB + qC;
    ex wA = dqA, wB = dqA + dqB, wC = dqA + dqB + dqC;
    ex g = s.symbol("g"), L_A = s.symbol("L_A"), L_B = s.symbol("L_B");
    ex d_A = s.symbol("d_A"), d_B = s.symbol("d_B"), d_C = s.symbol("d_C");
    ex m_A = s.symbol("m_A"), m_B = s.symbol("m_B"), m_C = s.symbol("m_C");
    ex I_A = s.symbol("I_A"), I_B = s.symbol("I_B"), I_C = s.symbol("I_C");
    ex T_A = s.symbol("T_A"), T_B = s.symbol("T_B"), T_C = s.symbol("T_C");
    RigidBody& A = sys.rigid_body("A");
    RigidBody& B = sys.rigid_body("B");
    RigidBody& C = sys.rigid_body("C");
    const Point& A_o = sys.point("A_o");
};

TEST_F(SampleModelTriplePendulum, HasThreeJointsWithTheirCoordinatesTorquesAndLinks) {
    ASSERT_EQ(model.q.size(), 3u);
    EXPECT_EQ(model.q[0].name(), "qA");
    EXPECT_EQ(model.q[1].name(), "qB");
    EXPECT_EQ(model.q[2].name(), "qC");
    EXPECT_EQ(model.unknowns.size(), 3u);
    EXPECT_TRUE(model.unknowns[0].is_equal(T_A));
    EXPECT_EQ(model.links, (std::vector<RigidBody*>{&A, &B, &C}));
}

TEST_F(SampleModelTriplePendulum, AngularVelocitiesAddUpTheJointRates) {
    EXPECT_TRUE(same(A.body_frame().ang_vel_in(N), dqA * N.z(), N));
    EXPECT_TRUE(same(B.body_frame().ang_vel_in(N), (dqA + dqB) * N.z(), N));
    EXPECT_TRUE(same(C.body_frame().ang_vel_in(N), (dqA + dqB + dqC) * N.z(), N));
}

TEST_F(SampleModelTriplePendulum, SegmentAxesAreTurnedByTheAbsoluteAngles) {
    // A is qA about Nz from N: Ay = -sin(qA) Nx + cos(qA) Ny
    EXPECT_TRUE(same(A.body_frame().y(), -sin(qA) * N.x() + cos(qA) * N.y(), N));
    EXPECT_TRUE(same(C.body_frame().y(), e(thC), N));
}

TEST_F(SampleModelTriplePendulum, MassCentreVelocitiesMatchTheHandFormulas) {
    // v^{Acm} = d_A qA' (-cos qA, -sin qA)
    EXPECT_TRUE(same(A.cm().vel_in(N), d_A * wA * (-cos(qA) * N.x() - sin(qA) * N.y()), N));
    // v^{Bcm} = L_A wA f_A + d_B wB f_B
    EXPECT_TRUE(same(B.cm().vel_in(N), L_A * wA * f(qA) + d_B * wB * f(thB), N));
    // v^{Ccm} = L_A wA f_A + L_B wB f_B + d_C wC f_C
    EXPECT_TRUE(
        same(C.cm().vel_in(N), L_A * wA * f(qA) + L_B * wB * f(thB) + d_C * wC * f(thC), N));
}

TEST_F(SampleModelTriplePendulum, AngularMomentumAboutTheAnkleMatchesTheHandFormula) {
    // for points at sum_j l_j e_j moving at sum_k l_k th_k' f_k, (r x v) . Nz =
    // sum_jk l_j l_k th_k' cos(th_j - th_k); each segment adds I_i w_i
    ex H_A = (I_A + m_A * d_A * d_A) * wA;
    ex H_B = I_B * wB + m_B * (L_A * L_A * wA + d_B * d_B * wB + L_A * d_B * (wA + wB) * cos(qB));
    ex H_C =
        I_C * wC +
        m_C * (L_A * L_A * wA + L_B * L_B * wB + d_C * d_C * wC + L_A * L_B * (wA + wB) * cos(qB) +
               L_A * d_C * (wA + wC) * cos(qB + qC) + L_B * d_C * (wB + wC) * cos(qC));
    Vector H = sys.calc_angular_momentum(sys.bodies({"A", "B", "C"}), A_o);
    EXPECT_TRUE(same(H, (H_A + H_B + H_C) * N.z(), N));
    EXPECT_TRUE(same(A.calc_angular_momentum(A_o, N), H_A * N.z(), N));
    EXPECT_TRUE(same(C.calc_angular_momentum(A_o, N), H_C * N.z(), N));
}

TEST_F(SampleModelTriplePendulum,
       GravityMomentAboutTheAnkleMatchesTheHandFormulaAndOnlyTheAnkleTorqueIsExternal) {
    // the moment of -m g Ny at x along Nx is m g (-x) Nz, and each x is -sum l sin th
    ex M_gravity = g * ((m_A * d_A + (m_B + m_C) * L_A) * sin(qA) +
                        (m_B * d_B + m_C * L_B) * sin(thB) + m_C * d_C * sin(thC));
    LoadResultant R = sys.calc_resultant(sys.bodies({"A", "B", "C"}), A_o);
    EXPECT_TRUE(same(R.force, -(m_A + m_B + m_C) * g * N.y(), N));
    EXPECT_TRUE(same(R.moment, (T_A + M_gravity) * N.z(), N));
    // upright, gravity has no moment about the ankle
    GiNaC::exmap upright{{qA, 0}, {qB, 0}, {qC, 0}, {T_A, 0}};
    EXPECT_TRUE(near(s.evaluate(R.moment.components_in(N)[2], upright), 0.0));

    // the head-arms-trunk alone: the hip torque T_C and its own weight about the hip
    LoadResultant R_C = sys.calc_resultant(sys.bodies({"C"}), sys.point("C_o"));
    EXPECT_TRUE(same(R_C.moment, (T_C + g * m_C * d_C * sin(thC)) * N.z(), N));
    // the thigh alone: the knee torque on it, minus the hip torque it exerts on C
    LoadResultant R_B = sys.calc_resultant(sys.bodies({"B"}), sys.point("B_o"));
    EXPECT_TRUE(same(R_B.moment, (T_B - T_C + g * m_B * d_B * sin(thB)) * N.z(), N));
}

TEST_F(SampleModelTriplePendulum, TotalMassAndPotentialEnergyMatchTheSegments) {
    BodySet S = sys.bodies({"A", "B", "C"});
    EXPECT_TRUE(same(sys.calc_mass(S), m_A + m_B + m_C));
    // Winter's segment masses for a 70 kg person: 6.51 + 14.00 + 47.46 kg
    EXPECT_TRUE(near(s.evaluate(sys.calc_mass(S)), 67.97));
    // V = g times the height of each mass centre above the ankle
    ex V = g * (m_A * d_A * cos(qA) + m_B * (L_A * cos(qA) + d_B * cos(thB)) +
                m_C * (L_A * cos(qA) + L_B * cos(thB) + d_C * cos(thC)));
    EXPECT_TRUE(same(sys.calc_potential_energy(), V));
}

// ---- n-link pendulums ------------------------------------------------------------------------

TEST(SampleModelNLinkPendulum, OneLinkIsARodSwingingAboutItsEnd) {
    SampleModel model = make_n_link_pendulum(1);
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    ASSERT_EQ(model.q.size(), 1u);
    ex q = model.q[0], dq = model.q[0].d(1);
    ex m = s.symbol("m1"), L = s.symbol("L1"), g = s.symbol("g");
    // K = 1/2 (m L^2 / 3) q'^2; the centre hangs L/2 below N_o: V = -m g (L/2) cos q
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), m * L * L / 6 * dq * dq));
    EXPECT_TRUE(same(sys.calc_potential_energy(), -m * g * (L / 2) * cos(q)));
    EXPECT_EQ(model.links.size(), 1u);
    EXPECT_EQ(model.unknowns.size(), 1u);
}

TEST(SampleModelNLinkPendulum, TwoLinksHaveTheTextbookKineticEnergyInRelativeAngles) {
    SampleModel model = make_n_link_pendulum(2, ChainKind::planar);
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    ASSERT_EQ(model.q.size(), 2u);
    ex q2 = model.q[1], w1 = model.q[0].d(1), w2 = model.q[0].d(1) + model.q[1].d(1);
    ex m1 = s.symbol("m1"), m2 = s.symbol("m2"), L1 = s.symbol("L1"), L2 = s.symbol("L2");
    // link 2 turns at w2 = q1' + q2'; its centre moves at L1 q1' (link 1 direction) plus
    // L2/2 w2 (link 2 direction), at the angle q2 between them:
    // K = 1/2 (m1 L1^2/3) q1'^2 + 1/2 m2 (L1^2 q1'^2 + L2^2/4 w2^2 + L1 L2 q1' w2 cos q2)
    //     + 1/2 (m2 L2^2/12) w2^2
    ex K = m1 * L1 * L1 * w1 * w1 / 6 +
           m2 / 2 * (L1 * L1 * w1 * w1 + L2 * L2 / 4 * w2 * w2 + L1 * L2 * w1 * w2 * cos(q2)) +
           m2 * L2 * L2 * w2 * w2 / 24;
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), K));
}

TEST(SampleModelNLinkPendulum, SpatialOneLinkIsASphericalPendulum) {
    SampleModel model = make_n_link_pendulum(1, ChainKind::spatial);
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    ASSERT_EQ(model.q.size(), 2u);
    ex qx = model.q[1], dqz = model.q[0].d(1), dqx = model.q[1].d(1);
    ex m = s.symbol("m1"), L = s.symbol("L1");
    // w = qz' Nz + qx' Bx = (qx', qz' sin qx, qz' cos qx) in B; about the end the rod has
    // mL^2/3 about Bx and Bz: K = (m L^2 / 6) (qx'^2 + qz'^2 cos^2 qx)
    ex K = m * L * L / 6 * (dqx * dqx + pow(dqz * cos(qx), 2));
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), K));
}

TEST(SampleModelNLinkPendulum,
     SpatialThreeLinkChainHasSixCoordinatesAndItsJointTorquesAreInternal) {
    SampleModel model = make_n_link_pendulum(3, ChainKind::spatial);
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ASSERT_EQ(model.q.size(), 6u);
    const char* names[] = {"qz1", "qx1", "qz2", "qx2", "qz3", "qx3"};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(model.q[static_cast<std::size_t>(i)].name(), names[i]);
    ASSERT_EQ(model.unknowns.size(), 6u);
    ASSERT_EQ(model.links.size(), 3u);

    // hanging straight down, the last centre is L1 + L2 + L3/2 below N_o
    GiNaC::exmap zero;
    for (const TimeVariable& q : model.q) zero[q.symbol()] = 0;
    Col3 p_N = model.links[2]->cm().pos_from(sys.origin()).components_in(N);
    Vector p(N, p_N.map([&](const ex& c) { return c.subs(zero); }));
    EXPECT_TRUE(same(p, -(s.symbol("L1") + s.symbol("L2") + s.symbol("L3") / 2) * N.y(), N));

    // over the whole chain only the torques of the first joint (from N) remain:
    // Tz1 about Nz and Tx1 about B1x = cos(qz1) Nx + sin(qz1) Ny
    LoadResultant R = sys.calc_resultant(sys.bodies(), sys.origin());
    ex qz1 = model.q[0];
    EXPECT_TRUE(same(R.moment.diff(s.symbol("Tz1")), N.z(), N));
    EXPECT_TRUE(same(R.moment.diff(s.symbol("Tx1")), cos(qz1) * N.x() + sin(qz1) * N.y(), N));
    for (const char* T : {"Tz2", "Tx2", "Tz3", "Tx3"})
        EXPECT_TRUE(same(R.moment.diff(s.symbol(T)), Vector(), N)) << T;
}

TEST(SampleModelPlanarChain, TwoUprightLinksHaveTheTextbookEnergies) {
    SampleModel model = make_planar_chain(2);
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    ASSERT_EQ(model.q.size(), 2u);
    ex q1 = model.q[0], q2 = model.q[1], d1 = model.q[0].d(1), d2 = model.q[1].d(1);
    ex g = s.symbol("g");
    exmap unit{{s.symbol("L1"), 1}, {s.symbol("L2"), 1}, {s.symbol("m1"), 1}, {s.symbol("m2"), 1}};
    // unit rods (1 m, 1 kg) standing on N_o: centres at heights cos(q1)/2 and cos(q1) + cos(q1 + q2)/2
    EXPECT_TRUE(same(sys.calc_potential_energy().subs(unit), g * (cos(q1) / 2 + cos(q1) + cos(q1 + q2) / 2)));
    // K = 1/2 (1/3) q1'^2 + 1/2 [q1'^2 + q1' (q1' + q2') cos q2 + (q1' + q2')^2 / 3]
    ex w2 = d1 + d2;
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()).subs(unit),
                     d1 * d1 / 6 + (d1 * d1 + d1 * w2 * cos(q2) + w2 * w2 / 3) / 2));
}

TEST(SampleModelPlanarChain, AChainWithoutLinksIsAnArgumentError) {
    EXPECT_THROW_MSG(make_planar_chain(0), ArgumentError,
                     "make_planar_chain(): a chain needs at least one link, not 0");
}

TEST(SampleModelNLinkPendulum, AChainWithoutLinksIsAnArgumentError) {
    EXPECT_THROW_MSG(make_n_link_pendulum(0), ArgumentError,
                     "make_n_link_pendulum(): a chain needs at least one link, not 0");
    EXPECT_THROW_MSG(make_n_link_pendulum(-2, ChainKind::spatial), ArgumentError,
                     "at least one link, not -2");
}

// ---- mass-spring-damper --------------------------------------------------------------------

TEST(SampleModelMassSpringDamper, ResultantIsTheSpringAndDamperForceAlongNx) {
    SampleModel model = make_mass_spring_damper();
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ASSERT_EQ(model.q.size(), 1u);
    ex x = model.q[0], dx = model.q[0].d(1);
    ex m = s.symbol("m"), k = s.symbol("k"), c = s.symbol("c");

    LoadResultant R = sys.calc_resultant(sys.bodies(), sys.origin());
    EXPECT_TRUE(same(R.force, (-k * x - c * dx) * N.x(), N));
    EXPECT_TRUE(same(R.moment, Vector(), N));
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), m * dx * dx / 2));
    EXPECT_TRUE(same(sys.calc_potential_energy(), k * x * x / 2));
    // the stated values: m = 1, k = 4, c = 0.4
    EXPECT_TRUE(
        near(s.evaluate(R.force.components_in(N)[0], {{x, 0.5}, {dx, -1.0}}), -4.0 * 0.5 + 0.4));
}

}  // namespace
}  // namespace alembert
