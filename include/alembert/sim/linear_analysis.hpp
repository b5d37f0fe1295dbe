// SPDX-License-Identifier: MIT
// Numbers of a linearization x' = A x + B r: eigenvalues and a stability verdict, pole
// placement by Ackermann's formula, and where stability changes along a parameter.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <functional>
#include <vector>

namespace alembert {

/// The eigenvalues and eigenvectors of a real square matrix, in a fixed order: real part
/// descending, then imaginary part descending (a conjugate pair: + before -). Each eigenvector
/// (a column of `vectors`) has unit length and its largest component real and positive, so
/// the same matrix gives the same printout. States with an exactly zero row or column in A
/// (ignorable coordinates, constant speeds) are taken out first with the exact eigenvalue 0,
/// so a chain of them does not blur zero into round-off; each eigenvector is the null
/// direction of A - lambda 1 (a repeated eigenvalue repeats its vector).
struct EigenAnalysis {
    std::vector<std::complex<double>> values{};
    Eigen::MatrixXcd vectors{};
};

/// @throws alembert::ArgumentError if A is not square or holds a non-finite number.
EigenAnalysis calc_eigen(const Eigen::MatrixXd& A);

/// Stability of x' = A x from its eigenvalues.
enum class Stability {
    asymptotically_stable,  ///< every real part below -tol
    marginal,               ///< none above tol, some within tol of zero (linear theory undecided)
    unstable,               ///< some real part above tol
};

/// The tolerance within which a real part counts as zero for A: 1e-6 max(1, |A|_max). A
/// repeated eigenvalue of multiplicity k comes out of floating point with errors near
/// eps^(1/k) |A| (1.5e-8 |A| for a double one), so a tighter bound would call a marginal
/// system unstable.
double zero_real_part_tolerance(const Eigen::MatrixXd& A);

/// The verdict for eigenvalues with the tolerance above.
Stability classify_stability(const std::vector<std::complex<double>>& values, double tol);

/// The gain k (a row, one per state) of the single-input state feedback r = -k x that gives
/// x' = (A - b k) x the characteristic polynomial prod (s - p_i), by Ackermann's formula
/// k = [0 ... 0 1] C^-1 phi(A), C = [b, A b, ..., A^(n-1) b]. Complex poles come in conjugate
/// pairs.
/// @throws alembert::ArgumentError if the sizes do not fit (b one column, one pole per state)
///         or a complex pole has no conjugate; alembert::SolveError if (A, b) is not
///         controllable (C singular: its reciprocal condition number below 1e-12).
Eigen::RowVectorXd place_poles(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                               const std::vector<std::complex<double>>& poles);

/// The linear-quadratic regulator of x' = A x + B r: the state feedback r = -K x that
/// minimises the integral of x^T Q x + r^T R r, with K = R^-1 B^T P and P the stabilising
/// solution of the continuous algebraic Riccati equation
///     A^T P + P A - P B R^-1 B^T P + Q = 0.
struct LqrSolution {
    Eigen::MatrixXd K{};  ///< the gain, one row per input
    Eigen::MatrixXd P{};  ///< the Riccati solution (symmetric, positive semi-definite)
    /// |A^T P + P A - P B R^-1 B^T P + Q|_F over the sum of the terms' norms
    double relative_residual = 0;
    int newton_steps = 0;  ///< Newton-Kleinman refinements taken after the first solution
};

/// Solves the Riccati equation above: P from the stable invariant subspace of the Hamiltonian
/// matrix H = [A, -B R^-1 B^T; -Q, -A^T] (its eigenvectors for the n eigenvalues with negative
/// real part, [U1; U2], P = U2 U1^-1), then refined by Newton-Kleinman steps (each a Lyapunov
/// equation of the closed loop, solved through its Kronecker form, for n <= 12) until the
/// residual stops falling; the relative residual is checked to be below 1e-8. Eigenvalues of H
/// within zero_real_part_tolerance(H) of the imaginary axis are refused.
/// @throws alembert::ArgumentError if the sizes do not fit, Q is not symmetric positive
///         semi-definite or R not symmetric positive definite; alembert::SolveError if H has
///         eigenvalues on the imaginary axis or U1 is singular ((A, B) not stabilisable, or a
///         mode on the imaginary axis that Q does not see), or the residual stays large.
LqrSolution solve_lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                      const Eigen::MatrixXd& R);

/// A change of stability along a parameter p: between two samples of a sweep, found by
/// bisection on "the largest real part is above the tolerance" to within 1e-12 (|p| + 1), then
/// moved to where the crossing mode's real part is zero (not where it passes the tolerance) by
/// linear extrapolation of the largest real part from two points on the unstable side.
struct StabilityChange {
    double at = 0;                  ///< the parameter value where it changes
    bool becomes_unstable = false;  ///< true: stable or marginal below, unstable above
};

/// The parameter values among `samples` (increasing) where x' = A(p) x changes between
/// unstable and not unstable, each found by bisection between the two samples that bracket it.
std::vector<StabilityChange> find_stability_changes(
    const std::function<Eigen::MatrixXd(double)>& A_of, const std::vector<double>& samples);

}  // namespace alembert
