// SPDX-License-Identifier: MIT
// Uniform time bases found in printed time columns, within their printed precision.
#include "alembert/sim/time_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace alembert {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// the largest distance of t_k from t_0 + k h, with its row
void worst_offset_from_grid(const std::vector<double>& t, double h, UniformTimeBase& out) {
    out.worst_row = 0;
    out.worst_offset = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double d = t[k] - (t.front() + static_cast<double>(k) * h);
        if (std::abs(d) > std::abs(out.worst_offset)) out.worst_offset = d, out.worst_row = k;
    }
}

std::string grid_number(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

}  // namespace

std::string UniformTimeBase::describe(std::size_t samples) const {
    if (!uniform) return "";
    std::string text =
        std::to_string(samples) + " samples at " + grid_number(1 / step) + " Hz (" +
        (step_from_rate ? "the rate the file states" : "the mean step of its times") + ")";
    if (resolution > 0 && std::abs(worst_offset) > 1e-6 * step)
        text += "; the times are printed to " + grid_number(resolution) +
                " s and lie on this grid within that precision (rounding, not jitter: nothing "
                "resampled)";
    return text;
}

double calc_printed_resolution(const std::vector<double>& t_s) {
    // fewest decimals d that write every time exactly (to 1/100 of the last digit)
    double scale = 1;
    for (int d = 0; d <= 9; ++d, scale *= 10) {
        const bool exact = std::all_of(t_s.begin(), t_s.end(), [&](double t) {
            const double x = t * scale;
            return std::abs(x - std::nearbyint(x)) <= 0.01 + 8 * kEps * std::abs(x);
        });
        if (exact) return 1 / scale;
    }
    return 0;
}

UniformTimeBase calc_uniform_time_base(const std::vector<double>& t_s, double rate_hz) {
    UniformTimeBase out;
    const std::size_t n = t_s.size();
    if (n < 2) return out;
    out.t0 = t_s.front();
    out.resolution = calc_printed_resolution(t_s);
    const double slack = 16 * kEps * std::max(std::abs(t_s.front()), std::abs(t_s.back()));
    const bool stated = rate_hz > 0 && std::isfinite(rate_hz);
    const double mean = (t_s.back() - t_s.front()) / static_cast<double>(n - 1);
    // the largest offset from the grid of step h
    auto offset = [&](double h) {
        out.step = h;
        worst_offset_from_grid(t_s, h, out);
        return std::abs(out.worst_offset);
    };
    // rounding explains an offset up to the resolution, but not one near the step itself:
    // times printed coarser than a quarter step cannot tell rounding from jitter
    auto tolerance = [&](double h) { return std::max(std::min(out.resolution, h / 4), 1e-6 * h); };

    // on the grid of their own mean step as written (to 1e-6 of it): nothing to round, and a
    // stated rate that agrees is the same grid (a header's 69.93 Hz for steps of 0.0143 s)
    if (offset(mean) <= 1e-6 * mean + slack) {
        out.uniform = true;
        out.tolerance = tolerance(mean);
        out.step_from_rate = stated && std::abs(mean * rate_hz - 1) <= 1e-3;
        return out;
    }
    // rounded: on the stated rate's grid, else their mean step's, within the printed precision
    if (stated && offset(1 / rate_hz) <= tolerance(1 / rate_hz) + slack) {
        out.uniform = out.step_from_rate = true;
        out.tolerance = tolerance(out.step);
        return out;
    }
    if (offset(mean) <= tolerance(mean) + slack) {
        out.uniform = true;
        out.tolerance = tolerance(mean);
        return out;
    }
    // off both: the offsets are from the stated grid when there is one
    offset(stated ? 1 / rate_hz : mean);
    out.step_from_rate = stated;
    out.tolerance = tolerance(out.step);
    return out;
}

}  // namespace alembert
