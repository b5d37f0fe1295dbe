// SPDX-License-Identifier: MIT
// The zero-lag Butterworth filter's gain and phase, and finite differences' orders.
#include "alembert/sim/filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "alembert/error.hpp"
#include "support/constants.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using test::kPi;

// amplitude and lag (in samples) of the filtered sine, measured in the middle of a long record
void response(double f, double fs, double fc, double& gain, double& lag) {
    const int n = 4000;
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = std::sin(2 * kPi * f * i / fs);
    std::vector<double> y = filter_lowpass(x, fs, fc);
    // least squares of y = a sin + b cos over the middle half
    double ss = 0, cc = 0, sc = 0, ys = 0, yc = 0;
    for (int i = n / 4; i < 3 * n / 4; ++i) {
        const double s = std::sin(2 * kPi * f * i / fs), c = std::cos(2 * kPi * f * i / fs);
        const double yi = y[static_cast<std::size_t>(i)];
        ss += s * s, cc += c * c, sc += s * c, ys += yi * s, yc += yi * c;
    }
    const double det = ss * cc - sc * sc;
    const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
    gain = std::hypot(a, b);
    lag = std::atan2(-b, a);
}

TEST(FilterLowpass, PassesLowFrequenciesHalvesPowerAtTheCutoffAndHasNoLag) {
    double gain = 0, phase = 0;
    response(0.5, 100, 6, gain, phase);
    EXPECT_NEAR(gain, 1.0, 1e-3);
    EXPECT_NEAR(phase, 0.0, 1e-9);
    // the combined two-pass filter is -3 dB at the cutoff (Winter's correction)
    response(6, 100, 6, gain, phase);
    EXPECT_NEAR(gain, 1 / std::sqrt(2.0), 0.01);
    EXPECT_NEAR(phase, 0.0, 1e-9);
    // two passes of a second-order section at f_c' = f_c / 0.802: gain 1 / (1 + (f/f_c')^4),
    // 0.0094 two octaves above the cutoff for the analog prototype (the bilinear transform
    // only lowers it)
    response(24, 100, 6, gain, phase);
    EXPECT_LT(gain, 0.0095);
}

TEST(FilterLowpass, KeepsAStraightLineExactlyUpToTheEnds) {
    std::vector<double> x(200);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = 2.0 - 0.03 * static_cast<double>(i);
    std::vector<double> y = filter_lowpass(x, 100, 6);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(y[i], x[i], 1e-9) << i;
}

TEST(FilterLowpass, RefusesACutoffAboveNyquist) {
    std::vector<double> x(10, 1.0);
    EXPECT_THROW_MSG(filter_lowpass(x, 100, 45), ArgumentError, "is too high for samples at");
}

TEST(Differentiate, IsExactForQuadraticsAndCubicsRespectively) {
    const double h = 0.01;
    std::vector<double> x(50);
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = h * static_cast<double>(i);
        x[i] = 1 + 2 * t - 3 * t * t;
    }
    std::vector<double> d = differentiate(x, h), dd = differentiate_twice(x, h);
    for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_NEAR(d[i], 2 - 6 * h * static_cast<double>(i), 1e-10);
        EXPECT_NEAR(dd[i], -6, 1e-7);
    }
}

}  // namespace
}  // namespace alembert
