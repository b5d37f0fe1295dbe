// SPDX-License-Identifier: MIT
// Common-subexpression naming: repeated subexpressions become named intermediates.
#pragma once

#include <cstddef>
#include <vector>

#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// Replaces, in place, every subexpression that occurs at least twice across `exprs` and
/// costs at least `min_ops` operations by a named intermediate of `table` (z1, z2, ...),
/// innermost first, so each intermediate's definition uses earlier intermediates only.
/// Returns the intermediates it created, in dependency order.
///
/// This is how formation steps keep expression swell in check: the results stay exactly equal
/// to the inputs once `table.expand_intermediates()` is applied.
std::vector<ex> introduce_intermediates(SymbolTable& table, std::vector<ex>& exprs,
                                        std::size_t min_ops = 2);

/// The intermediates of `table` that `exprs` reach, directly or through the definitions of
/// others, in the table's (dependency) order: each definition uses only intermediates listed
/// before it. One walk over the shared nodes of all the expressions and definitions.
std::vector<ex> calc_reached_intermediates(const SymbolTable& table, const std::vector<ex>& exprs);

/// Sum of count_ops over the expressions plus the definitions of the intermediates they
/// reach (each counted once): the cost of evaluating them in dependency order.
std::size_t count_ops_with_intermediates(const SymbolTable& table, const std::vector<ex>& exprs);

}  // namespace alembert
