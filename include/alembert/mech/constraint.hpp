// SPDX-License-Identifier: MIT
// Constraints a model declares: closed loops (configuration) and rolling (motion).
#pragma once

#include <string>

#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// What a constraint restricts.
enum class ConstraintKind {
    configuration,  ///< holonomic: f(q, t) = 0, e.g. a closed kinematic loop
    motion,         ///< nonholonomic: linear in the speeds, f(q, q', t) = 0, e.g. rolling
};

/// One scalar constraint residual, zero when the constraint holds.
struct Constraint {
    std::string name;
    ConstraintKind kind = ConstraintKind::configuration;
    ex residual;
};

/// Returns "configuration" or "motion".
const char* to_string(ConstraintKind kind);

}  // namespace alembert
