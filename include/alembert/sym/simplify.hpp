// SPDX-License-Identifier: MIT
// Simplification for mechanics: Pythagorean identities, angle sums, collection, and equality
// by meaning rather than by print order.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace alembert {

using GiNaC::ex;

class SymbolTable;

/// Number of arithmetic operations of `e` counted as a tree: n-1 for a sum or product of n
/// operands, one per power and per function call (how operation counts are reported).
std::size_t count_ops(const ex& e);

/// The sum of count_ops over `exprs`, each distinct node measured once for all of them: the
/// equations of a large model share most of their nodes, and measuring each equation on its
/// own walks the shared part once per equation.
std::size_t count_ops(const std::vector<ex>& exprs);

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

/// `e` with every sin, cos and tan of an angle shifted by a multiple of Pi/2 written without
/// the shift: sin(x + Pi) = -sin(x), cos(x - Pi/2) = sin(x), tan(x + Pi) = tan(x). A shift
/// written as a decimal number (180 deg) counts when it is a multiple of Pi/2 to 1e-12.
ex fold_angle_shifts(const ex& e);

/// Mechanics simplification: angle shifts by multiples of Pi/2 folded, trigonometric
/// simplification, plus rational normalisation when `e` has symbolic denominators; returns
/// whichever form has the fewest operations.
ex simplify(const ex& e);

/// simplify and collect_in with one memory across calls: a node met again (the same
/// kinematics in every row of a road-map, a coefficient shared by two equations) is looked up,
/// not simplified again. Keep one for a batch of related expressions; memory grows with the
/// distinct nodes seen.
class Simplifier {
public:
    Simplifier();
    ~Simplifier();
    Simplifier(Simplifier&&) noexcept;
    Simplifier& operator=(Simplifier&&) noexcept;

    /// simplify(e), remembering every node's result
    ex operator()(const ex& e);
    /// collect_in(e, symbols), its coefficients simplified through this memory
    ex collected(const ex& e, const std::vector<ex>& symbols);

private:
    struct Memo;
    std::unique_ptr<Memo> memo_;
};

/// `e` with the factors common to all its terms taken out: numeric content and every base
/// (symbol, function, sum) that divides each term, to its lowest power, so that
/// L*m*a + L*m*b prints L*m*(a + b). Applied to the sums inside products too (the
/// coefficients of a collected form). Equal to `e` in meaning; no expansion.
ex factor_common(const ex& e);

/// The terms of the sum `e` gathered by the factors they share that vary in time (symbols of
/// `table` other than constants): first by their functions (sin(qB)), then by the rest
/// (qA'*qB'), each group's constant coefficient with its common factors out:
/// sin(qB)*L_A*(L_B*m_C + d_B*m_B)*(2*qA'*qB' + qB'^2). `e` itself when that is not shorter.
/// Equal to `e` in meaning; one pass over the terms, no expansion.
ex group_by_varying_factors(const SymbolTable& table, const ex& e);

/// `e` collected in the listed symbols (e.g. the accelerations qA'', qB''), each coefficient
/// simplified.
ex collect_in(const ex& e, const std::vector<ex>& symbols);

/// The symbols of `e` an equation of motion is solved for (SymbolTable::is_solve_level:
/// highest declared derivatives, unknowns), in `table`'s declaration order.
std::vector<ex> solve_level_symbols(const SymbolTable& table, const ex& e);

/// Largest number of operations of an expression that calc_readable simplifies; larger ones
/// are printed as formed (simplifying them costs more than it shortens).
inline constexpr std::size_t kReadableSimplifyOps = 4000;

/// An equation as a person reads it: intermediates of `table` whose definitions (with their own
/// short intermediates written out) take at most `inline_ops` operations are written out, the
/// result simplified (simplify) and collected in the symbols it is solved for, and, with
/// `factor`, common factors taken out of it and of each coefficient (factor_common). Equal to
/// `e` in meaning. Intermediates left in the result are listed by calc_used_intermediates.
ex calc_readable(const SymbolTable& table, const ex& e, bool factor = false,
                 std::size_t inline_ops = 40);

/// `e` with the intermediates of `table` whose written-out definitions take at most
/// `inline_ops` operations written out (as calc_readable does), nothing else changed.
ex calc_inlined_intermediates(const SymbolTable& table, const ex& e, std::size_t inline_ops = 40);

/// The intermediates a reader of `printed` (forms returned by calc_readable with the same
/// `inline_ops`) must be shown, with their readable definitions, in dependency order: each
/// definition uses only intermediates listed before it.
std::vector<std::pair<ex, ex>> calc_used_intermediates(const SymbolTable& table,
                                                       const std::vector<ex>& printed,
                                                       std::size_t inline_ops = 40);

/// True if `a` and `b` are equal in meaning: their simplified difference is zero, or (for
/// identities the simplifier does not reach) they agree to a relative `tol` at several
/// pseudo-random real points (deterministic seed). Every symbol counts as an independent
/// real variable.
bool equal(const ex& a, const ex& b, double tol = 1e-10);

/// Largest |a - b| over `points` pseudo-random real points (deterministic seed); symbols are
/// drawn from [0.3, 1.7] with random sign so that no angle sits on a special value.
double max_numeric_difference(const ex& a, const ex& b, int points = 6);

}  // namespace alembert
