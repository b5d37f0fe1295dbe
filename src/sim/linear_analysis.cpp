// SPDX-License-Identifier: MIT
// Eigenvalues and stability of a linearization, Ackermann's pole placement, stability changes
// along a parameter.
#include "alembert/sim/linear_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include "alembert/error.hpp"

namespace alembert {

namespace {

bool is_unstable_at(const std::function<Eigen::MatrixXd(double)>& A_of, double p) {
    Eigen::MatrixXd A = A_of(p);
    return classify_stability(calc_eigen(A).values, zero_real_part_tolerance(A)) ==
           Stability::unstable;
}

// the largest real part of the eigenvalues of A(p), and the tolerance below which a real part
// counts as zero there
std::pair<double, double> largest_real_part_at(const std::function<Eigen::MatrixXd(double)>& A_of,
                                               double p) {
    Eigen::MatrixXd A = A_of(p);
    double g = -std::numeric_limits<double>::infinity();
    for (const std::complex<double>& l : calc_eigen(A).values) g = std::max(g, l.real());
    return {g, zero_real_part_tolerance(A)};
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

namespace {

// sigma_min / sigma_max of singular values sorted down; 0 for a zero or empty matrix
double svd_reciprocal_condition(const Eigen::VectorXd& sigma) {
    const Eigen::Index n = sigma.size();
    return n == 0 || !(sigma(0) > 0) ? 0.0 : sigma(n - 1) / sigma(0);
}

}  // namespace

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
    // the reciprocal condition number from the singular values: LU's estimate of it is
    // meaningless for a singular matrix (it reported 2.25 for one of rank 2 in 4)
    const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(C).singularValues();
    const double rcond = svd_reciprocal_condition(sigma);
    if (!(rcond > 1e-12)) {
        Eigen::Index rank = 0;
        for (Eigen::Index i = 0; i < n; ++i)
            if (sigma(i) > 1e-12 * sigma(0)) ++rank;
        std::ostringstream os;
        os << "place_poles(): the input cannot steer every state: the controllability matrix "
              "[b, A b, ...] reaches "
           << rank << " of the " << n << " states (reciprocal condition number " << std::setprecision(3)
           << rcond << ", below 1e-12); choose an input that reaches every state, or fewer states";
        throw SolveError(os.str());
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
    const Eigen::RowVectorXd last_row_of_inverse = lu.inverse().row(n - 1);
    return last_row_of_inverse * phi;
}

namespace {

// |A^T P + P A - P G P + Q|_F relative to the sum of the terms' norms (G = B R^-1 B^T)
double riccati_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& G, const Eigen::MatrixXd& Q,
                        const Eigen::MatrixXd& P) {
    const Eigen::MatrixXd AP = A.transpose() * P, PGP = P * G * P;
    const double scale = 2 * AP.norm() + PGP.norm() + Q.norm();
    const double r = (AP + AP.transpose() - PGP + Q).norm();
    return scale > 0 ? r / scale : r;
}

// P solving Ac^T P + P Ac = -W, through (1 (x) Ac^T + Ac^T (x) 1) vec(P) = -vec(W)
Eigen::MatrixXd solve_lyapunov(const Eigen::MatrixXd& Ac, const Eigen::MatrixXd& W) {
    const Eigen::Index n = Ac.rows();
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n * n, n * n);
    const Eigen::MatrixXd At = Ac.transpose();
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j)
            for (Eigen::Index k = 0; k < n; ++k) {
                L(i * n + k, i * n + j) += At(k, j);  // 1 (x) Ac^T: block i, row k, column j
                L(j * n + k, i * n + k) += At(j, i);  // Ac^T (x) 1: block (j, i) times 1
            }
    Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(W.data(), n * n);
    Eigen::VectorXd p = L.partialPivLu().solve(-w);  // nonsingular: Ac is stable
    Eigen::MatrixXd P = Eigen::Map<Eigen::MatrixXd>(p.data(), n, n);
    return (P + P.transpose()) / 2;
}

}  // namespace

LqrSolution solve_lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                      const Eigen::MatrixXd& R) {
    const Eigen::Index n = A.rows(), m = B.cols();
    if (A.cols() != n || B.rows() != n || Q.rows() != n || Q.cols() != n || R.rows() != m || R.cols() != m ||
        n == 0 || m == 0)
        throw ArgumentError("solve_lqr(): A is " + std::to_string(A.rows()) + " x " + std::to_string(A.cols()) +
                            ", B " + std::to_string(B.rows()) + " x " + std::to_string(B.cols()) + ", Q " +
                            std::to_string(Q.rows()) + " x " + std::to_string(Q.cols()) + " and R " +
                            std::to_string(R.rows()) + " x " + std::to_string(R.cols()) +
                            "; give a square A, B with a row per state, Q n x n and R m x m");
    for (const Eigen::MatrixXd* M : {&A, &B, &Q, &R})
        if (!M->allFinite()) throw ArgumentError("solve_lqr(): a matrix holds a number that is not finite");
    auto symmetric = [](const Eigen::MatrixXd& M) {
        return (M - M.transpose()).norm() <= 1e-12 * std::max(1.0, M.norm());
    };
    if (!symmetric(Q) || !symmetric(R))
        throw ArgumentError("solve_lqr(): Q and R must be symmetric; give weights on the diagonal");
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> qe(Q);
    if (qe.eigenvalues().minCoeff() < -1e-12 * std::max(1.0, Q.norm()))
        throw ArgumentError("solve_lqr(): the state weight Q has a negative eigenvalue (" +
                            std::to_string(qe.eigenvalues().minCoeff()) + "); give weights >= 0");
    Eigen::LLT<Eigen::MatrixXd> rl(R);
    if (rl.info() != Eigen::Success || Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(R).eigenvalues().minCoeff() <= 0)
        throw ArgumentError("solve_lqr(): the input weight R must be positive definite; give weights > 0");
    const Eigen::MatrixXd Rinv_Bt = rl.solve(B.transpose());
    const Eigen::MatrixXd G = B * Rinv_Bt;

    // ---- the stable invariant subspace of the Hamiltonian matrix
    Eigen::MatrixXd H(2 * n, 2 * n);
    H << A, -G, -Q, -A.transpose();
    Eigen::ComplexEigenSolver<Eigen::MatrixXd> es(H);
    if (es.info() != Eigen::Success) throw SolveError("solve_lqr(): the Hamiltonian's eigenvalues did not converge");
    const double tol = zero_real_part_tolerance(H);  // a double eigenvalue blurs by ~sqrt(eps)
    std::vector<Eigen::Index> stable;
    for (Eigen::Index i = 0; i < 2 * n; ++i) {
        const double re = es.eigenvalues()(i).real();
        if (std::abs(re) <= tol) {
            std::ostringstream os;  // real part within tol of 0: printed as 0, not 0.000000 or -1e-17
            os << "solve_lqr(): the Hamiltonian has the eigenvalue 0 " << (es.eigenvalues()(i).imag() < 0 ? "- " : "+ ")
               << std::abs(es.eigenvalues()(i).imag())
               << "i on the imaginary axis: a mode is not stabilisable by the inputs, or Q does "
                  "not weigh an undamped mode; weigh every state in Q or choose other inputs";
            throw SolveError(os.str());
        }
        if (re < 0) stable.push_back(i);
    }
    if (static_cast<Eigen::Index>(stable.size()) != n)
        throw SolveError("solve_lqr(): the Hamiltonian has " + std::to_string(stable.size()) +
                         " stable eigenvalues, not " + std::to_string(n));
    Eigen::MatrixXcd U1(n, n), U2(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        U1.col(j) = es.eigenvectors().col(stable[static_cast<std::size_t>(j)]).head(n);
        U2.col(j) = es.eigenvectors().col(stable[static_cast<std::size_t>(j)]).tail(n);
    }
    Eigen::FullPivLU<Eigen::MatrixXcd> lu(U1);
    // the condition number from the singular values (LU's estimate is meaningless when singular)
    const double rcond_U1 = svd_reciprocal_condition(Eigen::JacobiSVD<Eigen::MatrixXcd>(U1).singularValues());
    if (!lu.isInvertible() || !(rcond_U1 > 1e-12)) {
        std::ostringstream os;
        os << "solve_lqr(): the stable subspace does not determine P (U1 singular, reciprocal condition number "
           << std::setprecision(3) << rcond_U1 << "): (A, B) is not stabilisable";
        throw SolveError(os.str());
    }
    Eigen::MatrixXd P = (U2 * lu.inverse()).real();
    P = (P + P.transpose()) / 2;

    // ---- Newton-Kleinman refinement: K = R^-1 B^T P, then (A - B K)^T P + P (A - B K) = -(Q + K^T R K)
    LqrSolution out;
    double residual = riccati_residual(A, G, Q, P);
    if (n <= 12) {  // the Kronecker form is n^2 x n^2
        for (int step = 0; step < 8 && residual > 1e-15; ++step) {
            const Eigen::MatrixXd K = Rinv_Bt * P;
            Eigen::MatrixXd next = solve_lyapunov(A - B * K, Q + K.transpose() * R * K);
            const double r = riccati_residual(A, G, Q, next);
            if (!(r < residual)) break;
            P = next, residual = r, ++out.newton_steps;
        }
    }
    if (!(residual < 1e-8))
        throw SolveError("solve_lqr(): the Riccati residual is " + std::to_string(residual) +
                         " relative to its terms; the problem is too ill-conditioned (scale the states, or "
                         "weigh them more evenly)");
    out.P = P;
    out.K = Rinv_Bt * P;
    out.relative_residual = residual;
    return out;
}

std::vector<StabilityChange> find_stability_changes(
    const std::function<Eigen::MatrixXd(double)>& A_of, const std::vector<double>& samples) {
    std::vector<StabilityChange> out;
    if (samples.size() < 2) return out;
    std::vector<bool> unstable;
    for (double p : samples) unstable.push_back(is_unstable_at(A_of, p));
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        if (unstable[i] == unstable[i + 1]) continue;
        // ---- bisection on the verdict: lo keeps that of samples[i], hi that of samples[i + 1]
        double lo = samples[i], hi = samples[i + 1];
        const double goal = 1e-12 * (std::abs(lo) + std::abs(hi) + 1);
        for (int it = 0; it < 200 && hi - lo > goal; ++it) {
            const double mid = lo + (hi - lo) / 2;
            if (is_unstable_at(A_of, mid) == unstable[i])
                lo = mid;
            else
                hi = mid;
        }
        double at = lo + (hi - lo) / 2;
        // The verdict changes where the largest real part passes the zero tolerance, not where
        // it is zero: off by tolerance / slope (1e-2 of a damped oscillator's damping, 2.5e-4
        // m/s of a bicycle's capsize speed). On the unstable side the largest real part is the
        // crossing mode's; two values of it there, a little way off, extrapolate linearly to
        // its zero. (A mode on the axis on the stable side, such as an ignorable coordinate's
        // zero eigenvalue, does not disturb this, as a bisection on its sign would be.)
        const double side = unstable[i + 1] ? 1.0 : -1.0;  // towards the unstable side
        const double room = unstable[i + 1] ? samples[i + 1] - at : at - samples[i];
        double h = std::min(room / 6, 1e-4 * (samples[i + 1] - samples[i]));
        // twice: the second time from near the zero with a step a hundred times smaller, which
        // leaves the curvature of the real part out of the answer
        for (int pass = 0; pass < 2 && h > goal; ++pass, h /= 100) {
            // three points, to see the real part is straight there: a pair of real eigenvalues
            // that meet at zero and turn imaginary (x'' = (1 - p) x) vanishes like a square
            // root, and its verdict is already within tolerance^2 of the zero
            const double p1 = at + side * h, p2 = at + 2 * side * h, p3 = at + 3 * side * h;
            const double g1 = largest_real_part_at(A_of, p1).first, g2 = largest_real_part_at(A_of, p2).first,
                         g3 = largest_real_part_at(A_of, p3).first;
            const double slope = (g2 - g1) / (p2 - p1);
            const bool straight = std::abs((g3 - g2) - (g2 - g1)) <= 1e-3 * std::abs(g2 - g1);
            if (!(straight && g1 > 0 && g2 > g1 && std::isfinite(slope) && slope * side > 0)) break;
            const double zero = p1 - g1 / slope;
            if (!(zero >= samples[i] && zero <= samples[i + 1])) break;
            at = zero;
        }
        out.push_back({at, unstable[i + 1]});
    }
    return out;
}

}  // namespace alembert
