// SPDX-License-Identifier: MIT
// Plots by gnuplot: both formats written, and a clear message (CSV kept) without gnuplot.
#include "alembert/sim/plot.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "alembert/sim/simulation.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;

Table sample_table() {
    Table t;
    t.add_column("t", "s");
    t.add_column("qA", "deg");
    t.add_column("qB", "deg");
    t.add_column("energy", "J");
    for (int i = 0; i <= 20; ++i) {
        t.columns[0].push_back(0.1 * i);
        t.columns[1].push_back(i);
        t.columns[2].push_back(-i);
        t.columns[3].push_back(5.0);
    }
    return t;
}

fs::path scratch() {
    fs::path dir = fs::temp_directory_path() / ("alembert_plot_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

TEST(PlotCsv, DrawsPngAndSvgWithOnePanelPerUnit) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
    const fs::path dir = scratch();
    PlotResult r = write_table_and_plot(sample_table(), dir.string(), "run", {.title = "a test"});
    ASSERT_TRUE(r.drawn) << r.message;
    EXPECT_GT(fs::file_size(dir / "run.png"), 1000u);
    // the SVG is text: it names both panels' units and the curves
    std::ifstream svg(dir / "run.svg");
    std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("[deg]"), std::string::npos);
    EXPECT_NE(text.find("[J]"), std::string::npos);
    EXPECT_NE(text.find("qB"), std::string::npos);
    fs::remove_all(dir);
}

TEST(PlotCsv, LongRunsAreDrawnFromAThinnedCopyThatKeepsTheSpikes) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
    const fs::path dir = scratch();
    // 200000 rows, one of them a spike to 1000: every row in the CSV, about 4000 in the plot
    Table t;
    t.add_column("t", "s");
    t.add_column("x", "m");
    for (int i = 0; i < 200000; ++i) {
        t.columns[0].push_back(1e-3 * i);
        t.columns[1].push_back(i == 123457 ? 1000.0 : 0.001 * (i % 97));
    }
    PlotResult r = write_table_and_plot(t, dir.string(), "long");
    ASSERT_TRUE(r.drawn) << r.message;
    EXPECT_EQ(read_csv((dir / "long.csv").string()).row_count(), 200000u);
    std::ifstream svg(dir / "long.svg");
    std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    // the y axis reaches the spike: gnuplot labels it 1000
    EXPECT_NE(text.find(" 1000</text>"), std::string::npos);
    // every row drawn would take several MB of path; the thinned copy well under one
    EXPECT_LT(text.size(), 1000000u);
    // no temporary left beside the plot
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    fs::remove_all(dir);
}

TEST(PlotCsv, WithoutGnuplotSaysWhatToInstallAndKeepsTheCsv) {
    const fs::path dir = scratch();
    ::setenv("ALEMBERT_GNUPLOT", "/nonexistent/gnuplot", 1);
    PlotResult r = write_table_and_plot(sample_table(), dir.string(), "run");
    ::unsetenv("ALEMBERT_GNUPLOT");
    EXPECT_FALSE(r.drawn);
    EXPECT_NE(r.message.find("apt install gnuplot-nox"), std::string::npos) << r.message;
    EXPECT_TRUE(fs::exists(dir / "run.csv"));
    EXPECT_FALSE(fs::exists(dir / "run.png"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace alembert
