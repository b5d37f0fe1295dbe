// SPDX-License-Identifier: MIT
// Deciding whether an expression is identically zero by evaluating it at random states, never
// by expanding it (the positions of a long chain expand exponentially).
#pragma once

#include <vector>

#include "alembert/sym/symbol_table.hpp"
#include "alembert/vec/vector.hpp"

namespace alembert {

/// True if e is zero at two pseudo-random states: every symbol it depends on through named
/// intermediates (constants with a value keep it) takes a value in ±[0.3, 1.7] drawn from its
/// name and the state, e is evaluated in extended precision through the intermediates (never
/// expanded; each intermediate's values are computed once and remembered for later tests),
/// and taken as zero below 1e-11 times the largest of 1 and the values of the terms of e. This
/// sees the cancellations a symbolic test misses inside intermediates and trigonometric
/// identities. When e cannot be evaluated there (a division by zero, a root of a negative
/// number), it falls back to a symbolic test, simplify(e) == 0, when e with its intermediates
/// is small (at most 2000 operations); larger ones count as not zero.
bool is_zero_at_random_states(const SymbolTable& st, const ex& e);

/// For each of `symbols`, whether `e` changes with it: e at two random states (as above), then
/// with that symbol alone moved by 1, compared at 1e-11 times the size of e's terms. One
/// compilation of e for all of them, instead of a derivative and a zero test for each (a long
/// chain's row is a deep tree, and differentiating it walks the tree). For a symbol e holds
/// linearly (a load's measure) this is "its coefficient is not zero". Where e cannot be
/// evaluated, each symbol's derivative is tested by is_zero_at_random_states.
std::vector<bool> calc_changes_with_at_random_states(const SymbolTable& st, const ex& e,
                                                     const std::vector<ex>& symbols);

/// Whether `e` changes with the symbol `x` when the symbols of `zeroed` are held at 0 and the
/// others take random values: e compiled once (through the intermediates, never expanded) and
/// evaluated at two random states with x moved by 1, the change compared at 1e-11 times the
/// size of e's terms. A row that holds a speed only multiplied by other speeds (psi' theta')
/// does not change with it when those speeds are 0. False where e cannot be evaluated there.
bool calc_changes_with_others_zero_at_random_states(const SymbolTable& st, const ex& e,
                                                    const ex& x, const std::vector<ex>& zeroed);

/// The same for every measure of v in frame F.
bool is_zero_at_random_states(const SymbolTable& st, const Vector& v, const Frame& F);

}  // namespace alembert
