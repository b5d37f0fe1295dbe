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
    /// seconds, and the longest step of an irregular time base that is resampled. Short gaps
    /// are filled by interpolation; a longer one is more movement than an interpolation can
    /// honestly invent.
    double max_gap_s = 0.1;
    /// The sampling rate the file states (a .trc header's DataRate), Hz; 0 if it states none.
    /// Times that lie on its grid within their printed precision are read at this rate.
    double rate_hz = 0;
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
    /// rate_hz is the rate the file states (TimeBaseOptions::rate_hz), not one of its steps.
    bool rate_from_file = false;
    /// The rate the file states, Hz (0: none); when its times are uniform at another rate,
    /// they win and describe() says so.
    double file_rate_hz = 0;
    /// The time column's printed precision, s (calc_printed_resolution; 0: written in full).
    double time_resolution_s = 0;
    /// The times were rounded (off the uniform grid by up to their printed precision) and were
    /// replaced by the grid's times t_0 + k / rate_hz: rounding, not resampling.
    bool times_rounded = false;
    /// The largest distance of an input time from the uniform grid, s.
    double worst_offset_s = 0;
    /// The longest gap that is filled (TimeBaseOptions::max_gap_s), s.
    double max_gap_s = 0;
    std::size_t samples_in = 0, samples_out = 0;

    /// The report as sentences, one a line: the rate and where it comes from, the rounding of
    /// the times, each gap with its time range and the method, the resampling with its rate
    /// ("nothing filled or resampled" when there was nothing to do).
    std::string describe() const;
};

/// Fills the gaps (NaN) of every column of `table` and puts it on a uniform time base.
/// Method, stated because results depend on it:
///  - times that lie on a uniform grid within the time column's printed precision (a 60 Hz
///    column rounded to milliseconds, a 150 Hz column printed to 8 decimals) are uniform
///    samples (calc_uniform_time_base): at options.rate_hz when they fit it (the file's
///    stated rate), else at their mean step; rounded times are replaced by the grid's times
///    and nothing is resampled;
///  - a gap is filled by a natural cubic spline through all the column's valid samples
///    (de Boor, A Practical Guide to Splines, ch. IV), which reproduces straight-line motion;
///  - an irregular time base (jitter beyond the printed precision, a dropped frame) is
///    resampled from the first time at options.rate_hz when that is within a quarter of the
///    typical step, else at the typical step (with every step within a quarter of the median,
///    the least-squares slope of the times over their rows; else the mean of the steps within
///    a quarter of the median), each column by a natural cubic spline through its samples, on
///    the grid inside the trial's first and last times.
/// `time_column` is the index of the time column (in s or ms); `source` names the data in
/// messages (the file's path).
/// @throws alembert::ArgumentError naming the column (or marker), its time range, its samples
///         and the file's lines if a gap touches the start or end of the trial (no
///         interpolation there: trim the trial), is longer than options.max_gap_s, or the
///         column has fewer than 2 valid samples; naming the row if the times are missing,
///         not increasing, or fewer than 2; naming the two times if an irregular time base has
///         a step longer than options.max_gap_s.
TimeBaseReport regularize_time_base(Table& table, std::size_t time_column,
                                    const std::string& source,
                                    const TimeBaseOptions& options = {});

}  // namespace alembert
