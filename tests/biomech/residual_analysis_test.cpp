// SPDX-License-Identifier: MIT
// Winter's residual analysis on a smooth signal plus white noise of known size.
#include "alembert/biomech/residual_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

TEST(ResidualAnalysis, FindsTheNoiseLevelAndACutoffAboveTheSignalsBand) {
    // 1 Hz and 3 Hz components sampled at 100 Hz for 4 s, plus white noise of rms 0.005
    const double fs = 100, sigma = 0.005;
    std::mt19937 rng(12345);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<double> x;
    for (int k = 0; k < 400; ++k) {
        const double t = k / fs;
        x.push_back(std::sin(2 * std::numbers::pi * t) + 0.3 * std::sin(2 * std::numbers::pi * 3 * t) + noise(rng));
    }
    ResidualAnalysis r = calc_residual_analysis(x, fs);
    // white noise through a low-pass of cutoff fc leaves sigma sqrt(1 - fc/fN) behind; the line
    // over the upper half meets fc = 0 near sigma (about 1.06 sigma for an ideal filter)
    EXPECT_GT(r.noise_rms, 0.8 * sigma);
    EXPECT_LT(r.noise_rms, 1.3 * sigma);
    // the chosen cutoff keeps the 3 Hz component and rejects most of the noise band
    EXPECT_GT(r.cutoff_hz, 3.0);
    EXPECT_LT(r.cutoff_hz, 15.0);
    // the residual falls as the cutoff rises
    EXPECT_GT(r.residuals.front(), r.residuals.back());
    EXPECT_DOUBLE_EQ(r.cutoffs_hz.back(), 35.0);
}

TEST(ResidualAnalysis, RefusesTooShortSignalsAndBadRates) {
    EXPECT_THROW_MSG(calc_residual_analysis({1, 2, 3}, 100), ArgumentError, "3 samples");
    EXPECT_THROW_MSG(calc_residual_analysis({1, 2, 3, 4, 5}, -1), ArgumentError, "must be positive");
}

}  // namespace
}  // namespace alembert
