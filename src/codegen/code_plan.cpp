// SPDX-License-Identifier: MIT
// The programs of the generated functions, compiled once per model, and their names.
#include "alembert/codegen/code_plan.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <regex>
#include <set>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"
#include "linear_split.hpp"
#include "reaction_solve.hpp"

namespace alembert {

namespace {

constexpr const char* kWho = "generate_code()";

bool is_identifier(const std::string& s) {
    static const std::regex word("[A-Za-z][A-Za-z0-9_]*");
    return std::regex_match(s, word);
}

std::string unit_of(const CodegenOptions& o, const std::string& name) {
    auto it = o.units.find(name);
    return it == o.units.end() ? std::string() : it->second;
}

std::string per_second(const std::string& unit, int power) {
    if (unit.empty()) return unit;
    return unit + (power == 1 ? "/s" : "/s^2");
}

// compiles `outputs` of `inputs` with the parameters; the compiler's messages get our context
StraightLineProgram compile(const SymbolTable& table, const std::vector<ex>& inputs,
                            const std::vector<ex>& outputs, const CompileOptions& parameters,
                            const std::string& what) {
    try {
        return CompiledExpressions(table, inputs, outputs, parameters).calc_program();
    } catch (const ArgumentError& e) {
        throw ArgumentError(std::string(kWho) + ": " + what + ": " + e.what() +
                            " (generated functions take t, the coordinates, their rates, the "
                            "loads and the constants)");
    }
}

// the parameters (by program position) that a program reads
void mark_parameters_read(const StraightLineProgram& p, std::vector<char>& used) {
    auto mark = [&](std::uint32_t v) {
        if (p.kind(v) == ValueKind::parameter) used[v - p.input_count] = 1;
    };
    for (const auto* code : {&p.prelude, &p.body})
        for (const ProgramInstruction& in : *code) {
            if (in.op == ProgramOp::combine) {
                for (std::uint32_t k = in.a; k < in.a + in.b; ++k) mark(p.terms[k].value);
            } else {
                mark(in.a);
                if (in.op != ProgramOp::sincos) mark(in.b);
            }
        }
    for (std::uint32_t v : p.outputs) mark(v);
}

// the table's values of the parameters (NaN without one)
std::vector<double> parameter_values(const SymbolTable& table, const std::vector<ex>& parameters) {
    std::vector<double> v;
    for (const ex& c : parameters) v.push_back(table.value(c).value_or(std::nan("")));
    return v;
}

// M symmetric at three pseudo-random states (the mass matrices of Kane's and Lagrange's
// methods are; a road-map's rows need not be)
bool symmetric_at_random_states(const StraightLineProgram& p, const std::vector<double>& parameters,
                                std::size_t n) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> draw(-1.5, 1.5);
    std::vector<double> in(p.input_count), out(p.outputs.size());
    for (int trial = 0; trial < 3; ++trial) {
        for (double& x : in) x = draw(rng);
        evaluate(p, in.data(), parameters.data(), out.data());
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < i; ++j) {
                double a = out[i * n + j], b = out[j * n + i];
                double scale = std::max({1.0, std::fabs(a), std::fabs(b)});
                if (!(std::fabs(a - b) <= 1e-10 * scale)) return false;
            }
    }
    return true;
}

// the constants kept as parameters: those of the options, or every constant of the table
std::vector<ex> chosen_parameters(const SymbolTable& table, const CodegenOptions& options) {
    if (!options.parameters) return table.symbols(SymbolKind::constant);
    for (const ex& c : *options.parameters)
        if (!table.owns(c) || table.kind(c) != SymbolKind::constant)
            throw ArgumentError(std::string(kWho) + ": the parameter '" + to_string(c) +
                                "' is not a constant of the table; list constants only");
    return *options.parameters;
}

// the parameters the plan's programs read, with their defaults
void record_parameters(CodePlan& plan, const SymbolTable& table, const std::vector<ex>& parameters,
                       const std::vector<std::string>& parameter_names,
                       const CodegenOptions& options) {
    std::vector<char> used(parameters.size(), 0);
    for (const CodeFunction* f : plan.functions()) mark_parameters_read(f->program, used);
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (!used[i]) continue;
        std::optional<double> value = table.value(parameters[i]);
        if (!value)
            throw ArgumentError(std::string(kWho) + ": the constant '" + parameter_names[i] +
                                "' has no value; give it one with SymbolTable::set_value() (it "
                                "is the parameter's default in the generated code)");
        plan.parameters.push_back({parameter_names[i], unit_of(options, parameter_names[i]),
                                   *value});
    }
}

// the simulation's settings checked, initial values defaulted (nv velocity states)
void check_simulation(CodePlan& plan, const CodegenOptions& options, std::size_t nv,
                      std::size_t load_count, const char* velocities) {
    plan.simulation = options.simulation;
    plan.simulation_spec = options.simulation_spec;
    SimulationSpec& sim = plan.simulation_spec;
    const std::size_t n = plan.coordinate_count;
    if (sim.initial_q.empty()) sim.initial_q.assign(n, 0.0);
    if (sim.initial_qp.empty()) sim.initial_qp.assign(nv, 0.0);
    if (sim.initial_q.size() != n || sim.initial_qp.size() != nv)
        throw ArgumentError(std::string(kWho) + ": the simulation has " +
                            std::to_string(sim.initial_q.size()) + " initial values of q and " +
                            std::to_string(sim.initial_qp.size()) + " of " + velocities + " for " +
                            std::to_string(n) + " coordinates and " + std::to_string(nv) + " " +
                            velocities + "; give one each (or none)");
    if (!(sim.final_time > 0) || !(sim.output_step > 0) || !(sim.absolute_tolerance > 0) ||
        !(sim.relative_tolerance > 0))
        throw ArgumentError(std::string(kWho) + ": the simulation's final time, output step "
                            "and tolerances must be positive");
    if (!sim.load_laws.empty() && sim.load_laws.size() != load_count)
        throw ArgumentError(std::string(kWho) + ": " + std::to_string(sim.load_laws.size()) +
                            " load laws for " + std::to_string(load_count) +
                            " loads; give one per load (or none for zero loads)");
}

// the loads as the plan names them, each checked to be an unknown of the table
void plan_loads(CodePlan& plan, const SymbolTable& table, const std::vector<ex>& loads,
                const CodegenOptions& options) {
    for (const ex& u : loads) {
        if (!table.owns(u) || table.kind(u) != SymbolKind::unknown)
            throw ArgumentError(std::string(kWho) + ": the load '" + to_string(u) +
                                "' is not an unknown of the table; declare it with "
                                "SymbolTable::add_unknown()");
        plan.loads.push_back({table.name(u), unit_of(options, table.name(u))});
    }
}

// the constants kept as named parameters, and how every function is compiled with them
struct ParameterPlan {
    std::vector<ex> symbols;
    std::vector<std::string> names;
    CompileOptions compile;
};

ParameterPlan plan_parameters(const SymbolTable& table, const CodegenOptions& options) {
    ParameterPlan pp;
    pp.symbols = chosen_parameters(table, options);
    for (const ex& c : pp.symbols) pp.names.push_back(table.name(c));
    pp.compile = {.parameters = pp.symbols, .expand_angle_sums = options.expand_angle_sums};
    return pp;
}

// the requested outputs' expressions (through `in_state`, which writes them in the generated
// functions' inputs), their names checked and recorded in the plan
template <class InState>
std::vector<ex> plan_outputs(CodePlan& plan, const CodegenOptions& options, InState in_state) {
    std::vector<ex> y;
    std::set<std::string> seen;
    for (const CodegenOutput& o : options.outputs) {
        if (!is_identifier(o.name) || !seen.insert(o.name).second)
            throw ArgumentError(std::string(kWho) + ": the output name '" + o.name +
                                "' is not an identifier or is used twice; name each output "
                                "once with letters, digits and _");
        y.push_back(in_state(o.expression));
        plan.outputs.push_back({o.name, o.unit.empty() ? unit_of(options, o.name) : o.unit});
    }
    return y;
}


}  // namespace

std::size_t CodePlan::array_length(const std::string& array) const {
    if (array == "u") return load_count;
    if (array == "ur" || array == "urp") return qp.size();
    if (array == "us") return dependent_speeds.size();
    return coordinate_count;
}

std::vector<const CodeFunction*> CodePlan::functions() const {
    std::vector<const CodeFunction*> out{&mass_forcing};
    if (!accelerations.empty()) out.push_back(&accelerations);
    if (!mass_matrix.empty()) out.push_back(&mass_matrix);
    if (!bias_forces.empty()) out.push_back(&bias_forces);
    for (const CodeFunction& f : jacobian_functions) out.push_back(&f);
    if (!inverse_dynamics.empty()) out.push_back(&inverse_dynamics);
    if (!inverse_dynamics_derivatives.empty()) out.push_back(&inverse_dynamics_derivatives);
    if (!reactions.empty()) out.push_back(&reactions);
    if (!output_function.empty()) out.push_back(&output_function);
    if (!load_laws.empty()) out.push_back(&load_laws);
    if (!constraint_drift.empty()) out.push_back(&constraint_drift);
    if (!kinematics.empty()) out.push_back(&kinematics);
    if (!dependent_speed_function.empty()) out.push_back(&dependent_speed_function);
    return out;
}

bool CodePlan::negated_identity_loads() const {
    const std::size_t n = coordinate_count;
    if (load_coefficients.size() != n * n) return false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            if (load_coefficients[i * n + j] != (i == j ? -1.0 : 0.0)) return false;
    return true;
}

std::vector<CodegenConstraint> differentiate_constraints(SymbolTable& table,
                                                         const std::vector<Constraint>& constraints) {
    std::vector<CodegenConstraint> out;
    for (const Constraint& c : constraints) {
        CodegenConstraint k{c.name, c.kind, c.residual, table.dt(c.residual), 0};
        k.acceleration = c.kind == ConstraintKind::configuration ? table.dt(k.rate) : k.rate;
        out.push_back(std::move(k));
    }
    return out;
}

CodePlan plan_code(const SymbolTable& table, const DynamicsEquations& eq,
                   const CodegenOptions& options) {
    CodePlan plan;
    plan.name = options.name;
    plan.source = options.source.empty() ? "an Alembert model" : options.source;
    plan.version = generator_version();
    if (!is_identifier(options.name))
        throw ArgumentError(std::string(kWho) + ": the name '" + options.name +
                            "' is not an identifier; use letters, digits and _ (starting with "
                            "a letter), e.g. 'triple_pendulum'");
    const std::size_t n = eq.coordinates.size();
    if (n == 0)
        throw ArgumentError(std::string(kWho) + ": no coordinates given; list the generalized "
                            "coordinates q of the model");
    if (eq.residuals.size() != n)
        throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.residuals.size()) +
                            " residuals for " + std::to_string(n) +
                            " coordinates; give one equation of motion per coordinate");
    plan.coordinate_count = n;
    plan.load_count = eq.loads.size();

    // ---- names and units --------------------------------------------------------------------
    std::vector<ex> q, qp, qpp;
    for (const TimeVariable& v : eq.coordinates) {
        if (v.order() < 2)
            throw ArgumentError(std::string(kWho) + ": the coordinate '" + v.name() +
                                "' has no second derivative; declare it with order 2");
        q.push_back(v.d(0));
        qp.push_back(v.d(1));
        qpp.push_back(v.d(2));
        std::string unit = unit_of(options, v.name());
        plan.q.push_back({table.name(v.d(0)), unit});
        plan.qp.push_back({table.name(v.d(1)), per_second(unit, 1)});
        plan.qpp.push_back({table.name(v.d(2)), per_second(unit, 2)});
    }
    plan_loads(plan, table, eq.loads, options);
    const ParameterPlan pp = plan_parameters(table, options);
    const std::vector<ex>& parameters = pp.symbols;
    const std::vector<std::string>& parameter_names = pp.names;
    const CompileOptions& compile_options = pp.compile;
    std::vector<std::string> q_names, qp_names, qpp_names, u_names;
    for (std::size_t i = 0; i < n; ++i) {
        q_names.push_back(plan.q[i].name);
        qp_names.push_back(plan.qp[i].name);
        qpp_names.push_back(plan.qpp[i].name);
    }
    for (const CodeSymbol& u : plan.loads) u_names.push_back(u.name);
    auto input_names = [&](std::initializer_list<const std::vector<std::string>*> arrays) {
        std::vector<std::string> names{"t"};
        for (const auto* a : arrays) names.insert(names.end(), a->begin(), a->end());
        return names;
    };
    auto symbols = [&](std::initializer_list<const std::vector<ex>*> arrays) {
        std::vector<ex> in{table.time()};
        for (const auto* a : arrays) in.insert(in.end(), a->begin(), a->end());
        return in;
    };

    // ---- constraints: the square system in (q'', constraint forces) ----------------------------
    const std::size_t nc = eq.constraints.size();
    if (eq.constraint_forces.size() != nc)
        throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.constraint_forces.size()) +
                            " constraint forces for " + std::to_string(nc) +
                            " constraints; give one load measure per constraint (the force or "
                            "torque that holds it), so that the equations and the constraints "
                            "determine the accelerations and the constraint forces");
    for (std::size_t i = 0; i < nc; ++i) {
        const ex& l = eq.constraint_forces[i];
        if (!table.owns(l) || table.kind(l) != SymbolKind::unknown)
            throw ArgumentError(std::string(kWho) + ": the constraint force '" + to_string(l) +
                                "' is not an unknown of the table; declare it with "
                                "SymbolTable::add_unknown()");
        for (const ex& u : eq.loads)
            if (u.is_equal(l))
                throw ArgumentError(std::string(kWho) + ": '" + to_string(l) + "' is both a load "
                                    "(an input) and a constraint force (solved for); list it once");
        plan.constraint_forces.push_back({table.name(l), unit_of(options, table.name(l))});
        plan.constraint_names.push_back(eq.constraints[i].name);
        plan.constraint_kinds.push_back(eq.constraints[i].kind);
    }
    if (nc > 0 && !eq.accelerations.empty())
        throw ArgumentError(std::string(kWho) + ": explicit accelerations were given for a model "
                            "with constraints; leave them out (the constrained system is solved "
                            "for q'' and the constraint forces)");

    // ---- mass matrix and forcing -------------------------------------------------------------
    // given, or split from the compiled residuals (linear in q''): E = f - M q''
    StraightLineProgram mf_program;
    if (nc > 0) {
        // E = (residuals, c'' or g') = b - A x, x = (q'', lambda)
        std::vector<ex> E = eq.residuals;
        for (const CodegenConstraint& c : eq.constraints) E.push_back(c.acceleration);
        StraightLineProgram P = compile(table, symbols({&q, &qp, &eq.loads, &qpp, &eq.constraint_forces}),
                                        E, compile_options,
                                        "the equations of motion and the constraints");
        std::vector<std::size_t> unknowns;
        for (std::size_t i = 0; i < n + nc; ++i) unknowns.push_back(1 + 2 * n + eq.loads.size() + i);
        try {
            mf_program = split_linear(P, unknowns);
        } catch (const SolveError& e) {
            throw SolveError(std::string(kWho) + ": the equations and the constraints at the "
                             "acceleration level are not linear in the accelerations q'' and the "
                             "constraint forces (" + e.what() + ")");
        }
    } else if (eq.mass_forcing) {
        const LinearSystem& D = *eq.mass_forcing;
        if (D.A.rows() != n || D.A.cols() != n || D.b.rows() != n)
            throw ArgumentError(std::string(kWho) + ": the mass matrix given is " +
                                std::to_string(D.A.rows()) + " x " + std::to_string(D.A.cols()) +
                                " for " + std::to_string(n) + " coordinates");
        for (std::size_t i = 0; i < n; ++i)
            if (D.unknowns.size() != n || !D.unknowns[i].is_equal(qpp[i]))
                throw ArgumentError(std::string(kWho) + ": the mass matrix given is not for the "
                                    "accelerations q'' of the coordinates, in their order (its "
                                    "unknowns differ at position " + std::to_string(i + 1) +
                                    "); give M and f of M q'' = f, or leave mass_forcing empty");
        std::vector<ex> mf;
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j) mf.push_back(D.A(i, j));
        for (unsigned i = 0; i < n; ++i) mf.push_back(D.b(i, 0));
        mf_program = compile(table, symbols({&q, &qp, &eq.loads}), mf, compile_options,
                             "the mass matrix and forcing");
    } else {
        StraightLineProgram E = compile(table, symbols({&q, &qp, &eq.loads, &qpp}),
                                        eq.residuals, compile_options, "the equations of motion");
        std::vector<std::size_t> accelerations;
        for (std::size_t i = 0; i < n; ++i) accelerations.push_back(1 + 2 * n + eq.loads.size() + i);
        try {
            mf_program = split_linear(E, accelerations);
        } catch (const SolveError& e) {
            throw SolveError(std::string(kWho) + ": the equations are not linear in the "
                             "accelerations q'' (" + e.what() + ")");
        }
    }
    const std::size_t k = n + nc;
    plan.mass_forcing = {.name = "mass_forcing",
                         .summary = nc ? "coefficients A (row by row) and right side b of A x = b, "
                                         "x = (qpp, constraint forces): the equations of motion, "
                                         "then the constraints at the acceleration level"
                                       : "mass matrix M (row by row) and forcing f of M q'' = f",
                         .arrays = {"q", "qp", "u"},
                         .results = {nc ? "A" : "M", nc ? "b" : "f"},
                         .result_sizes = {k * k, k},
                         .program = std::move(mf_program),
                         .input_names = input_names({&q_names, &qp_names, &u_names}),
                         .parameter_names = parameter_names};
    plan.symmetric_mass_matrix =
        nc == 0 &&
        symmetric_at_random_states(plan.mass_forcing.program, parameter_values(table, parameters), n);
    if (nc > 0) {
        // per constraint its value and velocity-level value, for Baumgarte's stabilisation
        std::vector<ex> e;
        for (const CodegenConstraint& c : eq.constraints) {
            e.push_back(c.kind == ConstraintKind::configuration ? c.value : ex(0));
            e.push_back(c.kind == ConstraintKind::configuration ? c.rate : c.value);
        }
        plan.constraint_drift = {
            .name = "constraint_drift",
            .summary = "per constraint its value c (0 for a motion constraint) and its "
                       "velocity-level value c' (g for a motion constraint g = 0)",
            .arrays = {"q", "qp"},
            .results = {"e"},
            .result_sizes = {2 * nc},
            .program = compile(table, symbols({&q, &qp}), e, compile_options, "the constraints"),
            .input_names = input_names({&q_names, &qp_names}),
            .parameter_names = parameter_names};
    }

    // ---- explicit accelerations (articulated-body recursion) ----------------------------------
    if (!eq.accelerations.empty()) {
        if (eq.accelerations.size() != n)
            throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.accelerations.size()) +
                                " explicit accelerations for " + std::to_string(n) +
                                " coordinates; give one per coordinate, or none");
        plan.accelerations = {
            .name = "accelerations",
            .summary = "accelerations qpp from the loads u (articulated-body recursion: no mass "
                       "matrix, no solve)",
            .arrays = {"q", "qp", "u"},
            .results = {"qpp"},
            .result_sizes = {n},
            .program = compile(table, symbols({&q, &qp, &eq.loads}), eq.accelerations,
                               compile_options, "the accelerations"),
            .input_names = input_names({&q_names, &qp_names, &u_names}),
            .parameter_names = parameter_names};
    }

    // ---- the mass matrix alone and the bias forces alone (composite-rigid-body recursion) -----
    if (!eq.mass_matrix.empty() || !eq.bias_forces.empty()) {
        if (nc > 0)
            throw ArgumentError(std::string(kWho) + ": a mass matrix or bias forces alone were "
                                "given for a model with constraints; leave them out");
        if (!eq.mass_matrix.empty() && eq.mass_matrix.size() != n * n)
            throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.mass_matrix.size()) +
                                " entries of the mass matrix alone for " + std::to_string(n) +
                                " coordinates; give n x n, row by row, or none");
        if (!eq.bias_forces.empty() && eq.bias_forces.size() != n)
            throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.bias_forces.size()) +
                                " bias forces for " + std::to_string(n) +
                                " coordinates; give one per coordinate, or none");
    }
    if (!eq.mass_matrix.empty())
        plan.mass_matrix = {
            .name = "mass_matrix",
            .summary = "mass matrix M (nq x nq, row by row) alone (composite-rigid-body "
                       "recursion: no forcing)",
            .arrays = {"q"},
            .results = {"M"},
            .result_sizes = {n * n},
            .program = compile(table, symbols({&q}), eq.mass_matrix, compile_options,
                               "the mass matrix alone"),
            .input_names = input_names({&q_names}),
            .parameter_names = parameter_names};
    if (!eq.bias_forces.empty())
        plan.bias_forces = {
            .name = "bias_forces",
            .summary = "bias forces C(q, qp) qp + g(q) alone (M qpp + bias are the generalized "
                       "inertia forces and weights)",
            .arrays = {"q", "qp"},
            .results = {"bias"},
            .result_sizes = {n},
            .program = compile(table, symbols({&q, &qp}), eq.bias_forces, compile_options,
                               "the bias forces"),
            .input_names = input_names({&q_names, &qp_names}),
            .parameter_names = parameter_names};

    // ---- point and frame Jacobians: position, J, J' q' ------------------------------------------
    std::set<std::string> jacobian_names;
    for (const CodegenJacobian& j : options.jacobians) {
        const KinematicJacobian& kj = j.jacobian;
        if (!is_identifier(j.name) || !jacobian_names.insert(j.name).second)
            throw ArgumentError(std::string(kWho) + ": the Jacobian name '" + j.name +
                                "' is not an identifier or is used twice; name each once with "
                                "letters, digits and _");
        if (nc > 0)
            throw ArgumentError(std::string(kWho) + ": Jacobians were requested for a model "
                                "with constraints; leave them out");
        if (kj.jacobian.size() != kj.rows() * n)
            throw ArgumentError(std::string(kWho) + ": the Jacobian '" + j.name + "' has " +
                                std::to_string(kj.jacobian.size()) + " entries for " +
                                std::to_string(kj.rows()) + " rows and " + std::to_string(n) +
                                " coordinates; form it for the coordinates generated");
        plan.jacobian_functions.push_back(
            {.name = j.name + "_position",
             .summary = "position of '" + j.name + "' (a point's p in N; a frame's R_NB row by "
                        "row, then its origin's p in N)",
             .arrays = {"q"},
             .results = {"pos"},
             .result_sizes = {kj.position.size()},
             .program = compile(table, symbols({&q}), kj.position, compile_options,
                                "the position of '" + j.name + "'"),
             .input_names = input_names({&q_names}),
             .parameter_names = parameter_names});
        plan.jacobian_functions.push_back(
            {.name = j.name + "_jacobian",
             .summary = "Jacobian J of '" + j.name + "' (" + std::to_string(kj.rows()) +
                        " x nq, row by row, in N: v = J qp; a frame's angular rows first)",
             .arrays = {"q"},
             .results = {"J"},
             .result_sizes = {kj.jacobian.size()},
             .program = compile(table, symbols({&q}), kj.jacobian, compile_options,
                                "the Jacobian of '" + j.name + "'"),
             .input_names = input_names({&q_names}),
             .parameter_names = parameter_names});
        plan.jacobian_functions.push_back(
            {.name = j.name + "_jacobian_dot_rates",
             .summary = "J' qp of '" + j.name + "' (the acceleration at qpp = 0, in N)",
             .arrays = {"q", "qp"},
             .results = {"Jdqp"},
             .result_sizes = {kj.rows()},
             .program = compile(table, symbols({&q, &qp}), kj.jacobian_dot_rates,
                                compile_options, "J' q' of '" + j.name + "'"),
             .input_names = input_names({&q_names, &qp_names}),
             .parameter_names = parameter_names});
    }

    // ---- inverse dynamics: the residuals solved for the loads ---------------------------------
    if (!eq.inverse_residuals.empty() && eq.inverse_residuals.size() != eq.loads.size())
        throw ArgumentError(std::string(kWho) + ": " + std::to_string(eq.inverse_residuals.size()) +
                            " inverse-dynamics residuals for " + std::to_string(eq.loads.size()) +
                            " loads; give one per load (the road-map rows of the loads)");
    if (nc == 0 && !eq.loads.empty() && (eq.loads.size() == n || !eq.inverse_residuals.empty())) {
        std::vector<ex> u = detail::solve_for_loads(
            table, eq.inverse_residuals.empty() ? eq.residuals : eq.inverse_residuals, eq.loads,
            kWho);
        plan.inverse_dynamics = {
            .name = "inverse_dynamics",
            .summary = "loads u that give the accelerations qpp (inverse dynamics)",
            .arrays = {"q", "qp", "qpp"},
            .results = {"u"},
            .result_sizes = {eq.loads.size()},
            .program =
                compile(table, symbols({&q, &qp, &qpp}), u, compile_options, "inverse dynamics"),
            .input_names = input_names({&q_names, &qp_names, &qpp_names}),
            .parameter_names = parameter_names};
    }

    // ---- derivatives of inverse dynamics (forward dynamics' follow from them and M) ------------
    if (!eq.inverse_dynamics_dq.empty() || !eq.inverse_dynamics_dqp.empty()) {
        if (nc > 0 || eq.loads.size() != n || !eq.inverse_residuals.empty() ||
            eq.inverse_dynamics_dq.size() != n * n || eq.inverse_dynamics_dqp.size() != n * n)
            throw ArgumentError(std::string(kWho) + ": the derivatives of inverse dynamics have " +
                                std::to_string(eq.inverse_dynamics_dq.size()) + " and " +
                                std::to_string(eq.inverse_dynamics_dqp.size()) + " entries for " +
                                std::to_string(n) + " coordinates and " +
                                std::to_string(eq.loads.size()) + " loads; form them with "
                                "add_dynamics_derivatives for a model without constraints, one "
                                "load per coordinate and no joint-reaction rows");
        // the loads' coefficients A of E = b - A u, numeric for joint torques and forces
        const LinearSystem L = detail::split_linear(table, eq.residuals, eq.loads, kWho);
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j) {
                const ex a = L.A(i, j);
                if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::ex_to<GiNaC::numeric>(a).is_real())
                    throw ArgumentError(std::string(kWho) + ": the load '" + to_string(eq.loads[j]) +
                                        "' enters the equation of '" + plan.q[i].name +
                                        "' with the coefficient " + to_string(a) + ", not a number; "
                                        "forward dynamics' derivatives are generated for loads "
                                        "that enter with constant coefficients (joint torques "
                                        "and forces)");
                plan.load_coefficients.push_back(GiNaC::ex_to<GiNaC::numeric>(a).to_double());
            }
        std::vector<ex> d = eq.inverse_dynamics_dq;
        d.insert(d.end(), eq.inverse_dynamics_dqp.begin(), eq.inverse_dynamics_dqp.end());
        plan.inverse_dynamics_derivatives = {
            .name = "inverse_dynamics_derivatives",
            .summary = "derivatives of inverse dynamics d u/d q and d u/d qp at fixed qpp "
                       "(nu x nq each, row by row: dtau_dq[i nq + j] = d u_i/d q_j)",
            .arrays = {"q", "qp", "qpp"},
            .results = {"dtau_dq", "dtau_dqp"},
            .result_sizes = {n * n, n * n},
            .program = compile(table, symbols({&q, &qp, &qpp}), d, compile_options,
                               "the derivatives of inverse dynamics"),
            .input_names = input_names({&q_names, &qp_names, &qpp_names}),
            .parameter_names = parameter_names};
    }

    // ---- joint reactions: their road-map rows solved at the accelerations qpp ------------------
    if (!eq.reactions.empty()) {
        if (nc > 0)
            throw ArgumentError(std::string(kWho) + ": joint-reaction measures were given for a "
                                "model with constraints; list them as constraint forces, or "
                                "leave them out");
        for (const ex& m : eq.reactions) {
            auto at = std::find_if(eq.loads.begin(), eq.loads.end(),
                                   [&](const ex& u) { return u.is_equal(m); });
            if (at == eq.loads.end())
                throw ArgumentError(std::string(kWho) + ": the joint-reaction measure '" +
                                    to_string(m) + "' is not one of the loads; list it among them");
            plan.reaction_loads.push_back(static_cast<std::size_t>(at - eq.loads.begin()));
        }
        const std::vector<ex> r =
            detail::solve_reaction_rows(table, eq.reaction_residuals, eq.reactions, kWho);
        std::string measures;
        for (std::size_t slot : plan.reaction_loads)
            measures += (measures.empty() ? "" : ", ") + plan.loads[slot].name;
        plan.reactions = {
            .name = "reactions",
            .summary = "joint-reaction measures (" + measures + ") from their road-map rows at "
                       "the accelerations qpp (forward dynamics first) and the other loads u",
            .arrays = {"q", "qp", "qpp", "u"},
            .results = {"reaction"},
            .result_sizes = {r.size()},
            .program = compile(table, symbols({&q, &qp, &qpp, &eq.loads}), r, compile_options,
                               "the joint reactions"),
            .input_names = input_names({&q_names, &qp_names, &qpp_names, &u_names}),
            .parameter_names = parameter_names};
    }

    // ---- requested outputs ---------------------------------------------------------------------
    if (!options.outputs.empty()) {
        const std::vector<ex> y = plan_outputs(plan, options, [](const ex& e) { return e; });
        plan.output_function = {
            .name = "outputs",
            .summary = "requested outputs y",
            .arrays = {"q", "qp", "qpp", "u"},
            .results = {"y"},
            .result_sizes = {y.size()},
            .program = compile(table, symbols({&q, &qp, &qpp, &eq.loads}), y, compile_options,
                               "the outputs"),
            .input_names = input_names({&q_names, &qp_names, &qpp_names, &u_names}),
            .parameter_names = parameter_names};
    }

    // ---- simulation: initial values and load laws -----------------------------------------------
    check_simulation(plan, options, n, eq.loads.size(), "q'");
    const SimulationSpec& sim = plan.simulation_spec;
    if (!eq.loads.empty()) {
        std::vector<ex> laws = sim.load_laws;
        if (laws.empty()) laws.assign(eq.loads.size(), ex(0));
        plan.load_laws = {.name = "load_laws",
                          .summary = "loads u during a simulation, from t, q and qp",
                          .arrays = {"q", "qp"},
                          .results = {"u"},
                          .result_sizes = {eq.loads.size()},
                          .program = compile(table, symbols({&q, &qp}), laws, compile_options,
                                             "the load laws"),
                          .input_names = input_names({&q_names, &qp_names}),
                          .parameter_names = parameter_names};
    }

    // ---- the parameters the programs read, with their defaults ----------------------------------
    record_parameters(plan, table, parameters, parameter_names, options);
    return plan;
}

CodePlan plan_speed_code(const SymbolTable& table, const KaneEquations& K,
                         const std::vector<ex>& loads, const CodegenOptions& options) {
    CodePlan plan;
    plan.name = options.name;
    plan.source = options.source.empty() ? "an Alembert model" : options.source;
    plan.version = generator_version();
    plan.speed_form = true;
    if (!is_identifier(options.name))
        throw ArgumentError(std::string(kWho) + ": the name '" + options.name +
                            "' is not an identifier; use letters, digits and _ (starting with "
                            "a letter), e.g. 'rolling_disk'");
    const std::size_t n = K.coordinates.size(), nr = K.independent_speeds.size(),
                      ns = K.dependent_speeds.size();
    if (K.kinematic_equations.empty() || n == 0 || nr == 0)
        throw ArgumentError(std::string(kWho) + ": Kane's equations were formed without chosen "
                            "speeds (KaneOptions::speeds and kinematic_equations); pass them as "
                            "DynamicsEquations{q, kane.residuals, loads} instead");
    if (K.coordinate_rates.size() != n || K.coordinate_rate_symbols.size() != n ||
        K.dependent_speed_values.size() != ns || K.dependent_speed_rates.size() != ns ||
        K.dynamics.A.rows() != nr || K.dynamics.A.cols() != nr || K.dynamics.b.rows() != nr ||
        K.dynamics.unknowns.size() != nr)
        throw ArgumentError(std::string(kWho) + ": the KaneEquations are incomplete (" +
                            std::to_string(n) + " coordinates, " + std::to_string(nr) +
                            " independent speeds, but counts of their rates, dependent speeds "
                            "or mass matrix differ); pass form_kane_equations' result whole");
    plan.coordinate_count = n;
    plan.load_count = loads.size();

    // ---- names and units --------------------------------------------------------------------
    std::vector<ex> q = K.coordinates, ur = K.independent_speeds, urp = K.dynamics.unknowns;
    for (std::size_t i = 0; i < n; ++i) {
        std::string unit = unit_of(options, table.name(q[i]));
        plan.q.push_back({table.name(q[i]), unit});
        plan.coordinate_rates.push_back({table.name(K.coordinate_rate_symbols[i]), per_second(unit, 1)});
    }
    for (std::size_t r = 0; r < nr; ++r) {
        std::string unit = unit_of(options, table.name(ur[r]));
        plan.qp.push_back({table.name(ur[r]), unit});
        plan.qpp.push_back({table.name(urp[r]), per_second(unit, 1)});
    }
    for (const ex& us : K.dependent_speeds)
        plan.dependent_speeds.push_back({table.name(us), unit_of(options, table.name(us))});
    plan_loads(plan, table, loads, options);
    const ParameterPlan pp = plan_parameters(table, options);
    const std::vector<ex>& parameters = pp.symbols;
    const std::vector<std::string>& parameter_names = pp.names;
    const CompileOptions& compile_options = pp.compile;
    auto names = [](const std::vector<CodeSymbol>& v) {
        std::vector<std::string> out;
        for (const CodeSymbol& x : v) out.push_back(x.name);
        return out;
    };
    const std::vector<std::string> q_names = names(plan.q), ur_names = names(plan.qp),
                                   urp_names = names(plan.qpp), u_names = names(plan.loads);
    auto input_names = [&](std::initializer_list<const std::vector<std::string>*> arrays) {
        std::vector<std::string> out{"t"};
        for (const auto* a : arrays) out.insert(out.end(), a->begin(), a->end());
        return out;
    };
    auto symbols = [&](std::initializer_list<const std::vector<ex>*> arrays) {
        std::vector<ex> in{table.time()};
        for (const auto* a : arrays) in.insert(in.end(), a->begin(), a->end());
        return in;
    };
    // what outputs and load laws may hold beyond the state: q', the dependent speeds and
    // their rates, replaced by their expressions in q, u_r, u_r'
    exmap replaced;
    for (std::size_t i = 0; i < n; ++i)
        if (!K.coordinate_rate_symbols[i].is_equal(K.coordinate_rates[i]))
            replaced[K.coordinate_rate_symbols[i]] = K.coordinate_rates[i];
    for (std::size_t s = 0; s < ns; ++s) {
        replaced[K.dependent_speeds[s]] = K.dependent_speed_values[s];
        TimeVariable v = table.variable(table.name(K.dependent_speeds[s]));
        if (v.order() >= 1) replaced[v.d(1)] = K.dependent_speed_rates[s];
    }
    auto in_state = [&](const ex& e) { return e.subs(replaced); };

    // ---- mass matrix and forcing of M u_r' = f --------------------------------------------------
    std::vector<ex> mf;
    for (unsigned i = 0; i < nr; ++i)
        for (unsigned j = 0; j < nr; ++j) mf.push_back(K.dynamics.A(i, j));
    for (unsigned i = 0; i < nr; ++i) mf.push_back(K.dynamics.b(i, 0));
    plan.mass_forcing = {.name = "mass_forcing",
                         .summary = "mass matrix M (row by row) and forcing f of M ur' = f, ur "
                                    "the independent speeds",
                         .arrays = {"q", "ur", "u"},
                         .results = {"M", "f"},
                         .result_sizes = {nr * nr, nr},
                         .program = compile(table, symbols({&q, &ur, &loads}), mf, compile_options,
                                            "the mass matrix and forcing"),
                         .input_names = input_names({&q_names, &ur_names, &u_names}),
                         .parameter_names = parameter_names};
    plan.symmetric_mass_matrix = symmetric_at_random_states(
        plan.mass_forcing.program, parameter_values(table, parameters), nr);

    // ---- kinematic differential equations and dependent speeds ----------------------------------
    plan.kinematics = {.name = "kinematics",
                       .summary = "coordinate rates qp = k(q, ur) (the kinematic differential "
                                  "equations, dependent speeds replaced)",
                       .arrays = {"q", "ur"},
                       .results = {"qp"},
                       .result_sizes = {n},
                       .program = compile(table, symbols({&q, &ur}), K.coordinate_rates,
                                          compile_options, "the kinematic differential equations"),
                       .input_names = input_names({&q_names, &ur_names}),
                       .parameter_names = parameter_names};
    if (ns > 0)
        plan.dependent_speed_function = {
            .name = "dependent_speeds",
            .summary = "dependent speeds us from the motion constraints",
            .arrays = {"q", "ur"},
            .results = {"us"},
            .result_sizes = {ns},
            .program = compile(table, symbols({&q, &ur}), K.dependent_speed_values,
                               compile_options, "the dependent speeds"),
            .input_names = input_names({&q_names, &ur_names}),
            .parameter_names = parameter_names};

    // ---- requested outputs ---------------------------------------------------------------------
    if (!options.outputs.empty()) {
        const std::vector<ex> y = plan_outputs(plan, options, in_state);
        plan.output_function = {
            .name = "outputs",
            .summary = "requested outputs y",
            .arrays = {"q", "ur", "urp", "u"},
            .results = {"y"},
            .result_sizes = {y.size()},
            .program = compile(table, symbols({&q, &ur, &urp, &loads}), y, compile_options,
                               "the outputs"),
            .input_names = input_names({&q_names, &ur_names, &urp_names, &u_names}),
            .parameter_names = parameter_names};
    }

    // ---- simulation: initial values and load laws -----------------------------------------------
    check_simulation(plan, options, nr, loads.size(), "independent speeds");
    if (!loads.empty()) {
        std::vector<ex> laws;
        for (const ex& l : plan.simulation_spec.load_laws) laws.push_back(in_state(l));
        if (laws.empty()) laws.assign(loads.size(), ex(0));
        plan.load_laws = {.name = "load_laws",
                          .summary = "loads u during a simulation, from t, q and ur",
                          .arrays = {"q", "ur"},
                          .results = {"u"},
                          .result_sizes = {loads.size()},
                          .program = compile(table, symbols({&q, &ur}), laws, compile_options,
                                             "the load laws"),
                          .input_names = input_names({&q_names, &ur_names}),
                          .parameter_names = parameter_names};
    }
    record_parameters(plan, table, parameters, parameter_names, options);
    return plan;
}

}  // namespace alembert
