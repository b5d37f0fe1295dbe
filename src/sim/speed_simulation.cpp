// SPDX-License-Identifier: MIT
// Forward simulation of Kane's equations in generalized speeds: the state (q, u_r), q' and
// the dependent speeds from their expressions, u_r' from the mass matrix factored numerically.
#include "alembert/sim/speed_simulation.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "number_text.hpp"
#include "ode_run.hpp"

namespace alembert {

namespace {

using detail::number;

// The numbers of Kane's equations in speeds at one state: one function of [t, q, u_r] giving
// [q', u_s, M row-major, f], the mass matrix solved for u_r'.
class SpeedEquationNumbers {
public:
    SpeedEquationNumbers(std::string who, NumericFunction f, std::size_t n, std::size_t k,
                         std::size_t m, std::vector<std::string> names)
        : who_(std::move(who)), f_(std::move(f)), n_(n), k_(k), m_(m), names_(std::move(names)),
          in_(1 + n + k), out_(n + m + k * k + k),
          M_(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)),
          b_(static_cast<Eigen::Index>(k)), x_(static_cast<Eigen::Index>(k)) {}

    std::size_t coordinates() const { return n_; }
    std::size_t independent() const { return k_; }
    std::size_t dependent() const { return m_; }

    // q' (n), u_s (m) and u_r' (k) at (t, q, u_r); qd, us or urd may be null
    void calc(double t, const double* q, const double* ur, double* qd, double* us, double* urd) {
        in_[0] = t;
        std::copy(q, q + n_, in_.begin() + 1);
        std::copy(ur, ur + k_, in_.begin() + 1 + static_cast<std::ptrdiff_t>(n_));
        f_.evaluate(in_.data(), out_.data());
        for (std::size_t i = 0; i < n_ + m_; ++i)
            if (!std::isfinite(out_[i]))
                fail(i < n_ ? "the rate " + names_[i] + "' from the kinematic equations is " + number(out_[i])
                            : "the dependent speed " + names_[n_ + k_ + i - n_] +
                                  " from the motion constraints is " + number(out_[i]) +
                                  " (the constraints cannot be solved for it there)");
        if (qd) std::copy(out_.begin(), out_.begin() + static_cast<std::ptrdiff_t>(n_), qd);
        if (us)
            std::copy(out_.begin() + static_cast<std::ptrdiff_t>(n_),
                      out_.begin() + static_cast<std::ptrdiff_t>(n_ + m_), us);
        if (urd) solve(urd);
    }

private:
    void solve(double* urd) {
        const auto K = static_cast<Eigen::Index>(k_);
        const double* M = out_.data() + n_ + m_;
        double largest = 0;
        for (Eigen::Index r = 0; r < K; ++r) {
            for (Eigen::Index c = 0; c < K; ++c) {
                const double a = M[r * K + c];
                if (!std::isfinite(a))
                    fail("the mass matrix entry (" + std::to_string(r + 1) + ", " + std::to_string(c + 1) +
                         ") is " + number(a));
                M_(r, c) = a;
                largest = std::max(largest, std::abs(a));
            }
            const double f = M[K * K + r];
            if (!std::isfinite(f)) fail("the forcing of equation " + std::to_string(r + 1) + " is " + number(f));
            b_(r) = f;
        }
        bool symmetric = true;
        for (Eigen::Index r = 0; r < K && symmetric; ++r)
            for (Eigen::Index c = r + 1; c < K; ++c)
                symmetric = symmetric && std::abs(M_(r, c) - M_(c, r)) <= 1e-12 * largest;
        bool solved = false;
        if (symmetric) {
            ldlt_.compute(M_);
            const Eigen::VectorXd& d = ldlt_.vectorD();
            if (ldlt_.info() == Eigen::Success && ldlt_.isPositive() &&
                (K == 0 || d.minCoeff() > kMinRcond * d.cwiseAbs().maxCoeff()) && ldlt_.rcond() > kMinRcond) {
                x_ = ldlt_.solve(b_);
                solved = true;
            }
        }
        if (!solved) {
            lu_.compute(M_);
            const Eigen::VectorXd p = lu_.matrixLU().diagonal().cwiseAbs();
            const double ratio = K == 0 ? 1.0 : (p.maxCoeff() > 0 ? p.minCoeff() / p.maxCoeff() : 0.0);
            const double rcond = std::min(lu_.rcond(), ratio);
            if (!(rcond > kMinRcond))
                fail("the mass matrix of the independent speeds is singular or ill-conditioned "
                     "(reciprocal condition estimate " + number(rcond) + ")");
            x_ = lu_.solve(b_);
        }
        for (Eigen::Index r = 0; r < K; ++r) {
            if (!std::isfinite(x_(r)))
                fail("the solution for " + names_[n_ + static_cast<std::size_t>(r)] + "' is " + number(x_(r)));
            urd[r] = x_(r);
        }
    }

    [[noreturn]] void fail(const std::string& what) const {
        std::string state = "t = " + number(in_[0]);
        for (std::size_t i = 0; i < n_ + k_; ++i) state += ", " + names_[i] + " = " + number(in_[1 + i]);
        throw SolveError(who_ + what + " at " + state +
                         "; check the masses and inertias, or whether the speeds or the constraints "
                         "are singular in this configuration (choose other dependent speeds)");
    }

    static constexpr double kMinRcond = 1e-13;
    std::string who_;
    NumericFunction f_;
    std::size_t n_, k_, m_;
    std::vector<std::string> names_;  // q_1..q_n, u_r..., u_s...
    std::vector<double> in_, out_;
    Eigen::MatrixXd M_;
    Eigen::VectorXd b_, x_;
    Eigen::LDLT<Eigen::MatrixXd> ldlt_;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

bool holds_any(const SymbolTable& table, const ex& e, const std::vector<ex>& symbols) {
    return std::any_of(symbols.begin(), symbols.end(), [&](const ex& s) { return table.depends_on(e, s); });
}

}  // namespace

SimulationResult run_speed_simulation(System& sys, const KaneEquations& kane,
                                      const SimulationRequest& request) {
    SymbolTable& table = sys.symbols();
    const std::string who = "run_simulation('" + request.model + "'): ";
    ALEMBERT_CHECK_ARG(!kane.kinematic_equations.empty(),
                       who + "the Kane's equations have no chosen speeds (u_r = q_r'); simulate "
                             "them with run_simulation");
    ALEMBERT_CHECK_ARG(kane.auxiliary_equations.size() == kane.auxiliary_speeds.size() &&
                           std::none_of(kane.auxiliary_speeds.begin(), kane.auxiliary_speeds.end(),
                                        [&](const ex& ua) {
                                            return std::any_of(kane.speeds.begin(), kane.speeds.end(),
                                                               [&](const ex& u) { return u.is_equal(ua); });
                                        }),
                       who + "the Kane's equations' auxiliary speeds must each have their auxiliary "
                             "equation and be none of the speeds (form them with "
                             "KaneOptions::auxiliary_speeds)");
    ALEMBERT_CHECK_ARG(request.constraint_forces.empty(),
                       who + "constraint forces are solved by run_simulation's road-map, not by "
                             "Kane's equations in generalized speeds: give the constraints to "
                             "form_kane_equations as motion constraints");
    const std::vector<ex>& q = kane.coordinates;
    const std::vector<ex>& ur = kane.independent_speeds;
    const std::vector<ex>& us = kane.dependent_speeds;
    const std::size_t n = q.size(), k = ur.size(), m = us.size();
    const auto name_of = [&](const ex& x) { return table.name(x); };

    // ---- load measures and specified quantities by their formulas
    exmap loads;
    for (const auto& [measure, formula] : request.inputs)
        ALEMBERT_CHECK_ARG(table.owns(measure) && table.kind(measure) == SymbolKind::unknown,
                           who + "an input is given for '" + to_string(measure) +
                               "', which is not a load measure of the model");
    const std::vector<ex> aux_measures = auxiliary_measures(table, kane, request.inputs);
    const auto is_aux_measure = [&](const ex& x) {
        return std::any_of(aux_measures.begin(), aux_measures.end(), [&](const ex& y) { return y.is_equal(x); });
    };
    for (const ex& measure : table.symbols(SymbolKind::unknown)) {
        auto it = request.inputs.find(measure);
        if (it != request.inputs.end()) {
            loads[measure] = it->second;
            continue;
        }
        if (is_aux_measure(measure)) continue;  // solved from the auxiliary equations below
        // a constraint force or reaction an output reads: these equations do not hold it
        const auto reads = [&](const ex& e) { return table.depends_on(e, measure); };
        if (std::any_of(request.outputs.begin(), request.outputs.end(),
                        [&](const OutputSpec& o) { return reads(o.expression); }) ||
            std::any_of(request.events.begin(), request.events.end(),
                        [&](const EventSpec& e) { return reads(e.expression); }))
            throw ArgumentError(who + "an output or stop condition reads the load measure '" +
                                to_string(measure) +
                                "', which Kane's equations in generalized speeds do not determine "
                                "(a measure without an input is zero there); give it by an input, "
                                "or leave it out of the outputs");
        loads[measure] = 0;
    }
    for (const auto& [symbol, formula] : request.specified) {
        ALEMBERT_CHECK_ARG(table.owns(symbol) && table.kind(symbol) == SymbolKind::specified,
                           who + "a value is given for '" + to_string(symbol) +
                               "', which is not a specified quantity of the model");
        loads[symbol] = formula;
    }
    // the auxiliary speeds and their rates are zero in the motion
    exmap aux_zero;
    for (const ex& ua : kane.auxiliary_speeds) {
        aux_zero[ua] = 0;
        aux_zero[table.dt(ua)] = 0;
    }
    const auto expanded = [&](const ex& e) {
        return request.specified.empty() ? e : table.expand_intermediates(e);
    };
    // q' -> k(q, u_r, t), u_s -> their values: a formula of the state in (t, q, u_r)
    exmap to_state;
    for (std::size_t i = 0; i < n; ++i) to_state[kane.coordinate_rate_symbols[i]] = kane.coordinate_rates[i];
    for (std::size_t s = 0; s < m; ++s) to_state[us[s]] = kane.dependent_speed_values[s];
    for (const auto& [ua, zero] : aux_zero) to_state[ua] = zero;
    const auto in_state = [&](const ex& e) { return expanded(e).subs(loads).subs(to_state); };

    // ---- the constraint forces the auxiliary equations determine, for outputs and events
    exmap aux_solution;
    if (!aux_measures.empty()) {
        const std::size_t a = kane.auxiliary_equations.size();
        std::string listed;
        for (const ex& x : aux_measures) listed += (listed.empty() ? "" : ", ") + to_string(x);
        if (aux_measures.size() != a)
            throw ArgumentError(who + "the " + std::to_string(a) + " auxiliary equation" + (a == 1 ? "" : "s") +
                                " of Kane's equations " + (a == 1 ? "holds " : "hold ") +
                                std::to_string(aux_measures.size()) +
                                " load measure" + (aux_measures.size() == 1 ? "" : "s") + " without an input (" +
                                listed + "); they determine the constraint forces when there is one "
                                "measure per auxiliary speed: give the others inputs, or one auxiliary "
                                "speed per constraint force");
        // a constraint force does no work in the motion: it must not act in the dynamics
        for (unsigned r = 0; r < k; ++r) {
            const std::vector<bool> acts = calc_changes_with_at_random_states(
                table, expanded(kane.dynamics.b(r, 0)).subs(to_state), aux_measures);
            for (std::size_t j = 0; j < acts.size(); ++j)
                if (acts[j])
                    throw ArgumentError(who + "the load measure '" + to_string(aux_measures[j]) +
                                        "', which the auxiliary equations determine, also acts in the "
                                        "dynamical equation of " + to_string(ur[r]) +
                                        ": it does work in the motion, so it is not a constraint force "
                                        "the auxiliary speeds bring out; give it an input, or open the "
                                        "constraint it enforces with its own auxiliary speed");
        }
        std::vector<ex> residuals;
        for (const ex& e : kane.auxiliary_equations)
            residuals.push_back(table.expand_intermediates(expanded(e).subs(loads)).subs(aux_zero));
        try {
            const std::vector<ex> solved = solve_symbolic(form_linear_system(residuals, aux_measures));
            for (std::size_t j = 0; j < aux_measures.size(); ++j) aux_solution[aux_measures[j]] = solved[j];
        } catch (const SolveError& e) {
            throw SolveError(who + "the auxiliary equations cannot be solved for " + listed + ": " + e.what());
        }
    }

    // ---- the numbers at a state: [t, q, u_r] -> [q', u_s, M, f]
    std::vector<ex> in{table.time()};
    in.insert(in.end(), q.begin(), q.end());
    in.insert(in.end(), ur.begin(), ur.end());
    std::vector<ex> out_exprs;
    for (const ex& r : kane.coordinate_rates) out_exprs.push_back(in_state(r));
    for (const ex& v : kane.dependent_speed_values) out_exprs.push_back(in_state(v));
    for (unsigned r = 0; r < k; ++r)
        for (unsigned c = 0; c < k; ++c) out_exprs.push_back(in_state(kane.dynamics.A(r, c)));
    for (unsigned r = 0; r < k; ++r) out_exprs.push_back(in_state(kane.dynamics.b(r, 0)));
    NumericFunction state_function;
    try {
        state_function = make_numeric_function(table, in, out_exprs, request.make);
    } catch (const ArgumentError& e) {
        throw ArgumentError(who + e.what() +
                            "; Kane's equations in speeds may depend on t, the coordinates, the "
                            "independent speeds, load measures given by inputs and constants "
                            "with values");
    }
    std::vector<std::string> names;
    for (const ex& x : q) names.push_back(name_of(x));
    for (const ex& x : ur) names.push_back(name_of(x));
    for (const ex& x : us) names.push_back(name_of(x));
    SpeedEquationNumbers numbers("forward dynamics of '" + request.model + "' in generalized speeds: ",
                                 std::move(state_function), n, k, m, names);

    // ---- what outputs see: [t, q, q', u_r, u_s, u_r'], laid out as a StateLayout
    StateLayout layout;
    layout.time = table.time();
    layout.coordinates = q;
    layout.rates = kane.coordinate_rate_symbols;
    for (const ex& x : q) layout.coordinate_names.push_back(name_of(x));
    layout.unknowns = ur;
    layout.unknowns.insert(layout.unknowns.end(), us.begin(), us.end());
    std::vector<ex> ur_rates;
    for (const ex& u : ur) ur_rates.push_back(table.dt(u));
    layout.unknowns.insert(layout.unknowns.end(), ur_rates.begin(), ur_rates.end());
    // q'' (declared) and u_s' in terms of the layout
    exmap second_order;
    std::vector<ex> replaced;
    for (std::size_t i = 0; i < n; ++i) {
        const TimeVariable v = table.variable(name_of(q[i]));
        if (v.order() >= 2) replaced.push_back(v.d(2));
    }
    for (const ex& u : us) replaced.push_back(table.dt(u));
    const auto for_outputs = [&](const ex& e) {
        ex x = expanded(e).subs(aux_solution).subs(loads);
        if (!aux_zero.empty()) x = table.expand_intermediates(x).subs(aux_zero);
        if (!holds_any(table, x, replaced)) return x;
        if (second_order.empty()) {
            for (std::size_t i = 0; i < n; ++i) {
                const TimeVariable v = table.variable(name_of(q[i]));
                if (v.order() >= 2) second_order[v.d(2)] = table.dt(kane.coordinate_rates[i]);
            }
            for (std::size_t s = 0; s < m; ++s) second_order[table.dt(us[s])] = kane.dependent_speed_rates[s];
        }
        return table.expand_intermediates(x).subs(second_order);
    };

    // ---- outputs: the user's, then the checks
    std::vector<OutputSpec> outputs = request.outputs;
    std::vector<std::string> drift_names;  // the drift columns, with what they check
    std::vector<std::string> drift_what;
    std::vector<ex> initial_checks;        // residuals and rates checked at the start
    std::vector<std::string> initial_what;
    if (request.checks) {
        // energy is kept when the loads without a potential do no work, nothing is driven and
        // the velocities vanish with the independent speeds (no B_s, no rheonomic q')
        bool conservative = request.specified.empty();
        exmap rest;
        for (const ex& u : ur) rest[u] = 0;
        for (const ex& r : kane.coordinate_rates)
            conservative = conservative && is_zero_at_random_states(table, r.subs(rest));
        for (const ex& v : kane.dependent_speed_values)
            conservative = conservative && is_zero_at_random_states(table, v.subs(rest));
        if (conservative) {
            const Frame& N = sys.newtonian();
            ex power = 0;
            for (const Load& l : sys.loads()) {
                if (l.conservative) continue;
                if (l.kind == LoadKind::force) power += dot(l.point->vel_in(N), l.vector);
                else if (l.on->frame()) power += dot(l.on->frame()->ang_vel_in(N), l.vector);
            }
            conservative = is_zero_at_random_states(table, in_state(power));
        }
        if (conservative) {
            // a model whose bodies are placed by velocities alone (a bicycle's rear contact at
            // rest, its position never stated) has no potential energy: no energy column then
            try {
                outputs.push_back({"energy",
                                   sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy(), "J"});
            } catch (const ModelError&) {
            }
        }
        const auto unit_of = [&](const std::string& name) {
            auto it = request.constraint_units.find(name);
            return it == request.constraint_units.end() ? std::string() : it->second;
        };
        for (std::size_t i = 0; i < kane.motion_constraints.size(); ++i) {
            const std::string name = "motion_" + std::to_string(i + 1);
            outputs.push_back({"drift_" + name, kane.motion_constraints[i], unit_of(name), 1.0});
            drift_names.push_back(name);
            drift_what.push_back("motion constraint " + std::to_string(i + 1) + " of Kane's equations");
        }
        const auto& t = GiNaC::ex_to<GiNaC::symbol>(table.time());
        for (const Constraint& c : sys.constraints()) {
            outputs.push_back({"drift_" + c.name, c.residual, unit_of(c.name), 1.0});
            drift_names.push_back(c.name);
            drift_what.push_back(std::string("the ") + to_string(c.kind) + " constraint '" + c.name + "'");
            const ex r = table.expand_intermediates(c.residual);
            initial_checks.push_back(r);
            initial_what.push_back(drift_what.back());
            if (c.kind != ConstraintKind::configuration) continue;
            ex rate = r.diff(t);
            for (std::size_t i = 0; i < n; ++i)
                rate += r.diff(GiNaC::ex_to<GiNaC::symbol>(q[i])) * kane.coordinate_rate_symbols[i];
            initial_checks.push_back(rate);
            initial_what.push_back("the rate of the configuration constraint '" + c.name + "'");
        }
    }
    for (OutputSpec& o : outputs) o.expression = for_outputs(o.expression);
    OutputFunction out = compile_outputs(table, layout, outputs, request.make);
    std::vector<EventSpec> event_specs = request.events;
    for (EventSpec& e : event_specs) e.expression = for_outputs(e.expression);
    EventFunction events = compile_events(table, layout, event_specs, request.make);

    // ---- the state at a time: [t, q, q', u_r, u_s, u_r'] for outputs and events
    const std::size_t width = 1 + 2 * n + 2 * k + m;
    std::vector<double> row(width);
    const auto gather = [&](double t, const detail::OdeState& x) -> const double* {
        row[0] = t;
        std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), row.begin() + 1);
        std::copy(x.begin() + static_cast<std::ptrdiff_t>(n), x.end(),
                  row.begin() + static_cast<std::ptrdiff_t>(1 + 2 * n));
        numbers.calc(t, x.data(), x.data() + n, row.data() + 1 + n, row.data() + 1 + 2 * n + k,
                     row.data() + 1 + 2 * n + k + m);
        return row.data();
    };
    const auto rhs = [&](const detail::OdeState& x, detail::OdeState& dxdt, double t) {
        numbers.calc(t, x.data(), x.data() + n, dxdt.data(), nullptr, dxdt.data() + n);
    };

    // ---- initial values: q and u_r; a dependent speed or a rate given is checked
    const double t0 = request.options.t_initial, tol = request.options.constraint_tolerance;
    detail::OdeState x0(n + k, 0.0);
    std::vector<std::pair<ex, double>> checked;  // u_s or q' given, with its value
    for (const auto& given : request.initial_values) {
        const ex& symbol = given.first;  // named, not bound: a lambda may capture it
        const double v = table.evaluate(given.second);
        const auto at = [&](const std::vector<ex>& list) {
            return static_cast<std::size_t>(
                std::find_if(list.begin(), list.end(), [&](const ex& x) { return x.is_equal(symbol); }) -
                list.begin());
        };
        if (std::size_t i = at(q); i < n) x0[i] = v;
        else if (std::size_t r = at(ur); r < k) x0[n + r] = v;
        else if (at(us) < m || at(kane.coordinate_rate_symbols) < n) checked.emplace_back(symbol, v);
        else
            throw ArgumentError(who + "an initial value is given for '" + to_string(symbol) +
                                "', which is neither a coordinate nor a speed of the Kane's "
                                "equations; give the coordinates " + to_string(q.front()) +
                                ", ... and the independent speeds");
    }
    const double* start = gather(t0, x0);
    for (const auto& [symbol, v] : checked) {
        std::size_t j = 0;
        for (; j < width; ++j)
            if ((j >= 1 + n && j < 1 + 2 * n && symbol.is_equal(layout.rates[j - 1 - n])) ||
                (j >= 1 + 2 * n + k && j < 1 + 2 * n + k + m && symbol.is_equal(us[j - 1 - 2 * n - k])))
                break;
        const double follows = start[j];
        if (std::abs(v - follows) <= tol * std::max(1.0, std::abs(follows))) continue;
        const bool dependent = j >= 1 + 2 * n;
        throw ArgumentError(who + "the initial value " + number(v) + " of '" + to_string(symbol) +
                            "' disagrees with " + number(follows) + ", its value from the " +
                            (dependent ? "motion constraints" : "kinematic equations") +
                            " at the initial coordinates and independent speeds; leave it out (" +
                            (dependent ? "dependent speeds follow from the independent ones"
                                       : "the coordinates' rates follow from the speeds") +
                            ") or give independent speeds that make it so");
    }
    if (!initial_checks.empty()) {
        NumericFunction f = make_numeric_function(table, [&] {
            std::vector<ex> all{layout.time};
            all.insert(all.end(), layout.coordinates.begin(), layout.coordinates.end());
            all.insert(all.end(), layout.rates.begin(), layout.rates.end());
            all.insert(all.end(), layout.unknowns.begin(), layout.unknowns.end());
            return all;
        }(), [&] {
            std::vector<ex> e;
            for (const ex& c : initial_checks) e.push_back(expanded(c).subs(loads));
            return e;
        }(), {});
        std::vector<double> values(initial_checks.size());
        f.evaluate(start, values.data());
        for (std::size_t j = 0; j < values.size(); ++j)
            if (!(std::abs(values[j]) <= tol))
                throw ArgumentError(who + "the initial state violates " + initial_what[j] + ": its residual is " +
                                    number(values[j]) + " at t = " + number(t0) + " s, beyond the tolerance " +
                                    number(tol) + " (SimulationOptions::constraint_tolerance); give "
                                    "initial coordinates and speeds that satisfy it");
    }

    // ---- the run; it stops at the first output row where a constraint has drifted too far
    std::function<void(const Table&, std::size_t)> check_row;
    if (!drift_names.empty())
        check_row = [&](const Table& t, std::size_t r) {
            for (std::size_t c = 0; c < drift_names.size(); ++c) {
                const std::size_t col = t.column_index("drift_" + drift_names[c]);
                const double v = t.columns[col][r];
                if (std::abs(v) <= tol) continue;
                const std::string unit = t.units[col].empty() ? "" : " " + t.units[col];
                throw SolveError(who + "the residual of " + drift_what[c] + " grew to " + number(v) +
                                 unit + " at t = " + number(t.columns[0][r]) + " s, beyond the tolerance " +
                                 number(tol) + unit +
                                 " (SimulationOptions::constraint_tolerance): Kane's equations in "
                                 "generalized speeds keep only their own motion constraints, and the "
                                 "integration drifts off this one; give its rate to the Kane's "
                                 "equations as a motion constraint, tighten the error tolerances "
                                 "(tolerance abs 1e-10 rel 1e-10), or shorten the run");
            }
        };
    detail::OdeState x_end;
    SimulationResult result = detail::integrate_with_outputs(request.model, x0, rhs, gather, request.options,
                                                             out, events, check_row, x_end);
    result.q_end.assign(x_end.begin(), x_end.begin() + static_cast<std::ptrdiff_t>(n));
    result.u_end.assign(x_end.begin() + static_cast<std::ptrdiff_t>(n), x_end.end());
    result.qd_end.resize(n);
    numbers.calc(result.t_end, x_end.data(), x_end.data() + n, result.qd_end.data(), nullptr, nullptr);
    return result;
}

std::vector<ex> auxiliary_measures(const SymbolTable& table, const KaneEquations& kane, const exmap& inputs) {
    std::vector<ex> measures;
    if (kane.auxiliary_equations.empty()) return measures;
    for (const ex& measure : table.symbols(SymbolKind::unknown))
        if (!inputs.count(measure) &&
            std::any_of(kane.auxiliary_equations.begin(), kane.auxiliary_equations.end(),
                        [&](const ex& e) { return table.depends_on(e, measure); }))
            measures.push_back(measure);
    return measures;
}

}  // namespace alembert
