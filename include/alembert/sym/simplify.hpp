// SPDX-License-Identifier: MIT
// Simplification for mechanics: Pythagorean identities, angle sums, collection, and equality
// by meaning rather than by print order.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <vector>

namespace alembert {

using GiNaC::ex;

/// Number of arithmetic operations of `e` counted as a tree: n-1 for a sum or product of n
/// operands, one per power and per function call (how operation counts are reported).
std::size_t count_ops(const ex& e);

/// The largest number of terms expand(e) forms, an upper bound that assumes no cancellation:
/// a sum of sums adds their counts, a product multiplies them, and (t_1 + ... + t_k)^n has
/// C(n + k - 1, n) terms (the multinomial count). Infinity when the count passes 1e300.
/// Shared subexpressions are visited once, so the estimate is cheap beside the expansion.
double estimate_expansion_terms(const ex& e);

/// Trigonometric simplification of a sum of products:
///  - Pythagorean identity sin^2 x + cos^2 x = 1 in whichever direction shortens;
///  - angle sums s_a c_b +- c_a s_b = sin(a +- b) and c_a c_b -+ s_a s_b = cos(a +- b),
///    applied repeatedly so that triple sums fold too.
/// The expanded result is returned only when it has fewer operations than `e`.
ex trig_simplify(const ex& e);

/// Mechanics simplification: trigonometric simplification, plus rational normalisation when
/// `e` has symbolic denominators; returns whichever form has the fewest operations.
ex simplify(const ex& e);

/// `e` collected in the listed symbols (e.g. the accelerations qA'', qB''), each coefficient
/// simplified.
ex collect_in(const ex& e, const std::vector<ex>& symbols);

/// True if `a` and `b` are equal in meaning: their simplified difference is zero, or (for
/// identities the simplifier does not reach) they agree to a relative `tol` at several
/// pseudo-random real points (deterministic seed). Every symbol counts as an independent
/// real variable.
bool equal(const ex& a, const ex& b, double tol = 1e-10);

/// Largest |a - b| over `points` pseudo-random real points (deterministic seed); symbols are
/// drawn from [0.3, 1.7] with random sign so that no angle sits on a special value.
double max_numeric_difference(const ex& a, const ex& b, int points = 6);

}  // namespace alembert
