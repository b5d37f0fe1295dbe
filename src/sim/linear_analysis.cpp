// SPDX-License-Identifier: MIT
// Eigenvalues and stability of a linearization, Ackermann's pole placement, stability changes
// along a parameter.
#include "alembert/sim/linear_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "alembert/error.hpp"

namespace alembert {

namespace {

bool is_unstable_at(const std::function<Eigen::MatrixXd(double)>& A_of, double p) {
    Eigen::MatrixXd A = A_of(p);
    return classify_stability(calc_eigen(A).values, zero_real_part_tolerance(A)) ==
           Stability::unstable;
}

}  // namespace

EigenAnalysis calc_eigen(const Eigen::MatrixXd& A) {
    if (A.rows() != A.cols())
        throw ArgumentError("calc_eigen(): the matrix is " + std::to_string(A.rows()) + " x " +
                            std::to_string(A.cols()) + "; eigenvalues need a square matrix");
    if (!A.allFinite())
        throw ArgumentError(
            "calc_eigen(): the matrix holds a number that is not finite; check "
            "the operating point and the constants' values");
    EigenAnalysis out;
    const Eigen::Index n = A.rows();
    if (n == 0) return out;
    // ---- deflation: a state with a zero row or column gives the exact eigenvalue 0 (expand
    // det(lambda 1 - A) along it) and leaves the eigenvalues of the other states
    std::vector<Eigen::Index> kept(static_cast<std::size_t>(n));
    std::iota(kept.begin(), kept.end(), Eigen::Index{0});
    std::vector<std::complex<double>> values;
    for (bool removed = true; removed;) {
        removed = false;
        for (std::size_t a = 0; a < kept.size(); ++a) {
            bool zero_row = true, zero_col = true;
            for (Eigen::Index j : kept) {
                zero_row = zero_row && A(kept[a], j) == 0;
                zero_col = zero_col && A(j, kept[a]) == 0;
            }
            if (zero_row || zero_col) {
                values.emplace_back(0.0, 0.0);
                kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(a));
                removed = true;
                break;
            }
        }
    }
    if (!kept.empty()) {
        const Eigen::Index m = static_cast<Eigen::Index>(kept.size());
        Eigen::MatrixXd R(m, m);
        for (Eigen::Index i = 0; i < m; ++i)
            for (Eigen::Index j = 0; j < m; ++j)
                R(i, j) = A(kept[static_cast<std::size_t>(i)], kept[static_cast<std::size_t>(j)]);
        Eigen::EigenSolver<Eigen::MatrixXd> solver(R, false);
        if (solver.info() != Eigen::Success)
            throw SolveError("calc_eigen(): the eigenvalue iteration did not converge");
        for (Eigen::Index i = 0; i < m; ++i) values.push_back(solver.eigenvalues()(i));
    }
    // ---- order: real part descending, then imaginary part descending
    const double tie = 1e-12 * std::max(1.0, A.cwiseAbs().maxCoeff());
    std::stable_sort(values.begin(), values.end(), [&](const auto& a, const auto& b) {
        if (std::abs(a.real() - b.real()) > tie) return a.real() > b.real();
        return a.imag() > b.imag();
    });
    // ---- eigenvectors: the null direction of A - lambda 1 (its last right singular vector),
    // unit length, largest component real and positive
    const Eigen::MatrixXcd Ac = A.cast<std::complex<double>>();
    out.vectors.resize(n, n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const std::complex<double> l = values[static_cast<std::size_t>(k)];
        Eigen::JacobiSVD<Eigen::MatrixXcd> svd(Ac - l * Eigen::MatrixXcd::Identity(n, n),
                                               Eigen::ComputeFullV);
        Eigen::VectorXcd v = svd.matrixV().col(n - 1);
        Eigen::Index big = 0;
        for (Eigen::Index i = 1; i < n; ++i)
            if (std::abs(v(i)) > std::abs(v(big)) * (1 + 1e-9)) big = i;
        if (std::abs(v(big)) > 0) v *= std::conj(v(big)) / std::abs(v(big));
        const double norm = v.norm();
        if (norm > 0) v /= norm;
        v(big) = std::abs(v(big));
        out.vectors.col(k) = v;
    }
    out.values = std::move(values);
    return out;
}

double zero_real_part_tolerance(const Eigen::MatrixXd& A) {
    return 1e-6 * std::max(1.0, A.size() ? A.cwiseAbs().maxCoeff() : 0.0);
}

Stability classify_stability(const std::vector<std::complex<double>>& values, double tol) {
    bool on_axis = false;
    for (const std::complex<double>& l : values) {
        if (l.real() > tol) return Stability::unstable;
        if (l.real() >= -tol) on_axis = true;
    }
    return on_axis ? Stability::marginal : Stability::asymptotically_stable;
}

Eigen::RowVectorXd place_poles(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                               const std::vector<std::complex<double>>& poles) {
    const Eigen::Index n = A.rows();
    if (A.cols() != n || b.size() != n)
        throw ArgumentError("place_poles(): A is " + std::to_string(A.rows()) + " x " +
                            std::to_string(A.cols()) + " and b has " + std::to_string(b.size()) +
                            " rows; give a square A and one input column with a row per state");
    if (static_cast<Eigen::Index>(poles.size()) != n)
        throw ArgumentError("place_poles(): " + std::to_string(poles.size()) + " poles for " +
                            std::to_string(n) + " states; give one pole per state");
    // ---- the wanted characteristic polynomial s^n + c[n-1] s^(n-1) + ... + c[0]
    for (const std::complex<double>& p : poles) {
        if (p.imag() == 0) continue;
        const auto conj = std::count_if(poles.begin(), poles.end(), [&](const auto& z) {
            return std::abs(z - std::conj(p)) <= 1e-12 * std::max(1.0, std::abs(p));
        });
        const auto same = std::count_if(poles.begin(), poles.end(), [&](const auto& z) {
            return std::abs(z - p) <= 1e-12 * std::max(1.0, std::abs(p));
        });
        if (conj != same)
            throw ArgumentError("place_poles(): the complex pole " + std::to_string(p.real()) +
                                (p.imag() < 0 ? " - " : " + ") +
                                std::to_string(std::abs(p.imag())) +
                                "i has no conjugate; give complex poles in conjugate pairs");
    }
    std::vector<std::complex<double>> c{1.0};  // coefficients, highest power first
    for (const std::complex<double>& p : poles) {
        std::vector<std::complex<double>> next(c.size() + 1, 0.0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i] += c[i];
            next[i + 1] -= p * c[i];
        }
        c = next;
    }
    // ---- phi(A) = A^n + c1 A^(n-1) + ... + cn 1 (Horner)
    Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(n, n);
    for (std::size_t i = 1; i < c.size(); ++i)
        phi = A * phi + c[i].real() * Eigen::MatrixXd::Identity(n, n);
    // ---- controllability matrix and k = e_n^T C^-1 phi(A)
    Eigen::MatrixXd C(n, n);
    Eigen::VectorXd col = b;
    for (Eigen::Index j = 0; j < n; ++j) {
        C.col(j) = col;
        col = A * col;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
    const double rcond = lu.rcond();
    if (!lu.isInvertible() || !(rcond > 1e-12))
        throw SolveError(
            "place_poles(): the input cannot steer every state (the controllability "
            "matrix [b, A b, ...] is singular: reciprocal condition " +
            std::to_string(rcond) + "); choose an input that reaches every state, or fewer states");
    const Eigen::RowVectorXd last_row_of_inverse = lu.inverse().row(n - 1);
    return last_row_of_inverse * phi;
}

std::vector<StabilityChange> find_stability_changes(
    const std::function<Eigen::MatrixXd(double)>& A_of, const std::vector<double>& samples) {
    std::vector<StabilityChange> out;
    if (samples.size() < 2) return out;
    std::vector<bool> unstable;
    for (double p : samples) unstable.push_back(is_unstable_at(A_of, p));
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        if (unstable[i] == unstable[i + 1]) continue;
        // ---- bisection: lo keeps the verdict of samples[i], hi that of samples[i + 1]
        double lo = samples[i], hi = samples[i + 1];
        const double goal = 1e-12 * (std::abs(lo) + std::abs(hi) + 1);
        for (int it = 0; it < 200 && hi - lo > goal; ++it) {
            const double mid = lo + (hi - lo) / 2;
            if (is_unstable_at(A_of, mid) == unstable[i])
                lo = mid;
            else
                hi = mid;
        }
        out.push_back({lo + (hi - lo) / 2, unstable[i + 1]});
    }
    return out;
}

}  // namespace alembert
