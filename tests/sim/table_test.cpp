// SPDX-License-Identifier: MIT
// Units and CSV tables: round trip, atomic writing, errors with file:line.
#include "alembert/sim/table.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <random>
#include <numbers>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    fs::path dir =
        fs::temp_directory_path() / ("alembert_table_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(Unit, DegreesAndTorqueUnitsConvertToSI) {
    EXPECT_DOUBLE_EQ(parse_unit("deg").factor, std::numbers::pi / 180);
    EXPECT_DOUBLE_EQ(parse_unit(" N m ").factor, 1.0);
    EXPECT_DOUBLE_EQ(parse_unit("mm").factor, 1e-3);
    EXPECT_DOUBLE_EQ(parse_unit("rpm").factor, 2 * std::numbers::pi / 60);
    EXPECT_THROW_MSG(parse_unit("furlong"), ArgumentError, "unknown unit 'furlong'; use one of: ");
}

TEST(Table, WritesAHeaderWithUnitsAndReadsItBack) {
    Table t;
    t.add_column("t", "s");
    t.add_column("qA", "deg");
    t.add_column("count", "");
    t.columns = {{0, 0.01}, {-25, -24.999}, {1, 2}};
    const fs::path p = scratch("round_trip.csv");
    write_csv(t, p);
    std::ifstream in(p);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "t [s],qA [deg],count");
    Table back = read_csv(p);
    EXPECT_EQ(back.names, t.names);
    EXPECT_EQ(back.units, t.units);
    EXPECT_EQ(back.columns, t.columns);
    EXPECT_EQ(back.lines, (std::vector<int>{2, 3}));
    // the temporary is gone: only the file itself is left
    int files = 0;
    for (const auto& e : fs::directory_iterator(p.parent_path()))
        if (e.path().filename().string().find("round_trip") != std::string::npos) ++files;
    EXPECT_EQ(files, 1);
}

TEST(Table, CsvNumbersReadBackAsTheSameDoubles) {
    // doubles of every size and awkward ones: a written table read back is exact
    Table t;
    t.add_column("t", "s");
    t.add_column("x", "m");
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int k = 0; k < 2000; ++k) {
        t.columns[0].push_back(0.01 * k);
        t.columns[1].push_back(std::ldexp(mantissa(random), exponent(random)));
    }
    for (double v : {0.1 + 0.2, std::numbers::pi, 1.0 / 3, -0.0, 5e-324, 1.7976931348623157e308})
        t.columns[0].push_back(v), t.columns[1].push_back(-v);
    const fs::path p = scratch("exact.csv");
    write_csv(t, p);
    Table back = read_csv(p);
    ASSERT_EQ(back.row_count(), t.row_count());
    for (std::size_t c = 0; c < 2; ++c)
        for (std::size_t r = 0; r < t.row_count(); ++r)
            ASSERT_EQ(back.columns[c][r], t.columns[c][r]) << "column " << c << ", row " << r;
    // short values stay short, and fewer digits round when asked for
    EXPECT_EQ(format_csv_number(0.84), "0.84");
    EXPECT_EQ(format_csv_number(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(format_csv_number(std::numbers::pi, 4), "3.142");
    EXPECT_THROW_MSG(write_csv(t, p, 18), ArgumentError, "give 1 to 17, or 0 for the shortest");
}

TEST(Table, BadRowsAreReportedWithFileAndLine) {
    const fs::path p = scratch("bad.csv");
    write_text(p, "t [s], qA [deg]\n# a comment\n0, 1\n0.01, one\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError,
                     p.string() + ":4: cell 2 ('qA') is 'one', not a finite number");
    write_text(p, "t [s], qA [deg]\n0, 1, 2\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError,
                     p.string() + ":2: the row has 3 cells but the header names 2 columns");
    write_text(p, "t [s], qA [deg\n0, 1\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError, p.string() + ":1: header cell 'qA [deg' opens");
    write_text(p, "t [s], t [s]\n0, 1\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError, p.string() + ":1: column 't' appears twice");
    write_text(p, "t [s]\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError, "the file has a header but no rows of numbers");
    EXPECT_THROW_MSG(read_csv(scratch("missing.csv")), ArgumentError, "cannot open");
}

TEST(Table, AByteOrderMarkIsNotPartOfTheFirstColumnsName) {
    const fs::path p = scratch("bom.csv");
    write_text(p, "\xEF\xBB\xBFt [s],F_x [N]\n0,1\n0.01,2\n");
    Table t = read_csv(p);
    ASSERT_EQ(t.names, (std::vector<std::string>{"t", "F_x"}));  // underscores kept
    EXPECT_EQ(t.units[0], "s");
    EXPECT_EQ(t.row_count(), 2u);
}

TEST(Table, AnOpenSimMotionFileIsNamedNotMisread) {
    const fs::path p = scratch("walk.mot");
    write_text(p, "Coordinates\nversion=1\nnRows=2\nnColumns=2\ninDegrees=yes\nendheader\n"
                  "time\tknee_angle_r\n0\t1\n0.01\t2\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError,
                     p.string() + ":2: 'version=1': this looks like an OpenSim .mot/.sto file");
    write_text(p, "endheader\ntime,q\n0,1\n");
    EXPECT_THROW_MSG(read_csv(p), ArgumentError, "this looks like an OpenSim .mot/.sto file");
}

TEST(Unit, KnowsTheQuantityItMeasures) {
    EXPECT_EQ(parse_unit("deg").quantity, "angle");
    EXPECT_EQ(parse_unit("mm").quantity, "length");
    EXPECT_EQ(parse_unit("ms").quantity, "time");
    EXPECT_EQ(parse_unit("kN").quantity, "force");
    EXPECT_EQ(parse_unit("N*m").quantity, "torque");
    EXPECT_EQ(parse_unit("").quantity, "");
}

TEST(Table, AnUnwritablePathIsAnArgumentError) {
    Table t;
    t.add_column("t", "s");
    EXPECT_THROW_MSG(write_csv(t, "/nonexistent-dir/x.csv"), ArgumentError,
                     "write_csv(): cannot write '/nonexistent-dir/x.csv'");
}

}  // namespace
}  // namespace alembert

namespace alembert {
namespace {

TEST(PlotRows, ShortTablesKeepEveryRowLongOnesTheirEndsAndEachStretchsExtremes) {
    Table t;
    t.add_column("t", "s");
    t.add_column("a", "");
    t.add_column("b", "");
    for (int k = 0; k < 10; ++k) {
        t.columns[0].push_back(k);
        t.columns[1].push_back(k);
        t.columns[2].push_back(-k);
    }
    EXPECT_EQ(calc_plot_rows(t, 10).size(), 10u);
    // 100000 rows, 400 wanted: 400 / (2 x 2 series) = 100 stretches of 1000 rows; a rises
    // inside each stretch except for a dip at row 12345, b is a single spike at row 77777
    for (auto& c : t.columns) c.clear();
    for (int k = 0; k < 100000; ++k) {
        t.columns[0].push_back(k);
        t.columns[1].push_back(k == 12345 ? -1e9 : k % 1000);
        t.columns[2].push_back(k == 77777 ? 1e9 : 0);
    }
    const std::vector<std::size_t> rows = calc_plot_rows(t, 400);
    EXPECT_LE(rows.size(), 402u);
    EXPECT_EQ(rows.front(), 0u);
    EXPECT_EQ(rows.back(), 99999u);
    EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end()));
    EXPECT_EQ(std::adjacent_find(rows.begin(), rows.end()), rows.end());  // no row twice
    EXPECT_NE(std::find(rows.begin(), rows.end(), 12345u), rows.end());
    EXPECT_NE(std::find(rows.begin(), rows.end(), 77777u), rows.end());
    // each stretch's top of a (row 1000 k + 999) is kept
    for (std::size_t k = 0; k < 100; ++k)
        EXPECT_NE(std::find(rows.begin(), rows.end(), 1000 * k + 999), rows.end()) << k;
    const Table thin = calc_table_rows(t, rows);
    EXPECT_EQ(thin.names, t.names);
    EXPECT_EQ(thin.row_count(), rows.size());
    EXPECT_EQ(*std::min_element(thin.columns[1].begin(), thin.columns[1].end()), -1e9);
    EXPECT_EQ(*std::max_element(thin.columns[2].begin(), thin.columns[2].end()), 1e9);
}

}  // namespace
}  // namespace alembert
