// SPDX-License-Identifier: MIT
// The symbol table: declarations, look-up, the chain rule and numeric evaluation.
#include "alembert/sym/symbol_table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>
#include <unordered_set>

#include <ginac/hash_map.h>

#include "alembert/error.hpp"
#include "alembert/sym/derivative.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

namespace {

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

std::string primes(int k) { return std::string(static_cast<std::size_t>(k), '\''); }

// ---- the pole guard of evaluate() ----------------------------------------------------------
// GiNaC signals a division by zero met while substituting numbers (1/x at x = 0, log(0)) by
// throwing pole_error out of the middle of its evaluation, and leaks the terms it was building
// when it does. evaluate() therefore first computes its expression in double arithmetic, which
// turns a pole into an infinity or NaN, and reports a value that is not finite itself, before
// GiNaC is asked at all.

using DoubleValues = GiNaC::exhashmap<double>;

// e at the values `at` in double arithmetic; nullopt if e holds a symbol without a value or
// something this walk does not know (GiNaC then has the last word). Shared subtrees are
// evaluated once (memo).
std::optional<double> in_doubles(const ex& e, const DoubleValues& at, DoubleValues& memo) {
    using namespace GiNaC;
    if (is_a<numeric>(e)) {
        const numeric& n = ex_to<numeric>(e);
        if (!n.is_real()) return std::nullopt;
        return n.to_double();
    }
    if (is_a<symbol>(e)) {
        auto it = at.find(e);
        if (it == at.end()) return std::nullopt;
        return it->second;
    }
    if (auto it = memo.find(e); it != memo.end()) return it->second;
    std::vector<double> x;
    x.reserve(e.nops());
    if (!is_a<constant>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) {
            std::optional<double> xi = in_doubles(e.op(i), at, memo);
            if (!xi) return std::nullopt;
            x.push_back(*xi);
        }
    double v;
    if (is_a<constant>(e)) {
        ex f = evalf(e);
        if (!is_a<numeric>(f) || !ex_to<numeric>(f).is_real()) return std::nullopt;
        v = ex_to<numeric>(f).to_double();
    } else if (is_a<add>(e)) {
        v = 0;
        for (double xi : x) v += xi;
    } else if (is_a<mul>(e)) {
        v = 1;
        for (double xi : x) v *= xi;
    } else if (is_a<power>(e)) {
        v = std::pow(x[0], x[1]);
        if (x[0] == 0 && x[1] < 0) v = std::nan("");  // a pole, whatever the sign of zero
    } else if (is_a<function>(e)) {
        const unsigned serial = ex_to<function>(e).get_serial();
        auto one = [&](double (*f)(double)) -> std::optional<double> {
            if (x.size() != 1) return std::nullopt;
            return f(x[0]);
        };
        std::optional<double> r;
        if (serial == sin_SERIAL::serial) r = one(std::sin);
        else if (serial == cos_SERIAL::serial) r = one(std::cos);
        else if (serial == tan_SERIAL::serial) r = one(std::tan);
        else if (serial == exp_SERIAL::serial) r = one(std::exp);
        else if (serial == log_SERIAL::serial) r = x.size() == 1 && x[0] == 0 ? std::nan("") : one(std::log);
        else if (serial == abs_SERIAL::serial) r = one(std::fabs);
        else if (serial == asin_SERIAL::serial) r = one(std::asin);
        else if (serial == acos_SERIAL::serial) r = one(std::acos);
        else if (serial == atan_SERIAL::serial) r = one(std::atan);
        else if (serial == sinh_SERIAL::serial) r = one(std::sinh);
        else if (serial == cosh_SERIAL::serial) r = one(std::cosh);
        else if (serial == tanh_SERIAL::serial) r = one(std::tanh);
        else if (serial == atan2_SERIAL::serial && x.size() == 2) r = std::atan2(x[0], x[1]);
        if (!r) return std::nullopt;
        v = *r;
    } else {
        return std::nullopt;
    }
    memo.emplace(e, v);
    return v;
}

}  // namespace

const char* to_string(SymbolKind kind) {
    switch (kind) {
        case SymbolKind::time: return "time";
        case SymbolKind::constant: return "constant";
        case SymbolKind::variable: return "variable";
        case SymbolKind::specified: return "specified";
        case SymbolKind::unknown: return "unknown";
        case SymbolKind::intermediate: return "intermediate";
    }
    return "?";
}

const ex& TimeVariable::d(int k) const {
    if (k < 0 || k > order())
        throw ModelError("TimeVariable::d(): '" + name_ + primes(k) + "' is not declared; '" +
                         name_ + "' is declared up to order " + std::to_string(order()) +
                         "; declare it with a higher order");
    return d_[static_cast<std::size_t>(k)];
}

SymbolTable::SymbolTable() {
    Info i{.kind = SymbolKind::time, .name = "t"};
    t_ = make_symbol("t", i);
}

void SymbolTable::check_new_name(const std::string& name) const {
    if (!is_identifier(name))
        throw ArgumentError("SymbolTable: '" + name +
                            "' is not a valid name; use letters, digits and '_', "
                            "starting with a letter");
    auto it = by_name_.find(name);
    if (it != by_name_.end())
        throw ModelError("SymbolTable: '" + name + "' is already declared as a " +
                         to_string(info_.at(it->second).kind) + "; choose another name");
}

ex SymbolTable::make_symbol(const std::string& name, Info i, bool positive) {
    ex s = positive ? ex(GiNaC::possymbol(name)) : ex(GiNaC::realsymbol(name));
    i.name = name;
    if (!GiNaC::is_a<GiNaC::symbol>(i.base)) i.base = s;
    i.index = order_.size();
    info_.emplace(s, std::move(i));
    by_name_.emplace(name, s);
    order_.push_back(s);
    by_kind_.at(static_cast<std::size_t>(info_.at(s).kind)).push_back(s);
    return s;
}

ex SymbolTable::add_constant(const std::string& name, std::optional<double> value, bool positive) {
    check_new_name(name);
    if (positive && value && !(*value > 0))
        throw ArgumentError("SymbolTable: the positive constant '" + name + "' is given the value " +
                            std::to_string(*value) + "; give it a value greater than 0");
    return make_symbol(name, Info{.kind = SymbolKind::constant, .value = value}, positive);
}

ex SymbolTable::add_unknown(const std::string& name) {
    check_new_name(name);
    return make_symbol(name, Info{.kind = SymbolKind::unknown});
}

TimeVariable SymbolTable::add_variable(const std::string& name, int order) {
    return add_time_varying(name, order, SymbolKind::variable);
}

TimeVariable SymbolTable::add_specified(const std::string& name, int order) {
    return add_time_varying(name, order, SymbolKind::specified);
}

TimeVariable SymbolTable::add_time_varying(const std::string& name, int order, SymbolKind kind) {
    check_new_name(name);
    if (order < 0 || order > 8)
        throw ArgumentError("SymbolTable: derivative order " + std::to_string(order) + " of '" +
                            name + "' is out of range; use 0 to 8");
    std::vector<ex> d;
    for (int k = 0; k <= order; ++k) {
        Info i{.kind = kind, .base = d.empty() ? ex(0) : d.front(), .order = k};
        d.push_back(make_symbol(name + primes(k), i));
    }
    for (int k = 0; k < order; ++k) info_.at(d[static_cast<std::size_t>(k)]).next = d[k + 1u];
    return TimeVariable(name, std::move(d));
}

ex SymbolTable::add_intermediate(const ex& definition, const std::string& name) {
    std::string n = name;
    if (n.empty()) {
        do n = "z" + std::to_string(next_z_++);
        while (by_name_.count(n));
    } else {
        check_new_name(n);
    }
    return make_intermediate(definition, n);
}

ex SymbolTable::name_subexpression(const ex& definition) {
    auto it = z_by_definition_.find(definition);
    if (it != z_by_definition_.end()) return it->second;
    ex z = add_intermediate(definition);
    z_by_definition_.emplace(definition, z);
    return z;
}

ex SymbolTable::make_intermediate(const ex& definition, const std::string& n) {
    if (by_name_.count(n))
        throw ModelError("SymbolTable: '" + n + "' is already declared; choose another name");
    Info i{.kind = SymbolKind::intermediate, .definition = definition};
    for (const ex& s : symbols_of(definition)) {
        auto it = info_.find(s);
        if (it == info_.end())
            throw ArgumentError("SymbolTable::add_intermediate(): the definition of '" + n +
                                "' uses the symbol '" + GiNaC::ex_to<GiNaC::symbol>(s).get_name() +
                                "', which was not declared in this table");
        if (it->second.kind == SymbolKind::intermediate)
            i.leaves.insert(it->second.leaves.begin(), it->second.leaves.end());
        else
            i.leaves.insert(s);
    }
    ex z = make_symbol(n, std::move(i));
    intermediates_.push_back(z);
    return z;
}

void SymbolTable::set_value(const ex& constant, double value) {
    auto it = info_.find(constant);
    if (it == info_.end() || it->second.kind != SymbolKind::constant) {
        std::ostringstream os;
        os << "SymbolTable::set_value(): '" << constant
           << "' is not a constant of this table; declare it with add_constant()";
        throw ArgumentError(os.str());
    }
    it->second.value = value;
}

const ex& SymbolTable::symbol(const std::string& name) const {
    auto it = by_name_.find(name);
    if (it == by_name_.end()) {
        std::ostringstream os;
        os << "SymbolTable: no symbol named '" << name << "'; declare it first";
        throw ModelError(os.str());
    }
    return it->second;
}

TimeVariable SymbolTable::variable(const std::string& name) const {
    const ex& q = symbol(name);
    const Info& i = info(q, "SymbolTable::variable()");
    if (i.kind != SymbolKind::variable && i.kind != SymbolKind::specified)
        throw ModelError("SymbolTable::variable(): '" + name + "' is a " + to_string(i.kind) +
                         ", not a variable");
    std::vector<ex> d{i.base};
    for (ex s = info_.at(i.base).next; GiNaC::is_a<GiNaC::symbol>(s); s = info_.at(s).next)
        d.push_back(s);
    return TimeVariable(info_.at(i.base).name, std::move(d));
}

const SymbolTable::Info& SymbolTable::info(const ex& s, const char* caller) const {
    auto it = info_.find(s);
    if (it == info_.end()) {
        std::ostringstream os;
        os << caller << ": '" << s << "' is not a symbol of this table; declare it first";
        throw ArgumentError(os.str());
    }
    return it->second;
}

SymbolKind SymbolTable::kind(const ex& s) const { return info(s, "SymbolTable::kind()").kind; }
const std::string& SymbolTable::name(const ex& s) const {
    return info(s, "SymbolTable::name()").name;
}
int SymbolTable::derivative_order(const ex& s) const {
    return info(s, "SymbolTable::derivative_order()").order;
}
const ex& SymbolTable::base(const ex& s) const { return info(s, "SymbolTable::base()").base; }
std::optional<double> SymbolTable::value(const ex& s) const {
    return info(s, "SymbolTable::value()").value;
}
const ex& SymbolTable::definition(const ex& z) const {
    const Info& i = info(z, "SymbolTable::definition()");
    if (i.kind != SymbolKind::intermediate)
        throw ArgumentError("SymbolTable::definition(): '" + i.name + "' is not an intermediate");
    return i.definition;
}

std::vector<ex> SymbolTable::symbols(SymbolKind k) const {
    return by_kind_.at(static_cast<std::size_t>(k));
}

ex SymbolTable::dt(const ex& e) {
    // term by term: each term is differentiated only with respect to its own symbols, where
    // the whole sum would be traversed once per symbol of any term
    if (GiNaC::is_a<GiNaC::add>(e)) {
        ex sum = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) sum += dt(e.op(i));
        return sum;
    }
    ex result = 0;
    for (const ex& s : symbols_of(e)) {
        const Info& i = info(s, "SymbolTable::dt()");
        ex ds;
        switch (i.kind) {
            case SymbolKind::constant: continue;
            case SymbolKind::time: ds = 1; break;
            case SymbolKind::unknown:
                throw ModelError("SymbolTable::dt(): '" + i.name +
                                 "' is an unknown and has no time derivative; declare it as a "
                                 "variable or specified if it changes in time");
            case SymbolKind::variable:
            case SymbolKind::specified:
                if (!GiNaC::is_a<GiNaC::symbol>(i.next))
                    throw ModelError("SymbolTable::dt(): the derivative of '" + i.name +
                                     "' is not declared; declare '" + info_.at(i.base).name +
                                     "' with order " + std::to_string(i.order + 1) +
                                     " or higher");
                ds = i.next;
                break;
            case SymbolKind::intermediate: {
                auto it = z_dt_.find(s);
                if (it == z_dt_.end()) {
                    ex d = dt(i.definition);
                    std::string name = i.name + "'";
                    it = z_dt_.emplace(s, name_derivative(d, name)).first;
                }
                ds = it->second;
                break;
            }
        }
        if (ds.is_zero()) continue;
        result += calc_derivative(e, GiNaC::ex_to<GiNaC::symbol>(s)) * ds;
    }
    return result;
}

ex SymbolTable::diff(const ex& e, const ex& s) {
    if (GiNaC::is_a<GiNaC::add>(e)) {  // term by term, as dt()
        ex sum = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) sum += diff(e.op(i), s);
        return sum;
    }
    const Info& is = info(s, "SymbolTable::diff()");
    const bool s_is_z = is.kind == SymbolKind::intermediate;
    ex result = calc_derivative(e, GiNaC::ex_to<GiNaC::symbol>(s));
    for (const ex& z : symbols_of(e)) {
        const Info& iz = info(z, "SymbolTable::diff()");
        if (iz.kind != SymbolKind::intermediate || z.is_equal(s)) continue;
        if (!iz.leaves.count(s) && !(s_is_z && depends_on(iz.definition, s))) continue;
        ex dz = diff_intermediate(z, s);
        if (!dz.is_zero()) result += calc_derivative(e, GiNaC::ex_to<GiNaC::symbol>(z)) * dz;
    }
    return result;
}

// dz/ds, taken once per pair and named when not small
ex SymbolTable::diff_intermediate(const ex& z, const ex& s) {
    auto& row = z_diff_[z];
    if (auto it = row.find(s); it != row.end()) return it->second;
    constexpr std::size_t kNameOps = 4;
    ex dz = diff(info_.at(z).definition, s);
    ex named = name_if_large(dz, kNameOps);
    z_diff_[z].emplace(s, named);  // `row` may have moved while diff() added entries
    return named;
}

bool SymbolTable::is_solve_level(const ex& s) const {
    auto it = info_.find(s);
    if (it == info_.end()) return false;
    const Info& i = it->second;
    switch (i.kind) {
        case SymbolKind::unknown: return true;
        case SymbolKind::variable:
        case SymbolKind::specified: return !GiNaC::is_a<GiNaC::symbol>(i.next);
        case SymbolKind::intermediate:
            for (const ex& l : i.leaves)
                if (is_solve_level(l)) return true;
            return false;
        default: return false;
    }
}

namespace {
bool is_atom(const ex& e) { return GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e); }
}  // namespace

ex SymbolTable::name_if_large(const ex& e, std::size_t min_ops) {
    if (is_atom(e) || count_ops(e) <= min_ops) return e;
    return name_parts(e, min_ops, "");
}

ex SymbolTable::name_derivative(const ex& d, const std::string& name) {
    constexpr std::size_t kNameOps = 4;  // coefficients of q'' this small stay written out
    return d.is_zero() || is_atom(d) ? d : name_parts(d, kNameOps, name);
}

// Splits `e` (times `factor`) into sum_k c_k x_k + rest over the solve-level symbols x_k in
// one pass over its sums and products; false if e is not visibly linear in them (an x_k
// inside a power or a function, or in two factors of one product).
bool SymbolTable::collect_linear(const ex& e, const ex& factor,
                                 std::map<ex, ex, GiNaC::ex_is_less>& coeffs, ex& rest) const {
    auto holds_x = [&](const ex& f) {
        for (const ex& s : symbols_of(f))
            if (is_solve_level(s)) return true;
        return false;
    };
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (is_solve_level(e)) {
            if (info_.at(e).kind == SymbolKind::intermediate) return false;
            coeffs[e] += factor;
        } else {
            rest += factor * e;
        }
        return true;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!collect_linear(e.op(i), factor, coeffs, rest)) return false;
        return true;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        std::size_t holder = e.nops();
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (!holds_x(e.op(i))) continue;
            if (holder != e.nops()) return false;  // x in two factors
            holder = i;
        }
        if (holder == e.nops()) {
            rest += factor * e;
            return true;
        }
        ex others = factor;
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (i != holder) others *= e.op(i);
        return collect_linear(e.op(holder), others, coeffs, rest);
    }
    if (holds_x(e)) return false;
    rest += factor * e;
    return true;
}

bool SymbolTable::calc_linear_form(const ex& e, std::map<ex, ex, GiNaC::ex_is_less>& coeffs, ex& rest) {
    return collect_linear_through(e, 1, coeffs, rest);
}

// collect_linear, with the intermediates that hold solve-level symbols split by their
// remembered linear forms. With `unsplit`, an intermediate met whose form is not remembered yet
// is not split here: it is put in *unsplit and the walk stops (returns false)
bool SymbolTable::collect_linear_through(const ex& e, const ex& factor,
                                         std::map<ex, ex, GiNaC::ex_is_less>& coeffs, ex& rest,
                                         ex* unsplit) {
    auto holds_x = [&](const ex& f) {
        for (const ex& s : symbols_of(f))
            if (is_solve_level(s)) return true;
        return false;
    };
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (!is_solve_level(e)) {
            rest += factor * e;
        } else if (info_.at(e).kind == SymbolKind::intermediate) {
            if (unsplit && !z_linear_.count(e)) {
                *unsplit = e;
                return false;
            }
            const LinearForm* f = linear_form_of(e);
            if (!f) return false;
            for (const auto& [x, c] : f->coeffs) coeffs[x] += factor * c;
            rest += factor * f->rest;
        } else {
            coeffs[e] += factor;
        }
        return true;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!collect_linear_through(e.op(i), factor, coeffs, rest, unsplit)) return false;
        return true;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        std::size_t holder = e.nops();
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (!holds_x(e.op(i))) continue;
            if (holder != e.nops()) return false;  // x in two factors
            holder = i;
        }
        if (holder == e.nops()) {
            rest += factor * e;
            return true;
        }
        ex others = factor;
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (i != holder) others *= e.op(i);
        return collect_linear_through(e.op(holder), others, coeffs, rest, unsplit);
    }
    if (holds_x(e)) return false;
    rest += factor * e;
    return true;
}

// z = sum_x c_x x + rest, split once; nothing if z is not visibly linear in the x.
// An intermediate whose definition holds others is split after them, in the order the walk of
// its definition meets them (as a recursion would), but with a stack of its own: a chain of
// intermediates grows with the model, and a call per link would overflow the thread's stack.
const SymbolTable::LinearForm* SymbolTable::linear_form_of(const ex& z) {
    if (auto it = z_linear_.find(z); it != z_linear_.end()) return it->second ? &*it->second : nullptr;
    constexpr std::size_t kNameOps = 4;
    std::vector<ex> todo{z};
    while (!todo.empty()) {
        const ex y = todo.back();
        if (z_linear_.count(y)) {  // met twice on the way down
            todo.pop_back();
            continue;
        }
        std::map<ex, ex, GiNaC::ex_is_less> coeffs;
        ex rest = 0, first_unsplit;
        const bool linear = collect_linear_through(info_.at(y).definition, 1, coeffs, rest, &first_unsplit);
        if (!linear && !first_unsplit.is_zero()) {  // that one first, then y's walk again
            todo.push_back(first_unsplit);
            continue;
        }
        std::optional<LinearForm> form;
        if (linear) {
            form.emplace();
            for (const auto& [x, c] : coeffs)
                if (!c.is_zero()) form->coeffs.emplace(x, name_if_large(c, kNameOps));
            form->rest = name_if_large(rest, kNameOps);
        }
        z_linear_[y] = std::move(form);
        todo.pop_back();
    }
    const auto& kept = z_linear_.at(z);
    return kept ? &*kept : nullptr;
}

// e = sum_k c_k x_k + r over the solve-level symbols x_k of e, with c_k named when larger
// than min_ops and r named `rest_name` (or by its definition when rest_name is empty and r is
// large); e itself if it is not linear in the x_k
ex SymbolTable::name_parts(const ex& e, std::size_t min_ops, const std::string& rest_name) {
    auto name_rest = [&](const ex& r) {
        if (r.is_zero() || is_atom(r)) return r;
        if (!rest_name.empty()) return make_intermediate(r, unique_name(rest_name));
        return count_ops(r) <= min_ops ? r : name_subexpression(r);
    };
    std::map<ex, ex, GiNaC::ex_is_less> coeffs;
    ex rest = 0;
    if (!collect_linear(e, 1, coeffs, rest)) return e;
    ex out = 0;
    for (const auto& [x, c] : coeffs) out += name_if_large(c, min_ops) * x;
    return out + name_rest(rest);
}

std::string SymbolTable::unique_name(const std::string& name) const {
    std::string n = name;
    while (by_name_.count(n)) n += "'";
    return n;
}

GiNaC::exset SymbolTable::calc_leaf_symbols(const ex& e) const {
    // an intermediate's leaves were gathered when it was made: read, not walked again through
    // its definitions (a chain's kinematics nest n intermediates deep)
    GiNaC::exset out;
    for (const ex& s : symbols_of(e)) {
        auto it = info_.find(s);
        if (it != info_.end() && it->second.kind == SymbolKind::intermediate)
            out.insert(it->second.leaves.begin(), it->second.leaves.end());
        else
            out.insert(s);
    }
    return out;
}

bool SymbolTable::depends_on(const ex& e, const ex& s) const {
    if (e.has(s)) return true;
    // a leaf is found in the leaf sets gathered when each intermediate was made; only an
    // intermediate is looked for inside definitions (walking them for a leaf visited each
    // shared definition once per path, exponentially many in a long chain)
    auto is = info_.find(s);
    const bool s_is_z = is != info_.end() && is->second.kind == SymbolKind::intermediate;
    for (const ex& z : symbols_of(e)) {
        auto it = info_.find(z);
        if (it == info_.end() || it->second.kind != SymbolKind::intermediate) continue;
        if (!s_is_z && it->second.leaves.count(s)) return true;
        if (s_is_z && depends_on(it->second.definition, s)) return true;
    }
    return false;
}

const ex& SymbolTable::expanded_definition(const ex& z) const {
    auto it = z_expanded_.find(z);
    if (it != z_expanded_.end()) return it->second;
    ex full = expand_intermediates(info_.at(z).definition);
    return z_expanded_.emplace(z, full).first->second;
}

ex SymbolTable::expand_intermediates(const ex& e) const {
    exmap m;
    for (const ex& s : symbols_of(e)) {
        auto it = info_.find(s);
        if (it != info_.end() && it->second.kind == SymbolKind::intermediate)
            m[s] = expanded_definition(s);
    }
    return m.empty() ? e : e.subs(m);
}

exmap SymbolTable::constant_values() const {
    exmap m;
    for (const auto& [s, i] : info_)
        if (i.kind == SymbolKind::constant && i.value) m[s] = GiNaC::numeric(*i.value);
    return m;
}

double SymbolTable::evaluate(const ex& e, const exmap& values) const {
    EvaluationMemo memo(values);
    return evaluate(e, memo);
}

double SymbolTable::evaluate(const ex& e, EvaluationMemo& memo) const {
    exmap& m = memo.m_;
    DoubleValues& at = memo.at_;
    if (!memo.ready_) {
        m = constant_values();
        for (const auto& [k, v] : memo.values_) m[k] = v;
        // the pole guard (see in_doubles): a value that is not finite in double arithmetic is
        // reported here, without handing GiNaC a division by zero
        for (const auto& [k, x] : m)
            if (GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real())
                at.emplace(k, GiNaC::ex_to<GiNaC::numeric>(x).to_double());
        memo.ready_ = true;
    }
    // intermediates reachable from e and not yet evaluated, in dependency order
    GiNaC::exset needed;
    std::vector<ex> stack{e};
    while (!stack.empty()) {
        ex cur = stack.back();
        stack.pop_back();
        for (const ex& s : symbols_of(cur)) {
            auto it = info_.find(s);
            if (it != info_.end() && it->second.kind == SymbolKind::intermediate &&
                !m.count(s) && needed.insert(s).second)
                stack.push_back(it->second.definition);
        }
    }
    std::vector<const std::pair<const ex, Info>*> order;
    for (const ex& z : needed) order.push_back(&*info_.find(z));
    std::sort(order.begin(), order.end(),
              [](const auto* a, const auto* b) { return a->second.index < b->second.index; });
    auto guard = [&](const ex& expression, const std::string& what) {
        std::optional<double> x = in_doubles(expression, at, memo.memo_);
        if (x && !std::isfinite(*x))
            throw ArgumentError("SymbolTable::evaluate(): " + what +
                                " is not a finite real number at these values (a division by "
                                "zero, or a value outside a function's domain)");
        return x;
    };
    for (const auto* zi : order) {
        const auto& [z, i] = *zi;
        if (std::optional<double> x = guard(i.definition, "'" + i.name + "'")) at.emplace(z, *x);
        m[z] = GiNaC::evalf(i.definition.subs(m));
    }
    guard(e, "the expression");
    ex v = GiNaC::evalf(e.subs(m));
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
        for (const ex& s : symbols_of(v)) {
            auto it = info_.find(s);
            std::string n = it != info_.end() ? it->second.name
                                              : GiNaC::ex_to<GiNaC::symbol>(s).get_name();
            throw ArgumentError("SymbolTable::evaluate(): '" + n +
                                "' has no value; give it one (constants: set_value)");
        }
        std::ostringstream os;
        os << "SymbolTable::evaluate(): the expression does not evaluate to a real number ("
           << v << ")";
        throw ArgumentError(os.str());
    }
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

GiNaC::exset symbols_of(const ex& e) {
    // a walk over the DAG: a node shared by many parents is entered once (GiNaC's own
    // traversals walk the tree, whose size grows exponentially with the depth of sharing)
    GiNaC::exset out;
    // (op() of a sum may build a term anew, so the nodes entered are kept alive while their
    // addresses are remembered)
    std::unordered_set<const GiNaC::basic*> entered;
    std::vector<ex> alive, stack{e};
    while (!stack.empty()) {
        ex x = std::move(stack.back());
        stack.pop_back();
        if (GiNaC::is_a<GiNaC::symbol>(x)) {
            out.insert(x);
            continue;
        }
        if (x.nops() == 0 || !entered.insert(&GiNaC::ex_to<GiNaC::basic>(x)).second) continue;
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        alive.push_back(std::move(x));
    }
    return out;
}

namespace detail {
void throw_internal(const char* condition, SourceLocation where) {
    std::ostringstream os;
    os << "internal error: " << condition << " failed at " << where.file_name() << ":"
       << where.line() << " (" << where.function_name() << "); please report this";
    throw InternalError(os.str());
}
}  // namespace detail

}  // namespace alembert
