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

}  // namespace alembert
