// SPDX-License-Identifier: MIT
// Forward simulation: the chosen integrator's steps, dense output at the output times, events.
#include "alembert/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/sim/contact_loads.hpp"
#include "alembert/error.hpp"
#include "alembert/sim/progress.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "dense_stepper.hpp"
#include "ode_run.hpp"
#include "number_text.hpp"

namespace alembert {

namespace {

using State = detail::OdeState;

using detail::number;

// [t, q, q', x, inputs]: the inputs of output and event functions
std::vector<ex> output_inputs(const StateLayout& layout) {
    std::vector<ex> in{layout.time};
    in.insert(in.end(), layout.coordinates.begin(), layout.coordinates.end());
    in.insert(in.end(), layout.rates.begin(), layout.rates.end());
    in.insert(in.end(), layout.unknowns.begin(), layout.unknowns.end());
    in.insert(in.end(), layout.inputs.begin(), layout.inputs.end());
    return in;
}

NumericFunction compile_over_layout(const SymbolTable& table, const StateLayout& layout,
                                    const std::vector<ex>& expressions, const char* caller,
                                    const FunctionMaker& make) {
    try {
        return make_numeric_function(table, output_inputs(layout), expressions, make);
    } catch (const ArgumentError& e) {
        throw ArgumentError(std::string(caller) + ": " + e.what() +
                            "; an output may use t, the coordinates, their rates, the unknowns "
                            "of the equations (accelerations, constraint forces), the inputs and "
                            "constants with values");
    }
}

std::string names_of(const std::vector<ex>& list) {
    std::string text;
    for (const ex& x : list) text += (text.empty() ? "'" : ", '") + to_string(x) + "'";
    return text;
}

// the values of `expressions` (over the layout of fd) at the initial state
std::vector<double> calc_at_start(const SymbolTable& table, const ForwardDynamics& fd,
                                  const std::vector<ex>& expressions, const std::vector<double>& q0,
                                  const std::vector<double>& qd0, double t0) {
    const NumericFunction f =
        compile_over_layout(table, fd.layout(), expressions, "run_simulation()", {});
    const std::size_t n = fd.coordinate_count();
    std::vector<double> in(1 + 2 * n + fd.unknown_count() + fd.input_count(), 0.0);
    in[0] = t0;
    std::copy(q0.begin(), q0.end(), in.begin() + 1);
    std::copy(qd0.begin(), qd0.end(), in.begin() + 1 + static_cast<std::ptrdiff_t>(n));
    fd.calc_unknowns(t0, q0.data(), qd0.data(), nullptr, in.data() + 1 + 2 * n);
    std::vector<double> values(expressions.size());
    f.evaluate(in.data(), values.data());
    return values;
}

// thrown where the recursive formation's q'' are not finite, to retry on the dense equations
struct RecursionNotFinite : SolveError {
    RecursionNotFinite() : SolveError("the recursive formation's accelerations are not finite") {}
};

// the load laws (formulas of t, q, q') as one function of [t, q, q']
NumericFunction compile_over_layout_inputs(const SymbolTable& table, const std::vector<ex>& state,
                                           const std::vector<ex>& laws, const FunctionMaker& make) {
    try {
        return make_numeric_function(table, state, laws, make);
    } catch (const ArgumentError& e) {
        throw ArgumentError(std::string("run_simulation(): an input law: ") + e.what() +
                            "; an input is a formula of t, the coordinates, their rates and "
                            "constants with values");
    }
}

// the state at one instant and the functions of it
struct Evaluator {
    const ForwardDynamics& fd;
    const InputFunction& inputs;
    std::vector<double> in, u;

    Evaluator(const ForwardDynamics& f, const InputFunction& i)
        : fd(f),
          inputs(i),
          in(1 + 2 * f.coordinate_count() + f.unknown_count() + f.input_count()),
          u(f.input_count(), 0.0) {}

    // fills in = [t, q, q', x, inputs] from the state [q, q']
    const double* gather(double t, const State& x) {
        const std::size_t n = fd.coordinate_count(), k = fd.unknown_count();
        if (inputs) inputs(t, x.data(), x.data() + n, u.data());
        in[0] = t;
        std::copy(x.begin(), x.end(), in.begin() + 1);
        fd.calc_unknowns(t, x.data(), x.data() + n, u.data(), in.data() + 1 + 2 * n);
        std::copy(u.begin(), u.end(), in.begin() + static_cast<std::ptrdiff_t>(1 + 2 * n + k));
        return in.data();
    }
};

std::string residual_unit(const SimulationRequest& request, const std::string& constraint,
                          const char* per_time = "") {
    auto it = request.constraint_units.find(constraint);
    const std::string unit = it == request.constraint_units.end() ? "" : it->second;
    if (*per_time == 0) return unit.empty() ? "" : " " + unit;
    return " " + (unit.empty() ? std::string("1") : unit) + per_time;
}

// the declared constraints hold at the initial state: configuration residuals and their
// rates, motion residuals, each within the tolerance
void check_initial_constraints(const System& sys, const ForwardDynamics& fd,
                               const SimulationRequest& request, const std::vector<double>& q0,
                               const std::vector<double>& qd0) {
    if (sys.constraints().empty()) return;
    const SymbolTable& table = sys.symbols();
    const StateLayout& layout = fd.layout();
    const auto& t = GiNaC::ex_to<GiNaC::symbol>(table.time());
    std::vector<ex> residuals;
    std::vector<std::string> what, units;
    for (const Constraint& c : sys.constraints()) {
        const ex r = table.expand_intermediates(c.residual);
        residuals.push_back(r);
        what.push_back(std::string("the ") + to_string(c.kind) + " constraint '" + c.name + "'");
        units.push_back(residual_unit(request, c.name));
        if (c.kind != ConstraintKind::configuration) continue;
        // its rate: sum_i dr/dq_i q_i' + dr/dt
        ex rate = r.diff(t);
        for (std::size_t i = 0; i < layout.coordinates.size(); ++i)
            rate += r.diff(GiNaC::ex_to<GiNaC::symbol>(layout.coordinates[i])) * layout.rates[i];
        residuals.push_back(rate);
        what.push_back("the rate of the configuration constraint '" + c.name + "'");
        units.push_back(residual_unit(request, c.name, "/s"));
    }
    NumericFunction f = compile_over_layout(table, layout, residuals, "run_simulation()", {});
    std::vector<double> in(f.input_count, 0.0), out(f.output_count);
    in[0] = request.options.t_initial;
    std::copy(q0.begin(), q0.end(), in.begin() + 1);
    std::copy(qd0.begin(), qd0.end(), in.begin() + 1 + static_cast<std::ptrdiff_t>(q0.size()));
    f.evaluate(in.data(), out.data());
    const double tol = request.options.constraint_tolerance;
    for (std::size_t j = 0; j < out.size(); ++j)
        if (!(std::abs(out[j]) <= tol))
            throw ArgumentError(
                "run_simulation('" + request.model + "'): the initial state violates " + what[j] +
                ": its residual is " + number(out[j]) + units[j] + " at t = " +
                number(request.options.t_initial) + " s, beyond the tolerance " + number(tol) +
                units[j] + " (SimulationOptions::constraint_tolerance); the initial values are not moved "
                "onto the constraint silently: give initial coordinates and rates that satisfy "
                "it (solve the constraint for the dependent coordinates, e.g. with a statics "
                "road-map)");
}

// the drift columns of output row r stay within the tolerance
void check_constraint_drift(const System& sys, const SimulationRequest& request,
                            const Table& table, std::size_t r) {
    const double tol = request.options.constraint_tolerance;
    for (const Constraint& c : sys.constraints()) {
        const double v = table.columns[table.column_index("drift_" + c.name)][r];
        if (std::abs(v) <= tol) continue;
        throw SolveError(
            "run_simulation('" + request.model + "'): the residual of the constraint '" + c.name +
            "' grew to " + number(v) + residual_unit(request, c.name) + " at t = " +
            number(table.columns[0][r]) + " s, beyond the tolerance " + number(tol) +
            residual_unit(request, c.name) +
            " (SimulationOptions::constraint_tolerance): the integration drifts off the "
            "constraint, so the run stops here; tighten the error tolerances (tolerance abs "
            "1e-10 rel 1e-10), shorten the run, or check that the constraint forces are among "
            "the unknowns");
    }
}

}  // namespace

OutputFunction compile_outputs(const SymbolTable& table, const StateLayout& layout,
                               const std::vector<OutputSpec>& outputs, const FunctionMaker& make) {
    OutputFunction f;
    std::vector<ex> expressions;
    for (const OutputSpec& o : outputs) {
        Unit unit{o.unit, o.factor};
        if (o.factor == 0.0) {
            try {
                unit = parse_unit(o.unit);
            } catch (const ArgumentError& e) {
                throw ArgumentError("compile_outputs(): output '" + o.name + "': " + e.what());
            }
        }
        ALEMBERT_CHECK_ARG(std::isfinite(unit.factor) && unit.factor > 0,
                           "compile_outputs(): output '" + o.name + "': the unit factor " +
                               std::to_string(o.factor) + " is not a positive number");
        f.names.push_back(o.name);
        f.units.push_back(unit.name);
        f.factors.push_back(unit.factor);
        expressions.push_back(o.expression);
    }
    f.function = compile_over_layout(table, layout, expressions, "compile_outputs()", make);
    return f;
}

EventFunction compile_events(const SymbolTable& table, const StateLayout& layout,
                             const std::vector<EventSpec>& events, const FunctionMaker& make) {
    EventFunction f;
    std::vector<ex> expressions;
    for (const EventSpec& e : events) {
        f.names.push_back(e.name);
        f.directions.push_back(e.direction);
        expressions.push_back(e.expression);
    }
    f.function = compile_over_layout(table, layout, expressions, "compile_events()", make);
    return f;
}

double calc_output_row_count(const SimulationOptions& options, const std::string& who) {
    const double t0 = options.t_initial, tf = options.t_final;
    double rows = static_cast<double>(options.output_times.size());
    if (options.output_times.empty()) {
        ALEMBERT_CHECK_ARG(options.output_step > 0, who + "the output step must be positive, not " +
                                                        number(options.output_step));
        // one every step from t_initial, and t_final when the last step falls short of it
        const double count = std::floor((tf - t0) / options.output_step + 1e-9);
        const bool short_of_end =
            t0 + count * options.output_step < tf - 1e-12 * std::max(1.0, std::abs(tf));
        rows = count + 1 + (short_of_end ? 1 : 0);
    }
    const auto limit = static_cast<double>(options.max_output_rows);
    if (rows > limit) {
        char count[32];
        std::snprintf(count, sizeof count, "%.0f", rows);
        const std::string asking =
            options.output_times.empty()
                ? "the output step " + number(options.output_step) + " s from t = " + number(t0) +
                      " to " + number(tf) + " s asks for "
                : "the output times ask for ";
        throw ArgumentError(
            who + asking + count + " rows, more than the limit of " +
            std::to_string(options.max_output_rows) +
            " rows (SimulationOptions::max_output_rows; in a script, output limit N), which "
            "keeps a run from filling the memory; choose a larger output step, or raise the "
            "limit for a run that needs every row");
    }
    return rows;
}

namespace detail {

SimulationResult integrate_with_outputs(const std::string& model, const OdeState& x0,
                                        const OdeRhs& rhs, const OdeGather& gather,
                                        const SimulationOptions& options,
                                        const OutputFunction& outputs, const EventFunction& events,
                                        const std::function<void(const Table&, std::size_t)>& check_row,
                                        OdeState& x_end) {
    const std::string who = "simulate('" + model + "'): ";
    const double t0 = options.t_initial, tf = options.t_final;
    ALEMBERT_CHECK_ARG(tf > t0, who + "the final time " + number(tf) +
                                    " s must follow the initial time " + number(t0) + " s");
    ALEMBERT_CHECK_ARG(options.abs_tol > 0 && options.rel_tol >= 0,
                       who + "the error tolerances must be positive");

    // the output times
    calc_output_row_count(options, who);
    std::vector<double> times = options.output_times;
    if (times.empty()) {
        const auto count =
            static_cast<std::size_t>(std::floor((tf - t0) / options.output_step + 1e-9));
        for (std::size_t k = 0; k <= count; ++k)
            times.push_back(t0 + static_cast<double>(k) * options.output_step);
        if (times.back() < tf - 1e-12 * std::max(1.0, std::abs(tf))) times.push_back(tf);
    }
    for (std::size_t k = 0; k < times.size(); ++k)
        ALEMBERT_CHECK_ARG(times[k] >= t0 && times[k] <= tf && (k == 0 || times[k] > times[k - 1]),
                           who + "output time " + number(times[k]) +
                               " s is out of order or outside [t_initial, t_final]");

    // the table: t, then the outputs
    SimulationResult result;
    Table& table = result.table;
    table.add_column("t", "s");
    for (std::size_t c = 0; c < outputs.names.size(); ++c)
        table.add_column(outputs.names[c], outputs.units[c]);
    std::vector<double> out(outputs.names.size());
    auto emit = [&](double t, const State& x) {
        outputs.function.evaluate(gather(t, x), out.data());
        table.columns[0].push_back(t);
        for (std::size_t c = 0; c < out.size(); ++c)
            table.columns[c + 1].push_back(out[c] / outputs.factors[c]);
        if (check_row) check_row(table, table.row_count() - 1);
    };
    auto event_values = [&](double t, const State& x, std::vector<double>& values) {
        if (!values.empty()) events.function.evaluate(gather(t, x), values.data());
    };
    auto crossed = [&](std::size_t j, double before, double after) {
        const bool up = before < 0 && after >= 0, down = before > 0 && after <= 0;
        switch (events.directions[j]) {
            case EventDirection::rising:
                return up;
            case EventDirection::falling:
                return down;
            case EventDirection::any:
                break;
        }
        return up || down;
    };

    State x = x0;
    std::unique_ptr<detail::DenseStepper> method =
        detail::make_dense_stepper(options.integrator, options.abs_tol, options.rel_tol, rhs);
    detail::DenseStepper& stepper = *method;
    const double first_step =
        options.initial_step > 0
            ? options.initial_step
            : std::min(tf - t0, times.size() > 1 ? times[1] - times[0] : tf - t0) / 100;
    stepper.initialize(x, t0, first_step, tf);

    ProgressIndicator progress("simulating '" + model + "'", t0, tf, options.progress);
    std::vector<double> g_before(events.names.size()), g_after(events.names.size());
    event_values(t0, x, g_before);
    std::size_t next = 0;
    State xi(x0.size());
    double t_end = tf;
    try {
        while (next < times.size() && times[next] <= t0) emit(t0, x), ++next;
        while (stepper.current_time() < tf) {
            if (result.steps >= options.max_steps)
                throw SolveError(who + "more than " + std::to_string(options.max_steps) +
                                 " steps before t = " + number(stepper.current_time()) +
                                 " s; the model may be stiff or near a singularity (integrate "
                                 "a stiff model with the bdf integrator, loosen the tolerances "
                                 "or raise max_steps)");
            const auto [t_prev, t_cur] = stepper.do_step();
            ++result.steps;
            if (!(t_cur > t_prev) || (!stepper.guards_step_size() &&
                                      t_cur - t_prev < 1e-14 * std::max(1.0, std::abs(t_cur))))
                throw SolveError(who + "the step size fell to " + number(t_cur - t_prev) +
                                 " s at t = " + number(t_cur) +
                                 " s; the model may be singular "
                                 "or discontinuous there");
            // events: the earliest crossing inside this step, by bisection on the dense output
            double t_event = t_cur;
            std::size_t fired = events.names.size();
            if (!g_after.empty()) {
                event_values(t_cur, stepper.current_state(), g_after);
                for (std::size_t j = 0; j < g_after.size(); ++j) {
                    if (!crossed(j, g_before[j], g_after[j])) continue;
                    double lo = t_prev, hi = t_cur;
                    std::vector<double> gm(g_after.size());
                    for (int it = 0; it < 200 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi));
                         ++it) {
                        const double mid = 0.5 * (lo + hi);
                        stepper.calc_state(mid, xi);
                        event_values(mid, xi, gm);
                        (crossed(j, g_before[j], gm[j]) ? hi : lo) = mid;
                    }
                    if (hi < t_event || fired == events.names.size()) t_event = hi, fired = j;
                }
                g_before = g_after;
            }
            // outputs inside the step (up to the event), then stop at an event or the end
            const double t_limit = std::min(fired < events.names.size() ? t_event : t_cur, tf);
            while (next < times.size() && times[next] <= t_limit) {
                stepper.calc_state(times[next], xi);
                emit(times[next], xi);
                ++next;
            }
            if (fired < events.names.size() && t_event <= tf) {
                stepper.calc_state(t_event, xi);
                if (table.columns[0].empty() || table.columns[0].back() < t_event)
                    emit(t_event, xi);
                result.stopped_by = events.names[fired];
                t_end = t_event;
                break;
            }
            progress.update(t_cur);
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw SolveError(who + "the integrator failed at t = " + number(stepper.current_time()) +
                         " s: " + e.what());
    }
    if (result.stopped_by.empty()) {
        if (stepper.current_time() > tf)
            stepper.calc_state(tf, xi);
        else
            xi = stepper.current_state();
    }
    result.t_end = t_end;
    x_end = xi;
    return result;
}

}  // namespace detail

SimulationResult simulate(const ForwardDynamics& fd, const std::vector<double>& q0,
                          const std::vector<double>& qd0, const SimulationOptions& options,
                          const OutputFunction& outputs, const EventFunction& events,
                          const InputFunction& inputs,
                          const std::function<void(const Table&, std::size_t)>& check_row) {
    const std::size_t n = fd.coordinate_count();
    const std::string who = "simulate('" + fd.model() + "'): ";
    const double t0 = options.t_initial, tf = options.t_final;
    ALEMBERT_CHECK_ARG(q0.size() == n && qd0.size() == n,
                       who + "the initial state has " + std::to_string(q0.size()) +
                           " coordinates and " + std::to_string(qd0.size()) +
                           " rates; the model has " + std::to_string(n) + " coordinates");
    ALEMBERT_CHECK_ARG(tf > t0, who + "the final time " + number(tf) +
                                    " s must follow the initial time " + number(t0) + " s");
    ALEMBERT_CHECK_ARG(options.abs_tol > 0 && options.rel_tol >= 0,
                       who + "the error tolerances must be positive");
    const std::size_t width = 1 + 2 * n + fd.unknown_count() + fd.input_count();
    ALEMBERT_CHECK_ARG(outputs.function.input_count == width &&
                           (events.names.empty() || events.function.input_count == width),
                       who +
                           "the outputs or events were compiled for another layout; compile "
                           "them with this model's layout()");

    // the right-hand side x' = [q', q''(t, q, q', inputs)]
    std::vector<double> u(fd.input_count(), 0.0);
    auto rhs = [&](const State& x, State& dxdt, double t) {
        if (inputs) inputs(t, x.data(), x.data() + n, u.data());
        std::copy(x.begin() + static_cast<std::ptrdiff_t>(n), x.end(), dxdt.begin());
        fd.calc_accelerations(t, x.data(), x.data() + n, u.data(), dxdt.data() + n);
    };
    State x(2 * n);
    std::copy(q0.begin(), q0.end(), x.begin());
    std::copy(qd0.begin(), qd0.end(), x.begin() + static_cast<std::ptrdiff_t>(n));
    Evaluator at(fd, inputs);
    State x_end;
    SimulationResult result = detail::integrate_with_outputs(
        fd.model(), x, rhs, [&](double t, const State& xs) { return at.gather(t, xs); }, options,
        outputs, events, check_row, x_end);
    result.q_end.assign(x_end.begin(), x_end.begin() + static_cast<std::ptrdiff_t>(n));
    result.qd_end.assign(x_end.begin() + static_cast<std::ptrdiff_t>(n), x_end.end());
    return result;
}

SimulationResult run_simulation(const System& sys, const SimulationRequest& request) {
    const SymbolTable& table = sys.symbols();
    const std::string who = "run_simulation('" + request.model + "'): ";
    const std::vector<TimeVariable>& q = request.coordinates;

    // the measures solved with the accelerations: the constraint forces, and the declared
    // joint reactions an output or a stop condition reads (non-contributing, they are absent
    // from the equations of motion; setting them to zero like an idle motor would print 0)
    std::vector<ex> solved = request.constraint_forces;
    const auto is_solved = [&](const ex& m) {
        return std::any_of(solved.begin(), solved.end(), [&](const ex& c) { return c.is_equal(m); });
    };
    for (const JointReaction& reaction : sys.joint_reactions())
        for (const ReactionComponent& measure : reaction.components) {
            const ex& x = measure.measure;
            if (is_solved(x) || request.inputs.count(x)) continue;
            const auto reads = [&](const ex& e) { return table.depends_on(e, x); };
            if (std::any_of(request.outputs.begin(), request.outputs.end(),
                            [&](const OutputSpec& o) { return reads(o.expression); }) ||
                std::any_of(request.events.begin(), request.events.end(),
                            [&](const EventSpec& e) { return reads(e.expression); }))
                solved.push_back(x);
        }

    // the contact loads: measures the road-map determines though the equations of motion in
    // these coordinates do not (a friction's normal force, a contact force an output reads)
    std::vector<ex> reads;
    for (const OutputSpec& o : request.outputs) reads.push_back(o.expression);
    for (const EventSpec& e : request.events) reads.push_back(e.expression);
    const ContactLoads contact = find_contact_loads(sys, q, solved, request.inputs, reads, who);
    solved.insert(solved.end(), contact.measures.begin(), contact.measures.end());

    // load measures: the given formulas, the measures solved for, the rest zero
    exmap loads;
    for (const auto& [measure, formula] : request.inputs)
        ALEMBERT_CHECK_ARG(table.owns(measure) && table.kind(measure) == SymbolKind::unknown,
                           who + "an input is given for '" + to_string(measure) +
                               "', which is not a load measure of the model (declare it with "
                               "add_unknown and use it in a load)");
    for (const ex& measure : table.symbols(SymbolKind::unknown)) {
        if (is_solved(measure)) continue;
        auto it = request.inputs.find(measure);
        loads[measure] = it == request.inputs.end() ? ex(0) : it->second;
    }
    for (const auto& [symbol, formula] : request.specified) {
        ALEMBERT_CHECK_ARG(table.owns(symbol) && table.kind(symbol) == SymbolKind::specified,
                           who + "a value is given for '" + to_string(symbol) +
                               "', which is not a specified quantity of the model");
        loads[symbol] = formula;
    }
    // initial values
    std::vector<double> q0(q.size(), 0.0), qd0(q.size(), 0.0);
    for (const auto& [symbol, value] : request.initial_values) {
        bool found = false;
        for (std::size_t i = 0; i < q.size(); ++i) {
            if (symbol.is_equal(q[i].symbol())) q0[i] = table.evaluate(value), found = true;
            if (symbol.is_equal(q[i].d(1))) qd0[i] = table.evaluate(value), found = true;
        }
        ALEMBERT_CHECK_ARG(found, who + "an initial value is given for '" + to_string(symbol) +
                                      "', which is neither a coordinate nor a coordinate's rate");
    }
    const auto expanded = [&](const ex& e) {
        return request.specified.empty() ? e : table.expand_intermediates(e);
    };
    // the contact loads' rows, planned once; the signs assumed inside abs() and the start
    // values of the contact measures, found at the initial state
    std::optional<ContactRows> contact_rows;
    if (!contact.measures.empty()) contact_rows = plan_contact_rows(sys, q, solved);
    std::vector<int> signs(contact.abs_arguments.size(), 1);
    std::vector<double> contact_start(contact.measures.size(), 0.0);

    auto run = [&](bool allow_tree) {
        // a tree of bodies in relative coordinates: q'' from the articulated-body recursion (no
        // mass matrix, no solve; its size grows linearly in the bodies), the load measures run-time
        // inputs given by their formulas (they sit inside the recursion's named intermediates, out
        // of reach of a substitution); otherwise the dense equations with the loads substituted
        std::optional<TreeEquations> tree;
        if (allow_tree && solved.empty() && sys.constraints().empty() &&
            request.specified.empty())
            tree = form_tree_equations_if_tree(sys, q);
        std::vector<ex> measures;
        InputFunction input_laws;
        std::optional<ForwardDynamics> dynamics;
        if (tree) {
            const std::size_t n = q.size();
            LinearSystem eqs{GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(static_cast<unsigned>(n))),
                             GiNaC::matrix(static_cast<unsigned>(n), 1), {}};
            for (std::size_t i = 0; i < n; ++i) {
                eqs.b(static_cast<unsigned>(i), 0) = tree->accelerations[i];
                eqs.unknowns.push_back(q[i].d(2));
            }
            measures = table.symbols(SymbolKind::unknown);
            const ForwardDynamics recursion =
                compile_forward_dynamics(table, eqs, q, measures, request.model, request.make);
            NumericFunction checked = recursion.function();
            checked.evaluate = [inner = recursion.function().evaluate,
                                count = checked.output_count](const double* x, double* y) {
                inner(x, y);
                for (std::size_t j = 0; j < count; ++j)
                    if (!std::isfinite(y[j])) throw RecursionNotFinite();
            };
            dynamics.emplace(recursion.model(), recursion.layout(), checked);
            std::vector<ex> state{table.time()}, laws;
            for (const TimeVariable& v : q) state.push_back(v.symbol());
            for (const TimeVariable& v : q) state.push_back(v.d(1));
            for (const ex& m : measures) laws.push_back(loads.at(m));
            auto f = std::make_shared<NumericFunction>(
                compile_over_layout_inputs(table, state, laws, request.make));
            auto in = std::make_shared<std::vector<double>>(1 + 2 * n);
            input_laws = [f, in, n](double t, const double* qv, const double* qd, double* u) {
                (*in)[0] = t;
                std::copy(qv, qv + n, in->begin() + 1);
                std::copy(qd, qd + n, in->begin() + 1 + static_cast<std::ptrdiff_t>(n));
                f->evaluate(in->data(), u);
            };
        } else {
            const auto compile = [&] {
                LinearSystem eqs = contact_rows
                                       ? form_contact_equations(*contact_rows, contact.abs_arguments, signs)
                                       : form_forward_equations(sys, q, solved);
                if (!request.specified.empty()) {
                    // a specified quantity may sit inside a named intermediate's definition
                    eqs.A = GiNaC::ex_to<GiNaC::matrix>(table.expand_intermediates(eqs.A));
                    eqs.b = GiNaC::ex_to<GiNaC::matrix>(table.expand_intermediates(eqs.b));
                }
                eqs.A = GiNaC::ex_to<GiNaC::matrix>(eqs.A.subs(loads));
                eqs.b = GiNaC::ex_to<GiNaC::matrix>(eqs.b.subs(loads));
                dynamics.emplace(compile_forward_dynamics(table, eqs, q, {}, request.model, request.make));
            };
            compile();
            if (contact_rows) {
                // |a| = s a with s assumed, then checked at the initial state: each pass takes
                // the signs of the last solution; the run's events watch them afterwards
                std::vector<ex> watched = contact.measures;
                for (const ex& a : contact.abs_arguments) watched.push_back(expanded(a).subs(loads));
                for (std::size_t pass = 0;; ++pass) {
                    const std::vector<double> v =
                        calc_at_start(table, *dynamics, watched, q0, qd0, request.options.t_initial);
                    std::copy(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(contact_start.size()),
                              contact_start.begin());
                    double scale = 1.0;
                    for (double y : v) scale = std::max(scale, std::abs(y));
                    std::vector<int> found = signs;
                    for (std::size_t i = 0; i < signs.size(); ++i) {
                        const double y = v[contact_start.size() + i];
                        if (!(std::abs(y) > 1e-12 * scale))
                            throw SolveError(who + "'" + to_string(contact.abs_arguments[i]) +
                                             "' (a friction's normal force) is " + number(y) +
                                             " at the start, so the side its contact presses from "
                                             "is not known; start where the contact carries load, or "
                                             "give the friction's normal force by an input");
                        found[i] = y > 0 ? 1 : -1;
                    }
                    if (found == signs) break;
                    if (pass > signs.size())
                        throw SolveError(who + "no signs of " + names_of(contact.abs_arguments) +
                                         " agree with the solution at the start (the friction "
                                         "laws they enter have no consistent solution there)");
                    signs = found;
                    compile();
                }
            }
        }
        const ForwardDynamics& fd = *dynamics;

        // outputs: the user's, then the checks
        std::vector<OutputSpec> outputs = request.outputs;
        for (OutputSpec& o : outputs) o.expression = expanded(o.expression).subs(loads);
        if (request.checks) {
            bool conservative = request.specified.empty();  // a driven quantity does work
            exmap without_constraint_forces = loads;
            // (not a contact load: a friction's normal force is what makes its friction work)
            for (const ex& c : solved)
                if (std::none_of(contact.measures.begin(), contact.measures.end(),
                                 [&](const ex& m) { return m.is_equal(c); }))
                    without_constraint_forces[c] = 0;
            for (const ex& f : form_generalized_active_forces(sys, q, LoadSelection::nonconservative))
                conservative = conservative && equal(f.subs(without_constraint_forces), 0);
            if (conservative)
                outputs.push_back({"energy",
                                   sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy(),
                                   "J"});
            for (const Constraint& c : sys.constraints()) {
                auto unit = request.constraint_units.find(c.name);
                outputs.push_back({"drift_" + c.name, c.residual,
                                   unit == request.constraint_units.end() ? "" : unit->second, 1.0});
            }
        }
        OutputFunction out = compile_outputs(table, fd.layout(), outputs, request.make);
        std::vector<EventSpec> event_specs = request.events;
        for (EventSpec& e : event_specs) e.expression = expanded(e.expression).subs(loads);
        // a contact load that changes sign ends the run: a contact force that would pull means
        // the contact is lost, and a friction's normal force the sign assumed in |Fn| no longer
        // holds; both are watched as events from their signs at the start
        std::vector<std::string> lost_names;
        for (std::size_t i = 0; i < contact.measures.size(); ++i) {
            const double v = contact_start[i];
            lost_names.push_back("contact lost: '" + to_string(contact.measures[i]) + "' changes sign");
            event_specs.push_back({lost_names.back(), contact.measures[i],
                                   v > 0   ? EventDirection::falling
                                   : v < 0 ? EventDirection::rising
                                           : EventDirection::any});
        }
        for (std::size_t i = 0; i < contact.abs_arguments.size(); ++i) {
            const ex& a = contact.abs_arguments[i];
            lost_names.push_back("contact lost: '" + to_string(a) + "' changes sign");
            event_specs.push_back({lost_names.back(), signs[i] * expanded(a).subs(loads),
                                   EventDirection::falling});
        }
        EventFunction events = compile_events(table, fd.layout(), event_specs, request.make);

        check_initial_constraints(sys, fd, request, q0, qd0);
        // the run stops at the first output row where a constraint has drifted too far
        std::function<void(const Table&, std::size_t)> check_row;
        if (request.checks && !sys.constraints().empty())
            check_row = [&](const Table& t, std::size_t r) { check_constraint_drift(sys, request, t, r); };
        SimulationResult result =
            simulate(fd, q0, qd0, request.options, out, events, input_laws, check_row);
        result.recursive = tree.has_value();
        if (std::find(lost_names.begin(), lost_names.end(), result.stopped_by) != lost_names.end()) {
            const std::string what = result.stopped_by.substr(std::string("contact lost: ").size());
            // "t = 0.64, q = 0.86, q' = 2.7": the time with its unit, then the state
            std::string state = detail::describe_state(fd.layout(), result.t_end, result.q_end.data(),
                                                       result.qd_end.data(), nullptr);
            const std::size_t comma = state.find(", ");
            state = comma == std::string::npos ? "" : " (" + state.substr(comma + 2) + ")";
            result.contact_lost =
                who + what + " at t = " + number(result.t_end) + " s" + state +
                ": the contact force would pull, so the contact is lost there and these "
                "coordinates no longer describe the motion; the run stops at that instant";
        }
        return result;
    };
    try {
        return run(true);
    } catch (const RecursionNotFinite&) {
        // the recursion divides by articulated inertias: where they vanish (a singular
        // configuration, a massless body) its q'' are not finite; the dense equations then say
        // which accelerations are not determined, or integrate where the recursion cannot
        return run(false);
    }
}

PlotResult write_table_and_plot(const Table& table, const std::string& dir, const std::string& name,
                                const PlotOptions& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        throw ArgumentError("write_table_and_plot(): cannot create the directory '" + dir + "' (" +
                            ec.message() + ")");
    const std::string csv = (fs::path(dir) / (name + ".csv")).string();
    write_csv(table, csv);
    return plot_csv(table, csv, (fs::path(dir) / name).string(), options);
}

}  // namespace alembert
