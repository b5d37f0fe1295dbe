// SPDX-License-Identifier: MIT
// Frame orientation trees: rotation matrices along tree paths, angular velocity and angular
// acceleration, checked against textbook formulas and hand derivations (Kane 1985, ch. 1-2).
#include "alembert/vec/frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::sin;
using test::same;

// ---- hand-written helpers (independent of the library's rotation code) -------------------

/// R_PB of a simple rotation by `q` about axis `a`, entries written out by hand.
Mat3 rot(Axis a, const ex& q) {
    ex c = cos(q), s = sin(q);
    Mat3 R;
    switch (a) {
        case Axis::x:
            R.m = {1, 0, 0, 0, c, -s, 0, s, c};
            break;
        case Axis::y:
            R.m = {c, 0, s, 0, 1, 0, -s, 0, c};
            break;
        case Axis::z:
            R.m = {c, -s, 0, s, c, 0, 0, 0, 1};
            break;
    }
    return R;
}

/// Product of two 3x3 matrices, written out so the test does not lean on Mat3's operator.
Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            ex sum = 0;
            for (int k = 0; k < 3; ++k) sum += a(i, k) * b(k, j);
            r(i, j) = sum;
        }
    return r;
}

Mat3 transposed(const Mat3& a) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = a(j, i);
    return r;
}

/// The angular velocity of B in P, in B, from R = R_PB: skew(w) = R^T dR/dt (Kane 1985,
/// eq. 2.1.1), each entry of dR/dt taken with the symbol table's chain rule.
Col3 ang_vel_from_dcm(SymbolTable& s, const Mat3& R) {
    Mat3 Rdot = R;
    for (ex& e : Rdot.m) e = s.dt(e);
    Mat3 W = mul(transposed(R), Rdot);
    return Col3{{W(2, 1), W(0, 2), W(1, 0)}};
}

::testing::AssertionResult same_mat(const Mat3& a, const Mat3& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            auto r = same(a(i, j), b(i, j));
            if (!r) return r << " (entry " << i << "," << j << ")";
        }
    return ::testing::AssertionSuccess();
}

/// Expects the columns a and b to agree at `points` random values of all their symbols
/// (angles and rates drawn from [-pi, pi]).
void expect_agree_numerically(const SymbolTable& s, const Col3& a, const Col3& b, int points = 8) {
    GiNaC::exset syms;
    for (int i = 0; i < 3; ++i) {
        auto sa = symbols_of(a[i]), sb = symbols_of(b[i]);
        syms.insert(sa.begin(), sa.end());
        syms.insert(sb.begin(), sb.end());
    }
    std::mt19937 rng(7u + static_cast<unsigned>(syms.size()));
    std::uniform_real_distribution<double> value(-std::numbers::pi, std::numbers::pi);
    for (int k = 0; k < points; ++k) {
        exmap at;
        for (const ex& sym : syms) at[sym] = value(rng);
        for (int i = 0; i < 3; ++i) {
            double va = s.evaluate(a[i], at), vb = s.evaluate(b[i], at);
            EXPECT_NEAR(va, vb, 1e-12) << "component " << i << " at point " << k;
        }
    }
}

struct Angles {
    ex q1, q2, q3, u1, u2, u3;  // angles and their rates
};

Angles three_angles(SymbolTable& s) {
    TimeVariable q1 = s.add_variable("q1", 2), q2 = s.add_variable("q2", 2),
                 q3 = s.add_variable("q3", 2);
    return {q1.symbol(), q2.symbol(), q3.symbol(), q1.d(1), q2.d(1), q3.d(1)};
}

// ---- rotation matrices along tree paths --------------------------------------------------

TEST(Frame, RotationBetweenSiblingBranchesIsProductThroughCommonParent) {
    SymbolTable s;
    ex qa = s.add_variable("qa", 2), qb = s.add_variable("qb", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, qa);
    B.orient_axis(N, Axis::x, qb);
    // R_AB = R_NA^T R_NB with R_NA = Rz(qa), R_NB = Rx(qb), multiplied out by hand
    ex ca = cos(qa), sa = sin(qa), cb = cos(qb), sb = sin(qb);
    Mat3 expected;
    // clang-format off
    expected.m = {ca,  sa * cb, -sa * sb,
                  -sa, ca * cb, -ca * sb,
                  0,   sb,      cb};
    // clang-format on
    EXPECT_TRUE(same_mat(rotation_matrix(A, B), expected));
    EXPECT_TRUE(same_mat(rotation_matrix(B, A), transposed(expected)));
}

TEST(Frame, SameAxisRotationsAlongAChainFoldIntoOneAngle) {
    // a planar chain of relative angles: R_NC = Rz(qa) Rz(qb) Rz(qc) = Rz(qa + qb + qc), and
    // between branches R_BC' = Rz(-qb) Rz(qc') with entries cos(qc' - qb)
    SymbolTable s;
    ex qa = s.add_variable("qa", 2), qb = s.add_variable("qb", 2), qc = s.add_variable("qc", 2);
    ex qd = s.add_variable("qd", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B"), C(s, "C"), D(s, "D");
    A.orient_axis(N, Axis::z, qa);
    B.orient_axis(A, Axis::z, qb);
    C.orient_axis(B, Axis::z, qc);
    D.orient_axis(A, Axis::z, qd);
    Mat3 R = rotation_matrix(N, C);
    EXPECT_TRUE(same_mat(R, rot(Axis::z, qa + qb + qc)));
    // folded, not multiplied out: each entry is a single cos or sin of the angle sum
    EXPECT_TRUE(R(0, 0).is_equal(cos(qa + qb + qc)));
    EXPECT_TRUE(same_mat(rotation_matrix(B, D), rot(Axis::z, qd - qb)));
    EXPECT_TRUE(rotation_matrix(B, D)(0, 0).is_equal(rotation_matrix(D, B)(0, 0)));
    // a rotation and its inverse cancel to the identity exactly
    Frame E(s, "E");
    E.orient_axis(A, Axis::z, qb);
    Mat3 I = rotation_matrix(B, E), J = Mat3::identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_TRUE(I(i, j).is_equal(J(i, j)));
}

TEST(Frame, CosineOfANegatedAngleIsWrittenOnce) {
    // cos(-q) and cos(q) are one function: the child-to-parent and parent-to-child matrices
    // must not carry both, or sums of them would not combine
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    Frame N(s, "N"), A(s, "A");
    A.orient_axis(N, Axis::z, q, Sense::negative);
    EXPECT_TRUE(rotation_matrix(N, A)(0, 0).is_equal(cos(q)));
    EXPECT_TRUE(rotation_matrix(N, A)(1, 0).is_equal(-sin(q)));
    EXPECT_TRUE(same_mat(rotation_matrix(N, A), rot(Axis::z, -q)));
}

TEST(Frame, RotationMatricesInOppositeDirectionsAreInverses) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    ex q4 = s.add_variable("q4", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B"), C(s, "C");
    A.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    B.orient_space_fixed(N, RotationSequence::ZXZ, q3, q1, q4);
    C.orient_axis(B, Axis::y, q4);
    const Mat3 I = Mat3::identity();
    EXPECT_TRUE(same_mat(mul(rotation_matrix(A, C), rotation_matrix(C, A)), I));
    EXPECT_TRUE(same_mat(mul(rotation_matrix(C, A), rotation_matrix(A, C)), I));
    EXPECT_TRUE(same_mat(mul(rotation_matrix(N, C), rotation_matrix(C, N)), I));
    EXPECT_TRUE(same_mat(rotation_matrix(A, A), I));
}

TEST(Frame, BodyXYZRotationMatrixMatchesKaneTable) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B");
    B.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    ex c1 = cos(q1), s1 = sin(q1), c2 = cos(q2), s2 = sin(q2), c3 = cos(q3), s3 = sin(q3);
    // Kane, Likins & Levinson 1983, body-three 1-2-3: row i, column j is n_i . b_j
    Mat3 expected;
    // clang-format off
    expected.m = {c2 * c3,                 -c2 * s3,                 s2,
                  s1 * s2 * c3 + s3 * c1,  -s1 * s2 * s3 + c3 * c1,  -s1 * c2,
                  -c1 * s2 * c3 + s3 * s1, c1 * s2 * s3 + c3 * s1,   c1 * c2};
    // clang-format on
    EXPECT_TRUE(same_mat(rotation_matrix(N, B), expected));
}

TEST(Frame, SpaceFixedSequenceEqualsReversedBodyFixedSequence) {
    // rotating about the parent's axes 1, 2, 3 by q1, q2, q3 lands where rotating about the
    // body's axes 3, 2, 1 by q3, q2, q1 does: R = R3(q3) R2(q2) R1(q1)
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), S(s, "S"), B(s, "B");
    S.orient_space_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    B.orient_body_fixed(N, RotationSequence::ZYX, q3, q2, q1);
    Mat3 expected = mul(mul(rot(Axis::z, q3), rot(Axis::y, q2)), rot(Axis::x, q1));
    EXPECT_TRUE(same_mat(rotation_matrix(N, S), expected));
    EXPECT_TRUE(same_mat(rotation_matrix(N, B), expected));
    EXPECT_TRUE(same(S.ang_vel_in(N), B.ang_vel_in(N), N));
}

TEST(Frame, NegativeSenseEqualsRotationByNegatedAngle) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::y, q, Sense::negative);
    B.orient_axis(N, Axis::y, -q.symbol());
    ex c = cos(q.symbol()), sn = sin(q.symbol());
    Mat3 expected;  // Ry(-q)
    expected.m = {c, 0, -sn, 0, 1, 0, sn, 0, c};
    EXPECT_TRUE(same_mat(rotation_matrix(N, A), expected));
    EXPECT_TRUE(same_mat(rotation_matrix(N, B), expected));
    EXPECT_TRUE(same(A.ang_vel_in(N), -q.d(1) * N.y(), N));
    EXPECT_TRUE(same(A.ang_vel_in(N), B.ang_vel_in(N), N));
}

// ---- angular velocity --------------------------------------------------------------------

TEST(Frame, BodyXYZAngularVelocityMatchesKaneFormula) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B");
    B.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    ex c2 = cos(q2), s2 = sin(q2), c3 = cos(q3), s3 = sin(q3);
    // Kane 1985, Table 2.1 (body-three 1-2-3)
    Vector expected(B, Col3{{u1 * c2 * c3 + u2 * s3, -u1 * c2 * s3 + u2 * c3, u1 * s2 + u3}});
    EXPECT_TRUE(same(B.ang_vel_in(N), expected, B));
    EXPECT_TRUE(same(B.ang_vel_in(N), expected, N));
}

TEST(Frame, BodyZXZAngularVelocityMatchesEulerAngleFormula) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B");
    B.orient_body_fixed(N, RotationSequence::ZXZ, q1, q2, q3);
    ex s2 = sin(q2), c2 = cos(q2), c3 = cos(q3), s3 = sin(q3);
    // classical Euler angles (precession q1, nutation q2, spin q3), body components
    Vector expected(B, Col3{{u1 * s2 * s3 + u2 * c3, u1 * s2 * c3 - u2 * s3, u1 * c2 + u3}});
    EXPECT_TRUE(same(B.ang_vel_in(N), expected, B));
}

TEST(Frame, SpaceFixedAngularVelocityMatchesSkewOfRTransposeRdot) {
    const RotationSequence sequences[] = {RotationSequence::XYZ, RotationSequence::ZXY,
                                          RotationSequence::ZXZ, RotationSequence::YXY};
    for (RotationSequence seq : sequences) {
        SymbolTable s;
        auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
        Frame N(s, "N"), B(s, "B");
        B.orient_space_fixed(N, seq, q1, q2, q3);
        auto ax = axes_of(seq);
        // rotations about the fixed axes of N compose on the left
        Mat3 R = mul(mul(rot(ax[2], q3), rot(ax[1], q2)), rot(ax[0], q1));
        ASSERT_TRUE(same_mat(rotation_matrix(N, B), R)) << to_string(seq);
        SCOPED_TRACE(to_string(seq));
        expect_agree_numerically(s, B.ang_vel_in(N).components_in(B), ang_vel_from_dcm(s, R));
    }
}

TEST(Frame, DcmOrientationGivesSameAngularVelocityAsBodyFixedForm) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B"), C(s, "C");
    // Z then X about the body's axes, multiplied out by hand: R_NB = Rz(q1) Rx(q2)
    ex c1 = cos(q1), s1 = sin(q1), c2 = cos(q2), s2 = sin(q2);
    Mat3 R;
    // clang-format off
    R.m = {c1, -s1 * c2, s1 * s2,
           s1, c1 * c2,  -c1 * s2,
           0,  s2,       c2};
    // clang-format on
    B.orient_dcm(N, R);
    C.orient_body_fixed(N, RotationSequence::ZXZ, q1, q2, 0);
    ASSERT_TRUE(same_mat(rotation_matrix(N, C), R));
    EXPECT_TRUE(same(B.ang_vel_in(N), C.ang_vel_in(N), N));
    // the Euler-angle formula with the spin angle held at zero
    EXPECT_TRUE(same(B.ang_vel_in(N), Vector(B, Col3{{u2, u1 * s2, u1 * c2}}), B));
}

TEST(Frame, DcmOrientationOfFullEulerSequenceMatchesBodyFixedForm) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B"), C(s, "C");
    B.orient_dcm(N, mul(mul(rot(Axis::z, q1), rot(Axis::x, q2)), rot(Axis::z, q3)));
    C.orient_body_fixed(N, RotationSequence::ZXZ, q1, q2, q3);
    EXPECT_TRUE(same(B.ang_vel_in(N), C.ang_vel_in(N), N));
    EXPECT_TRUE(same(B.ang_vel_in(N), C.ang_vel_in(N), B));
}

TEST(Frame, AngularVelocitiesAddAlongChain) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), A(s, "A"), B(s, "B"), C(s, "C");
    A.orient_axis(N, Axis::z, q1);
    B.orient_axis(A, Axis::x, q2);
    C.orient_axis(B, Axis::y, q3);
    // addition theorem: w_NC = w_NA + w_AB + w_BC (Kane 1985, eq. 2.4.1)
    Vector w_NA = u1 * N.z(), w_AB = u2 * A.x(), w_BC = u3 * B.y();
    EXPECT_TRUE(same(A.ang_vel_in(N), w_NA, N));
    EXPECT_TRUE(same(B.ang_vel_in(A), w_AB, A));
    EXPECT_TRUE(same(C.ang_vel_in(B), w_BC, B));
    EXPECT_TRUE(same(C.ang_vel_in(N), w_NA + w_AB + w_BC, N));
    EXPECT_TRUE(same(C.ang_vel_in(N), w_NA + w_AB + w_BC, C));
    EXPECT_TRUE(same(C.ang_vel_in(A), w_AB + w_BC, N));
    // w_AN = -w_NA, also across several edges
    EXPECT_TRUE(same(N.ang_vel_in(A), -w_NA, N));
    EXPECT_TRUE(same(N.ang_vel_in(C), -(w_NA + w_AB + w_BC), C));
    EXPECT_TRUE(A.ang_vel_in(A).is_zero());
    // the sum agrees with the one read off R_NC = Rz(q1) Rx(q2) Ry(q3)
    Mat3 R = mul(mul(rot(Axis::z, q1), rot(Axis::x, q2)), rot(Axis::y, q3));
    expect_agree_numerically(s, C.ang_vel_in(N).components_in(C), ang_vel_from_dcm(s, R));
}

TEST(Frame, AngularVelocityBetweenSiblingBranchesPassesThroughCommonParent) {
    SymbolTable s;
    TimeVariable qa = s.add_variable("qa", 2), qb = s.add_variable("qb", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, qa);
    B.orient_axis(N, Axis::x, qb);
    // w_AB = w_AN + w_NB = -qa' Nz + qb' Nx
    Vector expected = -qa.d(1) * N.z() + qb.d(1) * N.x();
    EXPECT_TRUE(same(B.ang_vel_in(A), expected, N));
    EXPECT_TRUE(same(A.ang_vel_in(B), -expected, B));
    Mat3 R_AB = mul(transposed(rot(Axis::z, qa)), rot(Axis::x, qb));
    expect_agree_numerically(s, B.ang_vel_in(A).components_in(B), ang_vel_from_dcm(s, R_AB));
}

TEST(Frame, SetAngVelWithSpeedsReplacesDerivedOne) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    TimeVariable wx = s.add_variable("wx", 1), wy = s.add_variable("wy", 1),
                 wz = s.add_variable("wz", 1), q4 = s.add_variable("q4", 1);
    Frame N(s, "N"), B(s, "B"), C(s, "C");
    B.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    C.orient_axis(B, Axis::z, q4);
    Vector w = wx.symbol() * B.x() + wy.symbol() * B.y() + wz.symbol() * B.z();
    B.set_ang_vel(N, w);
    EXPECT_TRUE(same(B.ang_vel_in(N), w, B));
    Col3 in_B = B.ang_vel_in(N).components_in(B);
    for (int i = 0; i < 3; ++i)
        for (const ex& rate : {u1, u2, u3})
            EXPECT_FALSE(s.depends_on(in_B[i], rate)) << "component " << i;
    EXPECT_TRUE(same(N.ang_vel_in(B), -w, N));
    EXPECT_TRUE(same(C.ang_vel_in(N), w + q4.d(1) * B.z(), C));
    // the body components are the speeds, so alpha = wx' Bx> + wy' By> + wz' Bz>
    Vector alpha = wx.d(1) * B.x() + wy.d(1) * B.y() + wz.d(1) * B.z();
    EXPECT_TRUE(same(B.ang_acc_in(N), alpha, B));
}

TEST(Frame, SetAngAccReplacesDerivedOne) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex a = s.add_constant("a");
    Frame N(s, "N"), B(s, "B");
    B.orient_axis(N, Axis::z, q);
    EXPECT_TRUE(same(B.ang_acc_in(N), q.d(2) * N.z(), N));
    B.set_ang_acc(N, a * B.z());
    EXPECT_TRUE(same(B.ang_acc_in(N), a * N.z(), N));
}

TEST(Frame, SetAngVelRelativeToNonParentThrowsNamingFrames) {
    SymbolTable s;
    ex q = s.add_variable("q", 2), u = s.add_variable("u", 1);
    Frame N(s, "N"), A(s, "Arm"), B(s, "Body"), L(s, "Loose");
    A.orient_axis(N, Axis::z, q);
    B.orient_axis(A, Axis::x, q);
    EXPECT_THROW_MSG(B.set_ang_vel(N, u * B.x()), ArgumentError, "'Body'");
    EXPECT_THROW_MSG(B.set_ang_vel(N, u * B.x()), ArgumentError, "not in 'N'");
    EXPECT_THROW_MSG(B.set_ang_vel(N, u * B.x()), ArgumentError, "'Arm'");
    EXPECT_THROW_MSG(L.set_ang_vel(N, u * L.x()), ArgumentError, "orient 'Loose' first");
    EXPECT_THROW_MSG(B.set_ang_acc(N, u * B.x()), ArgumentError, "'Body'");
    EXPECT_THROW_MSG(B.set_ang_acc(N, u * B.x()), ArgumentError, "not in 'N'");
}

// ---- angular acceleration ----------------------------------------------------------------

TEST(Frame, BodyFixedAngularAccelerationIsDerivativeOfBodyComponents) {
    SymbolTable s;
    auto [q1, q2, q3, u1, u2, u3] = three_angles(s);
    Frame N(s, "N"), B(s, "B");
    B.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
    ex c2 = cos(q2), s2 = sin(q2), c3 = cos(q3), s3 = sin(q3);
    ex w1 = u1 * c2 * c3 + u2 * s3, w2 = -u1 * c2 * s3 + u2 * c3, w3 = u1 * s2 + u3;
    // ^N alpha^B = ^B d/dt w (w x w = 0), so the body components differentiate directly
    Vector expected(B, Col3{{s.dt(w1), s.dt(w2), s.dt(w3)}});
    EXPECT_TRUE(same(B.ang_acc_in(N), expected, B));
}

TEST(Frame, TwoSimpleRotationsAngularAccelerationIncludesTransportTerm) {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1", 2), q2 = s.add_variable("q2", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, q1);
    B.orient_axis(A, Axis::x, q2);
    // ^N alpha^B = q1'' Az> + q2'' Ax> + w_NA x w_AB, with w_NA x w_AB = q1' q2' Az> x Ax>
    //            = q1' q2' Ay>
    Vector expected = q1.d(2) * A.z() + q2.d(2) * A.x() + q1.d(1) * q2.d(1) * A.y();
    EXPECT_TRUE(same(B.ang_acc_in(N), expected, A));
    EXPECT_TRUE(same(B.ang_acc_in(N), expected, N));
}

TEST(Frame, SiblingAngularAccelerationMatchesHandDerivative) {
    SymbolTable s;
    TimeVariable qa = s.add_variable("qa", 2), qb = s.add_variable("qb", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, qa);
    B.orient_axis(N, Axis::x, qb);
    // ^A alpha^B = ^A d/dt (-qa' Nz> + qb' Nx>); Nz> is fixed in A and
    // ^A d/dt Nx> = ^A w^N x Nx> = -qa' Nz> x Nx> = -qa' Ny>
    Vector expected = -qa.d(2) * N.z() + qb.d(2) * N.x() - qa.d(1) * qb.d(1) * N.y();
    EXPECT_TRUE(same(B.ang_acc_in(A), expected, N));
}

// ---- errors ------------------------------------------------------------------------------

TEST(Frame, OrientingRelativeToItselfThrows) {
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    Frame A(s, "Arm");
    EXPECT_THROW_MSG(A.orient_axis(A, Axis::z, q), ModelError, "relative to itself");
    EXPECT_THROW_MSG(A.orient_axis(A, Axis::z, q), ModelError, "'Arm'");
    EXPECT_THROW_MSG(A.orient_dcm(A, Mat3::identity()), ModelError, "relative to itself");
    EXPECT_EQ(A.parent(), nullptr);
}

TEST(Frame, RotationCycleIsRejected) {
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, q);
    B.orient_axis(A, Axis::x, q);
    EXPECT_THROW_MSG(N.orient_axis(B, Axis::y, q), ModelError, "cycle");
    EXPECT_THROW_MSG(N.orient_axis(B, Axis::y, q), ModelError, "'N'");
    EXPECT_THROW_MSG(N.orient_axis(B, Axis::y, q), ModelError, "'B'");
    EXPECT_THROW_MSG(N.orient_body_fixed(A, RotationSequence::XYZ, q, q, q), ModelError, "cycle");
    // the rejected edge leaves the tree as it was
    EXPECT_EQ(N.parent(), nullptr);
    EXPECT_EQ(B.parent(), &A);
}

TEST(Frame, RotationBetweenUnconnectedFramesThrowsNamingBoth) {
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    Frame N(s, "N"), M(s, "M"), A(s, "Arm"), B(s, "Base");
    A.orient_axis(N, Axis::z, q);
    B.orient_axis(M, Axis::z, q);
    EXPECT_THROW_MSG(rotation_matrix(A, B), ModelError, "'Arm'");
    EXPECT_THROW_MSG(rotation_matrix(A, B), ModelError, "'Base'");
    EXPECT_THROW_MSG(B.ang_vel_in(A), ModelError, "'Arm'");
    EXPECT_THROW_MSG(B.ang_vel_in(A), ModelError, "'Base'");
}

TEST(Frame, RotationFromParentOfUnorientedFrameThrowsNamingIt) {
    SymbolTable s;
    Frame N(s, "Ground");
    EXPECT_THROW_MSG(N.rotation_from_parent(), ModelError, "'Ground'");
    EXPECT_THROW_MSG(N.rotation_from_parent(), ModelError, "not oriented");
}

TEST(Frame, FramesOfDifferentModelsCannotBeConnected) {
    SymbolTable s1, s2;
    ex q = s1.add_variable("q", 2);
    Frame N(s1, "N"), A(s2, "A");
    EXPECT_THROW_MSG(A.orient_axis(N, Axis::z, q), ModelError, "different symbol tables");
    EXPECT_EQ(A.parent(), nullptr);
}

TEST(Frame, EmptyNameIsRejected) {
    SymbolTable s;
    EXPECT_THROW_MSG(Frame(s, ""), ArgumentError, "non-empty name");
}

TEST(Frame, DerivativeBeyondDeclaredOrderThrowsNamingSymbol) {
    SymbolTable s;
    TimeVariable theta = s.add_variable("theta", 1);
    Frame N(s, "N"), A(s, "A");
    A.orient_axis(N, Axis::z, theta);
    EXPECT_TRUE(same(A.ang_vel_in(N), theta.d(1) * N.z(), N));
    // alpha needs theta'', which was not declared
    EXPECT_THROW_MSG(A.ang_acc_in(N), ModelError, "'theta''");
    EXPECT_THROW_MSG(s.dt(theta.d(1)), ModelError, "'theta''");
}

}  // namespace
}  // namespace alembert
