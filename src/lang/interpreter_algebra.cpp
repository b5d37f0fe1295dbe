// SPDX-License-Identifier: MIT
// Algebra inside expressions: coef(), replace(), taylor(), factor(), floor(), exclude() and
// include(), each one GiNaC operation on the value's intermediates written out.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "alembert/lang/lexer.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

// applies `op` to every measure of `v` (a scalar, a vector's or a dyadic's components, an
// array's or a matrix's entries), keeping its kind
Value map_value(Value v, const std::function<ex(const ex&)>& op) {
    if (v.kind == Kind::scalar) v.s = op(v.s);
    else if (v.kind == Kind::vector) v.v = v.v.map(op);
    else if (v.kind == Kind::dyadic) v.d = v.d.map(op);
    else if (v.kind == Kind::array)
        for (ex& s : v.a) s = op(s);
    else {
        std::vector<ex> out;
        out.reserve(v.a.size());
        for (const ex& s : v.a) out.push_back(op(s));
        v = matrix_value(v.rows, v.cols, std::move(out), v.dim);
    }
    return v;
}

// a whole number from 0 to 64 (an order or a power), or an error naming `what` at `e`
int small_order(const Value& v, const Expr& e, const std::string& what) {
    if (v.kind != Kind::scalar || !GiNaC::is_a<GiNaC::numeric>(v.s) ||
        !GiNaC::ex_to<GiNaC::numeric>(v.s).is_integer() || GiNaC::ex_to<GiNaC::numeric>(v.s) < 0 ||
        GiNaC::ex_to<GiNaC::numeric>(v.s) > Limits::max_power)
        throw ScriptError(e.location, what + " must be a whole number from 0 to " + std::to_string(Limits::max_power),
                          "write it as a number, such as 3");
    return GiNaC::ex_to<GiNaC::numeric>(v.s).to_int();
}

}  // namespace

// the declared symbol `e` names (q, q', L), or an error naming the function and its use
ex Interpreter::Impl::algebra_symbol(const Expr& e, const std::string& f, const std::string& role, Dimension* dim) {
    Value x = eval(e);
    SymbolTable& table = model(e.location).symbols();
    if (x.kind != Kind::scalar || !GiNaC::is_a<GiNaC::symbol>(x.s) || !table.owns(x.s))
        throw ScriptError(e.location, f + "(): " + role + " must be a declared symbol",
                          "a coordinate or its rate (q, q', q''), a constant, a specified quantity or an unknown; "
                          "q, q' and q'' are symbols of their own");
    if (dim) *dim = x.dim;
    return x.s;
}

Value Interpreter::Impl::eval_algebra(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    auto guarded = [&](auto&& fn) { return guard(e.location, fn); };
    SymbolTable& table = model(e.location).symbols();
    auto no_binding = [&](std::size_t i, const std::string& form) {
        if (a[i]->kind == Expr::Kind::binding)
            throw ScriptError(a[i]->location, f + "() takes no 'x = v' here", "write " + form);
    };

    if (f == "coef") {
        // the coefficient of x^n in a polynomial in x: (1/n!) d^n e/dx^n at x = 0, exact for
        // polynomials and formed without expanding e
        const std::string form = "coef(e, x), coef(e, x^n), coef(e, x, n) or coef([e1, e2], [x1, x2])";
        if (a.size() != 2 && a.size() != 3)
            throw ScriptError(e.location, "coef() takes 2 or 3 arguments, not " + std::to_string(a.size()),
                              "write " + form);
        for (std::size_t i = 0; i < a.size(); ++i) no_binding(i, form);
        Value x = eval(*a[0]);
        if (x.kind != Kind::scalar && x.kind != Kind::array)
            throw ScriptError(a[0]->location, "coef() takes a scalar or a list of scalars first",
                              x.kind == Kind::vector ? "take a measure first: coef(dot(v>, Nx>), q)" : "");
        std::vector<ex> xs;
        std::vector<Dimension> dims;
        int n = 1;
        const Expr* by = a[1].get();
        if (by->kind == Expr::Kind::list) {
            if (a.size() == 3) throw ScriptError(a[2]->location, "coef() with a list of symbols takes no power",
                                                 "write coef([e1, e2], [x1, x2]) for first powers");
            for (const ExprPtr& s : by->args) {
                Dimension d;
                xs.push_back(algebra_symbol(*s, f, "each symbol of the list", &d));
                dims.push_back(d);
                for (std::size_t k = 0; k + 1 < xs.size(); ++k)
                    if (xs[k].is_equal(xs.back()))
                        throw ScriptError(s->location, "coef(): '" + table.name(xs.back()) + "' is listed twice",
                                          "list each symbol once");
            }
        } else {
            const Expr* base = by;
            if (by->kind == Expr::Kind::power && a.size() == 2) {
                base = by->args[0].get();
                n = small_order(eval(*by->args[1]), *by->args[1], "coef(): the power of x^n");
            } else if (a.size() == 3) {
                n = small_order(eval(*a[2]), *a[2], "coef(): the power n");
            }
            Dimension d;
            xs.push_back(algebra_symbol(*base, f, "the second argument", &d));
            dims.push_back(d);
        }
        const std::vector<ex> es = x.kind == Kind::scalar ? std::vector<ex>{x.s} : x.a;
        std::vector<ex> out;
        out.reserve(es.size() * xs.size());
        for (std::size_t i = 0; i < es.size(); ++i) {
            const ex full = guarded([&] { return table.expand_intermediates(es[i]); });
            for (const ex& s : xs) {
                const GiNaC::symbol& sym = GiNaC::ex_to<GiNaC::symbol>(s);
                if (!guarded([&] { return full.is_polynomial(s); }))
                    throw ScriptError(a[0]->location,
                                      "coef(): " +
                                          (es.size() > 1 ? "element " + std::to_string(i + 1) + " of the list"
                                                         : std::string("the expression")) +
                                          " is not a polynomial in '" + table.name(s) + "': it holds " + table.name(s) +
                                          " inside a function, a root, a denominator or a symbolic power",
                                      "coef() takes coefficients of polynomials; diff(e, " + table.name(s) +
                                          ") is the derivative of any expression");
                out.push_back(guarded([&] {
                    ex c = full.diff(sym, static_cast<unsigned>(n)).subs(s == 0, GiNaC::subs_options::no_pattern);
                    return ex(c / GiNaC::factorial(n));
                }));
            }
        }
        Dimension d = x.dim;
        if (xs.size() == 1) d = x.dim / pow(dims[0], n);
        Value v;
        if (by->kind == Expr::Kind::list)
            return matrix_value(static_cast<int>(es.size()), static_cast<int>(xs.size()), std::move(out),
                                Dimension::open());
        if (x.kind == Kind::array) {
            v.kind = Kind::array, v.a = std::move(out), v.dim = d;
            return v;
        }
        v.kind = Kind::scalar, v.s = out.front(), v.dim = d;
        return v;
    }

    if (f == "replace") {
        // every x replaced by its v at once (GiNaC subs), the intermediates written out first
        if (a.size() < 2)
            throw ScriptError(e.location, "replace() takes the expression and at least one 'x = v'",
                              "write replace(e, q = 0, L = 2*r)");
        Value x = eval(*a[0]);
        if (a[0]->kind == Expr::Kind::binding)
            throw ScriptError(a[0]->location, "replace() takes the expression first", "write replace(e, q = 0)");
        GiNaC::exmap m;
        for (std::size_t i = 1; i < a.size(); ++i) {
            if (a[i]->kind != Expr::Kind::binding)
                throw ScriptError(a[i]->location, "replace() takes 'x = v' after the expression",
                                  "write replace(e, q = 0, L = 2*r)");
            Dimension dx;
            ex s = algebra_symbol(*a[i]->args[0], f, "the left side of 'x = v'", &dx);
            if (m.count(s))
                throw ScriptError(a[i]->args[0]->location, "replace(): '" + table.name(s) + "' is given twice",
                                  "give each symbol one value");
            Value v = eval(*a[i]->args[1]);
            if (v.kind != Kind::scalar)
                throw ScriptError(a[i]->args[1]->location, "replace(): the value of '" + table.name(s) + "' must be a scalar",
                                  "take a measure of a vector: dot(v>, Nx>)");
            check_dimension(v.dim, dx, "the value of '" + table.name(s) + "' in replace()", a[i]->args[1]->location);
            m[s] = v.s;
        }
        return guarded([&] {
            return map_value(x, [&](const ex& s) {
                return table.expand_intermediates(s).subs(m, GiNaC::subs_options::no_pattern);
            });
        });
    }

    if (f == "taylor") {
        // taylor(e, x = x0, ..., n): the Taylor polynomial of total order n about the point:
        // e at x0 + h*(x - x0), ... expanded in h to order n, at h = 1
        const std::string form = "taylor(e, q = 0, 3), taylor(e, q, 0, 3) or taylor(e, x = 0, y = 0, 2)";
        if (a.size() < 3) throw ScriptError(e.location, "taylor() takes 3 or more arguments, not " + std::to_string(a.size()),
                                            "write " + form);
        no_binding(0, form);
        Value x = eval(*a[0]);
        std::vector<std::pair<ex, ex>> at;
        std::vector<const Expr*> where;
        auto add_point = [&](const Expr& sx, const Expr& sv) {
            Dimension dx;
            ex s = algebra_symbol(sx, f, "the variable", &dx);
            for (const auto& [y, _] : at)
                if (y.is_equal(s))
                    throw ScriptError(sx.location, "taylor(): '" + table.name(s) + "' is given twice", "give each variable once");
            Value v = eval(sv);
            if (v.kind != Kind::scalar)
                throw ScriptError(sv.location, "taylor(): the point must be a scalar", "write " + form);
            check_dimension(v.dim, dx, "the point of '" + table.name(s) + "' in taylor()", sv.location);
            at.emplace_back(s, v.s);
            where.push_back(&sx);
        };
        if (a.size() == 4 && a[1]->kind != Expr::Kind::binding) {
            no_binding(2, form);
            add_point(*a[1], *a[2]);
        } else {
            for (std::size_t i = 1; i + 1 < a.size(); ++i) {
                if (a[i]->kind != Expr::Kind::binding)
                    throw ScriptError(a[i]->location, "taylor() takes 'x = x0' before the order", "write " + form);
                add_point(*a[i]->args[0], *a[i]->args[1]);
            }
        }
        no_binding(a.size() - 1, form);
        const int n = small_order(eval(*a.back()), *a.back(), "taylor(): the order");
        const GiNaC::symbol h("h_taylor");
        GiNaC::exmap shift;
        for (const auto& [s, s0] : at) shift[s] = s0 + h * (s - s0);
        auto op = [&](const ex& s) -> ex {
            const ex full = table.expand_intermediates(s).subs(shift, GiNaC::subs_options::no_pattern);
            // the sum of (1/k!) d^k/dh^k at h = 0: diff and subs, linear in the expression's
            // size (GiNaC's series multiplies out products, too slow for equations of motion)
            try {
                ex term = full, sum = 0;
                for (int k = 0; k <= n; ++k) {
                    if (k > 0) term = term.diff(h);
                    sum += term.subs(h == 0, GiNaC::subs_options::no_pattern) / GiNaC::factorial(k);
                }
                return sum;
            } catch (const std::exception&) {
                // a division by zero at the point: a removable singularity (sin(q)/q at 0), a
                // pole or a branch point, which the series tells apart
            }
            ex series;
            try {
                series = full.series(h == 0, n + 1);
            } catch (const std::exception&) {
                // GiNaC divides by zero at a root's or an absolute value's branch point
                throw ScriptError(a[0]->location,
                                  "taylor(): the expression has no Taylor series about this point (a root, an "
                                  "absolute value or a division by zero there)",
                                  "expand about a point where it is smooth");
            }
            if (series.ldegree(h) < 0)
                throw ScriptError(a[0]->location, "taylor(): the expression is singular at this point (it has a pole there)",
                                  "expand about a point where it is finite");
            ex p = GiNaC::series_to_poly(series);
            if (!p.is_polynomial(h))
                throw ScriptError(a[0]->location, "taylor(): the expression has no Taylor series about this point",
                                  "expand about a point where it is smooth");
            return p.subs(h == 1, GiNaC::subs_options::no_pattern);
        };
        return guarded([&] { return map_value(x, op); });
    }

    if (f == "factor") {
        if (a.size() != 1)
            throw ScriptError(e.location, "factor() takes 1 argument, not " + std::to_string(a.size()), "write factor(e)");
        no_binding(0, "factor(e)");
        Value x = eval(*a[0]);
        return guarded([&] {
            return map_value(x, [&](const ex& s) {
                const double terms = estimate_expansion_terms(s);
                if (terms > static_cast<double>(max_terms)) {
                    std::ostringstream t;
                    t << std::setprecision(3) << terms;
                    throw ScriptError(e.location,
                                      "factor(): factoring the expression would expand it to up to " + t.str() +
                                          " terms, more than the limit of " + std::to_string(max_terms),
                                      "factor a smaller expression, or raise the limit with --max-terms N");
                }
                return GiNaC::factor(s);
            });
        });
    }

    if (f == "exclude" || f == "include") {
        // the terms of the expanded expression that hold none (exclude) or at least one
        // (include) of the symbols, a symbol inside a function, a root, a power or a
        // denominator held as well
        const bool keep_holding = f == "include";
        const std::string form = f + "(e, x) or " + f + "(e, x, y, ...)";
        if (a.size() < 2)
            throw ScriptError(e.location, f + "() takes the expression and at least one symbol", "write " + form);
        for (std::size_t i = 0; i < a.size(); ++i) no_binding(i, form);
        Value x = eval(*a[0]);
        std::vector<ex> by;
        for (std::size_t i = 1; i < a.size(); ++i) {
            by.push_back(algebra_symbol(*a[i], f, "each symbol after the expression", nullptr));
            for (std::size_t k = 0; k + 1 < by.size(); ++k)
                if (by[k].is_equal(by.back()))
                    throw ScriptError(a[i]->location, f + "(): '" + table.name(by.back()) + "' is listed twice",
                                      "list each symbol once");
        }
        auto op = [&](const ex& s) -> ex {
            const ex full = table.expand_intermediates(s);
            // the expansion's size is bounded before GiNaC builds it, as expand() does
            const double terms = estimate_expansion_terms(full);
            if (terms > static_cast<double>(max_terms)) {
                std::ostringstream t;
                t << std::setprecision(3) << terms;
                throw ScriptError(e.location,
                                  f + "(): expanding the expression into its terms would form up to " + t.str() +
                                      " terms, more than the limit of " + std::to_string(max_terms),
                                  "take the terms of a smaller expression, or raise the limit with --max-terms N");
            }
            const ex sum = GiNaC::expand(full);
            auto holds = [&](const ex& term) {
                return std::any_of(by.begin(), by.end(), [&](const ex& y) { return term.has(y); });
            };
            if (!GiNaC::is_a<GiNaC::add>(sum)) return holds(sum) == keep_holding ? sum : ex(0);
            GiNaC::exvector kept;
            for (const ex& term : sum)
                if (holds(term) == keep_holding) kept.push_back(term);
            return GiNaC::add(kept);
        };
        return guarded([&] { return map_value(x, op); });
    }

    // floor: a number's; a symbol's floor has no derivative and no counterpart in the equations
    if (a.size() != 1)
        throw ScriptError(e.location, "floor() takes 1 argument, not " + std::to_string(a.size()), "write floor(x)");
    no_binding(0, "floor(x)");
    Value x = eval(*a[0]);
    if (x.kind != Kind::scalar) throw ScriptError(a[0]->location, "floor() takes a scalar", "");
    check_dimension(x.dim, Dimension::none(), "the argument of floor()", a[0]->location);
    ex n = guarded([&] { return GiNaC::evalf(table.expand_intermediates(x.s)); });
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real()) {
        // the symbols named (a few, in the table's order of names), not the whole expression
        std::vector<std::string> held;
        for (const ex& y : symbols_of(table.expand_intermediates(x.s)))
            if (table.owns(y)) held.push_back(table.name(y));
        std::sort(held.begin(), held.end());
        std::string list;
        for (std::size_t i = 0; i < held.size() && i < 5; ++i) list += (i ? ", " : "") + held[i];
        if (held.size() > 5) list += ", ...";
        if (list.empty()) list = "a value that is not a real number";
        throw ScriptError(a[0]->location, "floor() takes a number, but this holds " + list,
                          "floor() is a step of the numbers only; evaluate the expression first (replace(e, q = 1)), "
                          "or give the constants as numbers");
    }
    if (GiNaC::is_a<GiNaC::numeric>(x.s) && GiNaC::ex_to<GiNaC::numeric>(x.s).is_rational()) {
        // exact: numerator over denominator rounded down
        const GiNaC::numeric& r = GiNaC::ex_to<GiNaC::numeric>(x.s);
        GiNaC::numeric q = GiNaC::iquo(r.numer(), r.denom());
        if (r.is_negative() && !r.is_integer()) q = q - 1;
        x.s = q;
        return x;
    }
    const double d = GiNaC::ex_to<GiNaC::numeric>(n).to_double();
    if (!(std::abs(d) < 1e15))
        throw ScriptError(a[0]->location, "floor(): the number is too large to round down exactly", "");
    x.s = GiNaC::numeric(static_cast<long>(std::floor(d)));
    return x;
}

}  // namespace alembert::lang
