// SPDX-License-Identifier: MIT
// Trial patterns, shards and batch summaries.
#include "alembert/biomech/trial_batch.hpp"

#include <glob.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "alembert/biomech/gait_cycles.hpp"
#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

namespace alembert {

namespace {

std::string csv_cell(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c == '\n' ? ' ' : c;
    }
    return out + "\"";
}

}  // namespace

std::vector<std::string> expand_trial_pattern(const std::string& pattern) {
    if (pattern.find_first_of("*?[") == std::string::npos) return {pattern};
    glob_t g{};
    const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);
    std::vector<std::string> files;
    for (std::size_t i = 0; rc == 0 && i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
    ::globfree(&g);
    if (files.empty())
        throw ArgumentError("expand_trial_pattern(): '" + pattern +
                            "' matches no file; check the directory and quote the pattern so the "
                            "shell passes it on");
    std::sort(files.begin(), files.end());
    return files;
}

Shard parse_shard(const std::string& text) {
    Shard s;
    char slash = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d %c %d %c", &s.index, &slash, &s.count, &extra) != 3 || slash != '/' ||
        s.count < 1 || s.index < 0 || s.index >= s.count)
        throw ArgumentError("parse_shard(): '" + text +
                            "' is not a shard; write I/N with 0 <= I < N (task I of N, e.g. "
                            "$SLURM_ARRAY_TASK_ID/100)");
    return s;
}

std::vector<std::string> select_shard(const std::vector<std::string>& trials, Shard shard) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (static_cast<int>(i % static_cast<std::size_t>(shard.count)) == shard.index) out.push_back(trials[i]);
    return out;
}

std::vector<Peak> calc_peaks(const Table& result) {
    if (result.row_count() == 0) throw ArgumentError("calc_peaks(): the result table has no rows");
    std::vector<Peak> peaks;
    for (std::size_t c = 1; c < result.columns.size(); ++c) {
        Peak p;
        p.quantity = result.names[c] + (result.units[c].empty() ? "" : " [" + result.units[c] + "]");
        for (std::size_t r = 0; r < result.row_count(); ++r)
            if (std::fabs(result.columns[c][r]) > std::fabs(p.value) || r == 0) {
                p.value = result.columns[c][r];
                p.t = result.columns[0][r];
            }
        peaks.push_back(p);
    }
    return peaks;
}

void write_batch_summary(const std::vector<TrialOutcome>& outcomes, const std::string& path) {
    std::string text = "trial,status,quantity,peak,t_peak,message\n";
    for (const TrialOutcome& o : outcomes) {
        if (!o.ok) {
            text += csv_cell(o.trial) + ",failed,,,," + csv_cell(o.message) + "\n";
            continue;
        }
        for (const Peak& p : o.peaks)
            text += csv_cell(o.trial) + ",ok," + csv_cell(p.quantity) + "," +
                    format_csv_number(p.value) + "," + format_csv_number(p.t) + ",\n";
    }
    write_file_atomically(path, text, "write_batch_summary()");
}

CycleStatisticsReport write_cycle_statistics(const std::vector<std::string>& trial_dirs,
                                             const std::string& out_dir) {
    namespace fs = std::filesystem;
    CycleStatisticsReport report;
    // every trial's cycles, in the trials' order, then by cycle number
    std::vector<Table> curves;
    std::vector<std::string> names;
    for (const std::string& dir : trial_dirs) {
        std::size_t k = 1;
        for (; fs::exists(fs::path(dir) / ("cycle_" + std::to_string(k) + ".csv")); ++k) {
            const fs::path file = fs::path(dir) / ("cycle_" + std::to_string(k) + ".csv");
            curves.push_back(read_csv(file.string()));
            names.push_back(file.string());
        }
        report.trials += k > 1 ? 1 : 0;
    }
    report.curves = curves.size();
    if (curves.empty()) return report;
    // mean and SD, the summary, and the bands of the quantities a gait report plots
    const Table stats = calc_cycle_statistics(curves, names);
    const std::string base = (fs::path(out_dir) / "cycles").string();
    write_csv(stats, base + ".csv");
    write_cycle_summary(calc_cycle_summary(stats, curves.size()), base + "_summary.csv");
    report.files = {base + ".csv", base + "_summary.csv"};
    Table band;
    band.add_column("cycle", "%");
    band.columns[0] = stats.columns[0];
    for (std::size_t c = 1; c + 1 < stats.names.size(); c += 2) {
        std::string quantity;
        try {
            quantity = parse_unit(stats.units[c]).quantity;
        } catch (const ArgumentError&) {
            continue;  // a unit the plot does not know: left out of the bands
        }
        if (quantity != "angle" && quantity != "length" && quantity != "torque" && quantity != "force" &&
            quantity != "power" && quantity.find("per mass") == std::string::npos)
            continue;
        const std::string q = stats.names[c].substr(0, stats.names[c].size() - 5);  // "_mean"
        const std::vector<double>&mean = stats.columns[c], &sd = stats.columns[c + 1];
        std::vector<double> lo(mean.size()), hi(mean.size());
        for (std::size_t i = 0; i < mean.size(); ++i) lo[i] = mean[i] - sd[i], hi[i] = mean[i] + sd[i];
        band.columns[band.add_column(q + "_minus_sd", stats.units[c])] = lo;
        band.columns[band.add_column(q + "_mean", stats.units[c])] = mean;
        band.columns[band.add_column(q + "_plus_sd", stats.units[c])] = hi;
    }
    write_csv(band, base + "_band.csv");
    report.files.push_back(base + "_band.csv");
    PlotOptions plot;
    plot.title = "mean and SD over " + std::to_string(curves.size()) + " cycles of " +
                 std::to_string(report.trials) + " trials";
    report.plot = plot_csv(band, base + "_band.csv", base, plot);
    return report;
}

}  // namespace alembert
