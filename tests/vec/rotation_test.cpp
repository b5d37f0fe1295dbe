// SPDX-License-Identifier: MIT
// Simple rotation matrices and rotation-sequence names, checked against hand derivations.
#include "alembert/vec/rotation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "alembert/error.hpp"
#include "alembert/vec/frame.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using test::same;

constexpr std::array<Axis, 3> kAxes{Axis::x, Axis::y, Axis::z};

double to_double(const ex& e) {
    ex v = GiNaC::evalf(e);
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(v)) << v;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

/// [B_j>]_N for B rotated relative to N by `q` about their common axis, written out by hand
/// from the picture of the rotation (Kane 1985, 1.6): columns j = 0, 1, 2 are Bx>, By>, Bz>.
std::array<Col3, 3> hand_unit_vectors(Axis axis, const ex& q) {
    ex c = GiNaC::cos(q), s = GiNaC::sin(q);
    switch (axis) {
        case Axis::x:  // By> tips from Ny> towards Nz>
            return {Col3{{1, 0, 0}}, Col3{{0, c, s}}, Col3{{0, -s, c}}};
        case Axis::y:  // Bz> tips from Nz> towards Nx>
            return {Col3{{c, 0, -s}}, Col3{{0, 1, 0}}, Col3{{s, 0, c}}};
        case Axis::z:  // Bx> tips from Nx> towards Ny>
            break;
    }
    return {Col3{{c, s, 0}}, Col3{{-s, c, 0}}, Col3{{0, 0, 1}}};
}

using test::same_col;

TEST(Rotation, SimpleRotationsAreOrthonormalWithUnitDeterminant) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    for (Axis axis : kAxes) {
        for (int k = 0; k < 20; ++k) {
            double q = angle(rng);
            Mat3 R = simple_rotation(axis, GiNaC::numeric(q));
            double r[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) r[i][j] = to_double(R(i, j));
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    double rtr = 0;
                    for (int l = 0; l < 3; ++l) rtr += r[l][i] * r[l][j];
                    EXPECT_NEAR(rtr, i == j ? 1.0 : 0.0, 1e-14)
                        << "axis " << index_of(axis) << ", angle " << q << ", (R^T R)(" << i << ","
                        << j << ")";
                }
            double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                         r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                         r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
            EXPECT_NEAR(det, 1.0, 1e-14) << "axis " << index_of(axis) << ", angle " << q;
        }
    }
}

TEST(Rotation, SimpleRotationColumnsAreRotatedUnitVectorsInParent) {
    GiNaC::symbol q("q");
    for (Axis axis : kAxes) {
        Mat3 R = simple_rotation(axis, q);
        auto expected = hand_unit_vectors(axis, q);
        for (int j = 0; j < 3; ++j)
            EXPECT_TRUE(same_col(R.column(j), expected[static_cast<std::size_t>(j)]))
                << "axis " << index_of(axis) << ", column " << j;
    }
}

TEST(Rotation, FrameRotationMatrixColumnsAreChildUnitVectorsInParent) {
    for (Axis axis : kAxes) {
        SymbolTable s;
        ex q = s.add_variable("q", 2);
        Frame N(s, "N"), B(s, "B");
        B.orient_axis(N, axis, q);
        Mat3 R_NB = rotation_matrix(N, B);
        auto expected = hand_unit_vectors(axis, q);
        for (int j = 0; j < 3; ++j) {
            const Col3& e = expected[static_cast<std::size_t>(j)];
            EXPECT_TRUE(same_col(R_NB.column(j), e))
                << "axis " << index_of(axis) << ", column " << j;
            EXPECT_TRUE(same_col(B.unit(static_cast<Axis>(j)).components_in(N), e))
                << "axis " << index_of(axis) << ", unit vector " << j;
        }
    }
}

TEST(Rotation, QuarterTurnsAreRightHanded) {
    // a right-handed quarter turn about x carries y to z, about y carries z to x, about z
    // carries x to y
    const ex quarter = GiNaC::Pi / 2;
    Col3 ex_{{1, 0, 0}}, ey{{0, 1, 0}}, ez{{0, 0, 1}};
    EXPECT_TRUE(same_col(simple_rotation(Axis::x, quarter) * ey, ez));
    EXPECT_TRUE(same_col(simple_rotation(Axis::y, quarter) * ez, ex_));
    EXPECT_TRUE(same_col(simple_rotation(Axis::z, quarter) * ex_, ey));
}

TEST(Rotation, SuccessiveRotationsAboutOneAxisAddTheirAngles) {
    GiNaC::symbol a("a"), b("b");
    for (Axis axis : kAxes) {
        Mat3 product = simple_rotation(axis, a) * simple_rotation(axis, b);
        auto expected = hand_unit_vectors(axis, a + b);
        for (int j = 0; j < 3; ++j)
            EXPECT_TRUE(same_col(product.column(j), expected[static_cast<std::size_t>(j)]))
                << "axis " << index_of(axis) << ", column " << j;
    }
}

// clang-format off
const std::array<std::pair<const char*, RotationSequence>, 12> kSequences{{
    {"XYZ", RotationSequence::XYZ}, {"XZY", RotationSequence::XZY},
    {"YXZ", RotationSequence::YXZ}, {"YZX", RotationSequence::YZX},
    {"ZXY", RotationSequence::ZXY}, {"ZYX", RotationSequence::ZYX},
    {"XYX", RotationSequence::XYX}, {"XZX", RotationSequence::XZX},
    {"YXY", RotationSequence::YXY}, {"YZY", RotationSequence::YZY},
    {"ZXZ", RotationSequence::ZXZ}, {"ZYZ", RotationSequence::ZYZ},
}};
// clang-format on

TEST(Rotation, ParseAcceptsAllTwelveNamesInEitherCase) {
    for (const auto& [name, seq] : kSequences) {
        std::string upper = name, lower = name, mixed = name;
        for (char& c : lower) c = static_cast<char>(c - 'A' + 'a');
        mixed[1] = lower[1];
        EXPECT_EQ(parse_rotation_sequence(upper), seq) << upper;
        EXPECT_EQ(parse_rotation_sequence(lower), seq) << lower;
        EXPECT_EQ(parse_rotation_sequence(mixed), seq) << mixed;
        EXPECT_EQ(to_string(seq), upper);
    }
}

TEST(Rotation, SequenceAxesFollowItsName) {
    for (const auto& [name, seq] : kSequences) {
        auto axes = axes_of(seq);
        for (std::size_t i = 0; i < 3; ++i) {
            Axis expected = name[i] == 'X' ? Axis::x : name[i] == 'Y' ? Axis::y : Axis::z;
            EXPECT_EQ(axes[i], expected) << name << ", axis " << i;
        }
    }
}

TEST(Rotation, ParseRejectsUnknownNameListingTheAcceptedNames) {
    EXPECT_THROW_MSG(parse_rotation_sequence("XXY"), ArgumentError, "'XXY'");
    for (const auto& entry : kSequences)
        EXPECT_THROW_MSG(parse_rotation_sequence("XXY"), ArgumentError, entry.first);
    EXPECT_THROW_MSG(parse_rotation_sequence("XYZX"), ArgumentError, "'XYZX'");
    EXPECT_THROW_MSG(parse_rotation_sequence(""), ArgumentError, "is not a rotation sequence");
}

}  // namespace
}  // namespace alembert
