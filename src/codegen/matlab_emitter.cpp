// SPDX-License-Identifier: MIT
// The MATLAB/Octave emitter: one function file per generated function.
#include "alembert/codegen/matlab_emitter.hpp"

#include <sstream>

namespace alembert {

namespace {

// the text of a MATLAB string literal: quotes doubled (qA' -> qA'')
std::string matlab_string(const std::string& text) {
    std::string s;
    for (char ch : text) s += ch == '\'' ? std::string("''") : std::string(1, ch);
    return s;
}

std::string column_of(const std::vector<double>& v, const CodePrinter& pr) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : "; ") + pr.number(x);
    return s;
}

}  // namespace

std::vector<GeneratedFile> MatlabEmitter::emit(const CodePlan& plan) const {
    const CodePrinter& pr = printer_;
    const auto id = identifiers(plan);
    const std::string& N = plan.name;
    const std::size_t n = plan.coordinate_count;
    auto spell = [&](const CodeFunction& f) {
        return spelling(f, id, [&](std::size_t k) { return pr.element("h", k); });
    };
    std::vector<GeneratedFile> files;
    // a function file: signature, help line, the generator's header, body
    auto file = [&](const std::string& name, const std::string& signature,
                    const std::string& help, const std::string& body) {
        std::ostringstream os;
        os << "function " << signature << "\n% " << help << "\n%\n";
        for (const std::string& line : header(plan, name)) os << "% " << line << "\n";
        os << body << "end\n";
        files.push_back({name + ".m", os.str()});
    };

    // ---- parameters and context ----------------------------------------------------------------
    {
        std::ostringstream b;
        b << "p = struct();\n";
        for (const CodeSymbol& p : plan.parameters)
            b << "p." << id.at(p.name) << " = " << pr.number(p.value) << ";"
              << (p.unit.empty() ? "" : "  % [" + p.unit + "]") << "\n";
        file(N + "_parameters", "p = " + N + "_parameters()",
             "The model's constants, changeable without generating the code again.", b.str());
    }
    {
        std::ostringstream b;
        b << "if nargin < 1\n    p = " << N << "_parameters();\nend\nctx = struct('p', p);\n";
        for (const CodeFunction* f : plan.functions()) {
            const StraightLineProgram& p = f->program;
            ValueSpelling names = spell(*f);
            b << "% " << f->name << ": values of the parameters only\n"
              << "h = zeros(1, " << p.first_temporary - p.first_hoisted() << ");\n";
            std::vector<bool> used = parameters_read(p, p.prelude, false);
            for (std::size_t i = 0; i < used.size(); ++i)
                if (used[i]) b << names.parameters[i] << " = p." << names.parameters[i] << ";\n";
            pr.print(b, p, p.prelude, names, "");
            b << "ctx.h_" << f->name << " = h;\n";
        }
        file(N + "_context", "ctx = " + N + "_context(p)",
             "The parameters p (default " + N + "_parameters()) and the values computed from "
             "them once.",
             b.str());
    }

    // ---- the functions of the programs ----------------------------------------------------------
    for (const CodeFunction* f : plan.functions()) {
        const StraightLineProgram& p = f->program;
        ValueSpelling names = spell(*f);
        std::string outs = f->results.size() == 1 ? f->results[0]
                                                  : "[" + f->results[0] + ", " + f->results[1] + "]";
        std::string args = "t";
        for (const std::string& a : f->arrays) args += ", " + a;
        std::ostringstream b;
        b << "h = ctx.h_" << f->name << ";\n";
        std::vector<bool> used = parameters_read(p, p.body, true);
        for (std::size_t i = 0; i < used.size(); ++i)
            if (used[i]) b << names.parameters[i] << " = ctx.p." << names.parameters[i] << ";\n";
        std::vector<bool> read = inputs_read(p);
        std::size_t offset = 1;
        for (const std::string& a : f->arrays) {
            std::size_t len = a == "u" ? plan.load_count : n;
            for (std::size_t k = 0; k < len; ++k)
                if (read[offset + k])
                    b << pr.define(names.inputs[offset + k], pr.element(a, k)) << "\n";
            offset += len;
        }
        pr.print(b, p, p.body, names, "");
        std::size_t k = 0;
        for (std::size_t r = 0; r < f->results.size(); ++r) {
            const std::string& res = f->results[r];
            bool matrix = res == "M" || res == "dtau_dq" || res == "dtau_dqp";
            b << res << " = zeros(" << (matrix ? n : f->result_sizes[r]) << ", "
              << (matrix ? n : 1) << ");\n";
            for (std::size_t j = 0; j < f->result_sizes[r]; ++j, ++k) {
                std::string place = matrix ? res + "(" + std::to_string(j / n + 1) + ", " +
                                                 std::to_string(j % n + 1) + ")"
                                           : pr.element(res, j);
                b << pr.assign(place, pr.operand(p, p.outputs[k], names)) << "\n";
            }
        }
        file(N + "_" + f->name, outs + " = " + N + "_" + f->name + "(" + args + ", ctx)",
             "The " + f->summary + ".", b.str());
    }

    // ---- forward dynamics and the right-hand side for ode45 --------------------------------------
    {
        std::ostringstream b;
        if (!plan.accelerations.empty()) {
            b << "qpp = " << N << "_accelerations(t, q, qp, u, ctx);\n";
        } else {
            b << "[M, f] = " << N << "_mass_forcing(t, q, qp, u, ctx);\n";
            if (plan.symmetric_mass_matrix)
                b << "[R, failed] = chol(M);  % M = R'*R\n"
                  << "if failed\n    error('" << N << ":singular', '" << N
                  << "_forward_dynamics: the mass matrix is not positive definite at t = %g', t);\n"
                  << "end\nqpp = R \\ (R' \\ f);\n";
            else
                b << "qpp = M \\ f;\n";
        }
        file(N + "_forward_dynamics", "qpp = " + N + "_forward_dynamics(t, q, qp, u, ctx)",
             plan.accelerations.empty()
                 ? std::string("The accelerations qpp = M^-1 f (") +
                       (plan.symmetric_mass_matrix ? "Cholesky" : "LU") + ")."
                 : std::string("The accelerations qpp (articulated-body recursion)."),
             b.str());
    }
    if (!plan.inverse_dynamics_derivatives.empty()) {
        // d qpp/d q = M^-1 A du/dq at qpp (A the loads' coefficients in E = b - A u)
        const bool negated = plan.negated_identity_loads();
        std::ostringstream b;
        b << "qpp = " << N << "_forward_dynamics(t, q, qp, u, ctx);\n"
          << "[Dq, Dqp] = " << N << "_inverse_dynamics_derivatives(t, q, qp, qpp, ctx);\n"
          << (plan.mass_matrix.empty() ? "M = " + N + "_mass_forcing(t, q, qp, u, ctx);\n"
                                       : "M = " + N + "_mass_matrix(t, q, ctx);\n");
        if (negated) {
            b << "D = -[Dq, Dqp];\n";
        } else {
            b << "A = [";
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t j = 0; j < n; ++j)
                    b << (j ? ", " : "") << pr.number(plan.load_coefficients[i * n + j]);
                b << (i + 1 < n ? "; " : "");
            }
            b << "];  % the loads' coefficients\nD = A * [Dq, Dqp];\n";
        }
        if (plan.symmetric_mass_matrix)
            b << "R = chol(M);  % M = R'*R\nX = R \\ (R' \\ D);\n";
        else
            b << "X = M \\ D;\n";
        b << "dqpp_dq = X(:, 1:" << n << ");\ndqpp_dqp = X(:, " << n + 1 << ":" << 2 * n << ");\n";
        file(N + "_forward_dynamics_derivatives",
             "[qpp, dqpp_dq, dqpp_dqp] = " + N + "_forward_dynamics_derivatives(t, q, qp, u, ctx)",
             std::string("Forward dynamics with its derivatives d qpp/d q and d qpp/d qp (") +
                 (negated ? "-M^-1 du/dq" : "M^-1 A du/dq") + " at qpp).",
             b.str());
    }
    {
        std::ostringstream b;
        b << "q = x(1:" << n << ");\nqp = x(" << n + 1 << ":" << 2 * n << ");\n"
          << "u = " << (plan.load_count ? N + "_load_laws(t, q, qp, ctx)" : "zeros(0, 1)")
          << ";\nxdot = [qp; " << N << "_forward_dynamics(t, q, qp, u, ctx)];\n";
        file(N + "_rhs", "xdot = " + N + "_rhs(t, x, ctx)",
             "x' = [qp; qpp] for x = [q; qp], for ode45: ode45(@(t, x) " + N +
                 "_rhs(t, x, ctx), tspan, x0).",
             b.str());
    }
    if (plan.simulation) {
        const SimulationSpec& sim = plan.simulation_spec;
        std::string head = "t [s]";
        for (const auto* v : {&plan.q, &plan.qp, &plan.loads, &plan.outputs})
            for (const CodeSymbol& s : *v) head += "," + with_unit(s.name, s.unit);
        std::ostringstream b;
        b << "if nargin < 1\n    path = '" << N << ".csv';\nend\n"
          << "if nargin < 2\n    ctx = " << N << "_context();\nend\n"
          << "final_time = " << pr.number(sim.final_time) << ";  % [s]\n"
          << "output_step = " << pr.number(sim.output_step) << ";  % [s]\n"
          << "tspan = (0:floor(final_time / output_step * (1 + 1e-12)))' * output_step;\n"
          << "x0 = [" << column_of(sim.initial_q, pr) << "; " << column_of(sim.initial_qp, pr)
          << "];\n"
          << "options = odeset('RelTol', " << pr.number(sim.relative_tolerance)
          << ", 'AbsTol', " << pr.number(sim.absolute_tolerance) << ");\n"
          << "[t, x] = ode45(@(t, x) " << N << "_rhs(t, x, ctx), tspan, x0, options);\n"
          << "fid = fopen(path, 'w');\n"
          << "if fid < 0\n    error('" << N << ":file', '" << N
          << "_simulate: cannot open %s for writing', path);\nend\n"
          << "fprintf(fid, '%s\\n', '" << matlab_string(head) << "');\n"
          << "for k = 1:numel(t)\n"
          << "    q = x(k, 1:" << n << ")';\n    qp = x(k, " << n + 1 << ":" << 2 * n << ")';\n"
          << "    u = " << (plan.load_count ? N + "_load_laws(t(k), q, qp, ctx)" : "zeros(0, 1)")
          << ";\n";
        if (!plan.reactions.empty() || !plan.outputs.empty())
            b << "    qpp = " << N << "_forward_dynamics(t(k), q, qp, u, ctx);\n";
        if (!plan.reactions.empty()) {
            b << "    r = " << N << "_reactions(t(k), q, qp, qpp, u, ctx);  % in place of the load "
                 "laws' zeros\n";
            for (std::size_t k = 0; k < plan.reaction_loads.size(); ++k)
                b << "    u(" << plan.reaction_loads[k] + 1 << ") = r(" << k + 1 << ");  % "
                  << plan.loads[plan.reaction_loads[k]].name << "\n";
        }
        if (!plan.outputs.empty())
            b << "    y = " << N << "_outputs(t(k), q, qp, qpp, u, ctx);\n";
        else
            b << "    y = zeros(0, 1);\n";
        b << "    fprintf(fid, '%.17g', t(k));\n"
          << "    fprintf(fid, ',%.17g', [q; qp; u; y]);\n"
          << "    fprintf(fid, '\\n');\nend\nfclose(fid);\n";
        file(N + "_simulate", "[t, x] = " + N + "_simulate(path, ctx)",
             "Integrates with ode45 and writes t, q, qp, the loads and the outputs to path "
             "(default " + N + ".csv) as CSV.",
             b.str());
    }
    return files;
}

}  // namespace alembert
