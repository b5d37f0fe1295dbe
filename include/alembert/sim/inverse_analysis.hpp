// SPDX-License-Identifier: MIT
// Inverse dynamics over a whole motion: torques at every sample, written as CSV and plotted.
#pragma once

#include <string>
#include <vector>

#include "alembert/sim/inverse_dynamics.hpp"
#include "alembert/sim/motion.hpp"
#include "alembert/sim/plot.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// How an inverse-dynamics analysis reads, names and writes.
struct InverseAnalysisOptions {
    /// Smoothing of sampled motion data (ignored for prescribed motions).
    MotionFilterOptions filter{};
    /// Column names of the load measures; empty: their printed names without underscores
    /// ("T_A" -> "TA").
    std::vector<std::string> columns{};
    /// Units of the load measures (parse_unit); empty: "N m" for each.
    std::vector<std::string> units{};
    /// Title of the plot; empty: "inverse dynamics of '<model>'".
    std::string title{};
};

/// The load measures of `id` at every sample of `motion` (whose coordinates must be the
/// model's, in any order): a table with "t [s]" and one column per load measure.
/// @throws alembert::ArgumentError if a coordinate of the model is missing from the motion or
///         the options' lists have the wrong length; alembert::SolveError as calc_loads.
Table calc_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                            const InverseAnalysisOptions& options = {});

/// What run_inverse_dynamics wrote.
struct InverseAnalysisReport {
    Table loads{};      ///< t and the load measures, in their units
    std::string csv{};  ///< path of torques.csv
    PlotResult plot{};  ///< torques.png and torques.svg, or why not
};

/// The library call behind `alembert inverse MODEL --motion FILE --out DIR`: reads the motion
/// table FILE (read_motion, with the model's coordinate names and options.filter), evaluates
/// the load measures at every sample, and writes DIR/torques.csv (columns t, TA, TB, ... with
/// units in the header) and its plot DIR/torques.png and DIR/torques.svg. DIR is created if
/// needed. A missing gnuplot leaves the CSV written and says so in report.plot.message.
/// @throws as read_motion, calc_inverse_dynamics and write_csv.
InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const std::string& motion_csv,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options = {});

/// The same for a motion already in samples (a prescribed motion, PrescribedMotion::sample).
InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options = {});

}  // namespace alembert
