// SPDX-License-Identifier: MIT
#include "alembert/eom/readable_equation.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <vector>

#include "alembert/eom/zero_test.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

namespace {

// the accelerations `e` holds, by name, so that what is collected does not depend on the
// order symbols were made in
std::vector<ex> accelerations_of(const SymbolTable& st, const ex& e) {
    std::vector<ex> acc;
    for (const ex& s : symbols_of(e))
        if (st.owns(s) && st.kind(s) == SymbolKind::variable && st.derivative_order(s) == 2)
            acc.push_back(s);
    std::sort(acc.begin(), acc.end(),
              [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    return acc;
}

// the model's constants and numbers only: the same at every state
bool is_time_free(const SymbolTable& st, const ex& a) {
    for (const ex& s : symbols_of(a))
        if (!st.owns(s) || st.kind(s) != SymbolKind::constant) return false;
    return true;
}

// the symbols a row's equation is gathered by, by name: its accelerations (the highest
// derivatives declared: the rates of speeds in Kane's equations) and unknown loads, and the
// row's own unknown
std::vector<ex> gathering_symbols(const SymbolTable& st, const ex& e, const ex& unknown) {
    std::vector<ex> keys;
    for (const ex& s : symbols_of(e))
        if (s.is_equal(unknown) ||
            (st.owns(s) && (st.kind(s) == SymbolKind::variable || st.kind(s) == SymbolKind::unknown) &&
             st.is_solve_level(s)))
            keys.push_back(s);
    std::sort(keys.begin(), keys.end(),
              [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    return keys;
}

// e = sum_k c_k keys_k + rest, with every c_k and rest free of the keys
struct LinearParts {
    std::vector<ex> c;
    ex rest;
};

// the parts of `x` (expanded: the collected form's terms), when it is linear in the keys
std::optional<LinearParts> linear_parts(const ex& x, const std::vector<ex>& keys) {
    const ex xe = GiNaC::expand(x);
    LinearParts p;
    GiNaC::exmap zero;
    for (const ex& k : keys) zero[k] = 0;
    for (const ex& k : keys) {
        try {
            if (xe.degree(k) > 1 || xe.ldegree(k) < 0) return std::nullopt;
        } catch (const std::exception&) {  // GiNaC has no degree for a key under a root
            return std::nullopt;
        }
        p.c.push_back(xe.coeff(k, 1));
    }
    p.rest = xe.subs(zero, GiNaC::subs_options::no_pattern);
    for (const ex& k : keys) {
        if (p.rest.has(k)) return std::nullopt;
        for (const ex& c : p.c)
            if (c.has(k)) return std::nullopt;
    }
    return p;
}

// the factor of `term` that varies in time other than through functions (the product of
// rates qA'*qB', 1 for none)
ex rates_of(const SymbolTable& st, const ex& term) {
    const auto varies = [&](const ex& f) {
        if (GiNaC::is_a<GiNaC::function>(f)) return false;
        const ex base = GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f;
        if (GiNaC::is_a<GiNaC::function>(base)) return false;
        return !is_time_free(st, base);
    };
    if (!GiNaC::is_a<GiNaC::mul>(term)) return varies(term) ? term : ex(1);
    ex out = 1;
    for (std::size_t i = 0; i < term.nops(); ++i)
        if (varies(term.op(i))) out *= term.op(i);
    return out;
}

// c * scale, expanded: c is a part of the simplified equation, so it is simplified again
// only when divided by a coefficient that is not a number (to cancel what they share)
ex scaled(const ex& c, const ex& scale, Simplifier& simplifier) {
    return GiNaC::is_a<GiNaC::numeric>(scale) ? GiNaC::expand(c * scale) : GiNaC::expand(simplifier(c * scale));
}

// factor_common(e), unless that puts a sum over a denominator (-L/2*(a + b) prints as one
// fraction, which no line breaks): then e's terms as they stand
ex without_fraction(const ex& e) {
    const ex f = factor_common(e);
    if (!GiNaC::is_a<GiNaC::mul>(f)) return f;
    bool sum = false, denominator = false;
    for (std::size_t i = 0; i < f.nops(); ++i) {
        const ex& x = f.op(i);
        sum = sum || GiNaC::is_a<GiNaC::add>(x);
        denominator = denominator ||
                      (GiNaC::is_a<GiNaC::numeric>(x) && !GiNaC::ex_to<GiNaC::numeric>(x).is_integer()) ||
                      (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
                       GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_negative());
    }
    return sum && denominator ? e : f;
}

// `rest` * `scale`, its terms gathered by their products of rates (qA'^2, qA'*qB', none), each
// product's coefficient simplified, gathered by its functions, with common factors out
ex gathered_by_rates(const SymbolTable& st, const ex& rest, const ex& scale, Simplifier& simplifier) {
    if (rest.is_zero()) return 0;
    std::vector<std::pair<ex, ex>> groups;  // rates, coefficient; in the order first met
    std::map<ex, std::size_t, GiNaC::ex_is_less> at;
    const auto add = [&](const ex& t) {
        const ex r = rates_of(st, t);
        auto [it, added] = at.try_emplace(r, groups.size());
        if (added) groups.push_back({r, 0});
        groups[it->second].second += t / r;
    };
    if (GiNaC::is_a<GiNaC::add>(rest))
        for (std::size_t i = 0; i < rest.nops(); ++i) add(rest.op(i));
    else
        add(rest);
    // products of rates whose coefficients differ only by a number share them:
    // L_B*sin(qC)*(2*qA'*qC' + qC'^2)
    std::vector<std::pair<ex, ex>> shared;  // coefficient, sum of number * rates
    std::map<ex, std::size_t, GiNaC::ex_is_less> at_coefficient;
    for (const auto& [r, c] : groups) {
        const ex grouped = group_by_varying_factors(st, scaled(c, scale, simplifier));
        if (r.is_equal(1)) {  // the terms free of rates: their common factor taken out when
            shared.push_back({without_fraction(grouped), 1});  // that leaves no fraction over a sum
            continue;
        }
        const ex f = factor_common(grouped);
        ex n = 1;  // f's number: of a product, or the content of a sum (GiNaC spreads it)
        if (GiNaC::is_a<GiNaC::numeric>(f)) n = f;
        else if (GiNaC::is_a<GiNaC::mul>(f))
            for (std::size_t i = 0; i < f.nops(); ++i)
                if (GiNaC::is_a<GiNaC::numeric>(f.op(i))) n *= f.op(i);
        if (GiNaC::is_a<GiNaC::add>(f)) n = f.integer_content();
        if (n.is_zero()) n = 1;
        auto [it, added] = at_coefficient.try_emplace(f / n, shared.size());
        if (added) shared.push_back({f / n, 0});
        shared[it->second].second += n * r;
    }
    ex out = 0;
    for (const auto& [c, rates] : shared) out += c * factor_common(rates);
    return out;
}

}  // namespace

ex readable_equation(const System& sys, const ex& e, Simplifier& simplifier) {
    if (count_ops(e) > kReadableEquationOps) return e;
    const std::vector<ex> acc = accelerations_of(sys.symbols(), e);
    const ex x = simplifier(e);
    return acc.empty() ? x : simplifier.collected(x, acc);
}

ReadableRelation calc_solved_equation(const System& sys, const ex& e, const ex& unknown,
                                      Simplifier& simplifier) {
    if (count_ops(e) > kReadableEquationOps) return {0, e};
    const SymbolTable& st = sys.symbols();
    const ex x = readable_equation(sys, e, simplifier);
    // gathered by the accelerations, unknown loads and the row's unknown; by the first two
    // only when the unknown enters otherwise (a statics row's angle, inside its sines)
    std::vector<ex> keys = gathering_symbols(st, x, unknown);
    std::optional<LinearParts> p = linear_parts(x, keys);
    if (!p) {
        keys = gathering_symbols(st, x, ex());
        p = linear_parts(x, keys);
    }
    if (p) {
        // solved for the unknown when its coefficient a is the same at every state and not
        // zero: unknown = -(the rest)/a, each part divided by a before it is simplified
        std::optional<std::size_t> u;
        for (std::size_t k = 0; k < keys.size(); ++k)
            if (keys[k].is_equal(unknown) && is_time_free(st, p->c[k]) &&
                !is_zero_at_random_states(st, p->c[k]))
                u = k;
        const ex scale = u ? ex(-1 / p->c[*u]) : ex(1);
        ex rhs = 0;
        for (std::size_t k = 0; k < keys.size(); ++k)
            if (k != u)
                rhs += factor_common(group_by_varying_factors(st, scaled(p->c[k], scale, simplifier))) *
                       keys[k];
        rhs += gathered_by_rates(st, p->rest, scale, simplifier);
        const ex lhs = u ? keys[*u] : ex(0);
        if (!u) rhs = without_fraction(rhs);
        // the same equation: x = a (unknown - rhs), or x = rhs when not solved
        const ex residual = u ? x - p->c[*u] * (lhs - rhs) : x - rhs;
        if (is_zero_at_random_states(st, residual)) return {lhs, rhs};
    }
    return {0, factor_common(x)};
}

}  // namespace alembert
