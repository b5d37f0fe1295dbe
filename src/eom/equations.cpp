// SPDX-License-Identifier: MIT
// Linear systems from residuals, and their symbolic and numeric solution.
#include "alembert/eom/equations.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "alembert/error.hpp"
#include "alembert/sym/derivative.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

namespace {

// Why a coefficient matrix (columns: the unknowns) is singular, in the user's names: an
// unknown in no equation, or two unknowns that enter every equation in the same proportion
// (the same torque on the same body twice, say), which no set of equations can tell apart.
// Empty when the dependence is among three or more unknowns.
template <class Matrix>
std::string explain_dependent_unknowns(const Matrix& A, const std::vector<ex>& unknowns) {
    const auto n = A.cols();
    double scale = 0;
    for (Eigen::Index j = 0; j < n; ++j) scale = std::max(scale, static_cast<double>(A.col(j).norm()));
    const double tiny = 1e-12 * std::max(scale, 1e-300);
    for (Eigen::Index j = 0; j < n; ++j)
        if (static_cast<double>(A.col(j).norm()) <= tiny)
            return "; '" + to_string(unknowns[static_cast<std::size_t>(j)]) +
                   "' appears in no equation: choose equations that hold it";
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = i + 1; j < n; ++j) {
            const double ni = static_cast<double>(A.col(i).norm()), nj = static_cast<double>(A.col(j).norm());
            const double c = static_cast<double>(A.col(i).dot(A.col(j))) / (ni * nj);
            if (std::fabs(c) > 1 - 1e-12)
                return "; '" + to_string(unknowns[static_cast<std::size_t>(i)]) + "' and '" +
                       to_string(unknowns[static_cast<std::size_t>(j)]) +
                       "' enter every equation in the same proportion, so the equations cannot "
                       "tell them apart (the same load declared twice?): make them one unknown, "
                       "or give one of them a value";
        }
    return "";
}

// A with every symbol at a fixed pseudo-random value: a generic state, for explanations only
Eigen::MatrixXd at_generic_state(const GiNaC::matrix& A) {
    GiNaC::exset symbols;
    for (unsigned i = 0; i < A.rows(); ++i)
        for (unsigned j = 0; j < A.cols(); ++j)
            for (const ex& x : symbols_of(A(i, j))) symbols.insert(x);
    exmap at;
    unsigned k = 0;
    for (const ex& x : symbols) at[x] = 0.37 + 0.61 * std::fmod(0.754877666 * ++k, 1.0);
    Eigen::MatrixXd out(A.rows(), A.cols());
    for (unsigned i = 0; i < A.rows(); ++i)
        for (unsigned j = 0; j < A.cols(); ++j) {
            ex v = GiNaC::evalf(A(i, j).subs(at));
            out(i, j) = GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()
                            ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                            : std::nan("");
        }
    return out;
}

}  // namespace

LinearSystem form_linear_system(const std::vector<ex>& residuals, const std::vector<ex>& unknowns) {
    if (residuals.size() != unknowns.size())
        throw ArgumentError("form_linear_system(): " + std::to_string(residuals.size()) +
                            " equations for " + std::to_string(unknowns.size()) +
                            " unknowns; give one equation per unknown");
    const std::size_t n = unknowns.size();
    LinearSystem s{GiNaC::matrix(n, n), GiNaC::matrix(n, 1), unknowns};
    exmap zero;
    for (const ex& x : unknowns) {
        if (!GiNaC::is_a<GiNaC::symbol>(x))
            throw ArgumentError("form_linear_system(): unknown '" + to_string(x) +
                                "' is not a symbol");
        zero[x] = 0;
    }
    for (std::size_t i = 0; i < n; ++i) {
        // only the unknowns residual i holds have a coefficient other than 0 there (a road-map
        // row holds one or a few of them): one pass over the residual instead of n derivatives
        const GiNaC::exset held = symbols_of(residuals[i]);
        std::vector<ex> in_row;
        for (const ex& x : unknowns)
            if (held.count(x)) in_row.push_back(x);
        for (std::size_t j = 0; j < n; ++j) {
            if (!held.count(unknowns[j])) {
                s.A(i, j) = 0;
                continue;
            }
            const GiNaC::symbol& xj = GiNaC::ex_to<GiNaC::symbol>(unknowns[j]);
            ex a = calc_derivative(residuals[i], xj);
            for (const ex& x : in_row)
                if (a.has(x))
                    throw SolveError("form_linear_system(): equation " + std::to_string(i + 1) +
                                     " is not linear in '" + to_string(unknowns[j]) +
                                     "' (its coefficient holds '" + to_string(x) +
                                     "'); use a nonlinear solve");
            s.A(i, j) = -a;
        }
        s.b(i, 0) = residuals[i].subs(zero);
    }
    return s;
}

namespace {

// the permanent of a nonnegative n x n matrix (n <= 16): over the subsets of columns, the
// number of ways the first |mask| rows take the columns in mask; sums of nonnegative terms
// only, so no cancellation
double calc_permanent(const std::vector<std::vector<double>>& T) {
    const std::size_t n = T.size();
    std::vector<double> ways(std::size_t{1} << n, 0.0);
    ways[0] = 1;
    for (std::size_t mask = 0; mask < ways.size(); ++mask) {
        if (ways[mask] == 0) continue;
        const auto row = static_cast<std::size_t>(std::popcount(mask));
        if (row == n) continue;
        for (std::size_t j = 0; j < n; ++j)
            if (!(mask & (std::size_t{1} << j)) && T[row][j] != 0)
                ways[mask | (std::size_t{1} << j)] += ways[mask] * T[row][j];
    }
    return ways.back();
}

std::string format_terms(double terms) {
    std::ostringstream os;
    if (terms < 1e15) os << std::fixed << std::setprecision(0) << terms;
    else os << std::setprecision(3) << terms;
    return os.str();
}

}  // namespace

double estimate_solution_terms(const LinearSystem& sys) {
    const std::size_t n = sys.A.rows();
    std::vector<std::vector<double>> T(n, std::vector<double>(n, 0.0));
    std::vector<double> tb(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            const ex& a = sys.A(static_cast<unsigned>(i), static_cast<unsigned>(j));
            T[i][j] = a.is_zero() ? 0.0 : estimate_expansion_terms(a);
        }
        const ex& b = sys.b(static_cast<unsigned>(i), 0);
        tb[i] = b.is_zero() ? 0.0 : estimate_expansion_terms(b);
    }
    const double inf = std::numeric_limits<double>::infinity();
    auto capped = [&](double x) { return x > 1e300 ? inf : x; };
    if (n > 16) {
        double bound = 1;
        for (std::size_t i = 0; i < n; ++i) {
            double row = tb[i];
            for (double t : T[i]) row += t;
            bound *= row;
        }
        return capped(bound);
    }
    double numerator = 0;
    for (std::size_t j = 0; j < n; ++j) {
        std::vector<std::vector<double>> Tj = T;
        for (std::size_t i = 0; i < n; ++i) Tj[i][j] = tb[i];
        numerator = std::max(numerator, calc_permanent(Tj));
    }
    return capped(calc_permanent(T) + numerator);
}

std::vector<ex> solve_symbolic(const LinearSystem& sys, const SymbolicSolveOptions& options) {
    const unsigned n = sys.A.rows();
    // refused before any work when the written-out solution would be too large
    const double expected = estimate_solution_terms(sys);
    if (expected > options.max_terms) {
        std::string unknowns;
        for (const ex& x : sys.unknowns) unknowns += (unknowns.empty() ? "" : ", ") + to_string(x);
        throw SolveError("solve_symbolic(): solving for " + unknowns +
                         " symbolically would write out up to " + format_terms(expected) +
                         " terms (Cramer's rule expanded), more than the limit of " +
                         format_terms(options.max_terms) +
                         "; solve numerically at given values (solve_numeric, `solve ... at`), "
                         "generate code for the equations (codegen), or raise the limit "
                         "(SymbolicSolveOptions::max_terms, `solve ... limit N`)");
    }
    const std::size_t steps = n + 1;
    auto report = [&](std::size_t step) {
        if (options.progress) options.progress(step, steps);
    };
    report(0);
    GiNaC::matrix vars(n, 1);
    for (unsigned i = 0; i < n; ++i) vars(i, 0) = GiNaC::symbol("x" + std::to_string(i));
    GiNaC::matrix x;
    try {
        x = sys.A.solve(vars, sys.b, GiNaC::solve_algo::gauss);
    } catch (const std::runtime_error& e) {
        std::string why = explain_dependent_unknowns(at_generic_state(sys.A), sys.unknowns);
        throw SolveError(std::string("solve_symbolic(): the coefficient matrix is singular (") +
                         e.what() + ")" +
                         (why.empty() ? "; check that every unknown appears in the equations" : why));
    }
    // a singular but consistent system comes back with free parameters (vars) in the
    // solution: the equations do not determine those unknowns, whatever GiNaC writes for them
    std::string undetermined;
    for (unsigned i = 0; i < n; ++i) {
        bool free = false;
        for (unsigned j = 0; j < n && !free; ++j) free = x(i, 0).has(vars(j, 0));
        if (free) undetermined += (undetermined.empty() ? "" : ", ") + to_string(sys.unknowns[i]);
    }
    if (!undetermined.empty()) {
        report(steps);
        std::string why = explain_dependent_unknowns(at_generic_state(sys.A), sys.unknowns);
        throw SolveError("solve_symbolic(): the equations do not determine " + undetermined +
                         " (the coefficient matrix is singular: some equations repeat others)" +
                         (why.empty() ? "; replace the repeated equations with independent ones, "
                                        "or give some of these unknowns values"
                                      : why));
    }
    std::vector<ex> out;
    for (unsigned i = 0; i < n; ++i) {
        report(i + 1);
        out.push_back(simplify(GiNaC::normal(x(i, 0))));
    }
    report(steps);
    return out;
}

Eigen::VectorXd solve_numeric(const SymbolTable& table, const LinearSystem& sys,
                              const exmap& values) {
    const int n = static_cast<int>(sys.A.rows());
    // compiled once for this call: shared subexpressions and intermediates are evaluated
    // once, which is what makes large models affordable
    std::vector<ex> inputs, outputs;
    std::vector<long double> in;
    for (const auto& [s, v] : values) {
        if (!GiNaC::is_a<GiNaC::numeric>(v))
            throw ArgumentError("solve_numeric(): the value given for '" + to_string(s) +
                                "' is not a number (" + to_string(v) + ")");
        inputs.push_back(s);
        in.push_back(GiNaC::ex_to<GiNaC::numeric>(v).to_double());
    }
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) outputs.push_back(sys.A(static_cast<unsigned>(i), static_cast<unsigned>(j)));
        outputs.push_back(sys.b(static_cast<unsigned>(i), 0));
    }
    // extended precision for the coefficients and the decomposition: the answer is then
    // limited by the double it is returned in, not by rounding in long sums and in the LU of
    // an ill-conditioned mass matrix (long chains), so methods compare cleanly
    CompiledExpressions f(table, inputs, outputs);
    std::vector<long double> out(outputs.size());
    f.evaluate_extended(in.data(), out.data());
    MatrixXld A(n, n);
    VectorXld b(n);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) A(i, j) = out[static_cast<std::size_t>(i * (n + 1) + j)];
        b(i) = out[static_cast<std::size_t>(i * (n + 1) + n)];
    }
    std::string what = "solve_numeric(): the coefficient matrix for unknowns";
    for (const ex& x : sys.unknowns) what += " " + to_string(x);
    try {
        return solve_extended(A, b, what + " at this state", "");
    } catch (const SolveError& e) {
        // only now, on failure, look for the unknowns behind it
        std::string why = explain_dependent_unknowns(A, sys.unknowns);
        throw SolveError(e.what() +
                         (why.empty() ? "; the configuration may be singular (a locked or degenerate pose)" : why));
    }
}

Eigen::VectorXd solve_extended(const MatrixXld& A, const VectorXld& b, const std::string& what,
                               const std::string& hint) {
    Eigen::FullPivLU<MatrixXld> lu(A);
    double rcond = static_cast<double>(lu.rcond());
    if (!lu.isInvertible() || !(rcond > 1e-14)) {
        std::ostringstream os;
        os << what << " is singular or ill-conditioned (reciprocal condition estimate " << rcond
           << ")" << hint;
        throw SolveError(os.str());
    }
    return lu.solve(b).cast<double>();
}

}  // namespace alembert
