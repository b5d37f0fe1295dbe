// SPDX-License-Identifier: MIT
// Many trials: choosing them by pattern, sharding them over cluster tasks, summarising results.
#pragma once

#include <string>
#include <vector>

#include "alembert/sim/plot.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// The files a shell pattern matches ("trials/*.trc"), sorted by name so every run and every
/// shard sees the same order; a pattern without wildcards is returned as it is.
/// @throws alembert::ArgumentError if a pattern with wildcards matches nothing.
std::vector<std::string> expand_trial_pattern(const std::string& pattern);

/// A shard "I/N": task I (0-based) of N.
struct Shard {
    int index = 0;
    int count = 1;
};

/// Parses "I/N" (0 <= I < N).
/// @throws alembert::ArgumentError naming the text and the form expected.
Shard parse_shard(const std::string& text);

/// The trials of a shard: those at positions i with i % count == index, so N array tasks
/// given the same sorted list share it with no overlap and no gap, each taking about 1/N.
std::vector<std::string> select_shard(const std::vector<std::string>& trials, Shard shard);

/// The peak of one result column of a trial: the value of largest magnitude (with its sign)
/// and the first time it is reached.
struct Peak {
    std::string quantity{};  ///< "T_A [N m]"
    double value = 0;
    double t = 0;
};

/// The peaks of every column of a result table after the first (time).
/// @throws alembert::ArgumentError if the table has no rows.
std::vector<Peak> calc_peaks(const Table& result);

/// What happened to one trial of a batch.
struct TrialOutcome {
    std::string trial{};
    bool ok = false;
    std::string message{};    ///< why it failed (the first error line), empty if ok
    std::vector<Peak> peaks{};
};

/// Writes the batch summary as CSV, one row per trial and quantity:
/// trial,status,quantity,peak,t_peak,message (a failed trial has one row with its message;
/// cells with commas or quotes are quoted). Written to a temporary and renamed.
/// @throws alembert::ArgumentError if the path cannot be written.
void write_batch_summary(const std::vector<TrialOutcome>& outcomes, const std::string& path);

/// What write_cycle_statistics wrote.
struct CycleStatisticsReport {
    std::size_t curves = 0;            ///< normalised cycles read
    std::size_t trials = 0;            ///< trials they came from
    std::vector<std::string> files{};  ///< the files written (paths)
    PlotResult plot{};                 ///< the plot of the bands, or why not
};

/// The normalised cycles of a batch's trials, as `inverse ... cycles` writes them (each trial
/// directory's cycle_1.csv, cycle_2.csv, ...), pooled: their mean and sample SD at each
/// percentage (calc_cycle_statistics) in `out_dir`/cycles.csv, the summary per quantity
/// (calc_cycle_summary) in cycles_summary.csv, and the bands mean - SD, mean, mean + SD of the
/// loads, angles and powers (not rates and accelerations) in cycles_band.csv, plotted into
/// cycles.png and cycles.svg (one panel per unit; a missing gnuplot costs only the plot).
/// Directories without cycles (a failed trial, or one with no complete cycle) are passed over.
/// Returns with `curves` 0 and writes nothing when no trial has cycles.
/// @throws alembert::ArgumentError if the trials' cycles differ in columns (naming two), or a
///         file cannot be read or written.
CycleStatisticsReport write_cycle_statistics(const std::vector<std::string>& trial_dirs,
                                             const std::string& out_dir);

}  // namespace alembert
