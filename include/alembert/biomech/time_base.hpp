// SPDX-License-Identifier: MIT
// Gaps filled and irregular time bases resampled, with a report of what was done.
#pragma once

#include <string>
#include <vector>

#include "alembert/sim/table.hpp"

namespace alembert {

/// How regularize_time_base treats gaps and irregular sampling.
struct TimeBaseOptions {
    /// The longest gap (from the last sample before it to the first after) that is filled, in
    /// seconds. Short gaps are filled by interpolation; a longer one is more movement than an interpolation can honestly invent.
    double max_gap_s = 0.1;
    /// Time steps that differ from the median step by more than this fraction make the time
    /// base irregular, and the table is resampled.
    double step_tolerance = 1e-6;
};

/// A stretch of samples where a column (or a marker: its X, Y, Z columns together) is missing.
struct Gap {
    std::string name{};       ///< the column, or the marker for "M.X", "M.Y", "M.Z" columns
    double t_first = 0;       ///< time of the first missing sample, s
    double t_last = 0;        ///< time of the last missing sample, s
    std::size_t samples = 0;  ///< how many samples are missing
};

/// What regularize_time_base did.
struct TimeBaseReport {
    std::vector<Gap> gaps{};  ///< every gap, filled, in order of column then time
    bool resampled = false;   ///< the time base was irregular and was resampled
    double min_step_s = 0;    ///< the smallest and largest time steps of the input
    double max_step_s = 0;
    double rate_hz = 0;       ///< the sampling rate of the output
    std::size_t samples_in = 0, samples_out = 0;

    /// The report as sentences, one a line: the method, each gap with its time range, the
    /// resampling ("none needed" when there was nothing to do).
    std::string describe() const;
};

/// Fills the gaps (NaN) of every column of `table` and resamples it on a uniform time base
/// if its steps are irregular. Method, stated because results depend on it:
///  - a gap is filled by a natural cubic spline through all the column's valid samples
///    (de Boor, A Practical Guide to Splines, ch. IV), which reproduces straight-line motion;
///  - an irregular time base (a step differing from the median step by more than
///    options.step_tolerance of it) is resampled at the median step from the first time,
///    each column by a natural cubic spline through its samples.
/// `time_column` is the index of the time column (in s or ms); `source` names the data in
/// messages (the file's path).
/// @throws alembert::ArgumentError naming the column (or marker) and its time range if a gap
///         touches the start or end of the trial (no interpolation there: trim the trial),
///         is longer than options.max_gap_s, or the column has fewer than 2 valid samples;
///         naming the row if the times are missing, not increasing, or fewer than 2.
TimeBaseReport regularize_time_base(Table& table, std::size_t time_column,
                                    const std::string& source,
                                    const TimeBaseOptions& options = {});

}  // namespace alembert
