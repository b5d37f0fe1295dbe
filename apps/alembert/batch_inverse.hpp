// SPDX-License-Identifier: MIT
// `alembert inverse MODEL --motion 'trials/*.csv' --jobs N`: many trials, one process each.
#pragma once

#include <string>

namespace alembert::cli {

/// The options of a batch of inverse-dynamics trials.
struct BatchInverseOptions {
    std::string model;          ///< the script
    std::string pattern;        ///< the trials' files, a shell pattern
    std::string out;            ///< one directory per trial (named by its file's stem) and summary.csv
    double cutoff_hz = 6.0;
    bool compiled = false;
    bool tape = false;
    std::string unitless;
    unsigned jobs = 1;          ///< trials run at once (0: one per core)
    std::string shard;          ///< "I/N": only this task's share, for cluster array jobs
};

/// Runs each trial as a child `alembert inverse MODEL --motion TRIAL --out OUT/STEM` (separate
/// processes: a trial that fails or crashes cannot take the others down, and the symbolic
/// library need not be shared between threads), at most `jobs` at a time, with a progress line
/// on a terminal; then writes OUT/summary.csv (peaks and their times per trial, or the failure)
/// and prints the counts and each failure. Returns the exit status: 0 if every trial ran, 1 if
/// any failed, 2 for unusable options.
int run_inverse_batch(const BatchInverseOptions& options, const char* self);

}  // namespace alembert::cli
