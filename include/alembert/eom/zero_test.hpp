// SPDX-License-Identifier: MIT
// Deciding whether an expression is identically zero by evaluating it at random states, never
// by expanding it (the positions of a long chain expand exponentially).
#pragma once

#include "alembert/sym/symbol_table.hpp"
#include "alembert/vec/vector.hpp"

namespace alembert {

/// True if e is zero at two pseudo-random states: every symbol it depends on through named
/// intermediates (constants with a value keep it) drawn from ±[0.3, 1.7] with a fixed seed,
/// evaluated in extended precision through the intermediates (never expanded), and taken as
/// zero below 1e-11 times the largest of 1 and the values of the terms of e. This sees the
/// cancellations a symbolic test misses inside intermediates and trigonometric identities.
/// When e cannot be evaluated there (a division by zero, a root of a negative number), it falls
/// back to a symbolic test, simplify(e) == 0, when e with its intermediates is small (at most
/// 2000 operations); larger ones count as not zero.
bool is_zero_at_random_states(const SymbolTable& st, const ex& e);

/// The same for every measure of v in frame F.
bool is_zero_at_random_states(const SymbolTable& st, const Vector& v, const Frame& F);

}  // namespace alembert
