// SPDX-License-Identifier: MIT
// An equation of motion as a person reads it.
#pragma once

#include <cstddef>

#include "alembert/mech/system.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

/// Largest equation (in operations, count_ops) that readable_equation simplifies; a larger one
/// is shown as formed, since simplifying it costs more than it shortens.
inline constexpr std::size_t kReadableEquationOps = 4000;

/// `e` simplified and collected in the accelerations of `sys` it holds (their coefficients
/// simplified), when it takes at most kReadableEquationOps operations; `e` itself otherwise.
/// Equal to `e` in meaning. `simplifier` remembers what it has simplified: pass the same one
/// for the rows of one road-map, whose kinematics repeat from row to row.
ex readable_equation(const System& sys, const ex& e, Simplifier& simplifier);

/// A row's equation as a reader sees it: `lhs = rhs`, equal in meaning to 0 = e.
struct ReadableRelation {
    ex lhs = 0;  ///< the unknown solved for, or 0 when the equation is not solved
    ex rhs = 0;
    bool solved() const { return !lhs.is_zero(); }
};

/// The equation 0 = `e` of the row for `unknown`, to be read: solved for `unknown`
/// (unknown = rhs) when `e` takes at most kReadableEquationOps operations, holds `unknown`
/// linearly (e = a*unknown + b, with a and b free of it) and its coefficient `a` is a nonzero
/// number or a product of the model's constants (so the solution holds at every state, with no
/// division by something that can vanish); otherwise 0 = e. Either side is readable_equation's
/// form (collected in the accelerations), with common factors taken out of it and of each
/// acceleration's coefficient (factor_common). Nothing is expanded beyond what
/// readable_equation expands; a larger `e` is returned as formed (0 = e).
ReadableRelation calc_solved_equation(const System& sys, const ex& e, const ex& unknown,
                                      Simplifier& simplifier);

}  // namespace alembert
