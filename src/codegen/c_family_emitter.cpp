// SPDX-License-Identifier: MIT
// The C99 and C++ emitters: one text generator for both, differing in declarations.
#include <algorithm>
#include <functional>
#include <sstream>

#include "alembert/codegen/c_emitter.hpp"
#include "alembert/codegen/cpp_emitter.hpp"
#include "symbol_names.hpp"

namespace alembert {

namespace {

using IdMap = std::map<std::string, std::string>;

// what differs between C and C++
struct Dialect {
    bool cpp;
    std::string name;  // the model's name

    std::string math(const std::string& f) const { return cpp ? "std::" + f : f; }
    // the context's stored values of a function's prelude
    std::string hoisted_array(const CodeFunction& f) const {
        return cpp ? "h_" + f.name + "_" : "c->h_" + f.name;
    }
    std::string parameter(const std::string& id) const { return cpp ? "p_." + id : "c->p." + id; }
    std::string function(const std::string& f) const { return cpp ? f : name + "_" + f; }
    std::string null() const { return cpp ? "nullptr" : "(const double*)0"; }
    std::string size(const char* what) const {
        return cpp ? std::string(what) : name + "_" + [&] {
            std::string s(what);
            std::transform(s.begin(), s.end(), s.begin(), ::toupper);
            return s;
        }();
    }
};

std::size_t hoisted_count(const CodeFunction& f) {
    return f.program.first_temporary - f.program.first_hoisted();
}

// "double t, const double* q, const double* qp, const double* u, double* M, double* f"
std::string arguments(const CodeFunction& f) {
    std::string s = "double t";
    for (const std::string& a : f.arrays) s += ", const double* " + a;
    for (const std::string& r : f.results) s += ", double* " + r;
    return s;
}

std::string comment_block(const std::vector<std::string>& lines, bool cpp) {
    std::string s;
    if (cpp) {
        for (const std::string& l : lines) s += "// " + l + "\n";
        return s + "// clang-format off\n";
    }
    s = "/* ";
    for (std::size_t i = 0; i < lines.size(); ++i) s += (i ? "   " : "") + lines[i] + "\n";
    return s + "   clang-format off */\n";
}

// the body of a generated function: unpack what the program reads, the program, the stores
void print_body(std::ostream& os, const CodePlan& plan, const CodeFunction& f, const Dialect& d,
                const CodePrinter& pr, const ValueSpelling& names) {
    const StraightLineProgram& p = f.program;
    const std::string in = "    ";
    std::vector<bool> read = [&] {
        std::vector<bool> r(p.input_count, false);
        auto mark = [&](std::uint32_t v) {
            if (p.kind(v) == ValueKind::input) r[v] = true;
        };
        for (const ProgramInstruction& i : p.body) {
            if (i.op == ProgramOp::combine)
                for (std::uint32_t k = i.a; k < i.a + i.b; ++k) mark(p.terms[k].value);
            else {
                mark(i.a);
                if (i.op != ProgramOp::sincos) mark(i.b);
            }
        }
        for (std::uint32_t v : p.outputs) mark(v);
        return r;
    }();
    // arrays (and t) the program does not read
    if (!read[0]) os << in << "(void)t;\n";
    std::vector<std::size_t> lengths;
    std::size_t offset = 1;
    for (std::size_t a = 0; a < f.arrays.size(); ++a) {
        // q, qp, qpp have one entry per coordinate, u one per load, ur, urp one per speed
        std::size_t len = plan.array_length(f.arrays[a]);
        lengths.push_back(len);
        bool any = false;
        for (std::size_t k = 0; k < len; ++k) any = any || read[offset + k];
        if (!any) os << in << "(void)" << f.arrays[a] << ";\n";
        offset += len;
    }
    bool reads_context = false;
    // parameters and the prelude's values the body reads
    std::vector<bool> params(p.parameter_count, false);
    bool hoisted = false;
    auto mark = [&](std::uint32_t v) {
        if (p.kind(v) == ValueKind::parameter) params[v - p.input_count] = true;
        if (p.kind(v) == ValueKind::hoisted) hoisted = true;
    };
    for (const ProgramInstruction& i : p.body) {
        if (i.op == ProgramOp::combine)
            for (std::uint32_t k = i.a; k < i.a + i.b; ++k) mark(p.terms[k].value);
        else {
            mark(i.a);
            if (i.op != ProgramOp::sincos) mark(i.b);
        }
    }
    for (std::uint32_t v : p.outputs) mark(v);
    for (std::size_t k = 0; k < params.size(); ++k)
        if (params[k]) {
            const std::string& pid = names.parameters[k];
            os << in << pr.define(pid, d.parameter(pid)) << '\n';
            reads_context = true;
        }
    if (hoisted) {
        reads_context = true;
        if (!d.cpp) os << in << "const double* h = " << d.hoisted_array(f) << ";\n";
    }
    if (!d.cpp && !reads_context) os << in << "(void)c;\n";
    offset = 1;
    for (std::size_t a = 0; a < f.arrays.size(); ++a) {
        for (std::size_t k = 0; k < lengths[a]; ++k)
            if (read[offset + k])
                os << in << pr.define(names.inputs[offset + k], pr.element(f.arrays[a], k))
                   << '\n';
        offset += lengths[a];
    }
    pr.print(os, p, p.body, names, in);
    std::size_t k = 0;
    for (std::size_t r = 0; r < f.results.size(); ++r)
        for (std::size_t j = 0; j < f.result_sizes[r]; ++j, ++k)
            os << in << pr.assign(pr.element(f.results[r], j), pr.operand(p, p.outputs[k], names))
               << '\n';
}

// the prelude of a function inside init: its parameters, then its values stored
void print_prelude(std::ostream& os, const CodeFunction& f, const Dialect& d,
                   const CodePrinter& pr, const ValueSpelling& names) {
    const StraightLineProgram& p = f.program;
    if (p.prelude.empty()) return;
    const std::string in = "        ";
    os << "    {\n" << in << pr.comment(f.name + ": values of the parameters only") << '\n';
    std::vector<bool> params(p.parameter_count, false);
    for (const ProgramInstruction& i : p.prelude) {
        auto mark = [&](std::uint32_t v) {
            if (p.kind(v) == ValueKind::parameter) params[v - p.input_count] = true;
        };
        if (i.op == ProgramOp::combine)
            for (std::uint32_t k = i.a; k < i.a + i.b; ++k) mark(p.terms[k].value);
        else {
            mark(i.a);
            if (i.op != ProgramOp::sincos) mark(i.b);
        }
    }
    for (std::size_t k = 0; k < params.size(); ++k)
        if (params[k])
            os << in << pr.define(names.parameters[k], d.parameter(names.parameters[k])) << '\n';
    if (!d.cpp) os << in << "double* h = " << d.hoisted_array(f) << ";\n";
    pr.print(os, p, p.prelude, names, in);
    os << "    }\n";
}

// The Cholesky factorization, and the solve with it for m right sides at once (forward
// dynamics solves for one, the derivatives for 2 nq more).
std::string cholesky_factor_and_back(const Dialect& d) {
    std::ostringstream os;
    const std::string st = d.cpp ? "" : "static ";
    const std::string prefix = d.cpp ? "" : d.name + "_";
    os << "/* The Cholesky factorization A = L L^T of a symmetric positive definite A (n x n,\n"
          "   row by row; L overwrites A's lower triangle); returns 0, or -1 if A is not\n"
          "   positive definite. */\n"
       << st << "int " << prefix << "cholesky_factor(int n, double* A) {\n"
          "    for (int j = 0; j < n; ++j) {\n"
          "        double s = A[j * n + j];\n"
          "        for (int k = 0; k < j; ++k) s -= A[j * n + k] * A[j * n + k];\n"
          "        if (!(s > 0.0)) return -1;\n"
          "        const double d = " << d.math("sqrt") << "(s);\n"
          "        A[j * n + j] = d;\n"
          "        for (int i = j + 1; i < n; ++i) {\n"
          "            double r = A[i * n + j];\n"
          "            for (int k = 0; k < j; ++k) r -= A[i * n + k] * A[j * n + k];\n"
          "            A[i * n + j] = r / d;\n"
          "        }\n"
          "    }\n"
          "    return 0;\n"
          "}\n\n"
          "/* Solves L L^T X = B in place for m right sides (X n x m, row by row, holds B on\n"
          "   entry), L from cholesky_factor: row operations, the inner loops over the m. */\n"
       << st << "void " << prefix << "cholesky_back(int n, int m, const double* L, double* X) {\n"
          "    for (int i = 0; i < n; ++i) { /* L Y = B */\n"
          "        double* x = X + i * m;\n"
          "        for (int k = 0; k < i; ++k) {\n"
          "            const double l = L[i * n + k];\n"
          "            const double* y = X + k * m;\n"
          "            for (int j = 0; j < m; ++j) x[j] -= l * y[j];\n"
          "        }\n"
          "        const double d = 1.0 / L[i * n + i];\n"
          "        for (int j = 0; j < m; ++j) x[j] *= d;\n"
          "    }\n"
          "    for (int i = n - 1; i >= 0; --i) { /* L^T X = Y */\n"
          "        double* x = X + i * m;\n"
          "        for (int k = i + 1; k < n; ++k) {\n"
          "            const double l = L[k * n + i];\n"
          "            const double* y = X + k * m;\n"
          "            for (int j = 0; j < m; ++j) x[j] -= l * y[j];\n"
          "        }\n"
          "        const double d = 1.0 / L[i * n + i];\n"
          "        for (int j = 0; j < m; ++j) x[j] *= d;\n"
          "    }\n"
          "}\n";
    return os.str();
}

// The LU factorization with partial pivoting, and the solve with it for m right sides at
// once (forward dynamics solves for one, the derivatives for 2 nq more).
std::string lu_factor_and_back(const Dialect& d) {
    std::ostringstream os;
    const std::string st = d.cpp ? "" : "static ";
    const std::string prefix = d.cpp ? "" : d.name + "_";
    os << "/* The LU decomposition of A (n x n, row by row, overwritten by L below the\n"
          "   diagonal and U on and above it) with partial pivoting, p[k] the row swapped\n"
          "   with row k; returns 0, or -1 if A is singular. */\n"
       << st << "int " << prefix << "lu_factor(int n, double* A, int* p) {\n"
          "    for (int k = 0; k < n; ++k) {\n"
          "        int m = k;\n"
          "        for (int i = k + 1; i < n; ++i)\n"
          "            if (" << d.math("fabs") << "(A[i * n + k]) > " << d.math("fabs")
       << "(A[m * n + k])) m = i;\n"
          "        if (!(" << d.math("fabs") << "(A[m * n + k]) > 0.0)) return -1;\n"
          "        p[k] = m;\n"
          "        if (m != k)\n"
          "            for (int j = 0; j < n; ++j) {\n"
          "                const double s = A[k * n + j];\n"
          "                A[k * n + j] = A[m * n + j];\n"
          "                A[m * n + j] = s;\n"
          "            }\n"
          "        for (int i = k + 1; i < n; ++i) {\n"
          "            const double l = A[i * n + k] / A[k * n + k];\n"
          "            A[i * n + k] = l;\n"
          "            for (int j = k + 1; j < n; ++j) A[i * n + j] -= l * A[k * n + j];\n"
          "        }\n"
          "    }\n"
          "    return 0;\n"
          "}\n\n"
          "/* Solves A X = B in place for m right sides (X n x m, row by row, holds B on\n"
          "   entry), A and p from lu_factor: row operations, the inner loops over the m.\n"
          "   lu_factor swaps whole rows, L's multipliers too (P A = L U), so every swap is\n"
          "   applied to B before L Y = P B is solved. */\n"
       << st << "void " << prefix << "lu_back(int n, int m, const double* A, const int* p, double* X) {\n"
          "    for (int k = 0; k < n; ++k)\n"
          "        if (p[k] != k) {\n"
          "            double* x = X + k * m;\n"
          "            double* y = X + p[k] * m;\n"
          "            for (int j = 0; j < m; ++j) {\n"
          "                const double s = x[j];\n"
          "                x[j] = y[j];\n"
          "                y[j] = s;\n"
          "            }\n"
          "        }\n"
          "    for (int k = 0; k < n; ++k) {\n"
          "        const double* x = X + k * m;\n"
          "        for (int i = k + 1; i < n; ++i) {\n"
          "            const double l = A[i * n + k];\n"
          "            double* y = X + i * m;\n"
          "            for (int j = 0; j < m; ++j) y[j] -= l * x[j];\n"
          "        }\n"
          "    }\n"
          "    for (int i = n - 1; i >= 0; --i) {\n"
          "        double* x = X + i * m;\n"
          "        for (int k = i + 1; k < n; ++k) {\n"
          "            const double u = A[i * n + k];\n"
          "            const double* y = X + k * m;\n"
          "            for (int j = 0; j < m; ++j) x[j] -= u * y[j];\n"
          "        }\n"
          "        const double d = 1.0 / A[i * n + i];\n"
          "        for (int j = 0; j < m; ++j) x[j] *= d;\n"
          "    }\n"
          "}\n";
    return os.str();
}

std::string solvers(const CodePlan& plan, const Dialect& d) {
    std::ostringstream os;
    const std::string st = d.cpp ? "" : "static ";
    const std::string prefix = d.cpp ? "" : d.name + "_";
    if (!plan.accelerations.empty()) return os.str();  // forward dynamics solves nothing
    if (plan.symmetric_mass_matrix) {
        os << cholesky_factor_and_back(d) << "\n"
           << "/* Solves A x = b for a symmetric positive definite A (n x n, row by row) by the\n"
              "   Cholesky factorization A = L L^T (L overwrites A's lower triangle); returns 0,\n"
              "   or -1 if A is not positive definite. */\n"
           << st << "int " << prefix << "cholesky_solve(int n, double* A, const double* b, double* x) {\n"
              "    if (" << prefix << "cholesky_factor(n, A) != 0) return -1;\n"
              "    for (int i = 0; i < n; ++i) x[i] = b[i];\n"
              "    " << prefix << "cholesky_back(n, 1, A, x);\n"
              "    return 0;\n"
              "}\n";
    } else {
        os << lu_factor_and_back(d) << "\n"
           << "/* Solves A x = b (A n x n, row by row, overwritten by its LU decomposition, p its\n"
              "   n pivots) by LU decomposition with partial pivoting; returns 0, or -1 if A is\n"
              "   singular. */\n"
           << st << "int " << prefix << "lu_solve(int n, double* A, int* p, const double* b, double* x) {\n"
              "    if (" << prefix << "lu_factor(n, A, p) != 0) return -1;\n"
              "    for (int i = 0; i < n; ++i) x[i] = b[i];\n"
              "    " << prefix << "lu_back(n, 1, A, p, x);\n"
              "    return 0;\n"
              "}\n";
    }
    return os.str();
}

// with derivatives: M factored once and solved for many right sides (qpp and 2 nq columns);
// forward dynamics' cholesky_solve or lu_solve brought the factorization and the solve, unless
// the accelerations are explicit
std::string derivative_solvers(const CodePlan& plan, const Dialect& d) {
    if (plan.inverse_dynamics_derivatives.empty() || plan.accelerations.empty()) return "";
    return plan.symmetric_mass_matrix ? cholesky_factor_and_back(d) : lu_factor_and_back(d);
}

// forward dynamics with its derivatives: qpp, then d u/d q and d u/d qp of inverse dynamics at
// qpp turned into d qpp/d q = M^-1 A du/dq, d qpp/d qp = M^-1 A du/dqp (A the loads'
// coefficients in E = b - A u, -I for M qpp + h = u), M factored once
std::string forward_derivatives(const CodePlan& plan, const Dialect& d, const CodePrinter& pr) {
    std::ostringstream os;
    if (plan.inverse_dynamics_derivatives.empty()) return os.str();
    const std::string owner = d.cpp ? "Model::" : "";
    const std::string ctx = d.cpp ? "" : "const " + d.name + "_context* c, ";
    const std::string cnst = d.cpp ? " const" : "";
    const std::string c_arg = d.cpp ? "" : "c, ";
    const std::string nq = d.size("nq");
    const std::string prefix = d.cpp ? "" : d.name + "_";
    const std::string fail = d.cpp ? "false" : "-1", ok = d.cpp ? "true" : "0";
    const bool chol = plan.symmetric_mass_matrix;
    const bool aba = !plan.accelerations.empty();
    const bool need_f = !aba || plan.mass_matrix.empty();
    std::string factor = chol ? prefix + "cholesky_factor(" + nq + ", M)"
                              : prefix + "lu_factor(" + nq + ", M, p)";
    // M^-1 on m right sides, row by row in X
    auto back = [&](const std::string& m, const std::string& X) {
        return chol ? prefix + "cholesky_back(" + nq + ", " + m + ", M, " + X + ")"
                    : prefix + "lu_back(" + nq + ", " + m + ", M, p, " + X + ")";
    };
    const bool negated = plan.negated_identity_loads();
    os << "\n" << (d.cpp ? "bool " : "int ") << owner << d.function("forward_dynamics_derivatives")
       << "(" << ctx
       << "double t, const double* q, const double* qp, const double* u, double* qpp,\n"
       << "    double* dqpp_dq, double* dqpp_dqp)" << cnst << " {\n"
       << "    double M[" << nq << " * " << nq << "]" << (need_f ? ", f[" + nq + "]" : "")
       << (negated ? "" : ", T[" + nq + " * " + nq + "]") << ";\n";
    if (!chol) os << "    int p[" << nq << "];\n";
    if (!negated) {
        // A of E = b - A u, row by row
        os << "    static const double A[" << nq << " * " << nq << "] = {";
        for (std::size_t k = 0; k < plan.load_coefficients.size(); ++k)
            os << (k ? ", " : "") << pr.number(plan.load_coefficients[k]);
        os << "};\n";
    }
    os << "    int i, k;\n";
    if (!aba)
        os << "    /* qpp = M^-1 f, M factored for the derivatives too */\n"
           << "    " << d.function("mass_forcing") << "(" << c_arg << "t, q, qp, u, M, f);\n"
           << "    if (" << factor << " != 0) return " << fail << ";\n"
           << "    for (i = 0; i < " << nq << "; ++i) qpp[i] = f[i];\n"
           << "    " << back("1", "qpp") << ";\n";
    else {
        os << "    /* qpp by the articulated-body recursion, then M factored */\n"
           << "    if (" << (d.cpp ? "!" : "") << d.function("forward_dynamics") << "(" << c_arg
           << "t, q, qp, u, qpp)" << (d.cpp ? "" : " != 0") << ") return " << fail << ";\n";
        if (!plan.mass_matrix.empty())
            os << "    " << d.function("mass_matrix") << "(" << c_arg << "t, q, M);\n";
        else
            os << "    " << d.function("mass_forcing") << "(" << c_arg << "t, q, qp, u, M, f);\n";
        os << "    if (" << factor << " != 0) return " << fail << ";\n";
    }
    os << "    /* d u/d q and d u/d qp of inverse dynamics at qpp, then in their place\n"
       << "       d qpp/d q = " << (negated ? "-M^-1 du/dq" : "M^-1 A du/dq")
       << " and the same for qp, nq right sides at once */\n"
       << "    " << d.function("inverse_dynamics_derivatives") << "(" << c_arg
       << "t, q, qp, qpp, dqpp_dq, dqpp_dqp);\n"
       << "    for (k = 0; k < 2; ++k) {\n"
       << "        double* D = k == 0 ? dqpp_dq : dqpp_dqp;\n";
    if (negated)
        os << "        for (i = 0; i < " << nq << " * " << nq << "; ++i) D[i] = -D[i];\n";
    else
        os << "        int j, m;\n"
           << "        for (i = 0; i < " << nq << "; ++i)\n"
           << "            for (j = 0; j < " << nq << "; ++j) {\n"
           << "                double s = 0.0;\n"
           << "                for (m = 0; m < " << nq << "; ++m) s += A[i * " << nq << " + m] * D[m * "
           << nq << " + j];\n"
           << "                T[i * " << nq << " + j] = s;\n"
           << "            }\n"
           << "        for (i = 0; i < " << nq << " * " << nq << "; ++i) D[i] = T[i];\n";
    os << "        " << back(nq, "D") << ";\n"
       << "    }\n"
       << "    return " << ok << ";\n}\n";
    return os.str();
}

// the declarations of equations in generalized speeds, state (q, ur)
std::string speed_declarations(const CodePlan& plan, const Dialect& d) {
    std::ostringstream os;
    const std::string ind = d.cpp ? "    " : "";
    const std::string ctx = d.cpp ? "" : "const " + d.name + "_context* c, ";
    const std::string cnst = d.cpp ? " const" : "";
    const std::string solve = plan.symmetric_mass_matrix ? "Cholesky" : "LU with partial pivoting";
    const std::string fail = d.cpp ? "false" : "-1";
    os << ind << "/* Mass matrix M (nur x nur, row by row) and forcing f of M urp = f, ur the\n"
       << ind << "   independent speeds. */\n"
       << ind << "void " << d.function("mass_forcing") << "(" << ctx << arguments(plan.mass_forcing)
       << ")" << cnst << ";\n"
       << ind << "/* The coordinate rates qp = k(q, ur): the kinematic differential equations,\n"
       << ind << "   the dependent speeds replaced. */\n"
       << ind << "void " << d.function("kinematics") << "(" << ctx << arguments(plan.kinematics)
       << ")" << cnst << ";\n";
    if (!plan.dependent_speed_function.empty())
        os << ind << "/* The dependent speeds us (" << detail::names_of(plan.dependent_speeds)
           << ") from the motion constraints. */\n"
           << ind << "void " << d.function("dependent_speeds") << "(" << ctx
           << arguments(plan.dependent_speed_function) << ")" << cnst << ";\n";
    os << ind << "/* Forward dynamics: the rates urp = M^-1 f of the independent speeds (" << solve
       << ");\n"
       << ind << "   returns " << fail << " if M is singular. */\n"
       << ind << (d.cpp ? "bool " : "int ") << d.function("forward_dynamics") << "(" << ctx
       << "double t, const double* q, const double* ur, const double* u, double* urp)" << cnst
       << ";\n";
    if (!plan.output_function.empty())
        os << ind << "/* The requested outputs y. */\n"
           << ind << "void " << d.function("outputs") << "(" << ctx
           << arguments(plan.output_function) << ")" << cnst << ";\n";
    if (!plan.load_laws.empty())
        os << ind << "/* The loads u during a simulation, from t, q and ur. */\n"
           << ind << "void " << d.function("load_laws") << "(" << ctx
           << arguments(plan.load_laws) << ")" << cnst << ";\n";
    os << ind << "/* Right-hand side of x' = (qp, urp) for x = (q, ur), loads from load_laws (the\n"
       << ind << "   motion constraints hold at every state: no stabilisation); returns " << fail
       << "\n"
       << ind << "   if M is singular. */\n"
       << ind << (d.cpp ? "bool " : "int ") << d.function("rhs") << "(" << ctx
       << "double t, const double* x, double* dx)" << cnst << ";\n";
    return os.str();
}

// the declarations of the header (C: prototypes; C++: the class's members)
std::string declarations(const CodePlan& plan, const Dialect& d) {
    if (plan.speed_form) return speed_declarations(plan, d);
    std::ostringstream os;
    const std::string ind = d.cpp ? "    " : "";
    const std::string ctx = d.cpp ? "" : "const " + d.name + "_context* c, ";
    const std::string cnst = d.cpp ? " const" : "";
    const std::string solve = plan.symmetric_mass_matrix ? "Cholesky" : "LU with partial pivoting";
    const bool constrained = plan.constraint_count() > 0;
    if (constrained)
        os << ind << "/* Coefficients A ((nq + nc) x (nq + nc), row by row) and right side b of\n"
           << ind << "   A x = b, x = (qpp, lambda) with lambda the constraint forces: the equations\n"
           << ind << "   of motion, then the constraints at the acceleration level. */\n";
    else
        os << ind << "/* Mass matrix M (nq x nq, row by row) and forcing f of M qpp = f. */\n";
    os << ind << "void " << d.function("mass_forcing") << "(" << ctx
       << arguments(plan.mass_forcing) << ")" << cnst << ";\n"
       << ind;
    if (constrained)
        os << "/* Per constraint its value c (0 for a motion constraint) and its velocity-level\n"
           << ind << "   value c' (g for a motion constraint g = 0): e[2 i], e[2 i + 1]. */\n"
           << ind << "void " << d.function("constraint_drift") << "(" << ctx
           << arguments(plan.constraint_drift) << ")" << cnst << ";\n"
           << ind << "/* The accelerations qpp and the constraint forces lambda from A x = b (LU with\n"
           << ind << "   partial pivoting); returns " << (d.cpp ? "false" : "-1") << " if A is singular. */\n"
           << ind << (d.cpp ? "bool " : "int ") << d.function("constrained_dynamics") << "(" << ctx
           << "double t, const double* q, const double* qp, const double* u, double* qpp, "
              "double* lambda)" << cnst << ";\n"
           << ind << "/* Forward dynamics: the accelerations qpp (constrained_dynamics);\n"
           << ind << "   returns " << (d.cpp ? "false" : "-1") << " if A is singular. */\n";
    else if (!plan.accelerations.empty())
        os << "/* The accelerations qpp from the loads u by the articulated-body recursion (no\n"
           << ind << "   mass matrix, no solve). */\n"
           << ind << "void " << d.function("accelerations") << "(" << ctx
           << arguments(plan.accelerations) << ")" << cnst << ";\n"
           << ind << "/* Forward dynamics: the accelerations qpp (articulated-body recursion);\n"
           << ind << "   returns " << (d.cpp ? "false" : "-1") << " if one is not finite. */\n";
    else
        os << "/* Forward dynamics: the accelerations qpp = M^-1 f (" << solve << ");\n"
           << ind << "   returns " << (d.cpp ? "false" : "-1") << " if M is singular. */\n";
    os << ind << (d.cpp ? "bool " : "int ") << d.function("forward_dynamics") << "(" << ctx
       << "double t, const double* q, const double* qp, const double* u, double* qpp)" << cnst
       << ";\n";
    if (!plan.mass_matrix.empty())
        os << ind << "/* The mass matrix M (nq x nq, row by row) alone, by the composite-rigid-body\n"
           << ind << "   recursion. */\n"
           << ind << "void " << d.function("mass_matrix") << "(" << ctx
           << arguments(plan.mass_matrix) << ")" << cnst << ";\n";
    if (!plan.bias_forces.empty())
        os << ind << "/* The bias forces C(q, qp) qp + g(q) alone (with no loads, f = -bias). */\n"
           << ind << "void " << d.function("bias_forces") << "(" << ctx
           << arguments(plan.bias_forces) << ")" << cnst << ";\n";
    for (const CodeFunction& f : plan.jacobian_functions)
        os << ind << "/* The " << f.summary << ". */\n"
           << ind << "void " << d.function(f.name) << "(" << ctx << arguments(f) << ")" << cnst
           << ";\n";
    if (!plan.inverse_dynamics.empty())
        os << ind << "/* Inverse dynamics: the loads u that give the accelerations qpp. */\n"
           << ind << "void " << d.function("inverse_dynamics") << "(" << ctx
           << arguments(plan.inverse_dynamics) << ")" << cnst << ";\n";
    if (!plan.inverse_dynamics_derivatives.empty())
        os << ind << "/* Derivatives of inverse dynamics at fixed qpp: dtau_dq[i nq + j] = d u_i/d q_j\n"
           << ind << "   and dtau_dqp[i nq + j] = d u_i/d qp_j (d u/d qpp is the mass matrix). */\n"
           << ind << "void " << d.function("inverse_dynamics_derivatives") << "(" << ctx
           << arguments(plan.inverse_dynamics_derivatives) << ")" << cnst << ";\n"
           << ind << "/* Forward dynamics with its derivatives: qpp, dqpp_dq[i nq + j] = d qpp_i/d q_j\n"
           << ind << "   and dqpp_dqp[i nq + j] = d qpp_i/d qp_j, from inverse dynamics' derivatives\n"
           << ind << "   at qpp: d qpp/d q = "
           << (plan.negated_identity_loads() ? "-M^-1 du/dq" : "M^-1 A du/dq (A the loads' coefficients)")
           << ", the same for qp (M factored by\n"
           << ind << "   " << (plan.symmetric_mass_matrix ? "Cholesky" : "LU with partial pivoting")
           << "); returns " << (d.cpp ? "false" : "-1") << " if M is singular. */\n"
           << ind << (d.cpp ? "bool " : "int ") << d.function("forward_dynamics_derivatives") << "("
           << ctx << "double t, const double* q, const double* qp, const double* u,\n"
           << ind << "    double* qpp, double* dqpp_dq, double* dqpp_dqp)" << cnst << ";\n";
    if (!plan.reactions.empty()) {
        std::string measures, slots;
        for (std::size_t k = 0; k < plan.reaction_loads.size(); ++k) {
            measures += (k ? ", " : "") + plan.loads[plan.reaction_loads[k]].name;
            slots += (k ? ", " : "") + std::to_string(plan.reaction_loads[k]);
        }
        os << ind << "/* The joint-reaction measures reaction[] = (" << measures << "), the loads\n"
           << ind << "   u[" << slots << "], from their road-map rows at the accelerations qpp: call\n"
           << ind << "   forward_dynamics first; u's other entries are the loads that act (those\n"
           << ind << "   entries unread). The load laws give 0 for them: they do no work. */\n"
           << ind << "void " << d.function("reactions") << "(" << ctx
           << arguments(plan.reactions) << ")" << cnst << ";\n";
    }
    if (!plan.output_function.empty())
        os << ind << "/* The requested outputs y. */\n"
           << ind << "void " << d.function("outputs") << "(" << ctx
           << arguments(plan.output_function) << ")" << cnst << ";\n";
    if (!plan.load_laws.empty())
        os << ind << "/* The loads u during a simulation, from t, q and qp. */\n"
           << ind << "void " << d.function("load_laws") << "(" << ctx
           << arguments(plan.load_laws) << ")" << cnst << ";\n";
    if (constrained)
        os << ind << "/* Right-hand side of x' = (qp, qpp) for x = (q, qp), loads from load_laws,\n"
           << ind << "   the constraints stabilised by Baumgarte's method at the rate a =\n"
           << ind << "   " << d.size("stabilization") << ": c'' + 2 a c' + a^2 c = 0, g' + a g = 0;\n"
           << ind << "   returns " << (d.cpp ? "false" : "-1") << " if A is singular. */\n";
    else
        os << ind << "/* Right-hand side of x' = (qp, qpp) for x = (q, qp), loads from load_laws;\n"
           << ind << "   returns " << (d.cpp ? "false" : "-1") << " if M is singular. */\n";
    os
       << ind << (d.cpp ? "bool " : "int ") << d.function("rhs") << "(" << ctx
       << "double t, const double* x, double* dx)" << cnst << ";\n";
    return os.str();
}

std::string forward_and_rhs(const CodePlan& plan, const Dialect& d) {
    std::ostringstream os;
    const std::string owner = d.cpp ? "Model::" : "";
    const std::string ctx = d.cpp ? "" : "const " + d.name + "_context* c, ";
    const std::string cnst = d.cpp ? " const" : "";
    const std::string c_arg = d.cpp ? "" : "c, ";
    const std::string nq = d.size("nq"), nu = d.size("nu");
    const bool lu = !plan.symmetric_mass_matrix;
    const std::string solver = (d.cpp ? "" : d.name + "_") + std::string(lu ? "lu_solve" : "cholesky_solve");
    // the solver's call on n unknowns; LU's pivots, `pivots(n)`, declared before it
    auto solve = [&](const std::string& n, const std::string& A, const std::string& b, const std::string& x) {
        return solver + "(" + n + ", " + A + (lu ? ", p, " : ", ") + b + ", " + x + ")";
    };
    auto pivots = [&](const std::string& n) { return lu ? "    int p[" + n + "];\n" : std::string(); };
    const std::size_t nc = plan.constraint_count();
    if (plan.speed_form) {
        // x = (q, ur): q' from the kinematic equations, ur' = M^-1 f
        const std::string nur = d.size("nur");
        os << (d.cpp ? "bool " : "int ") << owner << d.function("forward_dynamics") << "(" << ctx
           << "double t, const double* q, const double* ur, const double* u, double* urp)" << cnst
           << " {\n"
           << "    double M[" << nur << " * " << nur << "], f[" << nur << "];\n"
           << pivots(nur)
           << "    " << d.function("mass_forcing") << "(" << c_arg << "t, q, ur, u, M, f);\n"
           << "    return " << solve(nur, "M", "f", "urp") << (d.cpp ? " == 0" : "")
           << ";\n}\n\n"
           << (d.cpp ? "bool " : "int ") << owner << d.function("rhs") << "(" << ctx
           << "double t, const double* x, double* dx)" << cnst << " {\n";
        std::string u = d.null();
        if (plan.load_count > 0) {
            os << "    double u[" << nu << "];\n"
               << "    " << d.function("load_laws") << "(" << c_arg << "t, x, x + " << nq << ", u);\n";
            u = "u";
        }
        os << "    " << d.function("kinematics") << "(" << c_arg << "t, x, x + " << nq << ", dx);\n"
           << "    return " << d.function("forward_dynamics") << "(" << c_arg << "t, x, x + " << nq
           << ", " << u << ", dx + " << nq << ");\n}\n";
        return os.str();
    }
    if (nc > 0) {
        // A x = b in x = (qpp, lambda); k = nq + nc unknowns
        const std::string k = "(" + nq + " + " + d.size("nc") + ")";
        const std::string type = d.cpp ? "bool " : "int ", ok = d.cpp ? "true" : "0",
                          fail = d.cpp ? "false" : "-1";
        os << type << owner << d.function("constrained_dynamics") << "(" << ctx
           << "double t, const double* q, const double* qp, const double* u, double* qpp, "
              "double* lambda)" << cnst << " {\n"
           << "    double A[" << k << " * " << k << "], b[" << k << "], x[" << k << "];\n"
           << pivots(k) << "    int i;\n"
           << "    " << d.function("mass_forcing") << "(" << c_arg << "t, q, qp, u, A, b);\n"
           << "    if (" << solve(k, "A", "b", "x") << " != 0) return " << fail << ";\n"
           << "    for (i = 0; i < " << nq << "; ++i) qpp[i] = x[i];\n"
           << "    for (i = 0; i < " << d.size("nc") << "; ++i) lambda[i] = x[" << nq << " + i];\n"
           << "    return " << ok << ";\n}\n\n"
           << type << owner << d.function("forward_dynamics") << "(" << ctx
           << "double t, const double* q, const double* qp, const double* u, double* qpp)" << cnst
           << " {\n"
           << "    double lambda[" << d.size("nc") << "];\n"
           << "    return " << d.function("constrained_dynamics") << "(" << c_arg
           << "t, q, qp, u, qpp, lambda);\n}\n\n"
           << type << owner << d.function("rhs") << "(" << ctx
           << "double t, const double* x, double* dx)" << cnst << " {\n"
           << "    const double a = " << d.size("stabilization") << ";\n"
           << "    double A[" << k << " * " << k << "], b[" << k << "], y[" << k << "], e[2 * "
           << d.size("nc") << "];\n"
           << pivots(k) << "    int i;\n";
        std::string u = d.null();
        if (plan.load_count > 0) {
            os << "    double u[" << nu << "];\n"
               << "    " << d.function("load_laws") << "(" << c_arg << "t, x, x + " << nq << ", u);\n";
            u = "u";
        }
        os << "    " << d.function("mass_forcing") << "(" << c_arg << "t, x, x + " << nq << ", " << u
           << ", A, b);\n"
           << "    " << d.function("constraint_drift") << "(" << c_arg << "t, x, x + " << nq
           << ", e);\n";
        for (std::size_t i = 0; i < nc; ++i)
            if (plan.constraint_kinds[i] == ConstraintKind::configuration)
                os << "    b[" << nq << " + " << i << "] += 2.0 * a * e[" << 2 * i + 1
                   << "] + a * a * e[" << 2 * i << "]; /* " << plan.constraint_names[i] << " */\n";
            else
                os << "    b[" << nq << " + " << i << "] += a * e[" << 2 * i + 1 << "]; /* "
                   << plan.constraint_names[i] << " */\n";
        os << "    if (" << solve(k, "A", "b", "y") << " != 0) return " << fail << ";\n"
           << "    for (i = 0; i < " << nq << "; ++i) {\n"
           << "        dx[i] = x[" << nq << " + i];\n"
           << "        dx[" << nq << " + i] = y[i];\n"
           << "    }\n"
           << "    return " << ok << ";\n}\n";
        return os.str();
    }
    os << (d.cpp ? "bool " : "int ") << owner << d.function("forward_dynamics") << "(" << ctx
       << "double t, const double* q, const double* qp, const double* u, double* qpp)" << cnst
       << " {\n";
    if (!plan.accelerations.empty())
        os << "    " << d.function("accelerations") << "(" << c_arg << "t, q, qp, u, qpp);\n"
           << "    for (int i = 0; i < " << nq << "; ++i)\n"
           << "        if (!(qpp[i] - qpp[i] == 0)) return " << (d.cpp ? "false" : "-1")
           << ";  /* not finite: a singular articulated inertia */\n"
           << "    return " << (d.cpp ? "true" : "0") << ";\n}\n\n";
    else
        os << "    double M[" << nq << " * " << nq << "], f[" << nq << "];\n"
           << pivots(nq)
           << "    " << d.function("mass_forcing") << "(" << c_arg << "t, q, qp, u, M, f);\n"
           << "    return " << solve(nq, "M", "f", "qpp") << (d.cpp ? " == 0" : "")
           << ";\n}\n\n";
    os << (d.cpp ? "bool " : "int ") << owner << d.function("rhs") << "(" << ctx
       << "double t, const double* x, double* dx)" << cnst << " {\n";
    std::string u = d.null();
    if (plan.load_count > 0) {
        os << "    double u[" << nu << "];\n"
           << "    " << d.function("load_laws") << "(" << c_arg << "t, x, x + " << nq << ", u);\n";
        u = "u";
    }
    os << "    for (int i = 0; i < " << nq << "; ++i) dx[i] = x[" << nq << " + i];\n"
       << "    return " << d.function("forward_dynamics") << "(" << c_arg << "t, x, x + " << nq
       << ", " << u << ", dx + " << nq << ");\n}\n";
    return os.str();
}

// ---- the simulation program ---------------------------------------------------------------------

std::string labelled(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " [" + unit + "]";
}

// "t [s],qA [rad],...": the CSV columns t, q, q', loads, outputs
std::string csv_header(const CodePlan& plan) {
    std::string h = "t [s]";
    for (const auto* v : {&plan.q, &plan.qp, &plan.loads, &plan.outputs})
        for (const CodeSymbol& s : *v) h += "," + labelled(s.name, s.unit);
    return h;
}

std::string list(const std::vector<double>& values, const CodePrinter& pr) {
    std::string s;
    for (double v : values) s += (s.empty() ? "" : ", ") + pr.number(v);
    return s;
}

std::string main_program(const CodePlan& plan, const Dialect& d, const CodePrinter& pr) {
    const SimulationSpec& sim = plan.simulation_spec;
    const std::string nq = d.size("nq"), nu = d.size("nu"), ny = d.size("ny");
    const std::string m = d.cpp ? "model." : d.name + "_";
    const std::string ctx = d.cpp ? "" : "&c, ";
    const std::string model_arg = d.cpp ? "const " + d.name + "::Model& model" : "const " + d.name + "_context* c";
    const std::string call_ctx = d.cpp ? "" : "c, ";
    const std::string nx = d.cpp ? "nx" : "NX";
    // the velocity part of the state: q' (nq of them) or the independent speeds
    const std::string nv = plan.speed_form ? d.size("nur") : nq;
    std::ostringstream os;
    os << "\n";
    if (d.cpp)
        os << "#include <algorithm>\n#include <cmath>\n#include <cstdio>\n#include <cstdlib>\n"
              "#include <cstring>\n\n#include \"" << d.name << ".hpp\"\n\nnamespace {\n\n"
           << "using namespace " << d.name << ";\nconstexpr int nx = nq + " << nv << ";\n";
    else
        os << "#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n"
              "#include \"" << d.name << ".h\"\n\n#define NX (" << nq << " + " << nv << ")\n";
    const std::string st = d.cpp ? "" : "static ";
    const std::string fabs = d.math("fabs"), sqrt = d.math("sqrt"), pow = d.math("pow");
    os << "\n/* The simulation: final time, output step and error tolerances. */\n"
       << st << "const double final_time = " << pr.number(sim.final_time) << ";\n"
       << st << "const double output_step = " << pr.number(sim.output_step) << ";\n"
       << st << "const double abs_tol = " << pr.number(sim.absolute_tolerance) << ";\n"
       << st << "const double rel_tol = " << pr.number(sim.relative_tolerance) << ";\n"
       << "/* Initial values: q, then " << (plan.speed_form ? "ur" : "qp") << ". */\n"
       << st << "const double x0[" << nx << "] = {" << list(sim.initial_q, pr)
       << ", " << list(sim.initial_qp, pr) << "};\n\n";
    os << R"(/* One Dormand-Prince 5(4) step of size h from (t, x) with k1 = f(t, x): the fifth-order
   solution xn, k7 = f(t + h, xn) (the next step's k1), and the weighted RMS norm of the
   difference from the embedded fourth-order solution (accept when <= 1).
   Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19-26. */
)" << st << "int step(" << model_arg << ", double t, const double* x, const double* k1, double h,\n"
       << "                double* xn, double* k7, double* err) {\n"
       << R"(    double k2[NX], k3[NX], k4[NX], k5[NX], k6[NX], y[NX];
    int i;
    for (i = 0; i < NX; ++i) y[i] = x[i] + h * (1.0 / 5.0) * k1[i];
    if (!RHS(t + h / 5.0, y, k2)) return 0;
    for (i = 0; i < NX; ++i) y[i] = x[i] + h * (3.0 / 40.0 * k1[i] + 9.0 / 40.0 * k2[i]);
    if (!RHS(t + 3.0 * h / 10.0, y, k3)) return 0;
    for (i = 0; i < NX; ++i)
        y[i] = x[i] + h * (44.0 / 45.0 * k1[i] - 56.0 / 15.0 * k2[i] + 32.0 / 9.0 * k3[i]);
    if (!RHS(t + 4.0 * h / 5.0, y, k4)) return 0;
    for (i = 0; i < NX; ++i)
        y[i] = x[i] + h * (19372.0 / 6561.0 * k1[i] - 25360.0 / 2187.0 * k2[i] +
                           64448.0 / 6561.0 * k3[i] - 212.0 / 729.0 * k4[i]);
    if (!RHS(t + 8.0 * h / 9.0, y, k5)) return 0;
    for (i = 0; i < NX; ++i)
        y[i] = x[i] + h * (9017.0 / 3168.0 * k1[i] - 355.0 / 33.0 * k2[i] +
                           46732.0 / 5247.0 * k3[i] + 49.0 / 176.0 * k4[i] -
                           5103.0 / 18656.0 * k5[i]);
    if (!RHS(t + h, y, k6)) return 0;
    for (i = 0; i < NX; ++i)
        xn[i] = x[i] + h * (35.0 / 384.0 * k1[i] + 500.0 / 1113.0 * k3[i] +
                            125.0 / 192.0 * k4[i] - 2187.0 / 6784.0 * k5[i] +
                            11.0 / 84.0 * k6[i]);
    if (!RHS(t + h, xn, k7)) return 0;
    double sum = 0.0;
    for (i = 0; i < NX; ++i) {
        const double e = h * (71.0 / 57600.0 * k1[i] - 71.0 / 16695.0 * k3[i] +
                              71.0 / 1920.0 * k4[i] - 17253.0 / 339200.0 * k5[i] +
                              22.0 / 525.0 * k6[i] - 1.0 / 40.0 * k7[i]);
        const double scale = abs_tol + rel_tol * FMAX(FABS(x[i]), FABS(xn[i]));
        sum += (e / scale) * (e / scale);
    }
    *err = SQRT(sum / NX);
    return 1;
}

/* One CSV row: t, q, qp, the loads (joint reactions computed at this state) and the outputs
   at (t, x). */
)" << st << "int write_row(FILE* out, " << model_arg << ", double t, const double* x) {\n";
    os << "    double u[" << (plan.load_count ? nu : std::string("1")) << "], qpp[" << nv
       << "], y[" << (plan.outputs.empty() ? std::string("1") : ny) << "];\n"
       << "    int i;\n";
    if (plan.load_count)
        os << "    " << (d.cpp ? "model." : d.name + "_") << "load_laws(" << call_ctx
           << "t, x, x + " << nq << ", u);\n";
    else
        os << "    u[0] = 0.0;\n    (void)u;\n";
    os << "    if (!" << (d.cpp ? std::string("(model.forward_dynamics(") : "(" + d.name + "_forward_dynamics(")
       << call_ctx << "t, x, x + " << nq << ", " << (plan.load_count ? "u" : d.null())
       << ", qpp)" << (d.cpp ? "" : " == 0") << ")) return 0;\n";
    if (!plan.reactions.empty()) {
        // the joint reactions at this state, in place of the load laws' zeros
        os << "    {\n        double r[" << plan.reaction_loads.size() << "];\n"
           << "        " << (d.cpp ? "model." : d.name + "_") << "reactions(" << call_ctx
           << "t, x, x + " << nq << ", qpp, u, r);\n";
        for (std::size_t k = 0; k < plan.reaction_loads.size(); ++k)
            os << "        u[" << plan.reaction_loads[k] << "] = r[" << k << "]; /* "
               << plan.loads[plan.reaction_loads[k]].name << " */\n";
        os << "    }\n";
    }
    if (!plan.outputs.empty())
        os << "    " << (d.cpp ? "model." : d.name + "_") << "outputs(" << call_ctx << "t, x, x + "
           << nq << ", qpp, u, y);\n";
    else
        os << "    y[0] = 0.0;\n    (void)y;\n";
    os << "    fprintf(out, \"%.17g\", t);\n"
       << "    for (i = 0; i < NX; ++i) fprintf(out, \",%.17g\", x[i]);\n";
    if (plan.load_count) os << "    for (i = 0; i < " << nu << "; ++i) fprintf(out, \",%.17g\", u[i]);\n";
    if (!plan.outputs.empty())
        os << "    for (i = 0; i < " << ny << "; ++i) fprintf(out, \",%.17g\", y[i]);\n";
    os << "    fprintf(out, \"\\n\");\n    return 1;\n}\n";
    if (d.cpp) os << "\n}  // namespace\n";
    os << R"(
/* Integrates from x0 to the final time by adaptive Dormand-Prince steps, landing exactly on
   every output time, and writes the CSV to argv[1] (default NAME.csv; "-" for standard
   output). argv[2], when given, replaces the final time. */
int main(int argc, char** argv) {
    const char* path = argc > 1 ? argv[1] : "NAME.csv";
    const double t_final = argc > 2 ? atof(argv[2]) : final_time;
    MODEL_DECL
    double x[NX], k1[NX], xn[NX], k7[NX];
    int i;
    for (i = 0; i < NX; ++i) x[i] = x0[i];
    FILE* out = strcmp(path, "-") == 0 ? stdout : fopen(path, "w");
    if (!out) {
        fprintf(stderr, "NAME: cannot open %s for writing\n", path);
        return 1;
    }
    fprintf(out, "HEADER\n");
    double t = 0.0, h = output_step / 10.0;
    if (!RHS(t, x, k1) || !write_row(out, MODEL_ARG t, x)) {
        fprintf(stderr, "NAME: the mass matrix is singular at t = 0\n");
        return 2;
    }
    for (long k = 1;; ++k) {
        double target = (double)k * output_step;
        if (target > t_final * (1.0 + 1e-12)) break;
        if (target > t_final) target = t_final;
        while (t < target) {
            const int last = h >= target - t;
            const double hh = last ? target - t : h;
            double err = 0.0;
            if (!step(MODEL_ARG t, x, k1, hh, xn, k7, &err)) {
                fprintf(stderr, "NAME: the mass matrix is singular near t = %.17g\n", t);
                return 2;
            }
            /* step size control: 0.9 err^(-1/5), between 0.2 and 5 times */
            double factor = err > 0.0 ? 0.9 * POW(err, -0.2) : 5.0;
            factor = FMIN(5.0, FMAX(0.2, factor));
            if (err <= 1.0) {
                t = last ? target : t + hh;
                for (i = 0; i < NX; ++i) {
                    x[i] = xn[i];
                    k1[i] = k7[i];
                }
                h = last ? FMAX(h, hh * factor) : hh * factor;
            } else {
                h = hh * factor;
            }
            if (h < 1e-14 * FMAX(1.0, FABS(t))) {
                fprintf(stderr, "NAME: step size too small at t = %.17g\n", t);
                return 3;
            }
        }
        if (!write_row(out, MODEL_ARG t, x)) return 2;
    }
    if (out != stdout) fclose(out);
    return 0;
}
)";
    std::string text = os.str();
    auto replace = [&](const std::string& a, const std::string& b) {
        for (std::size_t at = text.find(a); at != std::string::npos; at = text.find(a, at + b.size()))
            text.replace(at, a.size(), b);
    };
    replace("NX", nx);
    replace("RHS(", d.cpp ? "model.rhs(" : "!" + d.name + "_rhs(c, ");
    replace("MODEL_DECL", d.cpp ? "const Model model;"
                                : d.name + "_context context;\n    const " + d.name +
                                      "_context* c = &context;\n    " + d.name +
                                      "_init(&context, 0);");
    replace("MODEL_ARG ", d.cpp ? "model, " : "c, ");
    replace("FMAX(", d.math("fmax("));
    replace("FMIN(", d.math("fmin("));
    replace("FABS(", fabs + "(");
    replace("SQRT(", sqrt + "(");
    replace("POW(", pow + "(");
    replace("NAME.csv", d.name + ".csv");
    replace("NAME:", d.name + ":");
    replace("HEADER", csv_header(plan));
    (void)ctx;
    (void)m;
    return text;
}

// the sizes, each with a comment listing what it counts
using detail::names_of;

std::string constraint_list(const CodePlan& plan) {
    std::string s;
    for (std::size_t i = 0; i < plan.constraint_names.size(); ++i)
        s += (i ? ", " : "") + plan.constraint_names[i] +
             (plan.constraint_kinds[i] == ConstraintKind::configuration ? " (configuration)"
                                                                         : " (motion)");
    return s;
}

std::vector<GeneratedFile> emit_c_family(const CodePlan& plan, const Dialect& d,
                                         const CodePrinter& pr, const IdMap& id,
                                         const std::vector<std::string>& head_lines,
                                         const std::vector<std::string>& source_lines,
                                         const std::vector<std::string>& main_lines,
                                         const std::function<ValueSpelling(const CodeFunction&)>& spell) {
    std::vector<GeneratedFile> files;
    const std::string ext_h = d.cpp ? ".hpp" : ".h", ext_c = d.cpp ? ".cpp" : ".c";
    // ---- header --------------------------------------------------------------------------
    std::ostringstream h;
    h << comment_block(head_lines, d.cpp);
    if (d.cpp) {
        h << "#pragma once\n\nnamespace " << d.name << " {\n\n"
          << "constexpr int nq = " << plan.coordinate_count << ";  // coordinates: "
          << names_of(plan.q) << "\n"
          << "constexpr int nu = " << plan.load_count << ";  // loads: " << names_of(plan.loads)
          << "\n";
        if (plan.constraint_count() > 0) {
            std::string macro = d.name + "_STABILIZATION";
            std::transform(macro.begin(), macro.end(), macro.begin(), ::toupper);
            h << "constexpr int nc = " << plan.constraint_count() << ";  // constraints: "
              << constraint_list(plan) << "; their forces: " << names_of(plan.constraint_forces)
              << "\n"
              << "// The rate [1/s] at which the simulation's right-hand side damps the\n"
              << "// constraints' drift (Baumgarte); define " << macro << " before including to\n"
              << "// change it.\n"
              << "#ifndef " << macro << "\n#define " << macro << " 10.0\n#endif\n"
              << "constexpr double stabilization = " << macro << ";\n";
        }
        if (plan.speed_form)
            h << "constexpr int nur = " << plan.qp.size() << ";  // independent speeds: "
              << names_of(plan.qp) << "\n"
              << "constexpr int nus = " << plan.dependent_speeds.size() << ";  // dependent speeds: "
              << names_of(plan.dependent_speeds) << "\n";
        h
          << "constexpr int ny = " << plan.outputs.size() << ";  // outputs: "
          << names_of(plan.outputs) << "\n\n"
          << "// The model's constants, changeable without generating the code again.\n"
          << "struct Parameters {\n";
        for (const CodeSymbol& p : plan.parameters)
            h << "    double " << id.at(p.name) << " = " << pr.number(p.value) << ";"
              << (p.unit.empty() ? "" : "  // [" + p.unit + "]") << "\n";
        h << "};\n\n"
          << "// The equations of motion for one set of parameters: what depends on the\n"
          << "// parameters only is computed once, by the constructor and set_parameters.\n"
          << "class Model {\npublic:\n"
          << "    explicit Model(const Parameters& p = Parameters());\n"
          << "    void set_parameters(const Parameters& p);\n"
          << "    const Parameters& parameters() const { return p_; }\n\n"
          << declarations(plan, d) << "\nprivate:\n    Parameters p_;\n";
        for (const CodeFunction* f : plan.functions())
            if (hoisted_count(*f))
                h << "    double " << d.hoisted_array(*f) << "[" << hoisted_count(*f) << "];\n";
        h << "};\n\n}  // namespace " << d.name << "\n";
    } else {
        std::string guard = d.name + "_H_";
        std::transform(guard.begin(), guard.end(), guard.begin(), ::toupper);
        h << "#ifndef " << guard << "\n#define " << guard << "\n\n"
          << "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n"
          << "#define " << d.size("nq") << " " << plan.coordinate_count << " /* coordinates: "
          << names_of(plan.q) << " */\n"
          << "#define " << d.size("nu") << " " << plan.load_count << " /* loads: "
          << names_of(plan.loads) << " */\n"
          << "#define " << d.size("ny") << " " << plan.outputs.size() << " /* outputs: "
          << names_of(plan.outputs) << " */\n";
        if (plan.speed_form)
            h << "#define " << d.size("nur") << " " << plan.qp.size() << " /* independent speeds: "
              << names_of(plan.qp) << " */\n"
              << "#define " << d.size("nus") << " " << plan.dependent_speeds.size()
              << " /* dependent speeds: " << names_of(plan.dependent_speeds) << " */\n";
        if (plan.constraint_count() > 0)
            h << "#define " << d.size("nc") << " " << plan.constraint_count()
              << " /* constraints: " << constraint_list(plan) << "; their forces: "
              << names_of(plan.constraint_forces) << " */\n"
              << "/* The rate [1/s] at which the simulation's right-hand side damps the\n"
              << "   constraints' drift (Baumgarte); define it before including to change it. */\n"
              << "#ifndef " << d.size("stabilization") << "\n#define " << d.size("stabilization")
              << " 10.0\n#endif\n";
        h << "\n"
          << "/* The model's constants, changeable without generating the code again. */\n"
          << "typedef struct " << d.name << "_parameters {\n";
        for (const CodeSymbol& p : plan.parameters)
            h << "    double " << id.at(p.name) << ";"
              << (p.unit.empty() ? "" : " /* [" + p.unit + "] */") << "\n";
        if (plan.parameters.empty()) h << "    char none; /* (the model has no parameters) */\n";
        h << "} " << d.name << "_parameters;\n\n"
          << "/* The parameters and the values computed from them once, by " << d.name
          << "_init. */\n"
          << "typedef struct " << d.name << "_context {\n    " << d.name << "_parameters p;\n";
        for (const CodeFunction* f : plan.functions())
            if (hoisted_count(*f))
                h << "    double h_" << f->name << "[" << hoisted_count(*f) << "];\n";
        h << "} " << d.name << "_context;\n\n"
          << "/* Sets p to the model's values of the parameters. */\n"
          << "void " << d.name << "_default_parameters(" << d.name << "_parameters* p);\n"
          << "/* Sets the context for the parameters p (the model's values when p is NULL);\n"
          << "   call it again after changing them. */\n"
          << "void " << d.name << "_init(" << d.name << "_context* c, const " << d.name
          << "_parameters* p);\n"
          << declarations(plan, d)
          << "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
    }
    files.push_back({d.name + ext_h, h.str()});

    // ---- source ----------------------------------------------------------------------------
    std::ostringstream c;
    c << comment_block(source_lines, d.cpp) << "\n";
    c << (d.cpp ? "#include <cmath>\n\n#include \"" : "#include <math.h>\n\n#include \"")
      << d.name << ext_h << "\"\n\n";
    if (d.cpp) c << "namespace " << d.name << " {\n\nnamespace {\n\n";
    c << solvers(plan, d) << "\n";
    if (const std::string ds = derivative_solvers(plan, d); !ds.empty()) c << ds << "\n";
    if (d.cpp) {
        c << "}  // namespace\n\nModel::Model(const Parameters& p) { set_parameters(p); }\n\n"
          << "void Model::set_parameters(const Parameters& p) {\n    p_ = p;\n";
    } else {
        c << "void " << d.name << "_default_parameters(" << d.name << "_parameters* p) {\n";
        for (const CodeSymbol& p : plan.parameters)
            c << "    p->" << id.at(p.name) << " = " << pr.number(p.value) << ";"
              << (p.unit.empty() ? "" : " /* [" + p.unit + "] */") << "\n";
        if (plan.parameters.empty()) c << "    p->none = 0;\n";
        c << "}\n\nvoid " << d.name << "_init(" << d.name << "_context* c, const " << d.name
          << "_parameters* p) {\n"
          << "    if (p)\n        c->p = *p;\n    else\n        " << d.name
          << "_default_parameters(&c->p);\n";
    }
    for (const CodeFunction* f : plan.functions())
        print_prelude(c, *f, d, pr, spell(*f));
    c << "}\n";
    for (const CodeFunction* f : plan.functions()) {
        c << "\n" << pr.comment(f->summary) << "\n"
          << "void " << (d.cpp ? "Model::" : "") << d.function(f->name) << "("
          << (d.cpp ? "" : "const " + d.name + "_context* c, ") << arguments(*f) << ")"
          << (d.cpp ? " const" : "") << " {\n";
        print_body(c, plan, *f, d, pr, spell(*f));
        c << "}\n";
    }
    c << "\n" << forward_and_rhs(plan, d) << forward_derivatives(plan, d, pr);
    if (d.cpp) c << "\n}  // namespace " << d.name << "\n";
    files.push_back({d.name + ext_c, c.str()});

    if (plan.simulation)
        files.push_back({d.name + "_main" + ext_c,
                         comment_block(main_lines, d.cpp) + main_program(plan, d, pr)});
    return files;
}

}  // namespace

std::vector<GeneratedFile> CEmitter::emit(const CodePlan& plan) const {
    const Dialect d{false, plan.name};
    const auto id = identifiers(plan);
    auto spell = [&](const CodeFunction& f) {
        return spelling(f, id, [this](std::size_t k) { return printer_.element("h", k); });
    };
    return emit_c_family(plan, d, printer_, id, header(plan, "equations of motion (declarations)"),
                         header(plan, "equations of motion"),
                         header(plan, "simulation program"), spell);
}

std::vector<GeneratedFile> CppEmitter::emit(const CodePlan& plan) const {
    const Dialect d{true, plan.name};
    const auto id = identifiers(plan);
    auto spell = [&](const CodeFunction& f) {
        std::string array = d.hoisted_array(f);
        return spelling(f, id, [this, array](std::size_t k) { return printer_.element(array, k); });
    };
    return emit_c_family(plan, d, printer_, id, header(plan, "equations of motion (declarations)"),
                         header(plan, "equations of motion"),
                         header(plan, "simulation program"), spell);
}

}  // namespace alembert
