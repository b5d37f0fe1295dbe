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
    std::string text = std::to_string(samples) + " samples at " + grid_number(1 / step) + " Hz (" +
                       (step_from_rate ? "the rate the file states" : "the mean step of its times") + ")";
    if (resolution > 0 && std::abs(worst_offset) > 1e-6 * step)
        text += "; the times are printed to " + grid_number(resolution) +
                " s and lie on this grid within that precision (rounding, not jitter: nothing resampled)";
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
    const double largest = std::max(std::abs(t_s.front()), std::abs(t_s.back()));
    // a time fits the grid of step h within the printed precision (and floating-point error)
    auto fits = [&](double h) {
        out.step = h;
        // rounding explains an offset up to the resolution, but not one near the step itself:
        // times printed coarser than a quarter step cannot tell rounding from jitter
        out.tolerance = std::max(std::min(out.resolution, h / 4), 1e-6 * h);
        worst_offset_from_grid(t_s, h, out);
        return std::abs(out.worst_offset) <= out.tolerance + 16 * kEps * largest;
    };
    // the stated rate first, then the mean step; off both, the offsets are from the stated grid
    const bool stated = rate_hz > 0 && std::isfinite(rate_hz);
    if (stated && fits(1 / rate_hz)) {
        out.uniform = out.step_from_rate = true;
        return out;
    }
    const UniformTimeBase on_rate = out;
    out.uniform = fits((t_s.back() - t_s.front()) / static_cast<double>(n - 1));
    if (!out.uniform && stated) {
        out = on_rate;
        out.step_from_rate = true;
    }
    return out;
}

}  // namespace alembert
