// SPDX-License-Identifier: MIT
// calc_static_length on static trials generated with known segment lengths: a subject swaying
// as a rigid chain (the lengths exact), with marker noise (the mean within its standard error),
// with a gap, and the trials it refuses.
#include "alembert/biomech/static_trial.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

// The right leg standing for 2 s at 100 Hz: the hip sways 4 mm forward and back, the thigh and
// the leg lean by a few degrees, the knee's marker 6 cm lateral of the hip's (Z), so the
// lengths are distances in space: thigh 0.4123 m (HIP to KNEE), leg 0.4317 m (KNEE to ANKLE).
constexpr double kThigh = 0.4123, kLeg = 0.4317, kLateral = 0.06, kAlong = 0.18, kAcross = 0.06;
constexpr std::size_t kFrames = 200;

// uniform on (-h, h), a fixed sequence (the standard minimal generator of Park and Miller)
struct StaticNoise {
    std::uint64_t state = 20261127;
    double operator()(double h) {
        state = state * 48271 % 2147483647;
        return h * (2.0 * static_cast<double>(state) / 2147483647.0 - 1.0);
    }
};

MarkerTable standing_trial(double noise_m) {
    MarkerTable m;
    m.markers = {"HIP", "KNEE", "ANKLE", "THI"};
    m.data_rate_hz = 100, m.file_unit = "m";
    m.table.add_column("time", "s");
    for (const std::string& name : m.markers)
        for (const char* axis : {".X", ".Y", ".Z"}) m.table.add_column(name + axis, "m");
    StaticNoise noise;
    // the thigh's direction in space: lean a in the sagittal plane, the lateral offset fixed
    const double thigh_sagittal = std::sqrt(kThigh * kThigh - kLateral * kLateral);
    for (std::size_t k = 0; k < kFrames; ++k) {
        const double t = static_cast<double>(k) / 100;
        const double a = 0.05 * std::sin(1.3 * t), b = -0.03 * std::sin(0.9 * t + 0.4);
        const double hip[3] = {0.004 * std::sin(2.1 * t), 0.93, 0.10};
        const double knee[3] = {hip[0] + thigh_sagittal * std::sin(a), hip[1] - thigh_sagittal * std::cos(a),
                                hip[2] + kLateral};
        const double ankle[3] = {knee[0] + kLeg * std::sin(b), knee[1] - kLeg * std::cos(b), knee[2]};
        // a thigh marker kAlong down the thigh's line in the plane (u) and kAcross in front of it
        // (n, u turned a quarter turn counterclockwise: (cos a, sin a)), 3 cm lateral
        const double thi[3] = {hip[0] + kAlong * std::sin(a) + kAcross * std::cos(a),
                               hip[1] - kAlong * std::cos(a) + kAcross * std::sin(a), hip[2] + 0.03};
        m.table.columns[0].push_back(t);
        std::size_t col = 1;
        for (const double* p : {hip, knee, ankle, thi})
            for (int i = 0; i < 3; ++i) m.table.columns[col++].push_back(p[i] + noise(noise_m));
    }
    return m;
}

TEST(StaticLength, ARigidSwayGivesTheLengthsExactly) {
    const MarkerTable m = standing_trial(0);
    const StaticLength thigh = calc_static_length(m, "HIP", "KNEE");
    const StaticLength leg = calc_static_length(m, "KNEE", "ANKLE");
    EXPECT_NEAR(thigh.length_m, kThigh, 1e-14);
    EXPECT_NEAR(leg.length_m, kLeg, 1e-14);
    EXPECT_EQ(thigh.frames, kFrames);
    EXPECT_LT(thigh.sd_m, 1e-14);
    EXPECT_LT(leg.max_deviation_m, 1e-14);
    EXPECT_EQ(thigh.from, "HIP");
    EXPECT_EQ(thigh.to, "KNEE");
}

TEST(StaticLength, NoisyMarkersGiveTheLengthWithinTheMeansStandardError) {
    // noise uniform on +-0.5 mm per coordinate: sigma = 1 mm / sqrt(12) = 0.289 mm; a distance
    // takes the difference of two markers along the segment, sigma_d = sqrt(2) 0.289 = 0.408 mm;
    // the mean of 189 frames (11 lost to the gap) has a standard error of 0.408 / sqrt(189) =
    // 0.030 mm: the lengths within 4 of them, 0.12 mm; the bias of a distance from noise across
    // the segment, sigma^2 / L, is below 1e-6 mm. The frames' standard deviation estimates
    // sigma_d to 5 % (1 / sqrt(2 N)): within 20 %.
    MarkerTable m = standing_trial(0.0005);
    for (std::size_t k = 50; k <= 60; ++k)
        for (int a = 0; a < 3; ++a) m.table.columns[m.column("KNEE", a)][k] = std::numeric_limits<double>::quiet_NaN();
    const double sigma_d = std::sqrt(2.0) * 0.001 / std::sqrt(12.0);
    for (const auto& [from, to, L] : {std::tuple{"HIP", "KNEE", kThigh}, std::tuple{"KNEE", "ANKLE", kLeg}}) {
        SCOPED_TRACE(std::string(from) + "-" + to);
        const StaticLength s = calc_static_length(m, from, to);
        EXPECT_EQ(s.frames, kFrames - 11);
        EXPECT_NEAR(s.length_m, L, 4 * sigma_d / std::sqrt(189.0));
        EXPECT_NEAR(s.sd_m, sigma_d, 0.2 * sigma_d);
        EXPECT_LT(s.max_deviation_m, 0.002);  // at most 4 coordinates' worth of 0.5 mm
    }
    // HIP to ANKLE is not one segment: the knee bends by b - a (up to 0.08 rad), so their
    // distance changes by up to 0.7 mm (law of cosines), more than a limit of 0.1 mm
    StaticLengthOptions tight;
    tight.max_deviation_m = 1e-4;
    EXPECT_THROW_MSG(calc_static_length(m, "HIP", "ANKLE", tight), ArgumentError,
                     "calc_static_length(HIP, ANKLE): the distance between 'HIP' and 'ANKLE' is ");
}

TEST(StaticLength, TrialsThatCannotGiveALengthAreRefusedWithTheReason) {
    MarkerTable m = standing_trial(0);
    EXPECT_THROW_MSG(calc_static_length(m, "HIP", "TOE"), ArgumentError,
                     "calc_static_length(HIP, TOE): MarkerTable::column(): no marker 'TOE' in the marker file; its "
                     "markers are: HIP, KNEE, ANKLE, THI");
    EXPECT_THROW_MSG(calc_static_length(m, "HIP", "HIP"), ArgumentError, "the marker 'HIP' is given twice");
    // a marker swapped with another for one frame: the distance jumps, and the time is named
    MarkerTable swapped = m;
    for (int a = 0; a < 3; ++a)
        std::swap(swapped.table.columns[swapped.column("KNEE", a)][120], swapped.table.columns[swapped.column("ANKLE", a)][120]);
    EXPECT_THROW_MSG(calc_static_length(swapped, "HIP", "KNEE"), ArgumentError, "at t = 1.2 s (more than 0.01 m)");
    // never seen together
    for (std::size_t k = 0; k < kFrames; ++k) m.table.columns[m.column("ANKLE", 1)][k] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW_MSG(calc_static_length(m, "KNEE", "ANKLE"), ArgumentError,
                     "no frame of the trial (200 frames) sees both 'KNEE' and 'ANKLE'");
}

TEST(StaticPlace, AThighMarkerIsPlacedAlongAndAcrossTheHipToKneeLine) {
    // the rigid sway: 0.18 m down the line from the hip, 0.06 m in front of it, at every frame
    const StaticPlace p = calc_static_place(standing_trial(0), "HIP", "KNEE", "THI");
    EXPECT_EQ(p.marker, "THI");
    EXPECT_EQ(p.frames, kFrames);
    EXPECT_NEAR(p.along_m, kAlong, 1e-14);
    EXPECT_NEAR(p.across_m, kAcross, 1e-14);
    EXPECT_LT(p.sd_along_m, 1e-14);
    EXPECT_LT(p.sd_across_m, 1e-14);
    // measured from the knee towards the hip the line turns by half a turn: along is the
    // distance from the knee, kThigh's projection in the plane less kAlong, across changes sign
    const double thigh_in_plane = std::sqrt(kThigh * kThigh - kLateral * kLateral);
    const StaticPlace q = calc_static_place(standing_trial(0), "KNEE", "HIP", "THI");
    EXPECT_NEAR(q.along_m, thigh_in_plane - kAlong, 1e-14);
    EXPECT_NEAR(q.across_m, -kAcross, 1e-14);
}

TEST(StaticPlace, MarkersGivenTwiceOrNeverSeenTogetherAreRefused) {
    MarkerTable m = standing_trial(0);
    EXPECT_THROW_MSG(calc_static_place(m, "HIP", "KNEE", "HIP"), ArgumentError, "a marker is given twice");
    EXPECT_THROW_MSG(calc_static_place(m, "HIP", "KNEE", "TOE"), ArgumentError,
                     "calc_static_place(HIP, KNEE, TOE): MarkerTable::column(): no marker 'TOE'");
    for (std::size_t k = 0; k < kFrames; ++k) m.table.columns[m.column("THI", 0)][k] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW_MSG(calc_static_place(m, "HIP", "KNEE", "THI"), ArgumentError,
                     "no frame of the trial (200 frames) sees 'HIP', 'KNEE' and 'THI' together");
}

}  // namespace
}  // namespace alembert
