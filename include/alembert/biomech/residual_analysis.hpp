// SPDX-License-Identifier: MIT
// Winter's residual analysis: the cutoff frequency of a low-pass filter chosen from the data.
#pragma once

#include <vector>

namespace alembert {

/// The residual of filtering at each trial cutoff and the cutoff chosen.
struct ResidualAnalysis {
    std::vector<double> cutoffs_hz{};  ///< the trial cutoffs
    std::vector<double> residuals{};   ///< R(fc), in the signal's unit
    double noise_rms = 0;   ///< intercept at fc = 0 of the line fitted to the noise region
    double fit_from_hz = 0;  ///< the noise region: fit_from_hz to the largest trial cutoff
    double cutoff_hz = 0;   ///< the lowest cutoff whose residual is noise_rms (interpolated)
};

/// Winter's residual analysis (Winter 2009, Biomechanics and Motor Control of Human Movement,
/// ch. 3): the signal is filtered by filter_lowpass at cutoffs fc from `step_hz` up to
/// 0.35 of the sampling rate (below the filter's limit) in steps of `step_hz`, and the
/// residual R(fc) = sqrt(mean((x - x_fc)^2)) computed. Above the signal's band R falls
/// almost linearly with fc (only noise is removed); the line fitted there by least squares
/// (over the upper half of the trial cutoffs) meets fc = 0 at the noise's rms, and the cutoff
/// chosen is where R(fc) falls to that value: as much signal kept as noise let through.
/// @throws alembert::ArgumentError if the rate or step is not positive, or x has fewer than
///         4 samples.
ResidualAnalysis calc_residual_analysis(const std::vector<double>& x, double sample_rate_hz,
                                        double step_hz = 0.5);

}  // namespace alembert
