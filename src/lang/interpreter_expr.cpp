// SPDX-License-Identifier: MIT
// Expressions: values, dimension checks, functions and the monogram names of kinematic calls.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "alembert/lang/lexer.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

const char* kind_name(Value::Kind k) {
    switch (k) {
        case Value::Kind::scalar: return "a scalar";
        case Value::Kind::vector: return "a vector";
        case Value::Kind::array: return "an array";
        case Value::Kind::matrix: return "a matrix";
        case Value::Kind::dyadic: return "a dyadic";
    }
    return "a value";
}

namespace {

using Kind = Value::Kind;

Value scalar_value(const ex& s, Dimension d) {
    Value v;
    v.kind = Kind::scalar, v.s = s, v.dim = d;
    return v;
}

Value vector_value(const Vector& x, Dimension d) {
    Value v;
    v.kind = Kind::vector, v.v = x, v.dim = d;
    return v;
}

const Dimension kL = Dimension::length(), kM = Dimension::mass(), kT = Dimension::time();

// the 1-based index `e` names, checked against 1..n
std::size_t index_in(Interpreter::Impl& m, const Expr& e, std::size_t n, const std::string& of, const char* what) {
    Value i = m.eval(e);
    if (i.kind != Kind::scalar || !GiNaC::is_a<GiNaC::numeric>(i.s) || !GiNaC::ex_to<GiNaC::numeric>(i.s).is_integer())
        throw ScriptError(e.location, "an index must be a whole number", "");
    const auto& k = GiNaC::ex_to<GiNaC::numeric>(i.s);
    if (k < 1 || k > static_cast<long>(n))
        throw ScriptError(e.location,
                          "index " + to_string(i.s) + " is out of range: " + of + " has " + std::to_string(n) + " " + what,
                          "indices start at 1");
    return static_cast<std::size_t>(k.to_int() - 1);
}

}  // namespace

Value matrix_value(int rows, int cols, std::vector<ex> entries, Dimension dim) {
    Value v;
    v.kind = Kind::matrix;
    v.rows = rows, v.cols = cols;
    v.a = std::move(entries);
    v.dim = dim;
    if (rows == 3 && cols == 3)
        for (int i = 0; i < 9; ++i) v.m(i / 3, i % 3) = v.a[static_cast<std::size_t>(i)];
    return v;
}

void Interpreter::Impl::check_dimension(const Dimension& got, const Dimension& expected,
                                        const std::string& what, Location where) const {
    if (!got.conflicts(expected)) return;
    // a bare number wants a unit; a quantity of another dimension, a factor
    std::string hint = "check the units of the quantities in it";
    if (got.is_none() && expected.known && !expected.is_none())
        hint = "give its numbers units so that it comes out in " + si_unit(expected) + " (e.g. 2 " +
               si_unit(expected) + ")";
    throw ScriptError(where, what + " must be " + describe(expected) + ", but this is " + describe(got), hint);
}

ex Interpreter::Impl::scalar(const Expr& e, const Dimension& expected, const std::string& what) {
    Value v = eval(e);
    if (v.kind != Kind::scalar)
        throw ScriptError(e.location, what + " must be a scalar, but this is " + kind_name(v.kind),
                          v.kind == Kind::vector   ? "take a measure with dot(v>, Nx>) or mag(v>)"
                          : v.kind == Kind::dyadic ? "take a measure with dot(Nx>, D>>, Ny>)"
                                                   : "");
    check_dimension(v.dim, expected, what, e.location);
    return v.s;
}

Vector Interpreter::Impl::vector(const Expr& e, const Dimension& expected, const std::string& what) {
    Value v = eval(e);
    if (v.kind == Kind::scalar && v.s.is_zero()) return Vector();
    if (v.kind != Kind::vector)
        throw ScriptError(e.location, what + " must be a vector, but this is " + kind_name(v.kind),
                          v.kind == Kind::dyadic
                              ? "dot the dyadic with a vector: dot(D>>, v>)"
                              : "multiply by a unit vector such as Nx>, or write 0> for the zero vector");
    check_dimension(v.dim, expected, what, e.location);
    return v.v;
}

std::vector<ex> Interpreter::Impl::array(const Expr& e, const std::string& what) {
    Value v = eval(e);
    if (v.kind == Kind::scalar) return {v.s};
    if (v.kind != Kind::array)
        throw ScriptError(e.location, what + " must be a list of scalars [a, b, ...]", "");
    return v.a;
}

bool carries_unit(const Expr& e) {
    if (e.kind == Expr::Kind::number) return !e.unit.empty();
    for (const ExprPtr& a : e.args)
        if (a && carries_unit(*a)) return true;
    return false;
}

namespace {

// a rate in a unit that counts revolutions (1 Hz = 1 rev/s = 2*pi rad/s, 1 rpm = 2*pi/60 rad/s)
bool counts_revolutions(const UnitText& u) {
    bool rev = false, per = false;
    for (const UnitText::Factor& f : u.factors) {
        if (f.name.text == "Hz" || f.name.text == "rpm") return true;
        rev = rev || f.name.text == "rev";
        per = per || f.power < 0;
    }
    return rev && per;
}

bool holds_pi(const Expr& e) {
    if (e.kind == Expr::Kind::name && e.text == "pi") return true;
    return std::any_of(e.args.begin(), e.args.end(), [](const ExprPtr& a) { return a && holds_pi(*a); });
}

}  // namespace

const Expr* Interpreter::Impl::revolution_rate_in(const Expr& e) const {
    if (e.kind == Expr::Kind::number && counts_revolutions(e.unit)) return &e;
    if (e.kind == Expr::Kind::name) {
        const std::size_t p = e.text.find('\'');
        auto it = units.find(e.text.substr(0, p));
        if (it != units.end() && it->second.display) {
            const std::string& t = it->second.display->text;
            if (t.find("Hz") != std::string::npos || t.find("rpm") != std::string::npos ||
                t.find("rev/") != std::string::npos)
                return &e;
        }
    }
    for (const ExprPtr& a : e.args)
        if (const Expr* r = a ? revolution_rate_in(*a) : nullptr) return r;
    return nullptr;
}

Value Interpreter::Impl::number_with_unit(const Expr& e, const ex& n) {
    // a unit name joined by * or / that is also a name of the script is ambiguous: refuse it
    // rather than guess (2 kg*g: grams, or the constant g?)
    for (std::size_t i = 1; i < e.unit.factors.size(); ++i) {
        const Word& w = e.unit.factors[i].name;
        bool declared = values.count(w.text) || names.count(w.text) ||
                        (sys && sys->symbols().contains(w.text));
        if (!declared) continue;
        Unit u = *find_unit(w.text);
        throw ScriptError(w.location,
                          "'" + w.text + "' after the number " + e.number_text +
                              " reads as the unit " + u.text + " (" + describe(u.dimension) + "), but '" + w.text +
                              "' is also a name of this script",
                          "for the name, close the number's unit with parentheses: (" + e.number_text +
                              " " + e.unit.factors[0].name.text + ")*" + w.text +
                              "; for the unit, give the value a name: constant c = " + e.number_text +
                              " " + e.unit.factors[0].name.text + "*" + w.text);
    }
    Unit u = parse_unit(e.unit);
    // exact while the unit is SI (2 kg stays 2); a scaled unit multiplies by its factor
    ex value = u.scale == 1 ? n : ex(n * GiNaC::numeric(u.scale));
    return scalar_value(value, u.dimension);
}

Value Interpreter::Impl::eval_name(const Expr& e) {
    const std::string& n = e.text;
    auto it = values.find(n);
    if (it != values.end()) return it->second;
    if (n == "t") return scalar_value(model(e.location).symbols().time(), kT);
    if (n == "pi") return scalar_value(GiNaC::Pi, Dimension::none());
    if (sys && sys->symbols().contains(n)) return scalar_value(sys->symbols().symbol(n), symbol_dimension(n));
    auto kn = names.find(n);
    if (kn != names.end())
        throw ScriptError(e.location, "'" + n + "' is not a number or an array, so it cannot stand here",
                          "frames, bodies and points appear as arguments, e.g. vel(" + n + ", N)");
    undeclared({n, e.location}, "a symbol or value");
}

Value Interpreter::Impl::eval_vector_name(const Expr& e) {
    const std::string& n = e.text;
    auto it = values.find(n + ">");
    if (it != values.end()) return it->second;
    if (n.size() >= 2) {
        char axis = n.back();
        std::string f = n.substr(0, n.size() - 1);
        auto kn = names.find(f);
        if ((axis == 'x' || axis == 'y' || axis == 'z') && kn != names.end() &&
            (kn->second.kind == NameKind::frame || kn->second.kind == NameKind::body)) {
            Frame& F = frame({f, e.location});
            return vector_value(F.unit(axis == 'x' ? Axis::x : axis == 'y' ? Axis::y : Axis::z),
                                Dimension::none());
        }
    }
    throw ScriptError(e.location, "the vector '" + n + ">' is not defined",
                      "unit vectors are a frame or body name followed by x, y or z (Nx>); other "
                      "vectors must be assigned first (r> = ...)");
}

Value Interpreter::Impl::eval(const Expr& e) {
    switch (e.kind) {
        case Expr::Kind::number: {
            bool whole = e.number_text.find_first_of(".eE") == std::string::npos;
            ex n = whole ? ex(GiNaC::numeric(e.number_text.c_str())) : ex(GiNaC::numeric(e.number));
            if (!e.unit.empty()) return number_with_unit(e, n);
            // zero has every dimension (0 N*m is 0 m); other numbers are dimensionless
            return scalar_value(n, n.is_zero() ? Dimension::open() : Dimension::none());
        }
        case Expr::Kind::name: return eval_name(e);
        case Expr::Kind::vector_name: return eval_vector_name(e);
        case Expr::Kind::zero_vector: return vector_value(Vector(), Dimension::open());
        case Expr::Kind::dyadic_name: return eval_dyadic_name(e);
        case Expr::Kind::negate: {
            Value v = eval(*e.args[0]);
            if (v.kind == Kind::scalar) v.s = -v.s;
            else if (v.kind == Kind::vector) v.v = -v.v;
            else if (v.kind == Kind::dyadic) v.d = ex(-1) * v.d;
            else if (v.kind == Kind::matrix) {
                for (ex& x : v.a) x = -x;
                v = matrix_value(v.rows, v.cols, std::move(v.a), v.dim);
            } else throw ScriptError(e.location, std::string("cannot negate ") + kind_name(v.kind), "");
            return v;
        }
        case Expr::Kind::sum: {
            Value acc;
            for (std::size_t i = 0; i < e.args.size(); ++i) {
                Value v = eval(*e.args[i]);
                Location where = e.args[i]->location;
                if (v.kind == Kind::dyadic || (i > 0 && acc.kind == Kind::dyadic)) {
                    if (i == 0) acc = e.inverted[0] ? dyadic_product(v, scalar_value(-1, Dimension::none()), false, where) : v;
                    else acc = dyadic_sum(std::move(acc), v, e.inverted[i], where);
                    continue;
                }
                if (v.kind == Kind::matrix && i == 0) {
                    acc = v;
                    if (e.inverted[0]) acc = matrix_product(acc, scalar_value(-1, Dimension::none()), false, where);
                    continue;
                }
                if (v.kind == Kind::matrix || acc.kind == Kind::matrix) {
                    acc = matrix_sum(std::move(acc), v, e.inverted[i], where);
                    continue;
                }
                if (v.kind != Kind::scalar && v.kind != Kind::vector)
                    throw ScriptError(where, std::string("cannot add ") + kind_name(v.kind),
                                      "index an array, e.g. E[1]");
                if (i == 0) {
                    acc = v;
                    if (e.inverted[0]) acc.s = -acc.s, acc.v = -acc.v;
                    continue;
                }
                bool zero_s = v.kind == Kind::scalar && v.s.is_zero();
                bool acc_zero = acc.kind == Kind::scalar && acc.s.is_zero();
                if (v.kind != acc.kind && !zero_s && !acc_zero)
                    throw ScriptError(where, std::string("cannot add ") + kind_name(v.kind) + " to " +
                                                 kind_name(acc.kind),
                                      v.kind == Kind::vector ? "take a measure with dot(v>, Nx>)"
                                                             : "multiply the scalar by a unit vector");
                if (v.dim.conflicts(acc.dim))
                    throw ScriptError(where, "cannot add " + describe(v.dim) + " to " + describe(acc.dim),
                                      "the terms of a sum must have the same dimension; check the units");
                if (acc_zero && v.kind == Kind::vector) acc.kind = Kind::vector, acc.v = Vector();
                if (!v.dim.known) acc.dim = acc.dim.known ? acc.dim : v.dim;
                else if (!acc.dim.known) acc.dim = v.dim;
                if (acc.kind == Kind::scalar) acc.s = e.inverted[i] ? acc.s - v.s : acc.s + v.s;
                else if (!zero_s) acc.v = e.inverted[i] ? acc.v - v.v : acc.v + v.v;
            }
            return acc;
        }
        case Expr::Kind::product: {
            Value acc;
            for (std::size_t i = 0; i < e.args.size(); ++i) {
                Value v = eval(*e.args[i]);
                Location where = e.args[i]->location;
                if (i > 0 && (v.kind == Kind::dyadic || acc.kind == Kind::dyadic)) {
                    acc = dyadic_product(std::move(acc), v, e.inverted[i], where);
                    continue;
                }
                if (i > 0 && (v.kind == Kind::matrix || acc.kind == Kind::matrix || acc.kind == Kind::array)) {
                    acc = guard(where, [&] { return matrix_product(std::move(acc), v, e.inverted[i], where); });
                    continue;
                }
                if (v.kind != Kind::scalar && v.kind != Kind::vector &&
                    !(i == 0 && (v.kind == Kind::matrix || v.kind == Kind::array || v.kind == Kind::dyadic) &&
                      e.args.size() > 1))
                    throw ScriptError(where, std::string("cannot multiply ") + kind_name(v.kind),
                                      "index an array, e.g. E[1]");
                if (i == 0) {
                    acc = v;
                    continue;
                }
                if (e.inverted[i]) {
                    if (v.kind == Kind::vector)
                        throw ScriptError(where, "cannot divide by a vector", "divide by mag(v>) instead");
                    if (v.s.is_zero()) throw ScriptError(where, "division by zero", "");
                    acc.dim = acc.dim / v.dim;
                    if (acc.kind == Kind::scalar) acc.s = acc.s / v.s;
                    else acc.v = acc.v / v.s;
                    continue;
                }
                if (v.kind == Kind::vector && acc.kind == Kind::vector)
                    throw ScriptError(where, "cannot multiply two vectors with '*'",
                                      "use dot(a>, b>), cross(a>, b>) or outer(a>, b>) (the dyad)");
                acc.dim = acc.dim * v.dim;
                if (v.kind == Kind::vector) acc.v = acc.s * v.v, acc.kind = Kind::vector;
                else if (acc.kind == Kind::vector) acc.v = v.s * acc.v;
                else acc.s = acc.s * v.s;
            }
            return acc;
        }
        case Expr::Kind::power: {
            Value base = eval(*e.args[0]);
            Value p = eval(*e.args[1]);
            if (base.kind == Kind::matrix && p.kind == Kind::scalar)
                return matrix_power(base, p, *e.args[0], *e.args[1]);
            if (base.kind != Kind::scalar || p.kind != Kind::scalar)
                throw ScriptError(e.location, "powers take scalars and square matrices",
                                  "for vectors use dot(v>, v>)");
            check_dimension(p.dim, Dimension::none(), "an exponent", e.args[1]->location);
            Dimension d = base.dim;
            if (GiNaC::is_a<GiNaC::numeric>(p.s)) {
                const auto& n = GiNaC::ex_to<GiNaC::numeric>(p.s);
                if (n.is_integer()) {
                    if (GiNaC::abs(n) > Limits::max_power)
                        throw ScriptError(e.args[1]->location,
                                          "the power " + to_string(p.s) + " is too large (the limit is 64)",
                                          "");
                    d = pow(base.dim, n.to_int());
                } else if (base.dim.known && !base.dim.is_none()) {
                    GiNaC::numeric twice = n * 2;
                    bool even = twice.is_integer();
                    for (int x : base.dim.exponent) even = even && (x % 2 == 0);
                    if (!even)
                        throw ScriptError(e.location, "this power of " + describe(base.dim) + " has no dimension",
                                          "only whole powers, or square roots of squares, keep units");
                    Dimension h;
                    for (std::size_t i = 0; i < 3; ++i)
                        h.exponent[i] = base.dim.exponent[i] / 2 * twice.to_int();
                    d = h;
                }
            } else {
                check_dimension(base.dim, Dimension::none(), "the base of a symbolic power",
                                e.args[0]->location);
            }
            return scalar_value(GiNaC::pow(base.s, p.s), d);
        }
        case Expr::Kind::index: {
            auto it = values.find(e.text);
            if (it != values.end() && it->second.kind == Kind::matrix) {
                const Value& M = it->second;
                if (e.args.size() != 2)
                    throw ScriptError(e.location, "'" + e.text + "' is a matrix: give its row and column",
                                      "write " + e.text + "[1, 2]");
                std::size_t i = index_in(*this, *e.args[0], static_cast<std::size_t>(M.rows), e.text, "rows");
                std::size_t j = index_in(*this, *e.args[1], static_cast<std::size_t>(M.cols), e.text, "columns");
                return scalar_value(M.a[i * static_cast<std::size_t>(M.cols) + j], M.dim);
            }
            if (it == values.end() || it->second.kind != Kind::array) {
                if (it == values.end() && !names.count(e.text))
                    throw ScriptError(e.location, "'" + e.text + "' is not defined",
                                      "arrays come from kane, lagrange, roadmap or name = [a, b]");
                throw ScriptError(e.location, "'" + e.text + "' is not an array", "");
            }
            if (e.args.size() != 1)
                throw ScriptError(e.args[1]->location, "'" + e.text + "' is an array: give one index",
                                  "write " + e.text + "[1]");
            Value i = eval(*e.args[0]);
            if (i.kind != Kind::scalar || !GiNaC::is_a<GiNaC::numeric>(i.s) ||
                !GiNaC::ex_to<GiNaC::numeric>(i.s).is_integer())
                throw ScriptError(e.args[0]->location, "an index must be a whole number", "");
            const auto& n = GiNaC::ex_to<GiNaC::numeric>(i.s);
            const auto& a = it->second.a;
            if (n < 1 || n > static_cast<long>(a.size()))
                throw ScriptError(e.args[0]->location,
                                  "index " + to_string(i.s) + " is out of range: " + e.text + " has " +
                                      std::to_string(a.size()) + " elements",
                                  "indices start at 1");
            return scalar_value(a[static_cast<std::size_t>(n.to_int() - 1)], Dimension::open());
        }
        case Expr::Kind::list: {
            Value out;
            out.kind = Kind::array;
            for (const ExprPtr& x : e.args) out.a.push_back(scalar(*x, Dimension::open(), "an element of a list"));
            return out;
        }
        case Expr::Kind::matrix: {
            const int cols = static_cast<int>(e.args.size()) / e.rows;
            Dimension dim = Dimension::none();
            std::vector<ex> entries;
            for (const ExprPtr& a : e.args) {
                Value x = eval(*a);
                if (x.kind != Kind::scalar) throw ScriptError(a->location, "matrix entries must be scalars", "");
                if (x.dim.conflicts(Dimension::none())) dim = x.dim;
                entries.push_back(x.s);
            }
            return matrix_value(e.rows, cols, std::move(entries), dim);
        }
        case Expr::Kind::call: return eval_call(e);
        case Expr::Kind::binding:
            throw ScriptError(e.location, "'x = v' stands only among the arguments of replace() and taylor()",
                              "write replace(e, q = 0) or taylor(e, q = 0, 3)");
    }
    throw ScriptError(e.location, "internal: unknown expression", "");
}

std::string Interpreter::Impl::monogram(const Expr& c) const {
    if (c.kind != Expr::Kind::call) return "";
    auto arg = [&](std::size_t i) {
        return i < c.args.size() && c.args[i]->kind == Expr::Kind::name ? monogram_part(c.args[i]->text) : "";
    };
    const std::string& f = c.text;
    std::size_t n = c.args.size();
    if (n == 2 && !arg(0).empty() && !arg(1).empty()) {
        if (f == "angvel") return "w_" + arg(0) + "_" + arg(1) + ">";
        if (f == "angacc") return "alf_" + arg(0) + "_" + arg(1) + ">";
        if (f == "vel") return "v_" + arg(0) + "_" + arg(1) + ">";
        if (f == "acc") return "a_" + arg(0) + "_" + arg(1) + ">";
        if (f == "pos") return "p_" + arg(1) + "_" + arg(0) + ">";
        if (f == "rotation") return "R_" + arg(0) + "_" + arg(1);
        if (f == "angmomentum") return "H_" + arg(0) + "_" + arg(1) + ">";
        if (f == "moment") return "M_" + arg(0) + "_" + arg(1) + ">";
    }
    if (n == 1 && !arg(0).empty()) {
        if (f == "mass") return "m_" + arg(0);
        if (f == "momentum") return "L_" + arg(0) + "_" + sys->newtonian().name() + ">";
        if (f == "kinetic") return "KE_" + arg(0);
        if (f == "resultant") return "F_" + arg(0) + ">";
        if (f == "inertia")  // a rigid body's central inertia: I_B_Bcm>>
            if (auto it = names.find(c.args[0]->text); it != names.end() && it->second.kind == NameKind::body)
                return "I_" + arg(0) + "_" + monogram_part(c.args[0]->text + "cm") + ">>";
    }
    if (n == 0 && f == "potential") return "PE";
    return "";
}

Value Interpreter::Impl::eval_call(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    auto want = [&](std::size_t n, const std::string& form) {
        if (a.size() != n)
            throw ScriptError(e.location, f + "() takes " + std::to_string(n) + " argument" +
                                              (n == 1 ? "" : "s") + ", not " + std::to_string(a.size()),
                              "write " + form);
    };
    auto word = [&](std::size_t i, const std::string& what) -> Word {
        if (a[i]->kind != Expr::Kind::name)
            throw ScriptError(a[i]->location, f + "() needs " + what + " here, by name", "");
        return {a[i]->text, a[i]->location};
    };
    auto guarded = [&](auto&& fn) { return guard(e.location, fn); };
    static const char* math[] = {"sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "exp", "log", "abs"};
    for (const char* m : math) {
        if (f != m) continue;
        want(1, f + "(x)");
        Value x = eval(*a[0]);
        if (x.kind != Kind::scalar) throw ScriptError(a[0]->location, f + "() takes a scalar", "");
        // 2*pi*f*t with f in Hz counts the 2*pi of a cycle twice (1 Hz = 2*pi rad/s)
        if (f == "sin" || f == "cos" || f == "tan")
            if (const Expr* rate = revolution_rate_in(*a[0]); rate && holds_pi(*a[0])) {
                const std::string what = rate->kind == Expr::Kind::name
                                             ? "'" + rate->text + "' is a rate in revolutions"
                                             : "this rate is in revolutions";
                throw ScriptError(rate->location,
                                  what + " (1 Hz = 1 rev/s = 2*pi rad/s, 1 rpm = 2*pi/60 rad/s), so "
                                         "the 2*pi of a cycle is already in it, and with pi beside "
                                         "it it counts twice",
                                  "drop the 2*pi: " + f + "(w*t) with constant w = 1 Hz turns once per "
                                  "second; or give the rate in rad/s");
            }
        Dimension d = Dimension::none();
        if (f == "abs") d = x.dim;
        else if (f == "sqrt") {
            d = x.dim;
            if (x.dim.known) {
                for (int k : x.dim.exponent)
                    if (k % 2)
                        throw ScriptError(a[0]->location, "the square root of " + describe(x.dim) + " has no dimension",
                                          "check the units");
                for (auto& k : d.exponent) k /= 2;
            }
        } else if (x.dim.known && x.dim.exponent == std::array<int, 3>{0, 0, 1}) {
            throw ScriptError(a[0]->location,
                              "the argument of " + f + "() must be an angle or a number, but this is a time (s)",
                              "scale time by a rate or a period: " + f + "(w*t) with constant w = 1 Hz "
                              "(one cycle per second) or w = 3 rad/s, or " + f +
                              "(2*pi*t/T) with constant T = 2 s");
        } else {
            check_dimension(x.dim, Dimension::none(), "the argument of " + f + "()", a[0]->location);
        }
        ex r = guarded([&]() -> ex {
            if (f == "sin") return GiNaC::sin(x.s);
            if (f == "cos") return GiNaC::cos(x.s);
            if (f == "tan") return GiNaC::tan(x.s);
            if (f == "asin") return GiNaC::asin(x.s);
            if (f == "acos") return GiNaC::acos(x.s);
            if (f == "atan") return GiNaC::atan(x.s);
            if (f == "sqrt") return GiNaC::sqrt(x.s);
            if (f == "exp") return GiNaC::exp(x.s);
            if (f == "log") return GiNaC::log(x.s);
            return GiNaC::abs(x.s);
        });
        return scalar_value(r, d);
    }
    if (f == "minimum_jerk") {
        want(3, "minimum_jerk(t, t0, t1): 0 before t0, 1 after t1, 10u^3 - 15u^4 + 6u^5 between");
        Value x = eval(*a[0]);
        if (x.kind != Kind::scalar) throw ScriptError(a[0]->location, "minimum_jerk() takes time first", "");
        check_dimension(x.dim, Dimension::time(), "the first argument of minimum_jerk()", a[0]->location);
        double ends[2];
        for (std::size_t i = 1; i < 3; ++i) {
            Value v = eval(*a[i]);
            if (v.kind != Kind::scalar)
                throw ScriptError(a[i]->location, "the times of minimum_jerk() must be numbers",
                                  "write minimum_jerk(t, 0.15, 1.5), times in seconds");
            if (!v.dim.is_none())  // a bare number is in seconds
                check_dimension(v.dim, Dimension::time(), "a time of minimum_jerk()", a[i]->location);
            ends[i - 1] = guard(a[i]->location, [&] { return model(e.location).symbols().evaluate(v.s); },
                                "write minimum_jerk(t, 0.15, 1.5): times are numbers or constants with values");
        }
        return scalar_value(guarded([&] { return minimum_jerk(x.s, ends[0], ends[1]); }), Dimension::none());
    }
    if (f == "outer" || f == "unitdyadic" || f == "inertia" || f == "matrix" || f == "vector" ||
        (f == "dot" && a.size() == 3))
        return eval_dyadic(e);
    if (f == "dot" || f == "cross") {
        want(2, f + "(a>, b>)");
        Value x = eval(*a[0]), y = eval(*a[1]);
        if (f == "dot" && (x.kind == Kind::dyadic || y.kind == Kind::dyadic)) return dyadic_dot(e, x, y);
        for (std::size_t i = 0; i < 2; ++i)
            if ((i ? y : x).kind != Kind::vector)
                throw ScriptError(a[i]->location, f + "() takes two vectors", "");
        if (f == "dot") return scalar_value(guarded([&] { return alembert::dot(x.v, y.v); }), x.dim * y.dim);
        return vector_value(guarded([&] { return alembert::cross(x.v, y.v); }), x.dim * y.dim);
    }
    if (f == "express") {
        want(2, "express(v>, F)");
        Value x = eval(*a[0]);
        if (x.kind == Kind::dyadic) {
            Frame& F = frame(word(1, "a frame"));
            x.d = guarded([&] { return x.d.express_in(F); });
            return x;
        }
        if (x.kind != Kind::vector)
            throw ScriptError(a[0]->location, "express() takes a vector or a dyadic", "write express(v>, N)");
        Frame& F = frame(word(1, "a frame"));
        return vector_value(guarded([&] { return x.v.express_in(F); }), x.dim);
    }
    if (f == "dt") {
        if (a.size() != 1 && a.size() != 2)
            throw ScriptError(e.location, "dt() takes 1 or 2 arguments, not " + std::to_string(a.size()),
                              "write dt(s) for a scalar or dt(v>, N) for a vector in frame N");
        Value x = eval(*a[0]);
        if (a.size() == 2) {
            if (x.kind == Kind::dyadic) return dyadic_dt(e, x, frame(word(1, "a frame")));
            if (x.kind != Kind::vector) throw ScriptError(a[0]->location, "dt(v>, N) takes a vector or a dyadic", "");
            Frame& F = frame(word(1, "a frame"));
            return vector_value(guarded([&] { return x.v.dt_in(F); }), x.dim / kT);
        }
        if (x.kind == Kind::dyadic)
            throw ScriptError(a[0]->location, "a dyadic's time derivative depends on the frame", "write dt(D>>, N)");
        if (x.kind != Kind::scalar)
            throw ScriptError(a[0]->location, "a vector's time derivative depends on the frame",
                              "write dt(v>, N)");
        SymbolTable& table = model(e.location).symbols();
        return scalar_value(guarded([&] { return table.dt(x.s); }), x.dim / kT);
    }
    if (f == "mag" || f == "unit") {
        want(1, f + "(v>)");
        Value x = eval(*a[0]);
        if (x.kind != Kind::vector) throw ScriptError(a[0]->location, f + "() takes a vector", "");
        if (f == "mag") return scalar_value(guarded([&] { return x.v.magnitude(); }), x.dim);
        return vector_value(guarded([&] { return x.v.unit(); }), Dimension::none());
    }
    if (f == "simplify" || f == "expand") {
        want(1, f + "(x)");
        Value x = eval(*a[0]);
        auto op = [&](const ex& s) {
            // the expansion's size is bounded before GiNaC builds it
            const double terms = estimate_expansion_terms(s);
            if (terms > static_cast<double>(max_terms)) {
                std::ostringstream n;  // whole numbers while exact, else 3 digits
                if (terms < 1e15) n << std::fixed << std::setprecision(0) << terms;
                else n << std::setprecision(3) << terms;
                throw ScriptError(e.location,
                                  f + "(): expanding the expression would form up to " + n.str() +
                                      " terms, more than the limit of " + std::to_string(max_terms),
                                  "factor or split the expression, or raise the limit with --max-terms N "
                                  "(alembert run --max-terms N script.alb)");
            }
            return f == "simplify" ? alembert::simplify(s) : GiNaC::expand(s);
        };
        guarded([&] {
            if (x.kind == Kind::scalar) x.s = op(x.s);
            else if (x.kind == Kind::vector) x.v = x.v.map(op);
            else if (x.kind == Kind::dyadic) x.d = x.d.map(op);
            else if (x.kind == Kind::array)
                for (ex& s : x.a) s = op(s);
            else x = matrix_value(x.rows, x.cols, [&] {
                std::vector<ex> out;
                for (const ex& s : x.a) out.push_back(op(s));
                return out;
            }(), x.dim);
            return 0;
        });
        return x;
    }
    if (f == "angvel" || f == "angacc") {
        want(2, f + "(B, N)");
        Frame& B = frame(word(0, "a frame or body"));
        Frame& N = frame(word(1, "a frame"));
        bool acc = f == "angacc";
        return vector_value(guarded([&] { return acc ? B.ang_acc_in(N) : B.ang_vel_in(N); }),
                            acc ? pow(kT, -2) : pow(kT, -1));
    }
    if (f == "vel" || f == "acc") {
        want(2, f + "(P, N)");
        Point& P = point(word(0, "a point"));
        Frame& N = frame(word(1, "a frame"));
        bool acc = f == "acc";
        return vector_value(guarded([&] { return acc ? P.acc_in(N) : P.vel_in(N); }),
                            acc ? kL / pow(kT, 2) : kL / kT);
    }
    if (f == "pos") {
        want(2, "pos(P, O)");
        Point& P = point(word(0, "a point"));
        Point& O = point(word(1, "a point"));
        return vector_value(guarded([&] { return P.pos_from(O); }), kL);
    }
    if (f == "rotation") {
        want(2, "rotation(A, B)");
        Frame& A = frame(word(0, "a frame"));
        Frame& B = frame(word(1, "a frame"));
        Mat3 R = guarded([&] { return rotation_matrix(A, B); });
        std::vector<ex> entries;
        for (int i = 0; i < 9; ++i) entries.push_back(R(i / 3, i % 3));
        return matrix_value(3, 3, std::move(entries), Dimension::none());
    }
    if (f == "potential") {
        want(0, "potential()");
        System& m = model(e.location);
        return scalar_value(guarded([&] { return m.calc_potential_energy(); }), kM * kL * kL / kT / kT);
    }
    if ((f == "mass" && a.size() != 1) || f == "cm") {
        // mass(A, B, ...): the sum of their masses (mass(): every body's); cm(O), cm(O, A, B, ...): the position of
        // the mass centre of every body (or of those listed) from O
        const bool cm = f == "cm";
        if (cm && a.empty())
            throw ScriptError(e.location, "cm() takes the point first", "write cm(O) for every body, or cm(O, A, B)");
        System& m = model(e.location);
        BodySet S;
        for (std::size_t i = cm ? 1 : 0; i < a.size(); ++i) {
            const Word w = word(i, "a system or body");
            for (const Body* b : body_set(w)) {
                if (std::find(S.begin(), S.end(), b) != S.end())
                    throw ScriptError(w.location, f + "(): '" + b->name() + "' is counted twice",
                                      "list each body once (a system counts its bodies)");
                S.push_back(b);
            }
        }
        if (!cm) return scalar_value(guarded([&] { return m.calc_mass(a.empty() ? m.bodies() : S); }), kM);
        Point& O = point(word(0, "a point"));
        if (a.size() == 1) S = m.bodies();
        if (guarded([&] { return m.calc_mass(S).is_zero(); }))
            throw ScriptError(e.location, "cm(): the bodies' masses add up to 0, so they have no mass centre",
                              "give them masses first: mass A = m_A");
        return vector_value(guarded([&] { return m.calc_cm_pos(S, O); }), kL);
    }
    if (f == "mass" || f == "momentum" || f == "kinetic" || f == "resultant") {
        want(1, f + "(S)");
        BodySet S = body_set(word(0, "a system or body"));
        System& m = model(e.location);
        if (f == "mass") return scalar_value(guarded([&] { return m.calc_mass(S); }), kM);
        if (f == "kinetic")
            return scalar_value(guarded([&] { return m.calc_kinetic_energy(S); }), kM * kL * kL / kT / kT);
        if (f == "momentum")
            return vector_value(guarded([&] { return m.calc_linear_momentum(S); }), kM * kL / kT);
        return vector_value(guarded([&] { return m.calc_resultant(S, m.origin()).force; }),
                            Dimension::force());
    }
    if (f == "angmomentum" || f == "moment") {
        want(2, f + "(S, O)");
        BodySet S = body_set(word(0, "a system or body"));
        Point& O = point(word(1, "a point"));
        System& m = model(e.location);
        if (f == "moment")
            return vector_value(guarded([&] { return m.calc_resultant(S, O).moment; }), Dimension::torque());
        return vector_value(guarded([&] { return m.calc_angular_momentum(S, O); }), kM * kL * kL / kT);
    }
    if (f == "massmatrix") {
        want(1, "massmatrix(K), K formed by kane or lagrange");
        const Word k = word(0, "equations formed by kane or lagrange");
        auto it = formed.find(k.text);
        if (it == formed.end())
            throw ScriptError(k.location, "'" + k.text + "' holds no equations formed by kane or lagrange",
                              "form them first: kane " + k.text + " for q1, q2");
        SymbolTable& table = model(e.location).symbols();
        const FormedEquations& fe = it->second;
        // the accelerations: the coordinates' second derivatives, or the chosen speeds' rates
        std::vector<ex> acc;
        if (fe.kane)
            for (const ex& u : fe.kane->independent_speeds) acc.push_back(guarded([&] { return table.dt(u); }));
        else
            for (const TimeVariable& q : fe.coordinates) acc.push_back(q.d(2));
        // the equations read 0 = F - M acc (Kane's F + F*, Lagrange's Q - d/dt dL/dq' + dL/dq)
        std::vector<ex> entries;
        guarded([&] {
            for (const ex& r : fe.residuals) {
                ex full = table.expand_intermediates(r);
                for (const ex& x : acc) entries.push_back(alembert::simplify(-full.diff(GiNaC::ex_to<GiNaC::symbol>(x))));
            }
            return 0;
        });
        return matrix_value(static_cast<int>(fe.residuals.size()), static_cast<int>(acc.size()), std::move(entries),
                            Dimension::open());
    }
    if (f == "diff") {
        // the partial derivative by a symbol (q, q' and q'' are symbols of their own)
        want(2, "diff(s, x)");
        Value x = eval(*a[0]), by = eval(*a[1]);
        if (x.kind != Kind::scalar) throw ScriptError(a[0]->location, "diff() takes a scalar", "");
        SymbolTable& table = model(e.location).symbols();
        if (by.kind != Kind::scalar || !GiNaC::is_a<GiNaC::symbol>(by.s) || !table.owns(by.s))
            throw ScriptError(a[1]->location, "diff() differentiates by a declared symbol",
                              "write diff(s, q) with a coordinate, speed, constant or specified quantity");
        return scalar_value(guarded([&] { return table.expand_intermediates(x.s).diff(GiNaC::ex_to<GiNaC::symbol>(by.s)); }),
                            x.dim / by.dim);
    }
    if (f == "jacobian") {
        if (a.size() != 2 && a.size() != 3)
            throw ScriptError(e.location, "jacobian() takes 2 or 3 arguments, not " + std::to_string(a.size()),
                              "write jacobian([f1, f2], [q1, q2]) or jacobian(v>, [q1, q2], N)");
        Value x = eval(*a[0]);
        std::vector<ex> fs;
        if (x.kind == Kind::scalar) fs = {x.s};
        else if (x.kind == Kind::array) fs = x.a;
        else if (x.kind == Kind::vector) {
            if (a.size() != 3)
                throw ScriptError(a[0]->location, "a vector's Jacobian needs the frame of its components",
                                  "write jacobian(v>, [q1, q2], N)");
            Frame& F = frame(word(2, "a frame"));
            Vector w = guarded([&] { return x.v.express_in(F); });
            for (Axis ax : {Axis::x, Axis::y, Axis::z})
                fs.push_back(guarded([&] { return alembert::dot(w, F.unit(ax)); }));
        } else {
            throw ScriptError(a[0]->location, "jacobian() takes a scalar, a list [f1, f2] or a vector", "");
        }
        if (x.kind != Kind::vector && a.size() == 3)
            throw ScriptError(a[2]->location, "a frame is given only for a vector's Jacobian", "drop it");
        std::vector<ex> by = array(*a[1], "the symbols to differentiate by");
        SymbolTable& table = model(e.location).symbols();
        for (const ex& s : by)
            if (!GiNaC::is_a<GiNaC::symbol>(s) || !table.owns(s))
                throw ScriptError(a[1]->location, to_string(s) + " is not a declared symbol",
                                  "differentiate by coordinates, speeds or constants: [q1, q2]");
        std::vector<ex> entries;
        guarded([&] {
            for (const ex& fi : fs) {
                ex full = table.expand_intermediates(fi);
                for (const ex& s : by) entries.push_back(alembert::simplify(full.diff(GiNaC::ex_to<GiNaC::symbol>(s))));
            }
            return 0;
        });
        return matrix_value(static_cast<int>(fs.size()), static_cast<int>(by.size()), std::move(entries),
                            Dimension::open());
    }
    if (f == "coef" || f == "replace" || f == "taylor" || f == "factor" || f == "floor" || f == "exclude" ||
        f == "include")
        return eval_algebra(e);
    if (f == "transpose" || f == "inv" || f == "det" || f == "diagmat" || f == "element" || f == "rows" ||
        f == "cols")
        return eval_matrix(e);
    if (f == "eig" || f == "eigvec") return eval_eigen(e);
    if (f == "polynomial" || f == "roots") return eval_polynomial(e);
    throw ScriptError(e.location, "unknown function '" + f + "'",
                      "functions: sin cos tan asin acos atan sqrt exp log abs dot cross express dt "
                      "mag unit simplify expand angvel angacc vel acc pos rotation mass momentum "
                      "angmomentum kinetic potential resultant moment massmatrix jacobian diff coef "
                      "replace taylor factor floor exclude include transpose inv det diagmat element rows cols "
                      "eig eigvec polynomial roots cm outer unitdyadic inertia matrix vector");
}

// ---- output ----------------------------------------------------------------------------

std::string Interpreter::Impl::print(const Value& v) const {
    switch (v.kind) {
        case Kind::scalar: return to_string(v.s);
        case Kind::vector: return v.v.to_string();
        case Kind::dyadic: return v.d.to_string();
        case Kind::array: {
            std::string s = "[";
            for (std::size_t i = 0; i < v.a.size(); ++i) s += (i ? ", " : "") + to_string(v.a[i]);
            return s + "]";
        }
        case Kind::matrix: {
            std::string s = "[";
            for (int i = 0; i < v.rows; ++i)
                for (int j = 0; j < v.cols; ++j)
                    s += to_string(v.a[static_cast<std::size_t>(i * v.cols + j)]) +
                         (j + 1 < v.cols ? ", " : i + 1 < v.rows ? "; " : "]");
            return s;
        }
    }
    return "";
}

}  // namespace alembert::lang
