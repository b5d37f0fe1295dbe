// SPDX-License-Identifier: MIT
// Polynomials in one symbol: polynomial() between a list of coefficients and the polynomial,
// and roots(), the eigenvalues of the companion matrix of a polynomial of numbers.
#include <algorithm>
#include <cmath>

#include "alembert/lang/lexer.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

// the coefficients of x^0, x^1, ... of a polynomial in x (no expansion: (1/k!) d^k p/dx^k at 0),
// or nothing if p is not a polynomial in x
std::optional<std::vector<ex>> rising_coefficients(const ex& p, const ex& x) {
    if (!p.is_polynomial(x)) return std::nullopt;
    const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(x);
    std::vector<ex> c;
    ex term = p;
    for (int k = 0; k <= Limits::max_power; ++k) {
        c.push_back(term.subs(x == 0, GiNaC::subs_options::no_pattern) / GiNaC::factorial(k));
        if (!term.has(x)) return c;
        term = term.diff(s);
    }
    return std::nullopt;  // of a higher degree than powers may be written
}

}  // namespace

std::vector<double> real_polynomial_roots(const std::vector<double>& k, Location where, const std::string& what,
                                          const std::string& hint) {
    const int n = static_cast<int>(k.size()) - 1;
    // the companion matrix of x^n + b_(n-1) x^(n-1) + ... + b_0: its eigenvalues are the roots
    std::vector<double> companion(static_cast<std::size_t>(n * n), 0.0);
    for (int i = 1; i < n; ++i) companion[static_cast<std::size_t>(i * n + i - 1)] = 1;
    for (int i = 0; i < n; ++i) companion[static_cast<std::size_t>(i * n + n - 1)] = -k[static_cast<std::size_t>(n - i)] / k[0];
    std::vector<double> r = real_eigenvalues(companion, n, where, what, hint);
    // a Newton step or two on each simple root takes the eigenvalue iteration's rounding off
    auto value = [&](double x, double& slope) {
        double p = 0;
        slope = 0;
        for (double ki : k) slope = slope * x + p, p = p * x + ki;
        return p;
    };
    for (double& x : r)
        for (int it = 0; it < 3; ++it) {
            double slope = 0;
            const double p = value(x, slope);
            if (p == 0 || slope == 0) break;
            const double next = x - p / slope;
            double unused = 0;
            if (std::abs(value(next, unused)) >= std::abs(p)) break;
            x = next;
        }
    // a root next to a whole number that is a root exactly is that number
    for (double& x : r) {
        const double whole = std::round(x);
        double unused = 0;
        if (std::abs(x - whole) <= 1e-9 * std::max(1.0, std::abs(x)) && value(whole, unused) == 0) x = whole;
    }
    return r;
}

Value Interpreter::Impl::eval_polynomial(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    SymbolTable& table = model(e.location).symbols();
    auto guarded = [&](auto&& fn) { return guard(e.location, fn); };
    // a list, or a matrix of one row or column: the coefficients, highest power first
    auto coefficient_list = [&](const Value& v) -> std::optional<std::vector<ex>> {
        if (v.kind == Kind::array) return v.a;
        if (v.kind == Kind::matrix && (v.rows == 1 || v.cols == 1)) return v.a;
        return std::nullopt;
    };

    if (f == "polynomial") {
        // polynomial([c_n, ..., c_0], x) = c_n x^n + ... + c_0; polynomial(p, x): p's list
        const std::string form = "polynomial([1, -3, 2], x) or polynomial(p, x)";
        if (a.size() != 2)
            throw ScriptError(e.location, "polynomial() takes 2 arguments, not " + std::to_string(a.size()), "write " + form);
        Value c = eval(*a[0]);
        Dimension dx;
        const ex x = algebra_symbol(*a[1], f, "the second argument", &dx);
        if (auto list = coefficient_list(c)) {
            ex p = 0;
            for (std::size_t i = 0; i < list->size(); ++i) p += (*list)[i] * GiNaC::pow(x, static_cast<int>(list->size() - 1 - i));
            Value v;
            v.kind = Kind::scalar, v.s = p, v.dim = c.dim;
            return v;
        }
        if (c.kind != Kind::scalar)
            throw ScriptError(a[0]->location, "polynomial() takes a list of coefficients or a polynomial first", "write " + form);
        const ex p = guarded([&] { return table.expand_intermediates(c.s); });
        auto rising = guarded([&] { return rising_coefficients(p, x); });
        const std::string called = a[0]->kind == Expr::Kind::name ? "'" + a[0]->text + "'" : "the expression";
        if (!rising)
            throw ScriptError(a[0]->location,
                              "polynomial(): " + called + " is not a polynomial in '" + table.name(x) + "' of degree at most " +
                                  std::to_string(Limits::max_power),
                              "it holds " + table.name(x) + " inside a function, a root, a denominator or a symbolic power");
        const int n = static_cast<int>(rising->size());
        return matrix_value(1, n, std::vector<ex>(rising->rbegin(), rising->rend()), c.dim);
    }

    // roots(p, x) or roots([c_n, ..., c_0]): the real roots, ascending, as a column
    const std::string form = "roots(p, x) or roots([1, -3, 2])";
    if (a.empty() || a.size() > 2)
        throw ScriptError(e.location, "roots() takes 1 or 2 arguments, not " + std::to_string(a.size()), "write " + form);
    Value c = eval(*a[0]);
    std::vector<ex> falling;
    Dimension dim = Dimension::none();
    std::string x_name = "x";
    if (a.size() == 1) {
        auto list = coefficient_list(c);
        if (!list)
            throw ScriptError(a[0]->location, "roots() with one argument takes the list of coefficients, highest power first",
                              "write " + form);
        falling = *list;
    } else {
        if (c.kind != Kind::scalar)
            throw ScriptError(a[0]->location, "roots(p, x) takes a polynomial first", "write " + form);
        const ex x = algebra_symbol(*a[1], f, "the second argument", &dim);
        x_name = table.name(x);
        const ex p = guarded([&] { return table.expand_intermediates(c.s); });
        auto rising = guarded([&] { return rising_coefficients(p, x); });
        if (!rising)
            throw ScriptError(a[0]->location, "roots(): the expression is not a polynomial in '" + x_name + "'",
                              "it holds " + x_name + " inside a function, a root, a denominator or a symbolic power");
        falling.assign(rising->rbegin(), rising->rend());
    }
    // the coefficients as numbers (constants with values taken), highest power first
    std::vector<double> k;
    for (std::size_t i = 0; i < falling.size(); ++i) {
        const std::size_t power = falling.size() - 1 - i;
        k.push_back(guard(a[0]->location, [&] { return table.evaluate(falling[i]); },
                          "roots() takes a polynomial whose coefficients are numbers: the coefficient of " + x_name +
                              "^" + std::to_string(power) + " is " + to_string(falling[i]) +
                              "; give its constants values or substitute them with replace()"));
        if (!std::isfinite(k.back()))
            throw ScriptError(a[0]->location, "roots(): the coefficient of " + x_name + "^" + std::to_string(power) + " is not finite", "");
    }
    while (!k.empty() && k.front() == 0) k.erase(k.begin());
    if (k.size() < 2)
        throw ScriptError(a[0]->location, "roots(): the polynomial has no roots to find (its degree is 0, or it is 0)",
                          "give a polynomial of degree 1 or more");
    const int n = static_cast<int>(k.size()) - 1;
    std::vector<double> r = real_polynomial_roots(k, a[0]->location, "roots(): the roots", "the script's roots() gives real roots only");
    return matrix_value(n, 1, number_values(r), dim);
}

}  // namespace alembert::lang
