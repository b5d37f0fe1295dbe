// SPDX-License-Identifier: MIT
// Uniform time bases as lab files print them: rounding within the printed precision is not jitter.
#include "alembert/sim/time_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace alembert {
namespace {

// the times k / rate_hz, k = 0 ... n - 1, as printf("%.<decimals>f") writes and strtod reads them
std::vector<double> printed_times(int n, double rate_hz, int decimals, double jitter_s = 0) {
    std::vector<double> t;
    char cell[64];
    for (int k = 0; k < n; ++k) {
        const double wobble = jitter_s * (k % 3 == 1 ? 1 : k % 3 == 2 ? -1 : 0);
        std::snprintf(cell, sizeof cell, "%.*f", decimals, k / rate_hz + wobble);
        t.push_back(std::strtod(cell, nullptr));
    }
    return t;
}

TEST(PrintedResolution, IsTheLastDigitTheTimesAreWrittenTo) {
    EXPECT_DOUBLE_EQ(calc_printed_resolution(printed_times(151, 60, 3)), 1e-3);
    EXPECT_DOUBLE_EQ(calc_printed_resolution(printed_times(300, 150, 8)), 1e-8);
    EXPECT_DOUBLE_EQ(calc_printed_resolution({0, 0.01, 0.02}), 0.01);
    // written in full (17 significant digits): no printed precision
    std::vector<double> full;
    for (int k = 0; k < 20; ++k) full.push_back(k / 150.0);
    EXPECT_EQ(calc_printed_resolution(full), 0.0);
}

TEST(UniformTimeBase, SixtyHertzRoundedToMillisecondsIsUniformAtTheStatedRate) {
    // 0, 0.017, 0.033, 0.05, ...: steps of 16 and 17 ms, 151 samples over 2.5 s
    const std::vector<double> t = printed_times(151, 60, 3);
    const UniformTimeBase b = calc_uniform_time_base(t, 60);
    EXPECT_TRUE(b.uniform);
    EXPECT_TRUE(b.step_from_rate);
    EXPECT_DOUBLE_EQ(b.step, 1.0 / 60);
    EXPECT_DOUBLE_EQ(b.resolution, 1e-3);
    EXPECT_LE(std::abs(b.worst_offset), 0.5e-3 + 1e-12);  // the rounding of one time
    // without the stated rate the mean step gives the same 60 Hz
    const UniformTimeBase m = calc_uniform_time_base(t);
    EXPECT_TRUE(m.uniform);
    EXPECT_NEAR(1 / m.step, 60, 1e-9);
    EXPECT_NE(b.describe(t.size()).find(
                  "151 samples at 60 Hz (the rate the file states); the times are printed "
                  "to 0.001 s"),
              std::string::npos)
        << b.describe(t.size());
}

TEST(UniformTimeBase, OneHundredFiftyHertzPrintedToEightDecimalsIsUniform) {
    // steps of 0.00666666 and 0.00666667 s: 1.5e-6 of the step apart, within the 1e-8 s printed
    const std::vector<double> t = printed_times(301, 150, 8);
    const UniformTimeBase b = calc_uniform_time_base(t);
    EXPECT_TRUE(b.uniform);
    EXPECT_NEAR(1 / b.step, 150, 1e-6);
}

TEST(UniformTimeBase, JitterBeyondThePrintedPrecisionIsNotUniform) {
    // 0.3 ms of jitter at 100 Hz, printed to 0.1 ms: 3 digits of the last place off the grid
    const std::vector<double> t = printed_times(100, 100, 4, 0.3e-3);
    const UniformTimeBase b = calc_uniform_time_base(t, 100);
    EXPECT_FALSE(b.uniform);
    EXPECT_NEAR(std::abs(b.worst_offset), 0.3e-3, 1e-9);
    EXPECT_DOUBLE_EQ(b.tolerance, 1e-4);
    // printed as coarsely as the step, rounding cannot explain an offset of a quarter step
    const UniformTimeBase coarse = calc_uniform_time_base({0, 0.01, 0.03, 0.04, 0.05});
    EXPECT_FALSE(coarse.uniform);
    EXPECT_DOUBLE_EQ(coarse.tolerance, 0.0125 / 4);
}

TEST(UniformTimeBase, AStatedRateTheTimesContradictGivesWayToTheirMeanStep) {
    const std::vector<double> t = printed_times(50, 100, 2);
    const UniformTimeBase b = calc_uniform_time_base(t, 60);
    EXPECT_TRUE(b.uniform);
    EXPECT_FALSE(b.step_from_rate);
    EXPECT_NEAR(b.step, 0.01, 1e-15);
}

}  // namespace
}  // namespace alembert
