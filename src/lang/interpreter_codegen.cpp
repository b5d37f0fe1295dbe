// SPDX-License-Identifier: MIT
// The interpreter's `codegen` statement: what it generates from the script's equations (the
// road-map or Kane's equations in speeds, constraints, inputs, outputs), and where.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "alembert/codegen/codegen.hpp"
#include "alembert/codegen/native.hpp"
#include "alembert/eom/jacobians.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/lang/parser.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// qA'' -> qA_dd: a name the generated code can use
std::string code_identifier(const std::string& printed) {
    std::string out;
    std::size_t p = printed.find('\'');
    out = printed.substr(0, p);
    if (p != std::string::npos) out += "_" + std::string(printed.size() - p, 'd');
    return out;
}

}  // namespace

void Interpreter::Impl::codegen(const Statement& s) {
    if (model_only) return;
    const SymbolTable& table = model(s.location).symbols();
    CodegenRequest r;
    r.language = s.word("language");
    if (s.lists.count("loads"))
        for (const Word& w : s.lists.at("loads")) {
            ex x = symbol(w, "a load measure");
            if (table.kind(x) != SymbolKind::unknown)
                throw ScriptError(w.location, "'" + w.text + "' is not a load measure",
                                  "list unknowns declared with 'unknown' and used in loads");
            r.loads.push_back(x);
        }
    if (s.has_word("name")) r.name = s.word("name").text;
    if (s.lists.count("jacobians")) r.jacobians = s.lists.at("jacobians");
    if (s.has_word("derivatives")) r.derivatives = s.word("derivatives");
    r.dir = output_path(s);
    run_codegen(r, s.location);
}

void Interpreter::Impl::run_codegen(const CodegenRequest& r, Location where) {
    System& sys = model(where);
    const SymbolTable& table = sys.symbols();
    Language language = guard(r.language.location, [&] { return parse_language(r.language.text); });
    std::vector<TimeVariable> q = default_coordinates();
    if (q.empty())
        throw ScriptError(where, "the model has no coordinates to generate code for",
                          "declare variables (variable q'') and use them in rotations or translations");
    // equations in generalized speeds (a kane statement with speeds): the generated code's
    // state is then (q, u_r)
    const KaneEquations* speeds = speed_equations(where, "codegen");
    if (speeds && !sys.constraints().empty())
        throw ScriptError(where, "the model has both constraint statements and Kane's equations in "
                                 "generalized speeds; codegen generates one form",
                          "give the rolling as the kane statement's constraints, or declare the "
                          "coordinates with q'' and drop the speeds");
    if (speeds) {
        q.clear();
        for (const ex& x : speeds->coordinates) q.push_back(table.variable(table.name(x)));
    }
    for (const TimeVariable& v : q)
        if (!speeds && v.order() < 2)
            throw ScriptError(where, "the coordinate " + v.name() + " has no second derivative declared; generated "
                                     "code integrates q'', or the speeds of a kane statement",
                              "declare it as variable " + v.name() + "'', or form Kane's equations in "
                              "generalized speeds (kane K for ... speeds ... kinematics [...])");
    std::vector<ex> loads = r.loads.empty() ? table.symbols(SymbolKind::unknown) : r.loads;
    // closed loops and rolling: the unknowns that are neither listed loads nor inputs are the
    // constraint forces, solved for with the accelerations
    std::vector<ex> constraint_forces;
    if (!speeds && !sys.constraints().empty()) {
        if (language == Language::matlab)
            throw ScriptError(r.language.location,
                              "code for models with constraints is generated in C, C++ and Python only",
                              "write codegen c (or cpp, python)");
        std::vector<ex> given;
        for (const ex& u : table.symbols(SymbolKind::unknown)) {
            bool listed = r.loads.empty() ? numbers.inputs.count(u) != 0
                                          : std::any_of(r.loads.begin(), r.loads.end(),
                                                        [&](const ex& l) { return l.is_equal(u); });
            (listed ? given : constraint_forces).push_back(u);
        }
        loads = given;
        if (constraint_forces.size() != sys.constraints().size())
            throw ScriptError(where, "the model has " + std::to_string(sys.constraints().size()) +
                                         " scalar constraints but " + std::to_string(constraint_forces.size()) +
                                         " unknowns left to hold them",
                              "give the driving loads with input (input T = 0) or codegen c for T, so that "
                              "one unknown force per constraint remains");
    }
    // declared joint reactions without an input law: non-contributing, the equations of motion
    // do not hold them, so the generated code solves their road-map rows at each state's
    // accelerations (the load laws' 0 would be a wrong answer); an output may read one not
    // listed among the loads
    auto is_load = [&](const ex& x) {
        return std::any_of(loads.begin(), loads.end(), [&](const ex& l) { return l.is_equal(x); });
    };
    for (const JointReaction& reaction : sys.joint_reactions())
        for (const ReactionComponent& c : reaction.components) {
            const ex& x = c.measure;
            if (is_load(x) || numbers.inputs.count(x) ||
                std::none_of(numbers.outputs.begin(), numbers.outputs.end(),
                             [&](const auto& o) { return table.depends_on(o.expression, x); }))
                continue;
            if (!constraint_forces.empty() &&
                std::any_of(constraint_forces.begin(), constraint_forces.end(),
                            [&](const ex& f) { return f.is_equal(x); }))
                continue;
            loads.push_back(x);
        }
    std::vector<ex> reactions;
    std::string others;  // the loads that are not reactions computed here
    for (const ex& x : loads)
        if (!sys.reaction_of(x) || numbers.inputs.count(x))
            others += (others.empty() ? "" : ", ") + to_string(x);
    for (const ex& x : loads) {
        const JointReaction* reaction = sys.reaction_of(x);
        if (!reaction || numbers.inputs.count(x)) continue;
        if (speeds || !constraint_forces.empty()) {
            const std::string leave_out =
                others.empty() ? "leave the reaction statement and its unknowns out"
                               : "leave the measure out: codegen " + r.language.text + " for " + others;
            throw ScriptError(where, "the reaction '" + reaction->name + "' measure " + to_string(x) +
                                         " is not computed by code generated " +
                                         (speeds ? "from Kane's equations in generalized speeds"
                                                 : "for a model with constraints") +
                                         " (the program would write 0 for it)",
                              (speeds ? "declare the coordinates with q'' and drop the kane statement's "
                                        "speeds (the reactions are then computed at every sample), or "
                                      : "simulate computes it (output " + to_string(x) + "); or ") +
                                  leave_out);
        }
        reactions.push_back(x);
    }
    CodegenOptions opts;
    opts.name = r.name.empty() ? script_name : r.name;
    if (!is_identifier(opts.name))
        throw ScriptError(where, "'" + opts.name + "' cannot name generated code (letters, digits and _ only)",
                          "choose a name: codegen c name pendulum");
    opts.source = script_file;
    // generated code computes in SI units: its labels say those, not the units the script
    // declared (L_A = 41.82 cm is 0.4182 there, in m)
    for (const auto& [name, u] : units)
        if (u.dim.known && !u.dim.is_none()) opts.units[name] = si_unit(u.dim);
    for (std::size_t i = 0; i < numbers.outputs.size(); ++i) {
        // coordinates and rates are columns of the generated simulation already
        bool state = false;
        for (const TimeVariable& v : q) state = state || numbers.outputs[i].expression.is_equal(v.symbol()) ||
                                                (!speeds && numbers.outputs[i].expression.is_equal(v.d(1)));
        if (speeds)
            for (const ex& u : speeds->independent_speeds) state = state || numbers.outputs[i].expression.is_equal(u);
        // and so are the loads (the joint reactions among them computed at each sample)
        if (state || is_load(numbers.outputs[i].expression)) continue;
        opts.outputs.push_back({code_identifier(numbers.outputs[i].name), numbers.outputs[i].expression,
                                numbers.output_si_units[i]});
    }
    // point and frame Jacobians: a point's, or a body's frame at its origin B_o (else its mass
    // centre)
    for (const Word& w : r.jacobians) {
        if (speeds)
            throw ScriptError(w.location, "Jacobians are generated for the coordinates' rates, not for "
                                          "equations in generalized speeds",
                              "leave out 'jacobian' or declare the coordinates with q''");
        auto point_named = [&](const std::string& name) -> const Point* {
            for (const Point* P : sys.points())
                if (P->name() == name) return P;
            return nullptr;
        };
        const Body* body = nullptr;
        for (const Body* b : sys.bodies())
            if (b->name() == w.text) body = b;
        if (body && body->frame()) {
            const Point* O = point_named(w.text + "_o");
            if (!O || O->owner() != body) O = &body->cm();
            opts.jacobians.push_back(
                {code_identifier(w.text), guard(w.location, [&] {
                     return form_frame_jacobian(sys, q, *body->frame(), *O);
                 })});
        } else if (const Point* P = point_named(w.text)) {
            opts.jacobians.push_back(
                {code_identifier(w.text), guard(w.location, [&] { return form_point_jacobian(sys, q, *P); })});
        } else {
            throw ScriptError(w.location, "'" + w.text + "' is neither a point nor a rigid body of the model",
                              "name a point (point P) or a body (body B) declared before codegen");
        }
    }
    // derivatives of inverse and forward dynamics: one load per coordinate, an open chain or tree
    if (r.derivatives) {
        const Location at = r.derivatives->location;
        if (speeds)
            throw ScriptError(at, "derivatives are generated for the coordinates' rates, not for "
                                  "equations in generalized speeds",
                              "leave out 'derivatives' or declare the coordinates with q''");
        if (!constraint_forces.empty())
            throw ScriptError(at, "derivatives are not generated for a model with constraints",
                              "leave out 'derivatives'");
        if (loads.size() != q.size() || !reactions.empty() ||
            std::any_of(loads.begin(), loads.end(), [&](const ex& x) { return sys.reaction_of(x); }))
            throw ScriptError(at, "derivatives need one load per coordinate (" + std::to_string(loads.size()) +
                                      " loads for " + std::to_string(q.size()) + " coordinates)",
                              "list the joint torques and forces: codegen " + r.language.text +
                                  " for T1, T2 derivatives");
    }
    // the script's simulation settings make the generated simulation program
    opts.simulation = true;
    SimulationSpec& spec = opts.simulation_spec;
    spec.final_time = numbers.options.t_final;
    spec.output_step = numbers.options.output_step;
    spec.absolute_tolerance = numbers.options.abs_tol;
    spec.relative_tolerance = numbers.options.rel_tol;
    auto initial = [&](const ex& x) {
        auto it = numbers.initial.find(x);
        return it == numbers.initial.end() ? 0.0 : table.evaluate(it->second);
    };
    for (const TimeVariable& v : q) {
        spec.initial_q.push_back(initial(v.symbol()));
        if (!speeds) spec.initial_qp.push_back(initial(v.d(1)));
    }
    if (speeds)
        for (const ex& u : speeds->independent_speeds) spec.initial_qp.push_back(initial(u));
    for (const ex& l : loads) {
        auto it = numbers.inputs.find(l);
        spec.load_laws.push_back(it == numbers.inputs.end() ? ex(0) : it->second);
    }
    // a tree of bodies in relative coordinates: the recursive formation (linear in the number
    // of bodies, forward dynamics with no solve); otherwise Kane's equations with their M
    bool tree = false;
    GeneratedCode g = guard(where, [&] {
        // joint-reaction measures among the loads: inverse dynamics from the road-map rows
        std::vector<ex> inverse_residuals;
        if (std::any_of(loads.begin(), loads.end(),
                        [&](const ex& x) { return sys.reaction_of(x); }))
            inverse_residuals = residuals_of(plan_roadmap(sys, q, loads));
        // the joint reactions' own rows, in the planner's order, the driving loads given
        std::vector<ex> reaction_measures, reaction_residuals;
        if (!reactions.empty())
            for (const RoadmapRow& row : plan_roadmap(sys, q, reactions)) {
                reaction_measures.push_back(row.variable);
                reaction_residuals.push_back(row.equation);
            }
        if (speeds) return generate_code(table, *speeds, loads, language, r.dir, opts);
        if (!constraint_forces.empty()) {
            KaneEquations k = form_kane_equations(sys, KaneOptions{.coordinates = q});
            DynamicsEquations eqs{q, k.residuals, loads};
            eqs.constraints = differentiate_constraints(sys.symbols(), sys.constraints());
            eqs.constraint_forces = constraint_forces;
            return generate_code(table, eqs, language, r.dir, opts);
        }
        if (std::optional<TreeEquations> t =
                form_tree_equations_if_tree(sys, q, TreeOptions{.mass_matrix = true})) {
            tree = true;
            DynamicsEquations eqs{
                q, t->residuals, loads, std::nullopt, t->accelerations, inverse_residuals};
            eqs.mass_matrix = t->mass_matrix;
            eqs.bias_forces = t->bias_forces;
            eqs.reactions = reaction_measures;
            eqs.reaction_residuals = reaction_residuals;
            if (r.derivatives) add_dynamics_derivatives(sys.symbols(), eqs);
            return generate_code(table, eqs, language, r.dir, opts);
        }
        KaneEquations k = form_kane_equations(sys, KaneOptions{.coordinates = q});
        DynamicsEquations eqs{q, k.residuals, loads, k.dynamics, {}, inverse_residuals};
        eqs.reactions = reaction_measures;
        eqs.reaction_residuals = reaction_residuals;
        if (r.derivatives) add_dynamics_derivatives(sys.symbols(), eqs);
        return generate_code(table, eqs, language, r.dir, opts);
    });
    std::ostringstream out;
    const char* language_name[] = {"C", "C++", "MATLAB/Octave", "Python"};
    out << "generated " << language_name[static_cast<int>(language)] << " for '" << opts.name << "': ";
    for (std::size_t i = 0; i < g.files.size(); ++i) out << (i ? ", " : "") << g.files[i].filename().string();
    // (operation counts are left out: they shift by a few with GiNaC's term order from run to run)
    if (speeds)
        out << "\n  equations in generalized speeds, state (q, " << to_string(speeds->independent_speeds.front())
            << ", ...): kinematics, " << speeds->dependent_speeds.size() << " dependent speeds from the motion "
               "constraints, mass matrix and forcing (" << (g.symmetric_mass_matrix ? "Cholesky" : "LU")
            << " solve for the speeds' rates)";
    else if (g.constraint_count)
        out << "\n  " << g.constraint_count << " constraints: the equations and the constraints solved for the "
               "accelerations and " << g.constraint_count << " constraint forces (LU), Baumgarte's stabilisation "
               "in the simulation";
    else if (tree)
        out << "\n  recursive formation: mass matrix and forcing, accelerations by the articulated-body "
               "recursion (no solve), mass matrix alone (composite-rigid-body recursion) and bias forces";
    else
        out << "\n  mass matrix and forcing (" << (g.symmetric_mass_matrix ? "Cholesky" : "LU")
            << " solve for the accelerations)";
    if (!reactions.empty())
        out << ", " << reactions.size() << " joint-reaction measure" << (reactions.size() == 1 ? "" : "s")
            << " from the road-map rows at every sample";
    if (g.inverse_dynamics) out << ", inverse dynamics";
    else if (g.constraint_count) out << "; no inverse dynamics (a constrained model)";
    else if (speeds) out << "; no inverse dynamics (equations in generalized speeds)";
    else out << "; no inverse dynamics (" << loads.size() << " loads for " << q.size() << " coordinates)";
    if (!opts.outputs.empty()) out << ", " << opts.outputs.size() << " outputs";
    if (!opts.jacobians.empty())
        out << ", " << opts.jacobians.size() << (opts.jacobians.size() == 1 ? " Jacobian" : " Jacobians");
    if (r.derivatives) out << ", derivatives of inverse and forward dynamics";
    out << ", a simulation program";
    if (numbers.options.integrator != Integrator::dopri5)
        out << " (integrating by Dormand-Prince 5(4): the integrator " << to_string(numbers.options.integrator)
            << " applies to simulate, not to generated code)";
    transcript.result(out.str());
}


// ---- grammar -----------------------------------------------------------------------------

}  // namespace alembert::lang
