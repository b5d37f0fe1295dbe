// SPDX-License-Identifier: MIT
// Equations linear in chosen unknowns: the A x = b form, symbolic and numeric solution.
#pragma once

#include <Eigen/Dense>
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// Residuals E_i = 0 that are linear in the unknowns x, written as A x = b with
/// A_ij = -dE_i/dx_j and b_i = E_i at x = 0 (so E = b - A x). For dynamics with x = q'' this
/// is the mass matrix and forcing, M(q) q'' = f(q, q', t).
struct LinearSystem {
    GiNaC::matrix A;
    GiNaC::matrix b;
    std::vector<ex> unknowns;
};

/// Splits residuals that are linear in `unknowns` into A x = b.
/// @throws alembert::SolveError naming the unknown if a residual is not linear in it, and
///         alembert::ArgumentError if the counts differ.
LinearSystem form_linear_system(const std::vector<ex>& residuals, const std::vector<ex>& unknowns);

/// Solves A x = b symbolically (fraction-free elimination); each result is simplified.
/// Meant for small systems (a handful of unknowns): sizes grow quickly beyond that.
/// @throws alembert::SolveError if A is singular.
std::vector<ex> solve_symbolic(const LinearSystem& sys);

/// Dense matrices and columns in extended precision (long double).
using MatrixXld = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
using VectorXld = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

/// Solves A x = b by a full-pivoting LU decomposition in extended precision.
/// @throws alembert::SolveError reading "<what> is singular or ill-conditioned (reciprocal
///         condition estimate r)<hint>" if A is singular or its reciprocal condition estimate
///         is not above 1e-14.
Eigen::VectorXd solve_extended(const MatrixXld& A, const VectorXld& b, const std::string& what,
                               const std::string& hint);

/// Evaluates A and b at the values given (constants take their table values) and solves
/// A x = b with a pivoting LU decomposition.
/// @throws alembert::SolveError if A is singular or ill-conditioned (naming the condition
///         estimate), and alembert::ArgumentError if a symbol has no value.
Eigen::VectorXd solve_numeric(const SymbolTable& table, const LinearSystem& sys,
                              const exmap& values);

}  // namespace alembert
