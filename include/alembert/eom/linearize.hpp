// SPDX-License-Identifier: MIT
// Linearization of equations of motion about an operating point: x' = A x + B r.
#pragma once

#include <ginac/ginac.h>

#include <vector>

#include "alembert/eom/kane.hpp"

namespace alembert {

/// Equations of motion in first-order implicit form: residuals E(x, x', r, t) = 0 for the
/// states x with rates x' (x_i' is the time derivative of x_i). A rate may itself be a state
/// (q' in the pair x = (q, q')); those rows are x_i' = x_j and need no residual. The residuals
/// are linear in the other rates, one residual per such rate: kinematic equations
/// q' - k(q, u) and dynamical equations f - M u' in Kane's form, or f - M q'' for q'' in
/// second-order form.
struct FirstOrderEquations {
    std::vector<ex> states{};     ///< x
    std::vector<ex> rates{};      ///< x', one per state, in the same order
    std::vector<ex> residuals{};  ///< E = 0, linear in the rates that are not states
};

/// Kane's equations as first-order equations in x = (q, u_r): the kinematic equations
/// q_i' - k_i(q, u_r, t) (left out for q_i' that are themselves independent speeds, when
/// u = q') and the dynamical equations F~_r + F~_r* = 0.
FirstOrderEquations to_first_order(const KaneEquations& kane);

/// Second-order equations E(q, q', q'', r, t) = 0 (one per coordinate, linear in q'', such as
/// form_kane_equations(sys, q) or form_lagrange_equations(sys, q)) as first-order equations
/// in x = (q, q'), with rates (q', q'').
/// @throws alembert::ArgumentError if the counts differ or a coordinate has no q''.
FirstOrderEquations to_first_order(const std::vector<ex>& residuals,
                                   const std::vector<TimeVariable>& q);

/// What to linearize about.
struct LinearizeOptions {
    /// Values at the operating point: of states, and of inputs and constants if wanted (an
    /// input without a value keeps its symbol). A state left out stays a symbol, so A may
    /// depend on it (linearization about every value of an ignorable coordinate). The rates
    /// follow from the equations; a steady motion (nonzero speeds) is allowed.
    exmap operating_point{};
    /// The inputs r of B: specified functions or unknown load measures (motor torques).
    std::vector<ex> inputs{};
    /// Simplify the entries of A and B (alembert::simplify).
    bool simplify = true;
};

/// The linearized equations delta x' = A delta x + B delta r about an operating point
/// (x0, r0) with rates x0' = x'(x0, r0).
struct LinearizedEquations {
    std::vector<ex> states{};           ///< x
    std::vector<ex> inputs{};           ///< r
    GiNaC::matrix A{};                  ///< d x' / d x at the operating point
    GiNaC::matrix B{};                  ///< d x' / d r at the operating point
    std::vector<ex> operating_rates{};  ///< x0', zero at an equilibrium
};

/// Linearizes E(x, x', r, t) = 0 about the operating point. With M = -dE/dx' (the rates that
/// are not states, x_f'), the rates there solve M x_f' = E at x_f' = 0, and differentiating
/// E = 0 gives M delta x_f' = dE/dx delta x + dE/dr delta r, all at (x0, x0', r0); so the
/// rows of A and B for x_f' are M^-1 dE/dx and M^-1 dE/dr, and a row x_i' = x_j is the unit
/// row e_j. Residuals holding intermediates of `table` are differentiated through them at the
/// operating point (forward mode: each intermediate's value and first derivatives there,
/// once, in dependency order), never expanded, so the cost stays linear in their size.
/// @throws alembert::ArgumentError if the lists do not fit together (counts, a state listed
///         twice, an operating-point value for a rate, an input that is a state);
///         alembert::SolveError if a residual is not linear in the rates or M is singular at
///         the operating point.
LinearizedEquations linearize(const SymbolTable& table, const FirstOrderEquations& equations,
                              const LinearizeOptions& options = {});

/// Linearized second-order equations M dq'' + C dq' + K dq = H dr about an operating point
/// (q0, q0', r0) with accelerations q0'' there. With residuals E(q, q', q'', r) = 0 written
/// applied - inertial: M = -dE/dq'', C = -dE/dq', K = -dE/dq and H = dE/dr, all at
/// (q0, q0', q0'', r0). M is the mass matrix, C holds damping and gyroscopic terms, K
/// stiffness (negative along an unstable direction: an inverted pendulum's -m g L).
struct SecondOrderLinearization {
    std::vector<ex> coordinates{};  ///< q
    std::vector<ex> inputs{};       ///< r
    GiNaC::matrix M{}, C{}, K{}, H{};
};

/// Linearizes second-order equations (one per coordinate, linear in q'', as to_first_order
/// takes them) about `options.operating_point`; q0'' follows from the equations there.
/// @throws alembert::ArgumentError, alembert::SolveError as to_first_order and linearize do.
SecondOrderLinearization linearize_second_order(const SymbolTable& table,
                                                const std::vector<ex>& residuals,
                                                const std::vector<TimeVariable>& q,
                                                const LinearizeOptions& options = {});

}  // namespace alembert
