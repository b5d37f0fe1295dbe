// SPDX-License-Identifier: MIT
// Segment and joint angles from markers against hand values.
#include "alembert/biomech/segment_angles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// a marker table from planar positions (X forward, Y up, Z = 0) of each marker per sample
MarkerTable planar_markers(const std::vector<std::string>& names,
                           const std::vector<std::vector<std::pair<double, double>>>& xy) {
    MarkerTable m;
    m.markers = names;
    m.table.add_column("time", "s");
    for (const auto& n : names)
        for (const char* a : {".X", ".Y", ".Z"}) m.table.add_column(n + a, "m");
    for (std::size_t k = 0; k < xy.size(); ++k) {
        m.table.columns[0].push_back(0.01 * static_cast<double>(k));
        for (std::size_t i = 0; i < names.size(); ++i) {
            m.table.columns[1 + 3 * i].push_back(xy[k][i].first);
            m.table.columns[2 + 3 * i].push_back(xy[k][i].second);
            m.table.columns[3 + 3 * i].push_back(0.0);
        }
    }
    return m;
}

TEST(SegmentAngle, MatchesHandValuesOfTheLineBetweenTwoMarkers) {
    // leg from ankle (0.1, 0.1) to knee (0, 0.5): atan2(0.4, -0.1) = 104.036 deg;
    // then a 3-4-5 triangle: atan2(0.4, 0.3) = 53.130 deg
    MarkerTable m = planar_markers({"KNEE", "ANKLE"}, {{{0.0, 0.5}, {0.1, 0.1}},
                                                       {{0.4, 0.5}, {0.1, 0.1}}});
    std::vector<double> leg = calc_segment_angle(m, "ANKLE", "KNEE");
    EXPECT_NEAR(leg[0] / kDeg, 104.03624346792648, 1e-12);
    EXPECT_NEAR(leg[1] / kDeg, 53.13010235415598, 1e-12);
}

TEST(SegmentAngle, UnwrapsThroughHalfATurn) {
    // a segment turning counterclockwise through 180 deg in steps of 60 deg reads 0..360
    std::vector<std::vector<std::pair<double, double>>> xy;
    for (int k = 0; k <= 6; ++k)
        xy.push_back({{0, 0}, {std::cos(60 * k * kDeg), std::sin(60 * k * kDeg)}});
    MarkerTable m = planar_markers({"O", "P"}, xy);
    std::vector<double> theta = calc_segment_angle(m, "O", "P");
    for (int k = 0; k <= 6; ++k) EXPECT_NEAR(theta[k], 60 * k * kDeg, 1e-12);
}

TEST(SegmentAngle, ThePlaneChoosesTheAxes) {
    // forward = Z, up = Y: a segment along +Z and up 1 is at 45 deg
    MarkerTable m = planar_markers({"A", "B"}, {{{0, 0}, {0, 1}}});
    m.table.columns[m.column("B", 2)][0] = 1.0;
    EXPECT_NEAR(calc_segment_angle(m, "A", "B", SagittalPlane{2, 1})[0], 45 * kDeg, 1e-15);
    EXPECT_THROW_MSG(calc_segment_angle(m, "A", "B", SagittalPlane{1, 1}), ArgumentError,
                     "must be two different axes");
}

TEST(SegmentAngle, MissingOrCoincidentMarkersAreRefusedWithTheirTime) {
    MarkerTable m = planar_markers({"A", "B"}, {{{0, 0}, {1, 0}}, {{0, 0}, {0, 0}}});
    EXPECT_THROW_MSG(calc_segment_angle(m, "A", "B"), ArgumentError,
                     "markers 'A' and 'B' are at the same place at t = 0.01 s");
    m.table.columns[m.column("B", 0)][1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW_MSG(calc_segment_angle(m, "A", "B"), ArgumentError,
                     "marker 'B' is missing at t = 0.01 s; fill its gaps first");
    EXPECT_THROW_MSG(calc_segment_angle(m, "A", "C"), ArgumentError, "no marker 'C'");
}

TEST(SegmentAngleFit, RecoversARigidRotationAndIgnoresASymmetricStretch) {
    // a cross of four markers about (2, 1), turned by 30 deg and moved; then turned by 75 deg
    // with the A-C pair stretched outward by 10 % (which leaves the best rotation unchanged)
    auto cross = [](double angle, double stretch, double cx, double cy) {
        std::vector<std::pair<double, double>> p;
        const double rs[4] = {stretch, 1, stretch, 1};
        for (int i = 0; i < 4; ++i) {
            const double a = angle + 90 * i * kDeg;
            p.emplace_back(cx + 0.2 * rs[i] * std::cos(a), cy + 0.2 * rs[i] * std::sin(a));
        }
        return p;
    };
    MarkerTable m = planar_markers({"A", "B", "C", "D"},
                                   {cross(0, 1, 2, 1), cross(30 * kDeg, 1, 2.5, 1.1),
                                    cross(75 * kDeg, 1.1, 3, 0.9)});
    std::vector<double> theta = calc_segment_angle_fit(m, {"A", "B", "C", "D"});
    // the reference line A -> B at the first sample points at 135 deg
    EXPECT_NEAR(theta[0] / kDeg, 135, 1e-12);
    EXPECT_NEAR(theta[1] / kDeg, 165, 1e-12);
    EXPECT_NEAR(theta[2] / kDeg, 210, 1e-12);
    // two markers: the same as the line between them
    std::vector<double> two = calc_segment_angle_fit(m, {"A", "C"});
    std::vector<double> line = calc_segment_angle(m, "A", "C");
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(two[k], line[k], 1e-12);
    EXPECT_THROW_MSG(calc_segment_angle_fit(m, {"A"}), ArgumentError, "needs at least two");
}

TEST(JointAngle, IsTheDistalSegmentRelativeToTheProximalOne) {
    // thigh at -80 deg, leg at -100 deg: the leg is turned -20 deg from the thigh, which the
    // flexion-positive convention (sign -1) reads as +20 deg
    const std::vector<double> thigh = {-80 * kDeg}, leg = {-100 * kDeg};
    EXPECT_NEAR(calc_joint_angle(thigh, leg)[0] / kDeg, -20, 1e-12);
    EXPECT_NEAR(calc_joint_angle(thigh, leg, -1)[0] / kDeg, 20, 1e-12);
    EXPECT_THROW_MSG(calc_joint_angle(thigh, {1, 2}), ArgumentError, "1 proximal and 2 distal");
    EXPECT_THROW_MSG(calc_joint_angle(thigh, leg, 2), ArgumentError, "sign 2; use +1 or -1");
}

}  // namespace
}  // namespace alembert
