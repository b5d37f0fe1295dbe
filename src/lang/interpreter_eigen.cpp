// SPDX-License-Identifier: MIT
// The eigenvalues and eigenvectors of a matrix of numbers: eig() (Eigen's eigenvalues, a whole
// number kept exact where the characteristic polynomial says so) and eigvec() (for each
// eigenvalue the null space of M - lambda 1, by Eigen's SVD, in a basis fixed by the matrix alone).
#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "alembert/lang/lexer.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

// how a message names the matrix argument `e`: 'M' for a name, else "the matrix"
std::string eigen_matrix_called(const Expr& e) { return e.kind == Expr::Kind::name ? "'" + e.text + "'" : "the matrix"; }

// The canonical basis of the space spanned by the columns of `basis` (n by k, independent):
// the rows of the reduced row echelon form of its transpose (pivots taken left to right),
// made orthonormal in that order by Gram-Schmidt. It depends on the space alone, not on the
// basis given, so that a repeated eigenvalue's eigenvectors do not depend on rounding:
// the plane x + y + z = 0 gives (1, 0, -1)/sqrt 2 and (-1, 2, -1)/sqrt 6.
Eigen::MatrixXd canonical_basis(const Eigen::MatrixXd& basis) {
    Eigen::MatrixXd b = basis.transpose();  // k by n
    const Eigen::Index k = b.rows(), n = b.cols();
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < n && row < k; ++j) {
        Eigen::Index best = row;
        for (Eigen::Index r = row + 1; r < k; ++r)
            if (std::abs(b(r, j)) > std::abs(b(best, j))) best = r;
        if (std::abs(b(best, j)) <= 1e-9) continue;  // no pivot in this column
        b.row(row).swap(b.row(best));
        b.row(row) /= b(row, j);
        for (Eigen::Index r = 0; r < k; ++r)
            if (r != row) b.row(r) -= b(r, j) * b.row(row);
        ++row;
    }
    Eigen::MatrixXd out = b.transpose();  // n by k
    for (Eigen::Index c = 0; c < k; ++c) {
        for (Eigen::Index p = 0; p < c; ++p) out.col(c) -= out.col(p).dot(out.col(c)) * out.col(p);
        out.col(c).normalize();
    }
    return out;
}

// a unit vector's sign fixed: its largest component (by magnitude; the first of several equal
// ones) positive; components within 1e-12 of a whole number (0, 1, -1) taken as that number
void fix_sign(Eigen::Ref<Eigen::VectorXd> v) {
    const double largest = v.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (std::abs(v(i)) >= largest * (1 - 1e-9)) {
            if (v(i) < 0) v = -v;
            break;
        }
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (std::abs(v(i) - std::round(v(i))) <= 1e-12) v(i) = std::round(v(i));
}

}  // namespace

Value Interpreter::Impl::eval_eigen(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    SymbolTable& table = model(e.location).symbols();
    auto guarded = [&](auto&& fn) { return guard(e.location, fn); };
    const std::string form = f + "(M)";
    if (a.size() != 1)
        throw ScriptError(e.location, f + "() takes 1 argument, not " + std::to_string(a.size()), "write " + form);
    Value m = eval(*a[0]);
    if (m.kind == Kind::array) m = matrix_value(1, static_cast<int>(m.a.size()), m.a, m.dim);
    if (m.kind != Kind::matrix)
        throw ScriptError(a[0]->location, f + "() takes a matrix, but this is a " +
                                              std::string(m.kind == Kind::vector ? "vector" : "scalar"),
                          "write " + form + " with a matrix such as [a, b; c, d]");
    const std::string called = eigen_matrix_called(*a[0]);
    if (m.rows != m.cols)
        throw ScriptError(a[0]->location, f + "() takes a square matrix, and " + called + " is " + std::to_string(m.rows) +
                                              " by " + std::to_string(m.cols),
                          "write " + form + " with as many rows as columns");

    // the entries as numbers: constants with values taken, exact while every entry is a fraction
    const std::string hint = f + "() takes a matrix of numbers: give its constants values (constant k = 2) or "
                                 "substitute them with replace()";
    const GiNaC::exmap given = table.constant_values();
    const int n = m.rows;
    std::vector<double> entries;
    bool exact = true;
    for (ex& x : m.a) {
        ex v = guarded([&] { return table.expand_intermediates(x).subs(given, GiNaC::subs_options::no_pattern); });
        if (!GiNaC::is_a<GiNaC::numeric>(v)) v = GiNaC::numeric(guard(a[0]->location, [&] { return table.evaluate(x); }, hint));
        exact = exact && GiNaC::ex_to<GiNaC::numeric>(v).is_rational();
        entries.push_back(GiNaC::ex_to<GiNaC::numeric>(v).to_double());
        x = v;
    }

    // the eigenvalues, ascending (complex ones an error); one next to a whole number that is a
    // root of the exact characteristic polynomial is that number
    std::vector<double> values = real_eigenvalues(entries, n, a[0]->location, f + "(): the eigenvalues of " + called,
                                                  "the script's " + f + "() gives real eigenvalues only");
    if (exact && n <= 12) {
        GiNaC::matrix g(static_cast<unsigned>(n), static_cast<unsigned>(n));
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) g(static_cast<unsigned>(i), static_cast<unsigned>(j)) = m.a[static_cast<std::size_t>(i * n + j)];
        const GiNaC::symbol s("s_eig");
        const ex p = guarded([&] { return g.charpoly(s); });
        for (double& x : values) {
            const double whole = std::round(x);
            if (std::abs(x - whole) <= 1e-9 * std::max(1.0, std::abs(x)) && std::abs(whole) < 1e15 &&
                GiNaC::expand(p.subs(s == GiNaC::numeric(static_cast<long>(whole)))).is_zero())
                x = whole;
        }
    }
    if (f == "eig") return matrix_value(n, 1, number_values(values), m.dim);

    // eigvec: eigenvalues equal to rounding are one, of multiplicity k; its eigenvectors are the
    // right singular vectors of M - lambda 1 for its k smallest singular values, which must
    // all be 0 (to rounding): else the matrix has fewer independent eigenvectors than the
    // eigenvalue's multiplicity (it is defective)
    Eigen::MatrixXd M(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) M(i, j) = entries[static_cast<std::size_t>(i * n + j)];
    const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
    auto defective = [&](double lambda, int k) {
        return ScriptError(a[0]->location,
                           "eigvec(): " + called + " is defective: its eigenvalue " + format_complex(lambda, 0) +
                               ", repeated " + std::to_string(k) + " times, has fewer than " + std::to_string(k) +
                               " independent eigenvectors, so its eigenvectors are no basis",
                           "eig() gives its eigenvalues; a defective matrix has no matrix of eigenvectors");
    };
    Eigen::MatrixXd V(n, n);
    for (int first = 0; first < n;) {
        int last = first + 1;
        while (last < n && std::abs(values[static_cast<std::size_t>(last)] - values[static_cast<std::size_t>(first)]) <= 1e-8 * scale)
            ++last;
        const int k = last - first;
        double lambda = 0;
        for (int i = first; i < last; ++i) lambda += values[static_cast<std::size_t>(i)] / k;
        const Eigen::MatrixXd shifted = M - lambda * Eigen::MatrixXd::Identity(n, n);
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(shifted, Eigen::ComputeFullV);
        // singular values descending: the last k are the null space's
        if (svd.singularValues()(n - k) > 1e-8 * scale * n) throw defective(lambda, k);
        V.middleCols(first, k) = canonical_basis(svd.matrixV().rightCols(k));
        first = last;
    }
    // eigenvalues apart by more than rounding whose eigenvectors are (nearly) parallel: a
    // defective matrix whose repeated eigenvalue rounding has split
    Eigen::JacobiSVD<Eigen::MatrixXd> basis(V);
    if (basis.singularValues()(n - 1) < 1e-6) {
        int i = 0;
        for (int j = 1; j < n; ++j)
            if (std::abs(values[static_cast<std::size_t>(j)] - values[static_cast<std::size_t>(j - 1)]) <
                std::abs(values[static_cast<std::size_t>(i + 1)] - values[static_cast<std::size_t>(i)]))
                i = j - 1;
        throw defective(values[static_cast<std::size_t>(i)], 2);
    }
    std::vector<double> out(static_cast<std::size_t>(n * n));
    for (int j = 0; j < n; ++j) {
        fix_sign(V.col(j));
        for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i * n + j)] = V(i, j);
    }
    return matrix_value(n, n, number_values(out), Dimension::none());
}

}  // namespace alembert::lang
