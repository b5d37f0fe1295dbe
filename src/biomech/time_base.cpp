// SPDX-License-Identifier: MIT
// Gap filling and resampling by natural cubic splines, reported.
#include "alembert/biomech/time_base.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "alembert/error.hpp"
#include "alembert/sim/time_grid.hpp"

namespace alembert {

namespace {

/// Natural cubic spline through (x_i, y_i), x increasing: second derivatives m_i from the
/// tridiagonal system h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (s_i - s_{i-1}),
/// m_0 = m_n = 0 (de Boor, A Practical Guide to Splines, ch. IV). Two points: a straight line.
class NaturalSpline {
public:
    NaturalSpline(std::vector<double> x, std::vector<double> y)
        : x_(std::move(x)), y_(std::move(y)), m_(x_.size(), 0.0) {
        const std::size_t n = x_.size();
        if (n < 3) return;
        // forward sweep of the tridiagonal system (Thomas algorithm) for m_1..m_{n-2}
        std::vector<double> c(n, 0.0), d(n, 0.0);
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const double h0 = x_[i] - x_[i - 1], h1 = x_[i + 1] - x_[i];
            const double rhs = 6 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
            const double diag = 2 * (h0 + h1) - h0 * c[i - 1];
            c[i] = h1 / diag;
            d[i] = (rhs - h0 * d[i - 1]) / diag;
        }
        // back substitution
        for (std::size_t i = n - 2; i >= 1; --i) m_[i] = d[i] - c[i] * m_[i + 1];
    }

    double operator()(double xq) const {
        // the interval [x_k, x_{k+1}] holding xq
        std::size_t k = static_cast<std::size_t>(
            std::upper_bound(x_.begin(), x_.end(), xq) - x_.begin());
        k = std::clamp<std::size_t>(k, 1, x_.size() - 1) - 1;
        const double h = x_[k + 1] - x_[k], a = (x_[k + 1] - xq) / h, b = (xq - x_[k]) / h;
        return a * y_[k] + b * y_[k + 1] +
               ((a * a * a - a) * m_[k] + (b * b * b - b) * m_[k + 1]) * h * h / 6;
    }

private:
    std::vector<double> x_, y_, m_;
};

// the marker a coordinate column belongs to ("R.HEEL.X" -> "R.HEEL"), or the column itself
std::string gap_name(const std::string& column) {
    const std::size_t n = column.size();
    if (n > 2 && column[n - 2] == '.' && (column[n - 1] == 'X' || column[n - 1] == 'Y' || column[n - 1] == 'Z'))
        return column.substr(0, n - 2);
    return column;
}

std::string six_digits(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

std::string seconds(double t) { return six_digits(t) + " s"; }

}  // namespace

std::string TimeBaseReport::describe() const {
    std::ostringstream out;
    const std::string rate = six_digits(rate_hz) + " Hz" +
                             (rate_from_file ? " (the rate the file states)" : resampled ? " (the time column's typical step)" : "");
    // the rate, and a stated rate the times contradict
    if (file_rate_hz > 0 && !rate_from_file && std::abs(file_rate_hz - rate_hz) > 1e-3 * rate_hz)
        out << "time base: the file states " << six_digits(file_rate_hz) << " Hz, but its time column is "
            << (resampled ? "not on that grid" : "uniform at " + six_digits(rate_hz) + " Hz") << "; the time column is used\n";
    if (times_rounded)
        out << "time base: " << samples_in << " samples at " << rate << "; the time column is printed to "
            << seconds(time_resolution_s) << " and lies on that grid within its precision (largest offset "
            << six_digits(std::abs(worst_offset_s) * 1000) << " ms: rounding, not jitter), so the times were read as "
            << "t0 + k/" << six_digits(rate_hz) << " s and nothing was resampled\n";
    else if (gaps.empty() && !resampled)
        out << "time base: " << samples_in << " samples at " << six_digits(rate_hz)
            << " Hz, uniform and without gaps; nothing filled or resampled\n";
    for (const Gap& g : gaps)
        out << "gap filled: '" << g.name << "' missing from t = " << seconds(g.t_first)
            << " to " << seconds(g.t_last) << " (" << g.samples
            << " samples), filled by a natural cubic spline through its valid samples (gaps of up to "
            << seconds(max_gap_s) << " are filled, longer ones refused)\n";
    if (resampled)
        out << "time base resampled: steps from " << seconds(min_step_s) << " to "
            << seconds(max_step_s) << " are not uniform; " << samples_in << " samples became "
            << samples_out << " at " << rate << " by a natural cubic spline per column (a time was "
            << six_digits(std::abs(worst_offset_s) * 1000) << " ms off the uniform grid, more than the "
            << (time_resolution_s > 0 ? "time column's printed precision of " + seconds(time_resolution_s)
                                      : std::string("rounding of times written in full"))
            << " explains)\n";
    return out.str();
}

TimeBaseReport regularize_time_base(Table& table, std::size_t time_column,
                                    const std::string& source, const TimeBaseOptions& options) {
    TimeBaseReport report;
    if (time_column >= table.columns.size())
        throw ArgumentError("regularize_time_base(): " + source + " has no column " +
                            std::to_string(time_column) + " for time");
    const double t_factor = parse_unit(table.units[time_column]).factor;
    std::vector<double> t = table.columns[time_column];
    for (double& v : t) v *= t_factor;
    auto line = [&](std::size_t row) {
        return row < table.lines.size() ? ":" + std::to_string(table.lines[row]) : std::string();
    };
    auto where = [&](std::size_t row) { return source + line(row) + ": "; };
    // "frames 12 to 14, lines 17 to 19": the rows of a gap, counted from 1 as a lab's software
    // numbers frames, and their lines in the file
    auto samples = [&](std::size_t first, std::size_t last) {
        std::string text = "frames " + std::to_string(first + 1) + " to " + std::to_string(last + 1);
        if (last < table.lines.size())
            text += ", lines " + std::to_string(table.lines[first]) + " to " + std::to_string(table.lines[last]);
        return text;
    };
    // times present, increasing, at least two
    const std::size_t n = t.size();
    report.samples_in = n;
    report.file_rate_hz = options.rate_hz;
    report.max_gap_s = options.max_gap_s;
    if (n < 2) throw ArgumentError(source + ": " + std::to_string(n) + " samples; a trial needs at least 2");
    for (std::size_t r = 0; r < n; ++r) {
        if (std::isnan(t[r])) throw ArgumentError(where(r) + "the time is missing; give every row a time");
        if (r && !(t[r] > t[r - 1]))
            throw ArgumentError(where(r) + "time " + seconds(t[r]) + " does not come after " +
                                seconds(t[r - 1]) + "; sort the rows by time and remove repeated rows");
    }
    // steps: smallest, largest, median
    std::vector<double> steps;
    for (std::size_t r = 1; r < n; ++r) steps.push_back(t[r] - t[r - 1]);
    report.min_step_s = *std::min_element(steps.begin(), steps.end());
    report.max_step_s = *std::max_element(steps.begin(), steps.end());
    std::vector<double> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];

    // uniform as printed: the file's rate, or the mean step, within the printed precision
    const UniformTimeBase base = calc_uniform_time_base(t, options.rate_hz);
    report.time_resolution_s = base.resolution;
    report.worst_offset_s = base.worst_offset;
    const bool irregular = !base.uniform;
    double h = base.step;
    if (base.uniform) {
        report.rate_from_file = base.step_from_rate;
        // rounded times become the grid's: differences of rounded times are not the motion's
        if (base.resolution > 0 && std::abs(base.worst_offset) > 1e-9 * h) {
            report.times_rounded = true;
            for (std::size_t r = 0; r < n; ++r)
                table.columns[time_column][r] = (t.front() + static_cast<double>(r) * h) / t_factor;
        }
    } else {
        // irregular: the file's rate if the steps are near it, else the typical step: with
        // every step within a quarter of the median (jitter), the least-squares slope of the
        // times over their rows; else (dropped frames) the mean of the steps near the median
        double sum = 0;
        std::size_t count = 0;
        for (double step : steps)
            if (std::abs(step - median) <= median / 4) sum += step, ++count;
        h = sum / static_cast<double>(count);
        if (count == steps.size()) {
            const double k_mean = static_cast<double>(n - 1) / 2;
            double t_mean = 0, skk = 0, skt = 0;
            for (double v : t) t_mean += v / static_cast<double>(n);
            for (std::size_t k = 0; k < n; ++k) {
                const double dk = static_cast<double>(k) - k_mean;
                skk += dk * dk, skt += dk * (t[k] - t_mean);
            }
            h = skt / skk;
        }
        if (options.rate_hz > 0 && std::abs(1 / options.rate_hz - h) <= h / 4) {
            h = 1 / options.rate_hz;
            report.rate_from_file = true;
        }
        // the largest offset from the grid resampled on
        report.worst_offset_s = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const double d = t[k] - (t.front() + static_cast<double>(k) * h);
            if (std::abs(d) > std::abs(report.worst_offset_s)) report.worst_offset_s = d;
        }
        // a long step is missing data, not jitter
        for (std::size_t r = 1; r < n; ++r)
            if (t[r] - t[r - 1] > options.max_gap_s)
                throw ArgumentError(where(r) + "the time column jumps from t = " + seconds(t[r - 1]) + " to " +
                                    seconds(t[r]) + " (" + samples(r - 1, r) + "), a step of " +
                                    seconds(t[r] - t[r - 1]) + ", longer than the " + seconds(options.max_gap_s) +
                                    " that may be bridged by resampling; the frames between are missing: export "
                                    "them, or trim the trial");
    }
    report.rate_hz = 1 / h;

    // each column: find its gaps, check them, fill by a spline through the valid samples
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        if (c == time_column) continue;
        std::vector<double>& y = table.columns[c];
        std::vector<double> tv, yv;
        for (std::size_t r = 0; r < n; ++r)
            if (!std::isnan(y[r])) tv.push_back(t[r]), yv.push_back(y[r]);
        if (tv.size() == n && !irregular) continue;
        const std::string name = gap_name(table.names[c]);
        if (tv.size() < 2)
            throw ArgumentError(source + ": '" + name + "' has " + std::to_string(tv.size()) +
                                " valid samples of " + std::to_string(n) +
                                "; nothing to interpolate from: drop it or use another trial");
        for (std::size_t r = 0; r < n;) {
            if (!std::isnan(y[r])) { ++r; continue; }
            std::size_t e = r;
            while (e < n && std::isnan(y[e])) ++e;
            const Gap gap{name, t[r], t[e - 1], e - r};
            const std::string range = "'" + name + "' is missing from t = " + seconds(gap.t_first) +
                                      " to " + seconds(gap.t_last) + " (" + std::to_string(gap.samples) +
                                      " samples: " + samples(r, e - 1) + ")";
            if (r == 0 || e == n)
                throw ArgumentError(where(r == 0 ? 0 : n - 1) + range + ", at the " +
                                    (r == 0 ? "start" : "end") +
                                    " of the trial, where no interpolation is possible; trim the "
                                    "trial to where the marker is seen, or drop it");
            if (t[e] - t[r - 1] > options.max_gap_s)
                throw ArgumentError(where(r) + range + ", a gap of " + seconds(t[e] - t[r - 1]) +
                                    ", longer than the " + seconds(options.max_gap_s) +
                                    " that may be filled by interpolation; fill it in the capture "
                                    "software, raise the largest gap, or trim the trial");
            const bool known = std::any_of(report.gaps.begin(), report.gaps.end(), [&](const Gap& g) {
                return g.name == gap.name && g.t_first == gap.t_first && g.t_last == gap.t_last;
            });
            if (!known) report.gaps.push_back(gap);
            r = e;
        }
        const NaturalSpline spline(tv, yv);
        for (std::size_t r = 0; r < n; ++r)
            if (std::isnan(y[r])) y[r] = spline(t[r]);
    }

    // an irregular time base: resample every column on the grid inside the first and last times
    report.samples_out = n;
    if (irregular) {
        report.resampled = true;
        const std::size_t m = static_cast<std::size_t>(std::floor((t.back() - t.front()) / h + 1e-9)) + 1;
        std::vector<double> grid(m);
        for (std::size_t k = 0; k < m; ++k) grid[k] = t.front() + static_cast<double>(k) * h;
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            std::vector<double> y(m);
            if (c == time_column) {
                for (std::size_t k = 0; k < m; ++k) y[k] = grid[k] / t_factor;
            } else {
                const NaturalSpline spline(t, table.columns[c]);
                for (std::size_t k = 0; k < m; ++k) y[k] = spline(grid[k]);
            }
            table.columns[c] = std::move(y);
        }
        table.lines.clear();
        report.samples_out = m;
    }
    return report;
}

}  // namespace alembert
