// SPDX-License-Identifier: MIT
// Trial batches: patterns, shards that cover the trials once, peaks and the summary file.
#include "alembert/biomech/trial_batch.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;

fs::path batch_dir() {
    fs::path d = fs::temp_directory_path() / ("alembert_batch_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

TEST(TrialBatch, APatternListsItsFilesSortedAndAnEmptyMatchIsAnError) {
    const fs::path d = batch_dir();
    for (const char* n : {"b.csv", "a.csv", "c.trc"}) std::ofstream(d / n) << "x\n";
    const auto files = expand_trial_pattern((d / "*.csv").string());
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(fs::path(files[0]).filename(), "a.csv");
    EXPECT_EQ(fs::path(files[1]).filename(), "b.csv");
    EXPECT_EQ(expand_trial_pattern("one.csv"), std::vector<std::string>{"one.csv"});
    EXPECT_THROW_MSG(expand_trial_pattern((d / "*.mot").string()), ArgumentError, "matches no file");
}

TEST(TrialBatch, ShardsCoverEveryTrialExactlyOnce) {
    std::vector<std::string> trials;
    for (int i = 0; i < 23; ++i) trials.push_back("t" + std::to_string(100 + i));
    std::multiset<std::string> seen;
    for (int i = 0; i < 5; ++i) {
        const auto part = select_shard(trials, parse_shard(std::to_string(i) + "/5"));
        EXPECT_GE(part.size(), 4u);
        EXPECT_LE(part.size(), 5u);
        seen.insert(part.begin(), part.end());
    }
    EXPECT_EQ(seen, std::multiset<std::string>(trials.begin(), trials.end()));
    EXPECT_THROW_MSG(parse_shard("5/5"), ArgumentError, "write I/N with 0 <= I < N");
    EXPECT_THROW_MSG(parse_shard("1-4"), ArgumentError, "'1-4' is not a shard");
}

TEST(TrialBatch, PeaksAndTheSummaryNameTheFailedTrial) {
    Table t;
    t.add_column("t", "s");
    t.add_column("T_A", "N m");
    t.columns[0] = {0, 0.1, 0.2, 0.3};
    t.columns[1] = {1, -5, 4, 5};
    const auto peaks = calc_peaks(t);
    ASSERT_EQ(peaks.size(), 1u);
    EXPECT_EQ(peaks[0].quantity, "T_A [N m]");
    EXPECT_EQ(peaks[0].value, -5);  // the first of equal magnitudes
    EXPECT_EQ(peaks[0].t, 0.1);
    const fs::path out = batch_dir() / "summary.csv";
    write_batch_summary({{"trials/a.csv", true, "", peaks}, {"trials/bad.csv", false, "bad.csv:3: 'x' is not a number, \"q\"", {}}},
                        out.string());
    std::ifstream in(out);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), "trial,status,quantity,peak,t_peak,message\n"
                       "trials/a.csv,ok,T_A [N m],-5,0.1,\n"
                       "trials/bad.csv,failed,,,,\"bad.csv:3: 'x' is not a number, \"\"q\"\"\"\n");
}

}  // namespace
}  // namespace alembert
