// SPDX-License-Identifier: MIT
// Dyadics in expressions: D>> names, sums and scalar multiples, outer(), dot() with a dyadic
// (a vector, or a dyadic between two dyadics), dt() of a dyadic in a frame,
// unitdyadic(), inertia(), and matrix() and vector() between measures and vectors or dyadics.
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

Value dyadic_value(Dyadic d, Dimension dim) {
    Value v;
    v.kind = Kind::dyadic, v.d = std::move(d), v.dim = dim;
    return v;
}

}  // namespace

Value Interpreter::Impl::eval_dyadic_name(const Expr& e) {
    auto it = values.find(e.text + ">>");
    if (it != values.end()) return it->second;
    throw ScriptError(e.location, "the dyadic '" + e.text + ">>' is not defined",
                      "assign it first (" + e.text + ">> = outer(a>, b>)); inertia(B) is a body's central "
                      "inertia dyadic, unitdyadic(N) the unit dyadic");
}

Value Interpreter::Impl::dyadic_sum(Value acc, const Value& v, bool subtract, Location where) {
    // a zero scalar added to a dyadic is the zero dyadic (D>> + 0)
    const bool zero_v = v.kind == Kind::scalar && v.s.is_zero();
    const bool zero_acc = acc.kind == Kind::scalar && acc.s.is_zero();
    if ((v.kind != Kind::dyadic && !zero_v) || (acc.kind != Kind::dyadic && !zero_acc))
        throw ScriptError(where,
                          std::string("cannot ") + (subtract ? "subtract " : "add ") + kind_name(v.kind) +
                              (subtract ? " from " : " to ") + kind_name(acc.kind),
                          v.kind == Kind::matrix || acc.kind == Kind::matrix
                              ? "take the dyadic's matrix in a frame first: matrix(N, D>>)"
                              : "the terms of a sum of dyadics are dyadics: outer(a>, b>), inertia(B), "
                                "x*unitdyadic(N)");
    if (v.dim.conflicts(acc.dim))
        throw ScriptError(where, "cannot add " + describe(v.dim) + " to " + describe(acc.dim),
                          "the terms of a sum must have the same dimension; check the units");
    if (zero_acc) acc = dyadic_value(Dyadic(), acc.dim);
    if (!acc.dim.known) acc.dim = v.dim;
    if (zero_v) return acc;
    if (subtract) acc.d -= v.d;
    else acc.d += v.d;
    return acc;
}

Value Interpreter::Impl::dyadic_product(Value acc, const Value& v, bool divide, Location where) {
    if (acc.kind == Kind::dyadic && v.kind == Kind::dyadic)
        throw ScriptError(where, "cannot multiply two dyadics with '*'",
                          "dot a dyadic with vectors: dot(D>>, v>), dot(v>, D>>) or dot(a>, D>>, b>)");
    const Value& other = acc.kind == Kind::dyadic ? v : acc;
    if (other.kind == Kind::vector)
        throw ScriptError(where, "cannot multiply a dyadic and a vector with '*'",
                          "dot them: dot(D>>, v>) or dot(v>, D>>)");
    if (other.kind != Kind::scalar)
        throw ScriptError(where, std::string("cannot multiply a dyadic by ") + kind_name(other.kind),
                          "a dyadic is multiplied or divided by scalars only");
    if (divide) {
        if (v.kind == Kind::dyadic)
            throw ScriptError(where, "cannot divide by a dyadic", "divide the dyadic by a scalar instead");
        if (v.s.is_zero()) throw ScriptError(where, "division by zero", "");
        acc.dim = acc.dim / v.dim;
        acc.d = guard(where, [&] { return ex(1 / v.s) * acc.d; });
        return acc;
    }
    const Value& D = acc.kind == Kind::dyadic ? acc : v;
    return dyadic_value(guard(where, [&] { return other.s * D.d; }), acc.dim * v.dim);
}

Value Interpreter::Impl::dyadic_dot(const Expr& e, const Value& x, const Value& y) {
    const auto& a = e.args;
    if (x.kind == Kind::dyadic && y.kind == Kind::dyadic) {
        // (A_i m_ij B_j) . E = A_i m_ij (B_j . E) = A_i (m [E]_B)_il B_l, summed over x's parts
        Dyadic out = guard(e.location, [&] {
            Dyadic r;
            for (const auto& [A, B, m] : x.d.components()) r += Dyadic(*A, *B, m * y.d.components_in(*B));
            return r;
        });
        return dyadic_value(std::move(out), x.dim * y.dim);
    }
    const std::size_t other = x.kind == Kind::dyadic ? 1 : 0;
    const Value& w = other ? y : x;
    if (w.kind != Kind::vector && !(w.kind == Kind::scalar && w.s.is_zero()))
        throw ScriptError(a[other]->location,
                          std::string("dot() takes a vector beside a dyadic, but this is ") + kind_name(w.kind),
                          "write dot(D>>, v>) or dot(v>, D>>)");
    Value out;
    out.kind = Kind::vector, out.dim = x.dim * y.dim;
    out.v = guard(e.location, [&] { return other ? alembert::dot(x.d, w.v) : alembert::dot(w.v, y.d); });
    return out;
}

Value Interpreter::Impl::dyadic_dt(const Expr& e, const Value& x, Frame& F) {
    // D = F_i [D]_F(i, j) F_j with F's unit vectors fixed in F: dD/dt in F = F_i [D]_F'(i, j) F_j
    SymbolTable& table = F.symbols();
    Dyadic out = guard(e.location, [&] {
        return Dyadic(F, F, x.d.components_in(F).map([&](const ex& c) { return table.dt(c); }));
    });
    return dyadic_value(std::move(out), x.dim / Dimension::time());
}

Value Interpreter::Impl::eval_dyadic(const Expr& e) {
    const std::string& f = e.text;
    const auto& a = e.args;
    auto want = [&](std::size_t n, const std::string& form) {
        if (a.size() != n)
            throw ScriptError(e.location, f + "() takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") +
                                              ", not " + std::to_string(a.size()),
                              "write " + form);
    };
    auto word = [&](std::size_t i, const std::string& what) -> Word {
        if (a[i]->kind != Expr::Kind::name)
            throw ScriptError(a[i]->location, f + "() needs " + what + " here, by name", "");
        return {a[i]->text, a[i]->location};
    };
    auto of_kind = [&](std::size_t i, Kind k, const std::string& form) {
        Value x = eval(*a[i]);
        if (k == Kind::vector && x.kind == Kind::scalar && x.s.is_zero()) x.kind = Kind::vector, x.v = Vector();
        if (x.kind != k)
            throw ScriptError(a[i]->location,
                              f + "() takes " + kind_name(k) + " here, but this is " + kind_name(x.kind),
                              "write " + form);
        return x;
    };
    if (f == "outer") {
        // the dyad a> b>: (a> b>) . v> = a> (b> . v>)
        const std::string form = "outer(a>, b>)";
        want(2, form);
        Value x = of_kind(0, Kind::vector, form), y = of_kind(1, Kind::vector, form);
        return dyadic_value(guard(e.location, [&] { return alembert::outer(x.v, y.v); }), x.dim * y.dim);
    }
    if (f == "unitdyadic") {
        want(1, "unitdyadic(N)");
        Frame& F = frame(word(0, "a frame"));
        return dyadic_value(Dyadic::unit(F), Dimension::none());
    }
    if (f == "inertia") {
        want(1, "inertia(B)");
        RigidBody& B = rigid_body(word(0, "a rigid body"));
        return dyadic_value(guard(e.location, [&]() -> Dyadic { return B.inertia(); }),
                            Dimension::mass() * Dimension::length() * Dimension::length());
    }
    if (f == "dot") {
        // dot(a>, D>>, b>) = a> . (D>> . b>)
        const std::string form = "dot(a>, D>>, b>)";
        Value x = of_kind(0, Kind::vector, form), D = of_kind(1, Kind::dyadic, form), y = of_kind(2, Kind::vector, form);
        Value out;
        out.kind = Kind::scalar, out.dim = x.dim * D.dim * y.dim;
        out.s = guard(e.location, [&] { return alembert::dot(x.v, alembert::dot(D.d, y.v)); });
        return out;
    }
    if (f == "matrix") {
        // the measures in F: of a vector a column, of a dyadic its 3 by 3 matrix
        want(2, "matrix(N, v>) or matrix(N, D>>)");
        Frame& F = frame(word(0, "a frame"));
        Value x = eval(*a[1]);
        if (x.kind == Kind::scalar && x.s.is_zero()) x.kind = Kind::vector, x.v = Vector();
        if (x.kind == Kind::vector) {
            const Col3 c = guard(e.location, [&] { return x.v.components_in(F); });
            return matrix_value(3, 1, {c[0], c[1], c[2]}, x.dim);
        }
        if (x.kind == Kind::dyadic) {
            const Mat3 m = guard(e.location, [&] { return x.d.components_in(F); });
            return matrix_value(3, 3, std::vector<ex>(m.m.begin(), m.m.end()), x.dim);
        }
        throw ScriptError(a[1]->location, "matrix() takes a vector or a dyadic, but this is " +
                                              std::string(kind_name(x.kind)),
                          "write matrix(N, v>) or matrix(N, D>>)");
    }
    // vector(F, M): M's three entries (a column, a row or a list) as measures in F
    want(2, "vector(N, [x; y; z])");
    Frame& F = frame(word(0, "a frame"));
    Value m = eval(*a[1]);
    const bool three = (m.kind == Kind::matrix && m.rows * m.cols == 3 && (m.rows == 1 || m.cols == 1)) ||
                       (m.kind == Kind::array && m.a.size() == 3);
    if (!three)
        throw ScriptError(a[1]->location,
                          "vector() takes three measures (a column, a row or a list of 3), but this is " +
                              (m.kind == Kind::matrix ? "a " + std::to_string(m.rows) + " by " + std::to_string(m.cols) + " matrix"
                                                      : std::string(kind_name(m.kind))),
                          "write vector(N, [x; y; z])");
    Value out;
    out.kind = Kind::vector, out.dim = m.kind == Kind::array ? Dimension::open() : m.dim;
    out.v = Vector(F, Col3{{m.a[0], m.a[1], m.a[2]}});
    return out;
}

}  // namespace alembert::lang
