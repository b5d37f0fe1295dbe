// SPDX-License-Identifier: MIT
// Gaps filled and irregular time bases resampled by natural cubic splines, and reported.
#include "alembert/biomech/time_base.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
                                "filled by a natural cubic spline through its valid samples (gaps of up to 0.1 s "
                                "are filled, longer ones refused)"),
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
                     "walk.trc: 'HEEL' is missing from t = 0 s to 0 s (1 samples: frames 1 to 1), at the "
                     "start of the trial, where no interpolation is possible; trim the trial");
    t.columns[1] = {0, kNaN, kNaN, 3};
    EXPECT_THROW_MSG(regularize_time_base(t, 0, "walk.trc"), ArgumentError,
                     "'HEEL' is missing from t = 0.1 s to 0.2 s (2 samples: frames 2 to 3), a gap of 0.3 s, "
                     "longer than the 0.1 s that may be filled");
    TimeBaseOptions wide;
    wide.max_gap_s = 0.5;
    EXPECT_NO_THROW(regularize_time_base(t, 0, "walk.trc", wide));
    EXPECT_NEAR(t.columns[1][1], 1.0, 1e-12);
}

namespace fs = std::filesystem;

// a .trc of one marker M moving x = 100 + 50 sin(2 pi t) mm at `rate` Hz (times k / rate, as
// printf("%.<decimals>f") writes them, plus `jitter` s on every third and -jitter on the next),
// and a marker NEVER the cameras never saw; DataRate `header_rate`
fs::path write_trc(const std::string& name, int frames, double rate, double header_rate, int decimals,
                   double jitter = 0) {
    const fs::path p = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".trc");
    std::ofstream out(p);
    out << "PathFileType\t4\t(X/Y/Z)\t" << name << ".trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
        << header_rate << "\t" << header_rate << "\t" << frames << "\t2\tmm\n"
        << "Frame#\tTime\tM\t\t\tNEVER\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n";
    char time[64], x[64];
    for (int k = 0; k < frames; ++k) {
        const double wobble = jitter * (k % 3 == 1 ? 1 : k % 3 == 2 ? -1 : 0);
        const double t = k / rate + wobble;
        std::snprintf(time, sizeof time, "%.*f", decimals, t);
        std::snprintf(x, sizeof x, "%.6f", 100 + 50 * std::sin(2 * std::numbers::pi * t));
        out << k + 1 << "\t" << time << "\t" << x << "\t500\t20\t\t\t\n";
    }
    return p;
}

double x_true(double t) { return (100 + 50 * std::sin(2 * std::numbers::pi * t)) * 1e-3; }

TEST(RegularizeTimeBase, A60HzTrcWithMillisecondTimesIsReadAtItsDataRate) {
    // 151 frames over 2.5 s at 60 Hz, times rounded to ms (0, 0.017, 0.033, 0.05, ...): the
    // header's rate holds, so the frames stay 151 at 60 Hz, nothing resampled
    const fs::path p = write_trc("rounded60", 151, 60, 60, 3);
    MarkerTable m = select_markers(read_trc(p.string()), {"M"});
    const TimeBaseReport r = regularize_time_base(m.table, 0, p.string(), {.rate_hz = m.data_rate_hz});
    EXPECT_FALSE(r.resampled);
    EXPECT_TRUE(r.times_rounded);
    EXPECT_TRUE(r.rate_from_file);
    EXPECT_EQ(r.samples_out, 151u);
    EXPECT_DOUBLE_EQ(r.rate_hz, 60.0);
    ASSERT_EQ(m.table.row_count(), 151u);
    // times on the 60 Hz grid, the marker's values as recorded
    for (std::size_t k : {1u, 2u, 75u, 150u}) {
        EXPECT_NEAR(m.table.columns[0][k], k / 60.0, 1e-12) << k;
        EXPECT_NEAR(m.table.columns[m.column("M", 0)][k], x_true(k / 60.0), 1e-9) << k;  // printed to 1e-6 mm
    }
    EXPECT_NE(r.describe().find("151 samples at 60 Hz (the rate the file states); the time column is printed to "
                                "0.001 s and lies on that grid within its precision"),
              std::string::npos)
        << r.describe();
    fs::remove(p);
}

TEST(RegularizeTimeBase, JitterBeyondThePrintedPrecisionIsResampledAtTheStatedRate) {
    // 0.3 ms of jitter at 100 Hz, times printed to 0.1 ms: resampled at the header's 100 Hz,
    // and the spline through the jittered samples gives the marker at the grid's times
    const fs::path p = write_trc("jitter100", 101, 100, 100, 4, 0.3e-3);
    MarkerTable m = select_markers(read_trc(p.string()), {"M"});
    const TimeBaseReport r = regularize_time_base(m.table, 0, p.string(), {.rate_hz = m.data_rate_hz});
    EXPECT_TRUE(r.resampled);
    EXPECT_TRUE(r.rate_from_file);
    EXPECT_DOUBLE_EQ(r.rate_hz, 100.0);
    EXPECT_NEAR(std::abs(r.worst_offset_s), 0.3e-3, 1e-6);
    ASSERT_EQ(m.table.row_count(), 101u);
    // a natural cubic spline through 100 Hz samples of a 1 Hz sine: within 2e-6 m inside
    for (std::size_t k = 5; k <= 95; k += 10) {
        EXPECT_NEAR(m.table.columns[0][k], k / 100.0, 1e-12);
        EXPECT_NEAR(m.table.columns[m.column("M", 0)][k], x_true(k / 100.0), 2e-6) << k;
    }
    EXPECT_NE(r.describe().find("101 samples became 101 at 100 Hz (the rate the file states) by a natural cubic "
                                "spline per column (a time was 0.3 ms off the uniform grid"),
              std::string::npos)
        << r.describe();
    fs::remove(p);
}

TEST(RegularizeTimeBase, AStepLongerThanTheLargestGapIsRefusedNamingItsTimes) {
    Table t;
    t.add_column("t", "s");
    t.add_column("q", "rad");
    t.columns = {{0, 0.01, 0.02, 0.25, 0.26}, {0, 1, 2, 3, 4}};
    t.lines = {7, 8, 9, 10, 11};
    EXPECT_THROW_MSG(regularize_time_base(t, 0, "walk.trc"), ArgumentError,
                     "walk.trc:10: the time column jumps from t = 0.02 s to 0.25 s (frames 3 to 4, lines 9 "
                     "to 10), a step of 0.23 s, longer than the 0.1 s");
}

TEST(RegularizeTimeBase, AMarkerTheModelDoesNotUseNeverBlocksTheTrial) {
    // NEVER has no valid sample: the whole table is refused, the markers used are not
    const fs::path p = write_trc("unused", 31, 60, 60, 3);
    MarkerTable all = read_trc(p.string());
    EXPECT_THROW_MSG(regularize_time_base(all.table, 0, p.string()), ArgumentError,
                     "'NEVER' has 0 valid samples of 31");
    MarkerTable used = select_markers(all, {"M"});
    EXPECT_EQ(used.markers, (std::vector<std::string>{"M"}));
    EXPECT_EQ(used.table.columns.size(), 4u);
    EXPECT_NO_THROW(regularize_time_base(used.table, 0, p.string(), {.rate_hz = used.data_rate_hz}));
    EXPECT_THROW_MSG(select_markers(all, {"M", "LASI"}), ArgumentError, "no marker 'LASI' in the marker file");
    fs::remove(p);
}

}  // namespace
}  // namespace alembert
