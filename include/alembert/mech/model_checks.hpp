// SPDX-License-Identifier: MIT
// Physical checks of what a user states: rotation matrices, masses and inertias.
#pragma once

#include <string>

#include "alembert/sym/matrix.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// Relative tolerance of the checks below.
inline constexpr double kModelCheckTolerance = 1e-9;

/// Checks that R_PB is a rotation matrix: R R^T = U and det R = +1, to kModelCheckTolerance.
/// The entries are evaluated with the constants at their values and the time-varying symbols
/// (and any constant without a value) at three fixed pseudo-random states, so a matrix that
/// is a rotation for every value of its angles passes and one that is not fails.
/// @throws alembert::ModelError naming `frame` and `parent`, the largest error of R R^T - U
///         or the determinant, the state where it was found, and how to fix it.
void check_direction_cosines(const SymbolTable& st, const Mat3& R_PB, const std::string& frame,
                             const std::string& parent);

/// Checks that a mass is not negative, when it has a value (it is skipped when it holds a
/// constant without a value or a time-varying symbol).
/// @throws alembert::ModelError naming `body` and the value.
void check_mass(const SymbolTable& st, const ex& mass, const std::string& body);

/// Checks that an inertia matrix (moments on the diagonal, products of inertia as matrix
/// elements off it, about any point) is physical: symmetric positive semidefinite, with
/// principal moments that satisfy the triangle inequality I1 + I2 >= I3 (every mass
/// distribution does, since I1 + I2 - I3 = 2 sum m z^2 in principal axes). A moment written
/// as exactly 0 is read as the planar convention (`0, 0, I_A`: only the moment about the
/// plane's normal matters) and turns the triangle check off. Skipped when an entry holds a
/// constant without a value or a time-varying symbol.
/// @throws alembert::ModelError naming `body`, the principal moments, and what is wrong.
void check_inertia_matrix(const SymbolTable& st, const Mat3& I, const std::string& body);

}  // namespace alembert
