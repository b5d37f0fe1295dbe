// SPDX-License-Identifier: MIT
// A planar model's coordinates from marker trajectories, against the motion that made them.
#include "alembert/biomech/model_markers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double L_T = 0.42, L_L = 0.40;  // thigh and leg, m

// marker positions (lab X forward, Y up) of each named marker at time t
using Positions = std::function<std::vector<std::pair<double, double>>(double t)>;

MarkerTable planar_trial(const std::vector<std::string>& names, const Positions& at,
                         std::size_t samples = 101) {
    MarkerTable m;
    m.markers = names;
    m.table.add_column("time", "s");
    for (const auto& n : names)
        for (const char* a : {".X", ".Y", ".Z"}) m.table.add_column(n + a, "m");
    for (std::size_t k = 0; k < samples; ++k) {
        const double t = 0.01 * static_cast<double>(k);
        m.table.columns[0].push_back(t);
        const auto p = at(t);
        for (std::size_t i = 0; i < names.size(); ++i) {
            m.table.columns[1 + 3 * i].push_back(p[i].first);
            m.table.columns[2 + 3 * i].push_back(p[i].second);
            m.table.columns[3 + 3 * i].push_back(0.0);
        }
    }
    return m;
}

// a thigh T hanging from the hip N_o, turned by q1 about Nz>, and a leg turned from it by q2
// (about Nz>, or about -Nz> when `backwards`); hip and knee markers on T, knee and ankle on L
struct LegModel {
    SymbolTable table;
    TimeVariable q1 = table.add_variable("q1"), q2 = table.add_variable("q2");
    std::vector<ModelMarker> markers;
    explicit LegModel(bool backwards = false, double leg = L_L) {
        const ex th_T = q1.symbol(),
                 th_L = backwards ? q1.symbol() - q2.symbol() : q1.symbol() + q2.symbol();
        const ex kx = L_T * sin(th_T), ky = -L_T * cos(th_T);
        markers = {{"HIP", "T", 0, 0},
                   {"KNEE", "T", kx, ky},
                   {"KNEE", "L", kx, ky},
                   {"ANKLE", "L", kx + leg * sin(th_L), ky - leg * cos(th_L)}};
    }
};

// the lab's trial of a swinging leg: hip at (1.2, 0.9), thigh angle a(t), knee angle b(t)
double thigh_angle(double t) { return 0.3 * std::sin(2 * kPi * t); }
double knee_angle(double t) { return -0.5 + 0.4 * std::cos(2 * kPi * t); }
MarkerTable swinging_leg() {
    return planar_trial({"HIP", "KNEE", "ANKLE"}, [](double t) {
        const double a = thigh_angle(t), b = a + knee_angle(t);
        const double kx = 1.2 + L_T * std::sin(a), ky = 0.9 - L_T * std::cos(a);
        return std::vector<std::pair<double, double>>{
            {1.2, 0.9}, {kx, ky}, {kx + L_L * std::sin(b), ky - L_L * std::cos(b)}};
    });
}

TEST(ModelMarkers, JointAnglesOfAPlanarChainAreTheMotionThatMadeTheMarkers) {
    LegModel m;
    const MarkerCoordinates c =
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg());
    // theta_T = q1, theta_L = q1 + q2
    EXPECT_EQ(c.segments, (std::vector<std::string>{"T", "L"}));
    EXPECT_EQ(c.turns, (std::vector<std::vector<int>>{{1, 0}, {1, 1}}));
    ASSERT_EQ(c.motion.names, (std::vector<std::string>{"t", "q1", "q2"}));
    EXPECT_EQ(c.motion.units[1], "rad");
    for (std::size_t k = 0; k < c.motion.row_count(); ++k) {
        const double t = c.motion.columns[0][k];
        EXPECT_NEAR(c.motion.columns[1][k], thigh_angle(t), 1e-12);
        EXPECT_NEAR(c.motion.columns[2][k], knee_angle(t), 1e-12);
    }
    // the model's origin (the hip) found in the lab; every marker where the model puts it
    EXPECT_NEAR(c.origin_h, 1.2, 1e-12);
    EXPECT_NEAR(c.origin_v, 0.9, 1e-12);
    for (double r : c.marker_residual_m) EXPECT_LT(r, 1e-12);
}

TEST(ModelMarkers, AJointTurnedAboutMinusZReadsTheOppositeSign) {
    // rotate L from T about -z by q2: the same markers give q2 = -(knee angle)
    LegModel m(true);
    const MarkerCoordinates c =
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg());
    EXPECT_EQ(c.turns, (std::vector<std::vector<int>>{{1, 0}, {1, -1}}));
    for (std::size_t k = 0; k < c.motion.row_count(); ++k)
        EXPECT_NEAR(c.motion.columns[2][k], -knee_angle(c.motion.columns[0][k]), 1e-12);
}

TEST(ModelMarkers, AMarkerWhereTheModelDoesNotPutItNamesTheMarkerAndTheCoordinate) {
    // the model's leg is 5 cm longer than the subject's
    LegModel m(false, L_L + 0.05);
    EXPECT_THROW_MSG(
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg()), ModelError,
        "marker 'ANKLE' (on L) is");
    EXPECT_THROW_MSG(
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg()), ModelError,
        "check the sign and offset of 'q2'");
}

TEST(ModelMarkers, ACoordinateNoSegmentsMarkersDetermineIsNamed) {
    LegModel m;
    m.markers.pop_back();  // no ankle: the leg has one marker
    EXPECT_THROW_MSG(
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg()), ModelError,
        "coordinate 'q2' turns no segment with two markers");
}

TEST(ModelMarkers, ACoordinateThatDoesNotTurnASegmentByOneIsRefused) {
    // a thigh whose drawing turns twice as fast as its coordinate: not a planar rotation by q1
    LegModel m;
    const ex a = 2 * m.q1.symbol();
    m.markers = {{"HIP", "T", 0, 0}, {"KNEE", "T", L_T * sin(a), -L_T * cos(a)}};
    EXPECT_THROW_MSG(calc_coordinates_from_markers(m.table, {m.q1}, m.markers, swinging_leg()),
                     ModelError, "coordinate 'q1' turns segment T by 2 rad per rad");
}

TEST(ModelMarkers, AMarkerTheFileLacksIsNamed) {
    LegModel m;
    m.markers[3].name = "HEEL";
    EXPECT_THROW_MSG(
        calc_coordinates_from_markers(m.table, {m.q1, m.q2}, m.markers, swinging_leg()),
        ArgumentError, "HEEL");
}

}  // namespace
}  // namespace alembert
