// SPDX-License-Identifier: MIT
// Linearization of first-order implicit equations about an operating point.
#include "alembert/eom/linearize.hpp"

#include <map>
#include <string>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "expression_lists.hpp"

namespace alembert {

namespace {

using detail::contains;
using detail::index_of;

const std::string kLinearize = "linearize(): ";

void require_symbol(const ex& x, const std::string& role) {
    if (!GiNaC::is_a<GiNaC::symbol>(x))
        throw ArgumentError(kLinearize + role + " '" + to_string(x) + "' is not a symbol");
}

const GiNaC::symbol& sym(const ex& x) { return GiNaC::ex_to<GiNaC::symbol>(x); }

// The derivatives of sign functions (csgn, step: Coulomb friction, one-sided contacts) that
// differentiation leaves as D[0](csgn)(v): 0 where v is a nonzero number; where v is 0 the
// equations have no derivative, which is an error at the operating point.
struct SignDerivatives : GiNaC::map_function {
    ex operator()(const ex& e) override {
        if (GiNaC::is_a<GiNaC::fderivative>(e)) {
            const auto& f = GiNaC::ex_to<GiNaC::fderivative>(e);
            if (f.get_serial() == GiNaC::csgn_SERIAL::serial ||
                f.get_serial() == GiNaC::step_SERIAL::serial) {
                const ex v = GiNaC::evalf(e.op(0));
                if (GiNaC::is_a<GiNaC::numeric>(v)) {
                    if (v.is_zero())
                        throw SolveError(kLinearize + "the equations have no derivative at the "
                                         "operating point: a sign function (Coulomb friction, "
                                         "a one-sided contact) switches there, at " +
                                         to_string(e.op(0)) +
                                         " = 0; linearize about a point where it is nonzero");
                    return 0;
                }
            }
        }
        return e.map(*this);
    }
};

ex with_sign_derivatives(const ex& e) {
    SignDerivatives f;
    return f(e);
}

// A value and its first partial derivatives (by target symbol) at one point.
struct Jet {
    ex value;
    std::map<ex, ex, GiNaC::ex_is_less> d;
};

// Values and first derivatives of expressions at a point, taken through the intermediates of
// `table` without expanding them (forward mode): each intermediate reachable from the
// expressions is visited once in dependency order, its value and derivatives formed from
// its definition and those of the intermediates it uses. The cost is linear in the total size
// of the definitions, where expanding a chain of intermediates first can be exponential.
class PointJets {
public:
    PointJets(const SymbolTable& table, const exmap& point, const std::vector<ex>& targets,
              const std::vector<ex>& roots)
        : table_(table), point_(point), targets_(targets.begin(), targets.end()) {
        GiNaC::exset needed;
        std::vector<ex> stack(roots.begin(), roots.end());
        while (!stack.empty()) {
            ex cur = stack.back();
            stack.pop_back();
            for (const ex& s : symbols_of(cur))
                if (table_.owns(s) && table_.kind(s) == SymbolKind::intermediate &&
                    needed.insert(s).second)
                    stack.push_back(table_.definition(s));
        }
        for (const ex& z : table_.intermediates())
            if (needed.count(z)) z_.emplace(z, jet(table_.definition(z)));
    }
    Jet jet(const ex& e) const {
        exmap at;
        std::vector<ex> syms;
        for (const ex& s : symbols_of(e)) {
            syms.push_back(s);
            auto z = z_.find(s);
            if (z != z_.end()) {
                at[s] = z->second.value;
            } else {
                auto p = point_.find(s);
                if (p != point_.end()) at[s] = p->second;
            }
        }
        Jet out{tidy(e.subs(at, GiNaC::subs_options::no_pattern)), {}};
        // the symbols whose derivatives do not count, at numeric values, put in before
        // differentiating: each derivative below then walks the smaller expression
        exmap fixed;
        for (const ex& s : syms) {
            if (targets_.count(s) != 0) continue;
            auto z = z_.find(s);
            if (z != z_.end() && !z->second.d.empty()) continue;
            auto v = at.find(s);
            if (v != at.end() && GiNaC::is_a<GiNaC::numeric>(v->second)) fixed.insert(*v);
        }
        const ex reduced = fixed.empty() ? e : e.subs(fixed, GiNaC::subs_options::no_pattern);
        for (const ex& s : syms) {
            const bool target = targets_.count(s) != 0;
            auto z = z_.find(s);
            if (!target && (z == z_.end() || z->second.d.empty())) continue;
            ex partial = with_sign_derivatives(reduced.diff(sym(s)).subs(at, GiNaC::subs_options::no_pattern));
            if (partial.is_zero()) continue;
            if (target) out.d[s] += partial;
            if (z != z_.end())
                for (const auto& [t, dz] : z->second.d) out.d[t] += partial * dz;
        }
        for (auto& [t, d] : out.d) d = tidy(d);
        return out;
    }

private:
    // polynomials in the symbols left (a forward speed kept symbolic) expanded, so values
    // stay flat sums instead of nesting intermediate by intermediate
    static ex tidy(const ex& e) {
        if (GiNaC::is_a<GiNaC::numeric>(e)) return e;
        GiNaC::lst vars;
        for (const ex& s : symbols_of(e)) vars.append(s);
        return e.is_polynomial(vars) ? GiNaC::expand(e) : e;
    }
    const SymbolTable& table_;
    const exmap& point_;
    GiNaC::exset targets_;
    std::map<ex, Jet, GiNaC::ex_is_less> z_;
};

bool holds_intermediates(const SymbolTable& table, const std::vector<ex>& es) {
    for (const ex& e : es)
        for (const ex& s : symbols_of(e))
            if (table.owns(s) && table.kind(s) == SymbolKind::intermediate) return true;
    return false;
}

}  // namespace

FirstOrderEquations to_first_order(const KaneEquations& kane) {
    FirstOrderEquations f;
    f.states = kane.coordinates;
    f.states.insert(f.states.end(), kane.independent_speeds.begin(),
                    kane.independent_speeds.end());
    f.rates = kane.coordinate_rate_symbols;
    f.rates.insert(f.rates.end(), kane.dynamics.unknowns.begin(), kane.dynamics.unknowns.end());
    // kinematic rows q' - k(q, u), except where q' is itself a state (u = q')
    for (std::size_t i = 0; i < kane.coordinates.size(); ++i)
        if (!contains(f.states, kane.coordinate_rate_symbols[i]))
            f.residuals.push_back(kane.coordinate_rate_symbols[i] - kane.coordinate_rates[i]);
    f.residuals.insert(f.residuals.end(), kane.residuals.begin(), kane.residuals.end());
    return f;
}

FirstOrderEquations to_first_order(const std::vector<ex>& residuals,
                                   const std::vector<TimeVariable>& q) {
    if (residuals.size() != q.size())
        throw ArgumentError("to_first_order(): " + std::to_string(residuals.size()) +
                            " equations for " + std::to_string(q.size()) +
                            " coordinates; give one second-order equation per coordinate");
    FirstOrderEquations f;
    for (const TimeVariable& qi : q) {
        if (qi.order() < 2)
            throw ArgumentError("to_first_order(): coordinate '" + qi.name() +
                                "' has no second derivative; declare it with order 2");
        f.states.push_back(qi.symbol());
        f.rates.push_back(qi.d(1));
    }
    for (const TimeVariable& qi : q) {
        f.states.push_back(qi.d(1));
        f.rates.push_back(qi.d(2));
    }
    f.residuals = residuals;
    return f;
}

LinearizedEquations linearize(const SymbolTable& table, const FirstOrderEquations& eqs,
                              const LinearizeOptions& options) {
    const std::vector<ex>& x = eqs.states;
    const std::size_t N = x.size();
    if (eqs.rates.size() != N)
        throw ArgumentError(kLinearize + std::to_string(N) + " states and " +
                            std::to_string(eqs.rates.size()) + " rates; give one rate per state");
    for (std::size_t i = 0; i < N; ++i) {
        require_symbol(x[i], "state");
        require_symbol(eqs.rates[i], "rate");
        if (index_of(x, x[i]) != i)
            throw ArgumentError(kLinearize + "state '" + to_string(x[i]) + "' is listed twice");
    }
    for (const ex& r : options.inputs) {
        require_symbol(r, "input");
        if (contains(x, r) || contains(eqs.rates, r))
            throw ArgumentError(kLinearize + "input '" + to_string(r) +
                                "' is a state or a rate; inputs are specified functions or "
                                "load measures");
    }

    // ---- the rates that are not states: the residuals fix them
    std::vector<ex> free;        // x_f'
    std::vector<std::size_t> free_row;  // the state row of each
    for (std::size_t i = 0; i < N; ++i)
        if (!contains(x, eqs.rates[i])) {
            free.push_back(eqs.rates[i]);
            free_row.push_back(i);
        }
    const std::size_t F = free.size();
    if (eqs.residuals.size() != F)
        throw ArgumentError(kLinearize + std::to_string(eqs.residuals.size()) + " residuals for " +
                            std::to_string(F) +
                            " rates that are not states; give one equation per such rate");
    for (const auto& [key, value] : options.operating_point)
        if (contains(free, key))
            throw ArgumentError(kLinearize + "the operating point gives a value for the rate '" +
                                to_string(key) +
                                "'; give the states only, the rates follow from the equations");
    const exmap& op = options.operating_point;

    const std::string singular =
        kLinearize +
        "the equations cannot be solved for the rates at the operating point "
        "(singular mass matrix there); choose another operating point or coordinates";
    const std::size_t R = options.inputs.size();
    GiNaC::matrix M(static_cast<unsigned>(F), static_cast<unsigned>(F)),
        b(static_cast<unsigned>(F), 1);
    GiNaC::matrix J(static_cast<unsigned>(F), static_cast<unsigned>(N + R));
    exmap free0;
    for (const ex& r : free) free0[r] = 0;
    GiNaC::matrix xf0;
    exmap at_op = op;  // states, inputs and rates at the operating point
    if (holds_intermediates(table, eqs.residuals)) {
        // ---- through the intermediates, at the operating point (forward mode): M x_f' = b
        // with the rates zero, then [dE/dx dE/dr] with the rates there
        exmap at_zero = op;
        for (const ex& r : free) at_zero[r] = 0;
        PointJets zero(table, at_zero, free, eqs.residuals);
        for (unsigned i = 0; i < F; ++i) {
            Jet e = zero.jet(eqs.residuals[i]);
            for (unsigned j = 0; j < F; ++j) {
                auto d = e.d.find(free[j]);
                M(i, j) = d == e.d.end() ? ex(0) : -d->second;
            }
            b(i, 0) = e.value;
        }
        xf0 = detail::solve_by_blocks(M, b, free, singular);
        for (unsigned j = 0; j < F; ++j) at_op[free[j]] = xf0(j, 0);
        std::vector<ex> targets = x;
        targets.insert(targets.end(), options.inputs.begin(), options.inputs.end());
        targets.insert(targets.end(), free.begin(), free.end());
        PointJets there(table, at_op, targets, eqs.residuals);
        for (unsigned i = 0; i < F; ++i) {
            Jet e = there.jet(eqs.residuals[i]);
            auto d_of = [&](const ex& t) {
                auto d = e.d.find(t);
                return d == e.d.end() ? ex(0) : d->second;
            };
            for (unsigned j = 0; j < N; ++j) J(i, j) = d_of(x[j]);
            for (unsigned k = 0; k < R; ++k)
                J(i, static_cast<unsigned>(N) + k) = d_of(options.inputs[k]);
            // linear in the rates: the same coefficients with the rates zero and there
            for (unsigned j = 0; j < F; ++j)
                if (!equal(-d_of(free[j]), M(i, j)))
                    throw SolveError(kLinearize + "equation " + std::to_string(i + 1) +
                                     " is not linear in the rate '" + to_string(free[j]) +
                                     "' (its coefficient changes with the rates)");
        }
    } else {
        // ---- M x_f' = b: the rates at the operating point
        std::vector<ex> E = eqs.residuals;
        for (unsigned i = 0; i < F; ++i) {
            for (unsigned j = 0; j < F; ++j) {
                ex a = E[i].diff(sym(free[j]));
                for (const ex& r : free)
                    if (a.has(r))
                        throw SolveError(kLinearize + "equation " + std::to_string(i + 1) +
                                         " is not linear in the rate '" + to_string(free[j]) +
                                         "' (its coefficient holds '" + to_string(r) + "')");
                M(i, j) = -a.subs(op);
            }
            b(i, 0) = E[i].subs(free0).subs(op);
        }
        xf0 = detail::solve_by_blocks(M, b, free, singular);
        for (unsigned j = 0; j < F; ++j) at_op[free[j]] = xf0(j, 0);

        // ---- [dE/dx dE/dr] at the operating point
        for (unsigned i = 0; i < F; ++i) {
            for (unsigned j = 0; j < N; ++j)
                J(i, j) = with_sign_derivatives(E[i].diff(sym(x[j])).subs(at_op));
            for (unsigned k = 0; k < R; ++k)
                J(i, static_cast<unsigned>(N) + k) =
                    with_sign_derivatives(E[i].diff(sym(options.inputs[k])).subs(at_op));
        }
    }
    // ---- M [A_f B_f] = [dE/dx dE/dr]
    GiNaC::matrix AB = detail::solve_by_blocks(M, J, free, singular);

    // ---- assemble: unit rows for rates that are states, solved rows for the others
    LinearizedEquations out;
    out.states = x;
    out.inputs = options.inputs;
    out.A = GiNaC::matrix(static_cast<unsigned>(N), static_cast<unsigned>(N));
    out.B = GiNaC::matrix(static_cast<unsigned>(N), static_cast<unsigned>(R));
    out.operating_rates.assign(N, 0);
    for (std::size_t i = 0; i < N; ++i) {
        std::size_t j = index_of(x, eqs.rates[i]);
        if (j < N) {
            out.A(static_cast<unsigned>(i), static_cast<unsigned>(j)) = 1;
            out.operating_rates[i] = x[j].subs(op);
        }
    }
    auto tidy = [&](const ex& e) { return options.simplify ? simplify(GiNaC::normal(e)) : e; };
    for (unsigned f = 0; f < F; ++f) {
        const unsigned i = static_cast<unsigned>(free_row[f]);
        for (unsigned j = 0; j < N; ++j) out.A(i, j) = tidy(AB(f, j));
        for (unsigned k = 0; k < R; ++k) out.B(i, k) = tidy(AB(f, static_cast<unsigned>(N) + k));
        out.operating_rates[i] = tidy(xf0(f, 0));
    }
    return out;
}

SecondOrderLinearization linearize_second_order(const SymbolTable& table,
                                                const std::vector<ex>& residuals,
                                                const std::vector<TimeVariable>& q,
                                                const LinearizeOptions& options) {
    // the first-order linearization checks the lists and gives q0'' (its rates q0', q0'')
    LinearizeOptions first = options;
    first.simplify = false;
    const LinearizedEquations lin = linearize(table, to_first_order(residuals, q), first);
    const unsigned n = static_cast<unsigned>(q.size());
    const unsigned R = static_cast<unsigned>(options.inputs.size());
    exmap at_op = options.operating_point;
    for (unsigned i = 0; i < n; ++i) at_op[q[i].d(2)] = lin.operating_rates[n + i];
    auto tidy = [&](const ex& e) { return options.simplify ? simplify(GiNaC::normal(e)) : e; };
    SecondOrderLinearization out;
    out.inputs = options.inputs;
    out.M = out.C = out.K = GiNaC::matrix(n, n);
    out.H = GiNaC::matrix(n, R);
    for (unsigned i = 0; i < n; ++i) {
        out.coordinates.push_back(q[i].symbol());
        const ex E = table.expand_intermediates(residuals[i]);
        for (unsigned j = 0; j < n; ++j) {
            out.M(i, j) = tidy(-with_sign_derivatives(E.diff(sym(q[j].d(2))).subs(at_op)));
            out.C(i, j) = tidy(-with_sign_derivatives(E.diff(sym(q[j].d(1))).subs(at_op)));
            out.K(i, j) = tidy(-with_sign_derivatives(E.diff(sym(q[j].symbol())).subs(at_op)));
        }
        for (unsigned k = 0; k < R; ++k)
            out.H(i, k) = tidy(with_sign_derivatives(E.diff(sym(options.inputs[k])).subs(at_op)));
    }
    return out;
}

}  // namespace alembert
