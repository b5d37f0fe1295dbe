// SPDX-License-Identifier: MIT
// Inverse dynamics over a whole motion: torques at every sample, written as CSV and plotted.
#pragma once

#include <map>
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
    /// Column names of the load measures; empty: their printed names ("T_A", "F_x").
    std::vector<std::string> columns{};
    /// Units of the load measures (parse_unit); empty: "N m" for each.
    std::vector<std::string> units{};
    /// Title of the plot; empty: "inverse dynamics of '<model>'".
    std::string title{};
    /// The columns plotted (empty: every load measure) and whether to plot at all.
    std::vector<std::string> plotted{};
    bool plot = true;
    /// Largest residual (SI: m, rad, m/s) the motion may leave in a constraint of the model
    /// (InverseDynamics::constraint_names) at any sample; beyond it the motion is refused.
    double constraint_tolerance = 1e-6;
    /// The SI unit of each constraint's residual by constraint name ("m"), for messages.
    std::map<std::string, std::string> constraint_units{};
};

/// The load measures of `id` at every sample of `motion` (whose coordinates must be the
/// model's, in any order): a table with "t [s]" and one column per load measure.
/// @throws alembert::ArgumentError if a coordinate of the model is missing from the motion,
///         the options' lists have the wrong length or two columns would share a name, or
///         if the motion violates a constraint of the model beyond
///         options.constraint_tolerance (naming it, the samples, times and the residual), or
///         an equation of motion the loads were not solved from
///         (InverseDynamics::unused_equation_names) beyond
///         InverseDynamics::kUnusedEquationTolerance of the size of its terms;
///         alembert::SolveError listing the samples (times) where the loads are not
///         determined: A singular or nearly singular (reciprocal condition estimate below
///         InverseDynamics::kMinReciprocalCondition) or a load not finite. No number is
///         made up for those samples.
Table calc_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                            const InverseAnalysisOptions& options = {});

/// The name of the file inverse dynamics writes, from the units of its load measures:
/// "forces" when every load is a force (N, kN), "loads" when forces and torques mix, else
/// "torques" (torques, or loads whose unit is not stated).
std::string inverse_dynamics_file_stem(const std::vector<std::string>& units);
/// What run_inverse_dynamics wrote.
struct InverseAnalysisReport {
    Table loads{};      ///< t and the load measures, in their units
    std::string csv{};  ///< path of torques.csv (forces.csv, loads.csv)
    PlotResult plot{};  ///< its plot, .png and .svg, or why not
};

/// The library call behind `alembert inverse MODEL --motion FILE --out DIR`: reads the motion
/// table FILE (read_motion, with the model's coordinate names and options.filter), evaluates
/// the load measures at every sample, and writes DIR/torques.csv (columns t, T_A, T_B, ... with
/// units in the header) and its plot DIR/torques.png and DIR/torques.svg; forces.csv when
/// every load is a force, loads.csv when they mix (inverse_dynamics_file_stem). DIR is
/// created if needed. A missing gnuplot leaves the CSV written and says so in report.plot.message.
/// @throws as read_motion, calc_inverse_dynamics and write_csv.
InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const std::string& motion_csv,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options = {});

/// The same for a motion already in samples (a prescribed motion, PrescribedMotion::sample).
InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options = {});

}  // namespace alembert
