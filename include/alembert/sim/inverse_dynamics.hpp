// SPDX-License-Identifier: MIT
// Numeric inverse dynamics: the load measures (joint torques) of a motion, sample by sample.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "alembert/sim/forward_dynamics.hpp"

namespace alembert {

/// Inverse dynamics of a model as numbers: at (t, q, q', q'') the load measures that make the
/// motion happen (motor torques, and constraint forces when the equations hold them).
///
/// The evaluation is one NumericFunction, so a tape or generated code can serve:
///   inputs  [t, q_1..q_n, q_1'..q_n', q_1''..q_n'']   (1 + 3n values)
///   outputs solved form:   [T_1..T_k], the load measures themselves;
///           unsolved form: [A row-major (k x k), b_1..b_k] of A T = b, solved per call by LU.
/// compile_inverse_dynamics makes the solved form whenever each equation holds exactly one
/// load measure (an MG road-map plans its rows so; Kane's equations of joint torques are so
/// too): T_i = b_i / A_ii is compiled directly and no solve is left for run time.
/// One call at a time per object.
class InverseDynamics {
public:
    /// @throws alembert::ArgumentError if the function's sizes do not match the layout
    ///         (layout.unknowns are the load measures; layout.inputs must be empty).
    InverseDynamics(std::string model, StateLayout layout, NumericFunction loads, bool solved);

    const std::string& model() const { return model_; }
    const StateLayout& layout() const { return layout_; }
    const NumericFunction& function() const { return function_; }
    /// True if the function gives the load measures directly (no solve at run time).
    bool solved() const { return solved_; }
    std::size_t coordinate_count() const { return layout_.coordinates.size(); }
    /// Number of load measures k.
    std::size_t load_count() const { return layout_.unknowns.size(); }
    /// Printed names of the load measures ("T_A").
    std::vector<std::string> load_names() const;

    /// Below this reciprocal condition estimate of A (unsolved form) the load measures are
    /// taken as not determined by the motion: A is singular or nearly singular.
    static constexpr double kMinReciprocalCondition = 1e-12;

    /// The load measures (k values, in layout().unknowns order) at (t, q, q', q'').
    /// @throws alembert::SolveError naming the model and the state if a value is not finite or
    ///         (unsolved form) A's reciprocal condition estimate is below
    ///         kMinReciprocalCondition.
    void calc_loads(double t, const double* q, const double* qd, const double* qdd,
                    double* loads) const;

    /// As calc_loads, but a state where the loads are not determined is returned, not thrown:
    /// the empty string when `loads` holds finite values, else what is wrong ("the equations
    /// are singular ... (reciprocal condition estimate 3e-17)", "T_A is inf"). `rcond`
    /// receives A's reciprocal condition estimate (1 for the solved form).
    std::string try_calc_loads(double t, const double* q, const double* qd, const double* qdd,
                               double* loads, double* rcond) const;

    /// The model's constraints a motion must satisfy: `residuals` evaluates their residuals
    /// (configuration and motion constraints, SI) over the same inputs [t, q, q', q''], one
    /// output per name in `names` ("the configuration constraint 'loop_x'").
    /// @throws alembert::ArgumentError if the sizes do not match.
    void set_constraints(std::vector<std::string> names, NumericFunction residuals);
    /// Names of the constraints set by set_constraints (empty: none).
    const std::vector<std::string>& constraint_names() const { return constraint_names_; }
    /// The constraint residuals (constraint_names().size() values, SI) at (t, q, q', q'').
    void calc_constraint_residuals(double t, const double* q, const double* qd, const double* qdd,
                                   double* residuals) const;

    /// The size of each load's coefficient in the solved form (T_i = b_i / c_i): `sizes`
    /// evaluates [c_1..c_k, |c_1|..|c_k|] over [t, q, q', q''], where |c_i| bounds c_i by the
    /// sizes of its terms (calc_size_bound). try_calc_loads takes T_i as not determined where
    /// |c_i| <= kMinReciprocalCondition |c_i|_bound: a coefficient such as cos(q1) at q1 = 90
    /// deg is 6e-17 in floating point, not 0, and b_i / c_i there is noise.
    /// @throws alembert::ArgumentError if the sizes do not match (or the form is unsolved).
    void set_coefficient_sizes(NumericFunction sizes);

    /// Equations of motion the load measures are not solved from (an under-actuated model:
    /// fewer loads acting than coordinates), to be checked at each sample: `residuals`
    /// evaluates [r_1..r_m, s_1..s_m] over [t, q, q', q'', T_1..T_k], each residual r_j with
    /// the size s_j of its terms; `names` names them ("Kane's equation for th").
    /// @throws alembert::ArgumentError if the sizes do not match.
    void set_unused_equations(std::vector<std::string> names, NumericFunction residuals);
    /// Names of the equations set by set_unused_equations (empty: none).
    const std::vector<std::string>& unused_equation_names() const { return unused_names_; }
    /// The residuals and their sizes (2 m values: r_1..r_m, s_1..s_m) of the unused equations
    /// at (t, q, q', q'') with the load measures `loads`.
    void calc_unused_residuals(double t, const double* q, const double* qd, const double* qdd,
                               const double* loads, double* residuals) const;
    /// A motion satisfies an unused equation where |r_j| <= kUnusedEquationTolerance s_j.
    static constexpr double kUnusedEquationTolerance = 1e-9;

private:
    [[noreturn]] void fail(const std::string& what, double t, const double* q,
                           const double* qd) const;

    std::string model_;
    StateLayout layout_;
    NumericFunction function_;
    bool solved_ = true;
    mutable std::vector<double> in_, out_;
    mutable Eigen::MatrixXd A_;
    mutable Eigen::VectorXd b_;
    mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
    std::vector<std::string> constraint_names_;
    NumericFunction constraints_;
    NumericFunction coefficient_sizes_;
    mutable std::vector<double> sizes_out_;
    std::vector<std::string> unused_names_;
    NumericFunction unused_;
    mutable std::vector<double> unused_in_;
};

/// An upper bound of |e| from the sizes of its terms, as an expression: |a + b| <= |a| + |b|,
/// |a b| <= |a| |b|, |sin x|, |cos x| <= 1, and |x| for anything else (symbols,
/// intermediates, other functions). The scale a relative zero test compares e with: e = cos(q)
/// has size 1, so cos(90 deg) = 6e-17 is zero against it.
ex calc_size_bound(const ex& e);

/// Compiles equations `eqs` that are linear in load measures (eqs.unknowns, e.g. joint
/// torques; A T = b) as functions of t and the coordinates `q` with their first and second
/// derivatives; constants with values are folded. `make` chooses the evaluator (empty: the
/// tape; see FunctionMaker).
/// @throws alembert::ArgumentError naming a symbol that is none of those.
InverseDynamics compile_inverse_dynamics(const SymbolTable& table, const LinearSystem& eqs,
                                         const std::vector<TimeVariable>& q,
                                         const std::string& model, const FunctionMaker& make = {});

/// Plans the MG road-map of `sys` for the load measures `loads` (one row per measure, about
/// the joint where the other unknown forces drop out) and compiles it, with the residuals of
/// the model's constraints (set_constraints) so a motion can be checked against them. A model
/// without constraints in which fewer of `loads` act than it has coordinates (a cart driven
/// by F carrying a rod on a pin) has equations the loads are not solved from: Kane's
/// equations F_r + F_r* = 0 of every coordinate are set as unused equations
/// (set_unused_equations), so calc_inverse_dynamics checks that the motion satisfies them. Where
/// the model is a tree (explain_not_tree) with as many load measures as coordinates, each
/// entering the rows (motor torques, forces on bodies; not joint reactions), the same rows are
/// formed recursively instead (form_tree_equations: their size grows linearly in the number of
/// bodies, the planned closed forms' as its square); the loads are the same.
/// `specified` gives the specified quantities the motion drives, and their derivatives, as
/// formulas of t (as SimulationRequest::specified): they are substituted into the rows, through
/// the intermediates; the load that drives a specified quantity comes from its row (S = what
/// moves when only it changes; see plan_roadmap).
/// @throws as plan_roadmap and compile_inverse_dynamics above.
InverseDynamics compile_inverse_dynamics(const System& sys, const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& loads, const std::string& model,
                                         const FunctionMaker& make = {},
                                         const exmap& specified = {});

}  // namespace alembert
