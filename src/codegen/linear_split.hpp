// SPDX-License-Identifier: MIT
// Private to codegen: expressions linear in some symbols split into coefficients and the rest,
// in time linear in the size of their graphs.
#pragma once

#include <vector>

#include "alembert/eom/equations.hpp"

namespace alembert::detail {

/// Splits residuals E_i linear in `unknowns` x into A x = b (A_ij = -dE_i/dx_j, b_i = E_i at
/// x = 0), as form_linear_system does, but by one pass over each shared subexpression instead
/// of a derivative per unknown: subexpressions free of x are kept as they are (shared), named
/// intermediates are followed into their definitions, sums and products are split term by
/// term. The cost follows the size of the expressions' graph, not of their trees or of n^2.
/// @throws alembert::SolveError naming the equation and the unknown if E_i is not linear in it.
LinearSystem split_linear(const SymbolTable& table, const std::vector<ex>& residuals,
                          const std::vector<ex>& unknowns, const char* who);

/// The residuals E(u) = b - A u, linear in the loads u, solved for them: u = A^-1 b. When A is
/// numeric (joint loads enter road-maps and Kane's equations of chains with coefficients +-1)
/// its inverse is exact and the loads are sums of the b; otherwise the system is solved
/// symbolically, one decoupled block at a time.
/// @throws alembert::SolveError if the residuals are not linear in the loads or do not
///         determine them.
std::vector<ex> solve_for_loads(const SymbolTable& table, const std::vector<ex>& residuals,
                                const std::vector<ex>& loads, const char* who);

}  // namespace alembert::detail
