// SPDX-License-Identifier: MIT
// Motions: minimum jerk by hand, exact derivatives of formulas, sampled data in degrees.
#include "alembert/sim/motion.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
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

}  // namespace
}  // namespace alembert
