// SPDX-License-Identifier: MIT
// Motions: minimum jerk by hand, exact derivatives of formulas, sampled data in degrees.
#include "alembert/sim/motion.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "alembert/error.hpp"
#include "support/constants.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;
using test::kDeg;

TEST(PrescribedMotion, MinimumJerkHasTheTextbookValueRateAndAcceleration) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    // q = 10 deg + 90 deg s((t - 0.2) / 1.3)
    PrescribedMotion motion(s, {q}, {10 * kDeg + 90 * kDeg * minimum_jerk(s.time(), 0.2, 1.5)});
    const double T = 1.3, A = 90 * kDeg;
    for (double t : {0.0, 0.2, 0.5, 0.85, 1.2, 1.5, 2.0}) {
        const double u = std::clamp((t - 0.2) / T, 0.0, 1.0);
        const double s0 = 10 * std::pow(u, 3) - 15 * std::pow(u, 4) + 6 * std::pow(u, 5);
        const double s1 = (30 * u * u - 60 * std::pow(u, 3) + 30 * std::pow(u, 4)) / T;
        const double s2 = (60 * u - 180 * u * u + 120 * std::pow(u, 3)) / (T * T);
        double value, rate, acceleration;
        motion.calc_state(t, &value, &rate, &acceleration);
        EXPECT_NEAR(value, 10 * kDeg + A * s0, 1e-14) << "t = " << t;
        EXPECT_NEAR(rate, A * s1, 1e-13) << "t = " << t;
        EXPECT_NEAR(acceleration, A * s2, 1e-12) << "t = " << t;
    }
}

TEST(PrescribedMotion, AFormulaWithAnUnknownSymbolIsNamed) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex w = s.add_constant("omega");
    EXPECT_THROW_MSG(PrescribedMotion(s, {q}, {GiNaC::sin(w * s.time())}), ArgumentError, "omega");
}

TEST(ReadMotion, ConvertsDegreesFiltersAndDifferentiates) {
    // a slow sine in degrees at 200 Hz: the filter barely touches it, so q' and q'' follow
    // the exact derivatives away from the ends
    const fs::path p =
        fs::temp_directory_path() / ("alembert_motion_" + std::to_string(::getpid()) + ".csv");
    {
        std::ofstream out(p);
        out << "t [s],qB [deg],other [m]\n";
        for (int i = 0; i <= 400; ++i) {
            const double t = i / 200.0;
            out << t << "," << 30 * std::sin(2 * std::numbers::pi * 0.5 * t) << ",1\n";
        }
    }
    MotionSamples m = read_motion(p, {"qB"}, {.cutoff_hz = 8});
    const double w = std::numbers::pi, A = 30 * kDeg;
    ASSERT_EQ(m.t.size(), 401u);
    for (std::size_t i = 100; i <= 300; i += 20) {
        const double t = m.t[i];
        EXPECT_NEAR(m.q[0][i], A * std::sin(w * t), 1e-4);
        EXPECT_NEAR(m.qd[0][i], A * w * std::cos(w * t), 1e-3);
        EXPECT_NEAR(m.qdd[0][i], -A * w * w * std::sin(w * t), 1e-2);
    }
    EXPECT_THROW_MSG(read_motion(p, {"qA"}), ArgumentError,
                     "no column for the coordinate 'qA'; name a column 'qA [deg]' (columns "
                     "found: t, qB, other)");
    fs::remove(p);
}

Table one_coordinate(const std::string& name, const std::string& unit,
                     const std::string& time_unit = "s") {
    Table t;
    t.add_column("t", time_unit);
    t.add_column(name, unit);
    t.columns = {{0, 0.01, 0.02, 0.03, 0.04}, {10, 10, 10, 10, 10}};
    return t;
}

TEST(ReadMotion, AColumnInAUnitOfAnotherQuantityIsRefused) {
    MotionFilterOptions deg{.cutoff_hz = 0, .declared_units = {"deg"}};
    EXPECT_THROW_MSG(differentiate_motion(one_coordinate("q1", "m"), "m.csv", {"q1"}, deg),
                     ArgumentError,
                     "m.csv: column 'q1 [m]' is a length, but the coordinate 'q1' is an angle "
                     "(declared in deg); give the column a unit of an angle (deg, rad)");
    MotionFilterOptions metres{.cutoff_hz = 0, .declared_units = {"m"}};
    EXPECT_THROW_MSG(differentiate_motion(one_coordinate("x", "deg"), "m.csv", {"x"}, metres),
                     ArgumentError, "column 'x [deg]' is an angle, but the coordinate 'x' is a length");
    // a coordinate of no stated unit still takes only angles and lengths
    EXPECT_THROW_MSG(differentiate_motion(one_coordinate("q", "N"), "m.csv", {"q"}, {.cutoff_hz = 0}),
                     ArgumentError, "column 'q [N]' is a force, but the coordinate 'q' is an angle or a length");
    EXPECT_THROW_MSG(differentiate_motion(one_coordinate("q", "deg", "deg"), "m.csv", {"q"}, deg),
                     ArgumentError, "m.csv: the time column 't [deg]' is in a unit of angle");
}

TEST(ReadMotion, AColumnWithoutAUnitIsNeverReadAsRadiansForACoordinateInDegrees) {
    MotionFilterOptions deg{.cutoff_hz = 0, .declared_units = {"deg"}};
    EXPECT_THROW_MSG(differentiate_motion(one_coordinate("q1", ""), "m.csv", {"q1"}, deg),
                     ArgumentError,
                     "m.csv: column 'q1' has no unit, but the coordinate 'q1' is declared in deg");
    // an explicit setting says how to read it
    deg.unitless_unit = "deg";
    MotionSamples m = differentiate_motion(one_coordinate("q1", ""), "m.csv", {"q1"}, deg);
    EXPECT_NEAR(m.q[0][0], 10 * kDeg, 1e-15);
    // a coordinate declared in SI, or not declared, reads a bare column in SI
    MotionFilterOptions rad{.cutoff_hz = 0, .declared_units = {"rad"}};
    EXPECT_EQ(differentiate_motion(one_coordinate("q1", ""), "m.csv", {"q1"}, rad).q[0][0], 10);
    EXPECT_EQ(differentiate_motion(one_coordinate("q1", ""), "m.csv", {"q1"}, {.cutoff_hz = 0}).q[0][0], 10);
}

TEST(ReadMotion, TwoTimeColumnsAreRefused) {
    Table t = one_coordinate("q", "rad");
    t.add_column("time", "s");
    t.columns[2] = t.columns[0];
    EXPECT_THROW_MSG(differentiate_motion(t, "m.csv", {"q"}), ArgumentError,
                     "m.csv: two time columns, 't' and 'time'; keep one of them");
}

TEST(ReadMotion, UnevenTimesAreReportedWithTheLine) {
    Table t;
    t.add_column("t", "s");
    t.add_column("q", "rad");
    t.columns = {{0, 0.01, 0.02, 0.035, 0.04}, {0, 0, 0, 0, 0}};
    t.lines = {2, 3, 4, 5, 6};
    EXPECT_THROW_MSG(differentiate_motion(t, "walk.csv", {"q"}), ArgumentError,
                     "walk.csv:5: time step 0.015");
    t.columns[0] = {0, 0.01, 0.01, 0.02, 0.03};
    EXPECT_THROW_MSG(differentiate_motion(t, "walk.csv", {"q"}), ArgumentError,
                     "walk.csv:4: time 0.010000 s does not increase");
}

TEST(ReadMotion, TimesPrintedTo8DecimalsAt150HzAreUniformAndDifferentiateExactly) {
    // q = 0.5 sin(2 pi t) rad at 150 Hz, times and values as a .mot prints them (8 decimals):
    // steps of 0.00666666 and 0.00666667 s are the rounding of 1/150 s, not jitter
    Table t;
    t.add_column("t", "s");
    t.add_column("q", "rad");
    char cell[64];
    const double w = 2 * std::numbers::pi;
    for (int k = 0; k <= 150; ++k) {
        std::snprintf(cell, sizeof cell, "%.8f", k / 150.0);
        t.columns[0].push_back(std::strtod(cell, nullptr));
        t.columns[1].push_back(0.5 * std::sin(w * k / 150.0));
    }
    const MotionSamples m = differentiate_motion(t, "walk.mot", {"q"}, {.cutoff_hz = 0});
    // central differences at h = 1/150 s err by (w h)^2/6 = 2.9e-4 of q' and (w h)^2/12 of q''
    for (int k = 10; k <= 140; k += 10) {
        const double tk = k / 150.0;
        EXPECT_NEAR(m.qd[0][k], 0.5 * w * std::cos(w * tk), 3.5e-4 * 0.5 * w) << tk;
        EXPECT_NEAR(m.qdd[0][k], -0.5 * w * w * std::sin(w * tk), 2e-4 * 0.5 * w * w) << tk;
    }
}

TEST(ReadMotion, AMissingSampleIsRefusedWithItsColumnAndTime) {
    Table t;
    t.add_column("t", "s");
    t.add_column("q", "rad");
    t.columns = {{0, 0.01, 0.02, 0.03, 0.04}, {0, 0.1, std::nan(""), 0.3, 0.4}};
    t.lines = {8, 9, 10, 11, 12};
    EXPECT_THROW_MSG(differentiate_motion(t, "walk.mot", {"q"}), ArgumentError,
                     "walk.mot:10: column 'q' has no value (NaN) at t = 0.02 s; a missing coordinate is not "
                     "read as data");
}

TEST(ReadMotion, AColumnInMetresForARotationIsRefusedNamingBoth) {
    // the coordinate is declared without a unit, but turns a frame of the model: an angle
    Table t = one_coordinate("qA", "m");
    MotionFilterOptions o;
    o.kinematic_quantities = {"angle"};
    EXPECT_THROW_MSG(differentiate_motion(t, "m.csv", {"qA"}, o), ArgumentError,
                     "m.csv: column 'qA [m]' is a length, but the coordinate 'qA' is an angle (it turns a "
                     "frame of the model); give the column a unit of an angle (deg, rad)");
    // and a translation read from degrees
    Table x = one_coordinate("x", "deg");
    o.kinematic_quantities = {"length"};
    EXPECT_THROW_MSG(differentiate_motion(x, "m.csv", {"x"}, o), ArgumentError,
                     "column 'x [deg]' is an angle, but the coordinate 'x' is a length (it moves points of "
                     "the model and turns no frame)");
}

}  // namespace
}  // namespace alembert
