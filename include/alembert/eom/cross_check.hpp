// SPDX-License-Identifier: MIT
// Forming a model by several methods and comparing their solved accelerations.
#pragma once

#include <string>
#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// The outcome of forming one model by several methods.
struct MethodComparison {
    std::vector<std::string> methods;  ///< "road-map", "Kane", "Lagrange", "Newton–Euler"
    int states = 0;                    ///< random states compared
    double max_difference = 0;         ///< largest |q''_method - q''_road-map|, scaled by max(1, |q''|)
    std::vector<double> differences;   ///< the same per method (0 for the road-map itself)
};

/// Forms the equations of motion of `sys` in the coordinates `q` by the planned road-map, by
/// Kane's method, by Lagrange's method and by brute-force Newton–Euler (every joint reaction
/// an unknown, solved for with the accelerations; alembert::form_newton_euler_equations),
/// solves each for the accelerations q'' at `states` pseudo-random states (q, q', specified
/// inputs and unknown load measures drawn from [-1, 1], constants without a value from
/// [0.5, 1.5]; deterministic for a given seed), and reports the largest relative difference
/// from the road-map's. Each method's residuals E (linear in its unknowns x, E = b - A x) are
/// compiled once (alembert::CompiledExpressions); at each state b = E(0) and the columns of A
/// come from evaluations at x = s e_j (s = 2^20), which also check that E is linear in x.
/// @throws alembert::SolveError if a method's coefficient matrix is singular at a drawn
///         state or its equations are not linear in its unknowns, alembert::ModelError if
///         Newton–Euler cannot infer the model's joints.
MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states = 3, unsigned seed = 1);

}  // namespace alembert
