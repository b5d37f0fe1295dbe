// SPDX-License-Identifier: MIT
// Gait events from force plates, cycles, time normalised to 0-100 % and mean +- SD curves,
// checked on records whose crossings, values and statistics are worked by hand.
#include "alembert/biomech/gait_cycles.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "alembert/error.hpp"

namespace gait_cycles_test {

using namespace alembert;

// a plate sampled at 100 Hz from 0 to 1.5 s whose vertical force ramps from 0 to 400 N over
// 0.1 s from `on`, holds, and ramps back to 0 over 0.1 s from `off`
ForcePlate trapezoid(const std::string& name, double on, double off) {
    ForcePlate p;
    p.name = name;
    for (int k = 0; k <= 150; ++k) {
        const double t = 0.01 * k;
        double F = 0;
        if (t > on && t < on + 0.1)
            F = 4000 * (t - on);
        else if (t >= on + 0.1 && t <= off)
            F = 400;
        else if (t > off && t < off + 0.1)
            F = 400 - 4000 * (t - off);
        p.t.push_back(t);
        p.F[1].push_back(F);
        for (int a : {0, 2}) p.F[a].push_back(0);
        for (int a = 0; a < 3; ++a) p.p_CoP[a].push_back(0), p.T_free[a].push_back(0);
    }
    return p;
}

TEST(GaitCycles, ContactsAreWhereTheVerticalForceCrossesTheThreshold) {
    // 20 N is reached 20/4000 = 5 ms into the rise, and left 5 ms before the fall ends:
    // strikes at 0.105 and 1.105 s, foot off at 0.6 + 0.1 (380/400) = 0.695 s; the second
    // contact is still loaded at the end of the record, so it has no off
    const GaitEvents e =
        calc_gait_events({trapezoid("left", 0.1, 0.6), trapezoid("left2", 1.1, 1.5)});
    ASSERT_EQ(e.strikes.size(), 2u);
    ASSERT_EQ(e.offs.size(), 1u);
    EXPECT_NEAR(e.strikes[0], 0.105, 1e-12);
    EXPECT_NEAR(e.strikes[1], 1.105, 1e-12);
    EXPECT_NEAR(e.offs[0], 0.695, 1e-12);
    const std::vector<GaitCycle> cycles = calc_gait_cycles(e);
    ASSERT_EQ(cycles.size(), 1u);
    EXPECT_NEAR(cycles[0].start, 0.105, 1e-12);
    EXPECT_NEAR(cycles[0].end, 1.105, 1e-12);
    // stance of 0.59 s in a cycle of 1 s: foot off at 59 %
    EXPECT_NEAR(cycles[0].foot_off_percent(), 59, 1e-9);
    // a higher threshold (100 N): 25 ms into the rise, 25 ms before the end of the fall
    ForcePlate high = trapezoid("left", 0.1, 0.6);
    high.contact_threshold = 100;
    const GaitEvents h = calc_gait_events({high});
    EXPECT_NEAR(h.strikes.at(0), 0.125, 1e-12);
    EXPECT_NEAR(h.offs.at(0), 0.675, 1e-12);
}

TEST(GaitCycles, AContactUnderwayAtTheStartIsNoStrikeAndAMissingForceIsRefused) {
    ForcePlate p = trapezoid("right", 0.5, 0.9);
    p.F[1][0] = p.F[1][1] = 300;  // loaded at the first samples: contact began before the record
    const GaitEvents e = calc_gait_events({p});
    ASSERT_EQ(e.strikes.size(), 1u);
    EXPECT_NEAR(e.strikes[0], 0.505, 1e-12);
    ASSERT_EQ(e.offs.size(), 2u);  // the first contact ends at 0.01 + 0.01 (280/300) s
    EXPECT_NEAR(e.offs[0], 0.01 + 0.01 * 280.0 / 300.0, 1e-12);
    EXPECT_NEAR(e.offs[1], 0.995, 1e-12);
    EXPECT_TRUE(calc_gait_cycles(e).empty());
    p.F[1][60] = std::numeric_limits<double>::quiet_NaN();
    try {
        calc_gait_events({p});
        FAIL();
    } catch (const ArgumentError& error) {
        EXPECT_NE(std::string(error.what()).find("'right'"), std::string::npos) << error.what();
    }
}

TEST(GaitCycles, ACycleIsResampledAt101PointsFrom0To100Percent) {
    // x = 3 t + 1 is linear, so interpolation is exact; the cycle from 0.105 to 1.105 s
    Table t;
    t.add_column("t", "s");
    t.add_column("x", "N m");
    t.add_column("y", "rad");
    for (int k = 0; k <= 150; ++k) {
        t.columns[0].push_back(0.01 * k);
        t.columns[1].push_back(3 * 0.01 * k + 1);
        t.columns[2].push_back(std::sin(2 * 0.01 * k));
    }
    const Table c = calc_cycle_table(t, GaitCycle{0.105, 1.105, 0.695});
    ASSERT_EQ(c.names, (std::vector<std::string>{"cycle", "x", "y"}));
    EXPECT_EQ(c.units, (std::vector<std::string>{"%", "N m", "rad"}));
    ASSERT_EQ(c.row_count(), 101u);
    for (std::size_t i = 0; i <= 100; ++i) {
        const double ti = 0.105 + 0.01 * static_cast<double>(i);
        EXPECT_NEAR(c.columns[0][i], static_cast<double>(i), 1e-12);
        EXPECT_NEAR(c.columns[1][i], 3 * ti + 1, 1e-12);
        // linear interpolation of sin(2t) between samples 10 ms apart: error below h^2/8 |y''| =
        // 5e-5
        EXPECT_NEAR(c.columns[2][i], std::sin(2 * ti), 5e-5);
    }
    try {
        calc_cycle_table(t, GaitCycle{1.0, 2.0, 1.5});
        FAIL();
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "the cycle from t = 1 to 2 s is not inside the results, t = 0 to 1.5 s"),
                  std::string::npos)
            << e.what();
    }
}

TEST(GaitCycles, MeanAndSampleStandardDeviationAcrossCurves) {
    // three curves: x = 1, 2, 3 everywhere, y = -5 p/100, -4 p/100, -6 p/100: mean 2 and -5 p/100,
    // SD 1 and p/100 (sample SD, n - 1 = 2)
    std::vector<Table> curves;
    for (double a : {1.0, 2.0, 3.0}) {
        Table c;
        c.add_column("cycle", "%");
        c.add_column("x", "N m");
        c.add_column("y", "W");
        const double b = a == 1 ? -5 : a == 2 ? -4 : -6;
        for (int i = 0; i <= 100; ++i) {
            c.columns[0].push_back(i);
            c.columns[1].push_back(a);
            c.columns[2].push_back(b * i / 100.0);
        }
        curves.push_back(c);
    }
    const Table s = calc_cycle_statistics(curves, {"a", "b", "c"});
    ASSERT_EQ(s.names, (std::vector<std::string>{"cycle", "x_mean", "x_sd", "y_mean", "y_sd"}));
    EXPECT_EQ(s.units, (std::vector<std::string>{"%", "N m", "N m", "W", "W"}));
    for (std::size_t i = 0; i <= 100; ++i) {
        EXPECT_NEAR(s.columns[1][i], 2, 1e-12);
        EXPECT_NEAR(s.columns[2][i], 1, 1e-12);
        EXPECT_NEAR(s.columns[3][i], -0.05 * static_cast<double>(i), 1e-12);
        EXPECT_NEAR(s.columns[4][i], 0.01 * static_cast<double>(i), 1e-12);
    }
    const std::vector<CycleSummaryRow> rows = calc_cycle_summary(s, 3);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].quantity, "y");
    EXPECT_EQ(rows[1].unit, "W");
    EXPECT_NEAR(rows[1].peak, -5, 1e-12);  // the largest magnitude, with its sign
    EXPECT_EQ(rows[1].peak_percent, 100);
    EXPECT_NEAR(rows[1].sd_at_peak, 1, 1e-12);
    EXPECT_EQ(rows[1].curves, 3u);
    // a curve of another model is named
    curves[2].names[1] = "z";
    try {
        calc_cycle_statistics(curves, {"a", "b", "c"});
        FAIL();
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("'c' has other columns or units than 'a'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(GaitCycles, TheSummaryIsWrittenAsCsv) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("alembert_cycles_" + std::to_string(::getpid()) + ".csv");
    write_cycle_summary({{"T_K", "N m", -40.5, 12, 3.25, -40.5, 20, 5}}, path.string());
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(),
              "quantity,unit,peak,peak_percent,sd_at_peak,min,max,curves\nT_K,N "
              "m,-40.5,12,3.25,-40.5,20,5\n");
    std::filesystem::remove(path);
}

}  // namespace gait_cycles_test
