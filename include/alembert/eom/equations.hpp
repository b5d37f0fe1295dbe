// SPDX-License-Identifier: MIT
// Equations linear in chosen unknowns: the A x = b form, symbolic and numeric solution.
#pragma once

#include <Eigen/Dense>
#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
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

/// The default of SymbolicSolveOptions::max_terms. Cramer's rule written out is a poor measure
/// of the time GiNaC's normal() takes on the result, but it grows with it: the seed's triple
/// pendulum's road-map for its accelerations (8856 terms) and the four-bar's with a joint force
/// (5082) take from 20 s to many minutes, the rolling disk's Kane equations (4) no time.
inline constexpr double kDefaultMaxSolveTerms = 1000;

/// Options of alembert::solve_symbolic.
struct SymbolicSolveOptions {
    /// The largest expected size (estimate_solution_terms()) a solve may start on; a larger
    /// one is refused before any work. Infinity: no limit.
    double max_terms = kDefaultMaxSolveTerms;
    /// Called at each step with (step, steps): step 0 starts the elimination, step k (1..n)
    /// the simplification of the k-th unknown, step n + 1 = steps ends. The caller shows it
    /// (the lang layer draws a progress line on a terminal); nothing is drawn here.
    std::function<void(std::size_t step, std::size_t steps)> progress{};
};

/// The expected size of the symbolic solution of A x = b: the number of terms Cramer's rule
/// gives written out with no cancellation, det A plus the largest numerator (A with a column
/// replaced by b). With T_ij the terms of A_ij expanded (estimate_expansion_terms, 0 where
/// A_ij = 0) that is perm(T) + max_j perm(T with column j replaced by b's counts), exact for
/// up to 16 unknowns (a sum over column subsets; zeros of A, such as a road-map's triangular
/// order, keep it small); beyond, the bound prod_i (sum_j T_ij + T_ib). Infinity past 1e300.
double estimate_solution_terms(const LinearSystem& sys);

/// Solves A x = b symbolically (fraction-free elimination); each result is simplified.
/// Meant for small systems (a handful of unknowns): sizes grow quickly beyond that, so a
/// system whose expected size (estimate_solution_terms()) passes options.max_terms is refused
/// before any work, and options.progress hears of each step.
/// @throws alembert::SolveError if A is singular (naming the unknowns the equations do not
///         determine when they are consistent), or if the expected size passes the limit
///         (the message names the size and the limit, and suggests solving numerically at
///         given values, generating code, or raising SymbolicSolveOptions::max_terms).
std::vector<ex> solve_symbolic(const LinearSystem& sys, const SymbolicSolveOptions& options = {});

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
