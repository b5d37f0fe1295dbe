// SPDX-License-Identifier: MIT
// Private to codegen: the joint-reaction measures solved from their road-map rows, block by
// block in the rows' order.
#pragma once

#include <vector>

#include "alembert/sym/symbol_table.hpp"

namespace alembert::detail {

/// Solves the road-map rows E_i = 0 of the joint-reaction measures r (row i is the planner's row
/// for r_i, the rows in the planner's order: each needs only the measures of the rows before it
/// and of its own block), linear in r, for r as expressions of everything else (t, q, q', q'',
/// the other loads, the constants). The rows are split once (split_linear: E = b - A r); then,
/// row after row, a row whose only unsolved measure is its own gives r_i = (b_i - sum_j A_ij
/// r_j) / A_ii with the r_j solved before it, and a row holding measures of later rows opens a
/// block that grows until the measures its rows hold are its own or solved, solved together by
/// solve_by_blocks. The solved expressions are shared, not copied, by the rows after them, so
/// the cost follows the rows' graph, not the depth of the chain.
/// @throws alembert::SolveError naming the measure if a row is not linear in the measures or a
///         block does not determine its measures (a zero coefficient, a singular block).
std::vector<ex> solve_reaction_rows(const SymbolTable& table, const std::vector<ex>& rows,
                                    const std::vector<ex>& measures, const char* who);

}  // namespace alembert::detail
