// SPDX-License-Identifier: MIT
// Numeric solve of equations one block after another, where the whole set is not linear.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// Solves `residuals` = 0 for `unknowns` at `values` block by block: a block is the first
/// residual that holds one unknown not yet solved, else the shortest run of the next residuals
/// (in their order, as plan_roadmap orders its rows) that holds as many unsolved unknowns as it
/// has residuals. Each block, with the numbers of the blocks before it substituted (so
/// -mu |Fn| csgn(x') becomes a number once Fn is known), must be linear in its own unknowns;
/// it is solved by solve_numeric. The result is in the order of `unknowns`.
/// @throws alembert::SolveError if the residuals cannot be split into such blocks, or a block
///         is not linear in its unknowns (form_linear_system's message) or is singular;
///         alembert::ArgumentError if a symbol has no value (solve_numeric).
Eigen::VectorXd solve_numeric_in_blocks(const SymbolTable& table, const std::vector<ex>& residuals,
                                        const std::vector<ex>& unknowns, const exmap& values);

}  // namespace alembert
