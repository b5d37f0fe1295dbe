// SPDX-License-Identifier: MIT
// Smoothing and differentiation of uniformly sampled signals (motion data).
#pragma once

#include <vector>

namespace alembert {

/// Zero-lag low-pass Butterworth filter, the usual practice for motion data (Winter 2009,
/// Biomechanics and Motor Control of Human Movement, sec. 3.4.4): a second-order Butterworth
/// section (bilinear transform with pre-warping) run forward, then backward over the result,
/// so the phase lag cancels; the combined filter is fourth order, and the cutoff of each pass
/// is raised by Winter's correction 1/C, C = (2^(1/2) - 1)^(1/4) = 0.802, so that the
/// combined -3 dB frequency is `cutoff_hz`. The ends are padded by odd reflection about the
/// end values (6 * sample_rate / cutoff samples, at most the signal's length - 1) and each
/// pass starts from steady state, which keeps end transients small.
/// @throws alembert::ArgumentError if the rates are not positive or the cutoff is not below
///         the Nyquist frequency sample_rate / 2 (after the correction), or x has < 3 samples.
std::vector<double> filter_lowpass(const std::vector<double>& x, double sample_rate_hz,
                                   double cutoff_hz);

/// First derivative of samples x at spacing h: central differences (x_{i+1} - x_{i-1}) / 2h
/// inside, second-order one-sided differences at the ends (-3x_0 + 4x_1 - x_2) / 2h.
/// @throws alembert::ArgumentError if x has fewer than 3 samples or h <= 0.
std::vector<double> differentiate(const std::vector<double>& x, double h);

/// Second derivative of samples x at spacing h: (x_{i+1} - 2x_i + x_{i-1}) / h^2 inside,
/// (2x_0 - 5x_1 + 4x_2 - x_3) / h^2 at the ends (second order).
/// @throws alembert::ArgumentError if x has fewer than 4 samples or h <= 0.
std::vector<double> differentiate_twice(const std::vector<double>& x, double h);

}  // namespace alembert
