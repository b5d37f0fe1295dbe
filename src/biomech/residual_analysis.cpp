// SPDX-License-Identifier: MIT
// Residual analysis over trial cutoffs, a line fitted to the noise region, the cutoff where
// the residual meets the noise level.
#include "alembert/biomech/residual_analysis.hpp"

#include <cmath>
#include <string>

#include "alembert/error.hpp"
#include "alembert/sim/filter.hpp"

namespace alembert {

ResidualAnalysis calc_residual_analysis(const std::vector<double>& x, double sample_rate_hz,
                                        double step_hz) {
    if (!(sample_rate_hz > 0) || !(step_hz > 0))
        throw ArgumentError("calc_residual_analysis(): sampling rate " + std::to_string(sample_rate_hz) +
                            " Hz and step " + std::to_string(step_hz) + " Hz; both must be positive");
    if (x.size() < 4)
        throw ArgumentError("calc_residual_analysis(): " + std::to_string(x.size()) +
                            " samples; the analysis needs at least 4");
    ResidualAnalysis r;
    const double f_max = 0.35 * sample_rate_hz;
    const double n = static_cast<double>(x.size());
    // residual at each trial cutoff
    for (double fc = step_hz; fc <= f_max + 1e-9; fc += step_hz) {
        const std::vector<double> y = filter_lowpass(x, sample_rate_hz, fc);
        double sum = 0;
        for (std::size_t i = 0; i < x.size(); ++i) sum += (x[i] - y[i]) * (x[i] - y[i]);
        r.cutoffs_hz.push_back(fc);
        r.residuals.push_back(std::sqrt(sum / n));
    }
    if (r.cutoffs_hz.size() < 4)
        throw ArgumentError("calc_residual_analysis(): a step of " + std::to_string(step_hz) +
                            " Hz leaves fewer than 4 trial cutoffs below " + std::to_string(f_max) +
                            " Hz; use a smaller step");
    // least-squares line over the upper half of the cutoffs: its intercept is the noise
    const std::size_t first = r.cutoffs_hz.size() / 2;
    r.fit_from_hz = r.cutoffs_hz[first];
    double sf = 0, sr = 0, sff = 0, sfr = 0, m = 0;
    for (std::size_t i = first; i < r.cutoffs_hz.size(); ++i) {
        const double f = r.cutoffs_hz[i], res = r.residuals[i];
        sf += f, sr += res, sff += f * f, sfr += f * res, m += 1;
    }
    const double slope = (m * sfr - sf * sr) / (m * sff - sf * sf);
    r.noise_rms = (sr - slope * sf) / m;
    // the lowest cutoff where the residual has fallen to the noise level
    r.cutoff_hz = r.cutoffs_hz.back();
    for (std::size_t i = 0; i < r.cutoffs_hz.size(); ++i) {
        if (r.residuals[i] > r.noise_rms) continue;
        if (i == 0) {
            r.cutoff_hz = r.cutoffs_hz[0];
        } else {
            const double f0 = r.cutoffs_hz[i - 1], f1 = r.cutoffs_hz[i];
            const double r0 = r.residuals[i - 1], r1 = r.residuals[i];
            r.cutoff_hz = f0 + (r0 - r.noise_rms) / (r0 - r1) * (f1 - f0);
        }
        break;
    }
    return r;
}

}  // namespace alembert
