// SPDX-License-Identifier: MIT
// Inverse kinematics: the coordinates of a model that best fit measured marker trajectories.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/time_base.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sym/evaluator.hpp"

namespace alembert {

/// A marker of a model: the name it has in the marker file and the model's point it is
/// stuck on, with the weight of its squared distance in the fit.
struct MarkerPoint {
    std::string name{};    ///< as in the .trc file
    const Point* point{};  ///< a point of the model (fixed on a body)
    double weight = 1.0;   ///< w_i > 0 of w_i |p_model - p_measured|^2
};

/// How InverseKinematics solves each frame.
struct InverseKinematicsOptions {
    /// Coordinates the first frame starts from (one per coordinate, in order; empty: all
    /// zero, the model's reference pose). Later frames start from the frame before.
    std::vector<double> initial{};
    /// Iterations (trial steps) allowed per frame before the frame is declared not converged.
    int max_iterations = 100;
    /// A frame has converged when a step |dq| is at most step_tolerance (1 + |q|), or the
    /// gradient of the cost is at most gradient_tolerance (m^2 per coordinate unit).
    double step_tolerance = 1e-12;
    double gradient_tolerance = 1e-15;
    /// A frame whose markers present leave a combination of coordinates free (the Jacobian's
    /// smallest singular value below rank_tolerance times its largest) is refused: its
    /// coordinates would be whatever the frame before left there.
    double rank_tolerance = 1e-8;
};

/// The fit of one frame.
struct InverseKinematicsFrame {
    double time = 0;                 ///< s
    std::vector<double> q{};         ///< coordinates, in the order given
    std::vector<double> residual{};  ///< per model marker |p_model - p_measured|, m; NaN if missing
    double rms = 0;                  ///< sqrt(mean of residual^2 over the markers present), m
    double max = 0;                  ///< the largest residual, m
    std::string worst_marker{};      ///< the marker with the largest residual
    std::vector<std::string> missing{};  ///< model markers missing (NaN) in this frame
    int iterations = 0;                  ///< trial steps taken
};

/// The result of inverse kinematics over a trial.
struct InverseKinematicsResult {
    std::vector<std::string> coordinates{};  ///< coordinate names, in the order given
    std::vector<std::string> units{};        ///< "rad" or "m" per coordinate (see below)
    std::vector<std::string> markers{};      ///< model marker names, in the order given
    std::vector<InverseKinematicsFrame> frames{};
    /// Stretches of frames where a model marker was missing (skipped in the fit), in order
    /// of marker then time.
    std::vector<Gap> gaps{};

    /// The coordinates as a table: "time [s]", then one column per coordinate, in "rad" for
    /// a coordinate that enters the marker positions through trigonometric functions and in
    /// "m" for the others (write_storage or write_csv writes it as a motion).
    Table calc_coordinate_table() const;
    /// The residuals as a table: "time [s]", one column "M [m]" per model marker (NaN where it
    /// is missing), then "rms [m]" and "max [m]".
    Table calc_residual_table() const;
    /// A summary, one sentence a line: frames and iterations, the RMS residual (mean and
    /// largest over frames), the largest residual with its marker and time, per marker its
    /// RMS over the trial, and each stretch where a marker was missing with its time range.
    std::string describe() const;
};

/// Inverse kinematics of a model over marker trajectories (OpenSim's "IK" step): per frame,
/// the coordinates q that minimise the weighted sum of squared distances between the model's
/// marker points and the measured markers,
///     q* = argmin_q sum_i w_i |p_i(q) - m_i|^2  over the markers i present in the frame,
/// where p_i(q) = r^{P_i/N_o} in N (the Newtonian frame's axes are the lab's X, Y, Z).
///
/// Method (stated because results depend on it):
///  - the positions p_i(q) and their partial derivatives dp_i/dq_k are formed symbolically
///    once and compiled once into one tape (CompiledExpressions): the Jacobian is analytic;
///  - each frame is solved by Levenberg-Marquardt (Levenberg 1944, Marquardt 1963): steps
///    (J^T W J + mu I) h = -J^T W r, mu started at tau times the largest diagonal of J^T W J
///    (tau = 1e-3 at the first frame, 1e-6 after) and updated by Nielsen's rule (Madsen,
///    Nielsen and Tingleff, Methods for Non-linear Least Squares Problems, 2004, algorithm
///    3.16), started from the previous frame's solution (the first frame from
///    options.initial); a trial step is kept when the cost falls, or, where the change in
///    cost is lost in its rounding (near a minimum with residuals), when the gradient falls;
///    after the stop, up to three undamped Gauss-Newton steps while they lower the gradient;
///  - a marker with a coordinate NaN in a frame is left out of that frame's sum (not taken as
///    zero) and named in the frame's `missing`.
///
/// Our own Levenberg-Marquardt rather than Eigen's unsupported module: the problems are small
/// and dense (tens of coordinates); ours starts its damping small where the previous frame's
/// solution is close (tau, below), stops on tolerances stated in the coordinates' own units and
/// reports its iterations; the unsupported module's interface is not part of Eigen's stable
/// API.
///
/// Construction checks the marker set: the model's markers must fix every coordinate
/// (3 m >= n, and the Jacobian of all marker positions at a generic configuration has full
/// column rank n).
///
/// The object keeps no reference to the System after construction. solve() allocates its own
/// workspace, so several threads may solve trials with one object at once;
/// calc_marker_positions() uses the tape's scratch buffer (one thread at a time).
class InverseKinematics {
public:
    /// Forms and compiles the marker positions and their Jacobian for `coordinates` (symbols
    /// q of `system`'s table). Partial derivatives may name intermediates in the system's
    /// symbol table, hence the non-const System.
    /// @throws alembert::ArgumentError if there are no coordinates or markers, a coordinate
    ///         is not a symbol of the table or is listed twice, a marker has no point, an empty
    ///         or repeated name, or a weight that is not positive and finite, a marker's
    ///         position uses a symbol that is neither a coordinate nor a constant with a value
    ///         (naming the marker and the symbol), or options.initial has the wrong size;
    ///         alembert::ModelError if the markers cannot fix the coordinates (fewer measured
    ///         marker coordinates than coordinates, or a combination the markers do not
    ///         change), naming the coordinates they leave free.
    InverseKinematics(System& system, std::vector<ex> coordinates, std::vector<MarkerPoint> markers,
                      InverseKinematicsOptions options = {});

    /// Solves every frame of `markers`, in time order.
    /// @throws alembert::ArgumentError if a model marker's name is not in the marker file
    ///         (naming it and listing the file's markers) or the table has no frames;
    ///         alembert::SolveError naming the frame and its time if a frame does not converge
    ///         within options.max_iterations, or if the markers present in it leave a
    ///         combination of coordinates free (naming the missing markers and those
    ///         coordinates).
    InverseKinematicsResult solve(const MarkerTable& markers) const;

    /// The model's marker positions p_i(q) at coordinates `q`, 3 per marker (x, y, z in N).
    /// @throws alembert::ArgumentError if q has the wrong size.
    std::vector<double> calc_marker_positions(const std::vector<double>& q) const;

    /// Coordinate names, in order.
    const std::vector<std::string>& coordinate_names() const { return coordinate_names_; }
    /// Operations of one evaluation of the positions and the Jacobian.
    std::size_t operation_count() const { return tape_.operation_count(); }

private:
    std::vector<std::string> coordinate_names_;
    std::vector<std::string> units_;
    std::vector<MarkerPoint> markers_;
    InverseKinematicsOptions options_;
    CompiledExpressions tape_;  // positions (3 m), then the Jacobian (3 m x n, row-major)
};

/// InverseKinematics(system, coordinates, markers, options).solve(table).
InverseKinematicsResult calc_inverse_kinematics(System& system, const std::vector<ex>& coordinates,
                                                const std::vector<MarkerPoint>& markers,
                                                const MarkerTable& table,
                                                const InverseKinematicsOptions& options = {});

}  // namespace alembert
