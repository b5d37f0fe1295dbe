// SPDX-License-Identifier: MIT
// Matrices as values: their arithmetic (M + N, c*M, M*N) and transpose(), inv(), det(),
// diagmat(), element(), rows(), cols() (GiNaC matrix operations).
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "alembert/lang/lexer.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

GiNaC::matrix ginac_matrix(const Value& m) {
    GiNaC::matrix g(static_cast<unsigned>(m.rows), static_cast<unsigned>(m.cols));
    for (int i = 0; i < m.rows; ++i)
        for (int j = 0; j < m.cols; ++j) g(static_cast<unsigned>(i), static_cast<unsigned>(j)) = m.a[static_cast<std::size_t>(i * m.cols + j)];
    return g;
}

Value from_ginac(const GiNaC::matrix& g, Dimension dim) {
    std::vector<ex> out;
    out.reserve(g.rows() * g.cols());
    for (unsigned i = 0; i < g.rows(); ++i)
        for (unsigned j = 0; j < g.cols(); ++j) out.push_back(g(i, j));
    return matrix_value(static_cast<int>(g.rows()), static_cast<int>(g.cols()), std::move(out), dim);
}

std::string size_text(const Value& m) { return std::to_string(m.rows) + " by " + std::to_string(m.cols); }

// how a message names the matrix argument `e`: 'M' for a name, else "the matrix"
std::string matrix_called(const Expr& e) { return e.kind == Expr::Kind::name ? "'" + e.text + "'" : "the matrix"; }

// a whole number from lo to hi given by `v`, or an error naming `what` at `e`
int whole_in(const Value& v, const Expr& e, int lo, int hi, const std::string& what) {
    if (v.kind != Kind::scalar || !GiNaC::is_a<GiNaC::numeric>(v.s) || !GiNaC::ex_to<GiNaC::numeric>(v.s).is_integer() ||
        GiNaC::ex_to<GiNaC::numeric>(v.s) < lo || GiNaC::ex_to<GiNaC::numeric>(v.s) > hi)
        throw ScriptError(e.location, what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi),
                          "write it as a number, such as 2");
    return GiNaC::ex_to<GiNaC::numeric>(v.s).to_int();
}

}  // namespace

std::vector<ex> number_values(const std::vector<double>& xs) {
    std::vector<ex> out;
    for (double x : xs)
        out.push_back(x == std::round(x) && std::abs(x) < 1e15 ? ex(GiNaC::numeric(static_cast<long>(x))) : ex(GiNaC::numeric(x)));
    return out;
}

std::string format_complex(double re, double im) {
    auto num = [](double x) {
        std::ostringstream o;
        o.precision(6);
        o << x;
        return o.str();
    };
    if (im == 0) return num(re);
    return num(re) + (im < 0 ? " - " : " + ") + num(std::abs(im)) + "i";
}

std::vector<double> real_eigenvalues(const std::vector<double>& entries, int n, Location where, const std::string& what,
                                     const std::string& hint) {
    Eigen::MatrixXd m(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m(i, j) = entries[static_cast<std::size_t>(i * n + j)];
    Eigen::EigenSolver<Eigen::MatrixXd> solver(m, false);
    if (solver.info() != Eigen::Success)
        throw ScriptError(where, what + ": the eigenvalue iteration did not converge", hint);
    std::vector<std::complex<double>> z;
    for (int i = 0; i < n; ++i) z.push_back(solver.eigenvalues()(i));
    // a conjugate pair keeps its imaginary parts; rounding leaves ~1e-16 on real values
    const double scale = std::max(1.0, m.cwiseAbs().maxCoeff());
    std::vector<double> real;
    std::vector<std::string> complex;
    std::sort(z.begin(), z.end(), [](auto x, auto y) { return x.real() != y.real() ? x.real() < y.real() : x.imag() < y.imag(); });
    for (const auto& x : z) {
        if (std::abs(x.imag()) <= 1e-12 * scale) real.push_back(x.real());
        else complex.push_back(format_complex(x.real(), x.imag()));
    }
    if (!complex.empty()) {
        std::string list;
        for (std::size_t i = 0; i < complex.size(); ++i) list += (i ? ", " : "") + complex[i];
        throw ScriptError(where, what + " are complex: " + list + "; the script's values are real numbers", hint);
    }
    return real;
}

// a list [a, b, c] beside a matrix is a row
static Value as_row(Value v) {
    if (v.kind != Kind::array) return v;
    const int n = static_cast<int>(v.a.size());
    return matrix_value(1, n, std::move(v.a), v.dim);
}

Value Interpreter::Impl::matrix_sum(Value acc, const Value& given, bool subtract, Location where) {
    acc = as_row(std::move(acc));
    const Value v = as_row(given);
    if (acc.kind != Kind::matrix || v.kind != Kind::matrix) {
        auto word = [](Kind k) {
            return k == Kind::matrix ? "a matrix" : k == Kind::vector ? "a vector" : k == Kind::array ? "an array"
                                                  : k == Kind::dyadic ? "a dyadic" : "a scalar";
        };
        throw ScriptError(where, std::string("cannot add ") + word(v.kind) + " to " + word(acc.kind),
                          "add matrices of the same size; diagmat(n, x) is x times the n by n identity");
    }
    if (acc.rows != v.rows || acc.cols != v.cols)
        throw ScriptError(where, "cannot add a " + size_text(v) + " matrix to a " + size_text(acc) + " matrix",
                          "matrices added must have the same size");
    if (v.dim.conflicts(acc.dim))
        throw ScriptError(where, "cannot add " + describe(v.dim) + " to " + describe(acc.dim),
                          "the terms of a sum must have the same dimension; check the units");
    if (!acc.dim.known) acc.dim = v.dim;
    for (std::size_t k = 0; k < acc.a.size(); ++k) acc.a[k] = subtract ? acc.a[k] - v.a[k] : acc.a[k] + v.a[k];
    return matrix_value(acc.rows, acc.cols, std::move(acc.a), acc.dim);
}

Value Interpreter::Impl::matrix_product(Value acc, const Value& given, bool divide, Location where) {
    acc = as_row(std::move(acc));
    const Value v = as_row(given);
    if (acc.kind == Kind::vector || v.kind == Kind::vector)
        throw ScriptError(where, "cannot multiply a matrix and a vector",
                          "multiply matrices by matrices or scalars: write the vector's measures as a column [x; y; z]");
    if (divide) {
        if (v.kind == Kind::matrix)
            throw ScriptError(where, "cannot divide by a matrix", "multiply by its inverse: A*inv(B)");
        if (v.s.is_zero()) throw ScriptError(where, "division by zero", "");
        for (ex& x : acc.a) x = x / v.s;
        return matrix_value(acc.rows, acc.cols, std::move(acc.a), acc.dim / v.dim);
    }
    const Dimension d = acc.dim * v.dim;
    if (acc.kind == Kind::scalar || v.kind == Kind::scalar) {
        const Value& m = acc.kind == Kind::matrix ? acc : v;
        const ex& c = acc.kind == Kind::scalar ? acc.s : v.s;
        std::vector<ex> out;
        out.reserve(m.a.size());
        for (const ex& x : m.a) out.push_back(c * x);
        return matrix_value(m.rows, m.cols, std::move(out), d);
    }
    if (acc.cols != v.rows)
        throw ScriptError(where,
                          "cannot multiply a " + size_text(acc) + " matrix by a " + size_text(v) +
                              " matrix: the first's columns must match the second's rows",
                          "transpose(M) turns rows into columns");
    return from_ginac(ginac_matrix(acc).mul(ginac_matrix(v)), d);
}

Value Interpreter::Impl::matrix_power(const Value& m, const Value& p, const Expr& base, const Expr& exponent) {
    check_dimension(p.dim, Dimension::none(), "an exponent", exponent.location);
    const ex k_ex = p.s;
    if (!GiNaC::is_a<GiNaC::numeric>(k_ex) || !GiNaC::ex_to<GiNaC::numeric>(k_ex).is_integer())
        throw ScriptError(exponent.location, "a power of a matrix takes a whole number, not " + to_string(k_ex),
                          "write M^2, M^0 or M^-1");
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(k_ex);
    if (GiNaC::abs(n) > Limits::max_power)
        throw ScriptError(exponent.location, "the power " + to_string(k_ex) + " is too large (the limit is 64)", "");
    if (m.rows != m.cols)
        throw ScriptError(base.location, "a power of a matrix takes a square matrix, and " + matrix_called(base) +
                                             " is " + size_text(m),
                          "multiply matrices whose sizes fit with '*'");
    const int k = n.to_int();
    const auto size = static_cast<unsigned>(m.rows);
    GiNaC::matrix g = ginac_matrix(m);
    Dimension d = m.dim;
    if (k < 0) {
        SymbolTable& table = model(base.location).symbols();
        std::vector<ex> entries = m.a;
        for (ex& x : entries) x = guard(base.location, [&] { return table.expand_intermediates(x); });
        g = ginac_matrix(matrix_value(m.rows, m.cols, entries, m.dim));
        if (guard(base.location, [&] { return GiNaC::normal(g.determinant()); }).is_zero())
            throw ScriptError(base.location, "a negative power of " + matrix_called(base) +
                                                 " needs its inverse, and it is singular (its determinant is 0)",
                              "check its rows for a dependence");
        g = guard(base.location, [&] {
            GiNaC::matrix inv = g.inverse();
            for (unsigned i = 0; i < inv.rows(); ++i)
                for (unsigned j = 0; j < inv.cols(); ++j) inv(i, j) = GiNaC::normal(inv(i, j));
            return inv;
        });
        d = Dimension::none() / m.dim;
    }
    // by squaring: |k| <= 64 takes at most 12 products
    GiNaC::matrix result = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(size));
    GiNaC::matrix square = g;
    for (unsigned left = static_cast<unsigned>(k < 0 ? -k : k); left > 0; left >>= 1) {
        if (left & 1u) result = result.mul(square);
        if (left > 1) square = square.mul(square);
    }
    return from_ginac(result, k == 0 ? Dimension::none() : pow(d, k < 0 ? -k : k));
}

Value Interpreter::Impl::eval_matrix(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    SymbolTable& table = model(e.location).symbols();
    auto guarded = [&](auto&& fn) { return guard(e.location, fn); };
    auto want = [&](std::size_t lo, std::size_t hi, const std::string& form) {
        if (a.size() < lo || a.size() > hi)
            throw ScriptError(e.location,
                              f + "() takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                                  " argument" + (hi == 1 ? "" : "s") + ", not " + std::to_string(a.size()),
                              "write " + form);
    };
    // the matrix argument i (an array [a, b] is a row)
    auto matrix_arg = [&](std::size_t i, const std::string& form) {
        Value m = eval(*a[i]);
        if (m.kind == Kind::array) return matrix_value(1, static_cast<int>(m.a.size()), m.a, m.dim);
        if (m.kind != Kind::matrix)
            throw ScriptError(a[i]->location, f + "() takes a matrix, but this is a " +
                                                  std::string(m.kind == Kind::vector ? "vector" : m.kind == Kind::dyadic ? "dyadic" : "scalar"),
                              m.kind == Kind::dyadic ? "take the dyadic's matrix in a frame: matrix(N, D>>)"
                                                     : "write " + form + " with a matrix such as [a, b; c, d]");
        return m;
    };
    auto square = [&](const Value& m, const std::string& form) {
        if (m.rows != m.cols)
            throw ScriptError(a[0]->location, f + "() takes a square matrix, and " + matrix_called(*a[0]) + " is " + size_text(m),
                              "write " + form + " with as many rows as columns");
    };

    if (f == "transpose") {
        want(1, 1, "transpose(M)");
        Value m = matrix_arg(0, "transpose(M)");
        std::vector<ex> out;
        out.reserve(m.a.size());
        for (int j = 0; j < m.cols; ++j)
            for (int i = 0; i < m.rows; ++i) out.push_back(m.a[static_cast<std::size_t>(i * m.cols + j)]);
        return matrix_value(m.cols, m.rows, std::move(out), m.dim);
    }
    if (f == "det" || f == "inv") {
        want(1, 1, f + "(M)");
        Value m = matrix_arg(0, f + "(M)");
        square(m, f + "(M)");
        for (ex& x : m.a) x = guarded([&] { return table.expand_intermediates(x); });
        const GiNaC::matrix g = ginac_matrix(m);
        // the determinant, brought to a normal form so that a singular matrix shows as 0
        const ex d = guarded([&] { return GiNaC::normal(g.determinant()); });
        if (f == "det") {
            Value v;
            v.kind = Kind::scalar, v.s = d, v.dim = pow(m.dim, m.rows);
            return v;
        }
        if (d.is_zero())
            throw ScriptError(a[0]->location, "inv(): " + matrix_called(*a[0]) + " is singular (its determinant is 0), so it has no inverse",
                              "check its rows for a dependence; solve ... for ... finds what a singular system determines");
        return guarded([&] {
            GiNaC::matrix inv = g.inverse();
            for (unsigned i = 0; i < inv.rows(); ++i)
                for (unsigned j = 0; j < inv.cols(); ++j) inv(i, j) = GiNaC::normal(inv(i, j));
            return from_ginac(inv, Dimension::none() / m.dim);
        });
    }
    if (f == "diagmat") {
        // diagmat(n, x), diagmat(n, m, x): x on the diagonal of n by m; diagmat([a, b, c])
        const std::string form = "diagmat(n, x), diagmat(n, m, x) or diagmat([a, b, c])";
        want(1, 3, form);
        if (a.size() == 1) {
            Value l = eval(*a[0]);
            if (l.kind == Kind::matrix && (l.rows == 1 || l.cols == 1)) l.kind = Kind::array;
            if (l.kind != Kind::array)
                throw ScriptError(a[0]->location, "diagmat() with one argument takes the list of the diagonal", "write " + form);
            const int n = static_cast<int>(l.a.size());
            std::vector<ex> out(static_cast<std::size_t>(n * n), ex(0));
            for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i * n + i)] = l.a[static_cast<std::size_t>(i)];
            return matrix_value(n, n, std::move(out), l.dim);
        }
        const int n = whole_in(eval(*a[0]), *a[0], 1, 100, "diagmat(): the number of rows");
        const int cols = a.size() == 3 ? whole_in(eval(*a[1]), *a[1], 1, 100, "diagmat(): the number of columns") : n;
        Value x = eval(*a.back());
        if (x.kind != Kind::scalar)
            throw ScriptError(a.back()->location, "diagmat(): the diagonal's value must be a scalar", "write " + form);
        std::vector<ex> out(static_cast<std::size_t>(n * cols), ex(0));
        for (int i = 0; i < std::min(n, cols); ++i) out[static_cast<std::size_t>(i * cols + i)] = x.s;
        return matrix_value(n, cols, std::move(out), x.s.is_zero() ? Dimension::open() : x.dim);
    }
    if (f == "element") {
        want(3, 3, "element(M, i, j)");
        Value m = matrix_arg(0, "element(M, i, j)");
        const int i = whole_in(eval(*a[1]), *a[1], 1, m.rows, "element(): the row of " + matrix_called(*a[0]));
        const int j = whole_in(eval(*a[2]), *a[2], 1, m.cols, "element(): the column of " + matrix_called(*a[0]));
        Value v;
        v.kind = Kind::scalar, v.s = m.a[static_cast<std::size_t>((i - 1) * m.cols + j - 1)], v.dim = m.dim;
        return v;
    }
    // rows(M): how many; rows(M, i, ...): those rows as a matrix (cols: those columns)
    const bool by_row = f == "rows";
    const std::string form = f + "(M) or " + f + "(M, i, ...)";
    if (a.empty()) want(1, 1, form);
    Value m = matrix_arg(0, form);
    if (a.size() == 1) {
        Value v;
        v.kind = Kind::scalar, v.s = by_row ? m.rows : m.cols, v.dim = Dimension::none();
        return v;
    }
    const int n = by_row ? m.rows : m.cols;
    std::vector<int> picked;
    for (std::size_t k = 1; k < a.size(); ++k)
        picked.push_back(whole_in(eval(*a[k]), *a[k], 1, n,
                                  f + "(): the " + (by_row ? "row" : "column") + " of " + matrix_called(*a[0])) -
                         1);
    std::vector<ex> out;
    const int count = static_cast<int>(picked.size());
    if (by_row) {
        for (int r : picked)
            for (int j = 0; j < m.cols; ++j) out.push_back(m.a[static_cast<std::size_t>(r * m.cols + j)]);
        return matrix_value(count, m.cols, std::move(out), m.dim);
    }
    for (int i = 0; i < m.rows; ++i)
        for (int c : picked) out.push_back(m.a[static_cast<std::size_t>(i * m.cols + c)]);
    return matrix_value(m.rows, count, std::move(out), m.dim);
}

}  // namespace alembert::lang
