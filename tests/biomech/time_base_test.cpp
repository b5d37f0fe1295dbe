// SPDX-License-Identifier: MIT
// Gaps filled and irregular time bases resampled by natural cubic splines, and reported.
#include "alembert/biomech/time_base.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/error.hpp"
#include "biomech_data.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();


TEST(RegularizeTimeBase, FillsAMarkerGapOnAStraightPathExactlyAndNamesItsTimes) {
    MarkerTable m = read_trc(test::biomech_data("gappy.trc"));
    TimeBaseReport r = regularize_time_base(m.table, 0, "gappy.trc");
    // the ankle moves 100 mm/s in X: 110, (111), (112), 113, 114 mm
    EXPECT_NEAR(m.table.columns[m.column("R.Ankle", 0)][1], 0.111, 1e-15);
    EXPECT_NEAR(m.table.columns[m.column("R.Ankle", 0)][2], 0.112, 1e-15);
    EXPECT_NEAR(m.table.columns[m.column("R.Ankle", 1)][2], 0.080, 1e-15);
    ASSERT_EQ(r.gaps.size(), 1u);  // X, Y and Z of one marker are one gap
    EXPECT_EQ(r.gaps[0].name, "R.Ankle");
    EXPECT_DOUBLE_EQ(r.gaps[0].t_first, 0.01);
    EXPECT_DOUBLE_EQ(r.gaps[0].t_last, 0.02);
    EXPECT_EQ(r.gaps[0].samples, 2u);
    EXPECT_FALSE(r.resampled);
    EXPECT_NE(r.describe().find("gap filled: 'R.Ankle' missing from t = 0.01 s to 0.02 s (2 samples), "
                                "filled by a natural cubic spline"),
              std::string::npos)
        << r.describe();
}

TEST(RegularizeTimeBase, FillsACubicGapCloseToTheTruth) {
    // a smooth signal sampled at 100 Hz with 5 samples missing: the spline fill is within
    // a small fraction of the signal's range of the true values
    Table t;
    t.add_column("t", "s");
    t.add_column("y", "m");
    for (int k = 0; k <= 100; ++k) {
        const double time = 0.01 * k;
        t.columns[0].push_back(time);
        t.columns[1].push_back(k >= 40 && k < 45 ? kNaN : std::sin(2 * std::numbers::pi * time));
    }
    TimeBaseReport r = regularize_time_base(t, 0, "sine");
    for (int k = 40; k < 45; ++k) EXPECT_NEAR(t.columns[1][k], std::sin(2 * std::numbers::pi * 0.01 * k), 1e-4);
    EXPECT_EQ(r.gaps.size(), 1u);
}

TEST(RegularizeTimeBase, ResamplesAnIrregularTimeBaseAtTheMedianStep) {
    Table t = read_csv(test::biomech_data("irregular.csv"));  // ms: 0, 10, 25, 30; hip 10, 12, 14, 16 deg
    TimeBaseReport r = regularize_time_base(t, 0, "irregular.csv");
    EXPECT_TRUE(r.resampled);
    EXPECT_DOUBLE_EQ(r.min_step_s, 0.005);
    EXPECT_DOUBLE_EQ(r.max_step_s, 0.015);
    EXPECT_DOUBLE_EQ(r.rate_hz, 100.0);
    ASSERT_EQ(r.samples_out, 4u);
    // times stay in the column's unit (ms)
    EXPECT_NEAR(t.columns[0][2], 20.0, 1e-12);
    EXPECT_NEAR(t.columns[0][3], 30.0, 1e-12);
    // the samples themselves are kept where the grid meets them
    EXPECT_NEAR(t.columns[1][1], 12.0, 1e-12);
    EXPECT_NEAR(t.columns[1][3], 16.0, 1e-12);
    EXPECT_NE(r.describe().find("time base resampled: steps from 0.005 s to 0.015 s are not uniform; "
                                "4 samples became 4 at 100 Hz"),
              std::string::npos)
        << r.describe();
}

TEST(RegularizeTimeBase, AUniformCompleteTableIsLeftAlone) {
    Table t;
    t.add_column("t", "s");
    t.add_column("q", "rad");
    t.columns[0] = {0, 0.1, 0.2};
    t.columns[1] = {1, 5, 2};
    TimeBaseReport r = regularize_time_base(t, 0, "x");
    EXPECT_EQ(t.columns[1], (std::vector<double>{1, 5, 2}));
    EXPECT_NE(r.describe().find("nothing filled or resampled"), std::string::npos);
}

TEST(RegularizeTimeBase, GapsAtTheEndsOrTooLongAreRefusedWithTheirTimes) {
    Table t;
    t.add_column("t", "s");
    t.add_column("HEEL.X", "m");
    t.columns[0] = {0, 0.1, 0.2, 0.3};
    t.columns[1] = {kNaN, 1, 2, 3};
    Table start = t;
    EXPECT_THROW_MSG(regularize_time_base(start, 0, "walk.trc"), ArgumentError,
                     "walk.trc: 'HEEL' is missing from t = 0 s to 0 s (1 samples), at the start of "
                     "the trial, where no interpolation is possible; trim the trial");
    t.columns[1] = {0, kNaN, kNaN, 3};
    EXPECT_THROW_MSG(regularize_time_base(t, 0, "walk.trc"), ArgumentError,
                     "'HEEL' is missing from t = 0.1 s to 0.2 s (2 samples), a gap of 0.3 s, longer "
                     "than the 0.1 s that may be filled");
    TimeBaseOptions wide;
    wide.max_gap_s = 0.5;
    EXPECT_NO_THROW(regularize_time_base(t, 0, "walk.trc", wide));
    EXPECT_NEAR(t.columns[1][1], 1.0, 1e-12);
}

}  // namespace
}  // namespace alembert
