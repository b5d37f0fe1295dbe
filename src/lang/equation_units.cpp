// SPDX-License-Identifier: MIT
// An equation's units checked term by term, intermediates worked out once.
#include "alembert/lang/equation_units.hpp"

#include <set>

#include "alembert/sym/print.hpp"

namespace alembert::lang {

namespace {

// a term as the reader sees it, cut short when long
std::string shown(const ex& term) {
    std::string s = to_string(term);
    return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

// "N·m" for N*m (the products of units the reader sees, not the script's spelling)
std::string unit_words(const Dimension& d) {
    std::string u = si_unit(d);
    if (u == "N*m") return "N\u00b7m";
    return u.empty() ? "a number" : u;
}

}  // namespace

EquationUnitChecker::Found EquationUnitChecker::of(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return {Dimension::none(), "", false, !GiNaC::ex_to<GiNaC::numeric>(e).is_rational()};
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (st_.owns(e) && st_.kind(e) == SymbolKind::intermediate) {
            auto it = intermediates_.find(e);
            if (it == intermediates_.end())
                it = intermediates_.emplace(e, of(st_.definition(e))).first;
            return it->second;
        }
        const Dimension d = of_symbol_(e);
        return {d, "", !d.known};
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
        // sin, cos, ... of angles; their arguments' own sums are checked
        Found r{Dimension::none(), "", false};
        for (const ex& a : e) {
            const Found f = of(a);
            if (r.conflict.empty()) r.conflict = f.conflict;
            r.partial = r.partial || f.partial;
            r.decimal = r.decimal || f.decimal;
        }
        return r;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        Found first{Dimension::open(), "", false};
        ex first_term;
        bool first_decimal = false;
        for (const ex& term : e) {
            const Found f = of(term);
            if (first.conflict.empty()) first.conflict = f.conflict;
            first.partial = first.partial || f.partial;
            first.decimal = first.decimal || f.decimal;
            if (!f.dimension.known) continue;
            if (!first.dimension.known) {
                first.dimension = f.dimension;
                first_term = term;
                first_decimal = f.decimal;
            } else if (f.dimension != first.dimension && (first_decimal || f.decimal)) {
                // a decimal number's unit may be what differs: the sum's dimension is open
                first.dimension = Dimension::open();
                first.partial = true;
                break;
            } else if (f.dimension != first.dimension && first.conflict.empty()) {
                first.conflict = "in a sum, " + shown(first_term) + " is in " +
                                 unit_words(first.dimension) + " but " + shown(term) + " in " +
                                 unit_words(f.dimension);
            }
        }
        return first;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        Found r{Dimension::none(), "", false};
        for (const ex& factor : e) {
            const Found f = of(factor);
            r.dimension = r.dimension * f.dimension;
            if (r.conflict.empty()) r.conflict = f.conflict;
            r.partial = r.partial || f.partial;
            r.decimal = r.decimal || f.decimal;
        }
        return r;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1))) {
        Found base = of(e.op(0));
        const GiNaC::numeric p = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
        if (p.is_integer())
            return {pow(base.dimension, p.to_int()), base.conflict, base.partial, base.decimal};
        // a square root of a square (a length's magnitude) keeps its dimension
        if (base.dimension.known && p.denom() == 2) {
            Dimension half;
            for (std::size_t i = 0; i < 3; ++i) {
                if (base.dimension.exponent[i] % 2 != 0) return {Dimension::open(), base.conflict, true};
                half.exponent[i] = base.dimension.exponent[i] / 2;
            }
            return {pow(half, p.numer().to_int()), base.conflict, base.partial, base.decimal};
        }
        return {Dimension::open(), base.conflict, true, base.decimal};
    }
    return {Dimension::open(), "", true};
}

ReportUnitCheck EquationUnitChecker::check(const ex& equation, const Dimension& expected) {
    ReportUnitCheck r;
    std::vector<ex> terms;
    if (GiNaC::is_a<GiNaC::add>(equation))
        for (const ex& t : equation) terms.push_back(t);
    else if (!equation.is_zero())
        terms.push_back(equation);
    Dimension want = expected;
    ex first;
    std::string conflict;
    std::set<std::string> undeclared;
    bool decimals = false;  // a term off only where a decimal number may have lost its unit
    std::vector<std::pair<ex, Found>> found;
    found.reserve(terms.size());
    for (const ex& term : terms) found.emplace_back(term, of(term));
    // the expected dimension from a term without decimals where the row gives none
    if (!want.known)
        for (const auto& [term, f] : found)
            if (f.dimension.known && !f.decimal) {
                want = f.dimension;
                first = term;
                break;
            }
    for (const auto& [term, f] : found) {
        if (conflict.empty()) conflict = f.conflict;
        if (f.partial) {
            // the leaves declared without a unit, to say which
            bool named = false;
            for (const ex& s : st_.calc_leaf_symbols(term))
                if (!of_symbol_(s).known) undeclared.insert(to_string(s)), named = true;
            if (!named && f.decimal) decimals = true;  // open only through a decimal number
            if (!f.dimension.known) continue;
        }
        if (!want.known) {
            want = f.dimension;
            first = term;
            continue;
        }
        if (f.dimension == want) continue;
        if (f.decimal)
            decimals = true;
        else
            r.terms.push_back(shown(term) + " is in " + unit_words(f.dimension));
    }
    r.unit = want.known ? si_unit(want) : "";
    const std::string unit = want.known ? unit_words(want) : "";
    if (!r.terms.empty() || !conflict.empty()) {
        r.verdict = ReportUnitCheck::Verdict::inconsistent;
        std::string s;
        for (const std::string& t : r.terms) s += (s.empty() ? "" : "; ") + std::string("the term ") + t;
        if (!s.empty())
            s += expected.known ? ", not " + unit : ", not " + unit + " as " + shown(first) + " is";
        if (!conflict.empty()) {
            r.terms.push_back(conflict);
            s += (s.empty() ? "" : "; ") + conflict;
        }
        r.summary = "units: " + s;
        return r;
    }
    if (decimals && undeclared.empty()) {
        r.summary = "units: not checked (a decimal number in a term may stand for a quantity "
                    "written with a unit, such as 0.35 m, whose unit the equation no longer "
                    "holds; declare such lengths and masses as constants with units)";
        return r;
    }
    if (!undeclared.empty() || !want.known) {
        std::string names;
        std::size_t shown_names = 0;
        for (const std::string& n : undeclared)
            if (++shown_names <= 8) names += (names.empty() ? "" : ", ") + n;
        if (undeclared.size() > 8) names += ", ...";
        r.summary = names.empty() ? "units: not checked (no units declared)"
                                  : "units: not checked (no units declared for " + names + ")";
        return r;
    }
    r.verdict = ReportUnitCheck::Verdict::consistent;
    r.summary = "units: " + unit;
    return r;
}

}  // namespace alembert::lang
