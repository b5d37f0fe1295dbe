// SPDX-License-Identifier: MIT
// Dyadics: unit dyadic, dyads, dot products with vectors and re-expression of inertia,
// checked against hand derivations.
#include "alembert/vec/dyadic.hpp"

#include <gtest/gtest.h>

#include "alembert/error.hpp"
#include "alembert/vec/frame.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::matrix;
using GiNaC::sin;
using test::same;

/// Simple rotation matrix written out by hand, as a GiNaC matrix so that products in the
/// tests use GiNaC's linear algebra rather than the library's.
matrix rot_matrix(Axis a, const ex& q) {
    ex c = cos(q), s = sin(q);
    switch (a) {
        case Axis::x:
            return matrix{{1, 0, 0}, {0, c, -s}, {0, s, c}};
        case Axis::y:
            return matrix{{c, 0, s}, {0, 1, 0}, {-s, 0, c}};
        case Axis::z:
            break;
    }
    return matrix{{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
}

matrix to_matrix(const Mat3& m) {
    matrix r(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) r(i, j) = m(static_cast<int>(i), static_cast<int>(j));
    return r;
}

::testing::AssertionResult same_mat(const Mat3& a, const matrix& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            auto r = same(a(i, j), b(static_cast<unsigned>(i), static_cast<unsigned>(j)));
            if (!r) return r << " (entry " << i << "," << j << ")";
        }
    return ::testing::AssertionSuccess();
}

/// N; A body-fixed XYZ from N; B turned about Ny> from N (a second branch).
struct Tree {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1", 2), q2 = s.add_variable("q2", 2),
                 q3 = s.add_variable("q3", 2), q4 = s.add_variable("q4", 2);
    ex a1 = s.add_constant("a1"), a2 = s.add_constant("a2"), a3 = s.add_constant("a3");
    ex b1 = s.add_constant("b1"), b2 = s.add_constant("b2"), b3 = s.add_constant("b3");
    ex c1 = s.add_constant("c1"), c2 = s.add_constant("c2"), c3 = s.add_constant("c3");
    Frame N{s, "N"};
    Frame A{s, "A"};
    Frame B{s, "B"};
    Tree() {
        A.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
        B.orient_axis(N, Axis::y, q4);
    }
    matrix R_NA() const {
        return rot_matrix(Axis::x, q1).mul(rot_matrix(Axis::y, q2)).mul(rot_matrix(Axis::z, q3));
    }
    matrix R_NB() const { return rot_matrix(Axis::y, q4); }
    Vector a() const { return a1 * A.x() + a2 * B.y() + a3 * N.z(); }
    Vector b() const { return b1 * B.z() + b2 * A.y() + b3 * N.x(); }
    Vector c() const { return c1 * N.y() + c2 * A.z() + c3 * B.x(); }
};

TEST(Dyadic, UnitDyadicDottedWithAnyVectorReturnsIt) {
    Tree t;
    Vector v = t.a();
    for (const Frame* F : {&t.N, &t.A, &t.B}) {
        Dyadic U = Dyadic::unit(*F);
        EXPECT_TRUE(same(dot(U, v), v, t.N)) << "U in " << F->name();
        EXPECT_TRUE(same(dot(v, U), v, t.A)) << "U in " << F->name();
    }
}

TEST(Dyadic, UnitDyadicIsIdentityInEveryFrame) {
    Tree t;
    matrix I = GiNaC::ex_to<matrix>(GiNaC::unit_matrix(3));
    EXPECT_TRUE(same_mat(Dyadic::unit(t.A).components_in(t.N), I));
    EXPECT_TRUE(same_mat(Dyadic::unit(t.A).components_in(t.B), I));
    EXPECT_TRUE(same_mat(Dyadic::unit(t.N).components_in(t.A), I));
}

TEST(Dyadic, OuterProductDottedWithVectorScalesByDotProduct) {
    Tree t;
    Vector a = t.a(), b = t.b(), c = t.c();
    Dyadic ab = outer(a, b);
    // (a b) . c = a (b . c) and c . (a b) = (c . a) b
    EXPECT_TRUE(same(dot(ab, c), dot(b, c) * a, t.N));
    EXPECT_TRUE(same(dot(c, ab), dot(c, a) * b, t.B));
}

TEST(Dyadic, SingleDyadDotsOnTheMatchingSide) {
    Tree t;
    Vector v = t.c();
    // (Ax> By>) . v = Ax> (By> . v) and v . (Ax> By>) = (v . Ax>) By>
    Mat3 e01;
    e01(0, 1) = 1;
    Dyadic D(t.A, t.B, e01);
    EXPECT_TRUE(same(dot(D, v), dot(t.B.y(), v) * t.A.x(), t.A));
    EXPECT_TRUE(same(dot(v, D), dot(v, t.A.x()) * t.B.y(), t.B));
}

TEST(Dyadic, InertiaReexpressedFromBodyToNewtonianIsRotatedByHand) {
    Tree t;
    ex Ixx = t.s.add_constant("Ixx"), Iyy = t.s.add_constant("Iyy"), Izz = t.s.add_constant("Izz"),
       Ixy = t.s.add_constant("Ixy"), Iyz = t.s.add_constant("Iyz"), Izx = t.s.add_constant("Izx");
    Mat3 I_A;
    I_A.m = {Ixx, Ixy, Izx, Ixy, Iyy, Iyz, Izx, Iyz, Izz};
    Dyadic I(t.A, t.A, I_A);
    // [I]_N = R_NA [I]_A R_NA^T
    matrix R = t.R_NA();
    matrix expected = R.mul(to_matrix(I_A)).mul(R.transpose());
    EXPECT_TRUE(same_mat(I.components_in(t.N), expected));
    // and from N on to the other branch: [I]_B = R_NB^T [I]_N R_NB
    matrix R2 = t.R_NB();
    EXPECT_TRUE(same_mat(I.components_in(t.B), R2.transpose().mul(expected).mul(R2)));
    // back in A it is the matrix it was written with
    EXPECT_TRUE(same_mat(I.express_in(t.N).components_in(t.A), to_matrix(I_A)));
}

TEST(Dyadic, PrincipalInertiaTurnedAboutZMatchesHandComponents) {
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    ex I1 = s.add_constant("I1"), I2 = s.add_constant("I2"), I3 = s.add_constant("I3");
    Frame N(s, "N"), B(s, "B");
    B.orient_axis(N, Axis::z, q);
    Mat3 diag;
    diag(0, 0) = I1, diag(1, 1) = I2, diag(2, 2) = I3;
    ex c = cos(q), sn = sin(q);
    // I1 Bx>Bx> + I2 By>By> + I3 Bz>Bz> with Bx> = c Nx> + s Ny>, By> = -s Nx> + c Ny>
    matrix expected{{I1 * c * c + I2 * sn * sn, (I1 - I2) * sn * c, 0},
                    {(I1 - I2) * sn * c, I1 * sn * sn + I2 * c * c, 0},
                    {0, 0, I3}};
    EXPECT_TRUE(same_mat(Dyadic(B, B, diag).components_in(N), expected));
}

TEST(Dyadic, MixedFrameDyadicFollowsBothRotations) {
    Tree t;
    Mat3 m;
    m.m = {t.a1, t.a2, t.a3, t.b1, t.b2, t.b3, t.c1, t.c2, t.c3};  // no symmetry
    Dyadic D(t.A, t.B, m);
    // sum_ij m_ij A_i> B_j> in N: R_NA m R_NB^T
    matrix expected = t.R_NA().mul(to_matrix(m)).mul(t.R_NB().transpose());
    EXPECT_TRUE(same_mat(D.components_in(t.N), expected));
}

TEST(Dyadic, SymmetricDyadicDotsAlikeFromEitherSide) {
    Tree t;
    Mat3 m;
    m.m = {t.a1, t.b3, t.b2, t.b3, t.a2, t.b1, t.b2, t.b1, t.a3};
    Dyadic D(t.A, t.A, m);
    Vector v = t.c();
    EXPECT_TRUE(same(dot(v, D), dot(D, v), t.N));
    // a symmetric dyadic built across frames: a b + b a
    Dyadic S = outer(t.a(), t.b()) + outer(t.b(), t.a());
    EXPECT_TRUE(same(dot(v, S), dot(S, v), t.B));
}

TEST(Dyadic, LeftDotEqualsTransposeRightDot) {
    Tree t;
    Mat3 m;
    m.m = {t.a1, t.a2, t.a3, t.b1, t.b2, t.b3, t.c1, t.c2, t.c3};
    Mat3 mT;
    mT.m = {t.a1, t.b1, t.c1, t.a2, t.b2, t.c2, t.a3, t.b3, t.c3};
    Dyadic D(t.A, t.B, m), DT(t.B, t.A, mT);
    Vector v = t.a1 * t.N.x() + t.q4.symbol() * t.A.y() + t.b2 * t.B.z();
    EXPECT_TRUE(same(dot(v, D), dot(DT, v), t.N));
    EXPECT_TRUE(same(dot(D, v), dot(v, DT), t.A));
}

TEST(Dyadic, PointMassInertiaAboutOffsetPointIsPerpendicularSquare) {
    SymbolTable s;
    ex q = s.add_variable("q", 2);
    ex mass = s.add_constant("m"), L = s.add_constant("L");
    Frame N(s, "N"), B(s, "B");
    B.orient_axis(N, Axis::z, q);
    // I = m (|r|^2 U - r r) for r = L Bx>: m L^2 (By>By> + Bz>Bz>)
    Vector r = L * B.x();
    Dyadic I = mass * (dot(r, r) * Dyadic::unit(N) - outer(r, r));
    ex mL2 = mass * L * L;
    EXPECT_TRUE(same_mat(I.components_in(B), matrix{{0, 0, 0}, {0, mL2, 0}, {0, 0, mL2}}));
    // angular momentum of the mass spinning about Bz> at rate w: H = m L^2 w Bz>
    ex w = s.add_constant("w");
    EXPECT_TRUE(same(dot(I, w * N.z()), mL2 * w * B.z(), N));
}

TEST(Dyadic, SumsDifferencesAndScalingActOnComponents) {
    Tree t;
    Dyadic D = outer(t.a(), t.b());
    EXPECT_TRUE((D - D).is_zero());
    EXPECT_TRUE((ex(0) * D).is_zero());
    Dyadic E = outer(t.c(), t.a());
    Mat3 sum = (D + ex(2) * E).components_in(t.N);
    Mat3 d = D.components_in(t.N), e = E.components_in(t.N);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_TRUE(same(sum(i, j), d(i, j) + 2 * e(i, j)));
}

}  // namespace
}  // namespace alembert
