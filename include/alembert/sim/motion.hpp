// SPDX-License-Identifier: MIT
// Motions for inverse dynamics: sampled data smoothed and differentiated, or formulas of time.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "alembert/sim/table.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// Samples of a motion: times and, per coordinate, q, q', q'' in SI units (rad, m, s).
struct MotionSamples {
    std::vector<std::string> coordinates{};  ///< names, as the model prints them ("qA")
    std::vector<double> t{};
    std::vector<std::vector<double>> q{}, qd{}, qdd{};  ///< [coordinate][sample]
};

/// How sampled data are read and become q, q', q''.
struct MotionFilterOptions {
    /// Cutoff of the zero-lag low-pass Butterworth filter (filter_lowpass), in Hz; 0 turns
    /// filtering off (differences of the raw samples). 6 Hz is a common choice for
    /// whole-body movements sampled at 50-200 Hz (Winter 2009, sec. 3.4.4).
    double cutoff_hz = 6.0;
    /// The unit each coordinate is declared in by the model ("deg", "rad", "m", "mm"; in the
    /// order of the coordinates), so a column is checked against it: its unit must measure the
    /// same quantity (an angle column for an angle), and a column without a unit is refused
    /// for a coordinate declared in a unit other than SI (deg, mm). Empty, or "" for a
    /// coordinate: not stated, any angle or length unit is accepted and no unit means SI.
    std::vector<std::string> declared_units{};
    /// For coordinates declared without a unit: the quantity the model's kinematics gives each
    /// ("angle": it turns a frame, a rotation; "length": it turns none, a translation), in the
    /// order of the coordinates, "" where not known. A column is checked against it as against
    /// a declared SI unit (rad, m), so a column 'qA [m]' for a rotation qA is refused.
    std::vector<std::string> kinematic_quantities{};
    /// How to read coordinate columns whose header gives no unit ("deg", "rad", "m", ...):
    /// the columns of the quantity this unit measures are read in it. Empty: such a column is
    /// read in SI (rad, m) unless its coordinate is declared in another unit (then refused).
    std::string unitless_unit{};
};

/// q, q', q'' from a motion table: the column "t" (or "time"; a time unit, s or ms, default
/// s) and one column per coordinate named as the coordinate ("qA [deg]": rad, deg, m, mm,
/// ...; see MotionFilterOptions for columns without a unit). Each coordinate is filtered
/// (options.cutoff_hz), then differentiated once and twice by central differences
/// (alembert::differentiate, differentiate_twice). Columns that are not coordinates are
/// ignored. `source` names the data in messages (the file's path).
/// The times must be uniform as printed: each on the grid of the mean step within the time
/// column's printed precision (calc_uniform_time_base), so times rounded to milliseconds or to
/// 8 decimals are accepted and the step is the mean step.
/// @throws alembert::ArgumentError "source:line: ..." if the times are not increasing or not
///         uniform (a sample off the grid by more than the printed precision), naming the row;
///         if there are two time columns; if a coordinate column is missing (listing those
///         found), has an unknown unit or one of another quantity than its coordinate's (a
///         length for an angle), has no value (NaN) at a sample (naming its time), or has no
///         unit while its coordinate is declared in a unit other than SI and
///         options.unitless_unit does not say how to read it; if fewer than 4 samples.
MotionSamples differentiate_motion(const Table& table, const std::string& source,
                                   const std::vector<std::string>& coordinates,
                                   const MotionFilterOptions& options = {});

/// read_csv(path), then differentiate_motion.
/// @throws as read_csv and differentiate_motion.
MotionSamples read_motion(const std::string& path, const std::vector<std::string>& coordinates,
                          const MotionFilterOptions& options = {});

/// A motion prescribed by formulas of time, q_i = f_i(t): q' and q'' are exact (GiNaC
/// differentiates the formulas; derivatives of step and csgn are taken as zero, so a formula
/// pieced together with step must be continuous in value and first derivative, as
/// minimum_jerk is, for q'' to hold). Formulas are in SI units and compiled once.
class PrescribedMotion {
public:
    /// @throws alembert::ArgumentError if the counts differ or a formula holds a symbol other
    ///         than time and constants with values (named).
    PrescribedMotion(const SymbolTable& table, const std::vector<TimeVariable>& q,
                     const std::vector<ex>& formulas);

    /// Number of coordinates.
    std::size_t size() const { return names_.size(); }
    /// q, q', q'' (size() values each) at time t.
    void calc_state(double t, double* q, double* qd, double* qdd) const;
    /// The motion at each of `times`.
    MotionSamples sample(const std::vector<double>& times) const;

private:
    std::vector<std::string> names_;
    std::shared_ptr<const CompiledExpressions> tape_;  // [q, q', q''] of t
};

/// The minimum-jerk transition s(u) = 10u^3 - 15u^4 + 6u^5 with u = (t - t0)/(t1 - t0),
/// held at 0 before t0 and at 1 after t1 (Flash & Hogan 1985): 0 -> 1 with zero velocity
/// and acceleration at both ends. Built with step(), so it compiles to a tape.
/// @throws alembert::ArgumentError if t1 <= t0.
ex minimum_jerk(const ex& t, double t0, double t1);

}  // namespace alembert
