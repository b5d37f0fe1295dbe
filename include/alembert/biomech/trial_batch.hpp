// SPDX-License-Identifier: MIT
// Many trials: choosing them by pattern, sharding them over cluster tasks, summarising results.
#pragma once

#include <string>
#include <vector>

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

}  // namespace alembert
