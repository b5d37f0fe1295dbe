// SPDX-License-Identifier: MIT
// Deciding whether an expression is identically zero by evaluating it at random states, never
// by expanding it (the positions of a long chain expand exponentially).
#pragma once

#include <array>
#include <memory>
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

/// Vectors' measures (their components in some frame, Col3) at the random states of the zero
/// tests above, and their changes when one symbol alone moves by 1: for a velocity, which is
/// linear in each speed, that change is its partial velocity. The evaluation with a symbol
/// moved is kept until another symbol is asked for, so the partials of every body's velocity
/// with respect to one speed cost one walk of the kinematics that speed reaches, not one per
/// body (a chain's planner asked n symbolic derivatives and zero tests of n bodies for each of
/// its n coordinates). Throws std::domain_error where a measure cannot be evaluated there.
class MeasuresAtRandomStates {
public:
    static constexpr int kStates = 2;
    using Values = std::array<std::array<long double, 3>, kStates>;  ///< [state][component]

    explicit MeasuresAtRandomStates(const SymbolTable& st);
    ~MeasuresAtRandomStates();
    MeasuresAtRandomStates(const MeasuresAtRandomStates&) = delete;
    MeasuresAtRandomStates& operator=(const MeasuresAtRandomStates&) = delete;

    /// c at each state
    Values calc_values(const Col3& c);
    /// c with `moved` moved by 1, less c, at each state
    Values calc_changes(const Col3& c, const ex& moved);
    /// Whether c changes with `moved`: a change over 1e-11 times the largest of 1 and the
    /// measures before and after, as the zero tests compare
    bool calc_changes_with(const Col3& c, const ex& moved);

    /// a and b agree at every state, component by component, to 1e-11 times the largest of 1
    /// and their magnitudes
    static bool agree(const Values& a, const Values& b);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace alembert
