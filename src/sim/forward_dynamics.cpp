// SPDX-License-Identifier: MIT
// Numeric forward dynamics: A x = b evaluated through a NumericFunction, solved with Eigen.
#include "alembert/sim/forward_dynamics.hpp"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "number_text.hpp"

namespace alembert {

namespace {

constexpr double kMinReciprocalCondition = 1e-13;

using detail::number;

// the smallest over the largest magnitude of an LU factorization's pivots (0 if one vanishes)
double pivot_ratio(const Eigen::MatrixXd& lu) {
    if (lu.rows() == 0) return 1;
    const Eigen::VectorXd pivots = lu.diagonal().cwiseAbs();
    const double largest = pivots.maxCoeff();
    return largest > 0 ? pivots.minCoeff() / largest : 0;
}

// the unknowns a singular A leaves undetermined: the largest entries of its null direction
// (the right singular vector of the smallest singular value), as "; q1'' and q3'' are not
// determined apart (null direction 0.707 q1'' - 0.707 q3'')"
std::string undetermined_unknowns(const Eigen::MatrixXd& A, const std::vector<ex>& unknowns) {
    if (A.rows() == 0) return "";
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const Eigen::VectorXd v = svd.matrixV().col(A.cols() - 1);
    const double largest = v.cwiseAbs().maxCoeff();
    const double sign = v(static_cast<Eigen::Index>(0)) < 0 && std::abs(v(0)) >= 0.1 * largest ? -1 : 1;
    std::string names, direction;
    std::size_t count = 0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        if (std::abs(v(i)) < 0.1 * largest) continue;
        std::ostringstream u;
        u << unknowns[static_cast<std::size_t>(i)];
        const double c = sign * v(i);
        names += (names.empty() ? "" : ", ") + u.str();
        direction += (direction.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) +
                     number(std::abs(c)) + " " + u.str();
        ++count;
    }
    if (count == 1) return "; " + names + " is not determined (it has no inertia there)";
    return "; " + names + " are not determined apart (null direction " + direction + ")";
}

}  // namespace

namespace detail {

std::string describe_state(const StateLayout& layout, double t, const double* q, const double* qd,
                           const double* inputs) {
    std::string s = "t = " + number(t);
    const std::size_t n = layout.coordinates.size();
    for (std::size_t i = 0; i < n && q; ++i)
        s += ", " + layout.coordinate_names[i] + " = " + number(q[i]);
    for (std::size_t i = 0; i < n && qd; ++i)
        s += ", " + layout.coordinate_names[i] + "' = " + number(qd[i]);
    for (std::size_t i = 0; i < layout.inputs.size() && inputs; ++i) {
        std::ostringstream name;
        name << layout.inputs[i];
        s += ", " + name.str() + " = " + number(inputs[i]);
    }
    return s;
}

}  // namespace detail

ForwardDynamics::ForwardDynamics(std::string model, StateLayout layout, NumericFunction system)
    : model_(std::move(model)), layout_(std::move(layout)), function_(std::move(system)) {
    const std::size_t n = coordinate_count(), k = unknown_count(), m = input_count();
    ALEMBERT_CHECK_ARG(layout_.rates.size() == n && layout_.coordinate_names.size() == n,
                       "ForwardDynamics('" + model_ + "'): the layout lists " + std::to_string(n) +
                           " coordinates but " + std::to_string(layout_.rates.size()) +
                           " rates; give one rate and one name per coordinate");
    ALEMBERT_CHECK_ARG(
        function_.input_count == 1 + 2 * n + m && function_.output_count == k * k + k,
        "ForwardDynamics('" + model_ + "'): the function takes " +
            std::to_string(function_.input_count) + " inputs and gives " +
            std::to_string(function_.output_count) + " outputs; the layout needs " +
            std::to_string(1 + 2 * n + m) + " inputs [t, q, q', inputs] and " +
            std::to_string(k * k + k) + " outputs [A row-major, b]");
    ALEMBERT_CHECK_ARG(static_cast<bool>(function_.evaluate),
                       "ForwardDynamics('" + model_ + "'): the function is empty");
    // where each q_i'' sits among the unknowns
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t at = k;
        for (std::size_t j = 0; j < k && i < layout_.accelerations.size(); ++j)
            if (layout_.unknowns[j].is_equal(layout_.accelerations[i])) at = j;
        ALEMBERT_CHECK_ARG(at < k, "ForwardDynamics('" + model_ + "'): the acceleration " +
                                       layout_.coordinate_names[i] +
                                       "'' is not among the unknowns of the equations; form them "
                                       "with the accelerations of every coordinate as unknowns");
        acceleration_index_.push_back(at);
    }
    in_.resize(function_.input_count);
    out_.resize(function_.output_count);
    A_.resize(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
    b_.resize(static_cast<Eigen::Index>(k));
    x_.resize(static_cast<Eigen::Index>(k));
    // decompositions of the right size with their status set (Eigen's preallocating
    // constructors leave it unset, and copying or moving one then reads it)
    const auto kk = static_cast<Eigen::Index>(std::max<std::size_t>(k, 1));
    ldlt_.compute(Eigen::MatrixXd::Identity(kk, kk));
    lu_.compute(Eigen::MatrixXd::Identity(kk, kk));
}

void ForwardDynamics::fail(const std::string& what, double t, const double* q, const double* qd,
                           const double* inputs) const {
    throw SolveError("forward dynamics of '" + model_ + "': " + what + " at " +
                     detail::describe_state(layout_, t, q, qd, inputs) +
                     "; check the masses and inertias, or whether this configuration is singular "
                     "(a constraint losing rank, a degenerate joint)");
}

void ForwardDynamics::solve(double t, const double* q, const double* qd,
                            const double* inputs) const {
    const std::size_t n = coordinate_count(), k = unknown_count(), m = input_count();
    // gather [t, q, q', inputs] and evaluate [A, b]
    double* in = in_.data();
    in[0] = t;
    for (std::size_t i = 0; i < n; ++i) in[1 + i] = q[i], in[1 + n + i] = qd[i];
    for (std::size_t i = 0; i < m; ++i) in[1 + 2 * n + i] = inputs[i];
    function_.evaluate(in, out_.data());

    // copy into Eigen, refusing non-finite entries by name
    const auto K = static_cast<Eigen::Index>(k);
    double largest = 0;
    for (Eigen::Index r = 0; r < K; ++r) {
        for (Eigen::Index c = 0; c < K; ++c) {
            const double a = out_[static_cast<std::size_t>(r * K + c)];
            if (!std::isfinite(a)) {
                std::ostringstream who;
                who << "the coefficient of " << layout_.unknowns[static_cast<std::size_t>(c)]
                    << " in equation " << r + 1 << " is " << number(a);
                fail(who.str(), t, q, qd, inputs);
            }
            A_(r, c) = a;
            largest = std::max(largest, std::abs(a));
        }
        const double br = out_[static_cast<std::size_t>(K * K + r)];
        if (!std::isfinite(br))
            fail("the right-hand side of equation " + std::to_string(r + 1) + " is " + number(br),
                 t, q, qd, inputs);
        b_(r) = br;
    }
    // symmetric positive definite: LDLT; otherwise LU
    bool symmetric = true;
    for (Eigen::Index r = 0; r < K && symmetric; ++r)
        for (Eigen::Index c = r + 1; c < K; ++c)
            if (std::abs(A_(r, c) - A_(c, r)) > 1e-12 * largest) {
                symmetric = false;
                break;
            }
    double rcond = 0;
    last_ldlt_ = false;
    if (symmetric) {
        ldlt_.compute(A_);
        // an exactly zero pivot is not an error to Eigen's LDLT (its solve skips it, giving
        // a least-squares answer), so pivots small against the largest are refused here
        const Eigen::VectorXd& d = ldlt_.vectorD();
        const bool pivots_positive =
            K == 0 || d.minCoeff() > kMinReciprocalCondition * d.cwiseAbs().maxCoeff();
        if (ldlt_.info() == Eigen::Success && ldlt_.isPositive() && pivots_positive) {
            rcond = ldlt_.rcond();
            if (rcond > kMinReciprocalCondition) {
                x_ = ldlt_.solve(b_);
                last_ldlt_ = true;
            }
        }
    }
    if (!last_ldlt_) {
        lu_.compute(A_);
        // Eigen's estimate can miss a matrix singular up to rounding (its solve then gives
        // finite nonsense), so the ratio of the smallest to the largest pivot bounds it too
        rcond = std::min(lu_.rcond(), pivot_ratio(lu_.matrixLU()));
        if (!(rcond > kMinReciprocalCondition))
            fail(std::string(symmetric ? "the mass matrix" : "the matrix of the equations") +
                     " is singular or ill-conditioned (reciprocal condition estimate " +
                     number(rcond) + ", below " + number(kMinReciprocalCondition) + ")" +
                     undetermined_unknowns(A_, layout_.unknowns),
                 t, q, qd, inputs);
        x_ = lu_.solve(b_);
    }
    for (Eigen::Index r = 0; r < K; ++r)
        if (!std::isfinite(x_(r))) {
            std::ostringstream who;
            who << "the solution for " << layout_.unknowns[static_cast<std::size_t>(r)] << " is "
                << number(x_(r));
            fail(who.str(), t, q, qd, inputs);
        }
}

void ForwardDynamics::calc_accelerations(double t, const double* q, const double* qd,
                                         const double* inputs, double* qdd) const {
    solve(t, q, qd, inputs);
    for (std::size_t i = 0; i < acceleration_index_.size(); ++i)
        qdd[i] = x_(static_cast<Eigen::Index>(acceleration_index_[i]));
}

void ForwardDynamics::calc_unknowns(double t, const double* q, const double* qd,
                                    const double* inputs, double* x) const {
    solve(t, q, qd, inputs);
    for (Eigen::Index r = 0; r < x_.size(); ++r) x[r] = x_(r);
}

ForwardDynamics compile_forward_dynamics(const SymbolTable& table, const LinearSystem& eqs,
                                         const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& inputs, const std::string& model,
                                         const FunctionMaker& make) {
    StateLayout layout;
    layout.time = table.time();
    for (const TimeVariable& qi : q) {
        layout.coordinates.push_back(qi.symbol());
        layout.rates.push_back(qi.d(1));
        layout.accelerations.push_back(qi.d(2));
        layout.coordinate_names.push_back(qi.name());
    }
    layout.unknowns = eqs.unknowns;
    layout.inputs = inputs;
    const unsigned k = static_cast<unsigned>(eqs.unknowns.size());
    ALEMBERT_CHECK_ARG(eqs.A.rows() == k && eqs.A.cols() == k && eqs.b.rows() == k,
                       "compile_forward_dynamics('" + model + "'): the equations have " +
                           std::to_string(eqs.A.rows()) + " rows for " + std::to_string(k) +
                           " unknowns; forward dynamics needs a square system");
    std::vector<ex> outputs;
    for (unsigned r = 0; r < k; ++r)
        for (unsigned c = 0; c < k; ++c) outputs.push_back(eqs.A(r, c));
    for (unsigned r = 0; r < k; ++r) outputs.push_back(eqs.b(r, 0));
    std::vector<ex> in{layout.time};
    in.insert(in.end(), layout.coordinates.begin(), layout.coordinates.end());
    in.insert(in.end(), layout.rates.begin(), layout.rates.end());
    in.insert(in.end(), inputs.begin(), inputs.end());
    NumericFunction f;
    try {
        f = make_numeric_function(table, in, outputs, make);
    } catch (const ArgumentError& e) {
        throw ArgumentError("compile_forward_dynamics('" + model + "'): " + e.what() +
                            "; forward dynamics may depend on t, the coordinates, their rates and "
                            "the inputs: list a load measure among the inputs, or give a constant "
                            "a value");
    }
    return ForwardDynamics(model, std::move(layout), std::move(f));
}

LinearSystem form_forward_equations(const System& sys, const std::vector<TimeVariable>& q,
                                    const std::vector<ex>& constraint_forces) {
    if (sys.constraints().empty() && constraint_forces.empty())
        return form_kane_equations(sys, KaneOptions{.coordinates = q, .simplify = false}).dynamics;
    std::vector<ex> unknowns;
    for (const TimeVariable& qi : q) unknowns.push_back(qi.d(2));
    unknowns.insert(unknowns.end(), constraint_forces.begin(), constraint_forces.end());
    std::vector<RoadmapRow> rows = plan_roadmap(sys, q, unknowns, Analysis::dynamics);
    return form_linear_system(residuals_of(rows), unknowns);
}

ForwardDynamics compile_forward_dynamics(const System& sys, const std::vector<TimeVariable>& q,
                                         const std::vector<ex>& inputs, const std::string& model,
                                         const std::vector<ex>& constraint_forces) {
    return compile_forward_dynamics(
        sys.symbols(), form_forward_equations(sys, q, constraint_forces), q, inputs, model);
}

}  // namespace alembert
