// SPDX-License-Identifier: MIT
// Numeric forward dynamics: evaluate A(q, t) x = b(q, q', t, inputs) and solve for q''.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "alembert/eom/equations.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sim/numeric_function.hpp"

namespace alembert {

/// The symbols the numeric functions of a model take, in order: time, coordinates q_1..q_n,
/// their rates q_1'..q_n', the unknowns of the equations (the accelerations q_i'' and any
/// constraint-force measures, in the order the equations list them) and the inputs (load
/// measures supplied while simulating, such as motor torques).
struct StateLayout {
    ex time{};
    std::vector<ex> coordinates{};
    std::vector<ex> rates{};
    /// The accelerations q_1''..q_n'' (each among the unknowns).
    std::vector<ex> accelerations{};
    std::vector<ex> unknowns{};
    std::vector<ex> inputs{};
    /// Printed names of the coordinates ("qA"), for messages and column headers.
    std::vector<std::string> coordinate_names{};
};

/// Forward dynamics of a model as numbers: at (t, q, q', inputs) it evaluates the linear
/// system A x = b of the equations of motion (for Kane's equations with u = q', A is the mass
/// matrix M(q) and b the forcing f(q, q', t)) and solves it for the unknowns x, of which the
/// accelerations q'' are the ones integration needs.
///
/// The evaluation is one NumericFunction, so a tape or generated code can serve:
///   inputs  [t, q_1..q_n, q_1'..q_n', input_1..input_m]   (1 + 2n + m values)
///   outputs [A_11, A_12, .., A_1k, A_21, .., A_kk, b_1..b_k]  (A row-major, k = unknowns)
/// The solve uses Eigen: LDLT (Cholesky) when A is symmetric (to 1e-12 of its largest entry)
/// and positive definite, a partial-pivoting LU otherwise.
///
/// One call at a time per object (the workspace is reused; nothing is allocated per call).
class ForwardDynamics {
public:
    /// A numeric model named `model` (used in messages) with its layout and function.
    /// @throws alembert::ArgumentError if the function's sizes do not match the layout or an
    ///         acceleration q_i'' is not among the unknowns.
    ForwardDynamics(std::string model, StateLayout layout, NumericFunction system);

    /// The model's name, as messages show it.
    const std::string& model() const { return model_; }
    /// The symbols of the inputs and outputs.
    const StateLayout& layout() const { return layout_; }
    /// The function evaluating A and b.
    const NumericFunction& function() const { return function_; }
    /// Number of coordinates n.
    std::size_t coordinate_count() const { return layout_.coordinates.size(); }
    /// Number of unknowns k (n accelerations plus constraint-force measures).
    std::size_t unknown_count() const { return layout_.unknowns.size(); }
    /// Number of inputs m.
    std::size_t input_count() const { return layout_.inputs.size(); }

    /// The accelerations q'' (n values) at (t, q, q', inputs); `inputs` may be null when the
    /// model has none.
    /// @throws alembert::SolveError naming the model and the state if A or b is not finite
    ///         there, or A is singular or ill-conditioned (reciprocal condition below 1e-13).
    void calc_accelerations(double t, const double* q, const double* qd, const double* inputs,
                            double* qdd) const;
    /// All unknowns x (k values, in layout().unknowns order: accelerations and constraint
    /// forces) at (t, q, q', inputs).
    /// @throws as calc_accelerations.
    void calc_unknowns(double t, const double* q, const double* qd, const double* inputs,
                       double* x) const;
    /// True if the last solve used LDLT (symmetric positive definite A), false for LU.
    bool last_solve_was_ldlt() const { return last_ldlt_; }

private:
    void solve(double t, const double* q, const double* qd, const double* inputs) const;
    [[noreturn]] void fail(const std::string& what, double t, const double* q, const double* qd,
                           const double* inputs) const;

    std::string model_;
    StateLayout layout_;
    NumericFunction function_;
    std::vector<std::size_t> acceleration_index_;  // position of q_i'' among the unknowns
    mutable std::vector<double> in_, out_;
    mutable Eigen::MatrixXd A_;
    mutable Eigen::VectorXd b_, x_;
    mutable Eigen::LDLT<Eigen::MatrixXd> ldlt_;
    mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
    mutable bool last_ldlt_ = false;
};

/// Compiles the equations `eqs` (A x = b, unknowns including q_i'' of every coordinate in
/// `q`) to a tape: constants with values are folded (compile again when they change); every
/// other symbol must be time, a coordinate, its rate, or one of `inputs`. `make` chooses the
/// evaluator (empty: the tape; see FunctionMaker).
/// @throws alembert::ArgumentError if an acceleration is missing from the unknowns or a symbol
///         is none of those (named).
ForwardDynamics compile_forward_dynamics(const SymbolTable& table, const LinearSystem& eqs,
                                         const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& inputs, const std::string& model,
                                         const FunctionMaker& make = {});

/// The equations of motion of `sys` in coordinates `q` as A x = b for forward dynamics:
/// Kane's equations with u = q' (A the symmetric mass matrix, x = q''; not simplified, since
/// the tape shares repeated subexpressions anyway and simplifying costs far more) when the model
/// declares no constraints and `constraint_forces` is empty; otherwise the planned MG road-map
/// whose unknowns are the accelerations and the load measures `constraint_forces` (such as a
/// closed loop's pin force), with the constraint rows at the acceleration level.
/// @throws as form_kane_equations and plan_roadmap.
LinearSystem form_forward_equations(const System& sys, const std::vector<TimeVariable>& q,
                                    const std::vector<ex>& constraint_forces = {});

/// form_forward_equations, then compile_forward_dynamics; `inputs` are the load measures
/// supplied at run time (the others must not appear).
/// @throws as form_forward_equations and compile_forward_dynamics above.
ForwardDynamics compile_forward_dynamics(const System& sys, const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& inputs, const std::string& model,
                                         const std::vector<ex>& constraint_forces = {});

namespace detail {
/// "t = 0.5, qA = 0.1, qB = 2, qA' = 0, qB' = 1" for messages.
std::string describe_state(const StateLayout& layout, double t, const double* q, const double* qd,
                           const double* inputs);
}  // namespace detail

}  // namespace alembert
