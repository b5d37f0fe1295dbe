// SPDX-License-Identifier: MIT
// Zero-lag Butterworth low-pass filter and finite differences.
#include "alembert/sim/filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "alembert/error.hpp"

namespace alembert {

namespace {

// one second-order low-pass Butterworth pass y = H(x), started at steady state on x[0]
void butterworth_pass(std::vector<double>& x, double wc) {
    const double k2 = wc * wc, r2 = std::numbers::sqrt2 * wc;
    const double norm = 1.0 / (1.0 + r2 + k2);
    const double b0 = k2 * norm, b1 = 2 * b0, b2 = b0;
    const double a1 = 2 * (k2 - 1) * norm, a2 = (1 - r2 + k2) * norm;
    double x1 = x[0], x2 = x[0], y1 = x[0], y2 = x[0];
    for (double& xi : x) {
        const double y = b0 * xi + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
        x2 = x1, x1 = xi, y2 = y1, y1 = y;
        xi = y;
    }
}

}  // namespace

std::vector<double> filter_lowpass(const std::vector<double>& x, double sample_rate_hz,
                                   double cutoff_hz) {
    ALEMBERT_CHECK_ARG(x.size() >= 3, "filter_lowpass(): " + std::to_string(x.size()) +
                                          " samples are too few to filter; give at least 3");
    ALEMBERT_CHECK_ARG(sample_rate_hz > 0 && cutoff_hz > 0,
                       "filter_lowpass(): the sample rate and the cutoff frequency must be "
                       "positive");
    // each pass's cutoff, corrected for two passes, pre-warped for the bilinear transform
    const double correction = std::pow(std::numbers::sqrt2 - 1, 0.25);
    const double pass_cutoff = cutoff_hz / correction;
    ALEMBERT_CHECK_ARG(pass_cutoff < 0.5 * sample_rate_hz,
                       "filter_lowpass(): the cutoff " + std::to_string(cutoff_hz) +
                           " Hz is too high for samples at " + std::to_string(sample_rate_hz) +
                           " Hz; choose a cutoff below " +
                           std::to_string(0.5 * sample_rate_hz * correction) + " Hz");
    const double wc = std::tan(std::numbers::pi * pass_cutoff / sample_rate_hz);

    // pad both ends by odd reflection about the end values
    const std::size_t n = x.size();
    const std::size_t pad =
        std::min(n - 1, static_cast<std::size_t>(std::ceil(6 * sample_rate_hz / cutoff_hz)));
    std::vector<double> y;
    y.reserve(n + 2 * pad);
    for (std::size_t k = pad; k >= 1; --k) y.push_back(2 * x.front() - x[k]);
    y.insert(y.end(), x.begin(), x.end());
    for (std::size_t k = 1; k <= pad; ++k) y.push_back(2 * x.back() - x[n - 1 - k]);

    // forward, backward
    butterworth_pass(y, wc);
    std::reverse(y.begin(), y.end());
    butterworth_pass(y, wc);
    std::reverse(y.begin(), y.end());
    return {y.begin() + static_cast<std::ptrdiff_t>(pad),
            y.begin() + static_cast<std::ptrdiff_t>(pad + n)};
}

std::vector<double> differentiate(const std::vector<double>& x, double h) {
    ALEMBERT_CHECK_ARG(x.size() >= 3 && h > 0,
                       "differentiate(): need at least 3 samples at a positive spacing");
    const std::size_t n = x.size();
    std::vector<double> d(n);
    for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (x[i + 1] - x[i - 1]) / (2 * h);
    d[0] = (-3 * x[0] + 4 * x[1] - x[2]) / (2 * h);
    d[n - 1] = (3 * x[n - 1] - 4 * x[n - 2] + x[n - 3]) / (2 * h);
    return d;
}

std::vector<double> differentiate_twice(const std::vector<double>& x, double h) {
    ALEMBERT_CHECK_ARG(x.size() >= 4 && h > 0,
                       "differentiate_twice(): need at least 4 samples at a positive spacing");
    const std::size_t n = x.size();
    std::vector<double> d(n);
    const double h2 = h * h;
    for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (x[i + 1] - 2 * x[i] + x[i - 1]) / h2;
    d[0] = (2 * x[0] - 5 * x[1] + 4 * x[2] - x[3]) / h2;
    d[n - 1] = (2 * x[n - 1] - 5 * x[n - 2] + 4 * x[n - 3] - x[n - 4]) / h2;
    return d;
}

}  // namespace alembert
