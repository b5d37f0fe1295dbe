// SPDX-License-Identifier: MIT
// Road-map, Kane, Lagrange and brute-force Newton–Euler side by side at random states.
#include "alembert/eom/cross_check.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {

// one method's residuals E, linear in the unknowns x (E = b - A x), compiled once as functions
// of x and the state; A and b come from evaluations at x = 0 and x = s e_j
class CompiledMethod {
public:
    CompiledMethod(std::string name, const SymbolTable& st, const std::vector<ex>& residuals,
                   std::vector<ex> x, const std::vector<ex>& state)
        : name_(std::move(name)), x_(std::move(x)) {
        if (residuals.size() != x_.size())
            throw ModelError("compare_methods(): the " + name_ + " method gives " +
                             std::to_string(residuals.size()) + " equations in " +
                             std::to_string(x_.size()) + " unknowns");
        std::vector<ex> inputs = x_;
        inputs.insert(inputs.end(), state.begin(), state.end());
        E_ = CompiledExpressions(st, std::move(inputs), residuals);
    }

    const std::string& name() const { return name_; }

    // x at the state (values in the order of the `state` symbols), evaluated and solved in
    // extended precision so that the comparison sees the methods, not rounding in long sums
    // and in the LU of an ill-conditioned mass matrix
    Eigen::VectorXd solve(const std::vector<double>& state) const {
        using Real = long double;
        // a power of two: A_j = (b - E(s e_j)) / s exactly scaled, b's rounding divided by s
        constexpr Real s = 1 << 20;
        const auto n = static_cast<Eigen::Index>(x_.size());
        std::vector<Real> in(x_.size(), 0.0L);
        in.insert(in.end(), state.begin(), state.end());
        VectorXld b(n), e(n), e2(n);
        MatrixXld A(n, n);
        E_.evaluate_extended(in.data(), b.data());
        for (Eigen::Index j = 0; j < n; ++j) {
            in[static_cast<std::size_t>(j)] = s;
            E_.evaluate_extended(in.data(), e.data());
            in[static_cast<std::size_t>(j)] = 2 * s;
            E_.evaluate_extended(in.data(), e2.data());
            in[static_cast<std::size_t>(j)] = 0;
            A.col(j) = (b - e) / s;
            // linear: E(2 s e_j) = b - 2 s A_j
            Real scale = 1 + b.cwiseAbs().maxCoeff() + 2 * s * A.col(j).cwiseAbs().maxCoeff();
            if (!((e2 - (b - 2 * s * A.col(j))).cwiseAbs().maxCoeff() <= 1e-9L * scale))
                throw SolveError("compare_methods(): the " + name_ +
                                 " equations are not linear in '" +
                                 to_string(x_[static_cast<std::size_t>(j)]) + "'");
        }
        return solve_extended(A, b,
                              "compare_methods(): the " + name_ +
                                  " coefficient matrix at a drawn state",
                              "; the configuration may be singular");
    }

private:
    std::string name_;
    std::vector<ex> x_;
    CompiledExpressions E_;
};

// accelerations given explicitly (the articulated-body recursion), evaluated at the state
class ExplicitMethod {
public:
    ExplicitMethod(std::string name, const SymbolTable& st, const std::vector<ex>& accelerations,
                   const std::vector<ex>& state)
        : name_(std::move(name)), x_(st, state, accelerations) {}
    const std::string& name() const { return name_; }
    Eigen::VectorXd solve(const std::vector<double>& state) const {
        std::vector<long double> in(state.begin(), state.end());
        VectorXld x(static_cast<Eigen::Index>(x_.output_count()));
        x_.evaluate_extended(in.data(), x.data());
        return x.cast<double>();
    }

private:
    std::string name_;
    CompiledExpressions x_;
};

// the symbols a random state gives values to (coordinates, speeds, with_accelerations: the
// accelerations too, specified inputs, unknown loads not excluded, constants without a value,
// the time) and the draws: the varying ones from [-1, 1], constants and the time from
// [0.5, 1.5], in the order of symbols(); deterministic for a seed
class StateSampler {
public:
    StateSampler(const SymbolTable& st, const std::vector<ex>& excluded, bool with_accelerations,
                 unsigned seed)
        : rng_(seed) {
        auto is_excluded = [&](const ex& s) {
            return std::any_of(excluded.begin(), excluded.end(),
                               [&](const ex& x) { return x.is_equal(s); });
        };
        for (SymbolKind kind : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
            for (const ex& s : st.symbols(kind))
                if (!(kind == SymbolKind::variable && st.derivative_order(s) >= 2 &&
                      !with_accelerations) &&
                    !is_excluded(s))
                    symbols_.push_back(s);
        varying_ = symbols_.size();
        for (const ex& c : st.symbols(SymbolKind::constant))
            if (!st.value(c)) symbols_.push_back(c);
        symbols_.push_back(st.time());
    }

    const std::vector<ex>& symbols() const { return symbols_; }

    std::vector<double> draw() {
        std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
        std::vector<double> values;
        for (std::size_t i = 0; i < symbols_.size(); ++i)
            values.push_back(i < varying_ ? unit(rng_) : positive(rng_));
        return values;
    }

private:
    std::vector<ex> symbols_;
    std::size_t varying_ = 0;
    std::mt19937 rng_;
};

}  // namespace

MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states, unsigned seed) {
    const SymbolTable& st = sys.symbols();
    std::vector<ex> acc;
    for (const TimeVariable& qi : q) acc.push_back(qi.d(2));
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, acc)) roadmap.push_back(r.equation);
    // Newton–Euler solves for the accelerations and every joint reaction together
    NewtonEulerEquations ne = form_newton_euler_equations(sys, q, acc);

    // what a state gives values to: coordinates, speeds, specified inputs, unknown loads,
    // constants without a value, the time
    StateSampler sampler(st, ne.reactions, false, seed);
    const std::vector<ex>& state = sampler.symbols();

    std::vector<CompiledMethod> methods;
    methods.emplace_back("road-map", st, roadmap, acc, state);
    methods.emplace_back("Kane", st, form_kane_equations(sys, q), acc, state);
    methods.emplace_back("Lagrange", st, form_lagrange_equations(sys, q), acc, state);
    methods.emplace_back("Newton–Euler", st, ne.equations, ne.unknowns, state);
    // trees: the road-map rows accumulated from the tip inward, and the articulated-body
    // accelerations
    std::vector<ExplicitMethod> explicit_methods;
    if (std::optional<TreeEquations> tree = form_tree_equations_if_tree(sys, q)) {
        methods.emplace_back("recursive road-map", st, tree->residuals, acc, state);
        explicit_methods.emplace_back("articulated body", st, tree->accelerations, state);
    }
    const std::size_t count = methods.size() + explicit_methods.size();
    MethodComparison out{{}, states, 0, std::vector<double>(count, 0.0)};
    for (const CompiledMethod& m : methods) out.methods.push_back(m.name());
    for (const ExplicitMethod& m : explicit_methods) out.methods.push_back(m.name());

    for (int k = 0; k < states; ++k) {
        const std::vector<double> values = sampler.draw();
        Eigen::VectorXd ref = methods[0].solve(values);
        for (std::size_t m = 1; m < count; ++m) {
            Eigen::VectorXd x = m < methods.size()
                                    ? methods[m].solve(values)
                                    : explicit_methods[m - methods.size()].solve(values);
            for (Eigen::Index i = 0; i < ref.size(); ++i)
                out.differences[m] = std::max(out.differences[m], std::abs(x(i) - ref(i)) /
                                                                      std::max(1.0, std::abs(ref(i))));
            out.max_difference = std::max(out.max_difference, out.differences[m]);
        }
    }
    return out;
}

ReactionComparison compare_reactions(const System& sys, const std::vector<TimeVariable>& q,
                                     int states, unsigned seed, const std::vector<ex>& loads) {
    const SymbolTable& st = sys.symbols();
    if (sys.joint_reactions().empty())
        throw ModelError(
            "compare_reactions(): the model declares no joint reaction; declare "
            "one with System::add_joint_reaction");
    std::vector<ex> measures;
    for (const JointReaction& jr : sys.joint_reactions())
        for (const ReactionComponent& c : jr.components) measures.push_back(c.measure);
    auto among = [](const std::vector<ex>& xs, const ex& s) {
        return std::any_of(xs.begin(), xs.end(), [&](const ex& x) { return x.is_equal(s); });
    };
    for (const ex& l : loads)
        if (among(measures, l))
            throw ArgumentError("compare_reactions(): the load '" + to_string(l) +
                                "' is a measure of a declared joint reaction; give only loads "
                                "that are not reactions (motor torques, applied forces)");
    // forward dynamics: the accelerations are the method's own unknowns; inverse dynamics:
    // the given loads, the accelerations drawn with the state
    const bool inverse = !loads.empty();
    std::vector<ex> own = loads;
    if (!inverse)
        for (const TimeVariable& qi : q) own.push_back(qi.d(2));

    // the road-map: its own unknowns and the declared measures together
    std::vector<ex> x_rm = own;
    x_rm.insert(x_rm.end(), measures.begin(), measures.end());
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, x_rm)) roadmap.push_back(r.equation);

    // Newton–Euler with the declared reaction loads set to zero
    NewtonEulerEquations ne = form_newton_euler_equations(sys, q, own);
    exmap zero;
    for (const ex& m : measures) zero[m] = 0;
    std::vector<ex> ne_equations;
    for (const ex& e : ne.equations) ne_equations.push_back(e.subs(zero));

    // the state: as compare_methods() draws it (with the accelerations for inverse dynamics),
    // less the loads solved for and every reaction measure
    std::vector<ex> excluded = ne.reactions;
    excluded.insert(excluded.end(), measures.begin(), measures.end());
    excluded.insert(excluded.end(), loads.begin(), loads.end());
    StateSampler sampler(st, excluded, inverse, seed);
    const std::vector<ex>& state = sampler.symbols();

    // per declared component: its projection by the road-map and by Newton–Euler
    std::vector<ex> by_roadmap, by_ne;
    for (const JointReaction& jr : sys.joint_reactions()) {
        auto j = std::find_if(ne.joints.begin(), ne.joints.end(),
                              [&](const NewtonEulerJoint& nj) { return nj.body == jr.child; });
        const std::string parent = jr.parent ? jr.parent->name() : sys.newtonian().name();
        if (j == ne.joints.end())
            throw ModelError("compare_reactions(): Newton–Euler infers no joint of '" +
                             jr.child->name() + "', the child of the reaction '" + jr.name + "'");
        Vector F, T;
        for (const ReactionComponent& c : jr.components)
            (c.kind == LoadKind::force ? F : T) += c.measure * c.direction;
        for (const ReactionComponent& c : jr.components) {
            const Body* ne_parent = c.kind == LoadKind::force ? j->parent : j->torque_parent;
            if (ne_parent != jr.parent)
                throw ModelError("compare_reactions(): Newton–Euler joins '" + jr.child->name() +
                                 "' to '" +
                                 (ne_parent ? ne_parent->name() : sys.newtonian().name()) +
                                 "', but the reaction '" + jr.name + "' is declared from '" +
                                 parent + "'; declare it from the body the child is placed from");
            if (c.kind == LoadKind::force) {
                by_roadmap.push_back(dot(c.direction, F));
                by_ne.push_back(dot(c.direction, j->force));
            } else {
                by_roadmap.push_back(dot(c.direction, T));
                by_ne.push_back(
                    dot(c.direction, j->torque + cross(j->at->pos_from(*jr.at), j->force)));
            }
        }
    }
    std::vector<ex> inputs = measures;
    inputs.insert(inputs.end(), ne.reactions.begin(), ne.reactions.end());
    inputs.insert(inputs.end(), state.begin(), state.end());
    std::vector<ex> outputs = by_roadmap;
    outputs.insert(outputs.end(), by_ne.begin(), by_ne.end());
    CompiledExpressions projections(st, inputs, outputs);

    CompiledMethod rm("road-map", st, roadmap, x_rm, state);
    CompiledMethod brute("Newton–Euler", st, ne_equations, ne.unknowns, state);
    ReactionComparison out{loads, states, 0,
                           std::vector<double>(loads.size() + measures.size(), 0.0)};
    out.measures.insert(out.measures.end(), measures.begin(), measures.end());
    auto record = [&](std::size_t i, long double a, long double b) {
        double d = static_cast<double>(std::abs(a - b) / std::max(1.0L, std::abs(b)));
        out.differences[i] = std::max(out.differences[i], d);
        out.max_difference = std::max(out.max_difference, d);
    };
    for (int k = 0; k < states; ++k) {
        const std::vector<double> values = sampler.draw();
        Eigen::VectorXd a = rm.solve(values), b = brute.solve(values);
        // the loads solved for: the same unknowns in both
        for (std::size_t i = 0; i < loads.size(); ++i)
            record(i, a(static_cast<Eigen::Index>(i)), b(static_cast<Eigen::Index>(i)));
        // the inputs of the projections: declared measures, Newton–Euler's, the state
        std::vector<long double> in;
        for (std::size_t i = 0; i < measures.size(); ++i)
            in.push_back(a(static_cast<Eigen::Index>(own.size() + i)));
        for (std::size_t i = 0; i < ne.reactions.size(); ++i)
            in.push_back(b(static_cast<Eigen::Index>(own.size() + i)));
        in.insert(in.end(), values.begin(), values.end());
        VectorXld p(static_cast<Eigen::Index>(outputs.size()));
        projections.evaluate_extended(in.data(), p.data());
        const auto m = static_cast<Eigen::Index>(measures.size());
        for (Eigen::Index i = 0; i < m; ++i)
            record(loads.size() + static_cast<std::size_t>(i), p(i), p(m + i));
    }
    return out;
}

}  // namespace alembert
