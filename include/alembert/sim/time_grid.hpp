// SPDX-License-Identifier: MIT
// The uniform time base a printed time column stands for: rounding within its precision is not
// jitter.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace alembert {

/// What calc_uniform_time_base found about a column of sample times.
struct UniformTimeBase {
    /// Every time lies on the grid t0 + k step within `tolerance`: the samples are uniform, and
    /// the differences from the grid are the rounding of the printed times.
    bool uniform = false;
    double t0 = 0;    ///< the first time, s
    double step = 0;  ///< the grid's step, s: 1/rate_hz when that rate fits, else the mean step
    /// The step is the given rate's (a file header's DataRate), not the mean of the times: the
    /// times fit that rate, or they fit neither it nor their mean step (then the offsets are
    /// from the given rate's grid).
    bool step_from_rate = false;
    /// The time column's printed precision, s (0.001 for times written as 0.017, 0.033, ...);
    /// 0 when the times carry more than 9 decimals (written in full, not rounded).
    double resolution = 0;
    /// How far a time may lie from the grid and still be a uniform sample: the resolution
    /// (two roundings of half of it: the time's and the first time's), at most a quarter of
    /// the step (coarser printing cannot tell rounding from jitter), and at least 1e-6 of the
    /// step (the test for times written in full).
    double tolerance = 0;
    std::size_t worst_row = 0;  ///< the row farthest from the grid
    double worst_offset = 0;    ///< its signed distance from the grid, s

    /// One sentence for a report: "151 samples at 60 Hz (the rate given); times printed to
    /// 0.001 s, their rounding within that precision". Empty if not uniform.
    std::string describe(std::size_t samples) const;
};

/// The decimal precision the times `t_s` (s) are printed to: 10^-d for the fewest decimals
/// d = 0 ... 9 that write every time exactly (to 1/100 of that last digit, beyond the
/// floating-point error of reading it), or 0 if none does (times written in full).
double calc_printed_resolution(const std::vector<double>& t_s);

/// Whether increasing times `t_s` (s, at least 2) are samples at a uniform rate, as a lab
/// file prints them. Times on the grid of their mean step (t_{n-1} - t_0) / (n - 1) to 1e-6
/// of it are uniform as written. Otherwise, with rate_hz > 0 (a header's rate), the grid
/// t_0 + k / rate_hz is tried first, then the mean step's: a time fits if it lies within
/// UniformTimeBase::tolerance of the grid. Rounding to the printed precision moves each time
/// by at most half a digit, so a 60 Hz column rounded to milliseconds (0, 0.017, 0.033, 0.05,
/// ...) is uniform, and so is a 150 Hz column printed to 8 decimals, while 0.3 ms of jitter
/// printed to 0.1 ms is not.
UniformTimeBase calc_uniform_time_base(const std::vector<double>& t_s, double rate_hz = 0);

}  // namespace alembert
