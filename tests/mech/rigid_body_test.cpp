// SPDX-License-Identifier: MIT
// Tests of rigid bodies and particles: inertia and the parallel-axis transfer, linear and
// angular momentum about moving points, kinetic energy; all against hand derivations.
#include "alembert/mech/rigid_body.hpp"

#include <gtest/gtest.h>

#include "alembert/error.hpp"
#include "alembert/mech/inertia.hpp"
#include "alembert/mech/system.hpp"
#include "support/expect.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::numeric;
using GiNaC::pow;
using GiNaC::sin;
using alembert::test::same;

// The symmetric matrix [[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]].
Mat3 sym_matrix(const ex& xx, const ex& yy, const ex& zz, const ex& xy, const ex& yz,
                const ex& zx) {
    Mat3 m;
    m(0, 0) = xx, m(1, 1) = yy, m(2, 2) = zz;
    m(0, 1) = m(1, 0) = xy;
    m(1, 2) = m(2, 1) = yz;
    m(2, 0) = m(0, 2) = zx;
    return m;
}

// Element-wise semantic equality of two 3x3 matrices.
::testing::AssertionResult same_matrix(const Mat3& a, const Mat3& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (auto r = same(a(i, j), b(i, j)); !r) return r << " at (" << i << ", " << j << ")";
    return ::testing::AssertionSuccess();
}

// ---- inertia and the parallel-axis transfer --------------------------------------------------

// A body B turning about Nz by q, with its origin B_o at N_o.
class RigidBodyTurningAboutNz : public ::testing::Test {
protected:
    RigidBodyTurningAboutNz() {
        B.body_frame().orient_axis(N, Axis::z, q);
        sys.point("B_o").set_pos(sys.origin(), Vector());
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m"), L = s.add_constant("L");
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Bf = B.body_frame();
    Point& Bo = sys.point("B_o");
};

TEST_F(RigidBodyTurningAboutNz, RodInertiaAboutItsEndTransfersToTheCentralOne) {
    // a thin rod along By from B_o, mass centre at L/2: about the end mL^2/3 about x and z
    B.cm().set_pos(Bo, (L / 2) * Bf.y());
    B.set_mass(m);
    B.set_inertia(Bo, m * L * L / 3, 0, m * L * L / 3);
    // central: mL^2/3 - m (L/2)^2 = mL^2/12
    Mat3 I_BBcm = sym_matrix(m * L * L / 12, 0, m * L * L / 12, 0, 0, 0);
    EXPECT_TRUE(same_matrix(B.inertia().components_in(Bf), I_BBcm));
    // and back to the end
    Mat3 I_BBo = sym_matrix(m * L * L / 3, 0, m * L * L / 3, 0, 0, 0);
    EXPECT_TRUE(same_matrix(B.calc_inertia_about(Bo).components_in(Bf), I_BBo));
    EXPECT_TRUE(same_matrix(B.calc_inertia_about(B.cm()).components_in(Bf), I_BBcm));
}

TEST_F(RigidBodyTurningAboutNz, InertiaAboutAPointOffsetInTwoAxesAddsMomentsAndProducts) {
    ex a = s.add_constant("a"), b = s.add_constant("b");
    ex Ixx = s.add_constant("Ixx"), Iyy = s.add_constant("Iyy"), Izz = s.add_constant("Izz"),
       Ixy = s.add_constant("Ixy"), Iyz = s.add_constant("Iyz"), Izx = s.add_constant("Izx");
    // the mass centre is at (a, b, 0) in B from B_o
    B.cm().set_pos(Bo, a * Bf.x() + b * Bf.y());
    B.set_mass(m);
    B.set_inertia(B.cm(), Ixx, Iyy, Izz, Ixy, Iyz, Izx);
    EXPECT_TRUE(
        same_matrix(B.inertia().components_in(Bf), sym_matrix(Ixx, Iyy, Izz, Ixy, Iyz, Izx)));
    // I^{B/Bo}_ij = I^{B/Bcm}_ij + m (r.r delta_ij - r_i r_j), r = (a, b, 0)
    Mat3 I_BBo = sym_matrix(Ixx + m * b * b, Iyy + m * a * a, Izz + m * (a * a + b * b),
                            Ixy - m * a * b, Iyz, Izx);
    EXPECT_TRUE(same_matrix(B.calc_inertia_about(Bo).components_in(Bf), I_BBo));
}

TEST_F(RigidBodyTurningAboutNz, InertiaTransferUsesTheOffsetAsSeenInTheBody) {
    // offset written in N while B is turned by q: in B, r = (a cos q, -a sin q, 0)
    ex a = s.add_constant("a"), J = s.add_constant("J");
    B.cm().set_pos(Bo, a * N.x());
    B.set_mass(m);
    B.set_inertia(B.cm(), J, J, J);
    ex rx = a * cos(q), ry = -a * sin(q);
    Mat3 I_BBo = sym_matrix(J + m * ry * ry, J + m * rx * rx, J + m * a * a, -m * rx * ry, 0, 0);
    EXPECT_TRUE(same_matrix(B.calc_inertia_about(Bo).components_in(Bf), I_BBo));
}

TEST_F(RigidBodyTurningAboutNz, InertiaGivenAsADyadicIsStoredAboutTheMassCentre) {
    ex J1 = s.add_constant("J1"), J2 = s.add_constant("J2"), J3 = s.add_constant("J3");
    B.cm().set_pos(Bo, L * Bf.z());
    B.set_mass(m);
    // about B_o the mass centre is L along Bz: central = given - m L^2 about x and y
    B.set_inertia(Bo, inertia_dyadic(Bf, J1, J2, J3));
    EXPECT_TRUE(B.has_inertia());
    EXPECT_TRUE(same_matrix(B.inertia().components_in(Bf),
                            sym_matrix(J1 - m * L * L, J2 - m * L * L, J3, 0, 0, 0)));
}

TEST_F(RigidBodyTurningAboutNz, InertiaAboutAnotherPointBeforeTheMassIsAnErrorNamingTheBody) {
    B.cm().set_pos(Bo, (L / 2) * Bf.y());
    EXPECT_THROW_MSG(B.set_inertia(Bo, 1, 0, 1), ModelError,
                     "the inertia of 'B' is given about 'B_o', not its mass centre");
    EXPECT_THROW_MSG(B.set_inertia(Bo, 1, 0, 1), ModelError, "call B.set_mass(...) first");
    EXPECT_FALSE(B.has_inertia());
}

TEST_F(RigidBodyTurningAboutNz, InertiaNeverSetIsAnErrorNamingTheBody) {
    B.set_mass(m);
    EXPECT_THROW_MSG(B.inertia(), ModelError, "the inertia of 'B' is not set");
    EXPECT_THROW_MSG(B.calc_kinetic_energy(N), ModelError, "the inertia of 'B' is not set");
}

TEST_F(RigidBodyTurningAboutNz, MomentumAndEnergyOfABodyWithoutMassAreErrorsNamingIt) {
    B.cm().set_pos(Bo, (L / 2) * Bf.y());
    B.set_inertia(B.cm(), 1, 0, 1);
    EXPECT_FALSE(B.has_mass());
    EXPECT_THROW_MSG(B.mass(), ModelError, "mass of 'B' is not set");
    EXPECT_THROW_MSG(B.calc_linear_momentum(N), ModelError, "mass of 'B' is not set");
    EXPECT_THROW_MSG(B.calc_angular_momentum(Bo, N), ModelError, "mass of 'B' is not set");
    EXPECT_THROW_MSG(B.calc_kinetic_energy(N), ModelError, "mass of 'B' is not set");
    EXPECT_THROW_MSG(B.calc_inertia_about(Bo), ModelError, "mass of 'B' is not set");

    Particle& Q = sys.add_particle("Q");
    Q.cm().set_pos(sys.origin(), L * N.x());
    EXPECT_THROW_MSG(Q.calc_linear_momentum(N), ModelError, "mass of 'Q' is not set");
    EXPECT_THROW_MSG(Q.calc_angular_momentum(Bo, N), ModelError, "mass of 'Q' is not set");
    EXPECT_THROW_MSG(Q.calc_kinetic_energy(N), ModelError, "mass of 'Q' is not set");
}

TEST_F(RigidBodyTurningAboutNz, RodPendulumEnergyIsThatOfRotationAboutItsEnd) {
    B.cm().set_pos(Bo, (L / 2) * Bf.y());
    B.set_mass(m);
    B.set_inertia(B.cm(), m * L * L / 12, 0, m * L * L / 12);
    // K = 1/2 (m L^2 / 3) q'^2
    EXPECT_TRUE(same(B.calc_kinetic_energy(N), m * L * L * pow(q.d(1), 2) / 6));
    // H^{B/Bo} = (m L^2 / 3) q' Nz; about the mass centre only the central part (mL^2/12) q'
    EXPECT_TRUE(same(B.calc_angular_momentum(Bo, N), m * L * L / 3 * q.d(1) * N.z(), N));
    EXPECT_TRUE(same(B.calc_angular_momentum(B.cm(), N), m * L * L / 12 * q.d(1) * N.z(), N));
    // L = m v^{Bcm} = m (L/2) q' (-cos q, -sin q)
    EXPECT_TRUE(same(B.calc_linear_momentum(N),
                     m * (L / 2) * q.d(1) * (-cos(q) * N.x() - sin(q) * N.y()), N));
}

TEST(RigidBody, SphericalRodEnergyIsThatOfRotationAboutTheFixedEnd) {
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable qz = s.add_variable("qz"), qx = s.add_variable("qx");
    ex m = s.add_constant("m"), L = s.add_constant("L");
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Bf = B.body_frame();
    Bf.orient_body_fixed(N, RotationSequence::ZXY, qz, qx, 0);
    sys.point("B_o").set_pos(sys.origin(), Vector());
    B.cm().set_pos(sys.point("B_o"), (L / 2) * Bf.y());
    B.set_mass(m);
    B.set_inertia(B.cm(), m * L * L / 12, 0, m * L * L / 12);
    // w = qz' Nz + qx' Bx, and Nz = sin(qx) By + cos(qx) Bz, so in B:
    // w = (qx', qz' sin qx, qz' cos qx); with I_Bo = diag(mL^2/3, 0, mL^2/3),
    // K = 1/2 w.I_Bo.w = (m L^2 / 6) (qx'^2 + qz'^2 cos^2 qx)
    ex K = m * L * L / 6 * (pow(qx.d(1), 2) + pow(qz.d(1) * cos(qx), 2));
    EXPECT_TRUE(same(B.calc_kinetic_energy(N), K));
}

TEST(RigidBody, DoublePendulumOfRodsHasTheTextbookKineticEnergy) {
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th1 = s.add_variable("th1"), th2 = s.add_variable("th2");
    ex m1 = s.add_constant("m1"), m2 = s.add_constant("m2"), L1 = s.add_constant("L1"),
       L2 = s.add_constant("L2");
    RigidBody& B1 = sys.add_rigid_body("B1");
    RigidBody& B2 = sys.add_rigid_body("B2");
    // absolute angles from the downward vertical: each rod hangs along its own -y axis
    B1.body_frame().orient_axis(N, Axis::z, th1);
    B2.body_frame().orient_axis(N, Axis::z, th2);
    sys.point("B1_o").set_pos(sys.origin(), Vector());
    sys.point("B2_o").set_pos(sys.point("B1_o"), -L1 * B1.body_frame().y());
    B1.cm().set_pos(sys.point("B1_o"), -(L1 / 2) * B1.body_frame().y());
    B2.cm().set_pos(sys.point("B2_o"), -(L2 / 2) * B2.body_frame().y());
    B1.set_mass(m1), B2.set_mass(m2);
    B1.set_inertia(B1.cm(), m1 * L1 * L1 / 12, 0, m1 * L1 * L1 / 12);
    B2.set_inertia(B2.cm(), m2 * L2 * L2 / 12, 0, m2 * L2 * L2 / 12);

    // K1 = 1/2 (m1 L1^2/3) th1'^2
    // K2 = 1/2 m2 (L1^2 th1'^2 + L2^2/4 th2'^2 + L1 L2 th1' th2' cos(th1 - th2))
    //      + 1/2 (m2 L2^2/12) th2'^2
    ex w1 = th1.d(1), w2 = th2.d(1);
    ex K1 = m1 * L1 * L1 * w1 * w1 / 6;
    ex K2 =
        m2 / 2 * (L1 * L1 * w1 * w1 + L2 * L2 / 4 * w2 * w2 + L1 * L2 * w1 * w2 * cos(th1 - th2)) +
        m2 * L2 * L2 * w2 * w2 / 24;
    EXPECT_TRUE(same(B1.calc_kinetic_energy(N), K1));
    EXPECT_TRUE(same(B2.calc_kinetic_energy(N), K2));
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), K1 + K2));
}

// ---- angular momentum about a moving point ---------------------------------------------------

// An off-centre disk D on a precessing arm: frame A turns about Nz by psi, D spins about Ay by
// phi; D_o is R_ along Ax, the mass centre is e along Dx and h along Dz from D_o; the central
// inertia has all six elements. O slides along Nx at s from N_o.
class RigidBodyOffCentreDisk : public ::testing::Test {
protected:
    RigidBodyOffCentreDisk() {
        A.orient_axis(N, Axis::z, psi);
        Df.orient_axis(A, Axis::y, phi);
        sys.point("D_o").set_pos(sys.origin(), R_ * A.x());
        D.cm().set_pos(sys.point("D_o"), e * Df.x() + h * Df.z());
        O.set_pos(sys.origin(), sv * N.x());
        D.set_mass(m);
        D.set_inertia(D.cm(), Ixx, Iyy, Izz, Ixy, Iyz, Izx);
    }

    // w = psi' Az + phi' Ay; Az = -sin(phi) Dx + cos(phi) Dz, so in D:
    Col3 w_ND_D() const { return {{-psi.d(1) * sin(phi), phi.d(1), psi.d(1) * cos(phi)}}; }
    // I.w written out in D
    Vector I_dot_w() const {
        Col3 w = w_ND_D();
        return Vector(Df,
                      {{Ixx * w[0] + Ixy * w[1] + Izx * w[2], Ixy * w[0] + Iyy * w[1] + Iyz * w[2],
                        Izx * w[0] + Iyz * w[1] + Izz * w[2]}});
    }
    // v^{Dcm} in A: with rho = e Dx + h Dz = (e c + h s, 0, h c - e s) in A and w = (0, phi',
    // psi') in A, v = R_ psi' Ay + w x rho
    Vector v_NDcm() const {
        ex c = cos(phi), sn = sin(phi);
        return Vector(A, {{phi.d(1) * (h * c - e * sn), R_ * psi.d(1) + psi.d(1) * (e * c + h * sn),
                           -phi.d(1) * (e * c + h * sn)}});
    }
    Vector p_ODcm() const {
        ex c = cos(phi), sn = sin(phi);
        return Vector(A, {{R_ + e * c + h * sn, 0, h * c - e * sn}}) - sv * N.x();
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable psi = s.add_variable("psi"), phi = s.add_variable("phi"), sv = s.add_variable("s");
    ex R_ = s.add_constant("R_"), e = s.add_constant("e"), h = s.add_constant("h"),
       m = s.add_constant("m");
    ex Ixx = s.add_constant("Ixx"), Iyy = s.add_constant("Iyy"), Izz = s.add_constant("Izz"),
       Ixy = s.add_constant("Ixy"), Iyz = s.add_constant("Iyz"), Izx = s.add_constant("Izx");
    Frame& A = sys.add_frame("A");
    RigidBody& D = sys.add_rigid_body("D");
    Frame& Df = D.body_frame();
    Point& O = sys.add_point("O");
};

TEST_F(RigidBodyOffCentreDisk, MassCentreVelocityMatchesTheHandFormula) {
    EXPECT_TRUE(same(D.cm().vel_in(N), v_NDcm(), N));
    EXPECT_TRUE(same(D.calc_linear_momentum(N), m * v_NDcm(), A));
}

TEST_F(RigidBodyOffCentreDisk, AngularMomentumAboutTheMassCentreIsInertiaDotOmega) {
    EXPECT_TRUE(same(D.calc_angular_momentum(D.cm(), N), I_dot_w(), Df));
}

TEST_F(RigidBodyOffCentreDisk, AngularMomentumAboutAMovingPointMatchesItsDefinition) {
    // H^{D/O} = I^{D/Dcm} . w + r^{Dcm/O} x m v^{Dcm}
    Vector H = I_dot_w() + cross(p_ODcm(), m * v_NDcm());
    EXPECT_TRUE(same(D.calc_angular_momentum(O, N), H, N));
    EXPECT_TRUE(same(D.calc_angular_momentum(O, N), H, Df));
}

TEST_F(RigidBodyOffCentreDisk, KineticEnergyIsTranslationPlusRotationAboutTheMassCentre) {
    // K = 1/2 m v.v + 1/2 w.I.w, with both written out in components
    Col3 v = v_NDcm().components_in(A), w = w_ND_D(), Iw = I_dot_w().components_in(Df);
    ex K = m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / 2 +
           (w[0] * Iw[0] + w[1] * Iw[1] + w[2] * Iw[2]) / 2;
    EXPECT_TRUE(same(D.calc_kinetic_energy(N), K));
}

// A rigid body B equal to three particles fixed on it, and the particles themselves. B turns
// by body-fixed XYZ angles q1, q2, q3 in N, its origin B_o moves in the Nx-Ny plane at (x, y),
// and the reference point O slides along Ny at u from N_o.
class RigidBodyOfParticles : public ::testing::Test {
protected:
    RigidBodyOfParticles() {
        Bf.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
        Bo.set_pos(sys.origin(), x * N.x() + y * N.y());
        O.set_pos(sys.origin(), u * N.y());
        // masses 1, 2, 3 at rho_1 = (1, 2, 0), rho_2 = (-1, 0, 1), rho_3 = (0, -1, -1) in B
        // from B_o; the mass centre is sum m rho / 6 = (-1, -1, -1)/6
        const int mass[3] = {1, 2, 3};
        const int rho[3][3] = {{1, 2, 0}, {-1, 0, 1}, {0, -1, -1}};
        for (int i = 0; i < 3; ++i) {
            Particle& P = sys.add_particle("P" + std::to_string(i + 1));
            P.set_mass(mass[i]);
            P.cm().set_pos(Bo, Vector(Bf, {{rho[i][0], rho[i][1], rho[i][2]}}));
            particles.push_back(&P);
        }
        B.cm().set_pos(Bo, Vector(Bf, {{numeric(-1, 6), numeric(-1, 6), numeric(-1, 6)}}));
        B.set_mass(6);
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2"), q3 = s.add_variable("q3"),
                 x = s.add_variable("x"), y = s.add_variable("y"), u = s.add_variable("u");
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Bf = B.body_frame();
    Point& Bo = sys.point("B_o");
    Point& O = sys.add_point("O");
    std::vector<const Particle*> particles;
};

TEST_F(RigidBodyOfParticles, CentralInertiaFromAboutTheOriginMatchesTheParticleSums) {
    // about B_o: Ixx = sum m (y^2 + z^2) = 4 + 2 + 6 = 12, Iyy = 1 + 4 + 3 = 8,
    // Izz = 5 + 2 + 3 = 10, Ixy = -sum m x y = -2, Iyz = -sum m y z = -3, Izx = -sum m z x = 2
    B.set_inertia(Bo, 12, 8, 10, -2, -3, 2);
    // central, from the positions relative to the mass centre d_i = rho_i - (-1,-1,-1)/6:
    // d1 = (7, 13, 1)/6, d2 = (-5, 1, 7)/6, d3 = (1, -5, -5)/6, so
    // Ixx = (170 + 2*50 + 3*50)/36 = 35/3, Iyy = (50 + 2*74 + 3*26)/36 = 23/3,
    // Izz = (218 + 2*26 + 3*26)/36 = 29/3, Ixy = -(91 - 2*5 - 3*5)/36 = -11/6,
    // Iyz = -(13 + 2*7 + 3*25)/36 = -17/6, Izx = -(7 - 2*35 - 3*5)/36 = 13/6
    Mat3 I_BBcm = sym_matrix(numeric(35, 3), numeric(23, 3), numeric(29, 3), numeric(-11, 6),
                             numeric(-17, 6), numeric(13, 6));
    EXPECT_TRUE(same_matrix(B.inertia().components_in(Bf), I_BBcm));
}

TEST_F(RigidBodyOfParticles, AngularMomentumAboutAMovingPointEqualsTheSumOverItsParticles) {
    B.set_inertia(B.cm(), numeric(35, 3), numeric(23, 3), numeric(29, 3), numeric(-11, 6),
                  numeric(-17, 6), numeric(13, 6));
    // the definition: H^{S/O} = sum r^{Pi/O} x m_i ^N v^{Pi}, velocities by differentiation
    Vector H, L;
    ex K = 0;
    for (const Particle* P : particles) {
        Vector v = P->point().vel_in(N);
        H += cross(P->point().pos_from(O), P->mass() * v);
        L += P->mass() * v;
        K += P->mass() * dot(v, v) / 2;
    }
    EXPECT_TRUE(same(B.calc_angular_momentum(O, N), H, N));
    EXPECT_TRUE(same(B.calc_linear_momentum(N), L, N));
    EXPECT_TRUE(same(B.calc_kinetic_energy(N), K));

    // the particles' own momenta, one by one and as a system, say the same
    BodySet S(particles.begin(), particles.end());
    EXPECT_TRUE(same(sys.calc_angular_momentum(S, O), H, N));
    EXPECT_TRUE(same(sys.calc_linear_momentum(S), L, N));
    EXPECT_TRUE(same(sys.calc_kinetic_energy(S), K));
    EXPECT_TRUE(same(sys.calc_mass(S), 6));
    EXPECT_TRUE(same(sys.calc_cm_pos(S, Bo), B.cm().pos_from(Bo), Bf));
}

}  // namespace
}  // namespace alembert
