// SPDX-License-Identifier: MIT
// Numeric inverse dynamics: solved load measures compiled directly, else A T = b solved by LU.
#include "alembert/sim/inverse_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/error.hpp"
#include "number_text.hpp"

namespace alembert {

namespace {

using detail::number;

// The recursive rows of a tree (form_tree_equations: about each joint, accumulated from the tip
// inward, so their size grows linearly in the number of bodies where the planned road-map's
// closed forms grow as its square) as equations in `loads`, where they serve: a tree with as
// many load measures as coordinates, each of which enters the rows (motor torques and forces on
// the bodies do; joint reactions do not, and need the road-map's rows about other points).
std::optional<LinearSystem> tree_rows_for(const System& sys, const std::vector<TimeVariable>& q,
                                          const std::vector<ex>& loads) {
    if (loads.empty() || loads.size() != q.size() || !sys.constraints().empty()) return std::nullopt;
    std::optional<TreeEquations> tree = form_tree_equations_if_tree(sys, q);
    if (!tree) return std::nullopt;
    auto in_rows = [&](const ex& x) {
        return std::any_of(tree->residuals.begin(), tree->residuals.end(), [&](const ex& r) { return r.has(x); });
    };
    if (!std::all_of(loads.begin(), loads.end(), in_rows)) return std::nullopt;
    // another unknown left in the rows (a reaction that did not cancel symbolically) is for
    // the road-map to keep out
    for (const ex& u : sys.symbols().symbols(SymbolKind::unknown))
        if (std::find(loads.begin(), loads.end(), u) == loads.end() && in_rows(u)) return std::nullopt;
    return form_linear_system(tree->residuals, loads);
}

std::string printed(const ex& e) {
    std::ostringstream s;
    s << e;
    return s.str();
}

// calc_size_bound, bottom-up over the expression's shared nodes (each once)
ex size_bound(const ex& e, std::map<ex, ex, GiNaC::ex_is_less>& seen) {
    if (auto it = seen.find(e); it != seen.end()) return it->second;
    ex b;
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        b = GiNaC::abs(e);
    } else if (GiNaC::is_a<GiNaC::add>(e)) {
        b = 0;
        for (const ex& term : e) b += size_bound(term, seen);
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        b = 1;
        for (const ex& factor : e) b *= size_bound(factor, seen);
    } else if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
               GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_pos_integer()) {
        b = GiNaC::pow(size_bound(e.op(0), seen), e.op(1));
    } else if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) ||
               GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) {
        b = 1;
    } else {
        b = GiNaC::abs(e);
    }
    seen.emplace(e, b);
    return b;
}

}  // namespace

ex calc_size_bound(const ex& e) {
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    return size_bound(e, seen);
}

InverseDynamics::InverseDynamics(std::string model, StateLayout layout, NumericFunction loads,
                                 bool solved)
    : model_(std::move(model)),
      layout_(std::move(layout)),
      function_(std::move(loads)),
      solved_(solved) {
    const std::size_t n = coordinate_count(), k = load_count();
    const std::size_t outputs = solved_ ? k : k * k + k;
    ALEMBERT_CHECK_ARG(
        layout_.inputs.empty() && layout_.rates.size() == n && layout_.coordinate_names.size() == n,
        "InverseDynamics('" + model_ +
            "'): the layout needs one rate and one "
            "name per coordinate and no inputs");
    ALEMBERT_CHECK_ARG(function_.input_count == 1 + 3 * n && function_.output_count == outputs &&
                           function_.evaluate,
                       "InverseDynamics('" + model_ + "'): the function takes " +
                           std::to_string(function_.input_count) + " inputs and gives " +
                           std::to_string(function_.output_count) + " outputs; the layout needs " +
                           std::to_string(1 + 3 * n) + " inputs [t, q, q', q''] and " +
                           std::to_string(outputs) + " outputs");
    in_.resize(function_.input_count);
    out_.resize(function_.output_count);
    if (!solved_) {
        A_.resize(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
        b_.resize(static_cast<Eigen::Index>(k));
        // the right size with its status set (the preallocating constructor leaves it unset)
        lu_.compute(Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)));
    }
}

std::vector<std::string> InverseDynamics::load_names() const {
    std::vector<std::string> names;
    for (const ex& u : layout_.unknowns) names.push_back(printed(u));
    return names;
}

void InverseDynamics::fail(const std::string& what, double t, const double* q,
                           const double* qd) const {
    throw SolveError("inverse dynamics of '" + model_ + "': " + what + " at " +
                     detail::describe_state(layout_, t, q, qd, nullptr) +
                     "; check the model's constants and whether the loads can hold this "
                     "configuration (a constraint losing rank)");
}

void InverseDynamics::calc_loads(double t, const double* q, const double* qd, const double* qdd,
                                 double* loads) const {
    double rcond = 1;
    const std::string problem = try_calc_loads(t, q, qd, qdd, loads, &rcond);
    if (!problem.empty()) fail(problem, t, q, qd);
}

std::string InverseDynamics::try_calc_loads(double t, const double* q, const double* qd,
                                            const double* qdd, double* loads,
                                            double* rcond) const {
    const std::size_t n = coordinate_count(), k = load_count();
    *rcond = 1;
    // gather [t, q, q', q''] and evaluate
    double* in = in_.data();
    in[0] = t;
    for (std::size_t i = 0; i < n; ++i)
        in[1 + i] = q[i], in[1 + n + i] = qd[i], in[1 + 2 * n + i] = qdd[i];
    if (solved_) {
        function_.evaluate(in, loads);
        for (std::size_t i = 0; i < k; ++i)
            if (!std::isfinite(loads[i])) {
                *rcond = 0;
                return printed(layout_.unknowns[i]) + " is " + number(loads[i]) +
                       " (its coefficient in its equation vanishes)";
            }
        // a coefficient zero against the size of its terms (cos(q1) = 6e-17 at 90 deg)
        if (coefficient_sizes_.evaluate) {
            coefficient_sizes_.evaluate(in, sizes_out_.data());
            for (std::size_t i = 0; i < k; ++i) {
                const double c = sizes_out_[i], size = sizes_out_[k + i];
                if (std::abs(c) > kMinReciprocalCondition * size) continue;
                *rcond = size > 0 ? std::abs(c) / size : 0.0;
                return printed(layout_.unknowns[i]) + " is not determined: its coefficient in its "
                       "equation is " + number(c) + ", zero against the size " + number(size) +
                       " of its terms (below " + number(kMinReciprocalCondition) + " of it)";
            }
        }
        return "";
    }
    // unsolved form: A T = b by LU with a condition check
    function_.evaluate(in, out_.data());
    const auto K = static_cast<Eigen::Index>(k);
    for (Eigen::Index r = 0; r < K; ++r) {
        for (Eigen::Index c = 0; c < K; ++c) A_(r, c) = out_[static_cast<std::size_t>(r * K + c)];
        b_(r) = out_[static_cast<std::size_t>(K * K + r)];
    }
    if (!A_.allFinite() || !b_.allFinite()) {
        *rcond = 0;
        return "the equations are not finite";
    }
    lu_.compute(A_);
    // Eigen's estimate can miss a matrix singular up to rounding, so the pivots bound it too
    const Eigen::VectorXd pivots = lu_.matrixLU().diagonal().cwiseAbs();
    *rcond = std::min(lu_.rcond(), pivots.maxCoeff() > 0 ? pivots.minCoeff() / pivots.maxCoeff() : 0.0);
    if (!(*rcond >= kMinReciprocalCondition))
        return "the equations are singular or nearly singular in the load measures (reciprocal "
               "condition estimate " +
               number(*rcond) + ", below " + number(kMinReciprocalCondition) + ")";
    Eigen::Map<Eigen::VectorXd>(loads, K) = lu_.solve(b_);
    for (std::size_t i = 0; i < k; ++i)
        if (!std::isfinite(loads[i])) return printed(layout_.unknowns[i]) + " is " + number(loads[i]);
    return "";
}

void InverseDynamics::set_constraints(std::vector<std::string> names, NumericFunction residuals) {
    ALEMBERT_CHECK_ARG(residuals.input_count == function_.input_count &&
                           residuals.output_count == names.size() && residuals.evaluate,
                       "InverseDynamics('" + model_ + "')::set_constraints(): the function takes " +
                           std::to_string(residuals.input_count) + " inputs and gives " +
                           std::to_string(residuals.output_count) + " outputs; it needs " +
                           std::to_string(function_.input_count) + " inputs [t, q, q', q''] and " +
                           "one output per name (" + std::to_string(names.size()) + ")");
    constraint_names_ = std::move(names);
    constraints_ = std::move(residuals);
}

void InverseDynamics::set_coefficient_sizes(NumericFunction sizes) {
    const std::size_t k = load_count();
    ALEMBERT_CHECK_ARG(solved_ && sizes.input_count == function_.input_count &&
                           sizes.output_count == 2 * k && sizes.evaluate,
                       "InverseDynamics('" + model_ + "')::set_coefficient_sizes(): the solved "
                       "form needs a function of [t, q, q', q''] giving " +
                           std::to_string(2 * k) + " outputs (each coefficient, then its size)");
    coefficient_sizes_ = std::move(sizes);
    sizes_out_.resize(2 * k);
}

void InverseDynamics::set_unused_equations(std::vector<std::string> names, NumericFunction residuals) {
    const std::size_t inputs = function_.input_count + load_count();
    ALEMBERT_CHECK_ARG(residuals.input_count == inputs && residuals.output_count == 2 * names.size() &&
                           residuals.evaluate,
                       "InverseDynamics('" + model_ + "')::set_unused_equations(): the function "
                       "takes " + std::to_string(residuals.input_count) + " inputs and gives " +
                           std::to_string(residuals.output_count) + " outputs; it needs " +
                           std::to_string(inputs) + " inputs [t, q, q', q'', loads] and a residual "
                           "and a size per name (" + std::to_string(2 * names.size()) + ")");
    unused_names_ = std::move(names);
    unused_ = std::move(residuals);
    unused_in_.resize(inputs);
}

void InverseDynamics::calc_unused_residuals(double t, const double* q, const double* qd,
                                            const double* qdd, const double* loads,
                                            double* residuals) const {
    if (unused_names_.empty()) return;
    const std::size_t n = coordinate_count(), k = load_count();
    double* in = unused_in_.data();
    in[0] = t;
    for (std::size_t i = 0; i < n; ++i)
        in[1 + i] = q[i], in[1 + n + i] = qd[i], in[1 + 2 * n + i] = qdd[i];
    std::copy(loads, loads + k, in + 1 + 3 * n);
    unused_.evaluate(in, residuals);
}

void InverseDynamics::calc_constraint_residuals(double t, const double* q, const double* qd,
                                                const double* qdd, double* residuals) const {
    if (constraint_names_.empty()) return;
    const std::size_t n = coordinate_count();
    double* in = in_.data();
    in[0] = t;
    for (std::size_t i = 0; i < n; ++i)
        in[1 + i] = q[i], in[1 + n + i] = qd[i], in[1 + 2 * n + i] = qdd[i];
    constraints_.evaluate(in, residuals);
}

InverseDynamics compile_inverse_dynamics(const SymbolTable& table, const LinearSystem& eqs,
                                         const std::vector<TimeVariable>& q,
                                         const std::string& model, const FunctionMaker& make) {
    StateLayout layout;
    layout.time = table.time();
    std::vector<ex> in{layout.time};
    for (const TimeVariable& qi : q) {
        layout.coordinates.push_back(qi.symbol());
        layout.rates.push_back(qi.d(1));
        layout.accelerations.push_back(qi.d(2));
        layout.coordinate_names.push_back(qi.name());
    }
    in.insert(in.end(), layout.coordinates.begin(), layout.coordinates.end());
    in.insert(in.end(), layout.rates.begin(), layout.rates.end());
    in.insert(in.end(), layout.accelerations.begin(), layout.accelerations.end());
    layout.unknowns = eqs.unknowns;
    const unsigned k = static_cast<unsigned>(eqs.unknowns.size());
    ALEMBERT_CHECK_ARG(eqs.A.rows() == k && eqs.A.cols() == k,
                       "compile_inverse_dynamics('" + model +
                           "'): " + std::to_string(eqs.A.rows()) + " equations for " +
                           std::to_string(k) + " load measures; give one equation per measure");

    // solved form when every row and column of A holds exactly one non-zero entry
    std::vector<int> row_of(k, -1);
    bool solved = true;
    for (unsigned r = 0; r < k && solved; ++r) {
        int found = -1;
        for (unsigned c = 0; c < k; ++c) {
            if (eqs.A(r, c).is_zero()) continue;
            if (found >= 0 || row_of[c] >= 0) {
                solved = false;
                break;
            }
            found = static_cast<int>(c);
        }
        if (found < 0) solved = false;
        if (solved) row_of[static_cast<std::size_t>(found)] = static_cast<int>(r);
    }
    std::vector<ex> outputs;
    if (solved) {
        for (unsigned c = 0; c < k; ++c) {
            const auto r = static_cast<unsigned>(row_of[c]);
            outputs.push_back(eqs.b(r, 0) / eqs.A(r, c));
        }
    } else {
        for (unsigned r = 0; r < k; ++r)
            for (unsigned c = 0; c < k; ++c) outputs.push_back(eqs.A(r, c));
        for (unsigned r = 0; r < k; ++r) outputs.push_back(eqs.b(r, 0));
    }
    NumericFunction f;
    try {
        f = make_numeric_function(table, in, outputs, make);
    } catch (const ArgumentError& e) {
        throw ArgumentError("compile_inverse_dynamics('" + model + "'): " + e.what() +
                            "; inverse dynamics may depend on t and the coordinates with their "
                            "first and second derivatives: give a constant a value, or make a "
                            "load measure one of the unknowns");
    }
    InverseDynamics id(model, std::move(layout), std::move(f), solved);
    if (solved) {
        // each coefficient with the size of its terms, for a zero test relative to the row
        std::vector<ex> sizes;
        for (unsigned c = 0; c < k; ++c) sizes.push_back(eqs.A(static_cast<unsigned>(row_of[c]), c));
        for (unsigned c = 0; c < k; ++c) sizes.push_back(calc_size_bound(sizes[c]));
        id.set_coefficient_sizes(make_numeric_function(table, in, sizes, {}));
    }
    return id;
}

InverseDynamics compile_inverse_dynamics(const System& sys, const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& loads, const std::string& model,
                                         const FunctionMaker& make, const exmap& specified) {
    const SymbolTable& table = sys.symbols();
    // the specified quantities' formulas of t, through the intermediates they sit in
    auto driven = [&](const ex& e) { return specified.empty() ? e : table.expand_intermediates(e).subs(specified); };
    if (specified.empty())
        if (std::optional<LinearSystem> tree = tree_rows_for(sys, q, loads))
            return compile_inverse_dynamics(sys.symbols(), *tree, q, model, make);
    std::vector<ex> E = residuals_of(plan_roadmap(sys, q, loads, Analysis::dynamics));
    for (ex& e : E) e = driven(e);
    InverseDynamics id = compile_inverse_dynamics(sys.symbols(), form_linear_system(E, loads), q, model, make);
    if (sys.constraints().empty()) {
        // fewer loads act than there are coordinates: the rows leave equations of motion out,
        // and a motion no load can make would get loads all the same; Kane's equation of
        // every coordinate is kept to check each sample against
        std::vector<ex> kane = form_kane_equations(sys, q);
        // which loads Kane's equations hold: their symbols taken once, through intermediates
        GiNaC::exset in_kane;
        for (const ex& r : kane) {
            const GiNaC::exset leaves = table.calc_leaf_symbols(r);
            in_kane.insert(leaves.begin(), leaves.end());
        }
        std::size_t acting = 0;
        for (const ex& T : loads) acting += in_kane.count(T);
        if (acting < q.size()) {
            std::vector<ex> in{table.time()}, checks;
            const StateLayout& layout = id.layout();
            in.insert(in.end(), layout.coordinates.begin(), layout.coordinates.end());
            in.insert(in.end(), layout.rates.begin(), layout.rates.end());
            in.insert(in.end(), layout.accelerations.begin(), layout.accelerations.end());
            in.insert(in.end(), loads.begin(), loads.end());
            std::vector<std::string> names;
            for (std::size_t i = 0; i < q.size(); ++i) {
                names.push_back("Kane's equation for " + q[i].name());
                checks.push_back(table.expand_intermediates(kane[i]).subs(specified));
            }
            for (std::size_t i = 0; i < q.size(); ++i) checks.push_back(calc_size_bound(checks[i]));
            id.set_unused_equations(std::move(names), make_numeric_function(table, in, checks, {}));
        }
        return id;
    }
    // the constraints a motion must satisfy
    std::vector<ex> in{table.time()}, residuals;
    const StateLayout& layout = id.layout();
    in.insert(in.end(), layout.coordinates.begin(), layout.coordinates.end());
    in.insert(in.end(), layout.rates.begin(), layout.rates.end());
    in.insert(in.end(), layout.accelerations.begin(), layout.accelerations.end());
    std::vector<std::string> names;
    for (const Constraint& c : sys.constraints()) {
        names.push_back(std::string("the ") + to_string(c.kind) + " constraint '" + c.name + "'");
        residuals.push_back(table.expand_intermediates(c.residual).subs(specified));
    }
    try {
        id.set_constraints(std::move(names), make_numeric_function(table, in, residuals, {}));
    } catch (const ArgumentError&) {
        // a residual holding a symbol without a value cannot be checked numerically
    }
    return id;
}

}  // namespace alembert
