// SPDX-License-Identifier: MIT
// Nonlinear statics: equilibrium configurations and loads from residuals E(x) = 0 by a damped
// Newton iteration.
#pragma once

#include <string>
#include <vector>

#include "alembert/eom/roadmap.hpp"

namespace alembert {

/// An interval an unknown must lie in: the branch of solutions wanted.
struct Bound {
    ex variable{};
    double lower = 0;
    double upper = 0;
};

/// A sign an expression must have at the solution: `expression` > 0 (positive) or < 0.
struct SignCondition {
    ex expression{};
    bool positive = true;
    std::string label{};  ///< how messages name the condition ("tip above the pivot")
};

/// Options of alembert::solve_equilibrium.
struct StaticsOptions {
    double tolerance = 1e-10;  ///< converged when max_i |E_i| <= tolerance
    int max_iterations = 50;
    /// Step limit: no unknown changes by more than max_step * max(1, |x_i|) in one iteration.
    double max_step = 1.0;
    /// Boxes: each listed unknown stays in [lower, upper]. The guess is clipped into the box;
    /// a step is shortened to stay inside, and an unknown on a bound that the Newton step
    /// would cross is held there while the others take the Newton step (active set). So the
    /// iteration can only land on a solution inside the box; it still needs a guess from
    /// which that solution is reachable, else it stalls on the bound (a SolveError).
    std::vector<Bound> bounds{};
    /// Checked at the solution; a solution that breaks one is refused with a SolveError.
    std::vector<SignCondition> conditions{};
    /// Where the Jacobian is singular, take the least-squares (minimum-norm) step instead of
    /// stopping; when false, a singular Jacobian is a SolveError.
    bool least_squares = true;
    /// At the solution, refuse (SolveError) when the equations do not fix every unknown there
    /// (as many residuals as unknowns and a singular Jacobian: the value of an unknown no
    /// residual changes with is the guess's); the message names the unknown and the residuals
    /// that do not change with it. A solution that passes is refined by full Newton steps
    /// while max|E| falls (to rounding, past `tolerance`).
    bool require_determined = false;
    /// How messages name the residuals, in their order (a road-map's "E_psi'"); "E[i]"
    /// (from 1) where empty.
    std::vector<std::string> residual_names{};
};

/// An equilibrium found by alembert::solve_equilibrium.
struct Equilibrium {
    std::vector<ex> unknowns{};
    std::vector<double> values{};  ///< in the order of `unknowns`
    int iterations = 0;
    double residual = 0;             ///< max_i |E_i| at the solution
    int least_squares_steps = 0;     ///< iterations at which the Jacobian was singular
    /// The value of one unknown.
    /// @throws alembert::ArgumentError if `x` is not one of the unknowns.
    double value(const ex& x) const;
    /// The unknowns and their values, for substitution or SymbolTable::evaluate.
    exmap as_map() const;
};

/// Solves E(x) = 0 for the `unknowns` x (coordinates q, unknown load measures, or a mix) by a
/// damped Newton iteration: at each iterate the step dx solves J dx = -E with the Jacobian
/// J = dE/dx formed symbolically once (GiNaC differentiation, through intermediates); the
/// step is limited (StaticsOptions::max_step), kept inside the bounds, and halved until
/// |E| decreases (backtracking line search on |E|^2, Armijo condition); when no Newton step
/// decreases |E|, the steepest-descent direction -J^T E is tried. A Jacobian is singular
/// when a singular value is below 1e-12 of the largest met, or so small that the Newton step
/// would exceed 1e12 max(1, |x|); then the minimum-norm least-squares step is taken.
///
/// The other symbols of E take their values from `values`, then from the table (constants);
/// speeds and accelerations of coordinates that are not given default to 0 (at rest).
/// `guess` gives the start; an unknown it omits starts at 0 (clipped into its bound). More
/// residuals than unknowns are solved in the least-squares sense (Gauss–Newton), converging
/// only if they are consistent.
///
/// Residuals usually come from alembert::plan_roadmap(..., Analysis::statics) (see
/// alembert::residuals_of) or alembert::form_generalized_active_forces (Kane's F_r = 0).
/// @throws alembert::ArgumentError if an unknown is not a symbol, there are fewer residuals
///         than unknowns, a bound is empty or names no unknown, or a symbol has no value.
/// @throws alembert::SolveError if the iteration does not converge (the message gives the
///         iterations, the last residual, the last iterate by name and a hint), if the Jacobian
///         is singular and StaticsOptions::least_squares is false, or if the solution breaks a
///         sign condition (the branch was not reached).
Equilibrium solve_equilibrium(const SymbolTable& table, const std::vector<ex>& residuals,
                              const std::vector<ex>& unknowns, const exmap& guess,
                              const exmap& values = {}, const StaticsOptions& options = {});

/// The equations of road-map rows, in row order.
std::vector<ex> residuals_of(const std::vector<RoadmapRow>& rows);

}  // namespace alembert
