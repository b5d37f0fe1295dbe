// SPDX-License-Identifier: MIT
// Vectors across frames: components, dot and cross products, derivatives, printing, checked
// against hand derivations.
#include "alembert/vec/vector.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/vec/frame.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::sin;
using test::same;

using test::same_col;

/// A is N turned by q about Nz> = Az>: Ax> = c Nx> + s Ny>, Ay> = -s Nx> + c Ny>.
struct Planar {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    Frame N{s, "N"};
    Frame A{s, "A"};
    Planar() { A.orient_axis(N, Axis::z, q); }
    ex c() const { return cos(q.symbol()); }
    ex sn() const { return sin(q.symbol()); }
};

// ---- components and products across frames -----------------------------------------------

TEST(Vector, ComponentsAcrossFramesMatchHandProjection) {
    Planar p;
    Vector v = 2 * p.A.x() + 3 * p.N.y();
    // in N: 2 (c, s, 0) + 3 (0, 1, 0); in A, Ny> = s Ax> + c Ay>
    EXPECT_TRUE(same_col(v.components_in(p.N), Col3{{2 * p.c(), 2 * p.sn() + 3, 0}}));
    EXPECT_TRUE(same_col(v.components_in(p.A), Col3{{2 + 3 * p.sn(), 3 * p.c(), 0}}));
}

TEST(Vector, AddingOppositeComponentsGivesTheZeroVector) {
    Planar p;
    EXPECT_TRUE((p.A.x() - p.A.x()).is_zero());
    EXPECT_TRUE((ex(0) * p.N.y()).is_zero());
    Vector v = p.q.symbol() * p.A.x() + p.N.z();
    v -= p.q.symbol() * p.A.x();
    ASSERT_EQ(v.components().size(), 1u);
    EXPECT_EQ(v.components()[0].first, &p.N);
}

TEST(Vector, DotAcrossFramesIsDirectionCosine) {
    Planar p;
    EXPECT_TRUE(same(dot(p.A.x(), p.N.x()), p.c()));
    EXPECT_TRUE(same(dot(p.N.x(), p.A.x()), p.c()));
    EXPECT_TRUE(same(dot(p.A.x(), p.N.y()), p.sn()));
    EXPECT_TRUE(same(dot(p.A.y(), p.N.x()), -p.sn()));
    EXPECT_TRUE(same(dot(p.A.y(), p.N.y()), p.c()));
    EXPECT_TRUE(same(dot(p.A.z(), p.N.z()), 1));
    EXPECT_TRUE(same(dot(p.A.x(), p.N.z()), 0));
    // (2 Ax> + Nz>) . (3 Ny> + Az>) = 6 s + 1
    EXPECT_TRUE(same(dot(2 * p.A.x() + p.N.z(), 3 * p.N.y() + p.A.z()), 6 * p.sn() + 1));
}

TEST(Vector, UnitVectorsFormRightHandedTriad) {
    Planar p;
    const Frame& N = p.N;
    EXPECT_TRUE(same(cross(N.x(), N.y()), N.z(), N));
    EXPECT_TRUE(same(cross(N.y(), N.z()), N.x(), N));
    EXPECT_TRUE(same(cross(N.z(), N.x()), N.y(), N));
    EXPECT_TRUE(same(cross(N.y(), N.x()), -N.z(), N));
}

TEST(Vector, CrossAcrossFramesMatchesHandResult) {
    Planar p;
    // Ax> x Ny> = (c Nx> + s Ny>) x Ny> = c Nz>
    EXPECT_TRUE(same(cross(p.A.x(), p.N.y()), p.c() * p.N.z(), p.N));
    // Ay> x Nx> = (-s Nx> + c Ny>) x Nx> = -c Nz>
    EXPECT_TRUE(same(cross(p.A.y(), p.N.x()), -p.c() * p.N.z(), p.N));
    // Nx> x Ax> = s Nz>
    EXPECT_TRUE(same(cross(p.N.x(), p.A.x()), p.sn() * p.N.z(), p.A));
    // Az> x Nx> = Nz> x Nx> = Ny>
    EXPECT_TRUE(same(cross(p.A.z(), p.N.x()), p.N.y(), p.N));
    // Nz> x Ax> = Ay>, written in A
    EXPECT_TRUE(same(cross(p.N.z(), p.A.x()), p.A.y(), p.A));
}

struct Spatial {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1", 2), q2 = s.add_variable("q2", 2),
                 q3 = s.add_variable("q3", 2), q4 = s.add_variable("q4", 2);
    ex a1 = s.add_constant("a1"), a2 = s.add_constant("a2"), a3 = s.add_constant("a3");
    ex b1 = s.add_constant("b1"), b2 = s.add_constant("b2"), b3 = s.add_constant("b3");
    Frame N{s, "N"};
    Frame A{s, "A"};
    Frame B{s, "B"};
    Spatial() {
        A.orient_body_fixed(N, RotationSequence::XYZ, q1, q2, q3);
        B.orient_axis(N, Axis::y, q4);
    }
    // vectors with parts in several frames of two branches
    Vector a() const { return a1 * A.x() + a2 * B.y() + a3 * N.z(); }
    Vector b() const { return b1 * B.x() + b2 * A.z() + b3 * N.y(); }
    Vector c() const { return q2.symbol() * N.x() + b1 * A.y() + a1 * q4.symbol() * B.z(); }
};

TEST(Vector, CrossIsAntiSymmetric) {
    Spatial p;
    Vector a = p.a(), b = p.b();
    EXPECT_TRUE(same(cross(a, b), -cross(b, a), p.N));
    EXPECT_TRUE(same(cross(a, b) + cross(b, a), Vector(), p.A));
}

TEST(Vector, CrossOfVectorWithItselfIsZero) {
    Spatial p;
    EXPECT_TRUE(same(cross(p.a(), p.a()), Vector(), p.N));
    EXPECT_TRUE(same(cross(p.b(), p.b()), Vector(), p.B));
    EXPECT_TRUE(cross(Vector(), p.a()).is_zero());
}

TEST(Vector, CrossIsPerpendicularToBothFactors) {
    Spatial p;
    Vector axb = cross(p.a(), p.b());
    EXPECT_TRUE(same(dot(axb, p.a()), 0));
    EXPECT_TRUE(same(dot(axb, p.b()), 0));
}

TEST(Vector, TripleProductIdentitiesHoldAtRandomPoints) {
    Spatial p;
    Vector a = p.a(), b = p.b(), c = p.c();
    // a x (b x c) = b (a . c) - c (a . b);  a . (b x c) = b . (c x a)
    Col3 lhs = cross(a, cross(b, c)).components_in(p.N);
    Col3 rhs = (dot(a, c) * b - dot(a, b) * c).components_in(p.N);
    ex box1 = dot(a, cross(b, c)), box2 = dot(b, cross(c, a));
    std::vector<ex> syms = {p.q1, p.q2, p.q3, p.q4, p.a1, p.a2, p.a3, p.b1, p.b2, p.b3};
    std::mt19937 rng(31337);
    std::uniform_real_distribution<double> value(-std::numbers::pi, std::numbers::pi);
    for (int k = 0; k < 10; ++k) {
        exmap at;
        for (const ex& sym : syms) at[sym] = value(rng);
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(p.s.evaluate(lhs[i], at), p.s.evaluate(rhs[i], at), 1e-12)
                << "component " << i << " at point " << k;
        EXPECT_NEAR(p.s.evaluate(box1, at), p.s.evaluate(box2, at), 1e-12) << "point " << k;
    }
}

TEST(Vector, ExpressInRoundTripKeepsTheVector) {
    Spatial p;
    Vector v = p.a();
    Vector in_N = v.express_in(p.N);
    ASSERT_EQ(in_N.components().size(), 1u);
    EXPECT_EQ(in_N.components()[0].first, &p.N);
    Vector back = in_N.express_in(p.B);
    ASSERT_EQ(back.components().size(), 1u);
    EXPECT_EQ(back.components()[0].first, &p.B);
    EXPECT_TRUE(same(back, v, p.B));
    EXPECT_TRUE(same(back, v, p.A));
    EXPECT_TRUE(same(back.express_in(p.A), v, p.N));
}

// ---- magnitude, direction, angle ---------------------------------------------------------

TEST(Vector, MagnitudeAndUnitVectorOfThreeFourFive) {
    Planar p;
    Vector v = 3 * p.N.x() + 4 * p.N.y();
    EXPECT_TRUE(same(v.magnitude(), 5));
    EXPECT_TRUE(same_col(v.unit().components_in(p.N),
                         Col3{{GiNaC::numeric(3, 5), GiNaC::numeric(4, 5), 0}}));
    EXPECT_TRUE(same(p.N.y().magnitude(), 1));
    EXPECT_TRUE(same((-2 * p.N.y()).unit(), -p.N.y(), p.N));
}

TEST(Vector, MagnitudeAcrossFramesFollowsLawOfCosines) {
    Planar p;
    // |Ax> + Nx>|^2 = 1 + 1 + 2 cos q
    EXPECT_TRUE(same((p.A.x() + p.N.x()).magnitude(), GiNaC::sqrt(2 + 2 * p.c())));
    EXPECT_TRUE(same((p.c() * p.N.x() + p.sn() * p.N.y()).magnitude(), 1));
    // the unit vector along Ax> + Nx> bisects the two
    Vector u = (p.A.x() + p.N.x()).unit();
    EXPECT_TRUE(same(u, (p.A.x() + p.N.x()) / GiNaC::sqrt(2 + 2 * p.c()), p.N));
    EXPECT_TRUE(same(dot(u, u), 1));
    EXPECT_TRUE(same(dot(u, p.N.x()), dot(u, p.A.x())));
}

TEST(Vector, AngleBetweenNxAndAxIsTheRotationAngle) {
    Planar p;
    ex theta = angle_between(p.N.x(), p.A.x());
    ex theta_y = angle_between(p.N.x(), p.A.y());
    for (double q : {0.1, 0.7, 1.2, std::numbers::pi / 2, 2.0, 2.9, 3.1}) {
        exmap at{{p.q.symbol(), q}};
        EXPECT_NEAR(p.s.evaluate(theta, at), q, 1e-12) << "q = " << q;
        // Ay> is Ax> turned a further quarter turn
        if (q < std::numbers::pi / 2) {
            EXPECT_NEAR(p.s.evaluate(theta_y, at), q + std::numbers::pi / 2, 1e-12) << "q = " << q;
        }
    }
    EXPECT_TRUE(same(angle_between(3 * p.N.x(), 2 * p.N.y() + p.A.z()), GiNaC::Pi / 2));
}

TEST(Vector, UnitOfZeroVectorThrows) {
    Planar p;
    EXPECT_THROW_MSG(Vector().unit(), ArgumentError, "zero");
    EXPECT_THROW_MSG((p.A.x() - p.A.x()).unit(), ArgumentError, "zero");
    // zero only after the Pythagorean identity
    Vector v = (GiNaC::pow(p.c(), 2) + GiNaC::pow(p.sn(), 2) - 1) * p.N.x();
    EXPECT_THROW_MSG(v.unit(), ArgumentError, "zero");
    // zero only once its parts in two frames are compared
    EXPECT_THROW_MSG((p.A.x() - p.c() * p.N.x() - p.sn() * p.N.y()).unit(), ArgumentError, "zero");
}

TEST(Vector, AngleWithZeroVectorThrows) {
    Planar p;
    EXPECT_THROW_MSG(angle_between(Vector(), p.N.x()), ArgumentError, "zero");
    EXPECT_THROW_MSG(angle_between(p.N.x(), p.A.y() - p.A.y()), ArgumentError, "zero");
    // Ay> - (-s Nx> + c Ny>) is zero, though written in two frames
    EXPECT_THROW_MSG(angle_between(p.A.y() + p.sn() * p.N.x() - p.c() * p.N.y(), p.N.x()),
                     ArgumentError, "zero");
}

TEST(Vector, ComponentsInUnconnectedFrameThrowNamingFrames) {
    SymbolTable s;
    Frame N(s, "N"), M(s, "Moon");
    EXPECT_THROW_MSG(N.x().components_in(M), ModelError, "'Moon'");
    EXPECT_THROW_MSG(dot(N.x(), M.x()), ModelError, "'Moon'");
    EXPECT_THROW_MSG(dot(N.x(), M.x()), ModelError, "'N'");
}

// ---- derivatives ------------------------------------------------------------------------

TEST(Vector, DerivativeOfVectorFixedInFrameIsAngularVelocityCrossVector) {
    Spatial p;
    // fixed in A: constant measures in A
    Vector v = p.a1 * p.A.x() + p.a2 * p.A.y() + p.a3 * p.A.z();
    ex c2 = cos(p.q2), s2 = sin(p.q2), c3 = cos(p.q3), s3 = sin(p.q3);
    ex u1 = p.q1.d(1), u2 = p.q2.d(1), u3 = p.q3.d(1);
    Col3 w{{u1 * c2 * c3 + u2 * s3, -u1 * c2 * s3 + u2 * c3, u1 * s2 + u3}};  // Kane's formula
    // w x v by hand, in A
    Col3 wxv{{w[1] * p.a3 - w[2] * p.a2, w[2] * p.a1 - w[0] * p.a3, w[0] * p.a2 - w[1] * p.a1}};
    Vector dv = v.dt_in(p.N);
    EXPECT_TRUE(same_col(dv.components_in(p.A), wxv));
    // and the same from differentiating [v]_N = R_NA [v]_A entry by entry
    Col3 vN = v.components_in(p.N);
    Col3 dvN{{p.s.dt(vN[0]), p.s.dt(vN[1]), p.s.dt(vN[2])}};
    EXPECT_TRUE(same_col(dv.components_in(p.N), dvN));
    // in A itself the vector does not change
    EXPECT_TRUE(v.dt_in(p.A).is_zero());
}

TEST(Vector, DerivativeOfRotatingArmMatchesHandResult) {
    Planar p;
    ex L = p.s.add_constant("L");
    TimeVariable r = p.s.add_variable("r", 2);
    ex u = p.q.d(1);
    // ^N d/dt (L Ay>) = L q' Az> x Ay> = -L q' Ax>
    EXPECT_TRUE(same((L * p.A.y()).dt_in(p.N), -L * u * p.A.x(), p.N));
    // once more: -L q'' Ax> - L q'^2 Ay> (tangential and centripetal)
    EXPECT_TRUE(same((L * p.A.y()).dt_in(p.N).dt_in(p.N),
                     -L * p.q.d(2) * p.A.x() - L * u * u * p.A.y(), p.A));
    // a telescoping arm: ^N d/dt (r Ay>) = r' Ay> - r q' Ax>
    EXPECT_TRUE(
        same((r.symbol() * p.A.y()).dt_in(p.N), r.d(1) * p.A.y() - r.symbol() * u * p.A.x(), p.N));
}

TEST(Vector, PartialVelocityIsCoefficientOfGeneralizedSpeed) {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1", 2), q2 = s.add_variable("q2", 2);
    ex L1 = s.add_constant("L1"), L2 = s.add_constant("L2");
    Frame N(s, "N"), A(s, "A"), B(s, "B");
    A.orient_axis(N, Axis::z, q1);
    B.orient_axis(A, Axis::z, q2);
    // double pendulum tip: r = L1 Ax> + L2 Bx>, v = L1 q1' Ay> + L2 (q1' + q2') By>
    Vector v = (L1 * A.x() + L2 * B.x()).dt_in(N);
    EXPECT_TRUE(same(v, L1 * q1.d(1) * A.y() + L2 * (q1.d(1) + q2.d(1)) * B.y(), N));
    EXPECT_TRUE(same(v.diff(q1.d(1)), L1 * A.y() + L2 * B.y(), N));
    EXPECT_TRUE(same(v.diff(q2.d(1)), L2 * B.y(), B));
    EXPECT_TRUE(v.diff(L1).diff(q2.d(1)).is_zero());
}

// ---- printing ----------------------------------------------------------------------------

TEST(Vector, PrintsUnitVectorsWithFrameNames) {
    SymbolTable s;
    Frame N(s, "N"), A(s, "A");
    EXPECT_EQ(N.x().to_string(), "Nx>");
    EXPECT_EQ(N.y().to_string(), "Ny>");
    EXPECT_EQ(A.z().to_string(), "Az>");
    EXPECT_EQ((-N.y()).to_string(), "-Ny>");
    EXPECT_EQ((N.x() + N.z()).to_string(), "Nx> + Nz>");
    EXPECT_EQ((N.x() - A.y()).to_string(), "Nx> - Ay>");
    std::ostringstream os;
    os << A.x();
    EXPECT_EQ(os.str(), "Ax>");
}

TEST(Vector, PrintsZeroVectorAsZeroArrow) {
    SymbolTable s;
    Frame N(s, "N");
    EXPECT_EQ(Vector().to_string(), "0>");
    EXPECT_EQ((N.x() - N.x()).to_string(), "0>");
}

}  // namespace
}  // namespace alembert
